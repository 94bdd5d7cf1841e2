"""Section 3 of the paper: the quasi-average R-bar, the interface and leader laws.

* eq. (4):  R-bar' = hat(omega~_h^s) R-bar  (the quasi-average, spatial velocity);
* eq. (6a): omega~_h^s = k_s R-bar sk(R-bar^T R_l)^vee  (the interface law);
* eq. (6b): omega_l = k_s sk(R_l^T R-bar)^vee + R_l^T omega_h^s  (the virtual leader);
* Section 2: omega_hi = R_i^T omega~_h^s, the human part of body i's velocity.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from verify.errors import VerifyInputError
from verify.so3 import E3, Array, exp, hat, transpose, vee
from verify.system.stealthy import dbar


def _check_gain(k_s: float) -> float:
    k = float(k_s)
    if not np.isfinite(k) or k <= 0.0:
        raise VerifyInputError(f"the coupling gain k_s must be a positive number, got {k_s!r}")
    return k


def interface_velocity(R_bar: ArrayLike, R_l: ArrayLike, k_s: float) -> Array:
    """omega~_h^s = k_s R-bar sk(R-bar^T R_l)^vee, eq. (6a)."""
    R_bar = np.asarray(R_bar, dtype=float)
    return _check_gain(k_s) * (R_bar @ vee(transpose(R_bar) @ np.asarray(R_l, dtype=float)))


def leader_velocity(R_l: ArrayLike, R_bar: ArrayLike, k_s: float, omega_h_s: ArrayLike) -> Array:
    """omega_l = k_s sk(R_l^T R-bar)^vee + R_l^T omega_h^s, eq. (6b) (a body velocity)."""
    R_l = np.asarray(R_l, dtype=float)
    coupling = _check_gain(k_s) * vee(transpose(R_l) @ np.asarray(R_bar, dtype=float))
    return coupling + transpose(R_l) @ np.asarray(omega_h_s, dtype=float)


def human_body_velocities(R: ArrayLike, omega_tilde: ArrayLike) -> Array:
    """omega_hi = R_i^T omega~_h^s for every body (shape (n, 3)), Section 2."""
    return transpose(R) @ np.asarray(omega_tilde, dtype=float)


def quasi_average_rate(R_bar: ArrayLike, omega_tilde: ArrayLike) -> Array:
    """R-bar' = hat(omega~_h^s) R-bar, eq. (4)."""
    return hat(omega_tilde) @ np.asarray(R_bar, dtype=float)


def rotation_taking_e3_to(u: ArrayLike) -> Array:
    """A rotation R with R e3 = u for a unit vector u (the shortest one, about e3 x u).

    For u = -e3 (where the shortest rotation is not unique) a half turn about e1 is used.
    """
    u = np.asarray(u, dtype=float)
    axis = np.cross(E3, u)
    sin_t = float(np.linalg.norm(axis))
    cos_t = float(np.dot(E3, u))
    angle = float(np.arctan2(sin_t, cos_t))
    if sin_t < 1e-12:
        return np.eye(3) if cos_t > 0 else np.diag([1.0, -1.0, -1.0])
    return exp(axis / sin_t * angle)


def quasi_average_initial(R: ArrayLike, yaw: float = 0.0) -> Array:
    """An initial quasi-average R-bar(0) with R-bar(0) e3 = dbar (Section 3, first paragraph).

    The rotation about the z-axis is free in the paper; ``yaw`` fixes it.
    """
    base = rotation_taking_e3_to(dbar(R))
    return base @ exp(np.array([0.0, 0.0, float(yaw)]))
