"""Continuous-time estimation of H(s) from closed-loop trials (Section 4, "Human Modeling").

:func:`estimate_model` estimates the structures with constant off-diagonal elements
(:meth:`Structure.paper`, :meth:`Structure.poles_zeros`) output by output: output i is
u_i = B_i(s)/A_i(s) e_i + c_ij e_j + noise. Method ``"riv+pem"`` (the default):

1. starting denominators: SRIVC (:mod:`verify.identify.estimate.riv`), a refined
   instrumental-variable estimate, from a few first prefilters (s + lam)^n, and a grid
   of stable denominators (:func:`starting_denominators`);
2. output-error prediction-error refinement (:mod:`verify.identify.estimate.pem`) from the
   starting points of least cost, poles kept below half the Nyquist frequency, each
   trial started as described below; the refinement of least cost is kept
   (:func:`fit_output` says why the grid is needed).

The covariance held in :attr:`Estimate.covariance` by default is the asymptotic
prediction-error covariance per output (outputs independent), in its colour-robust
sandwich form (:mod:`verify.identify.estimate.pem`): sigma^2 (J^T J)^-1 for white residuals,
corrected for the colour the protocol's decimation gives the noise. It costs one
Jacobian and is what the theory gives to O(1/N). The bootstrap over trials
(:func:`verify.identify.estimate.bootstrap.bootstrap`) is the alternative when the noise is in
doubt; it needs many re-estimates and, with the paper's six identification trials, has
few distinct resamples.

How far to trust the intervals (benchmarks/bench_identify_coverage.py, 50 simulated
closed-loop experiments per setting, asymptotic covariance): with 12 identification
trials every parameter's 95 % interval held the truth in 90-100 % of them; with the
paper's 6, the low-frequency pair b0_1, a0_1 only in 86 % (the others 90-96 %). The
asymptotic formula misses a finite-sample effect of the loop: in a weakly determined
direction part of the excitation is operator noise fed back through the leader, so the
information and the error are correlated. It fades as trials are added; with 6 trials
the standard errors in that direction were about 20 % too small. The covariance is
therefore widened for few trials (``inflate=True``, the default): multiplied by
:func:`few_trials_factor` = T / (T - 2) for T >= 4 identification trials (distinct trial
ids), 3 below: standard errors x 1.22 with 6 trials, x 1.10 with 12, -> 1 as trials are
added. The factor is empirical, chosen to cover the 20 % shortfall measured with 6
trials while vanishing with the data; its effect on coverage is what the benchmark
prints.

Start of each trial (default ``initial="carry"``, ``burn_in=0``): the model enters
each trial in the state it left the previous one in, carried to the reference change
and coasted with zero input over the dead time between them (the protocol of Section 4
removes that dead time because the operator has not yet reacted to the new reference),
the first trial of a log from rest (:func:`verify.identify.estimate.trial_data.dead_time_gaps`
says which trials follow on). No sample is left out of the criterion: the first second
after the start event carries the step response, the most informative part of a trial,
and leaving it out (``burn_in=1.0``, the earlier default) made the estimates of b1 and
a1 about 3 times less accurate on simulated noisy experiments (benchmarks/
bench_identify_methods.py), while the edge transient of the anti-aliasing filter it
guarded against moves noise-free estimates at 20 Hz by about 1e-4 relative only.
Starting every trial from rest (``initial="zero"``) leaves the operator's state at the
end of the previous trial as an unexplained transient that resembles the step response,
and on simulated experiments it biased the coupling estimates enough to
lower the coverage of their intervals (the joint 95 % region held the true parameters in
74 % of 100 experiments from rest, 80 % carried). Estimating each trial's initial state
instead (``initial="estimate"``) is exact for open-loop data but biased in closed loop:
the initial state is fitted from the same first seconds that carry the step response,
and in the loop the input there already depends on the noise, so the projection that
eliminates the initial state correlates the regressors with the noise (an
incidental-parameter bias that does not shrink with more trials); it also triples the
spread of the estimates. Measured on simulated experiments
(benchmarks/bench_identify_coverage.py).

Offsets (``offset=True``, the default ``OFFSET``): an uncalibrated stick logs u_i with a
constant added, which no model of the class produces from e (at rest, e = 0 gives
u = 0), so the fit bends H(s) to explain it. Fitted without an offset term, 0.1 on the logged u_1
of a simulated experiment moved a0_1 168 standard errors off its true value. The offset
o_i is one more linear column (all ones) of output i's output-error fit
(:func:`verify.identify.estimate.prediction.design`), solved with the numerator and the
coupling; its covariance block is marginalised out, so H(s)'s covariance (and the 95 %
region and every verdict drawn from it) accounts for it, and it is stored on the
:class:`Estimate` (``offsets``, ``offset_errors``), never in H(s). On logs without an
offset the term costs little: ``benchmarks/bench_identify_offset.py`` measures coverage
and error with and without it, on data with and without an offset (results in the
README, "Offsets").

The state-space structure ``order:N`` is not yet supported (one-line error).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from verify.errors import VerifyInputError
from verify.identify.estimate.pem import OutputFit, ar_start, denominator_bounds, refine
from verify.identify.estimate.prediction import INITIAL_STATES, fit_linear, lengths
from verify.identify.estimate.residual_tests import whiteness
from verify.identify.estimate.result import CannotIdentifyError, Estimate, assemble
from verify.identify.estimate.riv import srivc
from verify.identify.estimate.structure import Structure
from verify.identify.estimate.trial_data import OutputData, check_trials, output_data
from verify.inputs.experiment import Trial

__all__ = ["METHODS", "estimate_model", "few_trials_factor", "first_prefilters"]

#: Highest order p of the AR noise model 1/D(q) tried when the output error is coloured.
MAX_NOISE_ORDER = 6

#: Most starting points refined per output (when the first ones end on the search bound).
MAX_STARTS = 8

#: How the estimator treats the start of a trial, see :func:`estimate_model`.
INITIAL = "carry"
BURN_IN = 0.0  # seconds
#: Whether a constant offset per output is estimated by default (module docstring).
OFFSET = True

#: Estimation methods: name -> description.
METHODS = {
    "riv+pem": "SRIVC initial estimate, then output-error prediction-error refinement",
    "riv+bj": "as riv+pem, then an AR noise model (Box-Jenkins) when the output error is "
              "coloured",
    "arx+oe": "baseline: discrete ARX least squares, then output-error least squares "
              "with zero initial states (verify.identify.estimate.baseline)",
}


def first_prefilters(h: float) -> tuple[float, ...]:
    """The poles lam (rad/s) of the first SRIVC prefilters (s + lam)^n for step h.

    A human operator's bandwidth is a few rad/s; three prefilters a factor 4 apart,
    below a fifth of the Nyquist frequency pi/h, cover it.
    """
    return tuple(lam for lam in (0.5, 2.0, 8.0) if lam < 0.2 * np.pi / h) or (0.1 * np.pi / h,)


def starting_denominators(poles: int, h: float) -> list[np.ndarray]:
    """A grid of stable denominators (a_{n-1}..a_0) to start the refinement from.

    Poles at -w (all n), and for n >= 2 a pair with damping 0.4 at natural frequency w
    with the other poles at -w, for w from 0.3 rad/s up to a tenth of the Nyquist
    frequency pi/h, a factor 3 apart.
    """
    out = []
    w = 0.3
    while w <= max(0.1 * np.pi / h, 0.3):
        out.append(np.real(np.poly(-w * np.ones(poles)))[1:])
        if poles >= 2:
            pair = np.array([1.0, 0.8 * w, w * w])
            out.append(np.real(np.polymul(pair, np.poly(-w * np.ones(poles - 2))))[1:])
        w *= 3.0
    return out


def _cost(a: np.ndarray, data: OutputData, zeros: int) -> float:
    r = fit_linear(a, data, zeros)[1]
    value = float(r @ r)
    return value if np.isfinite(value) else np.inf


def fit_output(data: OutputData, poles: int, zeros: int, *, starts: int = 3,
               noise: bool = False, more_starts: Sequence[np.ndarray] = ()) -> OutputFit:
    """The output-error estimate of one output, refined from the best starting points.

    Candidates: the SRIVC denominators from each first prefilter, the grid of
    :func:`starting_denominators` and ``more_starts`` (denominators a_{n-1}..a_0 the
    caller knows to be good, e.g. a smaller model's times one more factor). The
    ``starts`` candidates of least output-error cost (after eliminating the linear
    parameters) are refined; the refinement of least cost that ends inside the search
    box is kept (further candidates are refined, up to MAX_STARTS, until one does),
    then given a noise model if its residual is coloured (:func:`with_noise_model`,
    when ``noise``). The grid is there because in this loop
    SRIVC can be ill-conditioned: the leader is noise-free, so u_h is close to a
    deterministic function of the derivative of e and the equation-error regressors of
    u_h and e are nearly collinear; the output-error criterion, whose predictor is
    causal, separates H(s) from that inverse relation (the operator noise at a sample
    is not yet in e). On decimated data that separation weakens (the protocol's
    zero-phase anti-aliasing filter lets e look slightly ahead), and a refinement can run
    to the bound of the search box (:func:`verify.identify.estimate.pem.denominator_bounds`),
    where the model imitates the leader's inverse; such a refinement is not a minimum
    of the criterion inside the model class and is set aside.
    """
    candidates = []
    for lam in first_prefilters(data.h):
        a0 = srivc(data, poles, zeros, lam=lam)
        if np.all(np.isfinite(a0)):
            candidates.append(a0)
    candidates += starting_denominators(poles, data.h)
    candidates += [np.asarray(a0, float) for a0 in more_starts if len(a0) == poles]
    upper = denominator_bounds(poles, data.h)
    # ranked where the refinement starts: inside the search box (an unstable SRIVC
    # candidate is clipped there, and its cost before clipping says nothing of that point)
    candidates = [np.clip(a0, 0.0, upper * (1 - 1e-9)) for a0 in candidates]
    costs = [_cost(a0, data, zeros) for a0 in candidates]
    order = [k for k in np.argsort(costs, kind="stable") if np.isfinite(costs[k])]
    best: OutputFit | None = None
    tried = 0
    for k in order:
        if tried >= MAX_STARTS or (tried >= starts and best is not None):
            break
        tried += 1
        try:
            fit = refine(data, candidates[k], zeros)
        except (np.linalg.LinAlgError, ValueError):
            continue
        if not np.isfinite(fit.cost) or np.any(fit.a >= (1 - 1e-6) * upper):
            continue  # on the search bound: the leader's inverse, not the operator
        if best is None or fit.cost < best.cost:
            best = fit
    if best is None:
        raise CannotIdentifyError(
            f"output {data.output + 1}: every refinement ran to the bound of the search "
            f"(poles at half the Nyquist frequency) or failed; the data do not determine a "
            f"{poles}-pole model (try a higher --rate or more trials)")
    return with_noise_model(data, best, zeros) if noise else best


def _white(fit: OutputFit, data: OutputData) -> bool:
    parts, start = [], 0
    for N in lengths(data, fit.noise if len(fit.noise) > 1 else None):
        parts.append(fit.residual[start:start + N])
        start += N
    try:
        return whiteness(parts).passed
    except VerifyInputError:
        return True  # too short to test: keep the simpler model


def with_noise_model(data: OutputData, fit: OutputFit, zeros: int) -> OutputFit:
    """``fit`` itself if its output error passes the whiteness test, else the Box-Jenkins
    refinement with AR(p) noise 1/D(q) for the smallest p <= MAX_NOISE_ORDER whose
    prediction errors pass it (the least BIC among them if none does).

    The protocol's anti-aliasing filter colours the operator noise of the decimated data;
    in closed loop a wrong noise model biases the direct prediction-error estimate, and
    the covariance sigma^2 (J^T J)^-1 needs white prediction errors (Ljung 1999, Sec.
    9.3 and 13.4).
    """
    if _white(fit, data):
        return fit
    best, best_bic = None, np.inf
    for order in range(1, MAX_NOISE_ORDER + 1):
        try:
            bj = refine(data, fit.a, zeros, ar_start(data, fit.a, zeros, order))
        except (np.linalg.LinAlgError, ValueError):
            continue
        if not np.isfinite(bj.cost):
            continue
        if _white(bj, data):
            return bj
        N = bj.residual.shape[0]
        bic = N * np.log(bj.cost / N) + (len(fit.b) + len(fit.a) + 1 + order) * np.log(N)
        if bic < best_bic:
            best, best_bic = bj, bic
    return fit if best is None else best


def few_trials_factor(trials: int) -> float:
    """The covariance factor for ``trials`` identification trials (module docstring):
    T / (T - 2) for T >= 4, 3 for fewer."""
    if not (isinstance(trials, int) and trials >= 1):
        raise VerifyInputError(f"the number of trials must be a positive integer, got "
                               f"{trials!r}")
    return trials / (trials - 2) if trials >= 4 else 3.0


def estimate_model(trials: Sequence[Trial], structure: Structure, *,
                   method: str = "riv+pem", initial: str = INITIAL,
                   burn_in: float = BURN_IN, inflate: bool = True,
                   offset: bool = OFFSET) -> Estimate:
    """Estimate H(s) in ``structure`` from uniformly sampled (closed-loop) trials.

    Parameters
    ----------
    trials
        Trials of the operator's input e (N, 2) and output u (N, 2), one sampling step;
        each trial starts from its own (estimated) initial state.
    structure
        :meth:`Structure.paper` or :meth:`Structure.poles_zeros`.
    initial, burn_in
        How the start of each trial is treated (module docstring): ``initial`` "carry"
        (the model continues from the previous trial across the dead time), "zero"
        (the model starts at rest) or "estimate" (each trial's initial state is
        estimated); the first ``burn_in`` seconds of each trial are simulated but left
        out of the criterion.
    inflate
        Multiply the covariance by :func:`few_trials_factor` of the number of distinct
        trials (module docstring); False gives the asymptotic covariance.
    offset
        Estimate a constant offset per output (an uncalibrated stick, module docstring)
        as a nuisance parameter; the baseline ``"arx+oe"`` has none.
    method
        ``"riv+pem"`` (module docstring), ``"riv+bj"`` (with an AR noise model when the
        output error is coloured, :func:`with_noise_model`) or ``"arx+oe"`` (the
        baseline of the benchmark).

    Returns
    -------
    Estimate
        Parameters in ``structure.names()`` order with their asymptotic covariance.

    References
    ----------
    Young & Jakeman (1980); Garnier, Mensler & Richard (2003); Ljung, System
    Identification (1999), Sec. 9.3 and 13.4.
    """
    if method not in METHODS:
        raise VerifyInputError(f"unknown estimation method {method!r}; choose one of "
                               f"{', '.join(METHODS)}")
    if initial not in INITIAL_STATES:
        raise VerifyInputError(f"initial must be one of {', '.join(INITIAL_STATES)}, got "
                               f"{initial!r}")
    h = check_trials(trials, structure)
    ok = isinstance(burn_in, int | float) and np.isfinite(burn_in) and burn_in >= 0
    skip = round(float(burn_in) / h) if ok else -1
    if skip < 0 or any(np.asarray(tr.t).shape[0] <= skip + 2 * (structure.poles + 1)
                       for tr in trials):
        raise VerifyInputError(f"burn_in = {burn_in!r} s leaves too few samples in some trial; "
                               f"use a shorter burn-in or longer trials")
    samples = sum(np.asarray(tr.t).shape[0] for tr in trials)
    if method == "arx+oe":
        from verify.identify.estimate.baseline import oe_from_arx

        return oe_from_arx(trials, structure, h)
    offset = bool(offset)
    fits = [fit_output(output_data(trials, i, h, initial=initial, skip=skip, offset=offset),
                       structure.poles, structure.zeros, noise=method == "riv+bj")
            for i in (0, 1)]
    est = assemble(structure, fits, method, samples, offset=offset)
    if not inflate:
        return est
    factor = few_trials_factor(len({tr.trial for tr in trials}))
    return replace(est, covariance=est.covariance * factor, inflation=factor,
                   offset_errors=tuple(float(x) * float(np.sqrt(factor))
                                       for x in est.offset_errors))
