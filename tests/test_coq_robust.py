"""Robust verdicts over an identified region checked by Coq's kernel (``RobustCert.v``):
the shipped robust band and refutation certificates as units, and mutations coqc refuses.

Tests that run ``coqc`` skip where it is not installed; they compile the three prelude
modules a robust unit needs (not the whole prelude) and are marked slow.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from coq_tools import compiles, run_coqc
from gmpy2 import mpq

from verify.coq import robust
from verify.coq.bundle import module_texts
from verify.coq.development import coqc_available, prelude_sources, required_prelude
from verify.coq.export import export_certificates
from verify.coq.kyp import CoqExportError
from verify.coq.robust_leaves import (
    direction_ok,
    positive_bounds,
    short_linear,
    short_positive,
    widened,
)
from verify.coq.robust_outside import dual_value, outside_direction, passes
from verify.identify.robust.band_check import parse_region
from verify.passivity.check import robust_band as rb

ROOT = Path(__file__).resolve().parents[1]
CERTS = ROOT / "certificates"
BAND = CERTS / "nonpassive_human-identified-robust-band-0-1.46-e70cf8beb9e5.json"
REFUTED = CERTS / "nonpassive_human-identified-robust-refuted-at-2.88945-ca067ce3563c.json"
PASSIVE = CERTS / "passive_human-identified-robust-band-0-7.97-3da104e65018.json"

needs_coqc = pytest.mark.skipif(not coqc_available(), reason="coqc not installed")


def test_the_shipped_band_and_refutation_become_units():
    export = export_certificates([BAND, REFUTED, PASSIVE])
    theorems = {u.name: u.theorems for u in export.units}
    assert theorems == {
        "Cert_nonpassive_human_identified_robust_band_0_1_46_e70cf8beb9e5":
            ("sigma_inverse", "robust_passive"),
        "Cert_nonpassive_human_identified_robust_refuted_at_2_88945_ca067ce3563c":
            ("sigma_inverse", "robust_not_passive"),
        "Cert_passive_human_identified_robust_band_0_7_97_3da104e65018":
            ("sigma_inverse", "robust_passive"),
    }
    assert not export.not_exported


def test_the_committed_development_exports_everything():
    listed = json.loads((CERTS / "coq" / "NOT_EXPORTED.json").read_text())
    assert listed == {"not_exported": []}
    _, modules = module_texts((CERTS / "coq" / "Certificates.v").read_text())
    text = modules["Cert_passive_human_identified_robust_band_0_7_97_3da104e65018"]
    assert text.count("ROut [") == 243
    # every positive and linear leaf on a coarse grid box, linear ones with short directions
    assert text.count("(RGrid ") == 688
    assert text.count("RLinY") == 100


def _outside_boxes():
    """(box, point) of every leaf 'outside' of the passive operator's band, with the
    region reduced to phi (its centre, covariance and inverse) and chi2."""
    data = json.loads(PASSIVE.read_text())
    region, _ = parse_region(data["region"], 10)
    phi, cov = rb.reduce_region(region.center, region.covariance)
    r = [mpq(x) for x in data["enclosure"]]
    w1, w2 = (mpq(w) for w in data["band"])
    root = [(c - h, c + h) for c, h in zip(phi, r, strict=True)] + [(w1 * w1, w2 * w2)]
    leaves = [(box[:-1], [mpq(v) for v in node[1]])
              for box, node in rb.leaves(data["pieces"][0]["tree"], root)
              if node[0] == "outside"]
    return leaves, phi, cov, rb.inverse(cov), region.chi2


def _leaf_boxes(kind: str):
    """(box, claimed bounds) of every leaf ``kind`` of the passive operator's band, with
    the region reduced to phi (its centre, covariance) and chi2."""
    data = json.loads(PASSIVE.read_text())
    region, _ = parse_region(data["region"], 10)
    phi, cov = rb.reduce_region(region.center, region.covariance)
    r = [mpq(x) for x in data["enclosure"]]
    w1, w2 = (mpq(w) for w in data["band"])
    root = [(c - h, c + h) for c, h in zip(phi, r, strict=True)] + [(w1 * w1, w2 * w2)]
    leaves = [(box, [mpq(v) for v in node[1:4]])
              for box, node in rb.leaves(data["pieces"][0]["tree"], root) if node[0] == kind]
    return leaves, phi, cov, region.chi2


def _moved(box, k: int, widths: int):
    """The box moved along coordinate k by ``widths`` of its widths."""
    lo, hi = box[k]
    out = list(box)
    out[k] = (lo + widths * (hi - lo), hi + widths * (hi - lo))
    return out


def test_short_linear_leaves_pass_exactly_and_fail_when_changed():
    leaves, phi, cov, chi2 = _leaf_boxes("linear")
    assert len(leaves) == 100
    for box, claimed in leaves[:3]:
        bits, forms = short_linear(box, claimed, phi, cov, chi2)
        wide = widened(box, bits)
        assert all(a <= lo and hi <= b for (lo, hi), (a, b) in zip(box, wide, strict=True))
        _, parts = rb.linear_parts(wide[:-1], wide[-1], "x", rb.Shape(1, 2))
        for (value, grad), (c, s, y) in zip(parts, forms, strict=True):
            assert max(len(str(v.numerator)) + len(str(v.denominator)) for v in y) < 12
            assert direction_ok(wide[:-1], value, grad, y, c, s, phi, cov, chi2)
            # the direction reversed: the region's term no longer bounds the slopes' part
            assert not direction_ok(wide[:-1], value, grad, [-v for v in y], c, s, phi, cov,
                                    chi2)
            # s below sqrt(chi2 y^T Sigma y)
            assert not direction_ok(wide[:-1], value, grad, y, c, s / 2, phi, cov, chi2)


def test_short_positive_leaves_pass_exactly_and_a_moved_box_does_not():
    leaves, _, _, _ = _leaf_boxes("positive")
    assert len(leaves) == 588
    for box, claimed in leaves[:20]:
        bits, bounds = short_positive(box, claimed)
        assert all(c > 0 for c in bounds)
        assert positive_bounds(widened(box, bits), bounds) == bounds
    box, claimed = leaves[0]
    assert positive_bounds(_moved(box, 8, 40), claimed) is None


def test_outside_directions_are_short_and_pass_exactly():
    leaves, phi, cov, inverse, chi2 = _outside_boxes()
    assert len(leaves) == 243
    for box, point in leaves[:40]:
        y = outside_direction(box, point, phi, cov, inverse, chi2)
        assert y is not None and passes(y, box, phi, cov, chi2)
        assert max(len(str(v.numerator)) + len(str(v.denominator)) for v in y) < 30
        # the exact tangent direction gives the Python checker's own bound
        exact = [sum(inverse[i][j] * (point[j] - phi[j]) for j in range(9)) for i in range(9)]
        lb, q = dual_value(exact, box, phi, cov)
        assert lb + lb - q == rb.outside_bound(inverse, phi, box, point)


def test_a_box_meeting_the_region_has_no_direction():
    leaves, phi, cov, inverse, chi2 = _outside_boxes()
    box, _ = leaves[0]
    # the box moved onto the centre: it meets the region, no plane can separate them
    centred = [(c - (hi - lo) / 2, c + (hi - lo) / 2) for c, (lo, hi) in zip(phi, box, strict=True)]
    assert outside_direction(centred, phi, phi, cov, inverse, chi2) is None
    point = [hi for _, hi in centred]
    assert outside_direction(centred, point, phi, cov, inverse, chi2) is None
    assert not passes([mpq(0)] * 9, box, phi, cov, chi2)


def test_a_unit_states_the_region_and_the_band():
    text = robust.robust_unit_from_file(BAND).text
    assert "forall th, in_region Si thc chi2 th -> paper_band_passive th w1 w2." in text
    assert "Definition w2 : Q := (73 # 50)." in text
    assert text.count("RPos") == 5


def test_a_tree_is_nested_in_pre_order():
    tree = [3, ["positive", "1", "2", "3"], 0, ["positive", "1", "1", "1"],
            ["positive", "2", "2", "2"]]
    assert robust.tree_literal(tree, False) == (
        "(RSplit 3 (RLeaf (RPos (1 # 1) (2 # 1) (3 # 1))) (RSplit 0 (RLeaf (RPos (1 # 1) "
        "(1 # 1) (1 # 1))) (RLeaf (RPos (2 # 1) (2 # 1) (2 # 1)))))")
    with pytest.raises(CoqExportError, match="after its last box"):
        robust.tree_literal([["positive", "1", "1", "1"], 0], False)
    with pytest.raises(CoqExportError, match="outside"):
        robust.tree_literal([["outside", ["0"] * 9]], False)


def test_a_certificate_the_checker_refuses_is_not_exported(tmp_path):
    bad = tmp_path / BAND.name
    bad.write_text(BAND.read_text().replace('"positive","393/1000"', '"positive","393/10"'))
    with pytest.raises(CoqExportError, match="not exported"):
        robust.robust_unit_from_file(bad)


@pytest.fixture(scope="module")
def robust_prelude(tmp_path_factory):
    if not coqc_available():
        pytest.skip("coqc not installed")
    folder = tmp_path_factory.mktemp("robust_prelude")
    needed = required_prelude(prelude_sources(), ["From VerifyCoq Require Import RobustCert."])
    for name, text in needed.items():
        (folder / f"{name}.v").write_text(text)
        run_coqc(folder, f"{name}.v", check=True)
    return folder


def _scaled(text: str, name: str, factor: int) -> str:
    """The definition ``name : Q := (p # q)`` with p multiplied by ``factor``."""
    pattern = re.compile(rf"(Definition {name} : Q := \()(-?\d+)( # \d+\))")
    assert pattern.search(text), name
    return pattern.sub(lambda m: f"{m.group(1)}{int(m.group(2)) * factor}{m.group(3)}",
                       text, count=1)


@pytest.mark.slow
@needs_coqc
def test_coqc_accepts_the_band_unit_and_refuses_mutations(robust_prelude):
    unit = robust.robust_unit_from_file(BAND)
    assert compiles(robust_prelude, unit.text, unit.name)
    # a wrong bound: the first leaf claims N_1 >= 100 times its bound
    first = re.search(r"RPos \((\d+) # (\d+)\)", unit.text)
    wrong = unit.text.replace(first.group(0), f"RPos ({int(first.group(1)) * 100} # "
                              f"{first.group(2)})", 1)
    assert not compiles(robust_prelude, wrong, unit.name)
    # a widened ellipsoid: chi2 doubled, the box no longer encloses it
    assert not compiles(robust_prelude, _scaled(unit.text, "chi2", 2), unit.name)
    # leaf boxes shifted: the first split cuts another coordinate
    shifted = unit.text.replace("(RSplit 9 ", "(RSplit 8 ", 1)
    assert shifted != unit.text
    assert not compiles(robust_prelude, shifted, unit.name)


@pytest.mark.slow
@needs_coqc
def test_coqc_accepts_the_refutation_unit_and_refuses_a_changed_frequency(robust_prelude):
    unit = robust.robust_unit_from_file(REFUTED)
    assert compiles(robust_prelude, unit.text, unit.name)
    assert not compiles(robust_prelude, _scaled(unit.text, "wstar", 3), unit.name)


def _first_outside(text: str) -> re.Match:
    match = re.search(r"ROut \[([^\]]*)\]", text)
    assert match, "no leaf ROut"
    return match


@needs_coqc
def test_coqc_checks_one_outside_leaf_and_refuses_a_moved_plane(robust_prelude):
    """The representative (not slow): one leaf 'outside' of the passive operator's band
    as a lemma [out_ok ... = true] on its own box; its direction reversed (the plane
    moved to the other side, so the box is no longer separated) makes coqc fail."""
    leaves, phi, cov, inverse, chi2 = _outside_boxes()
    box, point = leaves[0]
    y = outside_direction(box, point, phi, cov, inverse, chi2)
    unit = robust.robust_unit_from_file(PASSIVE).text
    head = unit[:unit.index("(** The half-widths")]

    def lemma(direction) -> str:
        boxes = "; ".join(f"({robust._q(lo)}, {robust._q(hi)})" for lo, hi in box)
        return (head + f"Definition B : list iv := [{boxes}].\n"
                f"Definition y : list Q := {robust._list(direction)}.\n"
                "Lemma leaf_ok : out_ok Sg chi2 (phicQ thc) B y = true.\n"
                "Proof. vm_cast_no_check (eq_refl true). Qed.\n")

    assert compiles(robust_prelude, lemma(y), "OutsideLeaf")
    moved = [-v for v in y]
    assert not passes(moved, box, phi, cov, chi2)
    assert not compiles(robust_prelude, lemma(moved), "OutsideLeaf")


def _linear_lemma(head: str, box, bits: int, forms) -> str:
    boxes = "; ".join(f"({robust._q(lo)}, {robust._q(hi)})" for lo, hi in box)
    cs = " ".join(robust._q(c) for c, _, _ in forms)
    ss = " ".join(robust._q(s) for _, s, _ in forms)
    ys = " ".join(robust._list(y) for _, _, y in forms)
    return (head + f"Definition B : list iv := grid_box {2 ** bits} [{boxes}].\n"
            "Lemma leaf_ok : lin_leaf Sg chi2 (phicQ thc) B (nth 9 B zero_iv) "
            f"{cs} {ss} {ys} = true.\n"
            "Proof. vm_cast_no_check (eq_refl true). Qed.\n")


@needs_coqc
def test_coqc_checks_one_linear_leaf_and_refuses_a_wrong_direction_or_a_moved_box(
        robust_prelude):
    """The representative (not slow): one linear leaf of the passive operator's band as a
    lemma [lin_leaf ... = true] on its box rounded out to its grid ([grid_box]), with the
    short directions the exporter writes; coqc refuses it with the det direction reversed,
    and on the box moved along c = c12 + c21 (the same numbers no longer bound det)."""
    leaves, phi, cov, chi2 = _leaf_boxes("linear")
    box, claimed = leaves[0]
    bits, forms = short_linear(box, claimed, phi, cov, chi2)
    unit = robust.robust_unit_from_file(PASSIVE).text
    head = unit[:unit.index("(** The half-widths")]
    assert compiles(robust_prelude, _linear_lemma(head, box, bits, forms), "LinearLeaf")
    c, s, y = forms[2]
    wrong = [*forms[:2], (c, s, [-v for v in y])]
    assert not compiles(robust_prelude, _linear_lemma(head, box, bits, wrong), "LinearLeaf")
    moved = _moved(box, 8, 3)
    wide = widened(moved, bits)
    _, parts = rb.linear_parts(wide[:-1], wide[-1], "x", rb.Shape(1, 2))
    assert not direction_ok(wide[:-1], *parts[2], y, c, s, phi, cov, chi2)
    assert not compiles(robust_prelude, _linear_lemma(head, moved, bits, forms), "LinearLeaf")


@pytest.mark.slow
@needs_coqc
def test_coqc_accepts_the_passive_band_unit(robust_prelude):
    unit = robust.robust_unit_from_file(PASSIVE)
    assert compiles(robust_prelude, unit.text, unit.name)


@pytest.mark.slow
@needs_coqc
def test_coqc_refuses_the_passive_band_with_a_moved_plane(robust_prelude):
    """The first leaf 'outside' with its direction reversed: its box meets the region on
    that side, and the unit's whole check fails."""
    unit = robust.robust_unit_from_file(PASSIVE)
    match = _first_outside(unit.text)
    entries = match.group(1).split("; ")
    reversed_ = [e.replace("(", "(-", 1).replace("(--", "(") if not e.startswith("(0 #")
                 else e for e in entries]
    assert reversed_ != entries
    wrong = unit.text.replace(match.group(0), "ROut [" + "; ".join(reversed_) + "]", 1)
    assert not compiles(robust_prelude, wrong, unit.name)


@needs_coqc
def test_the_hurwitz_lemma_of_degree_two(robust_prelude):
    """hurwitz2 is stated as the Routh-Hurwitz condition of degree 2; a wrong variant
    (a0 >= 0 allowed) is not provable from it and coqc refuses the attempt."""
    statement = ("From Coq Require Import Reals.\nFrom VerifyCoq Require Import BandCert "
                 "RobustCert.\nOpen Scope R_scope.\n"
                 "Check (hurwitz2 : forall a1 a0 : R, (forall s, quad_at a1 a0 s = (0, 0) -> "
                 "fst s < 0) <-> 0 < a1 /\\ 0 < a0).\n"
                 "Goal quad_at 3 2 (-1, 0) = (0, 0) /\\ quad_at 3 2 (-2, 0) = (0, 0).\n"
                 "Proof. unfold quad_at, cadd, cmul; simpl; split; f_equal; ring. Qed.\n")
    assert compiles(robust_prelude, statement, "Hurwitz2")
    wrong = ("From Coq Require Import Reals Lra.\nFrom VerifyCoq Require Import BandCert "
             "RobustCert.\nOpen Scope R_scope.\n"
             "Lemma wrong a1 a0 : 0 < a1 -> 0 <= a0 -> "
             "forall s, quad_at a1 a0 s = (0, 0) -> fst s < 0.\n"
             "Proof. intros H1 H0. apply hurwitz2. lra. Qed.\n")
    assert not compiles(robust_prelude, wrong, "Hurwitz2")
    loose = statement.replace("<-> 0 < a1 /\\ 0 < a0", "<-> 0 < a1 /\\ 0 <= a0")
    assert loose != statement
    assert not compiles(robust_prelude, loose, "Hurwitz2")
