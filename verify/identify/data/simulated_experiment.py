"""Simulated identification experiments in the protocol of Section 4, with a known human.

The paper's experiment (Section 4, "Simulation Setup" and "Human Modeling"): one run of
the closed loop (n = 8 bodies, the loop at 120 Hz) in which the reference d_r switches
every 15 s to a new direction; each 15 s segment is a trial (12 trials, 180 s); after
each switch the operator needs a moment before reacting and presses a start button; the
logged signals are e = first two components of sk(R_l^T R_r)^vee (the operator's input)
and u_h = first two components of omega_h^b (the operator's output).

:func:`simulate_experiment` runs that protocol with a *known* human in the paper's class
(any 2 x 2 :class:`verify.passivity.model.LTIModel`), wrapped in
:class:`verify.sim.noisy_humans.ReactingNoisyHuman` (operator noise inside the loop, a
seeded reaction time per trial ended by the start event), and adds measurement noise to
the logged e and u. The run becomes trials by
:func:`verify.sim.experiment_log.trajectory_trials`.

Conditions labs log in, each from a known operator: :func:`simulate_paused_experiment`
(reset pauses between trials), :func:`with_output_offset` (an uncalibrated stick: a
constant on the logged u) and :func:`simulate_open_loop_experiment` (no loop: a
multisine e drives the operator).
"""

from __future__ import annotations

import math

import numpy as np

from verify.errors import VerifyInputError
from verify.inputs.experiment import ExperimentLog, Trial
from verify.inputs.numbers import positive_real, real
from verify.sim.experiment_log import trajectory_trials
from verify.sim.inputs import Reference, autonomous_input
from verify.sim.noisy_humans import ReactingNoisyHuman
from verify.sim.run import simulate
from verify.sim.scenario import Scenario
from verify.so3 import exp

#: Default operator noise (rad/s, standard deviation of the held white noise on u_h) and
#: measurement noise (standard deviation on the logged e (rad) and u (rad/s)).
OPERATOR_NOISE = 0.05
MEASUREMENT_NOISE = 0.002


def add_measurement_noise(trials: tuple[Trial, ...], std: float, seed: int
                          ) -> tuple[Trial, ...]:
    """The trials with seeded white noise of standard deviation ``std`` on e and u.

    The noise of trial k is drawn after that of trials 0..k-1 (e, then u), so the first
    trials of a longer experiment get the same noise.
    """
    meas = np.random.default_rng(np.random.SeedSequence(seed).spawn(4)[3])
    out = []
    for tr in trials:
        e = tr.e + std * meas.standard_normal(tr.e.shape)
        u = tr.u + std * meas.standard_normal(tr.u.shape)
        out.append(Trial(tr.trial, tr.t, e, u, reference=tr.reference, start=tr.start))
    return tuple(out)


def _ball(rng: np.random.Generator, count: int, radius: float) -> np.ndarray:
    """Rotation vectors uniform in direction with angle uniform in [0, radius]."""
    v = rng.standard_normal((count, 3))
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    return v * rng.uniform(0, radius, (count, 1))


def experiment_scenario(human_model, *, k_s: float, n: int, trials: int, trial_seconds: float,
                        rate: float, operator_noise: float, reaction: tuple[float, float],
                        seed: int) -> Scenario:
    """The closed loop of one simulated experiment (see :func:`simulate_experiment`)."""
    scenario_ss, noise_ss, reaction_ss = np.random.SeedSequence(seed).spawn(3)
    rng = np.random.default_rng(scenario_ss)
    R0 = exp(_ball(rng, n, np.pi / 4))  # bodies within 45 degrees of R-bar(0) = I
    reference = Reference.switching(list(exp(_ball(rng, trials, np.pi / 3))), trial_seconds)
    h = 1.0 / rate
    periods = round(trials * trial_seconds * rate) + 1
    noise = operator_noise * np.random.default_rng(noise_ss).standard_normal((periods, 2))
    lo, hi = reaction
    seconds = np.random.default_rng(reaction_ss).uniform(lo, hi, trials)
    react = [math.ceil(s * rate - 1e-9) for s in seconds]
    human = ReactingNoisyHuman.of(human_model, noise=noise, reaction=react,
                                  reference=reference, h=h)
    return Scenario(R0, k_s, human, reference, autonomous=autonomous_input("zero", n)).validate()


def simulate_experiment(
    true_model,
    *,
    k_s: float = 3.0,
    n: int = 8,
    trials: int = 12,
    trial_seconds: float = 15.0,
    rate: float = 120.0,
    operator_noise: float = OPERATOR_NOISE,
    measurement_noise: float = MEASUREMENT_NOISE,
    reaction: tuple[float, float] = (0.2, 0.5),
    seed: int = 0,
) -> ExperimentLog:
    """One experiment of Section 4 with ``true_model`` as the operator.

    Parameters
    ----------
    true_model
        A 2 x 2 :class:`verify.passivity.model.LTIModel`, the operator's H(s).
    k_s, n
        The coupling gain and the number of bodies (the autonomous input is zero: it is
        stealthy, so it does not change e or u_h, Section 2).
    trials, trial_seconds, rate
        Reference segments (trials) of ``trial_seconds`` each, the loop and sample rate
        (Hz); ``trial_seconds * rate`` must be an integer.
    operator_noise
        Standard deviation of the white noise added to u_h, held per loop period,
        inside the loop.
    measurement_noise
        Standard deviation of white noise added to the logged e and u (not in the loop).
    reaction
        The operator's reaction time after each reference change is uniform in this
        interval (s), rounded up to whole loop periods; the start event is logged on the
        first sample after it.
    seed
        Seeds the bodies, the references, the noises and the reaction times.

    Returns
    -------
    ExperimentLog
        ``trials`` trials of ``trial_seconds * rate`` samples each, at ``rate``.
    """
    if getattr(true_model, "m", None) != 2:
        raise VerifyInputError("the true human model must be 2 x 2 (inputs e_1, e_2, outputs "
                               f"u_1, u_2, Section 4), got m = {getattr(true_model, 'm', None)}")
    k_s = positive_real(k_s, "k_s")
    trial_seconds = positive_real(trial_seconds, "trial_seconds")
    rate = positive_real(rate, "rate")
    if not (isinstance(n, int) and n >= 1 and isinstance(trials, int) and trials >= 1):
        raise VerifyInputError(f"n and trials must be positive integers, got n={n!r}, "
                               f"trials={trials!r}")
    per_trial = trial_seconds * rate
    if abs(per_trial - round(per_trial)) > 1e-9 * per_trial:
        raise VerifyInputError(f"trial_seconds * rate must be a whole number of samples, got "
                               f"{trial_seconds:g} s x {rate:g} Hz = {per_trial:g}")
    for value, what in ((operator_noise, "operator_noise"),
                        (measurement_noise, "measurement_noise")):
        if real(value, what) < 0:
            raise VerifyInputError(f"{what} must be >= 0, got {value!r}")
    lo, hi = (real(v, "reaction") for v in reaction)
    if not 0 <= lo <= hi < trial_seconds:
        raise VerifyInputError(f"reaction must be (lo, hi) with 0 <= lo <= hi < trial_seconds, "
                               f"got {reaction!r}")
    scenario = experiment_scenario(true_model, k_s=k_s, n=n, trials=trials,
                                   trial_seconds=trial_seconds, rate=rate,
                                   operator_noise=operator_noise, reaction=(lo, hi), seed=seed)
    seconds = trials * trial_seconds
    traj = simulate(scenario, seconds, 1.0 / rate)
    out = add_measurement_noise(trajectory_trials(traj, until=seconds), measurement_noise, seed)
    source = (f"simulated experiment: {true_model.name}, k_s = {k_s:g}, n = {n}, {trials} "
              f"trials x {trial_seconds:g} s at {rate:g} Hz, operator noise {operator_noise:g}, "
              f"measurement noise {measurement_noise:g}, reaction {lo:g}-{hi:g} s, seed {seed}")
    return ExperimentLog(out, rate, source)


def simulate_paused_experiment(true_model, *, pauses: tuple[float, float] = (2.0, 5.0),
                               trials: int = 12, trial_seconds: float = 15.0,
                               rate: float = 120.0, seed: int = 0, **options) -> ExperimentLog:
    """An experiment whose trials are separated by pauses in which the loop is reset.

    A lab that stops between trials resets the simulator (bodies, leader and operator at
    rest) and starts logging again after a pause. Each trial here is one run of
    :func:`simulate_experiment` (one trial, from rest, seeded by ``seed`` and the trial's
    index) placed on one clock with a pause uniform in ``pauses`` (s, whole sampling
    steps) before it; the other ``options`` are those of :func:`simulate_experiment`.
    The operator's state at a trial's first sample is then that of a fresh start, not
    what the previous trial left.
    """
    rate = positive_real(rate, "rate")
    lo, hi = (real(v, "pauses") for v in pauses)
    if not 0 <= lo <= hi:
        raise VerifyInputError(f"pauses must be (lo, hi) with 0 <= lo <= hi, got {pauses!r}")
    if not (isinstance(trials, int) and trials >= 1):
        raise VerifyInputError(f"trials must be a positive integer, got {trials!r}")
    gaps = np.random.default_rng(np.random.SeedSequence([seed, 1])).uniform(lo, hi, trials)
    out: list[Trial] = []
    clock = 0
    for k in range(trials):
        trial_seed = int(np.random.SeedSequence([seed, 2, k]).generate_state(1)[0])
        one = simulate_experiment(true_model, trials=1, trial_seconds=trial_seconds, rate=rate,
                                  seed=trial_seed, **options).trials[0]
        if k:
            clock += round(gaps[k] * rate)
        offset = clock / rate
        out.append(Trial(k, one.t + offset, one.e, one.u, reference=one.reference,
                         start=None if one.start is None else one.start + offset))
        clock += one.t.shape[0]
    return ExperimentLog(tuple(out), rate, f"simulated experiment with reset pauses "
                         f"{lo:g}-{hi:g} s between {trials} trials, seed {seed}")


def with_output_offset(log: ExperimentLog, offset: tuple[float, float]) -> ExperimentLog:
    """``log`` with the constant ``offset`` added to the logged u of every trial: an
    uncalibrated stick, whose reading is off by a constant the loop never saw."""
    o = np.array([real(v, "offset") for v in offset], float)
    if o.shape != (2,):
        raise VerifyInputError(f"offset must be two numbers (u1, u2), got {offset!r}")
    trials = tuple(Trial(tr.trial, tr.t, tr.e, np.asarray(tr.u, float) + o,
                         reference=tr.reference, start=tr.start) for tr in log.trials)
    return ExperimentLog(trials, log.rate, f"{log.source}; offset {o[0]:g}, {o[1]:g} on u")


def simulate_open_loop_experiment(true_model, *, trials: int = 6, seconds: float = 15.0,
                                  rate: float = 120.0, noise: float = 0.002, seed: int = 0,
                                  sines: int = 8) -> ExperimentLog:
    """Open-loop trials of ``true_model``: u = H e + white noise, e a multisine.

    Each trial's e is a sum of ``sines`` sines per component (frequencies uniform in
    0.1-4 rad/s, random phases, amplitude 0.3 / sqrt(sines)), the operator starts each
    trial at rest, the trials are logged back to back (a start event on each first
    sample), and white noise of standard deviation ``noise`` is added to the logged e
    and u. Not the loop of Section 4: e does not depend on u.
    """
    from scipy import signal

    rate = positive_real(rate, "rate")
    seconds = positive_real(seconds, "seconds")
    if not (isinstance(trials, int) and trials >= 1 and isinstance(sines, int) and sines >= 1):
        raise VerifyInputError(f"trials and sines must be positive integers, got "
                               f"trials={trials!r}, sines={sines!r}")
    rng = np.random.default_rng(seed)
    h = 1.0 / rate
    A, B, C, D = (np.asarray(x, dtype=float) for x in (true_model.A, true_model.B,
                                                        true_model.C, true_model.D))
    Ad, Bd, Cd, Dd, _ = signal.cont2discrete((A, B, C, D), h, method="foh")
    out = []
    for k in range(trials):
        t = k * seconds + np.arange(round(seconds * rate)) * h
        freqs = rng.uniform(0.1, 4.0, size=(2, sines))
        phases = rng.uniform(0, 2 * np.pi, size=(2, sines))
        e = np.column_stack([np.sum(0.3 * np.sin(np.outer(t - t[0], freqs[i]) + phases[i]),
                                    axis=1) / np.sqrt(sines) for i in range(2)])
        _, y, _ = signal.dlsim((Ad, Bd, Cd, Dd, h), e)
        u = y + noise * rng.standard_normal(y.shape)
        e = e + noise * rng.standard_normal(e.shape)
        out.append(Trial(k, t, e, u, start=float(t[0])))
    return ExperimentLog(tuple(out), rate, f"simulated open-loop experiment: "
                         f"{true_model.name}, {trials} trials x {seconds:g} s at {rate:g} Hz, "
                         f"multisine e, noise {noise:g}, seed {seed}")
