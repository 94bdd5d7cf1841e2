"""Can the data reject passivity? The best passive model against the best model.

The class is the paper's Section 4 structure: H(s) 2 x 2 with diagonal elements
h_i(s) = (b1_i s + b0_i)/(s^2 + a1_i s + a0_i) and constant off-diagonal elements c12, c21.

**Which models of the class are passive** (positive real: analytic in Re s > 0 and
H(jw) + H(jw)^H >= 0 at every w that is not a pole). With c = c12 + c21,
H(jw) + H(jw)^H = [[2 Re h_1, c], [c, 2 Re h_2]] and, writing x = w^2,
Re h_i(jw) = N_i(x)/D_i(x) with D_i = |den_i(jw)|^2 and

    N_i(x) = b0_i a0_i + (a1_i b1_i - b0_i) x.

* Re h_i(jw) -> 0 as w -> infinity (strictly proper h_i) while the off-diagonal term
  stays c, so det(H + H^H) -> -c^2: passivity needs **c12 = -c21**;
* with c = 0 the Hermitian part is diagonal: it needs N_i(x) >= 0 for every x >= 0, a
  line in x, so **b0_i a0_i >= 0 and a1_i b1_i >= b0_i**;
* analytic in Re s > 0 with no pole on the axis (the strict form, which the fit keeps):
  s^2 + a1_i s + a0_i Hurwitz, **a1_i > 0 and a0_i > 0**; then b0_i a0_i >= 0 is
  **b0_i >= 0**.

Together: c12 = -c21, a1_i > 0, a0_i > 0, b0_i >= 0, a1_i b1_i >= b0_i (which gives
b1_i >= 0). These are also sufficient: the conditions make each h_i positive real and
the constant skew part adds nothing to H + H^H. (The tests check this characterisation
against the repository's exact gate on random instances on both sides.)

**The constrained fit** uses the estimator's own output-error criterion and simulation
(:mod:`verify.identify.estimate.prediction`: the model driven by the logged e, state carried
across trials, the burn-in left out). With b0_i = p_i and b1_i = (p_i + q_i)/a1_i,
p_i, q_i >= 0, and c21 = -c12, the simulated output is linear in (p_1, q_1, p_2, q_2, c12)
for fixed denominators, so those are solved by bounded linear least squares
(``scipy.optimize.lsq_linear``) and only (log a1_i, log a0_i) are searched (variable
projection, as the unconstrained fit does). The unconstrained fit is recomputed in the
same way (with free numerators and free c12, c21) so that the two costs are comparable
and nested. Both fits carry the estimator's nuisance parameters, unconstrained: the
offset of each output when the estimate has one (an uncalibrated stick is no part of
H(s) and says nothing of its passivity), and the initial state of each trial whose
state the estimator fits (a trial that begins mid-response after a pause or at the
log's start, :func:`verify.identify.estimate.trial_data.fresh_starts`). Without them a
mid-response trial would be simulated from rest in both fits, and the misfit of its
start would weigh on the comparison as if it were evidence about H(s).

**The test.** The likelihood ratio of Gaussian output errors with a variance per output,
LR = sum_i N_i log(V_i(passive) / V_i(free)), V_i the residual sums of squares, with N_i
the effective number of samples (N_i divided by the Bartlett-weighted sum of the free
fit's residual autocorrelation over the covariance's noise window, 1 s at any logging
rate (:func:`verify.identify.estimate.pem.covariance_lags`), >= 1: the protocol's filtering and
decimation colour the residuals, and counting correlated samples as independent would
overstate the evidence). Under passivity LR is asymptotically chi-bar-squared (a
mixture of chi-square laws with 0..q degrees of freedom: M. J. Silvapulle and P. K. Sen,
*Constrained Statistical Inference*, Wiley 2005, Ch. 3); its tail is at most that of
chi-square with q = 5 (the equality and the four inequalities), which gives a
conservative p-value: the data reject passivity only when p < ``ALPHA``.

**When the data carry no information** the test is not run: when the free model is not
distinguishable from no response at all (H = 0, the same likelihood ratio against the
zero model with 10 degrees of freedom, p >= ``INFORMATIVE``), the denominators are not
identified, the regularity behind the chi-square law fails (pure noise outputs gave
p = 0.016 in the hostile tests), and the answer is that the data cannot test passivity.
For the same reason that comparison with H = 0 is itself no proof of information: the
denominator search is a supremum over parameters H = 0 does not identify, and once the
estimator's starts were ranked inside their search box, the free fit of the hostile test's
pure-noise outputs beat H = 0 at p = 2.8e-7 while explaining 1-1.5 % of them. So the
free model must also explain at least the identifiability gate's minimum share of every
output (``MIN_FIT``, 3 %, :mod:`verify.identify.quality.identifiability`; the command
only asks the test where that gate passed).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np

from verify.errors import VerifyInputError
from verify.identify.estimate.estimation import BURN_IN as ESTIMATOR_BURN_IN
from verify.identify.estimate.pem import covariance_lags
from verify.identify.estimate.prediction import design, used
from verify.identify.estimate.residual_tests import effective_samples
from verify.identify.estimate.structure import Structure
from verify.identify.estimate.trial_data import OutputData, check_trials, output_data
from verify.identify.quality.identifiability import MIN_FIT
from verify.inputs.experiment import Trial
from verify.progress import silent

#: Significance level of the test.
ALPHA = 0.05
#: The free model must beat the zero model at this p-value for the test to run.
INFORMATIVE = 1e-6
#: Constraints of the passive class (c12 = -c21, b0_i >= 0, a1_i b1_i >= b0_i).
CONSTRAINTS = 5
#: Burn-in left out of the criterion, seconds: the estimator's own default.
BURN_IN = ESTIMATOR_BURN_IN
#: The denominator search's Jacobian (central differences, relative step) and stopping
#: tolerances. The passive model is written to the digits its standard errors justify
#: (parts in 1e5 to 1e6 here). The simulated columns carry float noise of a few parts in
#: 1e14 that differs between BLAS builds; scipy's default forward differences (step
#: 1.5e-8) turn it into gradient noise of 1e-6, and the search stopped at points that
#: differed by 1e-6 between builds, enough to change a written digit on another machine.
DIFFERENCE_STEP = 1e-4
TOLERANCE = 1e-12
MAX_EVALUATIONS = 400


def passive_constraints(theta: Sequence[Any]) -> list[str]:
    """The constraints of the module docstring that ``theta`` (paper structure order,
    exact or float) violates; empty when the model is passive."""
    if len(theta) != 10:
        raise VerifyInputError(f"the paper's structure has 10 parameters, got {len(theta)}")
    bad = []
    if theta[8] != -theta[9]:
        bad.append("c12 = -c21")
    for i in range(2):
        b1, b0, a1, a0 = theta[4 * i:4 * i + 4]
        k = i + 1
        if not a1 > 0:
            bad.append(f"a1_{k} > 0")
        if not a0 > 0:
            bad.append(f"a0_{k} > 0")
        if not b0 >= 0:
            bad.append(f"b0_{k} >= 0")
        if not a1 * b1 >= b0:
            bad.append(f"a1_{k} b1_{k} >= b0_{k}")
    return bad


@dataclass(frozen=True)
class PassivityTest:
    """The best passive model against the best model of the class, on the same data."""

    theta_free: np.ndarray
    theta_passive: np.ndarray
    cost_free: tuple[float, float]  # residual sums of squares per output
    cost_passive: tuple[float, float]
    samples: tuple[int, int]
    effective_samples: tuple[float, float]
    statistic: float
    dof: int
    p_value: float
    fit_free: tuple[float, float]  # % (Section 4 fit ratio on the identification data)
    fit_passive: tuple[float, float]
    p_zero: float = 0.0  # the free model against H = 0 (module docstring)

    @property
    def informative(self) -> bool:
        """The free model beats H = 0 and explains at least ``MIN_FIT`` % of every output
        (module docstring)."""
        return self.p_zero < INFORMATIVE and min(self.fit_free) >= MIN_FIT

    @property
    def rejected(self) -> bool:
        return self.informative and self.p_value < ALPHA

    def sentence(self) -> str:
        p = f"p = {self.p_value:.3g}"
        if not self.informative and self.p_zero >= INFORMATIVE:
            return ("the data cannot test passivity: the best model is not distinguishable "
                    f"from no response at all (p = {self.p_zero:.3g} against H = 0)")
        if not self.informative:
            fits = ", ".join(f"{x:.3g}" for x in self.fit_free)
            return ("the data cannot test passivity: the best model explains only "
                    f"{fits} % of the outputs (at least {MIN_FIT:g} % each is needed; its "
                    f"p = {self.p_zero:.3g} against H = 0 is no evidence where H = 0 leaves "
                    "the denominators unidentified)")
        if self.rejected:
            return (f"the data reject passivity ({p}, likelihood ratio {self.statistic:.4g}, "
                    f"chi-square bound with {self.dof} degrees of freedom)")
        return (f"a passive model explains the data as well ({p}, likelihood ratio "
                f"{self.statistic:.4g}, chi-square bound with {self.dof} degrees of "
                "freedom)")

    def to_json(self) -> dict[str, Any]:
        return {"informative": self.informative, "p_zero": self.p_zero,
                "rejected": self.rejected, "p_value": self.p_value,
                "statistic": self.statistic, "dof": self.dof, "alpha": ALPHA,
                "sentence": self.sentence(),
                "theta_free": [float(x) for x in self.theta_free],
                "theta_passive": [float(x) for x in self.theta_passive],
                "cost_free": list(self.cost_free), "cost_passive": list(self.cost_passive),
                "samples": list(self.samples),
                "effective_samples": [round(x, 3) for x in self.effective_samples],
                "fit_free": list(self.fit_free), "fit_passive": list(self.fit_passive)}


def _outputs(trials: Sequence[Trial], structure: Structure, burn_in: float,
             offset: bool = False) -> tuple[OutputData, OutputData]:
    h = check_trials(trials, structure, what="the passivity test")
    skip = round(burn_in / h)
    return tuple(output_data(trials, i, h, initial="carry", skip=skip,  # type: ignore
                             offset=offset) for i in (0, 1))


def nuisance_columns(data: OutputData, poles: int = 2) -> list[int]:
    """Columns of :func:`verify.identify.estimate.prediction.design` (zeros = 1) that are
    nuisance parameters: the offset, when estimated, and the initial states of the
    trials whose state is fitted (module docstring)."""
    p = data.shared(1)
    out = list(range(3, p))
    for k in range(len(data.y)):
        if data.estimated(k):
            out += list(range(p + k * poles, p + (k + 1) * poles))
    return out


def _columns(a1: float, a0: float, data: OutputData) -> tuple[np.ndarray, np.ndarray,
                                                              np.ndarray]:
    """(s/A e_i, 1/A e_i, e_j, then the nuisance columns) over the used samples, and y_i
    over them."""
    X = design(np.array([a1, a0]), data, 1)
    Xu = used(X[:, [0, 1, 2, *nuisance_columns(data)]], data, None)
    y = used(np.concatenate(data.y), data, None)
    return Xu, y, X


def _inner(x: np.ndarray, data: tuple[OutputData, OutputData], weights: np.ndarray,
           passive: bool) -> tuple[np.ndarray, np.ndarray, list[np.ndarray]]:
    """For denominators exp(x) = (a1_1, a0_1, a1_2, a0_2): the linear parameters, the
    stacked weighted residual and the per-output residuals."""
    from scipy.optimize import lsq_linear

    a = np.exp(x)
    blocks, ys = [], []
    for i in range(2):
        Xu, y, _ = _columns(a[2 * i], a[2 * i + 1], data[i])
        blocks.append(Xu)
        ys.append(y)
    if not all(np.all(np.isfinite(B)) for B in blocks):
        return np.full(10, np.nan), np.full(sum(len(y) for y in ys), 1e6), []
    n1, n2 = len(ys[0]), len(ys[1])
    m1, m2 = blocks[0].shape[1] - 3, blocks[1].shape[1] - 3  # nuisance columns
    rows_of = (slice(0, n1), slice(n1, n1 + n2))
    if passive:  # columns for (p1, q1, p2, q2, c12); c21 = -c12; then the nuisance
        M = np.zeros((n1 + n2, 5 + m1 + m2))
        for i, (B, rows) in enumerate(zip(blocks, rows_of, strict=True)):
            a1 = a[2 * i]
            M[rows, 2 * i] = B[:, 0] / a1 + B[:, 1]
            M[rows, 2 * i + 1] = B[:, 0] / a1
            M[rows, 4] = B[:, 2] * (1.0 if i == 0 else -1.0)
        lower = np.r_[[0, 0, 0, 0], np.full(1 + m1 + m2, -np.inf)]
        first = 5
    else:  # (b1_1, b0_1, c12, b1_2, b0_2, c21), then the nuisance
        M = np.zeros((n1 + n2, 6 + m1 + m2))
        M[:n1, :3] = blocks[0][:, :3]
        M[n1:, 3:6] = blocks[1][:, :3]
        lower = np.full(6 + m1 + m2, -np.inf)
        first = 6
    M[:n1, first:first + m1] = blocks[0][:, 3:]
    M[n1:, first + m1:] = blocks[1][:, 3:]
    w = np.r_[np.full(n1, weights[0]), np.full(n2, weights[1])]
    Mw, yw = M * w[:, None], np.r_[ys[0], ys[1]] * w
    scale = np.linalg.norm(Mw, axis=0)
    scale[scale == 0] = 1.0
    if passive:
        sol = lsq_linear(Mw / scale, yw, bounds=(lower * scale, np.full(len(lower), np.inf)),
                         method="bvls")
        beta = sol.x / scale
    else:  # unbounded: the direct least-squares solution, not an iteration's stopping point
        beta = np.linalg.lstsq(Mw / scale, yw, rcond=None)[0] / scale
    r = yw - Mw @ beta
    res = [r[:n1] / weights[0], r[n1:] / weights[1]]
    if passive:
        p1, q1, p2, q2, c = beta[:5]
        theta = np.array([(p1 + q1) / a[0], p1, a[0], a[1],
                          (p2 + q2) / a[2], p2, a[2], a[3], c, -c])
    else:
        theta = np.array([beta[0], beta[1], a[0], a[1], beta[3], beta[4], a[2], a[3],
                          beta[2], beta[5]])
    return theta, r, res


def _fit(data, weights, start: np.ndarray, passive: bool):
    from scipy.optimize import least_squares

    def fun(x):
        return _inner(x, data, weights, passive)[1]

    best = None
    for x0 in (start, start + np.array([0.3, 0.0, 0.3, 0.0]),
               start - np.array([0.3, 0.0, 0.3, 0.0])):
        sol = least_squares(fun, x0, method="trf", x_scale=1.0, max_nfev=MAX_EVALUATIONS,
                            jac="3-point", diff_step=DIFFERENCE_STEP, xtol=TOLERANCE,
                            ftol=TOLERANCE, gtol=TOLERANCE)
        if best is None or sol.cost < best.cost:
            best = sol
    return _inner(best.x, data, weights, passive)


def _effective(residual: np.ndarray, data: OutputData) -> float:
    """N divided by the Bartlett-weighted residual autocorrelation sum (>= 1)."""
    spans = [len(own) - data.skip for own in data.own]
    return effective_samples(residual, spans, lags=covariance_lags(data.h, spans))


def _fit_ratio(y: np.ndarray, residual: np.ndarray) -> float:
    """Section 4's fit ratio, %: 100 (1 - |y - yhat| / |y - mean y|)."""
    d = np.linalg.norm(y - y.mean())
    return float(100 * (1 - np.linalg.norm(residual) / d)) if d > 0 else float("nan")


def passivity_test(trials: Sequence[Trial], theta: Sequence[float], *,
                   structure: Structure | None = None, burn_in: float = BURN_IN,
                   offset: bool = False,
                   stage: Callable[[str], None] = silent) -> PassivityTest:
    """Fit the best passive and the best free model of the paper's class to the
    (identification) ``trials``, starting from the estimate ``theta``; compare them by the
    likelihood-ratio test of the module docstring. ``offset``: both fits estimate a
    constant offset per output (as the estimator did); ``stage`` is told each of the four
    fits as it starts (progress lines)."""
    from scipy.stats import chi2

    structure = structure or Structure.paper()
    if structure != Structure.paper():
        raise VerifyInputError("the passivity test handles the paper's structure "
                               "(diagonal (b1 s + b0)/(s^2 + a1 s + a0), constant "
                               "off-diagonal elements)")
    data = _outputs(trials, structure, burn_in, offset)
    theta = np.asarray(theta, float)
    den = np.array([theta[2], theta[3], theta[6], theta[7]])
    start = np.log(np.clip(den, 1e-3, None))
    ones = np.ones(2)
    stage("passivity test: best model of the class, equal weights (fit 1 of 4)")
    free, _, res = _fit(data, ones, start, passive=False)
    sig = np.array([max(math.sqrt(float(r @ r) / len(r)), 1e-300) for r in res])
    stage("passivity test: best model of the class, weighted by output (fit 2 of 4)")
    free, _, res_free = _fit(data, 1 / sig, start, passive=False)
    stage("passivity test: best passive model (fit 3 of 4)")
    pas, _, res_pas = _fit(data, 1 / sig, np.log(np.clip(
        [free[2], free[3], free[6], free[7]], 1e-3, None)), passive=True)
    sig_p = np.array([max(math.sqrt(float(r @ r) / len(r)), 1e-300) for r in res_pas])
    stage("passivity test: best passive model, reweighted (fit 4 of 4)")
    pas2, _, res_pas2 = _fit(data, 1 / sig_p, np.log([pas[2], pas[3], pas[6], pas[7]]),
                             passive=True)
    if _lr(res_pas2, res_free, [1.0, 1.0]) < _lr(res_pas, res_free, [1.0, 1.0]):
        pas, res_pas = pas2, res_pas2
    V_free = tuple(float(r @ r) for r in res_free)
    V_pas = tuple(float(r @ r) for r in res_pas)
    n_eff = tuple(_effective(r, d) for r, d in zip(res_free, data, strict=True))
    stat = max(0.0, _lr(res_pas, res_free, n_eff))
    p_value = float(chi2.sf(stat, CONSTRAINTS))
    ys = [used(np.concatenate(d.y), d, None) for d in data]
    zero = _lr(ys, res_free, n_eff)
    p_zero = float(chi2.sf(max(zero, 0.0), 10))
    return PassivityTest(
        free, pas, V_free, V_pas, (len(res_free[0]), len(res_free[1])), n_eff, stat,  # type: ignore[arg-type]
        CONSTRAINTS, p_value,
        tuple(_fit_ratio(y, r) for y, r in zip(ys, res_free, strict=True)),  # type: ignore[arg-type]
        tuple(_fit_ratio(y, r) for y, r in zip(ys, res_pas, strict=True)),  # type: ignore[arg-type]
        p_zero)


def _lr(res_pas, res_free, n_eff) -> float:
    out = 0.0
    for rp, rf, n in zip(res_pas, res_free, n_eff, strict=True):
        vp, vf = float(rp @ rp), float(rf @ rf)
        if vf <= 0:
            return math.inf if vp > 0 else 0.0
        out += n * math.log(vp / vf)
    return out


def passive_literals(theta: Sequence[float],
                     errors: Sequence[float] | None = None) -> list[Fraction]:
    """Short decimals near the passive fit that satisfy the constraints *exactly*: each
    to the precision the unconstrained estimate's standard error justifies (when
    ``errors`` are given; :func:`verify.identify.model.model_writer.coefficient_text`), c21
    written as -c12, b1_i raised in its last digit until a1_i b1_i >= b0_i."""
    from verify.identify.model.model_writer import DIGITS, SE_DIGITS, coefficient_text

    errs = list(errors) if errors is not None else [None] * len(theta)
    lits = [Fraction(coefficient_text(float(x), e)) for x, e in zip(theta, errs, strict=True)]
    lits[9] = -lits[8]
    for i in range(2):
        b1, b0, a1 = 4 * i, 4 * i + 1, 4 * i + 2
        if lits[b0] < 0:
            lits[b0] = Fraction(0)
        e = errs[b1]
        if e is not None and math.isfinite(e) and e > 0:
            step = Fraction(10) ** (math.floor(math.log10(e)) - SE_DIGITS)
        else:
            step = Fraction(10) ** (math.floor(math.log10(abs(float(lits[b1])) or 1.0))
                                    - DIGITS + 1)
        while lits[a1] * lits[b1] < lits[b0]:
            lits[b1] += step
    return lits


def passive_model_text(name: str, test: PassivityTest, *, description: str = "",
                       errors: Sequence[float] | None = None) -> str:
    """The passive fit as a ``verify gate`` model file (its decimals satisfy the passivity
    constraints exactly; the gate certifies it), to the digits ``errors`` (the
    unconstrained estimate's standard errors) justify, its figures to 4 digits."""
    from verify.identify.model.model_writer import FIGURE_DIGITS, canonical, model_text

    lits = passive_literals(test.theta_passive, errors)
    bad = passive_constraints(lits)
    if bad:
        raise VerifyInputError(f"the passive fit violates {', '.join(bad)} (denominator "
                               "on its bound): no passive model file")
    table = {"method": "passive output-error fit (verify.identify.robust.passive_fit)",
             "passivity_constraints": "c12 = -c21, a1_i > 0, a0_i > 0, b0_i >= 0, "
                                      "a1_i b1_i >= b0_i",
             "likelihood_ratio": canonical(test.statistic, FIGURE_DIGITS),
             "p_value": canonical(test.p_value, FIGURE_DIGITS),
             "rejected": test.rejected,
             "fit_identification": [canonical(f, FIGURE_DIGITS) for f in test.fit_passive]}
    text, _ = model_text(name, Structure.paper(), [float(x) for x in lits], table,
                         description=description or "best passive model of the paper's "
                         "class for the logs (verify identify)")
    return text


PASSIVE_MODEL_FILE = "passive_model.toml"


def test_or_reason(estimate: Any, trials: Sequence[Trial],
                   stage: Callable[[str], None] = silent) -> PassivityTest | str:
    """The passivity test of an estimate on its identification trials (with offsets when
    the estimate has them), or why there is none (a structure other than the paper's, or
    a fit that fails: one line)."""
    if estimate.structure != Structure.paper():
        return (f"the passivity test handles the paper's structure only (not "
                f"{estimate.structure.kind})")
    try:
        return passivity_test(trials, estimate.theta, offset=bool(estimate.offsets),
                              stage=stage)
    except (VerifyInputError, ValueError, np.linalg.LinAlgError) as exc:
        return f"no passive fit: {exc}"


def summary_lines(test: PassivityTest | str | None, path: Any) -> list[str]:
    """What ``verify identify`` prints about the test."""
    if test is None:
        return []
    if isinstance(test, str):
        return [f"  passivity test: {test}"]
    if not test.informative:
        return [f"  passivity test: {test.sentence()}; no passive model written"]
    fits = ", ".join(f"{x:.2f}" for x in test.fit_passive)
    return [f"  passivity test (best passive model of the class vs the best model, same "
            f"output-error criterion): {test.sentence()}",
            f"  best passive model: {path} (fit on identification data {fits} %; "
            "c12 = -c21, b0 >= 0, a1 b1 >= b0, so `verify gate` certifies it)"]


__all__ = [
    "ALPHA",
    "CONSTRAINTS",
    "INFORMATIVE",
    "PASSIVE_MODEL_FILE",
    "PassivityTest",
    "nuisance_columns",
    "passive_constraints",
    "passive_literals",
    "passive_model_text",
    "passivity_test",
    "summary_lines",
    "test_or_reason",
]
