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
    samples the estimate used; ``method`` names the estimator.
    """

    structure: Structure
    theta: np.ndarray
    covariance: np.ndarray
    names: tuple[str, ...]
    method: str
    noise_std: np.ndarray
    samples: int
