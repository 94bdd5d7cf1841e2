"""Coarse certificates: the same proof on a coarse rational grid, so bytes do not jitter.

The KYP and band searches propose P (and Q) from floating-point Riccati or SDP
solutions whose last bits change with the BLAS and library versions. A certificate with
a margin stays valid when P moves a little, so before a certificate is written its
matrices are rounded to the coarsest dyadic grid (a few significant bits relative to the
largest entry) on which the exact check still passes. Rounding an exact matrix to a
coarse grid is a deterministic function of it, and last-bit noise in the proposal moves
the result only when an entry sits on a grid boundary. Equalities the KYP matrix needs
exactly (P B N = C^T N for N spanning ker(D + D^T)) are restored by an exact projection
after rounding. Every candidate is checked exactly; the unrounded matrix is kept when
no coarse one passes.
"""

from __future__ import annotations

from fractions import Fraction

from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel, check_kyp
from verify.passivity.check.gkyp import ComplexMatrix, check_gkyp

GRID_BITS = (8, 12, 16, 24, 32)  # significant bits relative to the largest entry


def _round(X: ex.RationalMatrix, exponent: int) -> ex.RationalMatrix:
    """Each entry to the nearest multiple of 2**exponent (ties to even), exactly."""
    step = Fraction(2) ** exponent
    return [[mpq(round(Fraction(x) / step) * step) for x in row] for row in X]


def _floor_log2(x: Fraction) -> int:
    """floor(log2 x) for a rational x > 0, exactly."""
    p, q = x.numerator, x.denominator
    e = p.bit_length() - q.bit_length()
    return e if (p >= q << e if e >= 0 else p << -e >= q) else e - 1


def _exponent(matrices: list[ex.RationalMatrix], bits: int) -> int | None:
    """Grid exponent keeping ``bits`` significant bits of the largest entry."""
    largest = max((abs(Fraction(x)) for X in matrices for row in X for x in row), default=0)
    if largest == 0:
        return None
    return _floor_log2(largest) + 1 - bits


def _symmetric(X: ex.RationalMatrix) -> ex.RationalMatrix:
    n = len(X)
    return [[X[min(i, j)][max(i, j)] for j in range(n)] for i in range(n)]


def _equalities(model: ExactModel):
    """(G, target) with the needed P G = target, or None when D + D^T is nonsingular."""
    S = ex.add(model.D, ex.transpose(model.D))
    N = ex.kernel_basis(S)
    if not N or not N[0]:
        return None
    G = ex.matmul(model.B, N)
    if ex.determinant(ex.matmul(ex.transpose(G), G)) == 0:
        return None
    return G, ex.matmul(ex.transpose(model.C), N)


def coarse_kyp(model: ExactModel, P: ex.RationalMatrix) -> ex.RationalMatrix:
    """The coarsest grid rounding of a valid KYP matrix P that ``check_kyp`` accepts."""
    from verify.passivity.search.kyp import _project_equalities

    if model.n == 0:
        return P
    equalities = _equalities(model)
    for bits in GRID_BITS:
        exponent = _exponent([P], bits)
        if exponent is None:
            return P
        candidate = _symmetric(_round(P, exponent))
        if equalities is not None:
            candidate = _project_equalities(candidate, *equalities)
        if check_kyp(model, candidate).ok:
            return candidate
    return P


def _hermitian(X: ComplexMatrix, exponent: int) -> ComplexMatrix:
    re, im = _round(X[0], exponent), _round(X[1], exponent)
    n = len(re)
    return (_symmetric(re), [[im[i][j] if i < j else (-im[j][i] if i > j else mpq(0))
                              for j in range(n)] for i in range(n)])


def coarse_band(model: ExactModel, P: ComplexMatrix, Q: ComplexMatrix,
                band: tuple[Fraction, Fraction]) -> tuple[ComplexMatrix, ComplexMatrix]:
    """The coarsest grid rounding of valid band matrices (P, Q) that ``check_gkyp`` accepts."""
    if model.n == 0:
        return P, Q
    for bits in GRID_BITS:
        exponent = _exponent([*P, *Q], bits)
        if exponent is None:
            return P, Q
        Pc, Qc = _hermitian(P, exponent), _hermitian(Q, exponent)
        if check_gkyp(model, Pc, Qc, band).ok:
            return Pc, Qc
    return P, Q


__all__ = ["GRID_BITS", "coarse_band", "coarse_kyp"]
