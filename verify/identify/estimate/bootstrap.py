"""Bootstrap covariance of the estimated parameters, resampling whole trials.

Trials are the independent units of the protocol of Section 4 (each starts after a
reference change, in its own state), so the resampling draws trials with replacement
(the nonparametric bootstrap of Efron & Tibshirani, An Introduction to the Bootstrap,
1993, Ch. 6, on the level of independent blocks) and re-estimates each draw. Draws whose
estimation fails are dropped; the result says how many were used.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from verify.errors import VerifyInputError
from verify.identify.estimate.estimation import estimate_model
from verify.identify.estimate.result import Estimate
from verify.identify.estimate.structure import Structure
from verify.inputs.experiment import Trial

__all__ = ["BootstrapResult", "bootstrap", "with_bootstrap_covariance"]


@dataclass(frozen=True)
class BootstrapResult:
    """Covariance of theta over ``used`` successful draws out of ``draws`` (rows: thetas)."""

    covariance: np.ndarray
    thetas: np.ndarray
    draws: int
    used: int


def bootstrap_draws(trials: Sequence[Trial], structure: Structure, draws: int, seed: int, *,
                    method: str = "riv+pem") -> BootstrapResult:
    """Re-estimate on ``draws`` resamples of the trials (with replacement), seeded."""
    trials = tuple(trials)
    if not (isinstance(draws, int) and draws >= 2):
        raise VerifyInputError(f"draws must be an integer >= 2, got {draws!r}")
    if len(trials) < 2:
        raise VerifyInputError(f"a bootstrap over trials needs at least 2 trials, got "
                               f"{len(trials)}")
    rng = np.random.default_rng(seed)
    thetas = []
    for _ in range(draws):
        pick = rng.integers(0, len(trials), len(trials))
        try:
            thetas.append(estimate_model([trials[k] for k in pick], structure,
                                         method=method).theta)
        except VerifyInputError:
            continue
    if len(thetas) < 2:
        raise VerifyInputError(f"only {len(thetas)} of {draws} bootstrap draws could be "
                               f"estimated; the trials are too few or too short")
    thetas = np.array(thetas)
    return BootstrapResult(np.cov(thetas, rowvar=False), thetas, draws, len(thetas))


def bootstrap(trials: Sequence[Trial], structure: Structure, draws: int, seed: int
              ) -> np.ndarray:
    """The bootstrap covariance of theta (``structure.names()`` order) over trials."""
    return bootstrap_draws(trials, structure, draws, seed).covariance


def with_bootstrap_covariance(estimate: Estimate, trials: Sequence[Trial], draws: int,
                              seed: int) -> Estimate:
    """``estimate`` with its covariance replaced by the bootstrap one."""
    cov = bootstrap(trials, estimate.structure, draws, seed)
    return replace(estimate, covariance=cov, covariance_kind="bootstrap")
