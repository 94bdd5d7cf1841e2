"""What ``verify check`` prints and writes for checked derivations (Section 3's proofs
or a user's).

Every line is made from the checker's results only and passes through
:func:`verify.artefacts.text.shown`, so names, labels, notes and exception texts from a
derivation file reach the terminal as inert text (no escape sequence, carriage return,
bidi control or lone surrogate acts). A counterexample is printed exactly: each variable
by the exact parameters of its chart (rationals, or a real algebraic number as its
polynomial and isolating interval), then a rounded value marked ``≈``.
"""

from __future__ import annotations

from collections.abc import Iterator

from verify.artefacts.text import shown
from verify.proof.checker import DerivationResult

_CHARTS = {
    "scalar": "", "vector": "entries ", "matrix": "entries ", "symmetric": "entries ",
    "rotation": "rotation of the quaternion ", "unit_vector": "unit vector of the "
    "stereographic point ", "angle": "angle with tan(θ/2) = ", "chart gap": "at ",
}


def counterexample_text(values: dict) -> str:
    """``name = exact value (≈ rounded)`` for every variable of a counterexample."""
    parts = []
    for name, v in values.items():
        exact = list(v.get("parameters", []))
        body = exact[0] if len(exact) == 1 else "(" + ", ".join(exact) + ")"
        approx = v.get("value")
        if isinstance(approx, list) and len(approx) == 1:
            approx = approx[0]
        rounded = (f" (≈ {approx:g})" if isinstance(approx, int | float)
                   and v.get("kind") in ("scalar", "angle") else "")
        parts.append(f"{name} = {_CHARTS.get(v.get('kind'), '')}{body}{rounded}")
    return "; ".join(parts)


def result_lines(r: DerivationResult) -> Iterator[str]:
    """The lines printed for one derivation, escaped."""
    yield shown(f"{r.name}: {r.verdict} ({r.seconds:.2f} s)  {r.conclusion}")
    if r.vacuous:
        yield shown(f"      vacuous: {r.vacuous}")
    for s in r.steps:
        yield shown(f"  step {s.index} {s.relation:<2} {s.verdict:<12} {s.justification}")
        grounds = s.declarations + s.assumptions
        if grounds:
            yield shown("      assuming " + "; ".join(grounds))
        if s.verdict != "verified":
            yield shown(f"      {s.exact}")
        if s.counterexample:
            yield shown("      counterexample (exact): "
                        + counterexample_text(s.counterexample["values"]))


def summary_line(results: list[DerivationResult]) -> str:
    verified = sum(r.verdict == "verified" for r in results)
    return f"{verified} of {len(results)} derivation(s) verified in every step"


__all__ = ["counterexample_text", "result_lines", "summary_line"]
