"""Residual tests of an identified model's prediction errors (Section 4).

The estimator uses the whiteness test to decide whether an output needs a noise model
(:func:`verify.identify.estimate.estimation.with_noise_model`); the quality stage reports
both tests as diagnostics (:func:`verify.identify.quality.fits.assess`). Residuals and
inputs are given per trial; products never cross a trial boundary.

* Residual whiteness: Ljung-Box statistic Q = N (N + 2) sum_{tau=1..M} rho(tau)^2 /
  (N - tau) of the residual's normalised autocorrelation rho (products within trials),
  compared with the chi-square quantile chi2_M(level) (Ljung & Box, Biometrika 65(2),
  1978). White residuals pass.
* Input-residual cross-correlation (Ljung, System Identification, 1999, Sec. 16.6,
  eq. (16.67)): zeta = N r^T R^-1 r / lambda with r the correlation of the residual
  eps(t) with phi(t) = (e_j(t), e_j(t-1), ..., e_j(t-M+1)), R the covariance of phi and
  lambda the residual variance; chi2_M under "residual independent of past input".
  Only lags tau >= 0 (input before or at the residual) are tested: in closed loop the
  residual drives later inputs through the leader, so negative lags correlate for any
  model.

* Effective sample size (:func:`effective_samples`): N divided by the Bartlett-weighted
  sum of the residual's autocorrelation over M lags (>= 1), the number of independent
  samples that carry the same evidence when the protocol's filtering and decimation, or
  unmodelled dynamics, colour the residual; the likelihood-ratio tests of the
  identification command count samples this way.

Defaults: M = 20 lags, level 0.95.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy.stats import chi2

from verify.errors import VerifyInputError

__all__ = ["LAGS", "LEVEL", "CrossCorrelationTest", "WhitenessTest", "cross_correlation",
           "effective_samples", "whiteness"]

LAGS = 20
LEVEL = 0.95


@dataclass(frozen=True)
class WhitenessTest:
    """Ljung-Box test of output ``output``'s residual (1-based), module docstring."""

    output: int
    lags: int
    level: float
    statistic: float
    threshold: float
    autocorrelation: np.ndarray  # rho(1..lags)

    @property
    def passed(self) -> bool:
        return self.statistic <= self.threshold


@dataclass(frozen=True)
class CrossCorrelationTest:
    """Independence of output ``output``'s residual from input ``input`` (1-based)."""

    output: int
    input: int
    lags: int
    level: float
    statistic: float
    threshold: float
    correlation: np.ndarray  # normalised correlation of eps(t) with e_j(t - tau), tau = 0..

    @property
    def passed(self) -> bool:
        return self.statistic <= self.threshold


def _lags(lags: int, shortest: int) -> int:
    if not (isinstance(lags, int) and lags >= 1):
        raise VerifyInputError(f"lags must be a positive integer, got {lags!r}")
    if shortest <= lags + 1:
        raise VerifyInputError(f"the residual tests need trials longer than lags + 1 = "
                               f"{lags + 1} samples; the shortest has {shortest}")
    return lags


def whiteness(residuals: Sequence[np.ndarray], *, output: int = 1, lags: int = LAGS,
              level: float = LEVEL) -> WhitenessTest:
    """Ljung-Box test of residuals given per trial (module docstring)."""
    residuals = [np.asarray(r, float) for r in residuals]
    M = _lags(lags, min(len(r) for r in residuals))
    N = sum(len(r) for r in residuals)
    r0 = sum(float(r @ r) for r in residuals)
    if not r0 > 0:
        raise VerifyInputError("the residual is identically zero; nothing to test")
    rho = np.array([sum(float(r[:-tau] @ r[tau:]) for r in residuals) / r0
                    for tau in range(1, M + 1)])
    Q = float(N * (N + 2) * np.sum(rho ** 2 / (N - np.arange(1, M + 1))))
    return WhitenessTest(output, M, level, Q, float(chi2.ppf(level, M)), rho)


def cross_correlation(residuals: Sequence[np.ndarray], inputs: Sequence[np.ndarray], *,
                      output: int = 1, input: int = 1, lags: int = LAGS,
                      level: float = LEVEL) -> CrossCorrelationTest:
    """Test of eps against lags 0..M-1 of one input, both given per trial (docstring)."""
    residuals = [np.asarray(r, float) for r in residuals]
    inputs = [np.asarray(x, float) for x in inputs]
    M = _lags(lags, min(len(r) for r in residuals))
    eps = np.concatenate([r[M - 1:] for r in residuals])
    phi = np.concatenate([np.column_stack([x[M - 1 - tau:len(x) - tau] for tau in range(M)])
                          for x in inputs])
    N = eps.shape[0]
    lam = float(eps @ eps) / N
    r = phi.T @ eps / N
    R = phi.T @ phi / N
    if not (lam > 0 and np.linalg.matrix_rank(R) == M):
        raise VerifyInputError(f"input {input} does not vary enough for the cross-correlation "
                               f"test at {M} lags")
    zeta = float(N * r @ np.linalg.solve(R, r) / lam)
    corr = r / np.sqrt(lam * np.diag(R))
    return CrossCorrelationTest(output, input, M, level, zeta, float(chi2.ppf(level, M)), corr)


def effective_samples(residual: np.ndarray, lengths: Sequence[int], *, lags: int = LAGS
                      ) -> float:
    """N / max(1, 1 + 2 sum_{k=1..lags} (1 - k/(lags + 1)) rho(k)) of a residual stacked
    over trials of the given ``lengths`` (products within trials; module docstring)."""
    parts, row = [], 0
    for count in lengths:
        parts.append(residual[row:row + count])
        row += count
    var = sum(float(p @ p) for p in parts) / max(sum(len(p) for p in parts), 1)
    if var <= 0:
        return float(len(residual))
    total = 0.0
    for k in range(1, lags + 1):
        acc = sum(float(p[k:] @ p[:-k]) for p in parts if len(p) > k)
        rho = acc / (var * len(residual))
        total += (1 - k / (lags + 1)) * rho
    return len(residual) / max(1.0, 1 + 2 * total)
