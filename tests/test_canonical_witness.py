"""Canonical witness frequencies: float noise in the search does not change the exact ω*.

The gate's *not passive* evidence is a rational ω* and vector v with
vᴴ(H(jω*) + H(jω*)ᴴ)v < 0, proved exactly. ω* is the simplest rational on the
Stern-Brocot path to the float minimiser that the exact check certifies, so the float
minimiser moved by 1e-12 (another BLAS thread count, another summation order) gives the
same ω*, the same witness, the same artefact bytes.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from verify.passivity.check.witness import (
    _continued_fraction,
    canonical_frequency_witness,
    frequency_witness,
    frequency_witness_at,
)
from verify.passivity.decision import decide
from verify.passivity.io.binding import exact_of
from verify.passivity.model import from_state_space


def _resonant(zeta: float, w0_squared: float = 9.0):
    """0.05 + c s/(s^2 + 2 zeta w0 s + w0^2): nu < 0 only in a band of relative width
    ~ zeta around w0 (nu(w0) = -0.05)."""
    a1 = 2 * zeta * float(np.sqrt(w0_squared))
    model = from_state_space([[0.0, 1.0], [-w0_squared, -a1]], [[0.0], [1.0]],
                             [[0.0, -0.1 * a1]], [[0.05]], name="resonant")
    return model, exact_of(model)


@pytest.mark.parametrize("zeta", [0.3, 1e-3, 1e-6, 1e-8])
@pytest.mark.parametrize("w0_squared", [9.0, 10.0])  # dip around 3, or around sqrt(10)
def test_noise_does_not_change_the_witness(zeta, w0_squared):
    """At zeta = 1e-8 around sqrt(10) the former rounding of omega (limit_denominator at
    10^6, then 10^12) gave four different rationals for these five floats."""
    _, em = _resonant(zeta, w0_squared)
    w0 = float(np.sqrt(w0_squared))
    omega = w0 * (1 + zeta / 7)  # inside the dip, not at its centre
    base = canonical_frequency_witness(em, omega)
    assert base is not None
    for noisy in (omega + 1e-12, omega - 1e-12, omega * (1 + 1e-9), omega * (1 - 1e-9),
                  np.nextafter(omega, 9)):
        again = canonical_frequency_witness(em, float(noisy))
        assert again is not None and again.data == base.data
    w = Fraction(base.data["omega"])
    assert frequency_witness_at(em, w) is not None  # re-checked exactly
    assert abs(w - Fraction(w0)) < 3 * zeta * w0  # in the dip


def test_the_witness_is_the_simplest_certified_rational_on_the_path():
    """At zeta = 0.3 the dip contains 3 itself: ω* = 3, not a 7-digit rounding."""
    _, em = _resonant(0.3)
    assert canonical_frequency_witness(em, 3.0123456789).data["omega"] == "3"


def test_gate_decision_reports_the_canonical_witness():
    model, _ = _resonant(1e-3)
    d = decide(model)
    assert d.verdict == "not passive" and d.witness.kind == "frequency"
    w = Fraction(d.witness.data["omega"])
    assert w.denominator < 10**4  # a short rational, not a rounding of a float


def test_no_witness_where_the_model_is_passive():
    _, em = _resonant(0.3)
    assert canonical_frequency_witness(em, 0.5) is None  # nu(0.5) > 0: nothing certified
    assert frequency_witness(em, 0.5) is None


def test_continued_fraction_terms():
    assert _continued_fraction(Fraction(415, 93)) == [4, 2, 6, 7]
    assert _continued_fraction(Fraction(0)) == [0]
