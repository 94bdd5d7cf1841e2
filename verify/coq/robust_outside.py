"""Directions for the leaves *outside* of a robust band certificate (``ROut`` in RobustCert.v).

A leaf *outside* says that its box of φ misses the identification's region; the certificate
gives a point p, and the exact Python checker bounds the region's quadratic form over the
box from below by its tangent plane at p (``outside_bound``). Coq checks the same fact
from the region's dual bound (``out_ok``): for a rational direction y on φ,

    2 min_box y.(φ - φc) - yᵀ Σ_φ y > χ²

shows that no φ of the box is in the region. With y = Σ_φ⁻¹ (p - φc) the left side *is*
the tangent-plane bound (q(p) + g.(φ - p) with g = 2y), so every leaf the Python checker
accepts passes. That y has entries of some 160 digits (Σ_φ⁻¹ has), so the direction
written into the unit is y scaled by the best factor t = lb / (yᵀ Σ_φ y) and rounded to
the coarsest dyadic grid 2⁻ᵏ on which the inequality above still holds, exactly. The
direction carries no trust: Coq re-checks the inequality for whatever y the unit gives.
"""

from __future__ import annotations

from collections.abc import Sequence

from gmpy2 import mpq

from verify.coq.robust_leaves import quadratic

Interval = tuple[mpq, mpq]

#: The finest grid tried before the exact direction is written.
MAX_BITS = 64


def dual_value(y: Sequence[mpq], box: Sequence[Interval], center: Sequence[mpq],
               covariance: Sequence[Sequence[mpq]]) -> tuple[mpq, mpq]:
    """(lb, yᵀ Σ y) with lb the least value of y.(φ - φc) over the box: the terms of
    RobustCert.v's ``out_ok`` (which checks lb + lb - yᵀ Σ y > χ²)."""
    lb = sum((min(y[k] * (box[k][0] - center[k]), y[k] * (box[k][1] - center[k]))
              for k in range(len(y))), mpq(0))
    return lb, quadratic(y, covariance)


def passes(y: Sequence[mpq], box: Sequence[Interval], center: Sequence[mpq],
           covariance: Sequence[Sequence[mpq]], chi2: mpq) -> bool:
    """Does ``out_ok`` accept y for this box (exact)?"""
    lb, q = dual_value(y, box, center, covariance)
    return lb + lb - q > chi2


def outside_direction(box: Sequence[Interval], point: Sequence[mpq],
                      center: Sequence[mpq], covariance: Sequence[Sequence[mpq]],
                      inverse: Sequence[Sequence[mpq]], chi2: mpq) -> list[mpq] | None:
    """A short rational direction y that ``out_ok`` accepts for ``box`` (φ coordinates
    only), from the leaf's tangent point; None when even the exact Σ_φ⁻¹ (p - φc) fails
    (the leaf is then not one the Python checker accepts either)."""
    n = len(center)
    exact = [sum((inverse[i][j] * (point[j] - center[j]) for j in range(n)), mpq(0))
             for i in range(n)]
    lb, q = dual_value(exact, box, center, covariance)
    if not lb + lb - q > chi2:
        return None
    scale = lb / q if q > 0 and lb > 0 else mpq(1)
    for bits in range(MAX_BITS + 1):
        grid = 2 ** bits
        rounded = [mpq(round(scale * v * grid), grid) for v in exact]
        if passes(rounded, box, center, covariance, chi2):
            return rounded
    return exact


__all__ = ["MAX_BITS", "dual_value", "outside_direction", "passes"]
