"""Exact (semi)definiteness of a symmetric integer matrix by fraction-free elimination.

A symmetric rational matrix M = Z / d (d > 0, :mod:`verify.passivity.check.intmat`) has
the definiteness of its integer numerator matrix Z, so the exact fallback of the KYP
check (the positive-real lemma of the paper's Section 4: P > 0 and M(P) <= 0) works on
Z alone, with no rational arithmetic:

1. **Strict question, FLINT.** ``fmpz_mat.fflu`` (fraction-free LU, in C) of a nonsingular Z
   that needs no row exchange has the leading principal minors d_1, ..., d_n of Z on
   the diagonal of its U factor. Sylvester's criterion: Z > 0 iff every d_k > 0; and
   when d_1, ..., d_(k-1) > 0 > d_k the k-th LDL^T pivot d_k / d_(k-1) is negative, so Z
   is not even semidefinite.
2. **Semidefinite question, or no answer from 1: symmetric Bareiss with zero pivots**
   (:func:`bareiss_psd`). The elimination keeps each entry equal to det(Z_K) times the
   Schur complement of the eliminated pivots K, and divides exactly by the previous
   pivot (Sylvester's determinant identity: every intermediate entry is a minor of Z,
   an integer). A
   Schur complement of a PSD matrix is PSD, so a zero pivot must come with a zero row
   (that index is then dropped and K unchanged) and a negative pivot refutes.

No entry is ever a fraction, and no gcd is taken; integers grow to at most k times
the bit length of Z's entries at step k (the minors' Hadamard bound). References:
E. H. Bareiss, Math. Comp. 22 (1968) 565-578; the semidefinite rule is that of the
rational LDL^T in :func:`verify.passivity.check.exact.psd_ldl`, which stays as the
independent reference the tests compare this with.
"""

from __future__ import annotations

from collections.abc import Sequence

import flint
import numpy as np
from gmpy2 import mpz

from verify.passivity.check.exact import LdlResult


def _flint_strict(rows: Sequence[Sequence[int]]) -> LdlResult | None:
    """Sylvester's criterion on FLINT's fraction-free LU, when it decides (Z nonsingular
    and no row exchange); None otherwise."""
    n = len(rows)
    Z = flint.fmpz_mat([[int(x) for x in row] for row in rows])
    perm, _L, _D, U = Z.fflu()
    if not perm.is_one():
        return None
    minors = [U[k, k] for k in range(n)]
    if any(x == 0 for x in minors):
        return None
    for k, x in enumerate(minors):
        if x < 0:
            return LdlResult(False, f"pivot {k} is negative (leading principal minor "
                             f"{k + 1} < 0 after positive ones; FLINT fraction-free LU)", k)
    return LdlResult(True, "all leading principal minors positive (FLINT fraction-free LU)")


def bareiss_psd(rows: Sequence[Sequence[int]], *, strict: bool = False) -> LdlResult:
    """Z >= 0 (``strict``: Z > 0) for a symmetric integer matrix, by symmetric Bareiss
    elimination with zero pivots allowed (exact; integers only)."""
    n = len(rows)
    if n == 0:
        return LdlResult(True, "empty matrix")
    a = np.empty((n, n), dtype=object)
    for i, row in enumerate(rows):
        a[i, :] = [mpz(int(x)) for x in row]
    index = list(range(n))
    prev = mpz(1)
    zero_pivots = 0
    while a.shape[0]:
        k = index[0]
        p = a[0, 0]
        row = a[0, 1:]
        if p < 0 or (strict and p == 0):
            return LdlResult(False, f"pivot {k} is {'negative' if p < 0 else 'zero'} "
                             "(fraction-free LDLᵀ)", k)
        if p == 0:
            if any(x != 0 for x in row):
                return LdlResult(False, f"zero pivot {k} with a non-zero row "
                                 "(fraction-free LDLᵀ)", k)
            zero_pivots += 1
        else:
            rest = a[1:, 1:]
            if rest.shape[0]:
                a_new = p * rest - np.outer(row, row)
                # exact: every entry is a minor of Z (Sylvester's identity)
                a = a_new // prev if prev != 1 else a_new
            else:
                a = rest
            prev = p
            index.pop(0)
            continue
        a = a[1:, 1:]
        index.pop(0)
    if strict:
        return LdlResult(True, "all pivots positive (fraction-free LDLᵀ)")
    extra = f", {zero_pivots} zero pivot(s) with zero rows" if zero_pivots else ""
    return LdlResult(True, f"all pivots non-negative (fraction-free LDLᵀ{extra})")


def psd_integer(rows: Sequence[Sequence[int]], *, strict: bool = False) -> LdlResult:
    """Exact decision of Z >= 0 (``strict``: Z > 0) for a symmetric integer matrix Z:
    FLINT's fraction-free LU when it decides, else :func:`bareiss_psd`."""
    n = len(rows)
    if any(len(row) != n for row in rows):
        return LdlResult(False, "matrix is not square")
    if any(rows[i][j] != rows[j][i] for i in range(n) for j in range(i)):
        return LdlResult(False, "matrix is not symmetric")
    if n == 0:
        return LdlResult(True, "empty matrix")
    # the strict question (P > 0) usually has an answer without zero minors: FLINT's LU
    # in C, about twice the speed of the Bareiss loop; a semidefinite one usually meets a
    # zero pivot, where the LU would be spent for nothing
    fast = _flint_strict(rows) if strict else None
    if fast is not None:
        return fast
    return bareiss_psd(rows, strict=strict)


__all__ = ["bareiss_psd", "psd_integer"]
