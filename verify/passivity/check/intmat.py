"""Exact rational matrices as one integer matrix over a common denominator.

A rational matrix R is held as ``(Z, d)``: Z a numpy object array of gmpy2 ``mpz``
integers and d a positive ``mpz``, with R = Z / d. Products and sums then run as numpy
object-array loops over integers with no gcd per operation (a 100 x 100 product takes a
few hundredths of a second where ``mpq`` arithmetic takes about a second); converting
back to ``mpq`` normalises each entry once. Nothing here rounds: every step is exact.

Linear systems go to FLINT (python-flint ``fmpz_mat.solve``: p-adic lifting over the
integers, no rational arithmetic per step); on a 200-state model a solve that exact
Gaussian elimination in ``mpq`` does not finish takes seconds and a few MB.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import reduce

import flint
import numpy as np
from gmpy2 import lcm, mpq, mpz

RationalMatrix = list[list[mpq]]  # the same alias as verify.passivity.check.exact


@dataclass(frozen=True)
class ScaledInt:
    """The exact matrix Z / d (Z: object array of mpz, d: positive mpz)."""

    Z: np.ndarray
    d: mpz

    @property
    def shape(self) -> tuple[int, int]:
        return self.Z.shape

    def entry(self, i: int, j: int) -> mpq:
        return mpq(self.Z[i, j], self.d)


def from_rational(m: RationalMatrix, cols: int | None = None) -> ScaledInt:
    """(Z, d) with d the least common denominator of the entries of ``m``."""
    rows = len(m)
    c = (len(m[0]) if rows else 0) if cols is None else cols
    d = reduce(lcm, (x.denominator for row in m for x in row), mpz(1))
    Z = np.empty((rows, c), dtype=object)
    for i, row in enumerate(m):
        for j, x in enumerate(row):
            Z[i, j] = x.numerator * (d // x.denominator)
    return ScaledInt(Z, d)


def to_rational(s: ScaledInt) -> RationalMatrix:
    """Back to normalised ``mpq`` rows."""
    return [[mpq(z, s.d) for z in row] for row in s.Z]


def matmul(a: ScaledInt, b: ScaledInt) -> ScaledInt:
    """The exact product (Za Zb) / (da db)."""
    if a.shape[1] != b.shape[0]:
        raise ValueError("shape mismatch in matmul")
    if 0 in a.shape or 0 in b.shape:
        Z = np.full((a.shape[0], b.shape[1]), mpz(0), dtype=object)
        return ScaledInt(Z, mpz(1))
    return ScaledInt(int_dot(a.Z, b.Z), a.d * b.d)


#: above this many multiply-adds a product goes to FLINT (about 3x faster at n = 200,
#: conversions included); below it the numpy object loop has less overhead
_FLINT_WORK = 200_000


def int_dot(X: np.ndarray, Y: np.ndarray) -> np.ndarray:
    """The exact product of two 2-D object arrays of integers (``mpz`` entries out)."""
    r, k = X.shape
    c = Y.shape[1]
    if r * k * c < _FLINT_WORK:
        return X.dot(Y)
    fx = flint.fmpz_mat(r, k, [int(x) for x in X.flat])
    fy = flint.fmpz_mat(k, c, [int(y) for y in Y.flat])
    out = np.empty(r * c, dtype=object)
    out[:] = [mpz(int(z)) for z in (fx * fy).entries()]
    return out.reshape(r, c)


def to_float(s: ScaledInt) -> np.ndarray:
    """Nearest floats (each entry correctly rounded through ``mpq``; used only to search)."""
    d = int(s.d)
    try:  # Python's int / int is correctly rounded
        return np.array([[int(z) / d for z in row] for row in s.Z], dtype=float).reshape(s.shape)
    except OverflowError:  # a quotient beyond the float range: +-inf there
        return np.array([[_saturated(z, d) for z in row] for row in s.Z],
                        dtype=float).reshape(s.shape)


def _saturated(z, d: int) -> float:
    try:
        return int(z) / d
    except OverflowError:
        return float("inf") if (z > 0) == (d > 0) else float("-inf")


def normalised(s: ScaledInt) -> ScaledInt:
    """c Z / d with c a power of two that brings the largest entry near 1 (exact).

    Definiteness and the sign of a quadratic form do not change under c > 0, so the float
    copy used to propose a certificate or a direction stays in range for any entries.
    """
    top = max((abs(int(z)) for z in s.Z.flat), default=0)
    if top == 0:
        return s
    shift = int(s.d).bit_length() - top.bit_length()
    if shift >= 0:
        return ScaledInt(s.Z * (mpz(1) << shift), s.d)
    return ScaledInt(s.Z, s.d * (mpz(1) << -shift))


def to_fmpz_mat(s: ScaledInt) -> flint.fmpz_mat:
    """The integer matrix Z as a FLINT ``fmpz_mat`` (the denominator is kept apart)."""
    rows, cols = s.shape
    return flint.fmpz_mat(rows, cols, [int(z) for z in s.Z.flat])


def fmpq_to_rational(m: flint.fmpq_mat) -> RationalMatrix:
    """A FLINT rational matrix as normalised ``mpq`` rows (exact)."""
    return [[mpq(int(m[i, j].p), int(m[i, j].q)) for j in range(m.ncols())]
            for i in range(m.nrows())]


def rational_to_fmpq(m: RationalMatrix, cols: int | None = None) -> flint.fmpq_mat:
    """``mpq`` rows as a FLINT rational matrix (exact)."""
    rows = len(m)
    c = (len(m[0]) if rows else 0) if cols is None else cols
    return flint.fmpq_mat(rows, c, [flint.fmpq(int(x.numerator), int(x.denominator))
                                    for row in m for x in row])
