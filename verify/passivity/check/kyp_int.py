"""The KYP matrix M(P) as one integer matrix over a common denominator (FLINT, exact).

M(P) = [[Aᵀ P + P A, P B − Cᵀ], [Bᵀ P − C, −(D + Dᵀ)]] (the KYP lemma, the paper's
Section 4) is formed from the integer numerators of A, B, C, D and P (each over its
own least common denominator) with FLINT ``fmpz_mat`` products: no rational arithmetic
per entry, and no gcd until the end. The result is exact; it feeds the verified
floating-point Cholesky test (:mod:`verify.passivity.check.float_cholesky`) without a
round trip through ``mpq``.

A certificate whose long denominators sit in a few rows and columns (a short dyadic P
corrected exactly on k pivot rows to meet P B N = Cᵀ N) is split: Aᵀ P = Aᵀ P_light +
(a product through those k rows and columns), so the n x n x n product runs on short
integers and only thin products carry the long ones.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import reduce

import flint
from gmpy2 import lcm, mpz

from verify.passivity.check import exact as ex


@dataclass(frozen=True)
class IntMatrix:
    """The exact matrix Z / d: Z a FLINT integer matrix, d a positive integer."""

    Z: flint.fmpz_mat
    d: int
    rows: list[list[int]]  # Z's entries as Python integers


def int_matrix(m: ex.RationalMatrix, rows: int, cols: int) -> IntMatrix:
    """``m`` over the least common denominator of its entries (exact)."""
    d = reduce(lcm, {x.denominator for row in m for x in row}, mpz(1))
    ints = [[int(x.numerator * (d // x.denominator)) for x in row] for row in m]
    return IntMatrix(flint.fmpz_mat(rows, cols, [z for row in ints for z in row]), int(d),
                     ints)


def int_matrix_from_ints(rows: list[list[int]], num: int, den: int,
                         cols: int | None = None) -> IntMatrix:
    """The matrix rows * den / num as an :class:`IntMatrix` (integer rows over d = num,
    times den; den is 1 or a power of two in use)."""
    r = len(rows)
    c = (len(rows[0]) if r else 0) if cols is None else cols
    ints = rows if den == 1 else [[z * den for z in row] for row in rows]
    return IntMatrix(flint.fmpz_mat(r, c, [z for row in ints for z in row]), num, ints)


def _fmpz(rows: list[list[int]], r: int, c: int) -> flint.fmpz_mat:
    return flint.fmpz_mat(r, c, [z for row in rows for z in row])


#: an entry is long when its denominator has this many more bits than the shortest
LONG_BITS = 64


def heavy_indices(P: ex.RationalMatrix) -> list[int] | None:
    """The few indices whose rows and columns hold every long-denominator entry of P
    (at most n/4 of them), or None when P has no such structure."""
    n = len(P)
    bits = [[x.denominator.bit_length() for x in row] for row in P]
    short = min((b for row in bits for b in row), default=0)
    long_ = [[b > short + LONG_BITS for b in row] for row in bits]
    heavy = [i for i in range(n) if sum(long_[i]) > n // 2]
    if not heavy or len(heavy) > n // 4:
        return None
    hs = set(heavy)
    if any(long_[i][j] for i in range(n) if i not in hs for j in range(n) if j not in hs):
        return None
    return heavy


@dataclass(frozen=True)
class SplitP:
    """P = L + H exactly: L short integers over a short denominator (any support), H
    nonzero only on the rows and columns ``heavy``, given by its heavy rows H[heavy, :]
    (``rows``) and its heavy columns on the other rows, H[light, heavy] (``cols``)."""

    light: IntMatrix
    heavy: list[int]
    rows: IntMatrix
    cols: IntMatrix

    @property
    def others(self) -> list[int]:
        hs = set(self.heavy)
        return [i for i in range(self.light.Z.nrows()) if i not in hs]


def split_rational(P: ex.RationalMatrix) -> SplitP | None:
    """P split through its heavy rows and columns (:func:`heavy_indices`), or None."""
    n = len(P)
    heavy = heavy_indices(P) if n >= 8 else None
    if heavy is None:
        return None
    hs = set(heavy)
    light = [i for i in range(n) if i not in hs]
    zero = ex.mpq(0)
    PL = int_matrix([[x if i not in hs and j not in hs else zero for j, x in enumerate(row)]
                     for i, row in enumerate(P)], n, n)
    RH = int_matrix([P[i] for i in heavy], len(heavy), n)
    CH = int_matrix([[P[i][j] for j in heavy] for i in light], len(light), len(heavy))
    return SplitP(PL, heavy, RH, CH)


def _place_columns(T: flint.fmpz_mat, X: flint.fmpz_mat, rows: list[int], cols: list[int],
                   factor: int) -> None:
    """T[rows[a], cols[b]] += factor X[a, b] (in place)."""
    f = flint.fmpz(factor)
    for a, i in enumerate(rows):
        for b, j in enumerate(cols):
            T[i, j] += X[a, b] * f


def _at_p(A: IntMatrix, sp: SplitP) -> tuple[flint.fmpz_mat, int]:
    """Aᵀ P = Aᵀ L + Aᵀ[:, heavy] H[heavy, :] + Aᵀ[:, others] H[others, heavy], as (Z, d):
    one n x n x n product on short integers, two thin ones on long ones."""
    n = A.Z.nrows()
    heavy, others = sp.heavy, sp.others
    k = len(heavy)
    At = A.Z.transpose()
    At_heavy = _fmpz([A.rows[i] for i in heavy], k, n).transpose()
    # H[others, heavy] placed in an n x k matrix (zero on the heavy rows): Aᵀ times it is
    # Aᵀ[:, others] H[others, heavy] without forming Aᵀ[:, others]
    placed = [[0] * k for _ in range(n)]
    for b, i in enumerate(others):
        placed[i] = sp.cols.rows[b]
    T0 = At * sp.light.Z  # / (dA dL)
    T1 = At_heavy * sp.rows.Z  # / (dA d1)
    T2 = At * _fmpz(placed, n, k)  # / (dA d2), in the heavy columns
    d = _lcm(sp.light.d, sp.rows.d, sp.cols.d)
    T = T0 * flint.fmpz(d // sp.light.d) + T1 * flint.fmpz(d // sp.rows.d)
    _place_columns(T, T2, list(range(n)), heavy, d // sp.cols.d)
    return T, A.d * d


def _p_b(sp: SplitP, B: IntMatrix) -> tuple[flint.fmpz_mat, int]:
    """P B = L B + H B as (Z, d) (thin products)."""
    m = B.Z.ncols()
    heavy, others = sp.heavy, sp.others
    LB = sp.light.Z * B.Z  # / (dL dB)
    HB_rows = sp.rows.Z * B.Z  # heavy rows of H B, / (d1 dB)
    HB_others = sp.cols.Z * _fmpz([B.rows[i] for i in heavy], len(heavy), m)  # / (d2 dB)
    d = _lcm(sp.light.d, sp.rows.d, sp.cols.d)
    T = LB * flint.fmpz(d // sp.light.d)
    f1, f2 = flint.fmpz(d // sp.rows.d), flint.fmpz(d // sp.cols.d)
    for a, i in enumerate(heavy):
        for j in range(m):
            T[i, j] += HB_rows[a, j] * f1
    for a, i in enumerate(others):
        for j in range(m):
            T[i, j] += HB_others[a, j] * f2
    return T, d * B.d


def _lcm(*values: int) -> int:
    return int(reduce(lcm, (mpz(v) for v in values), mpz(1)))


def negated_kyp_matrix(A: IntMatrix, B: IntMatrix, C: IntMatrix, D: IntMatrix,
                       P: ex.RationalMatrix | None = None, Pi: IntMatrix | None = None,
                       split: SplitP | None = None) -> tuple[list[list[int]], int]:
    """−M(P) as integer rows over one denominator: (rows, d) with −M(P) = rows / d.

    P is given as rationals (``P``, with ``Pi`` its :class:`IntMatrix` when the caller
    has it) or as a :class:`SplitP` (``split``)."""
    n, m = A.Z.nrows(), D.Z.nrows()
    if split is None and P is not None:
        split = split_rational(P)
    if split is not None:
        AtP, dT = _at_p(A, split)
        PB, dPB = _p_b(split, B)
    else:
        Pi = int_matrix(P, n, n) if Pi is None else Pi
        AtP, dT = A.Z.transpose() * Pi.Z, A.d * Pi.d
        PB, dPB = Pi.Z * B.Z, Pi.d * B.d
    d = _lcm(dT, dPB, C.d, D.d)
    top = (AtP + AtP.transpose()) * flint.fmpz(d // dT)
    off = PB * flint.fmpz(d // dPB) - C.Z.transpose() * flint.fmpz(d // C.d)
    S = (D.Z + D.Z.transpose()) * flint.fmpz(d // D.d)
    top_rows = [[-int(z) for z in row] for row in top.tolist()]
    off_rows = [[-int(z) for z in row] for row in off.tolist()] if m else [[] for _ in
                                                                         range(n)]
    S_rows = [[int(z) for z in row] for row in S.tolist()]
    rows = [top_rows[i] + off_rows[i] for i in range(n)]
    rows += [[off_rows[i][j] for i in range(n)] + S_rows[j] for j in range(m)]
    return rows, d


__all__ = ["IntMatrix", "SplitP", "heavy_indices", "int_matrix", "int_matrix_from_ints",
           "negated_kyp_matrix", "split_rational"]
