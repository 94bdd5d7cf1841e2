"""``verify simulate``: build a scenario from command-line settings, run it, write outputs.

The default scenario follows the experiment of Section 4: n = 8 bodies, the loop at
120 Hz, R-bar(0) and R_l(0) at the identity (the bodies start within 45 degrees of it),
the VR operator as the human, and a reference that is constant or switches every 15 s.
"""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from verify.errors import VerifyInputError
from verify.inputs.numbers import positive_real, real
from verify.inputs.time_grid import step_count
from verify.progress import is_terminal, progress_wanted
from verify.sim.energy import energy
from verify.sim.humans import Human, LTIHuman, StaticGainHuman, VROperator
from verify.sim.inputs import Reference, autonomous_input
from verify.sim.outputs import PLOT_NAMES, write_outputs
from verify.sim.properties import largest_rise
from verify.sim.resolution import stable_step, step_is_stable
from verify.sim.run import simulate
from verify.sim.scenario import Scenario
from verify.so3 import exp, orthogonality_error

SWITCH_PERIOD = 15.0  # s, the reference changes in the paper's experiment (Section 4)
MAX_STEPS = 2_000_000  # samples kept in memory: about 0.5 GB of trajectory
MAX_BODIES = 1_000_000  # bodies: the CF4 stages hold a few copies of n 3x3 matrices


@dataclass
class SimulateSettings:
    n: int = 8
    k_s: float = 3.0
    human: str = "vr"  # vr | static | model
    model: Path | None = None
    gain: float = 1.0
    seconds: float = 30.0
    step: float = 1.0 / 120.0
    seed: int = 0
    autonomous: str = "consensus"
    reference: str = "constant"  # constant | switching
    network: Path | None = None
    out: Path = Path("build/simulation")
    fmt: str = "npz"
    plots: bool = True
    check: bool = False  # also run the property checks (two more runs, h and h/2)
    log: Path | None = None  # also write the run's trials as an experiment log (.csv/.npz)
    operator_noise: float = 0.0  # std of white noise on u_h, held per loop period (model)
    measurement_noise: float = 0.0  # std of white noise on the logged e and u
    adaptive: float | None = None  # rtol of error-controlled steps (None: fixed step)
    progress: bool = False  # show progress on stderr even when it is not a terminal


def build_human(s: SimulateSettings) -> tuple[Human, str]:
    """The human model and one line on its passivity (which decides the storage used)."""
    if s.human == "vr":
        return VROperator(), "VR operator (Section 4 interface); passivity not established"
    if s.human == "static":
        gain = real(s.gain, "--gain")
        verdict = "passive" if gain >= 0 else "NOT passive (K + K^T < 0)"
        return StaticGainHuman(gain * np.eye(2)), f"static gain {gain:g} I: {verdict}"
    if s.human == "model":
        if s.model is None:
            raise VerifyInputError("--human model needs --model FILE")
        from verify.passivity.decision import PASSIVE
        from verify.passivity.io.model_file import load_model

        model = load_model(s.model)
        if model.m not in (2, 3):
            raise VerifyInputError(f"{s.model}: the human model needs 2 or 3 ports (inputs = "
                                   f"outputs), got {model.m}")
        human, decision = LTIHuman.gated(model)
        if decision.verdict == PASSIVE:
            return human, (f"{model.name}: passive (KYP certificate checked exactly); "
                           "S_h = x^T P x/2")
        return human, (f"{model.name}: {decision.verdict} ({decision.reason}); "
                       "S_h = running supply")
    raise VerifyInputError(f"unknown human {s.human!r}; choose vr, static or model")


def build_scenario(s: SimulateSettings, human: Human) -> Scenario:
    rng = np.random.default_rng(s.seed)
    k_s = positive_real(s.k_s, "the coupling gain k_s (--ks)")
    if s.network is not None:
        from verify.network_file import load_network

        R0 = load_network(s.network).attitudes
    else:
        if s.n < 1:
            raise VerifyInputError(f"--n must be at least 1, got {s.n}")
        R0 = exp(_ball(rng, s.n, np.pi / 4))
    n = R0.shape[0]
    if s.reference == "constant":
        reference = Reference.constant(exp(_ball(rng, 1, np.pi / 3)[0]))
    elif s.reference == "switching":
        count = int(np.ceil(s.seconds / SWITCH_PERIOD))
        reference = Reference.switching(list(exp(_ball(rng, max(count, 1), np.pi / 3))),
                                        SWITCH_PERIOD)
    else:
        raise VerifyInputError(f"unknown reference {s.reference!r}; choose constant or "
                               "switching")
    autonomous = autonomous_input(s.autonomous, n, s.seed)
    return Scenario(R0, k_s, human, reference, autonomous=autonomous).validate()


def _ball(rng: np.random.Generator, count: int, radius: float) -> np.ndarray:
    """Rotation vectors uniform in direction with angle uniform in [0, radius]."""
    v = rng.standard_normal((count, 3))
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    return v * rng.uniform(0, radius, (count, 1))


class ProgressBar:
    """A one-line progress bar on stderr (redrawn on a terminal, every 10% otherwise;
    shown only where :func:`verify.progress.progress_wanted` says so)."""

    def __init__(self, seconds: float, stream=None) -> None:
        self.seconds = seconds
        self.stream = sys.stderr if stream is None else stream
        self.tty = is_terminal(self.stream)
        self.start = time.perf_counter()
        self.shown = -1

    def __call__(self, k: int, steps: int) -> None:
        fraction = k / steps
        tenth = int(fraction * 10)
        if self.tty:
            if k % max(1, steps // 200) and k != steps:
                return
            bar = "#" * int(fraction * 30)
            print(f"\r  [{bar:<30}] {fraction:4.0%} {fraction * self.seconds:7.1f} s simulated, "
                  f"{time.perf_counter() - self.start:6.1f} s wall", end="", file=self.stream,
                  flush=True)
            if k == steps:
                print(file=self.stream)
        elif tenth > self.shown:
            self.shown = tenth
            print(f"  {fraction:4.0%} ({fraction * self.seconds:.1f} s simulated)",
                  file=self.stream, flush=True)


def run_simulate(s: SimulateSettings) -> int:
    if s.fmt not in ("npz", "csv"):
        raise VerifyInputError(f"unknown format {s.fmt!r}; choose npz or csv")
    seconds = positive_real(s.seconds, "--seconds")
    step = positive_real(s.step, "--step")
    steps = step_count(seconds, step)
    if steps > MAX_STEPS:
        raise VerifyInputError(f"{steps} steps asked (--seconds / --step); at most {MAX_STEPS} "
                               "are stored in memory: shorten the run or enlarge the step")
    if s.network is None and s.n > MAX_BODIES:
        raise VerifyInputError(f"--n {s.n}: at most {MAX_BODIES} bodies fit in memory here")
    noises = _check_log_settings(s)
    rtol = None if s.adaptive is None else positive_real(s.adaptive, "--adaptive")
    _check_outputs(s)
    human, human_line = build_human(s)
    scenario = build_scenario(s, human)
    if noises[0] > 0:
        scenario.human = _noisy(scenario, seconds / steps, steps, noises[0], s.seed)
        human_line += f"; operator noise {noises[0]:g} rad/s (S_h = running supply)"
    print(f"verify simulate: n = {scenario.n}, k_s = {scenario.k_s:g}, {seconds:g} s in "
          f"{steps} steps of {seconds / steps:.4g} s, autonomous input {s.autonomous}, "
          f"reference {s.reference}")
    print(f"  human: {human_line}")
    engine = "compiled" if noises[0] > 0 and fused_models(scenario) else "auto"
    print(f"  engine: {engine_line(scenario, engine)}")
    progress = (ProgressBar(seconds) if steps >= 600
                and progress_wanted(sys.stderr, forced=s.progress) else None)
    every = max(1, round(0.1 / (seconds / steps)))  # bodies' directions at 10 Hz
    start = time.perf_counter()
    if rtol is None:
        traj = simulate(scenario, seconds, step, direction_every=every, progress=progress,
                        engine=engine)
    else:
        traj = simulate(scenario, seconds, step, direction_every=every, progress=progress,
                        adaptive=True, rtol=rtol, atol=rtol / 100, engine=engine)
        print(f"  adaptive steps (rtol {rtol:g}, atol {rtol / 100:g}): {traj.steps} accepted, "
              f"{traj.rejected_steps} rejected; samples every {seconds / steps:.4g} s")
    wall = time.perf_counter() - start
    E = energy(traj)
    _summary(traj, E, wall)
    if rtol is None and not step_is_stable(scenario, seconds / steps):
        print(f"  WARNING: the step {seconds / steps:.4g} s is beyond CF4's stability bound "
              f"{stable_step(scenario):.3g} s for this loop (k_s = {scenario.k_s:g}): the "
              "figures above do not represent it; use --adaptive RTOL or a smaller --step")
    if s.check:
        _check_properties(scenario, seconds, step)
    title = f"n={scenario.n}, k_s={scenario.k_s:g}"
    paths = write_outputs(s.out, traj, E, s.fmt, title, with_plots=s.plots)
    if s.log is not None:
        paths.append(_write_log(s, traj, noises[1]))
    print("  wrote: " + ", ".join(str(p) for p in paths))
    return 0


def fused_models(scenario: Scenario) -> bool:
    """Whether the compiled kernels can integrate the scenario when asked to."""
    from verify.sim import fused

    try:
        return isinstance(fused.stepper(scenario, "compiled"), fused.CompiledStepper)
    except VerifyInputError:
        return False


def engine_line(scenario: Scenario, engine: str = "auto") -> str:
    """Which engine integrates the scenario, and why when it is the slow Python one."""
    from verify.sim import fused

    if isinstance(fused.stepper(scenario, engine), fused.CompiledStepper):
        return "compiled kernels (numba)"
    if not fused.laws_unmodified():
        why = "a closed-loop law was replaced at run time"
    elif fused.human_form(scenario.human) is None:
        why = f"the kernels do not model the human {type(scenario.human).__name__}"
    else:
        why = f"the kernels do not model the autonomous input {scenario.autonomous.name}"
    return f"Python field (slow: {why})"


def _check_outputs(s: SimulateSettings) -> None:
    """Every output checked before the run (:class:`verify.artefacts.outputs.OutputPlan`):
    no input replaced, no device written, the folders writable."""
    from verify.artefacts.outputs import OutputPlan

    plan = OutputPlan(inputs=[p for p in (s.model, s.network) if p is not None])
    plan.folder("--out", s.out)
    names = [f"trajectory.{s.fmt}"] + (list(PLOT_NAMES) if s.plots else [])
    for name in names:
        plan.file("--out", Path(s.out) / name)
    plan.file("--log", s.log)


def _check_log_settings(s: SimulateSettings) -> tuple[float, float]:
    """(operator noise, measurement noise), refused before the run when they cannot apply."""
    if s.log is not None and Path(s.log).suffix.lower() not in (".csv", ".npz"):
        raise VerifyInputError(f"--log {s.log}: name the log .csv or .npz (the experiment log "
                               "format of verify.inputs.experiment_log)")
    operator = real(s.operator_noise, "--operator-noise")
    measurement = real(s.measurement_noise, "--measurement-noise")
    if operator < 0 or measurement < 0:
        raise VerifyInputError("--operator-noise and --measurement-noise are standard "
                               "deviations: give numbers >= 0")
    if operator > 0 and s.human != "model":
        raise VerifyInputError("--operator-noise needs an LTI human (--model FILE): the noise is "
                               "added to the model's output")
    if measurement > 0 and s.log is None:
        raise VerifyInputError("--measurement-noise applies to the logged signals: give --log")
    return operator, measurement


def _noisy(scenario: Scenario, h: float, steps: int, std: float, seed: int) -> Human:
    """The scenario's LTI human with held operator noise of standard deviation ``std``."""
    from verify.sim.noisy_humans import ReactingNoisyHuman

    base = scenario.human
    noise = std * np.random.default_rng([seed, 1]).standard_normal((steps + 1, base.ports))
    return ReactingNoisyHuman(base.A, base.B, base.C, base.D, name=base.name, noise=noise,
                              reference=scenario.reference, h=h)


def _write_log(s: SimulateSettings, traj, measurement: float) -> Path:
    """The run's trials (one per reference segment) as an experiment log."""
    from verify.inputs.experiment import ExperimentLog, Trial
    from verify.inputs.experiment_log import write_log
    from verify.sim.experiment_log import trajectory_trials

    rng = np.random.default_rng([s.seed, 2])
    trials = []
    for tr in trajectory_trials(traj):
        e = tr.e + measurement * rng.standard_normal(tr.e.shape) if measurement else tr.e
        u = tr.u + measurement * rng.standard_normal(tr.u.shape) if measurement else tr.u
        trials.append(Trial(tr.trial, tr.t, e, u, reference=tr.reference, start=tr.start))
    source = (f"verify simulate: n = {traj.scenario.n}, k_s = {traj.scenario.k_s:g}, human "
              f"{traj.scenario.human.name}, reference {s.reference}, seed {s.seed}, operator "
              f"noise {s.operator_noise:g}, measurement noise {measurement:g}")
    return write_log(ExperimentLog(tuple(trials), 1.0 / traj.h, source), s.log)


def _summary(traj, E, wall: float) -> None:
    t = traj.t
    bad_rl = np.flatnonzero(E.lmin_rl <= 0)
    item2 = ("held throughout" if bad_rl.size == 0
             else f"FAILS from t = {t[bad_rl[0]]:.3g} s")
    print(f"  Assumption 1, item 2 (sym(R_rl) > 0): {item2}")
    print(f"  Lemma 1: min tr(R-bar_r) = {np.min(E.h) + 1:.6g} (>= 1 required while item 2 "
          "holds)")
    V = E.V
    rise = max(0.0, largest_rise(V))
    label = "human storage (x^T P x/2; 0 if static)" if E.uses_storage else "running supply"
    print(f"  V (S_h = {label}): {V[0]:.6g} -> {V[-1]:.6g}; largest rise {rise:.3g}"
          + ("" if traj.scenario.reference.is_constant else " (the reference switches: V "
             "jumps at switches)"))
    weakest = traj.weakest_coherence
    print(f"  dbar along the run: min |sum d_i|/n = {weakest:.3g}"
          + (" (below 1e-3: dbar and A(d) are ill-conditioned, see sec2.dbar-stays-defined)"
             if weakest < 1e-3 else ""))
    err = np.linalg.norm(traj.dbar - traj.R_r[:, :, 2], axis=1)
    print(f"  |dbar - d_r|: {err[0]:.4g} -> {err[-1]:.4g}")
    drift = max(float(np.max(orthogonality_error(traj.R_bar))),
                float(np.max(orthogonality_error(traj.final_bodies))))
    print(f"  orthogonality drift max |R^T R - I| = {drift:.2g} (no re-projection); "
          f"{wall:.2f} s wall, {wall / t[-1]:.3g} s per simulated second")


def _check_properties(scenario: Scenario, seconds: float, step: float) -> None:
    """The paper's conclusions on this scenario, within the integrator's error; a check
    the integration cannot resolve says so (never "holds")."""
    from verify.sim.checks import check_scenario

    checked = check_scenario(scenario, seconds, step)
    how = ("fixed step h and h/2" if checked.engine == "fixed"
           else f"{checked.engine} (error-controlled steps; {checked.note})"
           if checked.pair is not None else "none: no engine resolved the loop")
    print(f"  property checks, one pair of runs ({how}); tolerance from their difference:")
    for result in checked.results.values():
        if result is not None:
            print(f"    {result.line()}")
