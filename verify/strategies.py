"""Public hypothesis strategies for users' own test suites (rotations and networks).

>>> from hypothesis import given
>>> from verify.strategies import networks
>>> @given(networks(max_bodies=50))
... def test_my_controller(R): ...

Networks always have a well-defined dbar (|sum d_i| above the tool's threshold).
"""

from __future__ import annotations

import numpy as np
from hypothesis import assume
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from verify.so3 import exp, quaternion_to_matrix
from verify.system.stealthy import DBAR_RELATIVE_TOLERANCE

_unit_floats = st.floats(-1.0, 1.0, allow_nan=False, allow_infinity=False, width=64)


def _quaternion_rows(n: int):
    return hnp.arrays(np.float64, (n, 4), elements=_unit_floats)


def _to_rotations(q: np.ndarray) -> np.ndarray:
    q = q.copy()
    small = np.linalg.norm(q, axis=-1) < 1e-3
    q[small] = np.array([1.0, 0.0, 0.0, 0.0])
    return quaternion_to_matrix(q)


def rotations() -> st.SearchStrategy[np.ndarray]:
    """Single rotation matrices (3, 3), from quaternions with shrinkable entries."""
    return _quaternion_rows(1).map(lambda q: _to_rotations(q)[0])


@st.composite
def rotations_near_angle(draw, angle: float, spread: float = 1e-6) -> np.ndarray:
    """Rotations whose angle lies within ``spread`` of ``angle`` (e.g. pi for the log)."""
    axis = draw(hnp.arrays(np.float64, 3, elements=_unit_floats))
    if np.linalg.norm(axis) < 1e-3:
        axis = np.array([0.0, 0.0, 1.0])
    offset = draw(st.floats(-spread, spread, allow_nan=False))
    theta = float(np.clip(angle + offset, 0.0, np.pi))
    return exp(axis / np.linalg.norm(axis) * theta)


@st.composite
def networks(draw, min_bodies: int = 1, max_bodies: int = 200) -> np.ndarray:
    """Networks (n, 3, 3) with a well-defined dbar."""
    n = draw(st.integers(min_bodies, max_bodies))
    R = _to_rotations(draw(_quaternion_rows(n)))
    s = np.linalg.norm(R[:, :, 2].sum(axis=0))
    assume(s > 1e3 * DBAR_RELATIVE_TOLERANCE * n)
    return R


@st.composite
def near_cancelling_networks(draw, max_bodies: int = 200) -> np.ndarray:
    """Networks whose directions nearly cancel: |sum d_i| from 1e-6 to 1e-2."""
    from verify.sampling import near_cancelling_network

    n = draw(st.integers(2, max_bodies))
    residual = 10.0 ** draw(st.floats(-6.0, -2.0))
    seed = draw(st.integers(0, 2**32 - 1))
    return near_cancelling_network(np.random.default_rng(seed), n, residual)
