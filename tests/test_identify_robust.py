"""The robust verdict over a confidence region: interval forms, proofs, refutations."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from gmpy2 import mpq
from identify_models import biproper_model, paper_model

from verify.artefacts.atomic import write_atomic
from verify.certificates.registry import check_stored_certificate
from verify.identify.estimate.structure import Structure
from verify.identify.robust import band_certificate as rc
from verify.identify.robust.verdict import largest_band, robust_verdict
from verify.passivity.check import robust_band as rb


def _direct(theta, shape: rb.Shape, w: float):
    """N_1, N_2, det by complex floating point at one frequency."""
    out = []
    for i in range(2):
        block = theta[i * shape.per_element:(i + 1) * shape.per_element]
        num, den = block[: shape.zeros + 1], np.r_[1.0, block[shape.zeros + 1:]]
        n, d = np.polyval(num, 1j * w), np.polyval(den, 1j * w)
        out.append(((n * np.conj(d)).real, abs(d) ** 2))
    c = theta[-2] + theta[-1]
    return out[0][0], out[1][0], 4 * out[0][0] * out[1][0] - c * c * out[0][1] * out[1][1]


@pytest.mark.parametrize("zeros,poles", [(1, 2), (0, 1), (1, 1), (2, 3), (3, 3)])
def test_interval_forms_enclose_the_conditions(zeros, poles):
    shape = rb.Shape(zeros, poles)
    rng = np.random.default_rng(zeros * 10 + poles)
    for _ in range(20):
        theta = rng.normal(size=shape.parameters)
        phi = [*theta[:-2], theta[-2] + theta[-1]]
        width = rng.uniform(0, 0.1, size=len(phi) + 1)
        w = abs(rng.normal()) * 3
        box = [(mpq(float(p)) - mpq(float(h)), mpq(float(p)) + mpq(float(h)))
               for p, h in zip(phi, width[:-1], strict=True)]
        x = mpq(float(w * w))
        t = (x, x + mpq(float(width[-1])))
        bounds = rb.leaf_bounds(box, t, "x", shape, rb.ExactOps)
        for _ in range(10):  # random points of the box lie inside the enclosures
            u = rng.uniform(size=len(phi) + 1)
            point = [float(lo + (hi - lo) * mpq(float(s))) for (lo, hi), s
                     in zip([*box, t], u, strict=True)]
            th = np.array([*point[:-2], point[-2], 0.0])
            values = _direct(th, shape, np.sqrt(point[-1]))
            for (lo, hi), v in zip(bounds, values, strict=True):
                scale = 1e-9 * (1 + abs(v))
                assert float(lo) - scale <= v <= float(hi) + scale


def test_y_piece_is_the_reversed_polynomial():
    shape = rb.Shape(1, 2)
    theta = [mpq(6, 5), mpq(4, 5), mpq(2), mpq(3, 2), mpq(11, 10), mpq(9, 10), mpq(21, 10),
             mpq(7, 5), mpq(1, 50)]
    box = [(t, t) for t in theta]
    x = mpq(9, 2)
    N1, N2, det = rb.leaf_bounds(box, (x, x), "x", shape, rb.ExactOps)
    M1, M2, dety = rb.leaf_bounds(box, (1 / x, 1 / x), "y", shape, rb.ExactOps)
    assert M1[0] == N1[0] / x and M2[0] == N2[0] / x  # y^1 N(1/y)
    assert dety[0] == det[0] / x**4  # y^(2 poles) det(1/y)


def test_routh_and_kharitonov():
    q = [mpq(v) for v in (6, 11, 6, 1)]  # (s+1)(s+2)(s+3)
    assert rb.hurwitz(q)
    assert not rb.hurwitz([mpq(v) for v in (1, 1, 1, 1)])  # roots on the axis
    assert not rb.hurwitz([mpq(v) for v in (-1, 3, 1)])
    box = [(mpq(1), mpq(2)), (mpq(2), mpq(3)), (mpq(1), mpq(1))]
    assert rb.kharitonov_stable(box)
    assert not rb.kharitonov_stable([(mpq(-1, 10), mpq(2)), (mpq(2), mpq(3)), (mpq(1),
                                                                              mpq(1))])


def test_band_proof_writes_a_certificate_that_checks(tmp_path):
    f = paper_model(tmp_path)
    band = (Fraction(0), Fraction(5))
    r = robust_verdict(f.region(), f.structure, band, name=f.model.name,
                       source=str(tmp_path / "model.toml"))
    assert r.verdict == "passive" and r.certificate is not None
    path = tmp_path / rc.file_name(f.model.name, band, r.certificate["fingerprint"])
    write_atomic(path, rc.dumps(r.certificate))
    check = check_stored_certificate(path)
    assert check.ok, check.reason
    assert "centre = its written coefficients" in check.reason
    again = robust_verdict(f.region(), f.structure, band, name=f.model.name,
                           source=str(tmp_path / "model.toml"))
    assert rc.dumps(again.certificate) == path.read_text()  # byte-reproducible


def test_band_beyond_the_nominal_crossing_with_a_straddling_region_is_inconclusive(
        tmp_path):
    """On [0, 20] the centre fails beyond ~12 rad/s, but the region holds c12 + c21 = 0,
    where the model is passive at every frequency: the data cannot decide. The failing
    model is reported with its exact witness; the verdict is not 'not passive'."""
    f = paper_model(tmp_path)
    region = f.region()
    r = robust_verdict(region, f.structure, (Fraction(0), Fraction(20)),
                       name="m", source="")
    assert r.verdict == "inconclusive" and r.witness is not None
    assert region.contains(r.theta) and r.distance <= region.chi2
    assert 0 <= Fraction(r.witness.data["omega"]) <= 20
    assert r.refutation is None and r.certificate is None
    assert "cannot decide" in r.reason


def test_all_frequencies_for_the_paper_class_and_a_band_is_given(tmp_path):
    """c12 + c21 != 0 and Re h_i -> 0: the centre is not passive at high frequency, but
    this region holds c12 + c21 = 0 (inconclusive over all frequencies); on a band
    [0, w_max] every model of it is passive."""
    f = paper_model(tmp_path)
    region = f.region()
    r = robust_verdict(region, f.structure, None, name="m", source="")
    assert r.verdict == "inconclusive" and region.contains(r.theta)
    # both sides exact: a passive model of the region with c12 = -c21, by the gate
    assert r.straddles and region.contains(r.passive_theta)
    assert r.passive_theta[-2] == -r.passive_theta[-1]
    from verify.passivity.decision import decide
    from verify.passivity.model import from_transfer_function

    num, den = f.structure.transfer_matrix(r.passive_theta)
    assert decide(from_transfer_function(num, den)).verdict == "passive"
    found = largest_band(region, f.structure, Fraction(0), 100.0, name="m", source="",
                         steps=4, max_boxes=8000)
    assert found.w_max is not None and 2 < found.w_max < 13
    assert found.certificate is not None
    assert found.certificate["band"] == ["0", str(mpq(found.w_max))]


def test_all_frequency_proof_with_kharitonov_for_a_biproper_structure(tmp_path):
    f = biproper_model(tmp_path)
    r = robust_verdict(f.region(), f.structure, None, name=f.model.name,
                       source=str(tmp_path / "model.toml"))
    assert r.verdict == "passive", r.reason
    pieces = r.certificate["pieces"]
    assert [p["variable"] for p in pieces] == ["x", "y"]
    path = tmp_path / rc.file_name(f.model.name, None, r.certificate["fingerprint"])
    write_atomic(path, rc.dumps(r.certificate))
    assert check_stored_certificate(path).ok


def test_unsupported_structure_is_inconclusive_with_the_reason(tmp_path):
    f = paper_model(tmp_path)
    r = robust_verdict(f.region(), Structure.order(3), (Fraction(0), Fraction(1)),
                       name="m", source="")
    assert r.verdict == "inconclusive" and "not supported" in r.reason


def test_budget_exhaustion_is_inconclusive_not_passive(tmp_path):
    """[0, 5] is proved with the default budget; with 3 boxes it is inconclusive, and
    the reason says the centre is passive (no failing model: not a straddle)."""
    f = paper_model(tmp_path)
    r = robust_verdict(f.region(), f.structure, (Fraction(0), Fraction(5)), name="m",
                       source="", max_boxes=3)
    assert r.verdict == "inconclusive" and "budget" in r.reason
    assert r.passive_theta is not None and r.theta is None and not r.straddles


def test_first_order_bound_holds_on_the_box_part_of_the_ellipsoid():
    """Sampled points of (box ∩ ellipsoid) x t never fall below the first-order bound."""
    shape = rb.Shape(1, 2)
    theta = np.array([1.2, 0.8, 2.0, 1.5, 1.1, 0.9, 2.1, 1.4, 0.06, -0.04])
    rng = np.random.default_rng(3)
    cov = np.diag((0.02 * np.abs(theta)) ** 2)
    cov[-2:, -2:] = np.diag([0.005**2, 0.005**2])
    phi_c = [*theta[:-2], theta[-2] + theta[-1]]
    from verify.identify.model.region import make_region

    region = make_region([Fraction(str(x)) for x in theta], cov, Fraction(19, 20))
    pc, cov_phi = rb.reduce_region(region.center, region.covariance)
    S = np.linalg.inv(np.array([[float(x) for x in row] for row in cov_phi]))
    chi2 = float(region.chi2)
    for _ in range(6):
        offset = rng.normal(size=len(phi_c)) * 0.02 * np.abs(phi_c)
        half = 0.01 * np.abs(phi_c)
        box = [(mpq(float(c + o - h)), mpq(float(c + o + h)))
               for c, o, h in zip(phi_c, offset, half, strict=True)]
        x0 = float(rng.uniform(0, 30))
        t = (mpq(x0), mpq(x0 + 1))
        centre, parts = rb.linear_parts(box, t, "x", shape)
        lows = []
        for value, grad in parts:
            m = rb.gradient_midpoints(grad)
            quad = sum(m[i] * cov_phi[i][j] * m[j] for i in range(9) for j in range(9))
            s = mpq(float(np.sqrt(float(region.chi2 * quad)))) * mpq(1001, 1000)
            lows.append(float(rb.linear_bound(box, centre, value, grad, pc, s)))
        for _ in range(200):
            point = np.array([float(lo) + float(hi - lo) * u for (lo, hi), u
                              in zip(box, rng.uniform(size=9), strict=True)])
            d = point - np.array([float(x) for x in pc])
            if d @ S @ d > chi2:
                continue  # the bound is about the ellipsoid's part of the box only
            w = np.sqrt(x0 + rng.uniform())
            values = _direct(np.r_[point[:-1], point[-1], 0.0], shape, w)
            for low, v in zip(lows, values, strict=True):
                assert v >= low - 1e-9 * (1 + abs(v))
