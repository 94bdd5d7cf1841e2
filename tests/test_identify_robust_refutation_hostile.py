"""Hostile refutation certificates and confidence labels: each is refused, never passed.

A forger who edits a certificate can also recompute its fingerprint, statement and file
name (:func:`_resign`), so each case is refused by the check it targets. Grouped by class:
the tree, the claim (frequency, direction, band), the region and its confidence label
(exact chi-square level, for both robust certificate kinds), the binding to the model file.
"""

from __future__ import annotations

import copy
from fractions import Fraction
from pathlib import Path

import pytest
from gmpy2 import mpq
from identify_models import paper_model
from test_identify_robust_refutation import COUPLED

from verify.artefacts.atomic import write_atomic
from verify.certificates.registry import check_stored_certificate
from verify.identify.robust import band_certificate as rc
from verify.identify.robust import refutation_certificate as rfc
from verify.identify.robust.verdict import robust_verdict

BAND = (Fraction(0), Fraction(20))


@pytest.fixture(scope="module")
def refuted(tmp_path_factory):
    """(directory, certificate) of a region-wide refutation bound to its model file."""
    d = tmp_path_factory.mktemp("refuted")
    f = paper_model(d, theta=COUPLED)
    r = robust_verdict(f.region(), f.structure, BAND, name=f.model.name,
                       source=str(d / "model.toml"))
    assert r.verdict == "not passive" and r.refutation is not None
    return d, r.refutation


@pytest.fixture(scope="module")
def proved(tmp_path_factory):
    """(directory, certificate) of a robust band proof bound to its model file."""
    d = tmp_path_factory.mktemp("proved")
    f = paper_model(d)
    r = robust_verdict(f.region(), f.structure, (Fraction(0), Fraction(5)),
                       name=f.model.name, source=str(d / "model.toml"))
    assert r.verdict == "passive"
    return d, r.certificate


def _resign(data: dict) -> dict:
    band = None if data["band"] is None else tuple(Fraction(x) for x in data["band"])
    level = Fraction(data["region"]["level"])
    w = mpq(data["frequency"])
    v = (mpq(data["direction"][0]), mpq(data["direction"][1]))
    data["statement"] = rfc.statement(data["structure"], level, band, w, v)
    data["fingerprint"] = rfc.fingerprint(data["structure"], data["parameters"],
                                          data["region"], data["band"], data["frequency"],
                                          data["direction"])
    return data


def _write(directory: Path, data: dict) -> Path:
    path = directory / rfc.file_name(data["name"], Fraction(data["frequency"]),
                                     data["fingerprint"])
    write_atomic(path, rfc.dumps(data))
    return path


def _detached(data: dict) -> dict:
    out = copy.deepcopy(data)
    out["source"] = ""
    return out


def _check(directory: Path, data: dict, *, allow_unbound: bool = False):
    return check_stored_certificate(_write(directory, data), allow_unbound=allow_unbound)


# ------------------------------------------------------------------ untouched


def test_the_untouched_refutation_passes_bound_and_detached(refuted, tmp_path):
    d, data = refuted
    assert _check(d, data).ok
    detached = _check(tmp_path, _detached(data))  # no source file: its labels are unchecked
    assert not detached.ok and detached.status == "unbound" and "name" in detached.unchecked
    assert _check(tmp_path, _detached(data), allow_unbound=True).ok


# ------------------------------------------------------------------ the tree


def test_a_positive_claimed_bound_is_refused(refuted, tmp_path):
    _, data = refuted
    bad = _detached(data)
    k = next(i for i, n in enumerate(bad["tree"]) if isinstance(n, list))
    bad["tree"][k] = ["negative", "1"]
    check = _check(tmp_path, bad)
    assert not check.ok and "not < 0" in check.reason


def test_a_claimed_bound_below_the_exact_enclosure_is_refused(refuted, tmp_path):
    _, data = refuted
    bad = _detached(data)
    k = next(i for i, n in enumerate(bad["tree"]) if isinstance(n, list))
    assert bad["tree"][k][0] == "negative"
    bad["tree"][k] = ["negative", str(mpq(bad["tree"][k][1]) * 10**9)]
    check = _check(tmp_path, bad)
    assert not check.ok and "above the claimed" in check.reason


def test_an_outside_leaf_for_a_box_inside_the_region_is_refused(refuted, tmp_path):
    _, data = refuted
    bad = _detached(data)
    k = next(i for i, n in enumerate(bad["tree"]) if isinstance(n, list))
    centre = bad["region"]["center"]
    bad["tree"][k] = ["outside", [*centre[:-2], str(mpq(centre[-2]) + mpq(centre[-1]))]]
    check = _check(tmp_path, bad)
    assert not check.ok and "does not exceed chi2" in check.reason


def test_a_missing_or_extra_node_is_refused(refuted, tmp_path):
    _, data = refuted
    extra = _detached(data)
    extra["tree"].append(["negative", "-1"])
    check = _check(tmp_path, extra)
    assert not check.ok and "extra" in check.reason
    split = _detached(data)
    split["tree"] = [0, *split["tree"]]  # a split with only one child
    check = _check(tmp_path, split)
    assert not check.ok and "missing" in check.reason


def test_a_wrong_leaf_count_and_malformed_leaves_are_refused(refuted, tmp_path):
    _, data = refuted
    bad = _detached(data)
    bad["leaves"] += 1
    assert not _check(tmp_path, bad).ok
    for leaf in (["negative"], ["negative", -1], ["positive", "1", "1", "1"], "negative",
                 ["linear", "-1"], ["negative", "-1e3"]):
        bad = _detached(data)
        bad["tree"] = [leaf]
        check = _check(tmp_path, bad)
        assert not check.ok and ("malformed" in check.reason or "neither" in check.reason)


# ------------------------------------------------------------------ the claim


def test_a_frequency_moved_where_models_pass_is_refused(refuted, tmp_path):
    """At w = 1/10 rad/s every model of this region is passive: the old tree fails."""
    _, data = refuted
    bad = _detached(data)
    bad["frequency"] = "1/10"
    check = _check(tmp_path, _resign(bad))
    assert not check.ok and "does not refute" in check.reason


def test_a_frequency_outside_the_band_is_refused(refuted, tmp_path):
    _, data = refuted
    bad = _detached(data)
    bad["band"] = ["0", "1"]
    check = _check(tmp_path, _resign(bad))
    assert not check.ok and "not in the band" in check.reason


def test_a_flipped_or_zero_direction_is_refused(refuted, tmp_path):
    _, data = refuted
    flipped = _detached(data)
    flipped["direction"] = [flipped["direction"][0], str(-mpq(flipped["direction"][1]))]
    check = _check(tmp_path, _resign(flipped))
    assert not check.ok and "does not refute" in check.reason
    zero = _detached(data)
    zero["direction"] = ["0", "0"]
    check = _check(tmp_path, _resign(zero))
    assert not check.ok and "zero" in check.reason


def test_an_unsigned_edit_is_refused_by_the_fingerprint(refuted, tmp_path):
    _, data = refuted
    bad = _detached(data)
    bad["frequency"] = "19"
    check = _check(tmp_path, bad)
    assert not check.ok and ("fingerprint" in check.reason or "file name" in check.reason)


def test_a_statement_claiming_all_frequencies_for_a_band_is_refused(refuted, tmp_path):
    _, data = refuted
    bad = _detached(data)
    bad["statement"] = bad["statement"].replace(
        "on the band 0 <= w <= 20 rad/s", "at all frequencies")
    check = _check(tmp_path, bad)
    assert not check.ok and "statement" in check.reason


# ------------------------------------------------------------------ the region and its label


def test_a_widened_region_is_refused(refuted, tmp_path):
    _, data = refuted
    bad = _detached(data)
    reg = bad["region"]
    reg["covariance"] = [[str(mpq(v) * 100) for v in row] for row in reg["covariance"]]
    check = _check(tmp_path, _resign(bad))
    assert not check.ok and "does not enclose" in check.reason


@pytest.mark.parametrize("kind", ["refutation", "proof"])
def test_chi2_lowered_by_5e_10_is_refused_exactly(refuted, proved, tmp_path, kind):
    """Inside the old 1e-9 float agreement; refused by the exact level check."""
    _, data = refuted if kind == "refutation" else proved
    bad = _detached(data)
    bad["region"]["chi2"] = str(mpq(bad["region"]["chi2"]) - mpq(5, 10**10))
    if kind == "refutation":
        check = _check(tmp_path, _resign(bad))
    else:
        bad = _resign_proof(bad)
        check = check_stored_certificate(_write_proof(tmp_path, bad))
    assert not check.ok and "below the 0.95 quantile" in check.reason


@pytest.mark.parametrize("kind", ["refutation", "proof"])
def test_a_level_raised_with_the_same_chi2_is_refused(refuted, proved, tmp_path, kind):
    """The same region relabelled as the 99 % one."""
    _, data = refuted if kind == "refutation" else proved
    bad = _detached(data)
    bad["region"]["level"] = "99/100"
    if kind == "refutation":
        check = _check(tmp_path, _resign(bad))
    else:
        check = check_stored_certificate(_write_proof(tmp_path, _resign_proof(bad)))
    assert not check.ok and "quantile" in check.reason


@pytest.mark.parametrize("kind", ["refutation", "proof"])
def test_a_covariance_divided_by_4_is_refused_against_the_model_file(refuted, proved,
                                                                     kind):
    """A tighter region still labelled 0.95: the source file's covariance says otherwise
    (the chi2 label alone cannot show it; the binding does)."""
    d, data = refuted if kind == "refutation" else proved
    bad = copy.deepcopy(data)
    reg = bad["region"]
    reg["covariance"] = [[str(mpq(v) / 4) for v in row] for row in reg["covariance"]]
    if kind == "refutation":
        check = _check(d, _resign(bad))
    else:
        check = check_stored_certificate(_write_proof(d, _resign_proof(bad)))
    assert not check.ok and "covariance differs" in check.reason


def _resign_proof(data: dict) -> dict:
    band = None if data["band"] is None else tuple(Fraction(x) for x in data["band"])
    data["statement"] = rc.statement(data["structure"], Fraction(data["region"]["level"]),
                                     band)
    data["fingerprint"] = rc.fingerprint(data["structure"], data["parameters"],
                                         data["region"], data["band"])
    return data


def _write_proof(directory: Path, data: dict) -> Path:
    band = None if data["band"] is None else tuple(Fraction(x) for x in data["band"])
    path = directory / rc.file_name(data["name"], band, data["fingerprint"])
    write_atomic(path, rc.dumps(data))
    return path


# ------------------------------------------------------------------ the binding


def test_a_centre_that_differs_from_the_model_file_is_refused(refuted):
    d, data = refuted
    bad = copy.deepcopy(data)
    bad["region"]["center"][0] = str(mpq(bad["region"]["center"][0]) + mpq(1, 1000))
    check = _check(d, _resign(bad))
    assert not check.ok and "centre" in check.reason


def test_a_renamed_model_is_refused(refuted):
    d, data = refuted
    bad = copy.deepcopy(data)
    bad["name"] = "another operator"
    check = _check(d, _resign(bad))
    assert not check.ok and "name" in check.reason
