"""The confidence region of an identified parameter vector, as exact data.

The region is the ellipsoid {θ : (θ - θc)^T Σ^-1 (θ - θc) <= χ} with θc the parameter
values *as written* in the model file (exact decimals), Σ the estimated covariance read as
the exact binary rationals of its floats, and χ the ``level`` quantile of the chi-square
distribution with p = len(θ) degrees of freedom, read as the exact value of its float
(asymptotic normality of the estimate: L. Ljung, *System Identification*, 2nd ed., 1999,
Sec. 9.6). Every membership test is exact.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
from gmpy2 import mpq

from verify.errors import VerifyInputError
from verify.inputs.numbers import rational
from verify.passivity.check import robust_band as rb

#: Relative agreement asked of a stored chi-square value with scipy's quantile.
CHI2_AGREEMENT = 1e-9


def chi2_quantile(level: Fraction, dof: int) -> float:
    """The chi-square ``level`` quantile with ``dof`` degrees of freedom (scipy)."""
    from scipy.stats import chi2

    return float(chi2.ppf(float(level), dof))


@dataclass(frozen=True)
class Region:
    """θc, Σ, the confidence level and χ, all exact."""

    center: tuple[mpq, ...]
    covariance: tuple[tuple[mpq, ...], ...]
    level: Fraction
    chi2: mpq

    @property
    def dimension(self) -> int:
        return len(self.center)

    def float_center(self) -> np.ndarray:
        return np.array([float(x) for x in self.center])

    def float_covariance(self) -> np.ndarray:
        return np.array([[float(x) for x in row] for row in self.covariance])

    def contains(self, theta: Sequence[mpq]) -> bool:
        """Exact membership (needs Σ > 0, checked by :func:`make_region`)."""
        return rb.quadratic_form(rb.inverse(self.covariance), self.center, theta) <= self.chi2

    def half_widths(self) -> list[mpq]:
        """Rational r_i >= sqrt(χ Σ_ii), rounded up to 4 significant digits."""
        return half_widths(self.covariance, self.chi2)


def half_widths(covariance, chi2: mpq) -> list[mpq]:
    """Short rationals r_i with r_i^2 >= chi2 Σ_ii (4 significant digits, rounded up)."""
    out = []
    for i in range(len(covariance)):
        need = chi2 * covariance[i][i]
        r = _round_up(math.sqrt(float(need)))
        while r * r < need:
            r = _round_up(float(r) * (1 + 1e-3))
        out.append(r)
    return out


def _round_up(x: float) -> mpq:
    """A short rational >= x > 0 (4 significant digits), or 0 for x = 0."""
    if x <= 0:
        return mpq(0)
    e = math.floor(math.log10(x)) - 3
    return mpq(math.ceil(x / 10.0**e + 1e-9)) * mpq(10) ** e


def make_region(center: Sequence[object], covariance: np.ndarray, level: Fraction,
                chi2: float | None = None) -> Region:
    """The region from exact center values and a float covariance (one line on bad data)."""
    c = tuple(rational(x, f"center[{i}]") for i, x in enumerate(center))
    cov = np.asarray(covariance, dtype=float)
    p = len(c)
    if cov.shape != (p, p) or not np.all(np.isfinite(cov)):
        raise VerifyInputError(f"covariance: expected a finite {p} x {p} matrix, got shape "
                               f"{cov.shape}")
    S = tuple(tuple(mpq(float(v)) for v in row) for row in cov)  # the binary values
    if not rb.is_positive_definite([list(r) for r in S]):
        raise VerifyInputError("covariance: not symmetric positive definite (exact LDL^T); "
                               "the confidence ellipsoid is undefined")
    if not 0 < level < 1:
        raise VerifyInputError(f"confidence level {level} must lie in (0, 1)")
    value = chi2_quantile(level, p) if chi2 is None else float(chi2)
    return Region(c, S, Fraction(level), mpq(value))


__all__ = ["CHI2_AGREEMENT", "Region", "chi2_quantile", "half_widths", "make_region"]
