"""Does an answer drawn from the class's region also hold for the larger model?

The robust answers (:mod:`verify.identify.robust.verdict`) are exact statements about the
95 % region of the fitted class. They speak of the operator only if the operator is in
that class; when the data reject the class against one pole and one zero more
(:mod:`verify.identify.quality.model_class`), an exact answer about the region can be wrong
about the operator. Then a confident answer stands only where the larger model fitted to
the same data agrees with it, at the answer's own evidence:

* *passive* on a band (or at all frequencies): the larger model passes the exact gate
  (the tests of Section 3, :mod:`verify.passivity.gate`) on that band;
* *not passive* by a region-wide refutation at the frequency w* and direction v*: the
  larger model also has v*ᵀ (H(jw*) + H(jw*)ᴴ) v* < 0 there;
* the largest band [w1, w_max] proved for the region: the larger model passes the exact
  gate on it.

Where it does not agree, the answer becomes *inconclusive* with the reason, and the
certificate (exact, but about a class the data reject) is not written. With the class
not rejected nothing changes. What flows in: the :class:`ClassTest`, the robust answer and
the band search; what flows out: the same, possibly withdrawn, and a sentence for the
output.
"""

from __future__ import annotations

import tempfile
from dataclasses import replace
from fractions import Fraction
from pathlib import Path

import numpy as np

from verify.identify.quality.model_class import ClassTest
from verify.identify.robust.verdict import BandSearch, RobustResult
from verify.passivity.decision import INCONCLUSIVE, NOT_PASSIVE, PASSIVE

__all__ = ["check_answers", "larger_hermitian_form", "larger_passes_gate"]


def _larger_model(test: ClassTest):
    from verify.passivity.model import from_transfer_function

    theta = [Fraction(x) for x in test.larger_theta]
    num, den = test.larger.transfer_matrix(theta)
    return from_transfer_function(num, den, name=f"larger {test.larger_text()} fit")


def larger_passes_gate(test: ClassTest, band: tuple[Fraction, Fraction] | None) -> bool:
    """True if the exact gate finds the larger model passive on ``band`` (None: at all
    frequencies)."""
    from verify.passivity.gate import run_band_gate, run_gate

    model = _larger_model(test)
    with tempfile.TemporaryDirectory(prefix="verify-larger-") as tmp:
        if band is None:
            (result,) = run_gate([model], Fraction(0), Path(tmp))
        else:
            (result,) = run_band_gate([model], band, Fraction(0), Path(tmp))
    return result.decision.verdict == PASSIVE


def larger_hermitian_form(test: ClassTest, w: float, v: tuple[float, float]) -> float:
    """vᵀ (H(jw) + H(jw)ᴴ) v of the larger model (floats)."""
    theta = np.asarray(test.larger_theta, float)
    per = test.larger.zeros + 1 + test.larger.poles
    re = []
    for i in range(2):
        block = theta[i * per:(i + 1) * per]
        num, den = block[: test.larger.zeros + 1], np.r_[1.0, block[test.larger.zeros + 1:]]
        re.append(float((np.polyval(num, 1j * w) / np.polyval(den, 1j * w)).real))
    c = float(theta[-2] + theta[-1])
    return 2 * re[0] * v[0] ** 2 + 2 * c * v[0] * v[1] + 2 * re[1] * v[1] ** 2


def _band_text(band: tuple[Fraction, Fraction] | None) -> str:
    return "at all frequencies" if band is None else f"on [{band[0]}, {band[1]}] rad/s"


def check_answers(test: ClassTest | None, robust: RobustResult, search: BandSearch
                  ) -> tuple[RobustResult, BandSearch, str]:
    """The robust answer and the band search, each withdrawn where the class is rejected
    and the larger model disagrees (module docstring), and what was done, in a sentence
    ("" when nothing was checked)."""
    if test is None or not test.rejected:
        return robust, search, ""
    notes: list[str] = []
    checked = (robust.verdict == PASSIVE
               or (robust.verdict == NOT_PASSIVE and robust.refutation is not None)
               or search.w_max is not None)
    why = (f"the data reject the fitted class against {test.larger_text()}, and the larger "
           "model fitted to the same data")
    if robust.verdict == PASSIVE:
        if not larger_passes_gate(test, robust.band):
            notes.append(f"the region's proof of passivity {_band_text(robust.band)} is "
                         "withdrawn")
            robust = RobustResult(INCONCLUSIVE, robust.band,
                                  f"the exact proof holds for the class's region, but {why} "
                                  f"is not passive {_band_text(robust.band)}: the answer rests "
                                  "on the class, not on the data",
                                  seconds=robust.seconds, withdrawn=True)
    elif robust.verdict == NOT_PASSIVE and robust.refutation is not None:
        w = Fraction(robust.refutation["frequency"])
        v = tuple(float(Fraction(x)) for x in robust.refutation["direction"])
        form = larger_hermitian_form(test, float(w), v)  # type: ignore[arg-type]
        if not form < 0:
            notes.append(f"the region-wide refutation at w = {float(w):.6g} rad/s is "
                         "withdrawn")
            robust = RobustResult(INCONCLUSIVE, robust.band,
                                  f"the exact refutation holds for the class's region at "
                                  f"w = {float(w):.6g} rad/s, but {why} satisfies "
                                  f"vᵀ(H + Hᴴ)v = {form:.3g} >= 0 there: the answer rests "
                                  "on the class, not on the data", seconds=robust.seconds,
                                  withdrawn=True)
    if search.w_max is not None and not larger_passes_gate(test, (search.w1, search.w_max)):
        notes.append(f"the proof on [{search.w1}, {search.w_max}] rad/s is withdrawn (the "
                     "larger model is not passive there)")
        search = replace(search, w_max=None, certificate=None)
    if notes:
        return robust, search, f"{why} disagrees: " + "; ".join(notes)
    if not checked:
        return robust, search, (f"the data reject the fitted class against "
                                f"{test.larger_text()}; no answer here rests on it (the "
                                "robust answer is inconclusive and no band was proved)")
    return robust, search, (f"{why} agrees with every answer given (checked at each "
                            "answer's evidence)")
