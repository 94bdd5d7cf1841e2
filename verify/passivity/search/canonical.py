"""Coarse certificates: the same proof on a coarse rational grid, so bytes do not jitter.

The KYP and band searches propose P (and Q) from floating-point Riccati or SDP
solutions whose last bits change with the BLAS and library versions. A certificate with
a margin stays valid when P moves a little, so before a certificate is written its
matrices are rounded to the coarsest dyadic grid (a few significant bits relative to the
largest entry) on which the exact check still passes. Rounding an exact matrix to a
coarse grid is a deterministic function of it, and last-bit noise in the proposal moves
the result only when an entry sits on a grid boundary. Equalities the KYP matrix needs
exactly (P B N = C^T N for N spanning ker(D + D^T)) are restored exactly after
rounding: k pivot rows and columns of P (k = rank B N, the pivot rows of B N found
by exact elimination) are solved for exactly and every other entry keeps its grid value,
so only those rows carry long numbers (the denominator of the pivot block of B N) and
the rest stay short; a projection that spreads the correction over every entry is the
fallback. Short entries are what makes a certificate cheap to re-check, in Python and in
Coq's kernel (:mod:`verify.coq.kyp`). Every candidate is checked exactly; the unrounded
matrix is kept when no coarse one passes.
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


def pivot_rows(G: ex.RationalMatrix) -> list[int] | None:
    """k rows of G (n x k) whose k x k block is invertible, in increasing order: exact
    elimination, each column's pivot the remaining row of largest magnitude (the first
    such row on a tie), so the choice is a function of the exact G. None when G has
    rank below k."""
    n, k = len(G), len(G[0]) if G else 0
    W = [row[:] for row in G]
    chosen: list[int] = []
    for c in range(k):
        rest = [i for i in range(n) if i not in chosen]
        if not rest:
            return None
        r = max(rest, key=lambda i: (abs(W[i][c]), -i))
        if W[r][c] == 0:
            return None
        chosen.append(r)
        for i in rest:
            if i != r and W[i][c] != 0:
                f = W[i][c] / W[r][c]
                W[i] = [a - f * b for a, b in zip(W[i], W[r], strict=True)]
    return sorted(chosen)


def solve_pivot_rows(P: ex.RationalMatrix, G: ex.RationalMatrix, target: ex.RationalMatrix,
                     pivots: list[int]) -> ex.RationalMatrix:
    """The symmetric matrix equal to P off the ``pivots`` rows and columns with
    (result) G = target, exactly.

    With S the pivot rows, F the others and Y = P_FF: the rows F of the equality give
    P_FS = (T_F - Y G_F) G_S^-1 and the rows S give P_SS = (T_S - P_FS^T G_F) G_S^-1,
    which is symmetric when G^T T is (the condition for any symmetric solution).
    """
    n = len(P)
    free = [i for i in range(n) if i not in set(pivots)]
    Y = [[P[i][j] for j in free] for i in free]
    GS, GF = [G[i] for i in pivots], [G[i] for i in free]
    TS, TF = [target[i] for i in pivots], [target[i] for i in free]
    GSi = ex.inverse(GS)
    PFS = ex.matmul(ex.add(TF, ex.matmul(Y, GF), -1), GSi) if free else []
    PSS = ex.matmul(ex.add(TS, ex.matmul(ex.transpose(PFS), GF), -1) if free else TS, GSi)
    out = [row[:] for row in P]
    for a, i in enumerate(free):
        for b, j in enumerate(pivots):
            out[i][j] = out[j][i] = PFS[a][b]
    for a, i in enumerate(pivots):
        for b, j in enumerate(pivots):
            out[i][j] = PSS[a][b]
    return out


def coarse_kyp(model: ExactModel, P: ex.RationalMatrix) -> ex.RationalMatrix:
    """The coarsest grid rounding of a valid KYP matrix P that ``check_kyp`` accepts.

    When the KYP matrix needs P G = T exactly, the grids are tried first with the pivot
    rows of G solved for (:func:`solve_pivot_rows`: short entries elsewhere), then with
    the correction projected over every entry (long entries everywhere)."""
    from verify.passivity.search.kyp import _project_equalities

    if model.n == 0 or _exponent([P], GRID_BITS[0]) is None:
        return P
    equalities = _equalities(model)
    if equalities is None:
        fixes = [lambda X: X]
    else:
        fixes = [lambda X: _project_equalities(X, *equalities)]
        pivots = pivot_rows(equalities[0])
        if pivots is not None:
            fixes.insert(0, lambda X: solve_pivot_rows(X, *equalities, pivots))
    for fix in fixes:
        for bits in GRID_BITS:
            exponent = _exponent([P], bits)
            assert exponent is not None  # P is not zero
            candidate = fix(_symmetric(_round(P, exponent)))
            if ex.is_symmetric(candidate) and check_kyp(model, candidate).ok:
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


__all__ = ["GRID_BITS", "coarse_band", "coarse_kyp", "pivot_rows", "solve_pivot_rows"]
