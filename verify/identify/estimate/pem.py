"""Output-error prediction-error refinement and its asymptotic covariance.

The criterion is the output-error one, sum over the used samples of (u_i - yhat_i)^2
with yhat_i the model output simulated from the measured inputs, each trial from rest,
from the state the previous trial left it in or from an estimated initial state, the
first ``OutputData.skip`` samples of each trial left out
(:mod:`verify.identify.estimate.prediction`). For white noise on the output this is the
prediction-error (maximum-likelihood for Gaussian noise) criterion, which stays
consistent in closed loop because the noise model (white) is right (Ljung, System
Identification, 2nd ed., 1999, Sec. 13.4, "direct approach"). The numerator, coupling
(and initial states) are eliminated by linear least squares (variable projection); the
denominator is searched by ``scipy.optimize.least_squares`` in a box of stable
denominators with poles below half the Nyquist frequency (:func:`denominator_bounds`).

Covariance. For white prediction errors the asymptotic covariance is
sigma^2 (J^T J)^-1 (Ljung 1999, Sec. 9.3, eq. (9.18)), J the Jacobian of the prediction
errors in all parameters of the output (numerator, denominator, coupling, initial states
and noise model). The protocol's zero-phase anti-aliasing filter and decimation colour
the noise (the decimated spectrum nearly vanishes near the new Nyquist frequency, which no
low-order noise model whitens), and then that formula is too small. The covariance
used is therefore the sandwich (J^T J)^-1 J^T Sigma J (J^T J)^-1 (Ljung 1999, Sec. 9.3,
eq. (9.42) for a noise model that is not the true one), Sigma the residual covariance
within trials from the residual autocovariance up to ``COVARIANCE_LAGS`` lags with
Bartlett weights; for white residuals it reduces to the first formula. The initial states
are nuisance parameters; the covariance of H(s)'s parameters is the corresponding block of
the full matrix (so their uncertainty is accounted for).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from math import comb

import numpy as np
from scipy.optimize import least_squares

from verify.identify.estimate.prediction import design, fit_linear, lengths, used
from verify.identify.estimate.trial_data import OutputData

__all__ = ["OutputFit", "refine"]

_BAD = 1e6
#: Poles are searched in |s| <= MAX_POLE_FRACTION times the Nyquist frequency pi/h.
MAX_POLE_FRACTION = 0.5
#: Residual autocovariance lags the covariance accounts for (0: white residuals assumed).
COVARIANCE_LAGS = 20  # residual returned for a denominator whose simulation overflows
#: Relative step of the central differences in the denominator for the covariance's
#: Jacobian. The simulated regressors carry float noise of a few parts in 1e14 that
#: differs between BLAS builds; a difference quotient divides it by the step, so a step
#: of 1e-6 left noise of 4e-8 in the Jacobian and 1e-6 in the covariance, enough to
#: change its written decimals on another machine. At 1e-3 the noise is 1e-3 of that and
#: the truncation error (relative 1e-6, the same on every machine) is far below the
#: covariance's own statistical precision.
JACOBIAN_STEP = 1e-3


@dataclass(frozen=True)
class OutputFit:
    """The refined estimate of one output.

    ``b`` numerator (descending), ``a`` denominator (a_{n-1}..a_0), ``c`` coupling,
    ``initial`` the (T, n) free-response coefficients per trial, ``residual`` the
    prediction errors (whitened when there is a noise model), ``cost`` their sum of
    squares, ``covariance`` of (b, a, c) in that order (asymptotic), ``sigma`` the
    prediction-error standard deviation, ``noise`` the whitening filter
    (1, d_1, ..., d_p) of the noise model v = e / D(q) (just (1,) for output error).
    """

    b: np.ndarray
    a: np.ndarray
    c: float
    initial: np.ndarray
    residual: np.ndarray
    cost: float
    covariance: np.ndarray
    sigma: float
    noise: np.ndarray = field(default_factory=lambda: np.ones(1))


def _residual(x: np.ndarray, data: OutputData, zeros: int, n: int) -> np.ndarray:
    w = np.concatenate(([1.0], x[n:])) if len(x) > n else None
    r = fit_linear(x[:n], data, zeros, w)[1]
    if not np.all(np.isfinite(r)) or np.max(np.abs(r)) > _BAD:
        return np.full(r.shape, _BAD)
    return r


def denominator_bounds(n: int, h: float) -> np.ndarray:
    """Upper bounds binom(n, k) w^(n-k) of a_k (descending order), w = MAX_POLE_FRACTION pi/h.

    Every denominator whose roots lie in |s| <= w has |a_k| below these bounds (the
    coefficients are elementary symmetric functions of the roots), and every stable one
    has a_k > 0; the search stays in that box. Without it, on decimated closed-loop data
    the output-error search can run off to poles far above the Nyquist frequency, where
    the model imitates the leader's inverse (e is nearly the integral of -u_h) through the
    look-ahead that the protocol's zero-phase anti-aliasing filter gives e.
    """
    w = MAX_POLE_FRACTION * np.pi / h
    return np.array([comb(n, k) * w ** (n - k) for k in range(n - 1, -1, -1)], float)


def ar_start(data: OutputData, a: np.ndarray, zeros: int, order: int) -> np.ndarray:
    """d_1..d_p of an AR(p) model of the output error for denominator ``a`` (least squares),
    the start of the noise model's refinement."""
    beta, _, X = fit_linear(a, data, zeros)
    raw = np.concatenate(data.y) - X @ beta
    rows, target = [], []
    start = 0
    for own in data.own:
        r = raw[start:start + len(own)]
        for k in range(order, len(r)):
            rows.append(r[k - order:k][::-1])
            target.append(r[k])
        start += len(own)
    return -np.linalg.lstsq(np.array(rows), np.array(target), rcond=None)[0]


def refine(data: OutputData, a0: np.ndarray, zeros: int, d0: np.ndarray | None = None, *,
           lags: int = COVARIANCE_LAGS) -> OutputFit:
    """Minimise the prediction-error criterion of output ``data.output`` from denominator
    ``a0`` and, for a Box-Jenkins model with AR noise, noise coefficients ``d0``."""
    a0 = np.asarray(a0, float)
    n = len(a0)
    d0 = np.zeros(0) if d0 is None else np.asarray(d0, float)
    x0 = np.concatenate([a0, d0])
    upper = np.concatenate([denominator_bounds(n, data.h), np.full(len(d0), np.inf)])
    lower = np.concatenate([np.zeros(n), np.full(len(d0), -np.inf)])
    x0 = np.clip(x0, lower, np.where(np.isfinite(upper), upper * (1 - 1e-9), upper))
    sol = least_squares(_residual, x0, args=(data, zeros, n), jac="3-point", method="trf",
                        bounds=(lower, upper), x_scale="jac", xtol=1e-12, ftol=1e-12,
                        gtol=1e-12, max_nfev=400 * len(x0))
    a, d = sol.x[:n], sol.x[n:]
    w = np.concatenate(([1.0], d)) if len(d) else None
    beta, r, X = fit_linear(a, data, zeros, w)
    b = beta[: zeros + 1]
    c = float(beta[zeros + 1])
    eta = beta[zeros + 2:]
    # Jacobian of the (whitened) prediction error in (b, a, c, initial states, d):
    # linear columns are the whitened X; the denominator's by central differences of
    # X(a) beta with beta fixed; d_k's the raw output error delayed by k samples
    Ja = np.empty((r.shape[0], n))
    for k in range(n):
        step = JACOBIAN_STEP * max(1.0, abs(a[k]))
        hi, lo = a.copy(), a.copy()
        hi[k] += step
        lo[k] -= step
        Ja[:, k] = used((design(hi, data, zeros) - design(lo, data, zeros)) @ beta, data, w
                        ) / (2 * step)
    Xw = used(X, data, w)
    tail = Xw[:, zeros + 1:] if data.initial == "estimate" else Xw[:, zeros + 1:zeros + 2]
    columns = [Xw[:, : zeros + 1], Ja, tail]
    if len(d):
        raw = np.concatenate(data.y) - X @ beta
        lagged = np.zeros((raw.shape[0], len(d)))
        start = 0
        for own in data.own:
            N = len(own)
            for k in range(1, len(d) + 1):
                lagged[start + k:start + N, k - 1] = raw[start:start + N - k]
            start += N
        columns.append(used(lagged, data, np.concatenate(([1.0], np.zeros(len(d))))))
    J = np.column_stack(columns)
    dof = r.shape[0] - J.shape[1]
    rss = float(r @ r)
    sigma2 = rss / max(dof, 1)
    scale = np.linalg.norm(J, axis=0)
    scale[scale == 0] = 1.0
    Js = J / scale
    inv = np.linalg.pinv(Js.T @ Js)
    middle = _noise_weighted(Js, r, lengths(data, w), lags, r.shape[0] / max(dof, 1))
    full = (inv @ middle @ inv) / np.outer(scale, scale)
    p = zeros + 1 + n + 1
    cov = full[:p, :p]
    noise = np.concatenate(([1.0], d))
    initial = eta.reshape(-1, n) if data.initial == "estimate" else np.zeros((len(data.y), n))
    return OutputFit(b, a, c, initial, r, rss, cov, float(np.sqrt(sigma2)), noise)


def _noise_weighted(J: np.ndarray, r: np.ndarray, lengths: list[int], lags: int,
                    correction: float) -> np.ndarray:
    """J^T Sigma J with Sigma the residual covariance within trials (module docstring).

    gamma(tau) is the residual autocovariance pooled over trials (times ``correction``,
    N / (N - d), for the fitted parameters), tapered by Bartlett weights
    1 - tau / (lags + 1) so that the estimate stays positive semidefinite (Newey & West,
    Econometrica 55(3), 1987); tau = 0 alone gives sigma^2 J^T J.
    """
    N = r.shape[0]
    bounds = np.cumsum([0, *lengths])
    out = correction * float(r @ r) / N * (J.T @ J)
    for tau in range(1, lags + 1):
        gamma = 0.0
        cross = np.zeros((J.shape[1], J.shape[1]))
        for lo, hi in itertools.pairwise(bounds):
            if hi - lo <= tau:
                continue
            gamma += float(r[lo:hi - tau] @ r[lo + tau:hi])
            cross += J[lo:hi - tau].T @ J[lo + tau:hi]
        weight = 1.0 - tau / (lags + 1)
        out += weight * correction * gamma / N * (cross + cross.T)
    return out
