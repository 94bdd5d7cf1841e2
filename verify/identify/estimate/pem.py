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
within trials from the residual autocovariance over a window of ``COVARIANCE_SECONDS``
seconds (:func:`covariance_lags` samples at the data's step) with Bartlett weights; for
white residuals it reduces to the first formula. The window is set in seconds, not
samples, because what colours the residual is the operator and the loop (time
constants of a few tenths of a second, Section 4), whatever the logging rate: a fixed
20 lags covered 1 s at 20 Hz but 0.08 s at 250 Hz, and there the 95 % region held the
true operator in 3 of 7 simulated experiments against 8 of 8 at 120 Hz. The coverage at
20-250 Hz with a 1 s window is measured in ``benchmarks/bench_identify_coverage.py``.
The initial states and the output's offset (when estimated) are nuisance parameters; the
covariance of H(s)'s parameters is the corresponding block of the full matrix (so their
uncertainty is accounted for).
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass, field
from math import comb

import numpy as np
from scipy import signal
from scipy.optimize import least_squares

from verify.identify.estimate.prediction import design, fit_linear, lengths, used
from verify.identify.estimate.trial_data import OutputData

__all__ = ["COVARIANCE_SECONDS", "OutputFit", "covariance_lags", "refine"]

_BAD = 1e6  # residual returned for a denominator whose simulation overflows
#: Poles are searched in |s| <= MAX_POLE_FRACTION times the Nyquist frequency pi/h.
MAX_POLE_FRACTION = 0.5
#: Seconds of residual autocovariance the covariance accounts for (module docstring).
COVARIANCE_SECONDS = 1.0
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
    (1, d_1, ..., d_p) of the noise model v = e / D(q) (just (1,) for output error);
    ``offset`` the estimated constant on the output and ``offset_variance`` its
    (asymptotic) variance, 0 and 0 when no offset is estimated.
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
    offset: float = 0.0
    offset_variance: float = 0.0


def covariance_lags(h: float, lengths: Sequence[int] = (),
                    seconds: float = COVARIANCE_SECONDS) -> int:
    """The lags of the covariance's noise window: ``seconds`` at step ``h`` (at least 1),
    and below the longest trial (a lag no trial reaches adds nothing)."""
    lags = max(1, int(np.ceil(seconds / h - 1e-9)))
    longest = max(lengths, default=lags + 1)
    return int(max(1, min(lags, longest - 1)))


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
           lags: int | None = None) -> OutputFit:
    """Minimise the prediction-error criterion of output ``data.output`` from denominator
    ``a0`` and, for a Box-Jenkins model with AR noise, noise coefficients ``d0``.

    ``lags``: the covariance's noise window in samples (default :func:`covariance_lags`,
    ``COVARIANCE_SECONDS`` at the data's step)."""
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
    shared = data.shared(zeros)
    eta = beta[shared:]
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
    free = [col for k in range(len(data.y)) if data.estimated(k)
            for col in range(shared + k * n, shared + (k + 1) * n)]
    tail = Xw[:, [*range(zeros + 1, shared), *free]]  # c, the offset, initial states
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
    if lags is None:
        lags = covariance_lags(data.h, lengths(data, w))
    middle = _noise_weighted(Js, r, lengths(data, w), lags, r.shape[0] / max(dof, 1))
    full = (inv @ middle @ inv) / np.outer(scale, scale)
    p = zeros + 1 + n + 1
    cov = full[:p, :p]
    noise = np.concatenate(([1.0], d))
    initial = eta.reshape(-1, n)  # zero for the trials whose state is not fitted
    offset, offset_variance = ((float(beta[zeros + 2]), float(full[p, p])) if data.offset
                               else (0.0, 0.0))
    return OutputFit(b, a, c, initial, r, rss, cov, float(np.sqrt(sigma2)), noise, offset,
                     offset_variance)


def _noise_weighted(J: np.ndarray, r: np.ndarray, lengths: list[int], lags: int,
                    correction: float) -> np.ndarray:
    """J^T Sigma J with Sigma the residual covariance within trials (module docstring).

    gamma(tau) is the residual autocovariance pooled over trials (times ``correction``,
    N / (N - d), for the fitted parameters), tapered by Bartlett weights
    1 - tau / (lags + 1) so that the estimate stays positive semidefinite (Newey & West,
    Econometrica 55(3), 1987); tau = 0 alone gives sigma^2 J^T J. Sigma J is formed
    trial by trial as a convolution of J's columns with the tapered autocovariance
    (FFT), so a window of hundreds of lags (1 s at 250 Hz) costs about what one lag does.
    """
    N = r.shape[0]
    bounds = np.cumsum([0, *lengths])
    gamma = np.zeros(lags + 1)
    for lo, hi in itertools.pairwise(bounds):
        seg = r[lo:hi]
        m = min(lags, hi - lo - 1)
        if m < 1:
            continue
        size = int(2 ** np.ceil(np.log2(2 * (hi - lo))))
        spec = np.fft.rfft(seg, size)
        gamma[1:m + 1] += np.fft.irfft(spec * np.conj(spec), size)[1:m + 1]
    taus = np.arange(1, lags + 1)
    kernel_half = (1.0 - taus / (lags + 1)) * gamma[1:] * correction / N
    kernel = np.concatenate([kernel_half[::-1], [correction * float(r @ r) / N],
                             kernel_half])
    sigma_j = np.empty_like(J)
    for lo, hi in itertools.pairwise(bounds):
        if hi > lo:
            sigma_j[lo:hi] = signal.oaconvolve(J[lo:hi], kernel[:, None], mode="full",
                                               axes=0)[lags:lags + hi - lo]
    out = J.T @ sigma_j
    return (out + out.T) / 2
