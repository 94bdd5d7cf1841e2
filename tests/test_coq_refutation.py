"""Negative verdicts checked by Coq's kernel (``WitnessCert.v``): refutation units of the
gate's witnesses, attacks on them, and ``verify gate --coq --require-coq``.

Tests that run ``coqc`` skip where it is not installed.
"""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import pytest
from coq_tools import compiles
from gmpy2 import mpq

from verify.cli import main
from verify.coq import refutation as rf
from verify.coq.development import coqc_available
from verify.coq.kyp import CoqExportError
from verify.passivity.check.certificate import ExactModel
from verify.passivity.decision import decide
from verify.passivity.io.model_file import load_model

ROOT = Path(__file__).resolve().parents[1]
MODELS = ROOT / "verify" / "data" / "models"

needs_coqc = pytest.mark.skipif(not coqc_available(), reason="coqc not installed")


def exact(A, B, C, D) -> ExactModel:
    return ExactModel(*([[mpq(Fraction(x)) for x in row] for row in M] for M in (A, B, C, D)))


def unit_of(em: ExactModel, witness, name: str, margin=Fraction(0), band=None):
    return rf.refutation_unit(name, model=em, margin=margin, witness=witness, label="test",
                              source="test", fingerprint=em.fingerprint(), origin="test",
                              band=band)


@pytest.fixture(scope="module")
def ks25_decision():
    return decide(load_model(MODELS / "reconstructed_ks2p5.toml"))


def test_the_gate_witness_of_ks25_is_what_coq_recomputes(ks25_decision):
    base, found = rf.decision_witness(ks25_decision)
    assert isinstance(found, rf.FrequencyWitness)
    assert found.omega == Fraction(5, 2)
    # Re z^H Mt z = |d(jw)|^2 v^H (H + H^H) v: the gate's -36/389 times |d(5j/2)|^4 / ...
    assert found.value < 0
    assert rf.form_at(base, Fraction(5, 2), found.a, found.b) == found.value
    assert rf.form_at(base, Fraction(1), found.a, found.b) > 0  # passive below 2 rad/s


@needs_coqc
def test_coqc_accepts_the_refutation_and_rejects_a_changed_witness(prelude_dir,
                                                                   ks25_decision):
    unit = rf.decision_unit(ks25_decision, "Refutation_1")
    assert "Theorem not_passive : model_ok 4 2 A B C D /\\ ~ positive_real 4 2 A B C D." \
        in unit.text
    assert compiles(prelude_dir, unit.text, "Refutation_1")
    changed = unit.text.replace("Definition w_star : Q := (5 # 2).",
                                "Definition w_star : Q := (3 # 2).")
    assert changed != unit.text
    assert not compiles(prelude_dir, changed, "Refutation_1")
    flipped = unit.text.replace("[((1 # 1), (0 # 1)); ((0 # 1), (0 # 1))]",
                                "[((0 # 1), (0 # 1)); ((0 # 1), (0 # 1))]")
    assert flipped != unit.text  # the zero vector gives 0, not < 0
    assert not compiles(prelude_dir, flipped, "Refutation_1")


@needs_coqc
def test_unstable_and_infinity_witnesses_compile(prelude_dir):
    unstable = exact([[1, 0], [0, -3]], [[1], [1]], [[1, 1]], [[2]])
    found = rf.unstable_witness(unstable)
    assert found is not None and found.s1 > 0
    assert compiles(prelude_dir, unit_of(unstable, found, "Unstable").text, "Unstable")
    # an interval left of the root: no sign change, coqc refuses
    wrong = rf.UnstableWitness(Fraction(1, 4), Fraction(1, 2))
    assert not compiles(prelude_dir, unit_of(unstable, wrong, "Unstable").text, "Unstable")
    stable = exact([[-1]], [[1]], [[1]], [[1]])
    assert rf.unstable_witness(stable) is None
    at_infinity = exact([[-1]], [[1]], [[1]], [["-1/10"]])
    fw = rf.frequency_from_infinity(at_infinity, ["1"])
    assert fw is not None and fw.omega > 0
    assert compiles(prelude_dir, unit_of(at_infinity, fw, "Infinity").text, "Infinity")


@needs_coqc
def test_a_band_refutation_compiles_and_needs_its_witness_in_the_band(prelude_dir,
                                                                      ks25_decision):
    base, found = rf.decision_witness(ks25_decision)
    band = (Fraction(2), Fraction(3))
    assert compiles(prelude_dir, unit_of(base, found, "Band", band=band).text, "Band")
    with pytest.raises(CoqExportError, match="in the band"):
        unit_of(base, found, "Band", band=(Fraction(0), Fraction(1)))


def test_a_false_witness_is_not_proposed():
    passive = exact([[-1]], [[1]], [[1]], [[1]])  # 1/(s+1) + 1: positive real
    assert rf.frequency_from_data(passive, {"omega": "1", "a": ["1"], "b": ["0"]}) is None
    assert rf.frequency_from_infinity(passive, ["1"]) is None
    assert rf.frequency_from_data(passive, {"omega": "x"}) is None


@needs_coqc
def test_gate_require_coq_on_ks25_proves_it_not_passive(tmp_path, capsys):
    out_json = tmp_path / "gate.json"
    junit = tmp_path / "gate.xml"
    rc = main(["gate", str(MODELS / "reconstructed_ks2p5.toml"),
               "--certificates", str(tmp_path / "c"), "--coq", str(tmp_path / "coq"),
               "--require-coq", "--json", str(out_json), "--junit", str(junit)])
    out = capsys.readouterr().out
    assert rc == 1, out  # not passive
    assert "coq: compiled by coqc, accepted" in out
    [entry] = json.loads(out_json.read_text())
    assert entry["verdict"] == "not passive"
    assert entry["kernel"] == "coq"
    assert entry["coq_theorem"] == "Refutation_1.not_passive"
    assert '<property name="kernel" value="coq"/>' in junit.read_text()
    assert (tmp_path / "coq" / "Refutation_1.v").is_file()


def test_require_coq_needs_coq(tmp_path, capsys):
    rc = main(["gate", str(MODELS / "reconstructed_ks2p5.toml"), "--require-coq",
               "--certificates", str(tmp_path / "c")])
    assert rc == 2
    assert "--require-coq needs --coq" in capsys.readouterr().err


def test_gate_json_carries_the_kernel_status_without_coq(tmp_path, capsys):
    out_json = tmp_path / "gate.json"
    rc = main(["gate", str(MODELS / "reconstructed_ks2p5.toml"),
               "--certificates", str(tmp_path / "c"), "--json", str(out_json)])
    assert rc == 1
    [entry] = json.loads(out_json.read_text())
    assert entry["kernel"] == "exact-python" and entry["coq_theorem"] is None


def test_require_coq_fails_on_a_verdict_without_a_unit(tmp_path, capsys):
    """1 - 1/s: not passive by its residue at s = 0, a witness Coq does not state; no
    unit is written, the kernel status says why, and --require-coq fails."""
    model = tmp_path / "negint.toml"
    model.write_text('name = "negative integrator"\n[state_space]\nA = [[0.0]]\n'
                     "B = [[1.0]]\nC = [[-1.0]]\nD = [[1.0]]\n")
    out_json = tmp_path / "gate.json"
    rc = main(["gate", str(model), "--certificates", str(tmp_path / "c"),
               "--coq", str(tmp_path / "coq"), "--require-coq", "--json", str(out_json)])
    out = capsys.readouterr().out
    assert rc == 1
    assert "--require-coq: not accepted by coqc: negative integrator" in out
    [entry] = json.loads(out_json.read_text())
    assert entry["kernel"].startswith("not-exported: ")
    assert entry["coq_theorem"] is None
    assert not list((tmp_path / "coq").glob("Refutation_*.v"))
