"""Lie-group time stepping on SO(3): each step stays on the group (paper, eq. (1)).

Equations of the form Y' = hat(F(t, Y)) Y for a batch of rotations Y (shape (m, 3, 3)),
with F the spatial angular velocities (shape (m, 3)); a body velocity omega of R enters
as F = R omega. Every update multiplies by matrix exponentials, so Y stays in SO(3) to
rounding error without re-projection.

:func:`cf4_step` is the fourth-order commutator-free method of Celledoni, Marthinsen and
Owren (2003); :func:`lie_euler_step` is the first-order reference.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from verify.so3 import Array, exp

SpatialField = Callable[[float, Array], Array]


def lie_euler_step(f: SpatialField, t: float, Y: Array, h: float) -> Array:
    """Y_{k+1} = exp(h F(t, Y)) Y (order 1)."""
    return exp(h * f(t, Y)) @ Y


def cf4_step(f: SpatialField, t: float, Y: Array, h: float) -> Array:
    """One step of the order-4 commutator-free Lie-group method (CF4)."""
    F1 = f(t, Y)
    Y2 = exp(0.5 * h * F1) @ Y
    F2 = f(t + 0.5 * h, Y2)
    Y3 = exp(0.5 * h * F2) @ Y
    F3 = f(t + 0.5 * h, Y3)
    Y4 = exp(0.5 * h * (2.0 * F3 - F1)) @ Y2
    F4 = f(t + h, Y4)
    first = exp(h / 12.0 * (3.0 * F1 + 2.0 * F2 + 2.0 * F3 - F4))
    second = exp(h / 12.0 * (-F1 + 2.0 * F2 + 2.0 * F3 + 3.0 * F4))
    return second @ (first @ Y)


def integrate(
    f: SpatialField,
    Y0: Array,
    t_end: float,
    h: float,
    step: Callable[[SpatialField, float, Array, float], Array] = cf4_step,
    observe: Callable[[float, Array], None] | None = None,
) -> Array:
    """Integrate from t = 0 to ``t_end`` with fixed steps of (at most) ``h``."""
    steps = max(1, int(np.ceil(t_end / h - 1e-12)))
    dt = t_end / steps
    Y = np.array(Y0, dtype=float)
    if observe is not None:
        observe(0.0, Y)
    for k in range(steps):
        Y = step(f, k * dt, Y, dt)
        if observe is not None:
            observe((k + 1) * dt, Y)
    return Y


# --- rotations together with a Euclidean part (the human's state, running integrals) ---

MixedField = Callable[[float, Array, Array], tuple[Array, Array]]


def cf4_mixed_step(f: MixedField, t: float, Y: Array, x: Array, h: float) -> tuple[Array, Array]:
    """One CF4 step for (Y, x) in SO(3)^m x R^k with Y' = hat(F) Y and x' = g.

    ``f(t, Y, x)`` returns (F, g). On the Euclidean factor the exponential is a
    translation, so the same stages reduce to the classical Runge-Kutta method of order
    4; the two parts are advanced with the same stage values, so coupling between them
    keeps order 4.
    """
    F1, g1 = f(t, Y, x)
    Y2, x2 = exp(0.5 * h * F1) @ Y, x + 0.5 * h * g1
    F2, g2 = f(t + 0.5 * h, Y2, x2)
    Y3, x3 = exp(0.5 * h * F2) @ Y, x + 0.5 * h * g2
    F3, g3 = f(t + 0.5 * h, Y3, x3)
    Y4, x4 = exp(0.5 * h * (2.0 * F3 - F1)) @ Y2, x2 + 0.5 * h * (2.0 * g3 - g1)
    F4, g4 = f(t + h, Y4, x4)
    first = exp(h / 12.0 * (3.0 * F1 + 2.0 * F2 + 2.0 * F3 - F4))
    second = exp(h / 12.0 * (-F1 + 2.0 * F2 + 2.0 * F3 + 3.0 * F4))
    x_next = x + h / 6.0 * (g1 + 2.0 * g2 + 2.0 * g3 + g4)
    return second @ (first @ Y), x_next
