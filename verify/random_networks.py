"""Seeded numpy samplers of networks for numerical falsification (fast, no hypothesis).

The hypothesis strategies in :mod:`verify.strategies` are for test suites; these are for
the claim checks of ``verify all``, which must be deterministic for a given seed.
"""

from __future__ import annotations

import numpy as np

from verify.so3 import Array, exp, random_rotations
from verify.system.laws import rotation_taking_e3_to


def random_network(rng: np.random.Generator, n: int) -> Array:
    """n Haar-uniform attitudes (redrawn in the rare case that sum d_i nearly vanishes)."""
    while True:
        R = random_rotations(n, rng)
        if np.linalg.norm(R[:, :, 2].sum(axis=0)) > 1e-3 * n:
            return R


def near_cancelling_network(rng: np.random.Generator, n: int, residual: float) -> Array:
    """n >= 2 attitudes whose directions sum to a vector of length about ``residual``.

    Directions come in exactly opposite pairs (plus, for odd n, a triple at 120 degrees
    in a random plane); then one body is tilted by an angle ``residual``, and each body
    gets a random yaw about its own direction so the attitudes are otherwise generic.
    """
    if n < 2:
        raise ValueError("a cancelling configuration needs n >= 2")
    dirs: list[Array] = []
    if n % 2 == 1:
        frame = random_rotations(1, rng)[0]
        for k in range(3):
            a = 2 * np.pi * k / 3
            dirs.append(frame @ np.array([np.cos(a), np.sin(a), 0.0]))
    while len(dirs) < n:
        v = rng.standard_normal(3)
        v /= np.linalg.norm(v)
        dirs += [v, -v]
    R = np.stack([rotation_taking_e3_to(d) for d in dirs])
    yaw = rng.uniform(-np.pi, np.pi, size=n)
    R = R @ exp(np.stack([np.zeros(n), np.zeros(n), yaw], axis=-1))
    axis = np.cross(R[0, :, 2], rng.standard_normal(3))
    axis /= np.linalg.norm(axis)
    R[0] = exp(axis * residual) @ R[0]
    return R


def network_suite(rng: np.random.Generator, samples: int, max_bodies: int) -> list[Array]:
    """Random networks with n from 1 to ``max_bodies`` plus near-cancelling ones.

    About a quarter are near-cancelling, with |sum d_i| from 1e-2 down to 1e-6.
    """
    nets: list[Array] = []
    sizes = [1, 2, 3, max_bodies]
    sizes += list(rng.integers(1, max_bodies + 1, size=max(samples - len(sizes), 0)))
    for k, n in enumerate(sizes[:samples]):
        n = int(n)
        if k % 4 == 3 and n >= 2:
            nets.append(near_cancelling_network(rng, n, float(10.0 ** rng.uniform(-6, -2))))
        else:
            nets.append(random_network(rng, n))
    return nets
