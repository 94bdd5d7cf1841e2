"""Short numbers for the positive and linear leaves of a robust band unit (RobustCert.v).

The boxes of a band certificate's tree are midpoint splits of the enclosing box, whose
corners carry the identification's decimal centre: after a dozen splits a corner has a
denominator of about 10⁵·2¹², and the products of N_1, N_2 and det (the paper's
Section 4 conditions) then reach 45 digits, which Coq's kernel computes slowly. Two forms
of RobustCert.v let a unit use short numbers instead, and both are re-checked by Coq for
whatever numbers the unit gives:

* ``RGrid 2ᵏ t``: Coq rounds the leaf's box outwards to the dyadic grid 2⁻ᵏ
  (``grid_box``: each corner to a multiple of 2⁻ᵏ) and checks the leaf on that larger box,
  whose corners are short; the unit writes only the grid.
* ``RLinY c s y``: a linear leaf whose region term is bounded along a short rational
  direction y (the gradient midpoints, negated and rounded), with s² >= χ² yᵀ Σ_φ y
  (``lin_dir_ok``), instead of the 45-digit midpoints Coq would compute itself.

This module computes both exactly, with the terms Coq computes (the exact checker's
``leaf_bounds`` and ``linear_parts``), and returns a form only when its Coq check passes.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from gmpy2 import isqrt, mpq

from verify.passivity.check import robust_band as rb

Interval = tuple[mpq, mpq]

#: The paper's structure: first-order numerators over monic second-order denominators.
PAPER_SHAPE = rb.Shape(1, 2)
#: The grids 2⁻ᵏ tried for a leaf's box, coarsest first.
BOX_BITS = range(4, 31)
#: The grids 2⁻ʲ tried for a direction and its bound s.
DIRECTION_BITS = range(0, 41)


def widened(box: Sequence[Interval], bits: int) -> list[Interval]:
    """The box with its corners rounded outwards to the grid 2^-bits: RobustCert.v's
    ``grid_box`` (``Qfloor``, ``Qceiling``) for the grid 2^bits."""
    g = 2 ** bits
    return [(mpq(math.floor(lo * g), g), mpq(math.ceil(hi * g), g)) for lo, hi in box]


def _floor_on_grid(v: mpq, bits: int) -> mpq:
    g = 2 ** bits
    return mpq(math.floor(v * g), g)


def _ceil_sqrt_on_grid(v: mpq, bits: int) -> mpq:
    """The least s on the grid 2^-bits with s >= 0 and s² >= v (v >= 0)."""
    g = 2 ** bits
    n = int(isqrt(math.floor(v * g * g)))
    while mpq(n * n, g * g) < v:
        n += 1
    return mpq(n, g)


def _lower_bound(value: mpq, claimed: mpq) -> mpq | None:
    """The claimed bound when value reaches it, else a short positive one below value."""
    if value >= claimed:
        return claimed
    if value <= 0:
        return None
    for bits in DIRECTION_BITS:
        c = _floor_on_grid(value, bits)
        if c > 0:
            return c
    return None


def positive_bounds(box: Sequence[Interval], claimed: Sequence[mpq]) -> list[mpq] | None:
    """Lower bounds (c0, c1, c2) > 0 that RobustCert.v's ``RPos`` accepts on ``box``
    (φ coordinates then t = ω²), or None."""
    bounds = rb.leaf_bounds(box[:-1], box[-1], "x", PAPER_SHAPE, rb.ExactOps)
    out = [_lower_bound(lo, c) for (lo, _), c in zip(bounds, claimed, strict=True)]
    return None if any(c is None for c in out) else out


def direction_term(g: Interval, b: Interval, yk: mpq, pc: mpq) -> mpq:
    """RobustCert.v's ``dir_term``: -y_k (φc_k - m_k) + min((G_k + y_k)(b_k - m_k))."""
    m = (b[0] + b[1]) / 2
    lo, hi = g[0] + yk, g[1] + yk
    prods = (lo * (b[0] - m), lo * (b[1] - m), hi * (b[0] - m), hi * (b[1] - m))
    return -yk * (pc - m) + min(prods)


def quadratic(y: Sequence[mpq], covariance: Sequence[Sequence[mpq]]) -> mpq:
    """yᵀ Σ y, exactly."""
    n = len(y)
    return sum((y[i] * covariance[i][j] * y[j] for i in range(n) for j in range(n)), mpq(0))


def direction_ok(box: Sequence[Interval], value: Interval, grad: Sequence[Interval],
                 y: Sequence[mpq], c: mpq, s: mpq, phi_c: Sequence[mpq],
                 covariance: Sequence[Sequence[mpq]], chi2: mpq) -> bool:
    """Does RobustCert.v's ``lin_dir_ok`` accept (c, s, y) for one condition (exact)?"""
    q = quadratic(y, covariance)
    if not (c > 0 and s >= 0 and q > 0 and chi2 * q <= s * s):
        return False
    bound = value[0] - s + sum((direction_term(g, b, yk, pc)
                                for g, b, yk, pc in zip(grad, box, y, phi_c, strict=True)),
                               mpq(0))
    return c <= bound


def linear_forms(box: Sequence[Interval], claimed: Sequence[mpq], phi_c: Sequence[mpq],
                 covariance: Sequence[Sequence[mpq]], chi2: mpq
                 ) -> list[tuple[mpq, mpq, list[mpq]]] | None:
    """(c, s, y) per condition (N_1, N_2, det) that ``lin_dir_ok`` accepts on ``box``,
    with y the negated gradient midpoints rounded to the coarsest grid that passes; None
    when some condition has none."""
    phi, t = list(box[:-1]), box[-1]
    _, parts = rb.linear_parts(phi, t, "x", PAPER_SHAPE)
    out = []
    for (value, grad), c in zip(parts, claimed, strict=True):
        exact = [-(lo + hi) / 2 for lo, hi in grad]
        found = None
        for bits in DIRECTION_BITS:
            g = 2 ** bits
            y = [mpq(round(v * g), g) for v in exact]
            q = quadratic(y, covariance)
            if q <= 0:
                continue
            s = _ceil_sqrt_on_grid(chi2 * q, bits)
            bound = value[0] - s + sum((direction_term(gk, b, yk, pc) for gk, b, yk, pc
                                        in zip(grad, phi, y, phi_c, strict=True)), mpq(0))
            c_short = _lower_bound(bound, c)
            if c_short is not None and direction_ok(phi, value, grad, y, c_short, s, phi_c,
                                                    covariance, chi2):
                found = (c_short, s, y)
                break
        if found is None:
            return None
        out.append(found)
    return out


def short_positive(box: Sequence[Interval], claimed: Sequence[mpq]
                   ) -> tuple[int, list[mpq]] | None:
    """The coarsest grid 2^-bits whose box around ``box`` (:func:`widened`, Coq's
    ``grid_box``) ``RPos`` accepts: (bits, its bounds)."""
    for bits in BOX_BITS:
        bounds = positive_bounds(widened(box, bits), claimed)
        if bounds is not None:
            return bits, bounds
    return None


def short_linear(box: Sequence[Interval], claimed: Sequence[mpq], phi_c: Sequence[mpq],
                 covariance: Sequence[Sequence[mpq]], chi2: mpq
                 ) -> tuple[int, list[tuple[mpq, mpq, list[mpq]]]] | None:
    """The coarsest grid 2^-bits whose box around ``box`` ``RLinY`` accepts: (bits, the
    (c, s, y) of each condition)."""
    for bits in BOX_BITS:
        forms = linear_forms(widened(box, bits), claimed, phi_c, covariance, chi2)
        if forms is not None:
            return bits, forms
    return None


__all__ = ["BOX_BITS", "DIRECTION_BITS", "PAPER_SHAPE", "direction_ok", "direction_term",
           "linear_forms", "positive_bounds", "short_linear", "short_positive", "widened"]
