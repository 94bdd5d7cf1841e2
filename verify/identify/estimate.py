"""The result of an estimation: parameters in a structure, with their covariance."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from verify.identify.structure import Structure


@dataclass(frozen=True)
class Estimate:
    """Estimated parameters ``theta`` (ordered as ``structure.names()``) and covariance.

    ``covariance`` is the (asymptotic or bootstrap) covariance of ``theta``; the 95 %
    confidence region is the ellipsoid (θ - theta)^T covariance^-1 (θ - theta) <= chi2_p(0.95).
    ``noise_std`` is the residual standard deviation per output; ``samples`` the number of
    samples the estimate used; ``method`` names the estimator; ``covariance_kind`` says
    where ``covariance`` comes from: "asymptotic" (the prediction-error formula
    sigma^2 (J^T J)^-1, :mod:`verify.identify.pem`) or "bootstrap" (over trials,
    :mod:`verify.identify.bootstrap`); ``noise_model`` per output the whitening filter
    (1, d_1, ..., d_p) at the data's sampling step: the output noise is modelled as
    white noise through 1/D(q) (Box-Jenkins with AR noise); (1.0,) or empty means white
    output noise (output error). ``inflation`` is the factor the covariance was
    multiplied by for few trials (:func:`verify.identify.estimation.few_trials_factor`),
    1 when none.
    """

    structure: Structure
    theta: np.ndarray
    covariance: np.ndarray
    names: tuple[str, ...]
    method: str
    noise_std: np.ndarray
    samples: int
    covariance_kind: str = "asymptotic"
    noise_model: tuple[tuple[float, ...], ...] = ()
    inflation: float = 1.0

    def standard_errors(self) -> np.ndarray:
        """Square roots of the covariance's diagonal, in ``names`` order."""
        return np.sqrt(np.clip(np.diag(self.covariance), 0.0, None))
