"""Do the data reject the model class? The identified class against one pole and one zero more.

The 95 % region of the identified parameters (:mod:`verify.identify.model.region`) and
every verdict drawn from it speak of the operator only if the operator's H(s) lies in
the class that was fitted (Section 4 takes the diagonal elements
(b1 s + b0)/(s^2 + a1 s + a0) and constant off-diagonal elements). When it does not, the
region still shrinks with the data, but around the class's best approximation, and an
exact verdict on that region can be confidently wrong about the operator: a passive
third-order operator in the paper's closed loop gave an exact region-wide refutation of
passivity at 3.5 rad/s, where the second-order fit bends below zero and the operator
does not.

**The test.** Output i is u_i = B_i(s)/A_i(s) e_i + c_ij e_j + noise. It is fitted by the
estimator's own output-error criterion (:func:`verify.identify.estimate.estimation.fit_output`,
the same identification trials, the state carried across trials) in the identified
structure P:Z and in the larger (P+1):(Z+1); the larger fit also starts from the
identified denominator times (s + p) for p on a grid (``EMBEDDED_POLES``), so that its
search begins where the classes meet (without those starts one open-loop fit stopped in a
local minimum worse than the smaller model, whose residual was coloured). The classes
are nested (a common factor s + p on both sides of h_i), so the likelihood ratio of
Gaussian output errors

    LR_i = N_eff,i log(V_i(P:Z) / V_i(P+1:Z+1))

(V the residual sums of squares, N_eff the effective sample size of the larger fit's
residual over the covariance's noise window, 1 s at any logging rate,
:func:`verify.identify.estimate.residual_tests.effective_samples`) is compared
with chi-square with 2 degrees of freedom, plus one for each trial whose initial state
is fitted (the larger model has one more state to start from in each such trial: on
open-loop data every trial, below). The nesting is not regular (p is not
identified under the smaller class), so the law is a guide; measured on 24 outputs of
in-class closed-loop logs at 120 Hz: LR 0.13-8.1, against 449 and 26 for the
third-order operator. The class is **rejected** when some output's p-value is below
``LEVEL`` = 5e-4 (1e-3 shared by the two outputs). When the larger fit fails (every
refinement on the search bound), that output's larger model is the identified one with
the factor (s + 1) on both sides: LR_i = 0, no evidence either way.

Rejection alone does not withdraw a verdict: noise-free logs of an in-class operator
reject the class too (the sampled loop is not exactly a continuous-time model of the
class; LR 31 on one such log), and a rejected class can still give the right answer.
What rejection asks is that the verdict also hold for the larger model fitted to the same
data (:mod:`verify.identify.robust.model_class_check`); this module only measures.

**Open-loop data.** Without feedback (e an excitation the operator's output does not
act on) the comparison above is miscalibrated by the joins between trials: on
multisine open-loop logs of an in-class operator whose trials each start from rest but
are logged back to back, carrying the state across the joins misfits every trial's start,
the larger class absorbs part of that misfit, and the class was rejected (likelihood
ratio 23 on output 1, p = 8e-6). Open-loop data are recognised by e being at least
``OPEN_LOOP_ROUGHNESS`` = 0.6 times as rough as u (:func:`looks_open_loop`; in the loop the
leader integrates the operator's command and e is the smoother signal: R(e)/R(u) was
0.03-0.06 on noisy and 0.31-0.45 on noise-free simulated closed-loop logs, 0.78-0.80 on the
open-loop multisine logs). There both classes are fitted afresh with each trial's
initial state estimated, which is unbiased when the input does not depend on the noise
(:mod:`verify.identify.estimate.estimation`), so the joins no longer matter; the test
says which form it used. The larger model then also has one more initial state per
trial, and its likelihood ratio has that many more degrees of freedom: counted with 2
alone, in-class operators on open-loop multisine logs of 4 trials gave likelihood
ratios of 4-14 (mean about 8, where chi-square with 2 degrees of freedom has 2) and
p-values down to 9e-4 against the level 5e-4; the larger model had moved its extra pole
to 0, where the free response it adds is a constant per trial. Counting 2 + T for T
fitted initial states was not enough: on 30 seeds x 2 in-class operators
(``benchmarks/bench_identify_open_loop.py``, 4 trials, noise 0.002 on e and u) the
likelihood ratio averaged 9.79 against the 6 of chi-square with 6 degrees of freedom
(quantiles 0.5, 0.9, 0.99: 8.7, 15.2, 21.6 against 5.3, 10.6, 16.8), 20 % of the outputs
had p < 0.05 and one experiment of 60 rejected the class (p = 1.9e-4). Likely causes,
not separated here: the extra pole's location is not identified under the smaller
class (the law of such a ratio has a heavier tail than chi-square), and the sensor noise
on the logged e, which the operator never saw, is something a larger model can partly
filter. On open-loop data
the ratio is therefore divided by ``OPEN_LOOP_SCALE`` before the chi-square law is
applied, the factor that bench measured (a Satterthwaite-style scaling, as the
effective sample size does for coloured residuals); it is an empirical calibration for
multisine logs like those, so the sentence calls the open-loop p-value calibrated on
simulated multisine logs, and the third-order operator is still rejected with it
(tests). Out of sample (seeds 31-50, 40 experiments) the raw ratio averaged 1.72 times
2 + T, 1 of 80 outputs had p < 0.05 after the scaling and none was rejected.

**Offsets.** When the estimate has a constant offset per output (an uncalibrated stick,
:attr:`verify.identify.estimate.result.Estimate.offsets`), both classes are fitted with
their own offset, so the comparison is of H(s) alone; the test reports the identified
offsets with their standard errors and whether each differs from zero at the 5 % level
(|o| > 1.96 se; a nuisance parameter, so "significant" only says the stick is off).

What flows in: the identification trials and the estimate. What flows out: a
:class:`ClassTest` (per output LR, p-value, N_eff; the larger model's parameters; the
offsets).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from verify.identify.estimate.estimation import BURN_IN, INITIAL, fit_output
from verify.identify.estimate.pem import OutputFit, covariance_lags
from verify.identify.estimate.prediction import element_parameters, fit_linear, lengths
from verify.identify.estimate.residual_tests import effective_samples
from verify.identify.estimate.result import CannotIdentifyError, Estimate, assemble
from verify.identify.estimate.structure import Structure
from verify.identify.estimate.trial_data import check_trials, output_data
from verify.inputs.experiment import Trial

__all__ = ["DEGREES", "LEVEL", "OPEN_LOOP_ROUGHNESS", "ClassTest", "larger_structure",
           "looks_open_loop", "model_class_test"]

#: Per-output significance level (1e-3 shared by the two outputs).
LEVEL = 5e-4
#: Parameters the larger class adds to each output (one numerator, one denominator).
DEGREES = 2
#: Smallest R(e) / R(u) (roughness, module docstring) taken as open-loop data.
OPEN_LOOP_ROUGHNESS = 0.6
#: What the open-loop likelihood ratio is divided by: its mean over 2 + T on open-loop
#: logs of in-class operators (module docstring).
OPEN_LOOP_SCALE = 1.63
#: Extra poles p (rad/s) of the larger fit's starts A(s)(s + p), below half the Nyquist
#: frequency (module docstring).
EMBEDDED_POLES = (0.3, 1.0, 3.0, 10.0, 30.0)
#: Two-sided normal quantile of the offsets' significance (5 %).
OFFSET_Z = 1.959963984540054


def looks_open_loop(trials: Sequence[Trial]) -> bool:
    """True if e is at least ``OPEN_LOOP_ROUGHNESS`` times as rough as u in every
    component (module docstring, "Open-loop data")."""
    from verify.identify.quality.identifiability import roughness

    r_e, r_u = roughness(trials, "e"), roughness(trials, "u")
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = r_e / r_u
    return bool(np.all(np.isfinite(ratio)) and np.all(ratio >= OPEN_LOOP_ROUGHNESS))


def larger_structure(structure: Structure) -> Structure:
    """(P+1):(Z+1) for a structure P:Z with constant off-diagonal elements."""
    return Structure.poles_zeros(structure.poles + 1, structure.zeros + 1)


@dataclass(frozen=True)
class ClassTest:
    """The test of the module docstring: ``structure`` against ``larger``, per output the
    likelihood ratio, its chi-square p-value and N_eff, and ``larger_theta`` (the larger
    model's parameters, in ``larger.names()`` order) with ``larger_covariance`` (the
    estimator's asymptotic covariance, outputs independent, times the identified
    estimate's few-trials factor); ``fallbacks`` names the outputs whose larger fit failed
    (their larger model is the identified one, LR 0, its covariance mapped alike);
    ``degrees`` per output the chi-square degrees of freedom (``DEGREES`` plus the
    trials whose initial state is fitted, module docstring)."""

    structure: Structure
    larger: Structure
    statistic: tuple[float, float]
    p_value: tuple[float, float]
    effective: tuple[float, float]
    larger_theta: tuple[float, ...]
    fallbacks: tuple[str, ...] = ()
    larger_covariance: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)),
                                          compare=False, repr=False)
    open_loop: bool = False
    offsets: tuple[float, ...] = ()
    offset_errors: tuple[float, ...] = ()
    degrees: tuple[int, int] = (DEGREES, DEGREES)

    @property
    def offsets_significant(self) -> tuple[bool, ...]:
        """Per output: the offset differs from zero at the 5 % level (|o| > 1.96 se)."""
        return tuple(abs(o) > OFFSET_Z * se for o, se in
                     zip(self.offsets, self.offset_errors, strict=True))

    def offset_text(self) -> str:
        """The offsets with standard errors and significance, or '' when none."""
        if not self.offsets:
            return ""
        parts = [f"u{i + 1} {o:+.3g} (se {se:.2g}, "
                 f"{'significant' if sig else 'not significant'})"
                 for i, (o, se, sig) in enumerate(zip(self.offsets, self.offset_errors,
                                                      self.offsets_significant, strict=True))]
        return ("offsets of the logged outputs, estimated with both classes: "
                + ", ".join(parts) + " at the 5 % level")

    @property
    def rejected(self) -> bool:
        """True if some output's p-value is below ``LEVEL``."""
        return any(p < LEVEL for p in self.p_value)

    def larger_text(self) -> str:
        return f"{self.larger.poles}:{self.larger.zeros}"

    def sentence(self) -> str:
        """One line: rejected or not, with the figures."""
        lr = ", ".join(f"{x:.4g}" for x in self.statistic)
        ps = ", ".join(f"{p:.3g}" for p in self.p_value)
        dof = (f"{self.degrees[0]}" if self.degrees[0] == self.degrees[1] else
               f"{self.degrees[0]}, {self.degrees[1]}")
        verdict = ("the data reject it" if self.rejected else "the data do not reject it")
        tail = "; ".join(self.fallbacks)
        return (f"{verdict} against {self.larger_text()} (one pole and one zero more per "
                f"diagonal element, same output-error criterion): likelihood ratio {lr}, "
                f"p = {ps} (chi-square, {dof} degrees of freedom; level {LEVEL:g} per "
                f"output)" + (f"; {tail}" if tail else "")
                + ("; open-loop data: both classes fitted with each trial's initial state "
                   f"estimated, the likelihood ratio divided by {OPEN_LOOP_SCALE:g} before the "
                   "chi-square law (a calibration measured on simulated multisine logs)"
                   if self.open_loop else "")
                + (f"; {self.offset_text()}" if self.offsets else ""))

    def to_json(self) -> dict[str, object]:
        """Figures to 4 significant digits (byte-reproducible)."""
        def four(x: float) -> float:
            return float(f"{x:.4g}")

        return {"larger_structure": self.larger_text(), "level": LEVEL,
                "degrees_of_freedom": list(self.degrees),
                "likelihood_ratio": [four(x) for x in self.statistic],
                "p_value": [four(x) for x in self.p_value],
                "effective_samples": [four(x) for x in self.effective],
                "rejected": self.rejected, "larger_fit_failed": list(self.fallbacks),
                "open_loop": self.open_loop,
                "open_loop_scale": OPEN_LOOP_SCALE if self.open_loop else 1.0,
                "larger_theta": [four(x) for x in self.larger_theta],
                "offsets": [four(x) for x in self.offsets],
                "offset_standard_errors": [four(x) for x in self.offset_errors],
                "offsets_significant": list(self.offsets_significant)}


def _embedding(b: np.ndarray, a: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(b', a', J): the element with the factor (s + 1) on both sides (a, a' monic without
    the leading 1) and the Jacobian J of (b', a', c) in (b, a, c); the map is affine."""
    nb, na = len(b), len(a)
    J = np.zeros((nb + 1 + na + 1 + 1, nb + na + 1))
    for k in range(nb):  # b'_k = b_k + b_{k-1}
        J[k, k] = J[k + 1, k] = 1.0
    for k in range(na):  # a'_k = a_k + a_{k-1}, a_{-1} = 1
        J[nb + 1 + k, nb + k] = J[nb + 2 + k, nb + k] = 1.0
    J[-1, -1] = 1.0
    den = np.convolve(np.r_[1.0, a], [1.0, 1.0])
    return np.convolve(b, [1.0, 1.0]), den[1:], J


def model_class_test(estimate: Estimate, trials: Sequence[Trial]) -> ClassTest | None:
    """The test of the module docstring on the identification ``trials`` of
    ``estimate``; None for a structure without constant off-diagonal elements."""
    from scipy.stats import chi2

    structure = estimate.structure
    if not structure.diagonal_with_constant_coupling:
        return None
    larger = larger_structure(structure)
    h = check_trials(trials, structure)
    skip = round(BURN_IN / h)
    theta = np.asarray(estimate.theta, float)
    cov = np.asarray(estimate.covariance, float) / max(float(estimate.inflation), 1e-300)
    per = structure.zeros + 1 + structure.poles
    open_loop = looks_open_loop(trials)
    offset = bool(estimate.offsets)
    stats, ps, effs, fits, fallbacks, dofs = [], [], [], [], [], []
    for i in (0, 1):
        data = output_data(trials, i, h, initial="estimate" if open_loop else INITIAL,
                           skip=skip, offset=offset)
        b, a, c = element_parameters(structure, theta, i)
        if open_loop:  # refit the class too: the estimate's denominator was carried
            try:
                with np.errstate(all="ignore"):
                    a = fit_output(data, structure.poles, structure.zeros).a
            except (CannotIdentifyError, np.linalg.LinAlgError, ValueError):
                pass
        residual = fit_linear(np.asarray(a, float), data, structure.zeros)[1]
        cost = float(residual @ residual)
        starts = [np.convolve(np.r_[1.0, np.asarray(a, float)], [1.0, p])[1:]
                  for p in EMBEDDED_POLES if p < 0.5 * math.pi / h]
        try:
            with np.errstate(all="ignore"):
                fit = fit_output(data, larger.poles, larger.zeros, more_starts=starts)
        except (CannotIdentifyError, np.linalg.LinAlgError, ValueError) as exc:
            fallbacks.append(f"output {i + 1}: no larger fit ({exc})")
            big_b, big_a, J = _embedding(np.asarray(b, float), np.asarray(a, float))
            idx = [*range(i * per, (i + 1) * per), 2 * per + i]
            fit = OutputFit(big_b, big_a, float(c), np.zeros((0, 0)), residual, cost,
                            J @ cov[np.ix_(idx, idx)] @ J.T, 0.0)
        big_cost = float(fit.residual @ fit.residual)
        spans = lengths(data, None)
        n_eff = effective_samples(fit.residual, spans, lags=covariance_lags(h, spans))
        if cost > 0 and big_cost > 0 and math.isfinite(cost) and math.isfinite(big_cost):
            lr = max(0.0, n_eff * math.log(cost / big_cost))
        else:
            lr = 0.0
        dof = DEGREES + sum(data.estimated(k) for k in range(len(data.y)))
        stats.append(lr)
        dofs.append(int(dof))
        ps.append(float(chi2.sf(lr / (OPEN_LOOP_SCALE if open_loop else 1.0), dof)))
        effs.append(float(n_eff))
        fits.append(fit)
    both = assemble(larger, fits, estimate.method, estimate.samples)
    return ClassTest(structure, larger, (stats[0], stats[1]), (ps[0], ps[1]),
                     (effs[0], effs[1]), tuple(float(x) for x in both.theta),
                     tuple(fallbacks), both.covariance * float(estimate.inflation),
                     open_loop, tuple(float(x) for x in estimate.offsets),
                     tuple(float(x) for x in estimate.offset_errors), (dofs[0], dofs[1]))
