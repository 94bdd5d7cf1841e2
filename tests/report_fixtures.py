"""Runs of the claim registry for report tests, built without running the checks."""

from __future__ import annotations

from verify.claims.model import (
    CheckContext,
    Claim,
    ClaimResult,
    Evidence,
    EvidenceKind,
    Outcome,
    Verdict,
)
from verify.claims.runner import RunResult


def _never(_: CheckContext) -> Outcome:  # the claims below are rendered, never checked
    raise AssertionError("not run")


def step(index: int, relation: str, rhs: str, justification: str = "algebra", *,
         conditions=(), assumptions=(), exact: str = "lhs - rhs = 0 exactly",
         verdict: str = "verified") -> dict:
    """One step as the proof checker's JSON has it."""
    return {"index": index, "relation": relation, "lhs": "", "rhs": rhs,
            "justification": justification, "verdict": verdict, "exact": exact,
            "conditions": list(conditions), "assumptions": list(assumptions),
            "counterexample": None}


def derivation(name: str, start: str, steps: list[dict], statement: str = "a chain") -> Evidence:
    data = {"name": name, "statement": statement, "cite": "", "start": start,
            "conclusion": statement, "verdict": "verified", "conditions": [],
            "assumptions": [], "vacuous": "", "seconds": 0.5, "steps": steps}
    return Evidence(EvidenceKind.DERIVATION, f"{name}: verified", data)


def claim(cid: str, section: str, *, statement: str = "a statement", paper: str = "the paper",
          latex: str = "", finding: str = "Holds.", evidence=(), repaired: str | None = None,
          verdict: Verdict = Verdict.VERIFIED) -> ClaimResult:
    c = Claim(id=cid, section=section, paper_ref="Section 9", paper_says=paper,
              statement=statement, method="by hand", scope="every n", check=_never,
              latex=latex)
    return ClaimResult(c, Outcome(verdict, finding, tuple(evidence), repaired), 0.25)


def run_of(*results: ClaimResult) -> RunResult:
    return RunResult(tuple(results), 1.0, 7)


def registry_run() -> RunResult:
    """Every registered claim with a placeholder outcome (its repair when it has one)."""
    from verify.claims.catalog import REGISTRY

    results = []
    for c in REGISTRY:
        repaired = "repaired as stated" if c.repair_latex else None
        verdict = Verdict.REPAIRED if repaired else Verdict.ASSUMPTION
        results.append(ClaimResult(c, Outcome(verdict, "placeholder finding", (), repaired),
                                   0.0))
    return RunResult(tuple(results), 0.0, 7)


def committed_run(path=None) -> RunResult:
    """The registered claims with the outcomes of the committed ``reports/report.json``
    (findings, evidence summaries and data as the checks wrote them), so that the whole
    report renders in a second without running a check. Claims no longer registered are
    left out."""
    import json
    from pathlib import Path

    from verify.claims.catalog import REGISTRY

    path = Path(path or Path(__file__).resolve().parents[1] / "reports" / "report.json")
    doc = json.loads(path.read_text())
    known = set(REGISTRY.ids())
    results = []
    for c in doc["claims"]:
        if c["id"] not in known:
            continue
        evidence = tuple(Evidence(EvidenceKind(e["kind"]), e["summary"], e["data"] or {},
                                  e.get("path"), e["passed"]) for e in c["evidence"])
        outcome = Outcome(Verdict(c["verdict"]), c["finding"], evidence,
                          c.get("repaired_statement"))
        results.append(ClaimResult(REGISTRY.get(c["id"]), outcome, 0.0))
    return RunResult(tuple(results), 0.0, doc["seed"])
