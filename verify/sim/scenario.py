"""A closed-loop scenario of Sections 2-3 and its vector field.

State: rotations Y (n + 2, 3, 3), rows 0..n-1 the bodies R_i (eq. (1)), row n the
quasi-average R-bar (eq. (4)), row n + 1 the virtual leader R_l (eq. (5)); and a
Euclidean vector x = (human state, w) where w(t) = int_0^t e^T omega_h^b dt is the
supply the human has received, e = sk(R_l^T R_r)^vee (so S_h = beta + w, proof of
Theorem 1).

Velocities (all spatial, F, so that Y' = hat(F) Y):
* bodies: omega~_h^s + R_i (A(d) Omega~_a)_i  (Section 2, omega_i = R_i^T omega~ + ...);
* R-bar: omega~_h^s = k_s R-bar sk(R-bar^T R_l)^vee  (eq. (6a) in (4));
* R_l: R_l omega_l, omega_l = k_s sk(R_l^T R-bar)^vee + omega_h^b  (eq. (6b)).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from verify.errors import VerifyInputError
from verify.inputs.numbers import positive_real
from verify.sim.humans import Human
from verify.sim.inputs import Autonomous, Reference
from verify.so3 import Array, check_rotations, vee
from verify.system.laws import interface_velocity, leader_velocity, quasi_average_initial
from verify.system.stealthy import dbar, stealthy_input

LOOP_RATE = 120.0  # Hz, the simulator loop of Section 4 ("Simulation Setup")


@dataclass
class Scenario:
    """Everything a closed-loop run needs; :meth:`validate` rejects bad input."""

    R0: Array  # bodies at t = 0, shape (n, 3, 3)
    k_s: float
    human: Human
    reference: Reference
    R_l0: Array = field(default_factory=lambda: np.eye(3))
    autonomous: Autonomous = field(default_factory=Autonomous)
    rbar_yaw: float = 0.0  # the free rotation of R-bar(0) about its z-axis

    @property
    def n(self) -> int:
        return int(np.asarray(self.R0).shape[0])

    def validate(self) -> Scenario:
        R0 = np.asarray(self.R0, dtype=float)
        if R0.ndim != 3 or R0.shape[1:] != (3, 3):
            raise VerifyInputError(f"initial attitudes must have shape (n, 3, 3), got {R0.shape}")
        if R0.shape[0] == 0:
            raise VerifyInputError("the network needs at least one body (n >= 1)")
        positive_real(self.k_s, "the coupling gain k_s")
        check_rotations(R0, name="initial attitude")
        check_rotations(np.asarray(self.R_l0, dtype=float)[None], name="leader attitude")
        check_rotations(np.stack(self.reference.rotations), name="reference")
        dbar(R0)  # raises DbarUndefinedError when sum d_i = 0
        self.R0 = R0
        return self

    def initial_state(self) -> tuple[Array, Array]:
        """(Y0, x0) with R-bar(0) e3 = dbar(0) (Section 3) and zero supply."""
        Y0 = np.concatenate([self.R0, quasi_average_initial(self.R0, self.rbar_yaw)[None],
                             np.asarray(self.R_l0, dtype=float)[None]])
        x0 = np.concatenate([self.human.initial_state(), [0.0]])
        return Y0, x0


@dataclass(frozen=True)
class Held:
    """Quantities fixed over one loop period: the reference and a sampled human command."""

    R_r: Array
    human: Array | None


class ClosedLoop:
    """The vector field (F, g) of a scenario for one loop period's held values."""

    def __init__(self, scenario: Scenario) -> None:
        self.s = scenario
        self.n = scenario.n
        self.m = scenario.human.state_size

    def hold(self, t: float, Y: Array) -> Held:
        R_r = self.s.reference.at(t)
        return Held(R_r, self.s.human.hold(t, Y[self.n + 1], R_r))

    def signals(self, t: float, Y: Array, x: Array, held: Held) -> tuple[Array, Array, Array]:
        """(omega~_h^s, e, omega_h^b) at a state."""
        n = self.n
        R_bar, R_l = Y[n], Y[n + 1]
        omega_tilde = interface_velocity(R_bar, R_l, self.s.k_s)  # eq. (6a)
        e = vee(R_l.T @ held.R_r)
        omega_b = self.s.human.command(t, x[: self.m], e, R_l, held.human)
        return omega_tilde, e, omega_b

    def leader_velocity(self, R_l: Array, R_bar: Array, omega_b: Array) -> Array:
        """omega_l = k_s sk(R_l^T R-bar)^vee + omega_h^b, eq. (6b) (a body velocity)."""
        return leader_velocity(R_l, R_bar, self.s.k_s, R_l @ omega_b)

    def field(self, held: Held):
        n, human, autonomous = self.n, self.s.human, self.s.autonomous

        def f(t: float, Y: Array, x: Array) -> tuple[Array, Array]:
            omega_tilde, e, omega_b = self.signals(t, Y, x, held)
            R, R_bar, R_l = Y[:n], Y[n], Y[n + 1]
            F = np.empty((n + 2, 3))
            F[:n] = omega_tilde
            omega_a = autonomous(t, R)
            if omega_a is not None:
                F[:n] += (R @ stealthy_input(R, omega_a)[:, :, None])[:, :, 0]
            F[n] = omega_tilde
            F[n + 1] = R_l @ self.leader_velocity(R_l, R_bar, omega_b)
            g = np.empty(self.m + 1)
            g[: self.m] = human.state_rate(x[: self.m], e)
            g[self.m] = e @ omega_b
            return F, g

        return f
