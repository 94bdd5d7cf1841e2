"""Exogenous inputs of the closed loop: the reference R_r and the autonomous signal.

* reference (Section 3, quasi-reference R_r with R_r e3 = d_r): constant (Assumption 1,
  first item), or piecewise constant, switching every ``period`` seconds as in the
  experiment of Section 4 (15 s);
* autonomous input Omega~_a (Section 2, eq. (3)): zero, a seeded smooth random signal,
  or attitude synchronisation among the bodies (the remark after eq. (3)), each a body
  velocity per body, passed through the stealthy projector A(d) by the closed loop.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from verify.errors import VerifyInputError
from verify.so3 import Array, transpose, vee


@dataclass(frozen=True)
class Reference:
    """R_r(t): ``rotations[k]`` on [k period, (k + 1) period), the last one afterwards."""

    rotations: tuple[Array, ...]
    period: float | None = None

    @classmethod
    def constant(cls, R_r: Array) -> Reference:
        return cls((np.asarray(R_r, dtype=float),))

    @classmethod
    def switching(cls, rotations: Sequence[Array], period: float = 15.0) -> Reference:
        if not period > 0:
            raise VerifyInputError(f"the reference period must be positive, got {period}")
        return cls(tuple(np.asarray(R, dtype=float) for R in rotations), float(period))

    @property
    def is_constant(self) -> bool:
        return len(self.rotations) == 1

    def segment(self, t: float) -> int:
        if self.period is None:
            return 0
        return min(int(np.floor(t / self.period + 1e-9)), len(self.rotations) - 1)

    def at(self, t: float) -> Array:
        return self.rotations[self.segment(t)]

    def switch_times(self, t_end: float) -> list[float]:
        if self.period is None:
            return []
        return [k * self.period for k in range(1, len(self.rotations)) if k * self.period < t_end]


class Autonomous:
    """Omega~_a(t, R) as an (n, 3) array of body velocities, or None for zero."""

    name = "zero"

    def __call__(self, t: float, R: Array) -> Array | None:
        return None


def smooth_random_signal(rng: np.random.Generator, shape: tuple[int, ...], terms: int = 3,
                         amplitude: float = 1.0) -> Callable[[float], Array]:
    """A seeded smooth signal: a sum of sinusoids with random amplitudes and frequencies."""
    amp = amplitude * rng.standard_normal((terms, *shape))
    freq = rng.uniform(0.2, 2.0, size=(terms, *shape))
    phase = rng.uniform(0.0, 2 * np.pi, size=(terms, *shape))

    def signal(t: float) -> Array:
        return np.sum(amp * np.sin(freq * t + phase), axis=0)

    return signal


class SignalInput(Autonomous):
    """Omega~_a(t) from a given signal of shape (n, 3), independent of the attitudes."""

    name = "signal"

    def __init__(self, signal: Callable[[float], Array]) -> None:
        self.signal = signal

    def __call__(self, t: float, R: Array) -> Array:
        return self.signal(t)


class SmoothRandom(SignalInput):
    """A seeded sum of sinusoids per body and axis."""

    name = "random"

    def __init__(self, n: int, seed: int, amplitude: float = 0.3, terms: int = 3) -> None:
        super().__init__(smooth_random_signal(np.random.default_rng(seed), (n, 3), terms,
                                              amplitude))


@dataclass(frozen=True)
class Synchronisation(Autonomous):
    """Attitude synchronisation on a ring: omega_i = gain * sum_j sk(R_i^T R_j)^vee.

    The neighbours of body i are i - 1 and i + 1 (mod n), which keeps the cost O(n).
    """

    gain: float = 1.0
    name = "consensus"

    def __call__(self, t: float, R: Array) -> Array:
        if R.shape[0] < 2:
            return np.zeros((R.shape[0], 3))
        ahead = vee(transpose(R) @ np.roll(R, -1, axis=0))  # sk(R_i^T R_{i+1})^vee
        # sk(R_i^T R_{i-1})^vee = -sk(R_{i-1}^T R_i)^vee: the previous body's "ahead" term
        return self.gain * (ahead - np.roll(ahead, 1, axis=0))


AUTONOMOUS_KINDS = ("zero", "random", "consensus")


def autonomous_input(kind: str, n: int, seed: int = 0) -> Autonomous:
    """The autonomous input named ``kind`` (one of :data:`AUTONOMOUS_KINDS`)."""
    if kind == "zero":
        return Autonomous()
    if kind == "random":
        return SmoothRandom(n, seed)
    if kind == "consensus":
        return Synchronisation()
    raise VerifyInputError(f"unknown autonomous input {kind!r}; choose from "
                           f"{', '.join(AUTONOMOUS_KINDS)}")
