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

#: Kept for callers that still import it; no check uses a float agreement any more.
CHI2_AGREEMENT = 0.0
#: Terms of the exponential series tried before an exact level check gives up.
MAX_TERMS = 4000


def level_holds(level: Fraction | mpq, chi2: mpq, dof: int) -> bool | None:
    """Decide P(X <= chi2) >= level for X chi-square with an even ``dof``, exactly.

    With dof = 2m and y = chi2/2, P(X > chi2) = e^-y sum_{k<m} y^k/k! (the Poisson sum
    of the chi-square survival function with even degrees of freedom: M. Abramowitz and
    I. Stegun, *Handbook of Mathematical Functions*, 26.4.21), so the claim is
    S = sum_{k<m} y^k/k! <= (1 - level) e^y. The partial sums T_N of e^y bound it below;
    T_N + y^(N+1)/(N+1)! (N+2)/(N+2-y), for N + 2 > y, bounds it above. True or False
    when a bound decides, None when MAX_TERMS terms do not (or dof is odd, chi2 < 0 or
    chi2 > MAX_TERMS / 2, or chi2 lies within 1e-40 of the quantile).
    """
    if dof <= 0 or dof % 2 or chi2 < 0 or mpq(chi2) > MAX_TERMS // 2:
        return None
    # P(X <= c) increases with c: decide at short rationals c_lo <= c <= c_hi (40
    # decimals), so a hostile file's long numbers cannot make the series costly
    c = mpq(chi2)
    scale = 10**40
    c_lo, c_hi = mpq(_floor(c * scale), scale), mpq(-_floor(-c * scale), scale)
    if _holds(mpq(level), c_lo, dof):
        return True
    if _holds(mpq(level), c_hi, dof) is False:
        return False
    return None


def _floor(q: mpq) -> int:
    return int(q.numerator // q.denominator)


def _holds(level: mpq, chi2: mpq, dof: int) -> bool | None:
    """:func:`level_holds` at a short rational ``chi2`` (the series bounds)."""
    y, m = chi2 / 2, dof // 2
    term, S = mpq(1), mpq(0)
    for k in range(m):
        S += term
        term = term * y / (k + 1)
    # term = y^m/m!; T_{m-1} = S
    T, N = S, m - 1
    gap = 1 - level
    while N < MAX_TERMS:
        if S <= gap * T:
            return True
        if N + 2 > y:
            tail = term * (N + 2) / (N + 2 - y)  # term = y^(N+1)/(N+1)!
            if S > gap * (T + tail):
                return False
        T += term
        N += 1
        term = term * y / (N + 1)
    return None


def chi2_quantile(level: Fraction, dof: int) -> float:
    """The chi-square ``level`` quantile with ``dof`` degrees of freedom as a float.

    scipy's value, raised ulp by ulp for even ``dof`` until :func:`level_holds` proves
    P(X <= value) >= level exactly: the region it defines contains the exact
    ``level`` region (odd ``dof``: scipy's value, never used by a certificate)."""
    from scipy.stats import chi2

    value = float(chi2.ppf(float(level), dof))
    if dof % 2 == 0 and math.isfinite(value):
        for _ in range(1000):
            if level_holds(level, mpq(value), dof):
                break
            value = math.nextafter(value, math.inf)
    return value


def chi2_refusal(level: Fraction | mpq, chi2: mpq, dof: int) -> str | None:
    """None if ``chi2`` is at least the ``level`` quantile with ``dof`` degrees of freedom
    (decided exactly by :func:`level_holds`), else why the label does not hold."""
    holds = level_holds(level, chi2, dof)
    if holds:
        return None
    if holds is False:
        return (f"chi2 = {float(chi2):.17g} is below the {float(level)} quantile with {dof} "
                f"degrees of freedom (exactly: P(X <= chi2) < {level}), so the region is "
                f"not the {float(level)} confidence region")
    return (f"chi2 = {float(chi2):.6g} with {dof} degrees of freedom: the confidence level "
            f"{level} could not be re-derived exactly")


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


__all__ = ["CHI2_AGREEMENT", "MAX_TERMS", "Region", "chi2_quantile", "chi2_refusal",
           "half_widths", "level_holds", "make_region"]
