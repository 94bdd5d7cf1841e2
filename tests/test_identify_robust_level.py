"""The confidence label of a region, re-derived exactly: P(chi2_p <= value) >= level."""

from __future__ import annotations

from fractions import Fraction

import pytest
from gmpy2 import mpq
from scipy.stats import chi2

from verify.identify.model.region import chi2_quantile, chi2_refusal, level_holds


@pytest.mark.parametrize("dof", [2, 4, 8, 10, 14, 26, 50])
@pytest.mark.parametrize("level", [Fraction(1, 2), Fraction(9, 10), Fraction(19, 20),
                                   Fraction(999, 1000)])
def test_the_exact_level_agrees_with_scipy_away_from_the_quantile(dof, level):
    q = float(chi2.ppf(float(level), dof))
    assert level_holds(level, mpq(q * (1 + 1e-9)), dof) is True
    assert level_holds(level, mpq(q * (1 - 1e-9)), dof) is False


@pytest.mark.parametrize("dof", [2, 6, 10, 18, 26])
def test_the_written_quantile_is_proved_and_one_ulp_less_is_not_always(dof):
    """chi2_quantile rounds scipy's value up until the level is proved; the float one
    ulp below is then never provably enough (it is the smallest such float or scipy's)."""
    import math

    level = Fraction(19, 20)
    value = chi2_quantile(level, dof)
    assert level_holds(level, mpq(value), dof) is True
    assert chi2_refusal(level, mpq(value), dof) is None
    below = math.nextafter(value, 0)
    if value != float(chi2.ppf(0.95, dof)):  # raised: the float below was not enough
        assert level_holds(level, mpq(below), dof) is False


def test_the_exact_formula_at_two_degrees_of_freedom():
    """dof = 2: P(X <= c) = 1 - e^(-c/2), so the 1/2 quantile is 2 ln 2 (irrational)."""
    import math

    ln2 = math.log(2)
    assert level_holds(Fraction(1, 2), mpq(2 * ln2 * (1 + 1e-15)), 2) is True
    assert level_holds(Fraction(1, 2), mpq(2 * ln2 * (1 - 1e-15)), 2) is False


@pytest.mark.parametrize("case", ["odd", "negative", "huge", "zero dof"])
def test_undecidable_labels_are_refused_not_accepted(case):
    level = Fraction(19, 20)
    value, dof = {"odd": (mpq(20), 9), "negative": (mpq(-1), 10),
                  "huge": (mpq(10) ** 9, 10), "zero dof": (mpq(5), 0)}[case]
    assert level_holds(level, value, dof) is None
    assert "could not be re-derived" in chi2_refusal(level, value, dof)


def test_a_chi2_lowered_by_5e_10_is_refused_with_the_reason():
    level = Fraction(19, 20)
    value = mpq(chi2_quantile(level, 10)) - mpq(5, 10**10)
    why = chi2_refusal(level, value, 10)
    assert why is not None and "below the 0.95 quantile" in why


def test_a_long_rational_chi2_is_decided_at_short_bounds():
    """A hostile file's chi2 with a 3000-digit denominator: decided through 40-decimal
    bounds on each side (the series never sees the long number)."""
    level = Fraction(19, 20)
    q = mpq(chi2_quantile(level, 10))
    long_above = q + mpq(1, 10**3000 + 7)
    long_below = q - mpq(10**20, 10**3000 + 7) - mpq(1, 10**12)
    assert level_holds(level, long_above, 10) is True
    assert level_holds(level, long_below, 10) is False


@pytest.mark.parametrize("dof", [4, 10, 18, 26])
def test_the_exact_decision_agrees_with_50_digit_arithmetic_at_scipys_value(dof):
    """scipy's 0.95 quantile is sometimes just below the exact one (dof = 10: the
    chi-square CDF there is 0.95 - 6.7e-18): the exact check and an independent
    50-digit evaluation (mpmath) give the same side."""
    import mpmath

    value = float(chi2.ppf(0.95, dof))
    with mpmath.workdps(50):
        y = mpmath.mpf(value) / 2
        cdf = 1 - mpmath.e ** (-y) * sum(y**k / mpmath.factorial(k) for k in range(dof // 2))
        above = cdf >= mpmath.mpf(19) / 20
    assert level_holds(Fraction(19, 20), mpq(value), dof) is bool(above)
