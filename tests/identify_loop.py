"""Logs for the identification tests: the paper's closed loop with a known operator, and
hostile logs (pure noise, swapped signals, a diverging loop, a differentiator).

The closed loop is :func:`verify.identify.data.simulated_experiment.simulate_experiment` with
2 bodies and 8 short trials (a few seconds of CPU); the hostile logs are small numpy
constructions, independent of the estimator.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from verify.identify.data.simulated_experiment import simulate_experiment
from verify.identify.quality.coverage import true_model
from verify.inputs.experiment import ExperimentLog, Trial
from verify.inputs.experiment_log import write_log

#: The known operator (passive: c12 + c21 = 0, diagonal elements positive real).
THETA = np.array([1.2, 0.8, 2.0, 1.5, 1.2, 0.8, 2.0, 1.5, 0.05, -0.05])


def loop_log(path: Path, *, exact: bool = False, seed: int = 5, trials: int = 8) -> Path:
    """The paper's closed loop (n = 2) with the operator THETA, 120 Hz, 15 s trials."""
    noise = {"operator_noise": 0.0, "measurement_noise": 0.0} if exact else {}
    log = simulate_experiment(true_model(THETA), trials=trials, n=2, seed=seed, **noise)
    return write_log(log, path)


#: A passive operator outside the paper's class: diagonal elements
#: (s^2 + 2 s + 2)/(s^3 + 2 s^2 + 3 s + 2), Re h(jw) = 4/|den(jw)|^2 > 0 (0.0024 at 3.5 rad/s),
#: coupling c12 = -c21 = 0.05.
THIRD_ORDER = (("1", "2", "2"), ("1", "2", "3", "2"), "0.05")


def third_order_log(path: Path, *, seed: int = 5, trials: int = 8) -> Path:
    """The paper's closed loop (n = 2) with the passive third-order operator THIRD_ORDER."""
    from fractions import Fraction

    from verify.passivity.model import from_transfer_function

    num = [Fraction(x) for x in THIRD_ORDER[0]]
    den = [Fraction(x) for x in THIRD_ORDER[1]]
    c = Fraction(THIRD_ORDER[2])
    truth = from_transfer_function([[num, [c]], [[-c], num]], [[den, [1]], [[1], den]],
                                   name="passive third-order operator")
    return write_log(simulate_experiment(truth, trials=trials, n=2, seed=seed), path)


def per_trial_clocks(log: ExperimentLog) -> ExperimentLog:
    """The same log with each trial's time restarting at 0 (start events shifted too)."""
    out = []
    for tr in log.trials:
        t0 = float(tr.t[0])
        out.append(replace(tr, t=tr.t - t0, start=None if tr.start is None else tr.start - t0))
    return ExperimentLog(tuple(out), log.rate, log.source + ", per-trial clocks")


def swapped(log: ExperimentLog) -> ExperimentLog:
    """e and u exchanged (a wiring mistake)."""
    return ExperimentLog(tuple(replace(tr, e=tr.u.copy(), u=tr.e.copy()) for tr in log.trials),
                         log.rate, log.source + ", e and u swapped")


def pure_noise(*, trials: int = 8, seconds: float = 15.0, rate: float = 120.0,
               seed: int = 0) -> ExperimentLog:
    """e a smooth random signal, u white noise independent of it."""
    rng = np.random.default_rng(seed)
    N = round(seconds * rate)
    out = []
    for k in range(trials):
        t = k * seconds + np.arange(N) / rate
        e = np.cumsum(rng.standard_normal((N, 2)), axis=0) * 0.01
        u = 0.1 * rng.standard_normal((N, 2))
        out.append(Trial(k, t, e, u, start=float(t[0])))
    return ExperimentLog(tuple(out), rate, "pure noise")


def differentiator(*, trials: int = 8, seconds: float = 15.0, rate: float = 120.0,
                   seed: int = 0) -> ExperimentLog:
    """u = de/dt exactly (the leader's inverse): no 2-pole model inside the search box
    fits it; the best ones put their poles on the box's edge."""
    rng = np.random.default_rng(seed)
    N = round(seconds * rate)
    out = []
    for k in range(trials):
        t = k * seconds + np.arange(N) / rate
        freqs = rng.uniform(0.5, 20.0, size=(2, 6))
        phases = rng.uniform(0, 2 * np.pi, size=(2, 6))
        tau = t - t[0]
        e = np.column_stack([np.sum(0.05 * np.sin(np.outer(tau, freqs[i]) + phases[i]), axis=1)
                             for i in range(2)])
        u = np.column_stack([np.sum(0.05 * freqs[i] * np.cos(np.outer(tau, freqs[i])
                                                               + phases[i]), axis=1)
                             for i in range(2)])
        out.append(Trial(k, t, e, u, start=float(t[0])))
    return ExperimentLog(tuple(out), rate, "differentiator")


def diverging(*, trials: int = 8, seconds: float = 10.0, rate: float = 120.0,
              seed: int = 0) -> ExperimentLog:
    """A linear loop theta' = u, e = r - theta, u = -k e + v with k > 0: the operator
    pushes the leader away from the reference and the loop grows within each trial."""
    rng = np.random.default_rng(seed)
    h = 1.0 / rate
    N = round(seconds * rate)
    k_gain = 0.5
    theta = np.zeros(2)
    out = []
    for k in range(trials):
        r = rng.uniform(-0.3, 0.3, 2)
        t = k * seconds + np.arange(N) * h
        e = np.empty((N, 2))
        u = np.empty((N, 2))
        for n in range(N):
            e[n] = r - theta
            u[n] = -k_gain * e[n] + 0.01 * rng.standard_normal(2)
            theta = theta + h * u[n]
        out.append(Trial(k, t, e, u, start=float(t[0])))
        theta = np.zeros(2)
    return ExperimentLog(tuple(out), rate, "diverging loop")


__all__ = ["THETA", "differentiator", "diverging", "loop_log", "per_trial_clocks",
           "pure_noise", "swapped"]
