"""Turn checked derivations (:mod:`verify.proof`) into claim outcomes and evidence."""

from __future__ import annotations

from collections.abc import Iterable

from verify.artefacts.text import shown
from verify.claims.model import CheckContext, Evidence, EvidenceKind, Outcome, Verdict
from verify.proof import Derivation, DerivationResult, SearchSettings, check


def search_settings(context: CheckContext, salt: int = 0) -> SearchSettings:
    """Falsification effort per step: full by default, reduced with --quick."""
    if context.quick:
        return SearchSettings(samples=96, hypothesis_examples=25, ipopt_starts=1,
                              seed=context.seed + salt)
    return SearchSettings(samples=256, hypothesis_examples=60, ipopt_starts=3,
                          seed=context.seed + salt)


def derivation_evidence(result: DerivationResult, expected: str = "verified") -> list[Evidence]:
    """One derivation evidence item (its step table), plus one per exact counterexample.

    ``passed`` means the derivation came out as the claim's check expects (verified, or
    refuted for a statement the claim shows false); a counterexample item is passed when
    it was confirmed exactly, which it always is once reported.
    """
    verdict = result.verdict
    out = [
        Evidence(
            EvidenceKind.DERIVATION,
            shown(f"{result.name}: {result.conclusion} — {verdict} "
                  f"({len(result.steps)} step(s))"
                  + (f"; vacuous: {result.vacuous}" if result.vacuous else "")),
            result.to_json(),
            passed=verdict == expected,
        )
    ]
    for step in result.steps:
        if step.counterexample is not None:
            values = "; ".join(exact_value_text(name, v)
                               for name, v in step.counterexample["values"].items())
            out.append(
                Evidence(
                    EvidenceKind.COUNTEREXAMPLE,
                    shown(f"{result.name}, step {step.index} ({step.relation}) fails "
                          f"exactly at: {values}"),
                    step.counterexample,
                    passed=True,
                )
            )
    return out


def exact_value_text(name: str, v: dict) -> str:
    """A counterexample's variable shown exactly: each entry of its (rounded) value is
    matched to the one rational parameter it rounds from, so the matrix is written in
    rationals; when an entry matches no parameter or several, the rounded value is
    shown with its exact parameters and says so."""
    from fractions import Fraction

    params = [Fraction(p) for p in v["parameters"] if "/" in p or p.lstrip("-").isdigit()]
    exact = []
    for x in v["value"] if isinstance(v["value"], list) else [v["value"]]:
        found = {p for p in params if round(float(p), 6) == x}
        if len(found) != 1:
            return (f"{name} = {v['value']} (entries rounded to 6 decimals; exact parameters "
                    f"{', '.join(v['parameters'])})")
        exact.append(found.pop())
    if len(exact) == 9:
        rows = ("(" + ", ".join(str(x) for x in exact[3 * i:3 * i + 3]) + ")" for i in range(3))
        return f"{name} = ({', '.join(rows)}) exactly (rows)"
    return f"{name} = ({', '.join(str(x) for x in exact)}) exactly"


def check_all(
    derivations: Iterable[Derivation], context: CheckContext, salt: int = 0
) -> list[DerivationResult]:
    return [
        check(d, search_settings(context, salt + 101 * k)) for k, d in enumerate(derivations)
    ]


def outcome_from(
    results: list[DerivationResult],
    finding: str,
    *,
    extra: Iterable[Evidence] = (),
    expect_refuted: frozenset[str] = frozenset(),
    success: Verdict = Verdict.VERIFIED,
    repaired: str | None = None,
) -> Outcome:
    """Claim verdict from its derivations.

    ``success`` when every derivation came out as expected (verified, or refuted for the
    ids in ``expect_refuted``, which the claim is about); REFUTED if the claim is about a
    refutation that holds; INCONCLUSIVE otherwise, naming what did not come out.
    """
    evidence: list[Evidence] = []
    for r in results:
        evidence += derivation_evidence(
            r, "refuted" if r.name in expect_refuted else "verified"
        )
    evidence += list(extra)
    unexpected = [
        r.name for r in results
        if (r.verdict != "refuted" if r.name in expect_refuted else r.verdict != "verified")
    ]
    if unexpected:
        return Outcome(
            Verdict.INCONCLUSIVE,
            "Not every derivation came out as the check expects: "
            + ", ".join(f"{n} ({next(r.verdict for r in results if r.name == n)})"
                        for n in unexpected)
            + ". " + finding,
            tuple(evidence),
            repaired,
        )
    return Outcome(success, finding, tuple(evidence), repaired)
