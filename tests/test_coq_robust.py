"""Robust verdicts over an identified region checked by Coq's kernel (``RobustCert.v``):
the shipped robust band and refutation certificates as units, and mutations coqc refuses.

Tests that run ``coqc`` skip where it is not installed; they compile the three prelude
modules a robust unit needs (not the whole prelude) and are marked slow.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from coq_tools import compiles, run_coqc

from verify.coq import robust
from verify.coq.development import coqc_available, prelude_sources, required_prelude
from verify.coq.export import export_certificates
from verify.coq.kyp import CoqExportError

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
    }
    (left,) = export.not_exported
    assert left.file == PASSIVE.name and "outside" in left.reason


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
