"""Simplified refined instrumental variables for continuous-time models (SRIVC).

Young & Jakeman, Int. J. Control 31(4), 1980; Garnier, Mensler & Richard, Int. J.
Control 76(13), 2003 (the CONTSID toolbox); for multiple-input models with a common
denominator, Garnier, Gilson, Young & Huselstein, Control Eng. Practice 15(6), 2007.

For output i of the constant-coupling structure, A u_i = B e_i + c A e_j + A v. Both
sides are prefiltered by 1/Ahat (the current denominator estimate), which turns the
equation error into the noise v when Ahat = A, and gives the linear regression

    s^n/Ahat u_i = - sum_k a_k s^k/Ahat u_i + sum_k b_k s^k/Ahat e_i
                   + sum_k d_k s^k/Ahat e_j + (free responses of Ahat per trial),

with d_n = c. The regressors -s^k/Ahat u_i carry the noise; their instruments are the
same filters applied to the noise-free model output xhat = Bhat/Ahat e_i + chat e_j. The
other regressors are functions of e only and are their own instruments.

Closed loop (the leader makes e depend on past u_h, Section 3): the loop from u_h to e
is strictly proper (u_h drives a velocity, e is a function of the attitude), so e(t)
depends on the noise only strictly before t; with white operator noise at the sampling
rate the instruments are uncorrelated with the equation error, as closed-loop IV needs
(Gilson & Van den Hof, Automatica 41(2), 2005). This estimate starts the prediction-error
refinement (:mod:`verify.identify.estimate.pem`), which is consistent in closed loop with the
right noise model.

The first iteration is the least-squares state-variable filter estimate with the fixed
prefilter (s + lam)^n; unstable denominators are reflected into the left half plane
before they are used as prefilters.
"""

from __future__ import annotations

import numpy as np

from verify.identify.estimate.ct_filters import Filter
from verify.identify.estimate.trial_data import OutputData

__all__ = ["srivc"]


def stable(a: np.ndarray) -> np.ndarray:
    """The monic polynomial with the roots of ``a`` reflected into Re s < 0 (a_{n-1}..a_0).

    Roots on the imaginary axis move to Re s = -1e-3 |s| - 1e-6, so the result is a
    usable prefilter.
    """
    roots = np.roots(np.concatenate(([1.0], np.asarray(a, float))))
    re = -np.maximum(np.abs(roots.real), 1e-3 * np.abs(roots) + 1e-6)
    return np.real(np.poly(re + 1j * roots.imag))[1:]


def srivc(data: OutputData, poles: int, zeros: int, *, lam: float, iterations: int = 30,
          tol: float = 1e-9) -> np.ndarray:
    """The SRIVC denominator (a_{n-1}, ..., a_0) of output ``data.output``.

    ``lam`` (rad/s) is the pole of the first, fixed prefilter; iterations stop when the
    relative change of the denominator is below ``tol``.
    """
    n, m = poles, zeros
    a = np.real(np.poly(-lam * np.ones(n)))[1:]  # (s + lam)^n
    with np.errstate(over="ignore", invalid="ignore"):  # an unstable fit is caught below
        return _iterate(data, n, m, a, iterations, tol)


def _iterate(data: OutputData, n: int, m: int, a: np.ndarray, iterations: int, tol: float
             ) -> np.ndarray:
    prefilter = a.copy()
    T = len(data.y)
    width = n + (m + 1) + (n + 1) + T * n
    b, c = np.zeros(m + 1), 0.0
    for it in range(iterations + 1):
        filt = Filter(prefilter, data.h)
        Phi = np.zeros((data.samples, width))
        Zeta = np.zeros_like(Phi)
        target = np.zeros(data.samples)
        row = 0
        for k, (own, other, y) in enumerate(zip(data.own, data.other, data.y, strict=True)):
            N = len(y)
            U = filt.filtered(y)
            Ei = filt.filtered(own)
            Ej = filt.filtered(other)
            rows = slice(row, row + N)
            target[rows] = U[:, n]
            Phi[rows, :n] = -U[:, n - 1::-1]
            Phi[rows, n:n + m + 1] = Ei[:, m::-1]
            Phi[rows, n + m + 1:2 * n + m + 2] = Ej[:, ::-1]
            Phi[rows, 2 * n + m + 2 + k * n:2 * n + m + 2 + (k + 1) * n] = filt.free(N)
            Zeta[rows] = Phi[rows]
            if it > 0:  # instruments: the filtered noise-free model output
                xhat = Ei[:, m::-1] @ b + c * other
                Zeta[rows, :n] = -filt.filtered(xhat)[:, n - 1::-1]
            row += N
        scale = np.linalg.norm(Phi, axis=0)
        scale[scale == 0] = 1.0
        if it == 0:
            theta = np.linalg.lstsq(Phi / scale, target, rcond=None)[0] / scale
        else:
            M = (Zeta / scale).T @ (Phi / scale)
            theta = np.linalg.lstsq(M, (Zeta / scale).T @ target, rcond=None)[0] / scale
        a_new = theta[:n]
        b = theta[n:n + m + 1]
        c = theta[n + m + 1]
        if not np.all(np.isfinite(theta)):
            return a
        change = np.linalg.norm(a_new - a) / (1.0 + np.linalg.norm(a))
        a = a_new
        prefilter = stable(a)
        if it > 0 and change < tol:
            break
    return a
