"""Whether the data identify the operator at all: the gate before any verdict (Section 4).

A passivity verdict on an identified H(s) (Section 4, "Human Modeling", then the tests
of Section 3) is only worth something if the model describes the operator. Before the
command decides anything, :func:`check` asks five questions of the estimate and the
data; a "no" to any of them means *cannot identify* with the reason, and no model is
certified:

1. **Does the model explain the validation data?** The honest validation fit of each
   output (Section 4's fit ratio of the model simulated on the logged input,
   :func:`verify.identify.quality.fits.honest_fits`) must reach ``MIN_FIT`` = 3 %:
   the model's error on the validation data at most 97 % of the output's spread about
   its mean. Merely beating the zero model and the mean (fit > 0 %, the earlier rule)
   let a 2.8 % fit through, a short noisy session whose estimate had b1 = -410 against
   a true 1.2. The threshold comes from the fits correct models reach on simulated
   closed-loop experiments in the paper's protocol (``benchmarks/bench_identify_coverage.py``,
   fit ratio on the noisy data; 10 seeds per setting): lowest over outputs and seeds
   11.6 % at 20 Hz, 10.0 % at 50 Hz, 9.3 % at 120 Hz, 9.5 % at 250 Hz and 4.9 % at
   120 Hz with reset pauses between trials (the operator's noise on u is large against
   a small response there), while the fit of those models on noise-free data was above
   90 %. A fit ratio on noisy data measures
   the noise as much as the model, so it cannot separate a wrong model from a right one
   in a noisy session: 3 % sits below every correct model measured and above the wrong
   one of the report, a narrow gap. The question is a floor against models that explain
   almost nothing; the region's width and the robust verdict (inconclusive for such a
   session) are what keep a noisy session from a wrong answer.
2. **Is the estimate an interior, stable point?** Every denominator coefficient must lie
   strictly inside the search box of :func:`verify.identify.estimate.pem.denominator_bounds`
   (the poles in the open left half-plane, no coefficient within ``BOUND_MARGIN`` of
   the upper bound, and none on the box's lower edge a_k = 0: below ``LOWER_MARGIN``
   times binom(n, k) rho^(n-k), the size a_k has for n roots of the model's own largest
   modulus rho; measured against the box's upper bound instead, which grows as
   (pi/h)^(n-k), the rule called a0 = 1.8 of a 3-pole model at 120 Hz "zero"). An
   estimate on the box's edge is not a minimum of the criterion inside the model class,
   and its covariance is meaningless.
3. **Is the information matrix well conditioned?** The covariance must be finite and
   positive definite, and its correlation matrix (the scale-free form of the inverse
   information matrix) must have condition number at most ``MAX_CONDITION``. A larger
   one means some combination of parameters is not determined by the data.
4. **Are e and u the loop's input and output?** The leader integrates the operator's
   command (Section 2: R_l' = R_l ω_l with ω_l containing ω_h^b), so the operator's
   noise enters u directly and e only through that integration: in logs of the loop e
   is the smoother signal. With roughness R(x) = ||Δx|| / ||x - mean(x)|| over all
   trials (Δ the sample-to-sample difference), no component may have
   R(e_i) > ``MAX_ROUGHNESS_RATIO`` R(u_i); otherwise e and u are swapped or not the
   loop's signals. Measured on the prepared trials of simulated logs of the paper's loop:
   R(u_i) / R(e_i) = 3.2-3.4 noise-free (120 Hz), about 13 with the default noises
   decimated to 20 Hz and 30-34 at the logged 120 Hz (the shipped example logs), so
   swapped logs give 3.2-34 and are refused; the ratio 2 leaves room for
   open-loop logs (e a smooth random input, u = H e: R(e) / R(u) = 1.2 in the tests).
5. **Did the loop stay bounded?** In no trial may the RMS of e or u over the last
   quarter exceed ``MAX_GROWTH`` times the RMS over the first quarter, and the signals
   must be finite. A tracking trial settles after its reference change; a loop whose
   signals grow within trials is diverging and its data do not come from the steady
   operator Section 4 models.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from math import comb

import numpy as np

from verify.identify.estimate.pem import denominator_bounds
from verify.identify.estimate.prediction import element_parameters
from verify.identify.estimate.result import Estimate
from verify.inputs.experiment import Trial

__all__ = [
    "BOUND_MARGIN",
    "LOWER_MARGIN",
    "MAX_CONDITION",
    "MAX_GROWTH",
    "MIN_FIT",
    "Identifiability",
    "check",
    "condition_number",
    "growth",
    "interior",
    "roughness",
]

MIN_FIT = 3.0  # %, honest validation fit each output must reach (module docstring)
BOUND_MARGIN = 1e-3  # relative distance to the search box's upper bound
LOWER_MARGIN = 1e-6  # a coefficient below this fraction of its own scale is a_k = 0
MAX_CONDITION = 1e6  # of the parameters' correlation matrix (measured: 1e2-4e2)
MAX_ROUGHNESS_RATIO = 2.0  # largest admitted R(e_i) / R(u_i)
MAX_GROWTH = 10.0  # RMS of the last quarter of a trial over that of its first quarter


@dataclass(frozen=True)
class Identifiability:
    """The gate's answer: ``identifiable`` and, when not, the reasons (one per failed
    question); ``figures`` holds the numbers checked (for the JSON summary)."""

    identifiable: bool
    reasons: tuple[str, ...] = ()
    figures: dict[str, object] = field(default_factory=dict)

    def to_json(self) -> dict[str, object]:
        """The answer with its figures to 4 significant digits (byte-reproducible)."""
        def four(x):
            if isinstance(x, list):
                return [four(v) for v in x]
            return float(f"{x:.4g}") if isinstance(x, float) else x

        return {"identifiable": self.identifiable, "reasons": list(self.reasons),
                **{k: four(v) for k, v in self.figures.items()}}


def condition_number(covariance: np.ndarray) -> float:
    """Condition number of the correlation matrix of ``covariance`` (inf if it is not
    finite and positive definite)."""
    cov = np.asarray(covariance, float)
    if cov.size == 0 or not np.all(np.isfinite(cov)):
        return float("inf")
    d = np.diag(cov)
    if not np.all(d > 0):
        return float("inf")
    corr = cov / np.sqrt(np.outer(d, d))
    eig = np.linalg.eigvalsh((corr + corr.T) / 2)
    if not eig[0] > 0:
        return float("inf")
    return float(eig[-1] / eig[0])


def interior(estimate: Estimate, h: float) -> list[str]:
    """Reasons why some output's denominator is unstable or on the search box's edge."""
    out = []
    structure = estimate.structure
    upper = denominator_bounds(structure.poles, h)
    for i in (0, 1):
        _, a, _ = element_parameters(structure, estimate.theta, i)
        roots = np.roots(np.concatenate(([1.0], a)))
        names = structure.names()
        if not np.all(np.isfinite(a)) or np.any(a <= 0) or np.any(roots.real >= 0):
            out.append(f"output {i + 1}: the estimated denominator is not stable (poles "
                       + ", ".join(f"{complex(r):.3g}" for r in roots) + ")")
            continue
        per = structure.zeros + 1 + structure.poles
        rho = float(np.max(np.abs(roots)))
        own_scale = [comb(len(a), k + 1) * rho ** (k + 1) for k in range(len(a))]
        for k in range(len(a)):
            name = names[i * per + structure.zeros + 1 + k]
            if a[k] >= (1 - BOUND_MARGIN) * upper[k]:
                out.append(f"output {i + 1}: {name} = {a[k]:.4g} sits on the search bound "
                           f"{upper[k]:.4g} (poles at half the Nyquist frequency)")
            elif a[k] <= LOWER_MARGIN * own_scale[k]:
                out.append(f"output {i + 1}: {name} = {a[k]:.4g} sits on the search bound 0 "
                           "(a pole or a damping at zero)")
    return out


def growth(trials: Sequence[Trial]) -> float:
    """Largest ratio, over trials and the signals e and u, of the RMS over a trial's last
    quarter to that over its first quarter (inf for non-finite samples)."""
    worst = 0.0
    for tr in trials:
        for x in (np.asarray(tr.e, float), np.asarray(tr.u, float)):
            if not np.all(np.isfinite(x)):
                return float("inf")
            q = x.shape[0] // 4
            if q < 1:
                continue
            first = float(np.sqrt(np.mean(x[:q] ** 2)))
            last = float(np.sqrt(np.mean(x[-q:] ** 2)))
            if last == 0.0:
                continue
            worst = max(worst, last / first if first > 0 else float("inf"))
    return worst


def _finite(x: float) -> float | None:
    return float(x) if np.isfinite(x) else None


def roughness(trials: Sequence[Trial], signal: str) -> np.ndarray:
    """R(x) per component (module docstring, question 4) of ``signal`` "e" or "u"."""
    num = np.zeros(2)
    den = np.zeros(2)
    for tr in trials:
        x = np.asarray(getattr(tr, signal), float)
        num += np.sum(np.diff(x, axis=0) ** 2, axis=0)
        den += np.sum((x - x.mean(axis=0)) ** 2, axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.sqrt(np.where(den > 0, num / np.where(den > 0, den, 1.0), np.inf))


def check(estimate: Estimate, fit_validation: Sequence[float], trials: Sequence[Trial],
          h: float, *, basis: str = "") -> Identifiability:
    """The five questions of the module docstring, on the estimate, its honest validation
    fit (per output; ``basis``, when given, names the basis of that figure in the
    reason) and the prepared trials (identification and validation)."""
    reasons = []
    on = f" ({basis})" if basis else ""
    fits = [float(x) for x in fit_validation]
    for i, fit in enumerate(fits):
        if not fit >= MIN_FIT:
            worse = " (no better than predicting the output's mean or zero)" if fit <= 0 else ""
            reasons.append(f"output {i + 1}: the model simulated on the validation input{on} "
                           f"fits {fit:.2f} %{worse}, below the {MIN_FIT:g} % a model must explain "
                           "of the operator's output; the response is buried in noise: log "
                           "longer or less noisy trials")
    reasons += interior(estimate, h)
    cond = condition_number(estimate.covariance)
    if not cond <= MAX_CONDITION:
        reasons.append(f"the information matrix is ill-conditioned (condition number of "
                       f"the parameters' correlation {cond:.3g} > {MAX_CONDITION:.0e}): "
                       "some combination of parameters is not determined by the data")
    more, data_figures = data_reasons(trials)
    reasons += more
    figures = {"fit_validation": fits,
               "condition_number": cond if np.isfinite(cond) else None,
               "min_fit": MIN_FIT, "max_condition": MAX_CONDITION, **data_figures}
    return Identifiability(not reasons, tuple(reasons), figures)


def constant_signals(trials: Sequence[Trial]) -> list[str]:
    """A component of e or u that never moves (up to the anti-aliasing filter's rounding)
    carries no information about the operator: the data cannot identify H."""
    reasons = []
    for name in ("e", "u"):
        for i in (0, 1):
            parts = [np.asarray(getattr(tr, name))[:, i] for tr in trials]
            x = np.concatenate(parts) if parts else np.zeros(0)
            if x.size and not np.ptp(x) > 1e-9 * np.max(np.abs(x)):
                reasons.append(f"{name}_{i + 1} is constant over the trials: the data carry "
                               "no information about the operator")
    return reasons


def data_reasons(trials: Sequence[Trial]) -> tuple[list[str], dict[str, object]]:
    """Questions 4 and 5 of the module docstring, which need the data only: the reasons
    and the figures."""
    reasons = constant_signals(trials)
    if reasons:
        return reasons, {}
    r_e, r_u = roughness(trials, "e"), roughness(trials, "u")
    for i in (0, 1):
        if not r_e[i] <= MAX_ROUGHNESS_RATIO * r_u[i]:
            reasons.append(f"component {i + 1}: the input e is rougher than the output u "
                           f"(R(e) = {r_e[i]:.3g} > {MAX_ROUGHNESS_RATIO:g} R(u), R(u) = "
                           f"{r_u[i]:.3g}); in the loop the "
                           "leader integrates the operator's command, so e is the smoother "
                           "signal: e and u are swapped or not the loop's signals")
    grow = growth(trials)
    if not grow <= MAX_GROWTH:
        reasons.append(f"the loop diverged: a signal's RMS grew {grow:.3g}x from the first "
                       f"to the last quarter of a trial (limit {MAX_GROWTH:g}x)")
    figures = {"growth": grow if np.isfinite(grow) else None,
               "roughness_e": [_finite(x) for x in r_e],
               "roughness_u": [_finite(x) for x in r_u],
               "max_roughness_ratio": MAX_ROUGHNESS_RATIO, "max_growth": MAX_GROWTH}
    return reasons, figures
