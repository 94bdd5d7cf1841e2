"""Building evidence and verdicts of claims, shared by the section modules.

Each helper makes one kind of :class:`~verify.claims.model.Evidence` (an exact identity,
exact computations on instances, floating-point falsification, a reduction argument);
:func:`verdict_from` turns a list of them into an outcome that is a success only when
every piece passed.
"""

from __future__ import annotations

from typing import Any

from verify.claims.model import Evidence, EvidenceKind, Outcome, Verdict


def _data(data: dict[str, Any] | None, fields: dict[str, Any]) -> dict[str, Any]:
    return {**data, **fields} if data else fields


def exact(summary: str, ok: bool, data: dict[str, Any] | None = None, **fields) -> Evidence:
    """A symbolic identity decided exactly."""
    return Evidence(EvidenceKind.EXACT_IDENTITY, summary, _data(data, fields), passed=ok)


def instances(summary: str, ok: bool, data: dict[str, Any] | None = None,
              **fields) -> Evidence:
    """Exact rational computations on concrete instances."""
    return Evidence(EvidenceKind.EXACT_INSTANCE, summary, _data(data, fields), passed=ok)


def numeric(summary: str, ok: bool, data: dict[str, Any] | None = None, **fields) -> Evidence:
    """Floating-point falsification attempts (never a proof)."""
    return Evidence(EvidenceKind.NUMERICAL, summary, _data(data, fields), passed=ok)


def argument(summary: str) -> Evidence:
    """A reduction or a pointer to the claims and facts a verdict rests on."""
    return Evidence(EvidenceKind.ARGUMENT, summary)


def certificate(summary: str, ok: bool = True, *, path: str | None = None,
                data: dict[str, Any] | None = None) -> Evidence:
    """A certificate checked exactly (its file, when one was written, at ``path``)."""
    return Evidence(EvidenceKind.CERTIFICATE, summary, data or {}, path=path, passed=ok)


def counterexample(summary: str, ok: bool = True, *, path: str | None = None,
                   data: dict[str, Any] | None = None) -> Evidence:
    """A witness against a statement, checked exactly (or a run re-checked)."""
    return Evidence(EvidenceKind.COUNTEREXAMPLE, summary, data or {}, path=path, passed=ok)


def figure(summary: str, *, path: str | None, data: dict[str, Any] | None = None,
           ok: bool = True) -> Evidence:
    """A figure written to ``path`` (an illustration, not a proof)."""
    return Evidence(EvidenceKind.FIGURE, summary, data or {}, path=path, passed=ok)


def verdict_from(
    evidence: list[Evidence], success: Verdict, finding: str, repaired: str | None = None
) -> Outcome:
    """Success only if every exact and numerical piece passed; otherwise inconclusive.

    A failed numerical check beside a passed exact one is a contradiction (a bug in the
    tool or a rounding bound that is wrong): never a pass, never a refutation.
    """
    failed = [e for e in evidence if not e.passed]
    if failed:
        names = "; ".join(e.summary for e in failed)
        return Outcome(
            Verdict.INCONCLUSIVE,
            f"Some evidence did not pass ({names}); no verdict is given.",
            tuple(evidence),
        )
    return Outcome(success, finding, tuple(evidence), repaired)
