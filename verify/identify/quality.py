"""Quality of an identified model: fit ratios and residual tests (Section 4).

* Fit ratio per output (Section 4, "Human Modeling", the figure the paper quotes):
  100 (1 - ||y - yhat|| / ||y - mean(y)||), 2-norms over all samples of all trials of
  the data set, mean(y) over the same samples. yhat is the model *simulated* from the
  measured input e from a stated initial condition, never re-fitted to the data:
  :func:`honest_fits` runs the model over the identification and then the validation
  trials in log order, the first trial from rest and each later one from the state the
  model left the previous one in (coasted over the dead time between them, or from rest
  when the trials do not follow on, :func:`verify.identify.trial_data.dead_time_gaps`).
  That is the only fit the command reports and decides with.
* Residual tests are diagnostics: they are reported, never a reason to stop. A test that
  cannot be computed (e.g. a noise-free input that does not vary enough at the tested
  lags, or an identically zero residual) is reported as not computed, with the reason.
* The residual tests take the model's prediction errors: the output error y - yhat,
  filtered by the noise model's whitening filter D(q) when the estimate has one
  (:attr:`Estimate.noise_model`, the first p samples of each trial dropped).
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

Defaults: M = 20 lags, level 0.95.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy import signal
from scipy.stats import chi2

from verify.errors import VerifyInputError
from verify.identify.estimate import Estimate
from verify.identify.experiment import Trial
from verify.identify.prediction import predict

__all__ = ["CrossCorrelationTest", "Quality", "WhitenessTest", "assess", "cross_correlation",
           "fit_ratio", "honest_fits", "whiteness"]

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


@dataclass(frozen=True)
class Quality:
    """Fit ratios (%) per output and the residual tests of one data set."""

    fit: np.ndarray
    whiteness: tuple[WhitenessTest, ...]
    cross_correlation: tuple[CrossCorrelationTest, ...]
    samples: int
    initial: str = "carry"
    not_computed: tuple[str, ...] = ()

    @property
    def residuals_pass(self) -> bool:
        return not self.not_computed and all(
            t.passed for t in (*self.whiteness, *self.cross_correlation))


def fit_ratio(y: np.ndarray, yhat: np.ndarray) -> float:
    """100 (1 - ||y - yhat|| / ||y - mean(y)||) over all samples (Section 4).

    >>> round(fit_ratio(np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 1.0])), 4)
    29.2893
    """
    y = np.asarray(y, float).ravel()
    yhat = np.asarray(yhat, float).ravel()
    spread = np.linalg.norm(y - y.mean())
    if not spread > 0:
        raise VerifyInputError("the fit ratio is undefined for a constant output "
                               "(||y - mean(y)|| = 0)")
    return float(100.0 * (1.0 - np.linalg.norm(y - yhat) / spread))


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


def honest_fits(estimate: Estimate, identification: Sequence[Trial],
                validation: Sequence[Trial] = ()) -> tuple[list[np.ndarray],
                                                          list[np.ndarray]]:
    """The model simulated on the logged input (module docstring): (yhat per
    identification trial, yhat per validation trial), the trials taken in log order,
    identification first, the state carried across trials that follow on."""
    trials = [*identification, *validation]
    yhat = predict(estimate.structure, estimate.theta, trials, initial="carry")
    return list(yhat[:len(identification)]), list(yhat[len(identification):])


def assess(estimate: Estimate, trials: Sequence[Trial], *, yhat: Sequence[np.ndarray] | None
           = None, initial: str = "carry", lags: int = LAGS, level: float = LEVEL) -> Quality:
    """Fit ratios and residual tests of ``estimate`` on ``trials`` (module docstring).

    ``yhat``: the model's output per trial (e.g. from :func:`honest_fits`); by default
    the model simulated on ``trials`` alone from the ``initial`` condition ("carry":
    from rest, then carried; "zero"; "estimate": each trial's free response re-fitted,
    a figure that absorbs transients and is never a decision's basis)."""
    if yhat is None:
        yhat = predict(estimate.structure, estimate.theta, trials, initial=initial)
    elif initial == "estimate":
        raise ValueError("a given yhat is a simulation, not a re-initialised fit")
    u = [np.asarray(tr.u, float) for tr in trials]
    e = [np.asarray(tr.e, float) for tr in trials]
    fits = np.array([fit_ratio(np.concatenate([x[:, i] for x in u]),
                               np.concatenate([np.asarray(x)[:, i] for x in yhat]))
                     for i in (0, 1)])
    white = []
    cross = []
    skipped: list[str] = []
    for i in (0, 1):
        w = np.asarray(estimate.noise_model[i] if estimate.noise_model else (1.0,), float)
        lag = len(w) - 1
        res = [signal.lfilter(w, [1.0], x[:, i] - np.asarray(p)[:, i])[lag:]
               for x, p in zip(u, yhat, strict=True)]
        try:
            white.append(whiteness(res, output=i + 1, lags=lags, level=level))
        except VerifyInputError as exc:
            skipped.append(f"whiteness of output {i + 1}: {exc}")
        for j in (0, 1):
            try:
                cross.append(cross_correlation(res, [x[lag:, j] for x in e], output=i + 1,
                                               input=j + 1, lags=lags, level=level))
            except VerifyInputError as exc:
                skipped.append(f"cross-correlation of output {i + 1} with input {j + 1}: "
                               f"{exc}")
    return Quality(fits, tuple(white), tuple(cross), sum(len(x) for x in u), initial,
                   tuple(skipped))
