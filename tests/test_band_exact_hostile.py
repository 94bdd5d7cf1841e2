"""Attacks on the exact band route: forged certificates, inputs built to fool the root
counting, and band edges placed on the roots themselves. Grouped by class."""

from __future__ import annotations

import copy
import json
from fractions import Fraction

import pytest
from flint import fmpq, fmpq_poly

from verify.passivity.band import decide_band
from verify.passivity.check import interval_roots as ir
from verify.passivity.check.band_fd import (
    BandFdCertificate,
    IntervalFailure,
    IntervalNonnegativity,
    analyse_band,
    check_band_fd_data,
    negative_points,
    nonnegative_on,
    statement,
)
from verify.passivity.decision import NOT_PASSIVE, PASSIVE
from verify.passivity.model import from_transfer_function

F = Fraction
HAIR = F(1, 10**30)
BAND = (F(0), F(1) - F(1, 10**12))


def near_miss(hair: Fraction = -HAIR):
    """Re H(jw) = (w^2 - 1)^2 / (1 + w^2)^3 + hair: with hair = -1e-30 negative only within
    ~1e-15 of w = 1 (two roots just past BAND's edge); with +1e-30 positive, with complex
    roots ~1e-15 off the real axis at w = 1, which the bisection must resolve."""
    # n(s) = s^2/2 + s/2 + 1 solves n(s) d(-s) + n(-s) d(s) = 2 (s^2 + 1)^2 for
    # d = (s + 1)^3; then H - 1e-30
    num = [hair, F(1, 2) + 3 * hair, F(1, 2) + 3 * hair, 1 + hair]
    return from_transfer_function([[num]], [[[1, 3, 3, 1]]], name="near miss")


def _certificate(model, band) -> dict:
    d = decide_band(model, band)
    assert d.verdict == PASSIVE
    return json.loads(json.dumps(d.certificate.to_json()))


@pytest.fixture(scope="module")
def forged_base():
    return _certificate(near_miss(HAIR), (F(0), F(2)))


def _refused(data) -> bool:
    try:
        return not check_band_fd_data(data)[0].ok
    except ValueError:
        return True


class TestForgedCertificates:
    def test_the_genuine_one_passes(self, forged_base):
        assert check_band_fd_data(copy.deepcopy(forged_base))[0].ok

    def test_dropping_inner_breakpoints(self, forged_base):
        data = copy.deepcopy(forged_base)
        factors = [f for item in data["minor_sums"] for f in item["factors"]
                   if f["breakpoints"] and len(f["breakpoints"]) > 2]
        assert factors, "the near miss needs more than one piece"
        for f in factors:
            f["breakpoints"] = [f["breakpoints"][0], f["breakpoints"][-1]]
        assert _refused(data)

    def test_widening_the_band_with_its_statement(self):
        data = _certificate(near_miss(), BAND)
        data["band"] = ["0", "1"]
        assert _refused(data)  # statement no longer matches
        data["statement"] = statement((F(0), F(1)), F(0))
        assert _refused(data)  # breakpoints end before the new edge
        for item in data["minor_sums"]:
            for f in item["factors"]:
                if f["breakpoints"]:
                    f["breakpoints"][-1] = "1"
        assert _refused(data)  # the last piece now holds the two roots

    def test_flipping_the_content(self, forged_base):
        data = copy.deepcopy(forged_base)
        c = data["minor_sums"][0]["content"]
        data["minor_sums"][0]["content"] = c[1:] if c.startswith("-") else "-" + c
        assert _refused(data)

    @pytest.mark.parametrize("value", ["1e999999999", "2/4", " 1", "0x10", 1, True, None])
    def test_non_canonical_numbers(self, forged_base, value):
        data = copy.deepcopy(forged_base)
        data["minor_sums"][0]["content"] = value
        assert _refused(data)
        data = copy.deepcopy(forged_base)
        data["meta"]["margin"] = value
        assert _refused(data)

    def test_an_even_exponent_cannot_hide_a_sign_change(self, forged_base):
        data = copy.deepcopy(forged_base)
        for f in data["minor_sums"][0]["factors"]:
            if f["exponent"] % 2:
                f["exponent"] += 1
                f["breakpoints"] = None
        assert _refused(data)  # the product no longer multiplies out

    def test_unknown_and_missing_fields(self, forged_base):
        data = copy.deepcopy(forged_base)
        data["extra"] = 1
        assert _refused(data)
        data = copy.deepcopy(forged_base)
        del data["route"]
        assert _refused(data)

    def test_route_and_model_edits(self, forged_base):
        data = copy.deepcopy(forged_base)
        data["route"] = "numerator" if data["route"] == "hermitian" else "hermitian"
        assert _refused(data)
        data = copy.deepcopy(forged_base)
        data["model"]["D"][0][0] = "1"
        assert _refused(data)  # fingerprint


class TestEdgesOnRoots:
    def test_band_edges_exactly_at_roots_of_an_odd_factor(self):
        # F = (w - 1)(w - 2): negative on (1, 2), zero at both edges, positive outside
        F_ = fmpq_poly([2, -3, 1])
        assert isinstance(nonnegative_on(F_, fmpq(1), fmpq(2)), IntervalFailure)
        assert isinstance(nonnegative_on(F_, fmpq(2), fmpq(5)), IntervalNonnegativity)
        assert isinstance(nonnegative_on(F_, fmpq(0), fmpq(1)), IntervalNonnegativity)

    def test_a_sign_change_next_to_a_root_on_the_edge(self):
        # F = w (w - 1/3) on [0, 1]: a root at the edge w1 = 0, negative on (0, 1/3)
        F_ = fmpq_poly([0, fmpq(-1, 3), 1])
        fail = nonnegative_on(F_, fmpq(0), fmpq(1))
        assert isinstance(fail, IntervalFailure)
        (w,) = list(negative_points(F_, fail, fmpq(0), fmpq(1), lambda _: False))
        assert 0 < w < fmpq(1, 3) and F_(w) < 0
        u, v = ir.refine(F_, (fmpq(0), fmpq(1)), fmpq(1, 100))  # the end 0 is a root too
        assert u == v == fmpq(1, 3) or (u < fmpq(1, 3) < v and v - u <= fmpq(1, 100))

    def test_a_root_exactly_at_a_bisection_point(self):
        # roots 1/2 and 1/4 of the unit interval: bisection midpoints
        h = fmpq_poly([-1, 2]) * fmpq_poly([-1, 4])
        assert ir.count_roots_inside(h, 0, 1) == 2
        assert isinstance(nonnegative_on(h, fmpq(0), fmpq(1)), IntervalFailure)

    def test_non_squarefree_input_is_caught_by_the_step_guard(self):
        h = fmpq_poly([-1, 1]) ** 2 * fmpq_poly([-2, 1])
        with pytest.raises(RuntimeError):
            list(ir.roots_inside(h, 0, 3, max_steps=200))

    def test_tangency_on_the_edge_of_a_margin(self):
        model = near_miss()
        assert decide_band(model, (F(1), F(2)), -HAIR).verdict == PASSIVE
        assert decide_band(model, (F(1), F(2))).verdict == NOT_PASSIVE


class TestHugeNumbers:
    def test_entries_of_two_to_the_two_hundred(self):
        big = 2**200
        model = from_transfer_function([[[1, 0]]], [[[1, big, 1]]], name="big")
        assert decide_band(model, (F(0), F(big))).verdict == PASSIVE
        neg = from_transfer_function([[[-1, 0]]], [[[1, big, 1]]], name="big neg")
        d = decide_band(neg, (F(1, 10**9), F(big)))
        assert d.verdict == NOT_PASSIVE

    def test_certificate_round_trip_of_a_big_band(self):
        big = 2**200
        model = from_transfer_function([[[1, 0]]], [[[1, big, 1]]], name="big")
        an = analyse_band(model.exact, (F(0), F(big)))
        cert = BandFdCertificate("big", "", model.exact, (F(0), F(big)), F(0), an)
        assert check_band_fd_data(json.loads(json.dumps(cert.to_json())))[0].ok
