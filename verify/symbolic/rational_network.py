"""Exact rational instances of the paper's Section 2 objects.

A body attitude given by an integer quaternion has rational entries, so d_i, s,
P = I - s s^T / (s^T s), the unscaled W~ (blocks hat(e3) R_i^T P) and the repaired
projector A = I - W~ M^{-1} W~^T, M = W~^T W~ + s s^T / (s^T s), are all rational: every
relation between them is decided exactly, with no floating point. The factor 1/|s| (the
only irrational quantity) is left out; A does not depend on it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from verify.symbolic.algebra import E3, hat, rotation_from_quaternion

IntQuaternion = tuple[int, int, int, int]


@dataclass(frozen=True)
class RationalNetwork:
    """A network of bodies whose attitudes come from integer quaternions."""

    quaternions: tuple[IntQuaternion, ...]

    @classmethod
    def of(cls, quaternions: Sequence[Sequence[int]]) -> RationalNetwork:
        qs = tuple(tuple(int(c) for c in q) for q in quaternions)
        if not qs or any(len(q) != 4 or all(c == 0 for c in q) for q in qs):
            raise ValueError("need at least one non-zero integer quaternion (w, x, y, z)")
        return cls(qs)  # type: ignore[arg-type]

    @property
    def n(self) -> int:
        return len(self.quaternions)

    @cached_property
    def rotations(self) -> tuple[sp.Matrix, ...]:
        return tuple(rotation_from_quaternion([sp.Integer(c) for c in q]) for q in self.quaternions)

    @cached_property
    def directions(self) -> tuple[sp.Matrix, ...]:
        return tuple(R * E3 for R in self.rotations)

    @cached_property
    def direction_sum(self) -> sp.Matrix:
        s = sp.zeros(3, 1)
        for d in self.directions:
            s += d
        return s

    @property
    def dbar_defined(self) -> bool:
        return self.direction_sum != sp.zeros(3, 1)

    @cached_property
    def tangent_projector(self) -> sp.Matrix:
        """P = I - s s^T / (s^T s), the projector onto the plane orthogonal to dbar."""
        s = self.direction_sum
        return sp.eye(3) - (s * s.T) / (s.T * s)[0, 0]

    @cached_property
    def w_unscaled(self) -> sp.Matrix:
        """W~ = |s| W in Q^{3n x 3}, blocks hat(e3) R_i^T P."""
        P = self.tangent_projector
        blocks = [hat(E3) * R.T * P for R in self.rotations]
        return sp.Matrix.vstack(*blocks)

    @cached_property
    def s_matrix(self) -> sp.Matrix:
        """S(d) = blockdiag(-R_i hat(e3)) in Q^{3n x 3n}."""
        return sp.diag(*[-R * hat(E3) for R in self.rotations])

    @cached_property
    def jacobian_unscaled(self) -> sp.Matrix:
        """|s| d dbar / d d = [P, P, ..., P] in Q^{3 x 3n}."""
        return sp.Matrix.hstack(*([self.tangent_projector] * self.n))

    @cached_property
    def gram(self) -> sp.Matrix:
        return self.w_unscaled.T * self.w_unscaled

    @cached_property
    def projector(self) -> sp.Matrix:
        """Repaired A = I - W~ (W~^T W~ + s s^T / s^T s)^{-1} W~^T."""
        s = self.direction_sum
        M = self.gram + (s * s.T) / (s.T * s)[0, 0]
        W = self.w_unscaled
        return sp.eye(3 * self.n) - W * M.inv() * W.T

    @cached_property
    def projector_from_pinv(self) -> sp.Matrix:
        """A = I - W~ W~^+ with sympy's exact Moore-Penrose inverse (an independent route)."""
        W = self.w_unscaled
        return sp.eye(3 * self.n) - W * W.pinv()


def nearly_antipodal_pair(k: int) -> RationalNetwork:
    """Two bodies: d_1 = e3 and d_2 = R(q) e3 with q = (1, k, 0, 0), a turn of about pi - 2/k.

    |d_1 + d_2| = 2/sqrt(1 + k^2) (exactly), so large k gives a nearly cancelling sum.
    """
    return RationalNetwork.of([(1, 0, 0, 0), (1, k, 0, 0)])


def sample_networks() -> list[tuple[str, RationalNetwork]]:
    """The exact instances used by the Section 2 checks: n = 1..6, plus adversarial ones."""
    quats = [(1, 0, 0, 0), (2, 1, -1, 3), (1, 2, 2, -1), (3, -1, 0, 2), (1, 1, 1, 1), (4, 0, -3, 1)]
    nets = [(f"n={k}", RationalNetwork.of(quats[:k])) for k in range(1, len(quats) + 1)]
    nets.append(("nearly antipodal pair, |s| = 2/sqrt(1 + 10^12)", nearly_antipodal_pair(10**6)))
    nets.append(
        (
            "four bodies: one exactly opposite pair and one nearly opposite pair",
            RationalNetwork.of([(1, 0, 0, 0), (0, 1, 1, 0), (5, 0, 0, 3), (-5, 2, 3000, 1)]),
        )
    )
    return nets
