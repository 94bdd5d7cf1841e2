"""The exact band decision (verify.passivity.check.band_fd): every band question answered.

Models are built with a known nu(w) = Re H(jw) (single port): for a Hurwitz d and an even
target e(s), n solves n(s) d(-s) + n(-s) d(s) = 2 e(s), so Re H(jw) = e(jw) / |d(jw)|^2.
e(s) = (s^2 + 2)^2 touches 0 at w = sqrt 2 (irrational), e(s) = (s^2 + 1)^2 at w = 1.
"""

from __future__ import annotations

import json
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from flint import fmpq, fmpq_poly
from gmpy2 import mpq
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from verify.cli import main
from verify.passivity.band import decide_band
from verify.passivity.check import exact as ex
from verify.passivity.check import interval_roots as ir
from verify.passivity.check import qpoly as qp
from verify.passivity.check.band_fd import (
    SCHEMA,
    BandFdCertificate,
    analyse_band,
    band_witness,
    check_band_fd_data,
)
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.frequency_domain import analyse
from verify.passivity.check.witness import hermitian_part_at
from verify.passivity.decision import NOT_PASSIVE, PASSIVE, float_views, propose, shifted
from verify.passivity.model import from_transfer_function
from verify.passivity.search.gkyp_sdp import band_certificate

F = Fraction
KS25 = "verify/data/models/reconstructed_ks2p5.toml"
ZERO = Fraction(0)


def touching(e_roots_sq: int, shift: Fraction = ZERO, name: str = "tangent"):
    """H = n / (s + 1)^3 + shift with Re H(jw) = (w^2 - r)^2 / (1 + w^2)^3 + shift."""
    s = sp.symbols("s")
    d = sp.expand((s + 1) ** 3)
    e = sp.expand((s**2 + e_roots_sq) ** 2)
    c = sp.symbols("c0:4")
    n = sum(ci * s**i for i, ci in enumerate(c))
    lhs = sp.expand(n * d.subs(s, -s) + n.subs(s, -s) * d - 2 * e)
    sol = sp.solve(sp.Poly(lhs, s).coeffs(), c, dict=True)[0]
    num = [F(str(sol[ci])) for ci in reversed(c)]  # descending powers of s
    den = [F(1), F(3), F(3), F(1)]
    num = [a + shift * b for a, b in zip(num, den, strict=True)]
    return from_transfer_function([[num]], [[den]], name=name)


def nu_exact(model, w: Fraction) -> mpq:
    """nu(w) for one port: half of H(jw) + H(jw)^H, exactly."""
    M = hermitian_part_at(model.exact, w)
    return M[0][0] / 2


def assert_witness_exact(d, model, band, margin=ZERO):
    w = Fraction(d.witness.data["omega"])
    assert band[0] <= w <= band[1]
    v = [mpq(Fraction(x)) for x in d.witness.data["a"] + d.witness.data["b"]]
    M = hermitian_part_at(shifted(model.exact, margin), w)
    value = sum(v[i] * M[i][j] * v[j] for i in range(len(v)) for j in range(len(v)))
    assert value < 0
    return w


def test_the_construction_touches_zero_where_intended():
    m1, m2 = touching(1), touching(2)
    assert nu_exact(m1, F(1)) == 0 and nu_exact(m1, F(1, 2)) > 0
    assert nu_exact(m2, F(7, 5)) > 0 and nu_exact(m2, F(3, 2)) > 0


class TestTangency:
    def test_inside_rational(self):
        model = touching(1)
        d = decide_band(model, (F(0), F(2)))
        assert d.verdict == PASSIVE
        assert d.certificate.to_json()["schema"] == SCHEMA

    @pytest.mark.parametrize("band", [(F(0), F(1)), (F(1), F(3))])
    def test_at_the_edge(self, band):
        assert decide_band(touching(1), band).verdict == PASSIVE

    def test_at_sqrt_two_inside(self):
        d = decide_band(touching(2), (F(0), F(3, 2)))
        assert d.verdict == PASSIVE and d.certificate is not None

    def test_minus_1e30_at_sqrt_two_is_refuted_inside_the_band(self):
        model = touching(2, F(-1, 10**30))
        band = (F(0), F(3, 2))
        d = decide_band(model, band)
        assert d.verdict == NOT_PASSIVE
        w = assert_witness_exact(d, model, band)
        assert abs(w - F(14142135623730950488, 10**19)) < F(1, 10**12)

    def test_plus_1e30_at_sqrt_two_is_passive(self):
        d = decide_band(touching(2, F(1, 10**30)), (F(0), F(3, 2)))
        assert d.verdict == PASSIVE

    def test_margins_of_plus_and_minus_1e30(self):
        model, band = touching(2), (F(0), F(3, 2))
        assert decide_band(model, band, F(-1, 10**30)).verdict == PASSIVE
        d = decide_band(model, band, F(1, 10**30))
        assert d.verdict == NOT_PASSIVE
        assert_witness_exact(d, model, band, F(1, 10**30))

    def test_a_band_that_misses_the_tangency_by_a_hair(self):
        model = touching(1, F(-1, 10**30))  # nu < 0 only within ~1e-15 of w = 1
        assert decide_band(model, (F(0), F(1) - F(1, 10**12))).verdict == PASSIVE
        d = decide_band(model, (F(0), F(1)))
        assert d.verdict == NOT_PASSIVE
        assert_witness_exact(d, model, (F(0), F(1)))


class TestPoles:
    def test_pole_at_the_upper_edge(self):
        # 1/(s^2 + 1): Re H(jw) = 1 / (1 - w^2), +infinity below the pole, negative above
        model = from_transfer_function([[[1]]], [[[1, 0, 1]]], name="1/(s^2+1)")
        d = decide_band(model, (F(0), F(1)))
        assert d.verdict == PASSIVE and "poles at ω ≈ 1" in d.reason
        d = decide_band(model, (F(1), F(2)))
        assert d.verdict == NOT_PASSIVE
        assert_witness_exact(d, model, (F(1), F(2)))

    def test_lossless_pole_inside_and_at_edges(self):
        model = from_transfer_function([[[1, 0]]], [[[1, 0, 1]]], name="s/(s^2+1)")
        for band in ((F(0), F(1)), (F(1), F(2)), (F(1, 2), F(3))):
            d = decide_band(model, band)
            assert d.verdict == PASSIVE and "poles at ω ≈ 1" in d.reason

    def test_two_port_with_a_non_hermitian_residue_at_the_edge(self):
        # H = [[0, 1/(s^2+1)], [0, 0]] + I/1000: near w = 1 the off-diagonal blows up and
        # H + H^H is indefinite on both sides of the pole
        num = [[[F(1, 1000), 0, F(1, 1000)], [1]], [[0], [F(1, 1000), 0, F(1, 1000)]]]
        den = [[[1, 0, 1], [1, 0, 1]], [[1], [1, 0, 1]]]
        model = from_transfer_function(num, den, name="skew pole")
        d = decide_band(model, (F(0), F(1)))
        assert d.verdict == NOT_PASSIVE
        assert_witness_exact(d, model, (F(0), F(1)))


class TestBands:
    def test_tiny_band_far_below_a_dip(self):
        # H = 1 - 2 (s/10) / (s^2 + s/10 + 100): H(10j) = -1, H(0) = 1
        model = from_transfer_function([[[1, F(-1, 10), 100]]], [[[1, F(1, 10), 100]]],
                                       name="dip at 10")
        assert decide_band(model, (F(0), F(1, 10**12))).verdict == PASSIVE
        d = decide_band(model, (F(9), F(11)))
        assert d.verdict == NOT_PASSIVE
        assert_witness_exact(d, model, (F(9), F(11)))

    def test_poles_twelve_decades_apart(self):
        # H = (s + 1e12 + 1e-4) / ((s + 1e12)(s + 1e-4)) = 1/(s + 1e-4) + 1/(s + 1e12)
        den = [1, F(10**12) + F(1, 10**4), 10**8]
        model = from_transfer_function([[[1, F(10**12) + F(1, 10**4)]]], [[den]],
                                       name="decades")
        for band in ((F(0), F(1)), (F(0), F(10**12))):
            assert decide_band(model, band).verdict == PASSIVE
        neg = from_transfer_function([[[-1, 0]]], [[den]], name="decades, negative")
        d = decide_band(neg, (F(1, 10**6), F(1)))
        assert d.verdict == NOT_PASSIVE
        assert_witness_exact(d, neg, (F(1, 10**6), F(1)))

    def test_band_with_a_margin_equal_to_nu_at_the_edge(self):
        from verify.passivity.io.model_file import load_model

        ks25 = load_model(KS25)
        edge = F(14, 37)  # nu(3/2) = (2 - 9/8) / ((2 - 9/4)^2 + 9/4), the band's minimum
        assert nu_exact(ks25, F(3, 2)) == mpq(14, 37)
        assert decide_band(ks25, (F(0), F(3, 2)), edge).verdict == PASSIVE
        d = decide_band(ks25, (F(0), F(3, 2)), edge + F(1, 10**40))
        assert d.verdict == NOT_PASSIVE
        assert_witness_exact(d, ks25, (F(0), F(3, 2)), edge + F(1, 10**40))

    def test_gate_writes_and_rechecks_the_exact_band_certificate(self, tmp_path, capsys):
        certs = tmp_path / "certs"
        assert main(["gate", KS25, "--band", "0:2", "--certificates", str(certs)]) == 0
        (path,) = certs.glob("*.json")
        data = json.loads(path.read_text())
        assert data["schema"] == SCHEMA and data["band"] == ["0", "2"]
        assert check_band_fd_data(data)[0].ok
        capsys.readouterr()
        assert main(["certificates", "check", str(certs)]) == 0
        assert SCHEMA not in capsys.readouterr().out.replace(path.name, "")  # no refusal
        before = path.read_bytes()  # byte-reproducible: a rerun keeps the file
        assert main(["gate", KS25, "--band", "0:2", "--certificates", str(certs)]) == 0
        assert path.read_bytes() == before

    def test_gate_with_margin_and_band(self, tmp_path):
        certs = tmp_path / "certs"
        assert main(["gate", KS25, "--band", "0:1.5", "--margin", "14/37",
                     "--certificates", str(certs)]) == 0
        assert main(["certificates", "check", str(certs)]) == 0
        assert main(["gate", KS25, "--band", "0:1.5", "--margin", "0.3784",
                     "--certificates", str(certs)]) == 1


class TestRootCounting:
    def test_descartes_bisection_agrees_with_sturm(self):
        import random

        rng = random.Random(7)
        for _ in range(200):
            p = fmpq_poly([rng.randint(-6, 6) for _ in range(rng.randint(2, 9))])
            if rng.random() < 0.4:
                p *= fmpq_poly([-2, 3]) * fmpq_poly([-1, 1])
            if p.degree() < 1:
                continue
            h = qp.squarefree_part(p)
            a = fmpq(rng.randint(-8, 8), rng.randint(1, 3))
            b = a + fmpq(rng.randint(1, 9), rng.randint(1, 3))
            sturm = qp.count_roots(h, a, b) - (h(b) == 0)
            assert ir.count_roots_inside(h, a, b) == sturm
            found = ir.first_root_inside(h, a, b)
            assert (found.root is None) == (sturm == 0)
            if found.root is None:
                assert ir.check_no_root(h, a, b, found.breakpoints) is None

    def test_clustered_roots_are_separated(self):
        eps = fmpq(1, 10**40)
        h = fmpq_poly([-1, 1]) * fmpq_poly([-(1 + eps), 1]) * fmpq_poly([1, 0, 1])
        assert ir.count_roots_inside(h, 0, 2) == 2
        assert ir.count_roots_inside(h, 1, 2) == 1
        assert ir.count_roots_inside(h, 0, 2, closed=True) == 2
        assert ir.count_roots_inside(h, 1, 1 + eps, closed=True) == 2


# cross-checks on random models: the exact band route against exact point evaluations,
# the full-axis route and the GKYP route ------------------------------------------------

small = st.integers(-3, 3)
rational_w = st.builds(lambda p, q: F(p, q), st.integers(0, 40), st.integers(1, 8))


@st.composite
def models_and_bands(draw):
    n, m = draw(st.integers(1, 3)), draw(st.integers(1, 2))
    A = [[draw(small) for _ in range(n)] for _ in range(n)]
    B = [[draw(small) for _ in range(m)] for _ in range(n)]
    C = [[draw(small) for _ in range(n)] for _ in range(m)]
    D = [[draw(small) for _ in range(m)] for _ in range(m)]
    w1, w2 = draw(rational_w), draw(rational_w)
    if w1 == w2:
        w2 = w1 + F(1, 3)
    return ExactModel(*(ex.to_rational(np.array(x, dtype=float)) for x in (A, B, C, D))), \
        (min(w1, w2), max(w1, w2))


def _psd_at(model: ExactModel, w: Fraction) -> bool | None:
    M = hermitian_part_at(model, w)
    return None if M is None else ex.psd_ldl(M).ok


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(models_and_bands())
def test_exact_band_agrees_with_exact_points_and_the_full_axis(data):
    model, band = data
    an = analyse_band(model, band)
    inner = [band[0] + (band[1] - band[0]) * F(i, 8) for i in range(9)]
    if any(_psd_at(model, w) is False for w in inner):
        assert not an.passive
    if an.passive:
        cert = BandFdCertificate("m", "", model, band, F(0), an)
        data = json.loads(json.dumps(cert.to_json()))
        result, _, _ = check_band_fd_data(data)
        assert result.ok, result.reason
    else:
        k, fail = an.failure
        w = band_witness(model, an.polys, k, fail, an.band)
        assert w.kind == "frequency"
        omega = Fraction(w.data["omega"])
        assert band[0] <= omega <= band[1] and _psd_at(model, omega) is False
    if analyse(model, certify=False).verdict == "passive":
        assert an.passive


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(models_and_bands())
def test_exact_band_agrees_with_the_gkyp_route(data):
    model, band = data
    A, B, C, D = float_views(model)
    found = propose(band_certificate, model, A, B, C, D, band)
    an = analyse_band(model, band)
    if found is not None:  # an exactly checked GKYP certificate: passive on the band
        assert an.passive
