"""The proof-step tables of a report: one table per checked derivation.

A derivation (:mod:`verify.proof`) is a chain ``e0 R1 e1 R2 e2 ...``; its table shows the
start expression, then per step the relation and the new expression on a row of their
own, under it the justification, the assumptions the step uses and its verdict (and,
for an inequality, whether it rests on hand-written terms, on an SOS certificate, or on
both: the SOS re-proofs of the paper's Lemma 1 and Theorem 1 inequalities). The exact
check that most steps of a section share is stated once, under the section's tables.

Each cell has a plain-text form (JSON, terminals) and a LaTeX form (typeset reports).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from verify.claims.model import ClaimResult, EvidenceKind
from verify.report.mathtex import prose_to_latex, to_latex

__all__ = ["DerivationTable", "StepRow", "common_evidence", "derivation_tables", "sos_twins",
           "table_evidence"]


@dataclass(frozen=True)
class StepRow:
    """One step: ``relation`` is the step's relation and right-hand side (``= e1``)."""

    step: str
    relation: str
    relation_latex: str
    justification: str
    justification_latex: str
    assumptions: str
    assumptions_latex: str
    verdict: str
    proved_by: str
    evidence: str
    coq_theorem: str = ""  # the step's theorem in the exported Coq development


@dataclass(frozen=True)
class DerivationTable:
    """A derivation of a claim with its start expression and steps."""

    claim: str
    name: str
    statement: str
    statement_latex: str
    verdict: str
    start: str
    start_latex: str
    rows: tuple[StepRow, ...]


def sos_twins(results: list[ClaimResult] | tuple[ClaimResult, ...]) -> set[tuple[str, int]]:
    """(derivation, step) pairs whose SOS twin (``<name>.step<k>-sos``) was verified."""
    out = set()
    for r in results:
        for e in r.outcome.evidence:
            if e.kind is EvidenceKind.DERIVATION and e.data["verdict"] == "verified":
                head, _, tail = e.data["name"].rpartition(".step")
                if tail.endswith("-sos") and tail[:-4].isdigit():
                    out.add((head, int(tail[:-4])))
    return out


def _proved_by(name: str, step: dict, twins: set[tuple[str, int]]) -> str:
    """How an inequality step is proved: hand terms, SOS, or both (equalities: empty)."""
    if step["relation"] == "=":
        return ""
    if "SOS certificate" in step["justification"]:
        return "SOS"
    if step["justification"].startswith("cited:"):
        return "citation"
    return "hand terms + SOS" if (name, step["index"]) in twins else "hand terms"


def _evidence(step: dict) -> str:
    if step["counterexample"]:
        from verify.claims.proofs import exact_value_text

        values = step["counterexample"]["values"]
        return "counterexample: " + "; ".join(exact_value_text(k, v) for k, v in values.items())
    return step["exact"] or ""


def _row(name: str, step: dict, twins: set[tuple[str, int]]) -> StepRow:
    conditions = step["conditions"]
    justification = step["justification"]
    just_latex = prose_to_latex(justification)
    if conditions:
        justification += " [where " + "; ".join(conditions) + "]"
        just_latex += "; where " + "; ".join(f"${to_latex(c)}$" for c in conditions)
    assumptions = step["assumptions"]
    return StepRow(
        step=str(step["index"]),
        relation=f"{step['relation']} {step['rhs']}",
        relation_latex=to_latex(f"{step['relation']} {step['rhs']}"),
        justification=justification,
        justification_latex=just_latex,
        assumptions=", ".join(assumptions) or "none",
        assumptions_latex="; ".join(f"${to_latex(a)}$" for a in assumptions) or "none",
        verdict=step["verdict"],
        proved_by=_proved_by(name, step, twins),
        evidence=_evidence(step),
        coq_theorem=_coq_theorem(name, step, twins),
    )


def _coq_theorem(name: str, step: dict, twins: set[tuple[str, int]]) -> str:
    """The Coq theorem of a verified step ("" for a cited or unverified one):
    ``module.stepK`` for a step proved by algebra or hand terms
    (:mod:`verify.coq.derivations`), and for the SOS twin ``<derivation>.step<k>-sos``
    of a hand step, the unit exported from its certificate (:mod:`verify.coq.sos`)."""
    from verify.coq import sos
    from verify.coq.derivations import theorem_name

    if step["verdict"] != "verified":
        return ""
    how = _proved_by(name, step, twins)
    if how == "citation":
        return ""
    if how == "SOS":
        head, _, tail = name.rpartition(".step")
        if not (tail.endswith("-sos") and tail[:-4].isdigit()):
            return ""
        k = int(tail[:-4])
        return f"{sos.unit_name(head, k)}.{sos.theorem_name(k)}"
    return theorem_name(name, step["index"])


def step_coq_theorem(name: str, step: dict, twins: set[tuple[str, int]]) -> str:
    """The Coq theorem of a step of the derivation ``name`` ("" when none): see
    :func:`_coq_theorem`."""
    return _coq_theorem(name, step, twins)


def derivation_tables(results, twins: set[tuple[str, int]]) -> list[DerivationTable]:
    """The tables of the derivations the given claims checked, in order."""
    out = []
    for r in results:
        for e in r.outcome.evidence:
            if e.kind is not EvidenceKind.DERIVATION:
                continue
            d = e.data
            out.append(DerivationTable(
                claim=r.claim.id, name=d["name"], statement=d["statement"],
                statement_latex=prose_to_latex(d["statement"]), verdict=d["verdict"],
                start=d["start"], start_latex=to_latex(d["start"]),
                rows=tuple(_row(d["name"], s, twins) for s in d["steps"])))
    return out


def common_evidence(tables: list[DerivationTable]) -> str:
    """The exact check shared by more than one step of these tables ("" if none is)."""
    counts = Counter(row.evidence for t in tables for row in t.rows if row.evidence)
    if not counts:
        return ""
    text, n = counts.most_common(1)[0]
    return text if n > 1 else ""


def table_evidence(table: DerivationTable, common: str) -> str:
    """The exact check every step of one table shares, when it is not ``common`` and the
    table has more than one step ("" otherwise): stated once under that table."""
    texts = {row.evidence for row in table.rows}
    if len(table.rows) > 1 and len(texts) == 1:
        (text,) = texts
        return "" if text == common else text
    return ""
