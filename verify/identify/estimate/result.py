"""The result of an estimation: parameters in a structure, with their covariance.

:func:`assemble` puts the per-output fits of the estimators (the constant-coupling
structures of Section 4 are estimated one output at a time) together into one
:class:`Estimate`; :class:`CannotIdentifyError` is the estimator's answer when the data
determine no model.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from verify.errors import VerifyInputError
from verify.identify.estimate.structure import Structure

if TYPE_CHECKING:
    from verify.identify.estimate.pem import OutputFit

__all__ = ["CannotIdentifyError", "Estimate", "assemble"]


class CannotIdentifyError(VerifyInputError):
    """The data do not determine the model (raised by the estimator when every
    refinement ends on the search bound); the command reports *cannot identify*."""


@dataclass(frozen=True)
class Estimate:
    """Estimated parameters ``theta`` (ordered as ``structure.names()``) and covariance.

    ``covariance`` is the (asymptotic or bootstrap) covariance of ``theta``; the 95 %
    confidence region is the ellipsoid (θ - theta)^T covariance^-1 (θ - theta) <= chi2_p(0.95).
    ``noise_std`` is the residual standard deviation per output; ``samples`` the number of
    samples the estimate used; ``method`` names the estimator; ``covariance_kind`` says
    where ``covariance`` comes from: "asymptotic" (the prediction-error formula
    sigma^2 (J^T J)^-1, :mod:`verify.identify.estimate.pem`) or "bootstrap" (over trials,
    :mod:`verify.identify.estimate.bootstrap`); ``noise_model`` per output the whitening filter
    (1, d_1, ..., d_p) at the data's sampling step: the output noise is modelled as
    white noise through 1/D(q) (Box-Jenkins with AR noise); (1.0,) or empty means white
    output noise (output error). ``inflation`` is the factor the covariance was
    multiplied by for few trials (:func:`verify.identify.estimate.estimation.few_trials_factor`),
    1 when none. ``offsets`` are the estimated constants on the logged outputs u_1, u_2 and
    ``offset_errors`` their standard errors (widened like the covariance); both empty
    when no offset was estimated. The offsets are nuisance parameters: H(s) is
    ``theta`` alone, and ``covariance`` (of ``theta``) already accounts for them.
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
    offsets: tuple[float, ...] = ()
    offset_errors: tuple[float, ...] = ()

    def standard_errors(self) -> np.ndarray:
        """Square roots of the covariance's diagonal, in ``names`` order."""
        return np.sqrt(np.clip(np.diag(self.covariance), 0.0, None))


def assemble(structure: Structure, fits: Sequence[OutputFit], method: str, samples: int,
             covariance_kind: str = "asymptotic", *, offset: bool = False) -> Estimate:
    """The :class:`Estimate` of two output fits, parameters ordered as ``structure.names()``
    (with their offsets when ``offset``: the fits estimated one)."""
    per = structure.zeros + 1 + structure.poles
    theta = np.empty(2 * per + 2)
    cov = np.zeros((2 * per + 2, 2 * per + 2))
    for i, fit in enumerate(fits):
        idx = [*range(i * per, (i + 1) * per), 2 * per + i]  # b, a, then c_ij
        theta[idx] = np.concatenate([fit.b, fit.a, [fit.c]])
        cov[np.ix_(idx, idx)] = fit.covariance
    cov = 0.5 * (cov + cov.T)
    return Estimate(structure, theta, cov, structure.names(), method,
                    np.array([fit.sigma for fit in fits]), samples,
                    covariance_kind=covariance_kind,
                    noise_model=tuple(tuple(float(v) for v in fit.noise) for fit in fits),
                    offsets=tuple(float(fit.offset) for fit in fits) if offset else (),
                    offset_errors=tuple(float(np.sqrt(max(fit.offset_variance, 0.0)))
                                        for fit in fits) if offset else ())
