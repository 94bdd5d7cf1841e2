"""Monte Carlo check of an estimator on simulated closed-loop experiments.

Each repetition simulates the experiment of Section 4 with a known operator in the
paper's class (:func:`verify.identify.data.simulated_experiment.simulate_experiment`: the
SO(3) closed loop, operator noise inside the loop, measurement noise, reaction times),
prepares it with the paper's protocol (:func:`verify.identify.data.protocol.prepare`: dead
time to the start event, anti-aliasing and decimation) and estimates H(s) from the
identification trials. It records, per method, the estimate, its standard errors,
whether each parameter's 95 % interval theta_hat +- 1.96 se contains the true value,
whether the true parameter vector lies in the 95 % confidence ellipsoid, and two fit
ratios (Section 4): on the noisy identification data, and on clean data, i.e. against
the true operator's noise-free response to the same logged inputs (both with each
trial's initial state estimated).

Used by ``benchmarks/bench_identify_coverage.py`` and ``benchmarks/bench_identify_methods.py``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from scipy.stats import chi2

from verify.errors import VerifyInputError
from verify.identify.data.protocol import prepare
from verify.identify.data.simulated_experiment import (
    simulate_experiment,
    simulate_paused_experiment,
    with_output_offset,
)
from verify.identify.estimate.estimation import estimate_model
from verify.identify.estimate.prediction import predict
from verify.identify.estimate.structure import Structure
from verify.identify.quality.fits import fit_ratio
from verify.passivity.model import from_transfer_function

__all__ = ["Repetition", "Study", "repetition", "run_study", "true_model"]


def true_model(theta: Sequence[float], name: str = "known operator"):
    """The 2 x 2 LTIModel of the paper's structure with parameters ``theta``."""
    num, den = Structure.paper().transfer_matrix(list(theta))
    return from_transfer_function(num, den, name=name)


@dataclass(frozen=True)
class Repetition:
    """One seeded experiment: per method the estimate and standard errors (or the error)."""

    seed: int
    theta: dict[str, np.ndarray] = field(default_factory=dict)
    se: dict[str, np.ndarray] = field(default_factory=dict)
    in_ellipsoid: dict[str, bool] = field(default_factory=dict)
    fit_noisy: dict[str, np.ndarray] = field(default_factory=dict)
    fit_clean: dict[str, np.ndarray] = field(default_factory=dict)
    failed: dict[str, str] = field(default_factory=dict)
    offsets: dict[str, np.ndarray] = field(default_factory=dict)
    offset_errors: dict[str, np.ndarray] = field(default_factory=dict)


@dataclass(frozen=True)
class Study:
    """The repetitions of a study and its true parameters."""

    theta_true: np.ndarray
    names: tuple[str, ...]
    repetitions: tuple[Repetition, ...]

    def estimates(self, method: str) -> np.ndarray:
        return np.array([r.theta[method] for r in self.repetitions if method in r.theta])

    def coverage(self, method: str) -> np.ndarray:
        """Fraction of repetitions whose 95 % interval holds the true value, per parameter."""
        hits = [np.abs(r.theta[method] - self.theta_true) <= 1.959963984540054 * r.se[method]
                for r in self.repetitions if method in r.theta]
        return np.mean(hits, axis=0)

    def ellipsoid_coverage(self, method: str) -> float:
        return float(np.mean([r.in_ellipsoid[method] for r in self.repetitions
                              if method in r.theta]))


def run_study(theta_true: Sequence[float], seeds: Sequence[int], *,
              methods: Sequence[str] = ("riv+pem",), k_s: float = 3.0, n: int = 8,
              trials: int = 6, trial_seconds: float = 15.0, rate: float = 120.0,
              out_rate: float | str | None = None, operator_noise: float | None = None,
              measurement_noise: float | None = None, pauses: tuple[float, float] | None = None,
              progress=None, jobs: int = 1, offset: bool | None = None,
              true_offset: tuple[float, float] | None = None) -> Study:
    """Simulate, prepare and estimate once per seed (module docstring).

    ``rate`` is the loop and logging rate (Hz), ``out_rate`` the protocol's rate after
    decimation; ``pauses`` (lo, hi) seconds separates the trials by pauses in which the
    loop is reset to rest
    (:func:`verify.identify.data.simulated_experiment.simulate_paused_experiment`);
    ``true_offset`` adds a constant to the logged u (an uncalibrated stick,
    :func:`verify.identify.data.simulated_experiment.with_output_offset`); ``offset`` is
    the estimator's option (None: its default).

    ``jobs`` > 1 runs the seeds in that many processes; each repetition depends on its
    seed alone, so the study is the same as with one job.
    """
    theta_true = np.asarray(theta_true, float)
    extra = {}
    if operator_noise is not None:
        extra["operator_noise"] = operator_noise
    if measurement_noise is not None:
        extra["measurement_noise"] = measurement_noise
    settings = dict(methods=tuple(methods), k_s=k_s, n=n, trials=trials,
                    trial_seconds=trial_seconds, rate=rate, out_rate=out_rate, extra=extra,
                    pauses=pauses, offset=offset, true_offset=true_offset)
    reps: dict[int, Repetition] = {}
    if jobs > 1:
        from concurrent.futures import ProcessPoolExecutor

        from verify.process_tree import die_with_parent

        with ProcessPoolExecutor(jobs, initializer=die_with_parent) as pool:
            futures = [pool.submit(repetition, theta_true, seed, **settings) for seed in seeds]
            for future in futures:
                rep = future.result()
                reps[rep.seed] = rep
                if progress is not None:
                    progress(rep)
    else:
        for seed in seeds:
            reps[seed] = repetition(theta_true, seed, **settings)
            if progress is not None:
                progress(reps[seed])
    return Study(theta_true, Structure.paper().names(), tuple(reps[s] for s in seeds))


def repetition(theta_true: np.ndarray, seed: int, *, methods: tuple[str, ...], k_s: float,
               n: int, trials: int, trial_seconds: float, rate: float,
               out_rate: float | str | None, extra: dict,
               pauses: tuple[float, float] | None = None, offset: bool | None = None,
               true_offset: tuple[float, float] | None = None) -> Repetition:
    """One seeded experiment of :func:`run_study`."""
    structure = Structure.paper()
    if pauses is None:
        log = simulate_experiment(true_model(theta_true), k_s=k_s, n=n, trials=trials,
                                  trial_seconds=trial_seconds, rate=rate, seed=seed, **extra)
    else:
        log = simulate_paused_experiment(true_model(theta_true), pauses=pauses, k_s=k_s, n=n,
                                         trials=trials, trial_seconds=trial_seconds,
                                         rate=rate, seed=seed, **extra)
    if true_offset is not None:
        log = with_output_offset(log, true_offset)
    data = prepare(log, rate=out_rate, split=(trials, 0)).identification
    clean = predict(structure, theta_true, data)
    rep = Repetition(seed)
    for method in methods:
        try:
            est = estimate_model(data, structure, method=method,
                                 **({} if offset is None else {"offset": offset}))
        except VerifyInputError as err:
            rep.failed[method] = str(err)
            continue
        rep.theta[method] = est.theta
        rep.se[method] = est.standard_errors()
        diff = est.theta - theta_true
        try:
            stat = float(diff @ np.linalg.solve(est.covariance, diff))
        except np.linalg.LinAlgError:
            stat = np.inf
        rep.in_ellipsoid[method] = stat <= chi2.ppf(0.95, len(diff))
        rep.offsets[method] = np.array(est.offsets)
        rep.offset_errors[method] = np.array(est.offset_errors)
        yhat = predict(structure, est.theta, data, offsets=est.offsets)
        u = np.concatenate([np.asarray(tr.u, float) for tr in data])
        yh = np.concatenate(yhat)
        yc = np.concatenate(clean)
        rep.fit_noisy[method] = np.array([fit_ratio(u[:, i], yh[:, i]) for i in (0, 1)])
        yh_h = np.concatenate(predict(structure, est.theta, data))  # H(s) alone
        rep.fit_clean[method] = np.array([fit_ratio(yc[:, i], yh_h[:, i]) for i in (0, 1)])
    return rep
