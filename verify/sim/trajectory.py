"""The samples of a run: a :class:`Trajectory` and the :class:`Recorder` that fills it.

Both integrators of :func:`verify.sim.run.simulate` (fixed steps of CF4 and the
error-controlled steps of :mod:`verify.sim.adaptive`) sample the closed loop of Section 3
every loop period into a :class:`Recorder`, report their progress through a
:data:`Progress` callback and stop with :func:`dbar_lost` when the bodies' directions
cancel (dbar undefined, claim sec2.dbar-stays-defined).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from verify.errors import DbarUndefinedError
from verify.sim.scenario import Scenario
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
