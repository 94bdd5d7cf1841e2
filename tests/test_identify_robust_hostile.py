"""Hostile robust certificates and regions: each must be refused or refuted, never passed.

A forger who edits a certificate can also recompute its fingerprint, statement and file
name (:func:`_resign`), so each case below is refused by the check it targets, not only
by the fingerprint.
"""

from __future__ import annotations

import copy
import json
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from gmpy2 import mpq
from identify_models import PAPER_THETA, correlated_covariance, paper_model

from verify.artefacts.atomic import write_atomic
from verify.certificates.registry import check_stored_certificate
from verify.identify.estimate.structure import Structure
from verify.identify.model.model_writer import write_identified_model
from verify.identify.robust import band_certificate as rc
from verify.identify.robust.verdict import robust_verdict
from verify.passivity.check import robust_band as rb
from verify.passivity.check.realization import minimal_part
from verify.passivity.check.witness import frequency_witness_at
from verify.passivity.model import from_transfer_function

BAND = (Fraction(0), Fraction(5))


@pytest.fixture(scope="module")
def proved(tmp_path_factory):
    """(directory, certificate data) of a robust band proof bound to its model file."""
    d = tmp_path_factory.mktemp("robust")
    f = paper_model(d)
    r = robust_verdict(f.region(), f.structure, BAND, name=f.model.name,
                       source=str(d / "model.toml"))
    assert r.verdict == "passive"
    return d, r.certificate


def _resign(data: dict) -> dict:
    """Recompute what a forger can recompute: statement, fingerprint."""
    band = None if data["band"] is None else tuple(Fraction(x) for x in data["band"])
    data["statement"] = rc.statement(data["structure"], Fraction(data["region"]["level"]),
                                     band)
    data["fingerprint"] = rc.fingerprint(data["structure"], data["parameters"],
                                         data["region"], data["band"])
    return data


def _write(directory: Path, data: dict, name: str | None = None) -> Path:
    band = None if data["band"] is None else tuple(Fraction(x) for x in data["band"])
    path = directory / (name or rc.file_name(data["name"], band, data["fingerprint"]))
    write_atomic(path, rc.dumps(data))
    return path


def _detached(data: dict) -> dict:
    """The same certificate with no source file (the checks on the stored region alone)."""
    out = copy.deepcopy(data)
    out["source"] = ""
    return out


def test_the_untouched_certificate_passes(proved, tmp_path):
    d, data = proved
    assert check_stored_certificate(_write(d, data)).ok
    assert check_stored_certificate(_write(tmp_path, _detached(data)),
                                    allow_unbound=True).ok  # no source file: unbound


def test_a_removed_leaf_is_refused(proved, tmp_path):
    _, data = proved
    bad = _detached(data)
    tree = bad["pieces"][0]["tree"]
    last = max(i for i, node in enumerate(tree) if isinstance(node, list))
    del tree[last]
    bad["leaves"] -= 1
    check = check_stored_certificate(_write(tmp_path, bad))
    assert not check.ok and "missing" in check.reason


def test_an_extra_node_is_refused(proved, tmp_path):
    _, data = proved
    bad = _detached(data)
    bad["pieces"][0]["tree"].append(["positive", "1", "1", "1"])
    check = check_stored_certificate(_write(tmp_path, bad))
    assert not check.ok and "extra" in check.reason


def test_a_widened_region_is_refused(proved, tmp_path):
    """Covariance scaled up (the region grows): the stored enclosure no longer covers it."""
    _, data = proved
    bad = _detached(data)
    reg = bad["region"]
    reg["covariance"] = [[str(mpq(v) * 4) for v in row] for row in reg["covariance"]]
    check = check_stored_certificate(_write(tmp_path, _resign(bad)))
    assert not check.ok and "does not enclose" in check.reason


def test_a_widened_enclosure_with_the_old_leaves_is_refused(proved, tmp_path):
    """Widening the box too: the old tree's leaves now cover other boxes and fail."""
    _, data = proved
    bad = _detached(data)
    reg = bad["region"]
    reg["covariance"] = [[str(mpq(v) * 400) for v in row] for row in reg["covariance"]]
    bad["enclosure"] = [str(mpq(r) * 20) for r in bad["enclosure"]]
    check = check_stored_certificate(_write(tmp_path, _resign(bad)))
    assert not check.ok and "leaf" in check.reason


def test_a_shrunk_chi2_is_refused(proved, tmp_path):
    """A smaller region labelled 95 %: chi2 is not the level's quantile."""
    _, data = proved
    bad = _detached(data)
    bad["region"]["chi2"] = str(mpq(bad["region"]["chi2"]) / 4)
    check = check_stored_certificate(_write(tmp_path, _resign(bad)))
    assert not check.ok and "quantile" in check.reason


def test_a_tampered_bound_is_refused(proved, tmp_path):
    _, data = proved
    bad = _detached(data)
    tree = bad["pieces"][0]["tree"]
    k = next(i for i, node in enumerate(tree) if isinstance(node, list)
             and node[0] == "positive")
    tree[k][3] = str(mpq(tree[k][3]) * 10**6)  # claims more than the leaf shows
    check = check_stored_certificate(_write(tmp_path, bad))
    assert not check.ok and "below the claimed" in check.reason


def test_a_zero_claimed_bound_is_refused(proved, tmp_path):
    _, data = proved
    bad = _detached(data)
    tree = bad["pieces"][0]["tree"]
    k = next(i for i, node in enumerate(tree) if isinstance(node, list))
    tree[k] = ["positive", "0", "0", "0"]
    assert not check_stored_certificate(_write(tmp_path, bad)).ok


def test_a_larger_band_with_the_old_tree_is_refused(proved, tmp_path):
    _, data = proved
    bad = _detached(data)
    bad["band"] = ["0", "50"]
    check = check_stored_certificate(_write(tmp_path, _resign(bad)))
    assert not check.ok and "as the band asks" in check.reason
    bad["pieces"][0]["interval"] = ["0", "2500"]  # and the piece: leaves then fail
    check = check_stored_certificate(_write(tmp_path, _resign(bad)))
    assert not check.ok and "leaf" in check.reason


def test_a_centre_that_differs_from_the_model_file_is_refused(proved):
    d, data = proved
    bad = copy.deepcopy(data)
    center = bad["region"]["center"]
    center[-2] = str(mpq(center[-2]) - mpq(1, 100))  # c12 moved towards skew symmetry
    check = check_stored_certificate(_write(d, _resign(bad)))
    assert not check.ok and "centre" in check.reason


def test_a_covariance_that_differs_from_the_model_file_is_refused(proved):
    d, data = proved
    bad = copy.deepcopy(data)
    cov = bad["region"]["covariance"]
    cov[0][0] = str(mpq(cov[0][0]) / 2)  # a tighter region than the file states
    check = check_stored_certificate(_write(d, _resign(bad)))
    assert not check.ok and "covariance differs" in check.reason


def test_a_wrong_file_name_and_fingerprint_are_refused(proved, tmp_path):
    _, data = proved
    good = _detached(data)
    assert not check_stored_certificate(_write(tmp_path, good, "renamed.json")).ok
    bad = copy.deepcopy(good)
    bad["fingerprint"] = "0" * 64
    assert not check_stored_certificate(_write(tmp_path, bad, rc.file_name(
        bad["name"], BAND, good["fingerprint"]))).ok


def test_a_non_positive_definite_covariance_is_refused(proved, tmp_path):
    _, data = proved
    bad = _detached(data)
    bad["region"]["covariance"][0][0] = "0"
    check = check_stored_certificate(_write(tmp_path, _resign(bad)))
    assert not check.ok and "positive definite" in check.reason


def test_malformed_trees_are_refused(proved, tmp_path):
    _, data = proved
    for tree in ([99], [True], [["maybe"]], ["0"], [0] * (rb.MAX_DEPTH + 2)):
        bad = _detached(data)
        bad["pieces"][0]["tree"] = tree
        assert not check_stored_certificate(_write(tmp_path, bad)).ok, tree


def test_duplicate_keys_are_refused(proved, tmp_path):
    _, data = proved
    good = _detached(data)
    path = _write(tmp_path, good)
    text = path.read_text()
    path.write_text(text.replace('"leaves":', '"leaves":1,"leaves":', 1))
    assert not check_stored_certificate(path).ok


def test_one_failing_model_inside_the_region_is_never_not_passive(tmp_path):
    """The nominal model is passive on [0, 8] rad/s, but its region is wide enough in
    c12 + c21 to hold models that are not: the region straddles, and the verdict is
    inconclusive with both sides exact (a failing model with its witness, the passive
    centre with the gate's certificate); no refutation certificate."""
    theta = list(PAPER_THETA)
    cov = np.diag((0.01 * np.abs(np.asarray(theta))) ** 2)
    cov[-2, -2] = cov[-1, -1] = 0.03**2
    f = write_identified_model(tmp_path / "wide.toml", name="wide",
                               structure=Structure.paper(), theta=theta, covariance=cov)
    region = f.region()
    band = (Fraction(0), Fraction(8))
    r = robust_verdict(region, f.structure, band, name="wide", source="")
    assert r.verdict == "inconclusive" and r.straddles and r.refutation is None
    assert r.distance > 0 and region.contains(r.theta)  # not the centre: inside, exactly
    num, den = f.structure.transfer_matrix(r.theta)
    em = minimal_part(from_transfer_function(num, den).exact).model
    w = Fraction(r.witness.data["omega"])
    assert 0 <= w <= 8 and frequency_witness_at(em, w) is not None
    assert r.passive_theta == list(region.center)
    assert "straddles" in r.reason
    assert json.dumps(r.to_json())  # the JSON summary is serialisable


@pytest.fixture(scope="module")
def with_linear_leaves(tmp_path_factory):
    """A proof using first-order leaves (a small region near its largest band)."""
    d = tmp_path_factory.mktemp("linear")
    theta = list(PAPER_THETA)
    cov = correlated_covariance(theta, relative=0.005, coupling=0.005 / 4)
    f = write_identified_model(d / "model.toml", name="small", structure=Structure.paper(),
                               theta=theta, covariance=cov)
    band = (Fraction(0), Fraction(103, 10))
    r = robust_verdict(f.region(), f.structure, band, name="small", source="")
    assert r.verdict == "passive"
    assert any(isinstance(n, list) and n[0] == "linear"
               for n in r.certificate["pieces"][0]["tree"])
    return r.certificate


@pytest.mark.parametrize("position,factor,needle", [
    (4, mpq(1, 100), "sqrt(chi2"),  # a square-root bound too small
    (1, mpq(10**6), "first-order bound"),  # a claimed bound too large
])
def test_tampered_first_order_leaves_are_refused(with_linear_leaves, tmp_path, position,
                                                 factor, needle):
    good = _detached(with_linear_leaves)
    assert check_stored_certificate(_write(tmp_path, good), allow_unbound=True).ok
    bad = copy.deepcopy(good)
    tree = bad["pieces"][0]["tree"]
    k = next(i for i, n in enumerate(tree) if isinstance(n, list) and n[0] == "linear")
    tree[k][position] = str(mpq(tree[k][position]) * factor)
    check = check_stored_certificate(_write(tmp_path, bad))
    assert not check.ok and needle in check.reason
