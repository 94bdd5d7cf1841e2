"""The data model of the claim registry (README, "What the report says").

A :class:`Claim` is one checkable statement of the paper: where it stands, what the paper
writes (in our words), what exactly is checked and how, and the function that checks
it. Running the check gives an :class:`Outcome` (verdict, plain-words finding, evidence);
the runner wraps it with timing into a :class:`ClaimResult`.
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np


class Verdict(enum.StrEnum):
    """Possible verdicts. Only VERIFIED and REPAIRED rest on exact checks."""

    VERIFIED = "verified"
    REFUTED = "refuted"
    REPAIRED = "verified-with-repair"
    ASSUMPTION = "assumption"
    INCONCLUSIVE = "inconclusive"


class EvidenceKind(enum.StrEnum):
    """What a piece of evidence is."""

    EXACT_IDENTITY = "exact-identity"  # a symbolic identity decided exactly
    EXACT_INSTANCE = "exact-instance"  # an exact rational computation on concrete data
    ARGUMENT = "argument"  # a reduction that extends exact checks to every n
    COUNTEREXAMPLE = "counterexample"  # an exactly checked witness against a statement
    NUMERICAL = "numerical"  # floating-point falsification attempts (never a proof)
    CERTIFICATE = "certificate"  # a file under certificates/
    FIGURE = "figure"  # a file under reports/
    DERIVATION = "derivation"  # a derivation checked step by step (verify.proof)


@dataclass(frozen=True)
class Evidence:
    """One piece of evidence for a verdict; ``data`` must be JSON-serialisable."""

    kind: EvidenceKind
    summary: str
    data: dict[str, Any] = field(default_factory=dict)
    path: str | None = None
    passed: bool = True

    def to_json(self) -> dict[str, Any]:
        return {
            "kind": self.kind.value,
            "summary": self.summary,
            "passed": bool(self.passed),
            "path": self.path,
            "data": to_jsonable(self.data),
        }


@dataclass(frozen=True)
class Outcome:
    """Result of a check: a verdict, the finding in plain words, evidence, optional repair."""

    verdict: Verdict
    finding: str
    evidence: tuple[Evidence, ...] = ()
    repaired_statement: str | None = None


@dataclass
class CheckContext:
    """Settings shared by all checks of one run."""

    seed: int = 20261121
    samples: int = 200  # random networks per numerical cross-check
    max_bodies: int = 200
    out_dir: Path = Path("reports")
    quick: bool = False
    certificates_dir: Path | None = None  # where passive verdicts store certificates

    def rng(self, salt: str) -> np.random.Generator:
        """A generator seeded from the run seed and the claim id, so claims are independent."""
        return np.random.default_rng([self.seed, *salt.encode()])


CheckFunction = Callable[[CheckContext], Outcome]


@dataclass(frozen=True)
class Claim:
    """A registered claim of the paper."""

    id: str
    section: str
    paper_ref: str
    paper_says: str
    statement: str
    method: str
    scope: str
    check: CheckFunction
    #: the statement as LaTeX text with ``$...$`` formulas (the typeset reports use it;
    #: the plain ``statement`` stays for JSON and terminals); empty: derived from it
    latex: str = ""
    #: what the paper writes, the same way
    paper_latex: str = ""
    #: the repaired statement, the same way, for claims whose check gives one
    repair_latex: str = ""


@dataclass(frozen=True)
class ClaimResult:
    """A claim with the outcome of its check and the time the check took."""

    claim: Claim
    outcome: Outcome
    seconds: float

    def to_json(self) -> dict[str, Any]:
        c, o = self.claim, self.outcome
        return {
            "id": c.id,
            "section": c.section,
            "paper_ref": c.paper_ref,
            "paper_says": c.paper_says,
            "statement": c.statement,
            "method": c.method,
            "scope": c.scope,
            "verdict": o.verdict.value,
            "finding": o.finding,
            "repaired_statement": o.repaired_statement,
            "evidence": [e.to_json() for e in o.evidence],
            "seconds": round(self.seconds, 4),
        }


def to_jsonable(value: Any) -> Any:
    """Convert numpy scalars/arrays, tuples and paths to plain JSON values."""
    if isinstance(value, dict):
        return {str(k): to_jsonable(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [to_jsonable(v) for v in value]
    if isinstance(value, np.ndarray):
        return to_jsonable(value.tolist())
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, Path):
        return str(value)
    if isinstance(value, float) and not np.isfinite(value):
        return str(value)
    if type(value).__module__.startswith("sympy"):
        # sympy's true/false become booleans; exact numbers keep their exact text
        if getattr(value, "is_Boolean", False):
            return bool(value)
        return str(value)
    return value
