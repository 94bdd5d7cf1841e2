"""Seeded random closed-loop scenarios meeting Assumption 1 at t = 0 (numpy, no hypothesis).

The same recipe as :func:`verify.strategies.scenarios`, drawn from a numpy generator so
that ``verify all`` can run a fixed, reproducible set of trajectories.
"""

from __future__ import annotations

import numpy as np

from verify.passivity.port_hamiltonian import port_hamiltonian
from verify.sim.humans import Human, LTIHuman, StaticGainHuman
from verify.sim.inputs import AUTONOMOUS_KINDS, Reference, autonomous_input
from verify.sim.scenario import Scenario
from verify.so3 import Array, exp, random_rotations
from verify.system.laws import quasi_average_initial


def _within(rng: np.random.Generator, center: Array, max_angle: float, count: int) -> Array:
    axis = rng.standard_normal((count, 3))
    axis /= np.linalg.norm(axis, axis=1, keepdims=True)
    return center @ exp(axis * rng.uniform(0.0, max_angle, (count, 1)))


def random_passive_human(rng: np.random.Generator, max_states: int = 3) -> Human:
    """A static gain with K + K^T > 0, or a port-Hamiltonian model with its KYP storage."""
    if rng.random() < 0.5:
        k, skew = rng.uniform(0.3, 3.0), rng.uniform(-1.0, 1.0)
        return StaticGainHuman(np.array([[k, skew], [-skew, k]]))
    n = int(rng.integers(1, max_states + 1))
    J, L, M = (rng.uniform(-1, 1, (n, n)) for _ in range(3))
    G = rng.uniform(-2, 2, (n, 2))
    N = rng.uniform(-1, 1, (2, 2))
    model = port_hamiltonian(J, L, M, G, N, rng.uniform(0.3, 3.0))
    # a gate failure is not expected (D + D^T > 0); the human then has no storage
    return LTIHuman.gated(model)[0]


def random_scenario(rng: np.random.Generator, max_bodies: int = 6,
                    autonomous: tuple[str, ...] = AUTONOMOUS_KINDS) -> Scenario:
    """Bodies within 60 degrees of a common attitude, tr(R-bar_r) >= 1, sym(R_rl) > 0."""
    n = int(rng.integers(1, max_bodies + 1))
    R0 = _within(rng, random_rotations(1, rng)[0], np.pi / 3, n)
    yaw = float(rng.uniform(-np.pi, np.pi))
    R_bar0 = quasi_average_initial(R0, yaw)
    R_r = _within(rng, R_bar0, np.deg2rad(85), 1)[0]
    R_l0 = _within(rng, R_r, np.deg2rad(80), 1)[0]
    kind = autonomous[int(rng.integers(len(autonomous)))]
    return Scenario(R0, float(rng.uniform(0.5, 5.0)), random_passive_human(rng),
                    Reference.constant(R_r), R_l0=R_l0,
                    autonomous=autonomous_input(kind, n, int(rng.integers(2**31))),
                    rbar_yaw=yaw)
