"""Passivity indices nu_IFP and rho_OFP with exact bounds (paper, Section 4).

Known answers, worked by hand:
- 1/(s+1): Re H = 1/(1+w^2) -> 0 as w -> inf, so nu_IFP = 0; Re(1/H) = 1, so rho_OFP = 1.
- (s+2)/(s+1): Re H = (2+w^2)/(1+w^2) -> 1, nu_IFP = 1; Re(1/H) = (2+w^2)/(4+w^2) >= 1/2
  at w = 0, rho_OFP = 1/2.
- 1/(s^2+s+1): with t = w^2 - 1, Re H = -t/(t^2+t+1) >= -1/3 (at t = 1), nu_IFP = -1/3;
  Re(1/H) = 1 - w^2 is unbounded below, so no OFP index.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import check_kyp, exact_model
from verify.passivity.indices import check_ofp, ifp_index, loop_transform, ofp_index, round_up
from verify.passivity.io.model_file import load_model
from verify.passivity.model import from_state_space


def ss(A, B, C, D, name="m"):
    return from_state_space(*(np.atleast_2d(np.array(x, dtype=float)) for x in (A, B, C, D)),
                            name=name)


FIRST = ss([[-1]], [[1]], [[1]], [[0]], "1/(s+1)")
LEAD = ss([[-1]], [[1]], [[1]], [[1]], "(s+2)/(s+1)")
SECOND = ss([[0, 1], [-1, -1]], [[0], [1]], [[1, 0]], [[0]], "1/(s^2+s+1)")


@pytest.mark.parametrize("model, value", [(FIRST, 0), (LEAD, 1)])
def test_ifp_known_answers_are_exact(model, value):
    index = ifp_index(model)
    assert index.exact and index.lower == value and index.upper_at == "ω → ∞"
    shifted = exact_model(model.A, model.B, model.C, model.D - value * np.eye(1))
    assert check_kyp(shifted, index.certificate).ok


def test_ifp_of_a_second_order_lag_is_bracketed_exactly():
    index = ifp_index(SECOND)
    assert index.lower <= Fraction(-1, 3) <= index.upper
    assert index.upper - index.lower < Fraction(1, 10**5)
    assert index.estimate == pytest.approx(-1 / 3, abs=1e-9)


@pytest.mark.parametrize("model, value", [(FIRST, Fraction(1)), (LEAD, Fraction(1, 2))])
def test_ofp_known_answers(model, value):
    index = ofp_index(model)
    assert index.lower is not None and index.upper is not None
    assert index.lower <= value <= index.upper
    assert index.upper - index.lower < Fraction(1, 10**5)
    em = exact_model(model.A, model.B, model.C, model.D)
    assert check_ofp(em, index.certificate, index.lower)


def test_ofp_certificate_is_rejected_above_the_index():
    em = exact_model(FIRST.A, FIRST.B, FIRST.C, FIRST.D)
    P = ex.to_rational([[1.0]])  # V = x^2/2 proves OFP(1) of 1/(s+1) exactly
    assert check_ofp(em, P, Fraction(1))
    assert not check_ofp(em, P, Fraction(1) + Fraction(1, 10**9))


def test_loop_transform_of_first_order_lag():
    """u = u~ + y around 1/(s+1) gives 1/s exactly."""
    em = exact_model(FIRST.A, FIRST.B, FIRST.C, FIRST.D)
    loop = loop_transform(em, Fraction(1))
    assert [loop.A, loop.B, loop.C, loop.D] == [[[0]], [[1]], [[1]], [[0]]]


def test_no_ofp_index_for_relative_degree_two():
    index = ofp_index(SECOND)
    assert index.lower is None and index.upper is not None and index.upper < -1000


def test_shipped_models():
    m25 = load_model("verify/data/models/reconstructed_ks2p5.toml")
    m30 = load_model("verify/data/models/reconstructed_ks3p0.toml")
    ifp25 = ifp_index(m25)
    assert ifp25.lower < 0 and ifp25.upper < 0 and ifp25.lower <= ifp25.upper
    assert ifp25.upper - ifp25.lower < Fraction(1, 10**4)
    ofp25 = ofp_index(m25)  # the loop u = rho y goes unstable before the frequency bound holds
    assert ofp25.lower is None and ofp25.upper == -10**6 and "Re s > 0" in ofp25.upper_at
    ifp30, ofp30 = ifp_index(m30), ofp_index(m30)
    assert ifp30.exact and ifp30.lower == 0  # strictly proper diagonal, skew feedthrough
    assert ofp30.exact and ofp30.lower == 0  # skew D: Re z^H D z = 0 < |D z|^2 at infinity


def test_round_up_keeps_the_bound():
    x = Fraction(-465533256644351906551893, 9922240128700779205909760)
    q = round_up(x)
    assert q >= x and q - x <= Fraction(1, 10**6) and q.denominator <= 10**12


def test_ofp_upper_bound_next_to_a_pole_on_the_axis():
    """0.1 + s/(s^2 + 4): Re(1/H) -> 0 at the pole w = 2, so rho_OFP = 0; the witness must
    be taken beside the pole, where H(jw) is defined."""
    model = ss([[0, 1], [-4, 0]], [[0], [1]], [[0, 1]], [[0.1]])
    index = ofp_index(model)
    assert index.lower == 0 and index.upper is not None and index.upper < Fraction(1, 100)
