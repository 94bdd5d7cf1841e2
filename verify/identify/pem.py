"""Output-error prediction-error refinement and its asymptotic covariance.

The criterion is the output-error one, sum over all samples of (u_i - yhat_i)^2 with
yhat_i the model output simulated from the measured inputs with estimated initial states
(:mod:`verify.identify.prediction`). For white noise on the output this is the
prediction-error (maximum-likelihood for Gaussian noise) criterion, which stays
consistent in closed loop because the noise model (white) is right (Ljung, System
Identification, 2nd ed., 1999, Sec. 13.4, "direct approach"). The numerator, coupling
and initial states are eliminated by linear least squares (variable projection); the
denominator is searched by ``scipy.optimize.least_squares``.

Covariance (Ljung 1999, Sec. 9.3, eq. (9.18) for output error with white noise):
sigma^2 (J^T J)^-1 with J the Jacobian of yhat with respect to all parameters of the
output (numerator, denominator, coupling, initial states) and sigma^2 = RSS / (N - d).
The initial states are nuisance parameters; the covariance of H(s)'s parameters is the
corresponding block of the full inverse (so their uncertainty is accounted for).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from verify.identify.prediction import design, fit_linear
from verify.identify.trial_data import OutputData

__all__ = ["OutputFit", "refine"]

_BAD = 1e6  # residual returned for a denominator whose simulation overflows


@dataclass(frozen=True)
class OutputFit:
    """The refined estimate of one output.

    ``b`` numerator (descending), ``a`` denominator (a_{n-1}..a_0), ``c`` coupling,
    ``initial`` the (T, n) free-response coefficients per trial, ``residual`` all
    samples, ``cost`` the residual sum of squares, ``covariance`` of (b, a, c) in that
    order (asymptotic), ``sigma`` the residual standard deviation.
    """

    b: np.ndarray
    a: np.ndarray
    c: float
    initial: np.ndarray
    residual: np.ndarray
    cost: float
    covariance: np.ndarray
    sigma: float


def _residual(a: np.ndarray, data: OutputData, zeros: int) -> np.ndarray:
    r = fit_linear(a, data, zeros)[1]
    if not np.all(np.isfinite(r)) or np.max(np.abs(r)) > _BAD:
        return np.full(r.shape, _BAD)
    return r


def refine(data: OutputData, a0: np.ndarray, zeros: int) -> OutputFit:
    """Minimise the output-error criterion of output ``data.output`` from denominator a0."""
    a0 = np.asarray(a0, float)
    n = len(a0)
    sol = least_squares(_residual, a0, args=(data, zeros), jac="3-point", method="lm",
                        x_scale="jac", xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=400 * n)
    a = sol.x
    beta, r, X = fit_linear(a, data, zeros)
    b = beta[: zeros + 1]
    c = float(beta[zeros + 1])
    eta = beta[zeros + 2:]
    # Jacobian of yhat in (b, a, c, initial states): linear columns are X; the
    # denominator's by central differences of X(a) beta with beta fixed
    Ja = np.empty((r.shape[0], n))
    for k in range(n):
        step = 1e-6 * max(1.0, abs(a[k]))
        hi, lo = a.copy(), a.copy()
        hi[k] += step
        lo[k] -= step
        Ja[:, k] = (design(hi, data, zeros) @ beta - design(lo, data, zeros) @ beta) / (2 * step)
    J = np.column_stack([X[:, : zeros + 1], Ja, X[:, zeros + 1:]])
    dof = r.shape[0] - J.shape[1]
    rss = float(r @ r)
    sigma2 = rss / max(dof, 1)
    scale = np.linalg.norm(J, axis=0)
    scale[scale == 0] = 1.0
    Js = J / scale
    inv = np.linalg.pinv(Js.T @ Js) / np.outer(scale, scale)
    p = zeros + 1 + n + 1
    cov = sigma2 * inv[:p, :p]
    return OutputFit(b, a, c, eta.reshape(-1, n), r, rss, cov, float(np.sqrt(sigma2)))
