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
the logged e and u. :func:`trajectory_trials` turns any simulator trajectory into trials.
"""

from __future__ import annotations

import math

import numpy as np

from verify.errors import VerifyInputError
from verify.identify.experiment import ExperimentLog, Trial
from verify.inputs.numbers import positive_real, real
from verify.sim.inputs import Reference, autonomous_input
from verify.sim.noisy_humans import ReactingNoisyHuman
from verify.sim.run import simulate
from verify.sim.scenario import Scenario
from verify.sim.trajectory import Trajectory
from verify.so3 import exp, vee

#: Default operator noise (rad/s, standard deviation of the held white noise on u_h) and
#: measurement noise (standard deviation on the logged e (rad) and u (rad/s)).
OPERATOR_NOISE = 0.05
MEASUREMENT_NOISE = 0.002


def trajectory_trials(traj: Trajectory, *, until: float | None = None) -> tuple[Trial, ...]:
    """The trials of a run: one per reference segment, with the signals the human saw.

    Sample k (time t_k, the start of loop period k) carries e_k = the first two
    components of vee(sk(R_l(t_k)^T R_r(t_k))), with R_r the reference held over the
    period (as :class:`verify.sim.scenario.ClosedLoop` computes it), and u_k = the first
    two components of omega_h^b, recomputed from the recorded human state x_k through
    the human's own ``hold`` and ``command`` (the value the simulator used at the first
    stage of that period). A trial is a maximal run of samples in one reference segment
    (:meth:`verify.sim.inputs.Reference.segment`); ``reference`` is d_r = R_r e3. When
    the human is a :class:`ReactingNoisyHuman`, ``start`` is the time of the first
    sample after its reaction time. Samples at t >= ``until`` are left out.
    """
    scenario = traj.scenario
    human = scenario.human
    t = traj.t
    keep = np.ones(t.shape[0], bool) if until is None else t < until - 1e-9 * max(1.0, until)
    idx = np.flatnonzero(keep)
    if idx.size == 0:
        raise VerifyInputError(f"no samples before t = {until} s")
    m = human.state_size
    e3 = np.empty((idx.size, 3))
    u3 = np.empty_like(e3)
    for row, k in enumerate(idx):  # as ClosedLoop.signals computes them, bit for bit
        e3[row] = vee(traj.R_l[k].T @ traj.R_r[k])  # sk(R_l^T R_r)^vee
        held = human.hold(float(t[k]), traj.R_l[k], traj.R_r[k])
        u3[row] = human.command(float(t[k]), traj.x[k, :m], e3[row], traj.R_l[k], held)
    segments = np.array([scenario.reference.segment(float(t[k])) for k in idx])
    d_r = traj.R_r[idx][:, :, 2]
    reacting = getattr(human, "reacting", None)
    trials = []
    for seg in np.unique(segments):
        rows = np.flatnonzero(segments == seg)
        start = None
        if reacting is not None:
            ready = [r for r in rows if not reacting(float(t[idx[r]]))]
            start = float(t[idx[ready[0]]]) if ready else None
        trials.append(Trial(int(seg), t[idx[rows]].copy(), e3[rows, :2].copy(),
                            u3[rows, :2].copy(), reference=d_r[rows].copy(), start=start))
    return tuple(trials)


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
