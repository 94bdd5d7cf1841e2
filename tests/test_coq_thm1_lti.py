"""Theorem 1 with a certified LTI human (prelude ``LTIHuman.v``, ``Thm1LTI.v`` and the
``Thm1_<certificate>`` unit beside a KYP certificate's unit, Sections 3 and 4): the unit
is written from a fixed template and passes the audit, coqc accepts it for the k_s = 3.0
reconstruction with only the standard axioms, and refuses it when the k_s = 2.5 model's
data is forced in, when a premise the proof needs is dropped, or when the bound is
strengthened."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from coq_tools import compiles, run_coqc

from verify.coq.audit import (
    audit_assumptions,
    forbidden_commands,
    statement_problems,
    template_problems,
)
from verify.coq.development import PRELUDE_ORDER, prelude_sources
from verify.coq.export import export_certificates
from verify.coq.kyp import CoqExportError, kyp_units_from_file, matrix_literal
from verify.coq.thm1_lti import THEOREMS, thm1_unit, unit_name

ROOT = Path(__file__).resolve().parents[1]
CERTS = ROOT / "certificates"
KS3 = next(CERTS.glob("reconstructed-k_s-3.0-*.json"))
KS25_MODEL = ROOT / "verify" / "data" / "models" / "reconstructed_ks2p5.toml"


def _coquelicot_missing() -> bool:
    coqc = shutil.which("coqc")
    if coqc is None:
        return True
    where = subprocess.run([coqc, "-where"], capture_output=True, text=True, check=False)
    lib = Path(where.stdout.strip())
    return not any((lib / d / "Coquelicot").is_dir() for d in ("user-contrib", "../user-contrib"))


needs_coquelicot = pytest.mark.skipif(_coquelicot_missing(),
                                      reason="coqc or Coquelicot not installed")


def ks3_units():
    cert, thm1 = kyp_units_from_file(KS3)
    return cert, thm1


# ------------------------------------------------------------------ the unit (no coqc)


def test_a_kyp_certificate_gets_its_theorem1_unit_next_to_it():
    export = export_certificates([CERTS])
    names = [u.name for u in export.units]
    cert = "Cert_reconstructed_k_s_3_0_99babda880e6"
    assert names[names.index(cert) + 1] == unit_name(cert)
    # the k_s = 2.5 model is not passive: its band certificate gets no Theorem 1 unit
    assert not any(n.startswith("Thm1_reconstructed_k_s_2_5") for n in names)


def test_the_unit_takes_the_data_from_the_certificate_unit_and_passes_the_audit():
    cert, thm1 = ks3_units()
    assert thm1.theorems == tuple(THEOREMS)
    text = thm1.text
    assert f"From VerifyCoq Require QCert LTIHuman {cert.name}." in text
    for k in "ABCDP":
        assert f"Definition {k} : QCert.matQ := {cert.name}.{k}." in text
    assert "#" not in text  # no rational literal: no re-typed number
    assert f"{cert.name}.passive" in text
    files = {f"{thm1.name}.v": text}
    assert template_problems(files) == [] and forbidden_commands(files) == []
    assert statement_problems(f"{thm1.name}.v", text, dict(thm1.statements)) == []


def test_an_edited_statement_fails_the_round_trip():
    _, thm1 = ks3_units()
    edited = thm1.text.replace("<= V Rr Rb Rl (S_h 4 P x) 0)", "<= V Rr Rb Rl (S_h 4 P x) 1)", 1)
    assert edited != thm1.text
    assert statement_problems("X.v", edited, dict(thm1.statements))


def test_models_that_do_not_fit_the_loop_get_no_unit():
    with pytest.raises(CoqExportError, match="ports"):
        thm1_unit("Cert_x", 4, 4, label="four ports", origin="test")
    with pytest.raises(CoqExportError, match="state"):
        thm1_unit("Cert_x", 0, 2, label="static", origin="test")
    with pytest.raises(ValueError):
        unit_name("Refutation_1")


def test_hostile_label_stays_in_a_comment():
    unit = thm1_unit("Cert_x", 2, 2, label="*) Axiom bad : False. (*", origin="o")
    assert forbidden_commands({"X.v": unit.text}) == []
    assert template_problems({"X.v": unit.text}) == []


def test_prelude_lists_the_new_modules_after_their_dependencies():
    order = list(PRELUDE_ORDER)
    assert order.index("QCert") < order.index("LTIHuman")
    assert order.index("Barbalat") < order.index("Thm1LTI")
    assert order.index("LTIHuman") < order.index("Thm1LTI")
    files = {f"{n}.v": prelude_sources()[n] for n in ("LTIHuman", "Thm1LTI")}
    assert forbidden_commands(files) == []


# ------------------------------------------------------------------ coqc


def _write(folder: Path, unit) -> None:
    (folder / f"{unit.name}.v").write_text(unit.text)


@needs_coquelicot
def test_coqc_accepts_theorem1_with_the_certified_human_and_only_standard_axioms(prelude_dir):
    cert, thm1 = ks3_units()
    assert compiles(prelude_dir, cert.text, cert.name)
    assert compiles(prelude_dir, thm1.text, thm1.name)
    tops = ", ".join(f"{thm1.name}.{t}" for t in thm1.theorems)
    (prelude_dir / "ProbeThm1.v").write_text(
        f"From VerifyCoq Require {thm1.name}.\nDefinition tops := ({tops}).\n"
        "Print Assumptions tops.\n")
    # the certificate is checked on machine integers (QCert.v's kyp_wcheck), so the
    # primitive-integer axioms are allowed here, as in All.v's word block, and no others
    output = run_coqc(prelude_dir, "ProbeThm1.v", check=True).stdout
    assert not audit_assumptions(output).ok  # they do appear
    audit = audit_assumptions(output, word_block=True)
    assert audit.ok, audit.disallowed
    assert "Classical_Prop.classic" in audit.axioms


def _ks25_definitions() -> dict[str, str]:
    from verify.passivity.io.model_file import load_model

    exact = load_model(KS25_MODEL).exact
    return {k: matrix_literal(getattr(exact, k)) for k in "ABCD"}


@needs_coquelicot
def test_the_k_s_2_5_data_forced_into_the_certificate_unit_is_refused(prelude_dir):
    # the 2.5 model's A, B, C, D with the 3.0 certificate's P and witnesses: no KYP proof
    cert, _thm1 = ks3_units()
    text = cert.text
    for k, literal in _ks25_definitions().items():
        start = text.index(f"Definition {k} : matQ :=")
        end = text.index(".\n", start)
        text = text[:start] + f"Definition {k} : matQ :=\n  {literal}" + text[end:]
    assert text != cert.text
    assert not compiles(prelude_dir, text, cert.name)


@needs_coquelicot
def test_the_k_s_2_5_data_forced_into_the_theorem1_unit_is_refused(prelude_dir):
    # the 2.5 model's A, B, C, D in the Theorem 1 unit, the 3.0 certificate's passive
    cert, thm1 = ks3_units()
    assert compiles(prelude_dir, cert.text, cert.name)
    text = thm1.text.replace("From Coq Require Import Reals Lia.",
                             "From Coq Require Import QArith Reals Lia List.\n"
                             "Import ListNotations.")
    for k, literal in _ks25_definitions().items():
        old = f"Definition {k} : QCert.matQ := {cert.name}.{k}."
        assert old in text
        text = text.replace(old, f"Definition {k} : QCert.matQ :=\n  {literal}%Q.")
    assert not compiles(prelude_dir, text, "Thm1Forced25")


ITEM2 = "  (forall t, 0 <= t <= T -> lam_min_spec (mmul (mT Rr) (Rl t)) lam) ->\n"
INTEGRAL = "V Rr Rb Rl (S_h 4 P x) t + RInt (fun s => ks * lam * phi"


@needs_coquelicot
@pytest.mark.parametrize("old,new", [
    (ITEM2, ""),  # Assumption 1, item 2 dropped
    # the dissipation inequality strengthened: twice the integral
    (INTEGRAL, "V Rr Rb Rl (S_h 4 P x) t + RInt (fun s => 2 * ks * lam * phi"),
    # the human's state bounded by V(0) instead of 2 V(0)
    ("QCert.qform 4 P (x t) <= 2 * V Rr Rb Rl (S_h 4 P x) 0",
     "QCert.qform 4 P (x t) <= V Rr Rb Rl (S_h 4 P x) 0"),
])
def test_theorem1_unit_mutations_make_coqc_fail(prelude_dir, old, new):
    cert, thm1 = ks3_units()
    assert compiles(prelude_dir, cert.text, cert.name)
    assert thm1.text.count(old) == 1, old
    assert not compiles(prelude_dir, thm1.text.replace(old, new), "Thm1Mutant")


@needs_coquelicot
@pytest.mark.parametrize("module,old,new", [
    # the KYP premise dropped from the closed loop (both sections)
    ("Thm1LTI", "Hypothesis cert : QCert.kyp_certified n m A B C D P.\n", ""),
    # M(P) <= 0 dropped from the certificate the storage theorems assume (slow, as the
    # next: each compiles a prelude file twice, a copy and a mutant)
    pytest.param(
        "LTIHuman", "Hypothesis cert : kyp_certified n m A B C D P.",
        "Hypothesis cert : has_shape n n A /\\ has_shape n m B /\\ has_shape m n C /\\ "
        "has_shape m m D /\\ has_shape n n P /\\ symmetric n P /\\ pos_def n P /\\ True.",
        marks=pytest.mark.slow),
    # the human's output pad drops the second port: the supply no longer matches
    pytest.param("Thm1LTI", "(if Nat.ltb 1 m then y 1%nat else 0)", "0",
                 marks=pytest.mark.slow),
])
def test_prelude_mutations_make_coqc_fail(prelude_dir, module, old, new):
    text = prelude_sources()[module]
    assert text.count(old) >= 1, old
    assert compiles(prelude_dir, text, f"{module}Copy")  # the control: unmutated copy
    assert not compiles(prelude_dir, text.replace(old, new), f"{module}Mutant")


@pytest.mark.slow  # compiles the trajectory prelude when the cache is cold (about 60 s CPU)
@needs_coquelicot
def test_gate_with_coq_names_the_closed_loop_theorem(tmp_path, capsys):
    import json

    from verify.cli import main

    m30 = ROOT / "verify" / "data" / "models" / "reconstructed_ks3p0.toml"
    rc = main(["gate", str(m30), str(KS25_MODEL), "--certificates", str(tmp_path / "c"),
               "--coq", str(tmp_path / "coq"), "--json", str(tmp_path / "g.json")])
    out = capsys.readouterr().out
    assert rc == 1, out  # the 2.5 model is not passive
    assert "coq: compiled by coqc, accepted" in out
    rows = json.loads((tmp_path / "g.json").read_text())
    rows = rows["results"] if isinstance(rows, dict) else rows
    by_name = {r["name"]: r for r in rows}
    ks3 = by_name["reconstructed k_s = 3.0"]
    assert ks3["coq_closed_loop_theorem"] == \
        "Thm1_reconstructed_k_s_3_0_99babda880e6.thm1_energy"
    assert by_name["reconstructed k_s = 2.5"]["coq_closed_loop_theorem"] is None
    written = {p.name for p in (tmp_path / "coq").iterdir()}
    assert "Thm1_reconstructed_k_s_3_0_99babda880e6.v" in written
    assert not any(n.startswith("Thm1_") and "2_5" in n for n in written)


def test_margin_certificates_get_no_theorem1_unit(tmp_path):
    # H + I/10 passive is not H passive: no Theorem 1 with that human
    from verify.cli import main

    m30 = ROOT / "verify" / "data" / "models" / "reconstructed_ks3p0.toml"
    assert main(["gate", str(m30), "--margin=-1/10", "--certificates", str(tmp_path)]) == 0
    [path] = list(tmp_path.glob("*.json"))
    units = kyp_units_from_file(path)
    assert [u.name.startswith("Cert_") for u in units] == [True]


@pytest.mark.slow  # compiles two small developments (the prelude from the cache)
@needs_coquelicot
def test_a_refused_theorem1_unit_leaves_lemma1_evidence_standing(monkeypatch):
    from dataclasses import replace

    from verify.claims import coq_conclusions as cc

    cert, thm1 = ks3_units()
    broken = replace(thm1, text=thm1.text.replace(ITEM2, "", 1))
    monkeypatch.setattr(cc, "ks3_units", lambda: (cert, broken))
    cc._compiled.cache_clear()
    try:
        assert cc.lemma1_kernel_evidence().passed
        evidence, tops = cc.thm1_kernel_evidence()
        assert not evidence.passed and "Thm1_" in evidence.summary
        assert tops == tuple(f"{thm1.name}.{t}" for t in thm1.theorems)
    finally:
        cc._compiled.cache_clear()
