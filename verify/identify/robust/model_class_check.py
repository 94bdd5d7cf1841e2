"""Does an answer drawn from the class's region also hold for the larger model?

The robust answers (:mod:`verify.identify.robust.verdict`) are exact statements about the
95 % region of the fitted class. They speak of the operator only if the operator is in
that class; when the data reject the class against one pole and one zero more
(:mod:`verify.identify.quality.model_class`), an exact answer about the region can be wrong
about the operator. Then a confident answer stands only where the larger model fitted to
the same data, with its own 95 % region, agrees with it at the answer's own evidence:

* *passive* on a band (or at all frequencies): the larger model passes the exact gate
  (the tests of Section 3, :mod:`verify.passivity.gate`) on that band, and on a grid of
  the band nu(w) = lambda_min(H(jw) + H(jw)ᴴ)/2 stays >= 0 over the larger region to
  first order;
* *not passive* by a region-wide refutation at the frequency w* and direction v*:
  f = v*ᵀ (H(jw*) + H(jw*)ᴴ) v* stays < 0 over the larger region to first order;
* the largest band [w1, w_max] proved for the region: as for *passive* on that band.

"Over the region to first order" is the linearised range f(θ) ± sqrt(chi2_p(0.95)
gᵀ Σ g), g the gradient of f at the larger fit θ (central differences), Σ its covariance
and p its number of parameters: the exact range of the linearised f over the 95 %
ellipsoid. The larger model is over-parameterised when the operator is in the smaller
class (a near-common factor), but its frequency response, which is what f measures, stays
well determined, so this check keeps answers on noise-free in-class data and withdraws
them when the larger region reaches across zero (a passive third-order operator's
refutation at 3.5 rad/s, where its Re h_i(jw) is 0.002, is withdrawn).

Where it does not agree, the answer becomes *inconclusive* with the reason, and the
certificate (exact, but about a class the data reject) is not written. With the class
not rejected nothing changes. What flows in: the :class:`ClassTest`, the robust answer and
the band search; what flows out: the same, possibly withdrawn, and a sentence for the
output.
"""

from __future__ import annotations

import math
import tempfile
from dataclasses import replace
from fractions import Fraction
from pathlib import Path

import numpy as np

from verify.identify.estimate.prediction import element_parameters
from verify.identify.quality.model_class import ClassTest
from verify.identify.robust.verdict import BandSearch, RobustResult, float_nu
from verify.passivity.decision import INCONCLUSIVE, NOT_PASSIVE, PASSIVE

__all__ = ["LEVEL", "band_grid", "check_answers", "larger_hermitian_form",
           "larger_passes_gate", "larger_region_passive", "margin_of_form"]

#: Level of the larger model's region (that of the identified region).
LEVEL = 0.95


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
    return _form(test, np.asarray(test.larger_theta, float), w, v)


def _diagonal(test: ClassTest, theta: np.ndarray, omega: np.ndarray
              ) -> tuple[np.ndarray, np.ndarray]:
    """h_1(jw), h_2(jw) of the larger structure at θ (floats)."""
    out = []
    for i in range(2):
        num, a, _ = element_parameters(test.larger, theta, i)
        with np.errstate(all="ignore"):
            out.append(np.polyval(num, 1j * omega) / np.polyval(np.r_[1.0, a], 1j * omega))
    return out[0], out[1]


def _form(test: ClassTest, theta: np.ndarray, w: float, v: tuple[float, float]) -> float:
    h1, h2 = _diagonal(test, theta, np.array([w]))
    c = float(theta[-2] + theta[-1])
    return float(2 * h1[0].real * v[0] ** 2 + 2 * c * v[0] * v[1] + 2 * h2[0].real * v[1] ** 2)


def _radius(test: ClassTest, level: float) -> float:
    from scipy.stats import chi2

    return math.sqrt(float(chi2.ppf(level, len(test.larger_theta))))


def _linearised(test: ClassTest, f, level: float) -> tuple[np.ndarray, np.ndarray]:
    """(f(θ), its half-range over the larger region to first order) for f of θ returning
    an array (module docstring)."""
    theta = np.asarray(test.larger_theta, float)
    cov = np.asarray(test.larger_covariance, float)
    value = np.asarray(f(theta), float)
    if cov.shape != (len(theta), len(theta)) or not np.all(np.isfinite(cov)):
        return value, np.full(value.shape, np.inf)
    grads = []
    for j in range(len(theta)):
        step = 1e-6 * max(1.0, abs(theta[j]))
        up, down = theta.copy(), theta.copy()
        up[j] += step
        down[j] -= step
        grads.append((np.asarray(f(up), float) - np.asarray(f(down), float)) / (2 * step))
    G = np.array(grads)  # (parameters, points)
    var = np.einsum("ip,ij,jp->p", G, cov, G)
    return value, _radius(test, level) * np.sqrt(np.clip(var, 0.0, None))


def margin_of_form(test: ClassTest, w: float, v: tuple[float, float],
                   level: float = LEVEL) -> tuple[float, float]:
    """(f, r): f = vᵀ(H(jw) + H(jw)ᴴ)v of the larger fit, r its first-order half-range."""
    value, r = _linearised(
        test, lambda th: np.array([_form(test, th, w, v)]), level)
    return float(value[0]), float(r[0])


def _rounding(test: ClassTest, grid: np.ndarray) -> np.ndarray:
    """1e-12 of |h_1| + |h_2| + |c12| + |c21| on ``grid``: below it a float nu is rounding
    (a lossless-like element's Re h(jw) falls as w^-6 while h itself falls as w^-1)."""
    theta = np.asarray(test.larger_theta, float)
    h1, h2 = _diagonal(test, theta, grid)
    return 1e-12 * (np.abs(h1) + np.abs(h2) + abs(theta[-2]) + abs(theta[-1]))


def band_grid(band: tuple[Fraction, Fraction] | None) -> np.ndarray:
    """Frequencies where the first-order margin of nu is checked: 200 evenly spaced and
    200 log-spaced points of the band (of [1e-3, 1e5] rad/s for all frequencies)."""
    if band is None:
        return np.geomspace(1e-3, 1e5, 400)
    lo, hi = float(band[0]), float(band[1])
    return np.unique(np.r_[np.linspace(lo, hi, 200),
                           np.geomspace(max(lo, hi * 1e-4), hi, 200)])


def larger_region_passive(test: ClassTest, band: tuple[Fraction, Fraction] | None,
                          level: float = LEVEL) -> bool:
    """nu(w) - r(w) >= 0 on :func:`band_grid` (and, for all frequencies, c12 + c21 = 0
    with no variance: otherwise nu -> -|c12 + c21|/2 < 0 as w -> infinity)."""
    grid = band_grid(band)
    value, r = _linearised(
        test, lambda th: float_nu(test.larger, th, grid), level)
    if not bool(np.all(value - r >= -_rounding(test, grid))):
        return False
    if band is None:
        c, rc = _linearised(test, lambda th: np.array([th[-2] + th[-1]]), level)
        return bool(c[0] == 0 and rc[0] == 0)
    return True


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
        if not (larger_passes_gate(test, robust.band)
                and larger_region_passive(test, robust.band)):
            notes.append(f"the region's proof of passivity {_band_text(robust.band)} is "
                         "withdrawn")
            robust = RobustResult(INCONCLUSIVE, robust.band,
                                  f"the exact proof holds for the class's region, but {why} "
                                  f"is not passive {_band_text(robust.band)} (exact gate on "
                                  "the fit, or its 95 % region to first order): the answer "
                                  "rests on the class, not on the data",
                                  seconds=robust.seconds, withdrawn=True)
    elif robust.verdict == NOT_PASSIVE and robust.refutation is not None:
        w = Fraction(robust.refutation["frequency"])
        v = tuple(float(Fraction(x)) for x in robust.refutation["direction"])
        form, r = margin_of_form(test, float(w), v)  # type: ignore[arg-type]
        if not form + r < 0:
            notes.append(f"the region-wide refutation at w = {float(w):.6g} rad/s is "
                         "withdrawn")
            robust = RobustResult(INCONCLUSIVE, robust.band,
                                  f"the exact refutation holds for the class's region at "
                                  f"w = {float(w):.6g} rad/s, but {why} gives "
                                  f"vᵀ(H + Hᴴ)v = {form:.3g} ± {r:.3g} there (its 95 % "
                                  "region, to first order), not < 0: the answer rests "
                                  "on the class, not on the data", seconds=robust.seconds,
                                  withdrawn=True)
    proved = None if search.w_max is None else (search.w1, search.w_max)
    if proved is not None and not (larger_passes_gate(test, proved)
                                   and larger_region_passive(test, proved)):
        notes.append(f"the proof on [{search.w1}, {search.w_max}] rad/s is withdrawn (the "
                     "larger model, over its region to first order, is not passive there)")
        search = replace(search, w_max=None, certificate=None)
    if notes:
        return robust, search, (f"{why} disagrees: " + "; ".join(notes)
                                + f" (`--structure {test.larger_text()}` fits the larger "
                                "class and answers for its own region)")
    if not checked:
        return robust, search, (f"the data reject the fitted class against "
                                f"{test.larger_text()}; no answer here rests on it (the "
                                "robust answer is inconclusive and no band was proved)")
    return robust, search, (f"{why} agrees with every answer given (checked at each "
                            "answer's evidence)")
