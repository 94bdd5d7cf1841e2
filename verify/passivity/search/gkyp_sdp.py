"""Band certificates proposed by a semidefinite program (untrusted search, trusted check).

The generalized KYP LMI of :mod:`verify.passivity.check.gkyp` (Iwasaki & Hara, IEEE TAC
50(1), 2005, Theorem 2) is solved for Hermitian P and Q with a maximal margin by cvxpy +
Clarabel, in state coordinates balanced by a diagonal power-of-two similarity; the
solution is rounded to Gaussian rationals on successively finer dyadic grids, mapped
back exactly, and kept only when :func:`~verify.passivity.check.gkyp.check_gkyp` accepts
it. The solver's answer is never trusted: a failed or inaccurate solve yields ``None``.
"""

from __future__ import annotations

import warnings
from fractions import Fraction

import cvxpy as cp
import numpy as np
import scipy.linalg as sla
from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.gkyp import ComplexMatrix, check_gkyp


def solve_gkyp(A: np.ndarray, B: np.ndarray, C: np.ndarray, D: np.ndarray,
               band: tuple[float, float]) -> tuple[np.ndarray, np.ndarray, float] | None:
    """Max-margin Hermitian (P, Q) of the generalized KYP LMI (cvxpy + Clarabel); untrusted."""
    n, m = A.shape[0], D.shape[0]
    w1, w2 = band
    wc = (w1 + w2) / 2
    P = cp.Variable((n, n), hermitian=True)
    Q = cp.Variable((n, n), hermitian=True)
    t = cp.Variable()
    W = cp.bmat([[-Q, P + 1j * wc * Q], [P - 1j * wc * Q, -w1 * w2 * Q]])
    N = np.block([[A, B], [np.eye(n), np.zeros((n, m))]])
    Theta = -np.block([[np.zeros((n, n)), C.T], [C, D + D.T]])
    L = N.T @ W @ N + Theta
    cons = [Q >> t * np.eye(n), -L >> t * np.eye(n + m), t <= 1.0]
    prob = cp.Problem(cp.Maximize(t), cons)
    try:
        with warnings.catch_warnings():  # an inaccurate solution is caught by the exact check
            warnings.simplefilter("ignore")
            prob.solve(solver=cp.CLARABEL)
    except (cp.error.SolverError, ValueError):
        return None
    if P.value is None or Q.value is None or t.value is None:
        return None
    return np.asarray(P.value), np.asarray(Q.value), float(t.value)


def _hermitian_rational(X: np.ndarray, bits: int) -> ComplexMatrix:
    """Dyadic Gaussian-rational rounding, made exactly Hermitian."""
    Xr, Xi = ex.rationalize(X.real, bits), ex.rationalize(X.imag, bits)
    n = len(Xr)
    return ([[(Xr[i][j] + Xr[j][i]) / 2 for j in range(n)] for i in range(n)],
            [[(Xi[i][j] - Xi[j][i]) / 2 for j in range(n)] for i in range(n)])


def _unbalance(X: ComplexMatrix, t: list[mpq]) -> ComplexMatrix:
    """T^-H X T^-1 for T = diag(t), exactly (back from balanced to model coordinates)."""
    return tuple([[row[j] / (t[i] * t[j]) for j in range(len(t))] for i, row in enumerate(part)]
                 for part in X)  # type: ignore[return-value]


def band_certificate(em: ExactModel, A: np.ndarray, B: np.ndarray, C: np.ndarray,
                     D: np.ndarray, band: tuple[Fraction, Fraction]
                     ) -> tuple[ComplexMatrix, ComplexMatrix, float | None, str] | None:
    """Search, round and check exactly; (P, Q, margin, rounding) or None.

    The LMI is solved in coordinates balanced by a diagonal power-of-two similarity T
    (x = T xb), rounded there, and mapped back exactly by P = T^-H Pb T^-1 (same for Q),
    so badly scaled models keep their relative precision.
    """
    if em.n == 0:
        return (([], []), ([], []), None, "static") if check_gkyp(em, ([], []), ([], []),
                                                                  band).ok else None
    _, (scaling, _) = sla.matrix_balance(A, permute=False, separate=True)
    t = np.asarray(scaling, dtype=float)
    Ab, Bb, Cb = A * (1.0 / t)[:, None] * t[None, :], B / t[:, None], C * t[None, :]
    found = solve_gkyp(Ab, Bb, Cb, D, (float(band[0]), float(band[1])))
    if found is None:
        return None
    Pf, Qf, margin = found
    t_exact = [mpq(float(x)) for x in t]
    scale = max(1.0, float(np.max(np.abs(np.concatenate([Pf.ravel(), Qf.ravel()])))))
    for bits in (16, 24, 36, 48, 60):
        step = max(bits - int(np.ceil(np.log2(scale))), 8)
        P = _unbalance(_hermitian_rational(Pf, step), t_exact)
        Q = _unbalance(_hermitian_rational(Qf, step), t_exact)
        if check_gkyp(em, P, Q, band).ok:
            return P, Q, margin, f"{bits}-bit"
    return None


__all__ = ["band_certificate", "solve_gkyp"]
