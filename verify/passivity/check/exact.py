"""Exact rational matrices for certificate checks (no solver, no floating point).

Floating-point model data are dyadic rationals, so they convert to exact rationals
without loss (:func:`to_rational`). Rationals are gmpy2 ``mpq`` for speed; they print
and parse as "p/q" strings for JSON certificates.

:func:`psd_ldl` decides positive semidefiniteness of a symmetric rational matrix by an
exact LDL^T factorisation with zero pivots allowed: a Schur complement of a PSD matrix
is PSD, so a zero pivot must have a zero remaining row, and a negative pivot refutes.
:func:`pd_ldl` requires every pivot to be positive.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
from gmpy2 import mpq

from verify.passivity.check import intmat

RationalMatrix = list[list[mpq]]


def to_rational(a: np.ndarray | Sequence) -> RationalMatrix:
    """Exact rational copy of a 2-D float array (every finite float is a dyadic rational)."""
    arr = np.asarray(a, dtype=float)
    if arr.ndim != 2:
        raise ValueError("to_rational expects a 2-D array")
    if not np.all(np.isfinite(arr)):
        raise ValueError("a matrix entry is not finite")
    return [[mpq(float(x)) for x in row] for row in arr]


def rationalize(a: np.ndarray, bits: int = 40) -> RationalMatrix:
    """Round a float matrix to dyadic rationals with ``bits`` fractional bits."""
    scale = 2**bits
    return [[mpq(round(float(x) * scale), scale) for x in row] for row in np.asarray(a)]


def to_strings(m: RationalMatrix) -> list[list[str]]:
    return [[str(x) for x in row] for row in m]


def from_strings(rows: Sequence[Sequence[str]]) -> RationalMatrix:
    """Parse "p/q" strings (as written by :func:`to_strings`); raises ValueError."""
    out = []
    for row in rows:
        out_row = []
        for text in row:
            if not isinstance(text, str):
                raise ValueError("rational entries are strings 'p/q'")
            out_row.append(mpq(Fraction(text)))
        out.append(out_row)
    return out


def to_sympy(m: RationalMatrix, rows: int | None = None, cols: int | None = None):
    """The same exact matrix as a sympy Matrix (shape given explicitly for empty matrices)."""
    import sympy as sp

    r = len(m) if rows is None else rows
    c = (len(m[0]) if m else 0) if cols is None else cols
    return sp.Matrix(r, c, lambda i, j: sp.Rational(int(m[i][j].numerator),
                                                    int(m[i][j].denominator)))


def from_sympy(matrix) -> RationalMatrix:
    """An exact rational sympy Matrix (entries sympy Rationals) as mpq rows."""
    return [[mpq(int(x.p), int(x.q)) for x in row] for row in matrix.tolist()]


def _fmpq_mat(m: RationalMatrix, rows: int | None = None, cols: int | None = None):
    """The same exact matrix as a FLINT fmpq_mat (python-flint; no sympy to import)."""
    import flint

    r = len(m) if rows is None else rows
    c = (len(m[0]) if m else 0) if cols is None else cols
    out = flint.fmpq_mat(r, c)
    for i in range(r):
        for j in range(c):
            x = m[i][j]
            out[i, j] = flint.fmpq(int(x.numerator), int(x.denominator))
    return out


def _from_fmpq(matrix) -> RationalMatrix:
    return [[mpq(int(matrix[i, j].p), int(matrix[i, j].q)) for j in range(matrix.ncols())]
            for i in range(matrix.nrows())]


def _rref(S: RationalMatrix) -> tuple[RationalMatrix, list[int]]:
    """Reduced row echelon form of S and its pivot columns (exact, FLINT)."""
    R = _from_fmpq(_fmpq_mat(S).rref()[0])
    pivots = []
    for row in R:
        j = next((j for j, x in enumerate(row) if x != 0), None)
        if j is None:
            break
        pivots.append(j)
    return R, pivots


def kernel_basis(S: RationalMatrix) -> RationalMatrix:
    """Exact rational basis of ker S as columns (m x k); k may be 0.

    One vector per free column f of the reduced row echelon form (entry 1 at f, -R[i][f]
    at the i-th pivot column, 0 elsewhere): the same basis as sympy's ``nullspace``.
    """
    rows, cols = len(S), (len(S[0]) if S else 0)
    R, pivots = _rref(S) if rows and cols else ([], [])
    free = [j for j in range(cols) if j not in set(pivots)]
    if not free:
        return [[] for _ in range(rows)]  # as before: one empty row per row of S
    basis = zeros(cols, len(free))
    for k, f in enumerate(free):
        basis[f][k] = mpq(1)
        for i, p in enumerate(pivots):
            basis[p][k] = -R[i][f]
    return basis


def range_basis(S: RationalMatrix) -> RationalMatrix:
    """Exact basis of range S as columns (S's own pivot columns, as sympy's
    ``columnspace``); for symmetric S it spans (ker S)^perp."""
    rows = len(S)
    _, pivots = _rref(S) if rows and S[0] else ([], [])
    if not pivots:
        return [[] for _ in range(rows)]
    return [[S[i][j] for j in pivots] for i in range(rows)]


def inverse(M: RationalMatrix) -> RationalMatrix:
    """The exact inverse of a nonsingular square rational matrix (FLINT)."""
    return _from_fmpq(_fmpq_mat(M).inv())


def determinant(M: RationalMatrix) -> mpq:
    """The exact determinant of a square rational matrix (FLINT)."""
    d = _fmpq_mat(M).det()
    return mpq(int(d.p), int(d.q))


def zeros(r: int, c: int) -> RationalMatrix:
    return [[mpq(0)] * c for _ in range(r)]


def shape(m: RationalMatrix) -> tuple[int, int]:
    return len(m), (len(m[0]) if m else 0)


def transpose(m: RationalMatrix) -> RationalMatrix:
    r, c = shape(m)
    return [[m[i][j] for i in range(r)] for j in range(c)]


def matmul(a: RationalMatrix, b: RationalMatrix) -> RationalMatrix:
    ra, ca = shape(a)
    rb, cb = shape(b)
    if ca != rb:
        raise ValueError("shape mismatch in matmul")
    if 0 in (ra, ca, cb):
        return zeros(ra, cb)
    # integer products over a common denominator: exact, and far faster than mpq sums
    return intmat.to_rational(intmat.matmul(intmat.from_rational(a), intmat.from_rational(b)))


def add(a: RationalMatrix, b: RationalMatrix, sign: int = 1) -> RationalMatrix:
    return [[x + sign * y for x, y in zip(r, s, strict=True)] for r, s in zip(a, b, strict=True)]


def scale(c, a: RationalMatrix) -> RationalMatrix:
    return [[c * x for x in row] for row in a]


def block(rows: Sequence[Sequence[RationalMatrix]]) -> RationalMatrix:
    """Assemble a block matrix (blocks in each block row have equal row counts)."""
    out: RationalMatrix = []
    for blocks in rows:
        height = next((len(b) for b in blocks if len(b)), 0)
        for i in range(height):
            line: list[mpq] = []
            for b in blocks:
                line.extend(b[i] if b else [])
            out.append(line)
    return out


def is_symmetric(m: RationalMatrix) -> bool:
    n, c = shape(m)
    return n == c and all(m[i][j] == m[j][i] for i in range(n) for j in range(i))


@dataclass(frozen=True)
class LdlResult:
    """Outcome of an exact LDL^T test; ``index`` is the failing pivot (or None)."""

    ok: bool
    reason: str
    index: int | None = None
    min_pivot: mpq | None = None


def psd_ldl(m: RationalMatrix, *, strict: bool = False) -> LdlResult:
    """Exact test of M >= 0 (``strict``: M > 0) for symmetric rational M."""
    if not is_symmetric(m):
        return LdlResult(False, "matrix is not symmetric")
    n = len(m)
    a = [row[:] for row in m]
    min_pivot: mpq | None = None
    for k in range(n):
        d = a[k][k]
        min_pivot = d if min_pivot is None or d < min_pivot else min_pivot
        if d < 0 or (strict and d == 0):
            return LdlResult(False, f"pivot {k} is {'negative' if d < 0 else 'zero'}", k, d)
        if d == 0:
            if any(a[k][j] != 0 for j in range(k + 1, n)):
                return LdlResult(False, f"zero pivot {k} with a non-zero row", k, d)
            continue
        row_k = a[k]
        for i in range(k + 1, n):
            f = a[i][k]
            if f == 0:
                continue
            f = f / d
            row_i = a[i]
            for j in range(k + 1, i + 1):
                row_i[j] -= f * row_k[j]
            for j in range(k + 1, i + 1):
                a[j][i] = row_i[j]  # keep symmetric storage consistent
    return LdlResult(True, "all pivots non-negative" if not strict else "all pivots positive",
                     None, min_pivot)


def pd_ldl(m: RationalMatrix) -> LdlResult:
    return psd_ldl(m, strict=True)
