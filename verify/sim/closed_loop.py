"""The closed loop of Sections 2-3 as a vector field on SO(3)^(n+2).

State layout: rows 0..n-1 are the bodies R_i, row n the quasi-average R-bar, row n+1 the
virtual leader R_l. Inputs: the human's spatial command omega_h^s(t) (a given signal
here; human models arrive with the simulator issue) and the autonomous signal
Omega~_a(t) (shape (n, 3)), applied through the stealthy projector A(d).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from verify.so3 import Array
from verify.system.laws import (
    human_body_velocities,
    interface_velocity,
    leader_velocity,
)
from verify.system.stealthy import stealthy_input

Signal = Callable[[float], Array]


@dataclass(frozen=True)
class OpenLoopHumanSystem:
    """Bodies, quasi-average and leader driven by a given human command signal."""

    n: int
    k_s: float
    human_command: Signal  # omega_h^s(t), shape (3,)
    autonomous: Signal  # Omega~_a(t), shape (n, 3)

    def spatial_velocities(self, t: float, Y: Array) -> Array:
        """Spatial angular velocities of every row of the state (shape (n + 2, 3))."""
        n = self.n
        R, R_bar, R_l = Y[:n], Y[n], Y[n + 1]
        omega_tilde = interface_velocity(R_bar, R_l, self.k_s)  # eq. (6a)
        body = human_body_velocities(R, omega_tilde)  # omega_hi = R_i^T omega~
        body = body + stealthy_input(R, self.autonomous(t))  # + A(d) Omega~_a
        out = np.empty((n + 2, 3))
        out[:n] = np.einsum("nij,nj->ni", R, body)
        out[n] = omega_tilde  # eq. (4)
        omega_l = leader_velocity(R_l, R_bar, self.k_s, self.human_command(t))  # eq. (6b)
        out[n + 1] = R_l @ omega_l
        return out


def smooth_random_signal(
    rng: np.random.Generator, shape: tuple[int, ...], terms: int = 3, amplitude: float = 1.0
) -> Signal:
    """A seeded smooth signal: a sum of sinusoids with random amplitudes and frequencies."""
    amp = amplitude * rng.standard_normal((terms, *shape))
    freq = rng.uniform(0.2, 2.0, size=(terms, *shape))
    phase = rng.uniform(0, 2 * np.pi, size=(terms, *shape))

    def signal(t: float) -> Array:
        return np.sum(amp * np.sin(freq * t + phase), axis=0)

    return signal
