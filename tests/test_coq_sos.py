"""The paper's SOS certificates checked by Coq's kernel, and attacks on that check.

The exporter (:mod:`verify.coq.sos`) turns each ``certificates/sos-*.json`` of a
``by_sos`` step of Lemma 1 / Theorem 1 into a unit whose theorem states the step's
inequality with the SO3 prelude's names; Coq re-checks the SOS identity by computation
and the link to the statement by ``field``. Tests that run ``coqc`` skip where it is not
installed; they use the small certificates (about 1.5 s each), the two large ones are
compiled by the slow test of the whole development.
"""

from __future__ import annotations

import copy
import json
import shutil
from fractions import Fraction
from pathlib import Path

import pytest
from coq_tools import compiles

from verify.coq.audit import forbidden_commands
from verify.coq.development import (
    coqc_available,
    render_development,
)
from verify.coq.sos import certificate_for, ldl, paper_sos_steps, paper_sos_units, sos_unit
from verify.coq.terms import CoqExportError

ROOT = Path(__file__).resolve().parents[1]
CERTS = ROOT / "certificates"

needs_coqc = pytest.mark.skipif(not coqc_available(), reason="coqc not installed")


def _step(original: str, k: int):
    (step,) = [s for s in paper_sos_steps() if s.original == original and s.step == k]
    return step


SIGN = ("lemma1.boundary-sign-direct", 1)  # k_s tr(sym(R_rl)(I - xi xi^T)) >= 0
H_DOT_4 = ("lemma1.boundary-h-dot", 4)
H_DOT_5 = ("lemma1.boundary-h-dot", 5)
TRACE = ("lemma1.trace-inequality-psd", 1)  # tr(A G^T G) >= lambda_min(A) tr(G^T G)


def _data(step) -> dict:
    return json.loads(certificate_for(step, CERTS).read_text(encoding="utf-8"))


def _unit_text(key, data=None) -> str:
    step = _step(*key)
    data = _data(step) if data is None else data
    return sos_unit(step, data, file_label="test.json").text


# ------------------------------------------------------------------ exporter (no coqc)


@pytest.fixture(scope="module")
def sos_units():
    return paper_sos_units(CERTS)


def test_every_stored_paper_sos_certificate_becomes_a_unit(sos_units):
    units, outcome = sos_units
    stored = sorted(p.name for p in CERTS.glob("sos-*.json"))
    assert len(units) == len(stored) == 8
    assert sorted(u.source for u in units) == stored == sorted(outcome)
    assert not [f for f in outcome.values() if f.startswith("refused")]
    names = {u.name: u for u in units}
    unit = names["sos_lemma1_boundary_sign_direct_step1"]
    assert unit.theorems == ("step1_by_sos",)
    assert "step 1 of the derivation 'lemma1.boundary-sign-direct'" in unit.text
    assert ("Theorem step1_by_sos : (v_1_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 "
            "(mneg (outer v_3_xi v_3_xi)))))) >= 0.") in unit.text
    assert "Hypothesis assumption1 : pd v_2_R_rl." in unit.text
    # the committed list of files left out names no SOS certificate any more
    listed = json.loads((CERTS / "coq" / "NOT_EXPORTED.json").read_text())["not_exported"]
    assert not [i for i in listed if i["schema"] == "verify-sos-certificate/1"]


def test_the_sos_units_have_no_forbidden_command_and_print_their_assumptions(sos_units):
    units, _ = sos_units
    files = render_development(units)
    sos = {k: v for k, v in files.items() if k.startswith("sos_") or k == "SOSCert.v"}
    assert len(sos) == 9
    assert forbidden_commands(sos) == []
    all_v = files["All.v"]  # one Print Assumptions of a term naming every top theorem
    tuple_text = all_v[all_v.index("top_theorems"):all_v.index("Print Assumptions")]
    assert all_v.rstrip().endswith("Print Assumptions top_theorems.")
    for unit in units:
        assert f"{unit.name}.{unit.theorems[0]}" in tuple_text


def test_ldl_rebuilds_the_gram_matrix_exactly():
    q = [[Fraction(4), Fraction(2), Fraction(0)], [Fraction(2), Fraction(2), Fraction(1)],
         [Fraction(0), Fraction(1), Fraction(1)]]
    parts = ldl(q)
    rebuilt = [[sum(d * v[i] * v[j] for d, v in parts) for j in range(3)] for i in range(3)]
    assert rebuilt == q and all(d > 0 for d, _ in parts)
    # a PSD matrix with a zero pivot and a zero column is fine
    z = [[Fraction(0), Fraction(0)], [Fraction(0), Fraction(3)]]
    assert [d for d, _ in ldl(z)] == [3]


@pytest.mark.parametrize("gram", [
    [[1, 2], [2, 1]],  # indefinite: a negative pivot
    [[0, 1], [1, 5]],  # zero pivot, non-zero column
])
def test_ldl_refuses_a_matrix_that_is_not_psd(gram):
    with pytest.raises(CoqExportError, match="not PSD"):
        ldl([[Fraction(x) for x in row] for row in gram])


def test_the_exporter_refuses_a_multiplier_the_step_does_not_allow():
    step = _step(*SIGN)
    data = copy.deepcopy(_data(step))
    data["blocks"][0]["grounds"] = "1 (plain SOS)x"
    with pytest.raises(CoqExportError, match="not one this step allows"):
        sos_unit(step, data, file_label="x.json")


def test_the_exporter_refuses_a_certificate_of_other_variables():
    step = _step(*SIGN)
    other = _data(_step(*TRACE))
    with pytest.raises(CoqExportError, match="variables"):
        sos_unit(step, other, file_label="x.json")


def test_a_refused_paper_certificate_is_listed_with_its_reason(tmp_path):
    """A stored certificate made indefinite: the development leaves it out and says why
    (no crash, the other certificates still exported)."""
    for p in CERTS.glob("sos-*.json"):
        shutil.copy(p, tmp_path / p.name)
    step = _step(*SIGN)
    path = tmp_path / certificate_for(step, CERTS).name
    data = json.loads(path.read_text())
    data["blocks"][0]["gram"][0][0] = "-1"
    path.write_text(json.dumps(data))
    units, outcome = paper_sos_units(tmp_path)
    assert len(units) == 7
    assert outcome[path.name].startswith("refused: ") and "not PSD" in outcome[path.name]


def test_the_exporter_refuses_a_gram_matrix_made_indefinite():
    step = _step(*SIGN)
    data = copy.deepcopy(_data(step))
    data["blocks"][0]["gram"][0][0] = "-1"
    with pytest.raises(CoqExportError, match="not PSD"):
        sos_unit(step, data, file_label="x.json")


# ------------------------------------------------------------------ coqc


@needs_coqc
@pytest.mark.parametrize("key", [SIGN, H_DOT_5, TRACE, ("thm1.V-dot", 3)])
def test_coqc_accepts_the_paper_sos_certificate(prelude_dir, key):
    assert compiles(prelude_dir, _unit_text(key))


@pytest.mark.slow  # the two Gram-48 certificates: about 15 s of CPU together
@needs_coqc
@pytest.mark.parametrize("key", [("thm1.S_r-dot", 7), ("thm1.S_rl-dot", 4)])
def test_coqc_accepts_the_large_paper_sos_certificates(prelude_dir, key):
    assert compiles(prelude_dir, _unit_text(key))


@needs_coqc
def test_coqc_rejects_a_changed_gram_entry(prelude_dir):
    """An off-diagonal Gram entry changed (the matrix stays PSD): the identity fails."""
    step = _step(*SIGN)
    data = copy.deepcopy(_data(step))
    gram = data["blocks"][0]["gram"]
    i, j = next((i, j) for i in range(len(gram)) for j in range(i)
                if Fraction(gram[i][j]) != 0)
    changed = str(Fraction(gram[i][j]) * Fraction(99, 100))
    gram[i][j] = gram[j][i] = changed
    try:
        text = sos_unit(step, data, file_label="x.json").text
    except CoqExportError:
        return  # refused by the exporter: also sound
    assert not compiles(prelude_dir, text)


@needs_coqc
def test_coqc_rejects_a_changed_target_coefficient(prelude_dir):
    step = _step(*SIGN)
    data = copy.deepcopy(_data(step))
    mono, coeff = data["target"][0]
    data["target"][0] = [mono, str(Fraction(coeff) + 1)]
    assert not compiles(prelude_dir, sos_unit(step, data, file_label="x.json").text)


@needs_coqc
def test_coqc_rejects_a_dropped_square(prelude_dir):
    text = _unit_text(SIGN)
    start = text.index("Definition S1 : list (Q * list poly) :=")
    end = text.index("].\n", start)
    squares = text[start:end]
    last = squares.rindex(";\n   (")
    bad = text[:start] + squares[:last] + text[end:]
    assert bad != text
    assert not compiles(prelude_dir, bad)


@needs_coqc
def test_coqc_rejects_the_certificate_of_another_step(prelude_dir):
    """Steps 4 and 5 of the boundary derivation share their variables; step 4's
    certificate handed to step 5 is refused by the exporter or by coqc."""
    step5 = _step(*H_DOT_5)
    other = _data(_step(*H_DOT_4))
    try:
        text = sos_unit(step5, other, file_label="x.json").text
    except CoqExportError:
        return
    assert not compiles(prelude_dir, text)


@needs_coqc
def test_coqc_rejects_a_changed_statement(prelude_dir):
    text = _unit_text(SIGN)
    old = "(mneg (outer v_3_xi v_3_xi)))))) >= 0."
    assert text.count(old) == 1
    assert not compiles(prelude_dir, text.replace(old, old.replace(">= 0.", ">= 1.")))


@needs_coqc
def test_coqc_rejects_a_rotation_step_whose_link_does_not_hold(prelude_dir):
    """A step over rotations (the link by computation at the prelude's level,
    SOSCert.link_ok): its coefficient -1/2 made -1/3 everywhere in the unit. The new
    inequality still holds, but the certificate's target is not its slack: the link's
    check, evaluated by the kernel, fails."""
    text = _unit_text(("thm1.V-dot", 3))
    old = "(-1/2) * v_1_k_s) * (lam1 + lam2)"
    assert text.count(old) == 3 and "sos_link" in text
    assert not compiles(prelude_dir, text.replace(old, "(-1/3) * v_1_k_s) * (lam1 + lam2)"))


@pytest.mark.slow  # a Gram-48 certificate: about 5 s of CPU
@needs_coqc
def test_coqc_rejects_a_rotation_multiplier_over_another_denominator(prelude_dir):
    """A 3 x 3 multiplier's grounds by computation (SOSCert.mult_psd_9r): the product of
    norms D it is compared over changed (|q_r|^2 squared instead of once). The
    certificate's identity is untouched; the grounds lemma fails."""
    text = _unit_text(("thm1.S_r-dot", 7))
    (line,) = [x for x in text.splitlines() if "sos_psd9" in x]
    head, den = line.rsplit(" [", 1)
    assert den.startswith("0; 1; ") and den.endswith("]%nat.")
    bad = text.replace(line, f"{head} [0; 2; {den[len('0; 1; '):]}")
    assert bad != text
    assert not compiles(prelude_dir, bad)


@needs_coqc
def test_coqc_rejects_a_weakened_hypothesis(prelude_dir):
    """The multiplier's ground replaced by a hypothesis that does not give it (psd of
    the transpose's negation): the grounds lemma no longer holds."""
    text = _unit_text(SIGN)
    old = "Hypothesis assumption1 : pd v_2_R_rl."
    assert old in text
    assert not compiles(prelude_dir,
                        text.replace(old, "Hypothesis assumption1 : pd (mneg v_2_R_rl)."))


def test_the_report_names_each_sos_step_by_its_exported_theorem(sos_units):
    from verify.report.steps import _coq_theorem

    exported = {f"{u.name}.{t}" for u in sos_units[0] for t in u.theorems}
    for step in paper_sos_steps():
        if not certificate_for(step, CERTS).is_file():
            continue
        row = {"verdict": "verified", "relation": "<=", "index": 1,
               "justification": f"SOS re-proof of step {step.step}: SOS certificate"}
        name = _coq_theorem(f"{step.original}.step{step.step}-sos", row, set())
        assert name in exported
        assert _coq_theorem(f"{step.original}.step{step.step}-sos",
                            {**row, "verdict": "inconclusive"}, set()) == ""


@needs_coqc
@pytest.mark.parametrize("key", [SIGN, ("thm1.S_r-dot", 7)])
def test_coqc_rejects_a_changed_multiplier(prelude_dir, key):
    """A multiplier entry changed under the same grounds: its grounds lemma (by field, or
    by computation for Theorem 1's rotations) fails."""
    step = _step(*key)
    data = copy.deepcopy(_data(step))
    block = next(b for b in data["blocks"] if len(b["multiplier"]) == 3)
    mono, coeff = block["multiplier"][0][0][0]
    block["multiplier"][0][0][0] = [mono, str(Fraction(coeff) * 2)]
    assert not compiles(prelude_dir, sos_unit(step, data, file_label="x.json").text)
