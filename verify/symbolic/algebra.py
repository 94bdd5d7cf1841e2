"""Exact algebra over SO(3) with sympy (paper, Sections 2 and 3).

Rotations are parametrised by a quaternion q = (w, x, y, z) with rational entries,
R(q) = I + 2 (w hat(v) + hat(v)^2) / |q|^2, v = (x, y, z). Every rotation except none is
of this form (q real, not all zero) and the entries are rational functions of q, so a
matrix identity over SO(3) becomes a rational-function identity, which
:func:`is_zero` decides exactly: bring to one fraction, expand the numerator, compare
with 0. No floating point and no heuristic ``simplify`` is involved.

Expressions with a square root (the norm |s| in dbar) are decided by
:func:`is_zero_modulo_root`: the root is a symbol r with the relation r^2 = radicand, and
the numerator is reduced modulo that relation before comparison.
"""

from __future__ import annotations

from collections.abc import Sequence

import sympy as sp

E3 = sp.Matrix([0, 0, 1])


def hat(v: Sequence[sp.Expr] | sp.Matrix) -> sp.Matrix:
    """Skew-symmetric matrix of a 3-vector: hat(v) w = v x w."""
    x, y, z = (v[0], v[1], v[2])
    return sp.Matrix([[0, -z, y], [z, 0, -x], [-y, x, 0]])


def vee(M: sp.Matrix) -> sp.Matrix:
    """vee of the skew part of M: (sk M)^vee."""
    return sp.Matrix(
        [
            (M[2, 1] - M[1, 2]) / 2,
            (M[0, 2] - M[2, 0]) / 2,
            (M[1, 0] - M[0, 1]) / 2,
        ]
    )


def sk(M: sp.Matrix) -> sp.Matrix:
    """Skew-symmetric part (M - M^T)/2."""
    return (M - M.T) / 2


def sym(M: sp.Matrix) -> sp.Matrix:
    """Symmetric part (M + M^T)/2."""
    return (M + M.T) / 2


def quaternion_symbols(name: str) -> tuple[sp.Symbol, sp.Symbol, sp.Symbol, sp.Symbol]:
    """Four real symbols (w, x, y, z) for a generic rotation."""
    return sp.symbols(f"{name}_w {name}_x {name}_y {name}_z", real=True)


def rotation_from_quaternion(q: Sequence[sp.Expr]) -> sp.Matrix:
    """R(q) = I + 2 (w hat(v) + hat(v)^2) / |q|^2, exact for symbolic or rational q."""
    w, x, y, z = q
    K = hat([x, y, z])
    norm2 = w**2 + x**2 + y**2 + z**2
    return sp.eye(3) + 2 * (w * K + K * K) / norm2


def generic_rotation(name: str) -> sp.Matrix:
    """A symbolic rotation R(q) in four free quaternion symbols."""
    return rotation_from_quaternion(quaternion_symbols(name))


def vector_symbols(name: str) -> sp.Matrix:
    """A symbolic real 3-vector."""
    return sp.Matrix(sp.symbols(f"{name}_1 {name}_2 {name}_3", real=True))


def matrix_symbols(name: str, rows: int = 3, cols: int = 3) -> sp.Matrix:
    """A symbolic real matrix with independent entries (no constraint)."""
    return sp.Matrix(rows, cols, lambda i, j: sp.Symbol(f"{name}_{i + 1}{j + 1}", real=True))


def is_zero(expr: sp.Expr) -> bool:
    """Exact decision of ``expr == 0`` for a rational function of its symbols."""
    numerator, _ = sp.fraction(sp.together(sp.expand(expr)))
    return sp.expand(numerator) == 0


def is_zero_matrix(M: sp.Matrix) -> bool:
    """Exact decision that every entry of a matrix of rational functions is zero."""
    return all(is_zero(e) for e in M)


def is_zero_modulo_root(expr: sp.Expr, root: sp.Symbol, radicand: sp.Expr) -> bool:
    """Exact decision of ``expr == 0`` given root > 0 and root^2 = radicand.

    ``expr`` must be rational in ``root`` and the other symbols. The numerator is a
    polynomial in ``root``; its remainder modulo root^2 - radicand is a0 + a1*root, and
    with a1 != 0 that would need root = -a0/a1 for every value of the free symbols,
    impossible for an independent square root, so zero means a0 = a1 = 0 exactly.
    """
    numerator, _ = sp.fraction(sp.together(sp.expand(expr)))
    remainder = sp.rem(sp.expand(numerator), root**2 - radicand, root)
    coefficients = sp.Poly(sp.expand(remainder), root).all_coeffs()
    return all(sp.expand(c) == 0 for c in coefficients)
