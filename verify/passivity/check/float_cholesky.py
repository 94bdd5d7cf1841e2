"""Positive definiteness proved by one floating-point Cholesky factorisation (Rump's test).

For an exact rational symmetric X (held as an integer matrix over a common denominator,
:class:`verify.passivity.check.intmat.ScaledInt`), :func:`verified_pd` returns True only
when X is positive definite; False means "not proved here" (the caller then decides
exactly). The test:

1. X is scaled by a power of two (exact) so that its largest entry is near 1.
2. F is the floating-point matrix with F_ij = fl(X_ij) (correctly rounded) off the
   diagonal and F_ii the largest double <= X_ii - c on it (exactly rounded down).
3. c satisfies, in exact rational arithmetic after F is built,

       c >= alpha_n tr F + 6 n (n + max_i F_ii) eta + (n - 1)(u mu + eta),

   with u = 2^-53, eta = 2^-1074, gamma_k = k u / (1 - k u), alpha_n =
   gamma_(n+1) / (1 - gamma_(n+1)) and mu the largest off-diagonal |F_ij|.
4. Cholesky of F in IEEE binary64 (round to nearest, gradual underflow) runs to
   completion: every pivot is positive.

Then X is positive definite. Rump's theorem (S. M. Rump, *Verification of positive
definiteness*, BIT Numerical Mathematics 46 (2006) 433-452, Section 2; the bound of
INTLAB's ``isspd``; after J. W. Demmel, *On floating point errors in Cholesky*, LAPACK
Working Note 14, 1989) gives lambda_min(F) > -(alpha_n tr F + 6 n (n + max F_ii) eta)
when step 4 succeeds, for any order of evaluation of the inner products. The off-diagonal
rounding E = X - cI - F - diag(X_ii - c - F_ii) has |E_ij| <= u |F_ij| + eta, so
||E||_2 <= ||E||_inf <= (n - 1)(u mu + eta), and the diagonal remainder is >= 0; hence
lambda_min(X) >= c + lambda_min(F) - ||E||_2 > 0. The theorem and its constants are
stated in ``verify/passivity/TRUSTED.md``.

The factorisation is our own right-looking loop of elementwise numpy operations (one
correctly rounded IEEE operation each: no BLAS, no fused multiply-add), so the
hypotheses of the theorem hold for the code as written; the rounding mode and gradual
underflow are probed before each use (:func:`ieee_nearest`). Floating point cannot
make this say True for a matrix that is not positive definite; it can only fail to
prove a matrix that is (a margin below c, a semidefinite or a lossless one).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from verify.passivity.check import intmat

#: unit roundoff of IEEE binary64, round to nearest
UNIT_ROUNDOFF = Fraction(1, 2**53)
#: smallest positive (subnormal) binary64: the absolute error unit of gradual underflow
ETA = Fraction(1, 2**1074)


def gamma(k: int) -> Fraction:
    """gamma_k = k u / (1 - k u), exactly (Higham, *Accuracy and Stability*, Section 3.1)."""
    ku = k * UNIT_ROUNDOFF
    if ku >= 1:
        raise ValueError(f"gamma_{k} is undefined for binary64 (k u >= 1)")
    return ku / (1 - ku)


def alpha(n: int) -> Fraction:
    """alpha_n = gamma_(n+1) / (1 - gamma_(n+1)): Rump's per-row factor, for dense rows."""
    g = gamma(n + 1)
    return g / (1 - g)


def required_shift(diagonal: list[float], off_max: float) -> Fraction:
    """The least c (exact) the theorem asks for, given F's diagonal and largest
    off-diagonal |F_ij| (module doc, step 3)."""
    n = len(diagonal)
    trace = sum((Fraction(x) for x in diagonal), Fraction(0))
    top = max((Fraction(x) for x in diagonal), default=Fraction(0))
    return (alpha(n) * trace + 6 * n * (n + top) * ETA
            + (n - 1) * (UNIT_ROUNDOFF * Fraction(off_max) + ETA))


def ieee_nearest() -> bool:
    """numpy's binary64 arithmetic rounds to nearest and underflows gradually (probes)."""
    one = np.array([1.0])
    tiny = np.array([2.0 ** -1073])
    with np.errstate(all="ignore"):
        nearest = bool((one + 1e-30)[0] == 1.0 and (one - 1e-30)[0] == 1.0
                       and (-one - 1e-30)[0] == -1.0 and (-one + 1e-30)[0] == -1.0)
        gradual = bool((tiny / 2)[0] == 2.0 ** -1074 and (tiny / 2)[0] != 0.0)
    return nearest and gradual


def cholesky_completes(F: np.ndarray) -> bool:
    """Whether floating-point Cholesky of F runs to completion (every pivot > 0).

    Right-looking: at step k, r_kk = sqrt(a_kk), r_kj = a_kj / r_kk and a_ij -= r_ki r_kj
    for i, j > k, each a separately rounded elementwise operation, so every r_ij is
    (a_ij - sum_{k<i} r_ki r_kj) / r_ii with the sum evaluated in one fixed order."""
    a = np.array(F, dtype=np.float64, copy=True)
    n = a.shape[0]
    with np.errstate(all="ignore"):
        for k in range(n):
            pivot = a[k, k]
            if not (pivot > 0.0) or not math.isfinite(pivot):
                return False
            r = np.sqrt(pivot)
            row = np.divide(a[k, k + 1:], r)
            if not np.all(np.isfinite(row)):
                return False
            if k + 1 < n:
                tail = a[k + 1:, k + 1:]
                np.subtract(tail, np.multiply.outer(row, row), out=tail)
    return True


def float_matrix(rows: list[list[int]], d: int) -> tuple[np.ndarray, int]:
    """The nearest floats of 2^k X, X = rows / d (k chosen so that the largest entry is
    near 1), and k: 2^k X = rows 2^k / d, each entry correctly rounded (int / int)."""
    top = max((abs(z) for row in rows for z in row), default=0)
    k = d.bit_length() - top.bit_length() if top else 0
    num, den = (1 << k, d) if k >= 0 else (1, d << -k)
    if num == 1:
        F = np.array([[z / den for z in row] for row in rows], dtype=float)
    else:
        F = np.array([[(z * num) / den for z in row] for row in rows], dtype=float)
    return F.reshape(len(rows), len(rows[0]) if rows else 0), k


def verified_pd(s: intmat.ScaledInt) -> bool:
    """True only if X = Z / d is positive definite (module doc); False: not proved."""
    return verified_pd_rows([[int(z) for z in row] for row in s.Z], int(s.d))


def verified_pd_rows(rows: list[list[int]], d: int) -> bool:
    """True only if X = rows / d (integer rows, d > 0) is positive definite (module doc);
    False: not proved."""
    n = len(rows)
    if n == 0 or any(len(row) != n for row in rows) or d <= 0:
        return False
    F, k = float_matrix(rows, d)
    scale = Fraction(2) ** k / d
    return verified_pd_nearest(F, [rows[i][i] * scale for i in range(n)])


def verified_pd_nearest(F: np.ndarray, diagonal: list[Fraction]) -> bool:
    """True only if the symmetric matrix X with off-diagonal entries whose nearest
    doubles are F_ij and with the exact diagonal ``diagonal`` is positive definite
    (module doc, steps 2-4); False: not proved. F is not modified."""
    n = F.shape[0]
    if n == 0 or F.shape != (n, n) or len(diagonal) != n or not ieee_nearest():
        return False
    if not np.all(np.isfinite(F)) or not np.array_equal(F, F.T):
        return False
    off = np.abs(F)
    np.fill_diagonal(off, 0.0)
    off_max = float(off.max()) if n > 1 else 0.0
    # a first c from the floats, then the exact check of the theorem's inequality
    c = required_shift([max(_below(x), 0.0) for x in diagonal], off_max) * 2
    for _attempt in range(2):
        shifted = [_below(x - c) for x in diagonal]
        if any(not (0.0 < x < math.inf) for x in shifted):
            return False
        need = required_shift(shifted, off_max)
        if c >= need:
            break
        c = need * 2
    else:
        return False
    G = np.array(F, dtype=np.float64, copy=True)
    np.fill_diagonal(G, shifted)
    return cholesky_completes(G)


def _below(x: Fraction) -> float:
    """The largest double <= x (x exact; -inf below the range)."""
    try:
        f = float(x)  # correctly rounded to nearest
    except OverflowError:
        return math.inf if x > 0 else -math.inf
    if Fraction(f) > x:
        f = math.nextafter(f, -math.inf)
    return f


__all__ = ["alpha", "cholesky_completes", "gamma", "ieee_nearest", "required_shift",
           "verified_pd", "verified_pd_nearest", "verified_pd_rows"]
