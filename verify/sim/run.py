"""Run a scenario: CF4 on SO(3)^(n+2) x R^k, inputs held per loop period.

The loop period is the step (1/120 s by default, Section 4); the reference and a sampled
human command are read at the start of each step and held over it, so a switch of R_r
every 15 s falls on a step boundary. With ``adaptive=True`` the steps are chosen by error
control (:mod:`verify.sim.adaptive`) and the trajectory is still sampled every loop period.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from verify.errors import DbarUndefinedError, VerifyInputError
from verify.sim import kernels
from verify.sim.fused import run_fixed
from verify.sim.fused import stepper as make_stepper
from verify.sim.scenario import LOOP_RATE, Scenario
from verify.so3 import Array
from verify.system.stealthy import direction_sum, directions

Progress = Callable[[int, int], None]


@dataclass
class Trajectory:
    """Samples of a run every loop period (bodies' directions every ``direction_every``)."""

    scenario: Scenario
    h: float
    t: Array  # (T,)
    R_bar: Array  # (T, 3, 3)
    R_l: Array  # (T, 3, 3)
    R_r: Array  # (T, 3, 3), the reference held over the step that starts at t
    x: Array  # (T, m + 1): human state, then the supply w
    dbar: Array  # (T, 3), dbar of the bodies
    coherence: Array  # (T,), |sum d_i| / n: dbar is defined while this stays away from 0
    direction_times: Array  # (T_d,)
    d: Array | None  # (T_d, n, 3), the bodies' directions d_i
    final_bodies: Array  # (n, 3, 3)
    steps: int = 0  # integration steps taken (accepted ones when adaptive)
    rejected_steps: int = 0  # steps the error control rejected (adaptive only)

    @property
    def weakest_coherence(self) -> float:
        """Smallest |sum d_i|/n along the run, between samples too.

        s = sum d_i moves continuously, so between two samples it is estimated on the
        chord from s_k to s_(k+1); a crossing of 0 between samples (where dbar flips
        sign) then shows as a value near 0 instead of passing unseen.
        """
        s = self.dbar * self.coherence[:, None]
        a, b = s[:-1], s[1:]
        d = b - a
        dd = np.einsum("ij,ij->i", d, d)
        with np.errstate(invalid="ignore", divide="ignore"):
            tau = np.where(dd > 0, np.clip(-np.einsum("ij,ij->i", a, d) / dd, 0.0, 1.0), 0.0)
        chord = np.linalg.norm(a + tau[:, None] * d, axis=1)
        return float(min(np.min(self.coherence), np.min(chord, initial=np.inf)))

    @property
    def human_state(self) -> Array:
        return self.x[:, :-1]

    @property
    def supply(self) -> Array:
        return self.x[:, -1]


def step_count(seconds: float, h: float) -> int:
    """Number of equal steps of at most ``h`` covering [0, seconds]."""
    return max(1, int(np.ceil(seconds / h - 1e-9)))


ENGINES = ("auto", "compiled", "python")


class Recorder:
    """The sample arrays of a :class:`Trajectory` at times k dt, k = 0 .. steps."""

    def __init__(self, scenario: Scenario, steps: int, dt: float, x_size: int,
                 direction_every: int) -> None:
        T = steps + 1
        self.scenario, self.n, self.dt, self.every = scenario, scenario.n, dt, direction_every
        self.t = np.arange(T) * dt
        self.R_bar, self.R_l, self.R_r = (np.empty((T, 3, 3)) for _ in range(3))
        self.x, self.dbar, self.coherence = np.empty((T, x_size)), np.empty((T, 3)), np.empty(T)
        self.keep = (np.arange(0, T, direction_every) if direction_every > 0
                     else np.zeros(0, int))
        self.d = (np.empty((self.keep.shape[0], self.n, 3)) if direction_every > 0 else None)

    def wants_directions(self, k: int) -> bool:
        return self.d is not None and k % self.every == 0

    def record(self, k: int, Y: Array, x: Array, held_R_r: Array) -> None:
        """Sample k from the full state (rotations Y, Euclidean x)."""
        n = self.n
        d = directions(Y[:n]) if self.wants_directions(k) else None
        self.record_parts(k, Y[n], Y[n + 1], x, held_R_r, direction_sum(Y[:n]), d)

    def record_parts(self, k: int, R_bar: Array, R_l: Array, x: Array, R_r: Array, s: Array,
                     d: Array | None) -> None:
        """Sample k from R-bar, R_l, x, R_r, s = sum d_i and (when kept) the d_i."""
        self.R_bar[k], self.R_l[k], self.R_r[k], self.x[k] = R_bar, R_l, R_r, x
        norm = float(np.linalg.norm(s))
        self.coherence[k] = norm / self.n
        self.dbar[k] = s / norm if norm > 0 else np.nan
        if d is not None:
            self.d[k // self.every] = d

    def record_block(self, ks: slice, R_bar: Array, R_l: Array, x: Array, R_r: Array,
                     s: Array, d: Array | None) -> None:
        """Samples ks (consecutive) at once, as :meth:`record_parts` (d: one row per sample)."""
        self.R_bar[ks], self.R_l[ks], self.R_r[ks], self.x[ks] = R_bar, R_l, R_r, x
        norm = np.linalg.norm(s, axis=1)
        self.coherence[ks] = norm / self.n
        with np.errstate(invalid="ignore", divide="ignore"):
            self.dbar[ks] = np.where(norm[:, None] > 0, s / norm[:, None], np.nan)
        if d is not None:
            for j, k in enumerate(range(ks.start, ks.stop)):
                if self.wants_directions(k):
                    self.d[k // self.every] = d[j]

    def trajectory(self, final_bodies: Array, **stats: int) -> Trajectory:
        return Trajectory(self.scenario, self.dt, self.t, self.R_bar, self.R_l, self.R_r,
                          self.x, self.dbar, self.coherence, self.t[self.keep], self.d,
                          final_bodies.copy(), **stats)


def dbar_lost(t: float, exc: Exception) -> DbarUndefinedError:
    return DbarUndefinedError(
        f"at t = {t:.4g} s the bodies' directions cancel, so dbar and A(d) are undefined "
        f"(claim sec2.dbar-stays-defined: the autonomous input must keep |sum d_i| away "
        f"from 0): {exc}")


def simulate(
    scenario: Scenario,
    seconds: float,
    h: float = 1.0 / LOOP_RATE,
    *,
    direction_every: int = 0,
    progress: Progress | None = None,
    engine: str = "auto",
    adaptive: bool = False,
    rtol: float = 1e-8,
    atol: float = 1e-10,
) -> Trajectory:
    """Integrate ``scenario`` over [0, seconds]; samples every ``h`` (rounded to divide it).

    By default the step is ``h``, the loop period (fixed-step CF4, inputs held per step).
    ``direction_every`` > 0 stores every body's direction d_i each that many samples
    (memory n * T / direction_every * 3 floats); 0 stores none.

    ``engine`` chooses how the CF4 stages are evaluated: ``"python"`` is the field of
    :class:`~verify.sim.scenario.ClosedLoop` (the definition), ``"compiled"`` the fused
    kernels of :mod:`verify.sim.kernels` (same method and stages, rounding-level
    differences; an error when the scenario has a part they do not model), ``"auto"``
    the kernels when they apply and the Python field otherwise.

    ``adaptive=True`` chooses the steps by error control instead
    (:mod:`verify.sim.adaptive`: step doubling of CF4 with tolerances ``rtol`` and
    ``atol``, steps ending exactly on reference switches and, for a human that holds
    its command, on every loop period); the samples every ``h`` then come from a dense
    output of order 5.
    """
    scenario.validate()
    if not (np.isfinite(seconds) and seconds > 0):
        raise VerifyInputError(f"the simulated time must be positive, got {seconds}")
    if not (np.isfinite(h) and h > 0):
        raise VerifyInputError(f"the step must be positive, got {h}")
    if engine not in ENGINES:
        raise VerifyInputError(f"unknown engine {engine!r}; choose from {', '.join(ENGINES)}")
    steps = step_count(seconds, h)
    dt = seconds / steps
    stepper = make_stepper(scenario, engine)
    Y, x = scenario.initial_state()
    rec = Recorder(scenario, steps, dt, x.shape[0], direction_every)
    if adaptive:
        from verify.sim.adaptive import integrate_adaptive

        return integrate_adaptive(stepper, rec, Y, x, seconds, rtol=rtol, atol=atol,
                                  progress=progress)

    # whole stretches of steps in one compiled call where the stepper allows it (the
    # same stages and samples as the loop below); one Python step where it does not
    chunk = steps if progress is None else max(1, steps // 200)
    k = 0
    while k < steps:
        Y, x, k_done, status = run_fixed(stepper, rec, Y, x, k, min(steps, k + chunk), dt)
        if k_done > k and progress is not None:
            progress(k_done, steps)
        k = k_done
        if status == kernels.OK or k >= steps:
            continue
        if status == kernels.DBAR_UNDEFINED:
            raise dbar_lost(k * dt, stepper._undefined())
        held = stepper.hold(k * dt, Y)
        rec.record(k, Y, x, held.R_r)
        try:
            Y, x = stepper.step(k * dt, Y, x, dt, held)
        except DbarUndefinedError as exc:
            raise dbar_lost(k * dt, exc) from None
        k += 1
        if progress is not None:
            progress(k, steps)
    rec.record(steps, Y, x, stepper.hold(steps * dt, Y).R_r)
    return rec.trajectory(Y[:scenario.n], steps=steps)
