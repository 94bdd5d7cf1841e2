"""Certificates checked by Coq's kernel: the exporter, the audit and attacks on both.

Tests that run ``coqc`` skip where it is not installed; the rest (witnesses, refusals,
the audit's reading of sources and of ``Print Assumptions``) run everywhere. The prelude
is compiled once per module, then each attacked unit alone.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from coq_tools import compiles
from gmpy2 import mpq

from verify.cli import main
from verify.coq.audit import audit_assumptions, forbidden_commands, printed_axioms
from verify.coq.command import development_files
from verify.coq.development import coqc_available, prelude_sources
from verify.coq.export import export_certificates, paper_development_units
from verify.coq.kyp import CoqExportError, kyp_unit_from_file
from verify.coq.witness import Witness, psd_witness, residual_dominant

ROOT = Path(__file__).resolve().parents[1]
CERTS = ROOT / "certificates"
KS3 = CERTS / "reconstructed-k_s-3.0-99babda880e6.json"
COMMITTED = CERTS / "coq"

needs_coqc = pytest.mark.skipif(not coqc_available(), reason="coqc not installed")


def q(rows):
    return [[mpq(x) for x in row] for row in rows]


# ---------------------------------------------------------------- witnesses (no coqc)


def test_witness_of_a_definite_matrix_is_accepted_by_the_python_replica():
    m = q([[4, 1, 0], [1, 3, 1], [0, 1, 2]])
    w = psd_witness(m, strict=True)
    assert w is not None and w.eps > 0 and residual_dominant(m, w)


def test_no_witness_for_an_indefinite_or_singular_matrix():
    assert psd_witness(q([[1, 2], [2, 1]])) is None
    assert psd_witness(q([[1, 0], [0, 0]]), strict=True) is None
    w = psd_witness(q([[1, 0], [0, 0]]))  # semidefinite: fine without strictness
    assert w is not None and w.eps == 0


def test_a_witness_for_one_matrix_fails_for_a_changed_one():
    m = q([[2, 1], [1, 2]])
    w = psd_witness(m, strict=True)
    assert w is not None
    changed = q([[2, 1], [1, 1]])
    assert not residual_dominant(changed, w)
    assert not residual_dominant(m, Witness(mpq(-1), w.terms, w.method))


def test_rounded_witness_for_a_large_float_matrix():
    import numpy as np

    rng = np.random.default_rng(3)
    G = rng.standard_normal((20, 20))
    F = G @ G.T + 20 * np.eye(20)
    m = [[mpq(float(x)) for x in row] for row in F]
    w = psd_witness(m, strict=True)
    assert w is not None and w.method.startswith("rounded") and residual_dominant(m, w)


# ---------------------------------------------------------------- exporter refusals


def _tampered(tmp_path: Path, edit) -> Path:
    data = json.loads(KS3.read_text())
    edit(data)
    out = tmp_path / KS3.name
    out.write_text(json.dumps(data, indent=1) + "\n")
    return out


def test_the_exporter_refuses_a_certificate_of_another_model(tmp_path):
    def edit(data):
        data["model"]["A"][1][0] = "-7/4"  # the fingerprint names the stored model
    with pytest.raises(CoqExportError, match="fingerprint"):
        kyp_unit_from_file(_tampered(tmp_path, edit))


def test_the_exporter_refuses_a_matrix_that_is_not_a_certificate(tmp_path):
    def edit(data):
        data["P"][0][0] = "-109/32"
    with pytest.raises(CoqExportError, match="P > 0"):
        kyp_unit_from_file(_tampered(tmp_path, edit))


def test_the_exporter_refuses_a_changed_statement(tmp_path):
    def edit(data):
        data["statement"] = "H is strictly passive"
    with pytest.raises(CoqExportError, match="statement"):
        kyp_unit_from_file(_tampered(tmp_path, edit))


def test_every_shipped_certificate_kind_is_exported():
    export = export_certificates([CERTS])
    names = {u.name for u in export.units}
    assert "Cert_reconstructed_k_s_3_0_99babda880e6" in names
    assert "Cert_reconstructed_k_s_2_5_band_0_1_5_f0739b7ae628" in names  # exact band
    robust = {u.name for u in export.units if "_robust_" in u.name}
    assert {n.split("_identified_")[0] for n in robust} == {"Cert_passive_human",
                                                           "Cert_nonpassive_human"}
    # what this export leaves are the paper's SOS certificates, which the paper's
    # development takes up with its steps (paper_development_units)
    assert {i.schema for i in export.not_exported} == {"verify-sos-certificate/1"}
    assert paper_development_units(CERTS).not_exported == ()


def test_a_file_that_is_no_certificate_is_listed_with_a_reason(tmp_path):
    shutil.copy(KS3, tmp_path / KS3.name)
    (tmp_path / "notes.json").write_text('{"schema": "something-else/1"}')
    export = export_certificates([tmp_path])
    assert [u.name for u in export.units][:1] == ["Cert_reconstructed_k_s_3_0_99babda880e6"]
    left = {i.file: i for i in export.not_exported}
    assert list(left) == ["notes.json"] and left["notes.json"].reason


def test_the_development_is_the_same_bytes_twice():
    from verify.coq.paper import derivation_exports, paper_derivations, paper_units

    a = development_files(paper_development_units(CERTS))
    b = development_files(paper_development_units(CERTS))
    assert a == b
    # the derivation units are exported once per process: a second, fresh export of
    # new derivation objects writes the same text
    fresh = derivation_exports(paper_derivations())[0]
    assert [(u.name, u.text) for u in fresh] == [(u.name, u.text) for u in paper_units()]


def test_the_unit_names_the_model_and_states_the_lmi():
    text = kyp_unit_from_file(KS3).text
    assert "99babda880e694ef995d0c7ea536c7385aff424110cd10f829a99cc382daffe8" in text
    assert "verify/data/models/reconstructed_ks3p0.toml" in text
    assert "Theorem passive : kyp_certified 4 2 A B C D P." in text


# ---------------------------------------------------------------- audit (no coqc)


def test_forbidden_commands_are_found_outside_comments_only():
    files = {"X.v": "(* Admitted in a comment is fine *)\nLemma a : True.\nProof. admit.\n"
                    "Admitted.\n", "Y.v": "Axiom oops : False.\n", "Z.txt": "Axiom"}
    found = forbidden_commands(files)
    assert found == ["X.v: admit", "X.v: Admitted", "Y.v: Axiom"]
    assert forbidden_commands({"W.v": '(* (* nested *) Axiom *) Definition s := "Axiom".'}) == []


def test_the_prelude_has_no_forbidden_command():
    assert forbidden_commands({f"{k}.v": v for k, v in prelude_sources().items()}) == []


PRINTED = """Axioms:
ClassicalDedekindReals.sig_forall_dec
  : forall P : nat -> Prop,
    (forall n : nat, {P n} + {~ P n}) -> {n : nat | ~ P n} + {forall n : nat, P n}
ProofIrrelevance.proof_irrelevance : forall (P : Prop) (p1 p2 : P), p1 = p2
Closed under the global context
"""


def test_print_assumptions_output_is_read_and_foreign_axioms_refused():
    assert printed_axioms(PRINTED) == ["ClassicalDedekindReals.sig_forall_dec",
                                       "ProofIrrelevance.proof_irrelevance"]
    audit = audit_assumptions(PRINTED)
    assert not audit.ok and audit.disallowed == ("ProofIrrelevance.proof_irrelevance",)
    assert audit_assumptions("Closed under the global context\n").ok


# ---------------------------------------------------------------- coqc


@needs_coqc
def test_coqc_accepts_the_k_s_3_certificate(prelude_dir):
    assert compiles(prelude_dir, kyp_unit_from_file(KS3).text)


@needs_coqc
@pytest.mark.parametrize("old, new", [
    ("[[(Wp 545); (Wp 128);", "[[(Wp 45); (Wp 128);"),  # a changed number of P
    ("[(Wn 3); (Wn 4); (Wp 0); (Wp 0)]", "[(Wp 3); (Wn 4); (Wp 0); (Wp 0)]"),
    # ^ the certificate against another model (A changed, P and witnesses kept)
    ("(160%positive, 1%positive,", "(16%positive, 1%positive,"),  # P's denominator changed
    ("[(Wn 1); (Wp 0)]].", "[(Wp 1); (Wp 0)]]."),  # D's integers do not match D
    ("((Wp 10500), (Wp 525),", "((Wp 10500), (Wp 1),"),  # a wrong witness (eps too large)
    ("kyp_certified 4 2 A B C D P.", "kyp_certified 4 2 A B C Dm P."),  # swapped: H - I
    ("WP wP wM).",
     "WP wP (let '(e, d, ws, L) := wM in (e, d, tl ws, tl L)))."),  # a dropped term
])
def test_coqc_rejects_a_tampered_unit(prelude_dir, old, new):
    text = kyp_unit_from_file(KS3).text
    assert old in text
    bad = text.replace(old, new, 1)
    if "Dm" in new:  # the statement swapped (H - I for H), the proof left as it was
        bad = bad.replace("WA WB WC D dD", "WA WB WC Dm dD")
        bad = bad.replace("(** The certificate. *)",
                          "Definition Dm : matQ := msub D (scaled_identity 2 1).\n")
    assert not compiles(prelude_dir, bad)


@needs_coqc
def test_a_strengthened_statement_is_rejected(prelude_dir):
    """Claiming M(P) < 0 (strict) where the certificate only gives <= 0."""
    text = kyp_unit_from_file(KS3).text
    extra = ("\nTheorem too_strong : pos_def 6 (mneg (kyp A B C D P)).\n"
             "Proof. apply (pd_check_sound 6 _ (1 # 1000) []). vm_compute. reflexivity. Qed.\n")
    assert not compiles(prelude_dir, text + extra)


def test_the_committed_development_is_current():
    fresh = development_files(paper_development_units(CERTS))
    # coqc run by hand in the folder leaves build products (.vo, .glob, .nra.cache), which
    # git ignores; the committed development is the sources
    build_products = {".vo", ".vok", ".vos", ".glob"}
    committed = {p.name: p.read_text() for p in COMMITTED.iterdir()
                 if p.is_file() and not p.name.startswith(".")
                 and p.suffix not in build_products}
    assert committed == fresh, "certificates/coq/ differs from a fresh export"


@pytest.mark.slow  # about 40 CPU seconds; .ci/run compiles the committed development itself
@needs_coqc
def test_the_committed_development_is_accepted(tmp_path):
    assert main(["coq", "--check", "--out", str(tmp_path / "dev")]) == 0


@needs_coqc
def test_gate_with_coq_compiles_the_gate_certificate(tmp_path, capsys):
    model = ROOT / "verify" / "data" / "models" / "reconstructed_ks3p0.toml"
    rc = main(["gate", str(model), "--margin=-1/10", "--certificates", str(tmp_path / "c"),
               "--coq", str(tmp_path / "coq")])
    out = capsys.readouterr().out
    assert rc == 0, out
    assert "coq: compiled by coqc, accepted" in out
    units = [p for p in (tmp_path / "coq").iterdir() if p.name.startswith("Cert_")]
    assert len(units) == 1
    text = units[0].read_text()  # the margin is in the statement, D - nu0 I computed by Coq
    assert "Definition nu0 : Q := (-1 # 10)." in text
    assert "Theorem passive : kyp_certified 4 2 A B C D_shifted P." in text


@needs_coqc
def test_coqc_accepts_a_rounded_witness_and_rejects_it_for_a_changed_matrix(prelude_dir):
    """Long entries take the rounded-Cholesky route; Coq re-checks its residual."""
    big = mpq(2**200 + 1, 2**199)  # about 2, with 200-bit numerator and denominator
    m = q([[big, 1, 0], [1, big, 1], [0, 1, big]])
    w = psd_witness(m, strict=True)
    assert w is not None and w.method.startswith("rounded")
    from verify.coq.kyp import matrix_literal, q_literal, terms_literal

    def unit(matrix):
        return ("From Coq Require Import QArith List.\nFrom VerifyCoq Require Import QCert.\n"
                "Import ListNotations.\nLocal Open Scope Q_scope.\n"
                f"Definition M : matQ := {matrix_literal(matrix)}.\n"
                f"Definition e : Q := {q_literal(w.eps)}.\n"
                f"Definition ws : list term := {terms_literal(w)}.\n"
                "Theorem t : pos_def 3 M.\n"
                "Proof. apply (pd_check_sound 3 M e ws). vm_compute. reflexivity. Qed.\n")
    assert compiles(prelude_dir, unit(m), "Rounded")
    changed = [row[:] for row in m]
    changed[0][0] = mpq(1, 2)  # no longer dominant after the same terms
    assert not residual_dominant(changed, w)
    assert not compiles(prelude_dir, unit(changed), "Rounded")


def test_coq_command_refuses_a_missing_input(tmp_path, capsys):
    assert main(["coq", str(tmp_path / "nope.json"), "--out", str(tmp_path / "o")]) == 2
    assert "no such file" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_verify_all_step_writes_the_paper_development_only_into_an_existing_folder(tmp_path):
    from verify.coq.command import write_paper_development

    missing = tmp_path / "none"
    assert "no Coq development written" in write_paper_development(missing)
    assert not missing.exists()
    certs = tmp_path / "certs"
    certs.mkdir()
    shutil.copy(KS3, certs / KS3.name)
    write_paper_development(certs)
    written = {p.name: p.read_text() for p in (certs / "coq").iterdir()}
    assert written == development_files(paper_development_units(certs))
    # the certificate's unit and Theorem 1 with its human: modules of one bundle
    assert "Module Cert_reconstructed_k_s_3_0_99babda880e6." in written["Certificates.v"]
    assert "Module Thm1_reconstructed_k_s_3_0_99babda880e6." in written["Certificates.v"]


def test_coq_command_on_a_certificate_of_another_model_exits_1(tmp_path, capsys):
    def edit(data):
        data["model"]["C"][0][0] = "1"
    bad = _tampered(tmp_path, edit)
    assert main(["coq", str(bad), "--out", str(tmp_path / "dev")]) == 1
    out = capsys.readouterr().out
    assert "not exported" in out and "fingerprint" in out
    listed = json.loads((tmp_path / "dev" / "NOT_EXPORTED.json").read_text())
    assert [i["file"] for i in listed["not_exported"]] == [KS3.name]
    assert not [p for p in (tmp_path / "dev").iterdir() if p.name.startswith("Cert_")]


def test_rewriting_a_development_removes_units_no_longer_exported(tmp_path):
    from verify.coq.command import write_export

    certs = tmp_path / "certs"
    certs.mkdir()
    shutil.copy(KS3, certs / KS3.name)
    out = tmp_path / "dev"
    write_export(out, export_certificates([certs]))
    (out / "notes.txt").write_text("mine")
    assert (out / "Cert_reconstructed_k_s_3_0_99babda880e6.v").exists()
    write_export(out, export_certificates([tmp_path / "empty"]))
    assert not (out / "Cert_reconstructed_k_s_3_0_99babda880e6.v").exists()
    assert (out / "notes.txt").read_text() == "mine" and (out / "QCert.v").exists()


def test_the_paper_development_has_no_forbidden_command():
    files = development_files(paper_development_units(CERTS))
    assert forbidden_commands(files) == []
    top = files["All.v"].split("Definition top_theorems : unit :=", 1)[1]
    assert "Print Assumptions top_theorems." in top
    words = top.split("Definition word_theorems : unit :=", 1)[1]  # checked on machine integers
    assert "Cert_reconstructed_k_s_3_0_99babda880e6.passive" in words
    assert words.rstrip().endswith("Print Assumptions word_theorems.")


@pytest.mark.parametrize("case", ["not-json", "no-schema", "out-is-input"])
def test_coq_command_refuses_bad_input_in_one_line_and_writes_nothing(tmp_path, capsys, case):
    out = tmp_path / "dev"
    if case == "not-json":
        arg = tmp_path / "x.json"
        arg.write_text("not json")
    elif case == "no-schema":
        arg = tmp_path / "x.json"
        arg.write_text("{}")
    else:
        arg = tmp_path / KS3.name
        shutil.copy(KS3, arg)
        out = tmp_path
    before = sorted(p.name for p in tmp_path.iterdir())
    assert main(["coq", str(arg), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == before


@pytest.fixture(scope="module")
def band_certificate(tmp_path_factory):
    """A generalized KYP certificate of the k_s = 2.5 model on [0, 3/2] (the gate's band
    route with the exact band decision turned off)."""
    from fractions import Fraction

    from verify.passivity.gate import run_band_gate
    from verify.passivity.io.model_file import load_model

    folder = tmp_path_factory.mktemp("band")
    model = load_model(ROOT / "verify" / "data" / "models" / "reconstructed_ks2p5.toml")
    [result] = run_band_gate([model], (Fraction(0), Fraction(3, 2)), Fraction(0), folder,
                             exact_first=False)
    assert result.certificate_path is not None
    assert json.loads(result.certificate_path.read_text())["schema"].startswith(
        "verify-gkyp-certificate")
    return result.certificate_path


def test_band_certificates_are_exported(band_certificate):
    from verify.coq.band import gkyp_unit_from_file

    unit = gkyp_unit_from_file(band_certificate)
    assert "Theorem passive_on_band : gkyp_certified 4 2 A B C D Pr Pi Qr Qi w1 w2." in unit.text
    assert "Definition w2 : Q := (3 # 2)." in unit.text
    export = export_certificates([band_certificate.parent])
    assert [u.name for u in export.units] == [unit.name] and not export.not_exported


@needs_coqc
def test_coqc_accepts_a_band_certificate_and_rejects_a_wider_band(prelude_dir,
                                                                  band_certificate):
    from verify.coq.band import gkyp_unit_from_file

    text = gkyp_unit_from_file(band_certificate).text
    assert compiles(prelude_dir, text, "Band")
    wider = text.replace("Definition w2 : Q := (3 # 2).", "Definition w2 : Q := (5 # 1).")
    assert not compiles(prelude_dir, wider, "Band")


def test_gate_refuses_a_coq_folder_that_is_the_certificates_folder(tmp_path, capsys):
    model = ROOT / "verify" / "data" / "models" / "reconstructed_ks3p0.toml"
    assert main(["gate", str(model), "--certificates", str(tmp_path / "c"),
                 "--coq", str(tmp_path / "c")]) == 2
    assert "--coq" in capsys.readouterr().err
    assert not (tmp_path / "c").exists()


@pytest.fixture(scope="module")
def pivot_row_unit():
    """The Coq unit of a gate certificate whose P has long pivot rows and short dyadic
    entries elsewhere (a 6-state port-Hamiltonian model with D = 0: P B = C^T binds)."""
    from fractions import Fraction

    import numpy as np

    from verify.coq.kyp import kyp_unit
    from verify.passivity.decision import decide
    from verify.passivity.model import from_state_space
    from verify.passivity.port_hamiltonian import random_port_hamiltonian
    from verify.passivity.search.canonical import coarse_kyp

    A, B, C, D = random_port_hamiltonian(6, 2, np.random.default_rng([11, 6]), False)
    d = decide(from_state_space(A, B, C, D, name="pH n=6"))
    assert d.certificate is not None, d.reason
    model = d.certificate.model
    P = coarse_kyp(model, d.certificate.P)
    return kyp_unit("PivotRows", model=model, P=P, margin=Fraction(0), label="pH n=6",
                    source="(test)", fingerprint=model.fingerprint(), origin="test").text


def _p_block(text: str) -> str:
    return text[text.index("Definition WP : wmat"):text.index("(** Witnesses")]


def test_a_matrix_with_long_and_short_entries_is_written_over_two_denominators(
        pivot_row_unit):
    import re

    block = _p_block(pivot_row_unit)
    short, long = map(int, re.search(r"\((\d+)%positive, (\d+)%positive,", block).groups())
    assert short & (short - 1) == 0 and long.bit_length() > short.bit_length() + 64
    assert "true [" in block and "(Wp " in block  # long entries over the second one
    paper = _p_block(kyp_unit_from_file(KS3).text)  # short rationals: one denominator
    assert "(160%positive, 1%positive," in paper and "(Wl " not in paper


@needs_coqc
def test_coqc_accepts_pivot_rows_and_rejects_a_changed_long_entry(prelude_dir,
                                                                 pivot_row_unit):
    import re

    assert compiles(prelude_dir, pivot_row_unit, "PivotRows")
    block = _p_block(pivot_row_unit)
    entry = re.search(r"\(Wl (true|false) true \[(\d+);", block)
    assert entry is not None
    changed = block.replace(entry.group(0),
                            f"(Wl {entry.group(1)} true [{int(entry.group(2)) ^ 1};", 1)
    assert not compiles(prelude_dir, pivot_row_unit.replace(block, changed), "PivotRows")


@needs_coqc
def test_coq_sums_over_several_denominators_exactly(prelude_dir):
    """QCert's dot product and row sums by bins of denominators compute the exact value
    (and a wrong value is refused)."""
    def unit(value: str) -> str:
        return ("From Coq Require Import QArith List.\nFrom VerifyCoq Require Import QCert.\n"
                "Import ListNotations.\nLocal Open Scope Q_scope.\n"
                "Example e1 : Qeq_bool (dot [(1 # 2); (2 # 6); (3 # 2)] "
                "[(1 # 1); (2 # 5); (1 # 1)]) " + value + " = true.\n"
                "Proof. vm_compute. reflexivity. Qed.\n"
                "Example e2 : Qeq_bool (sumQb 3 (fun j => nth j [(1 # 2); (1 # 3); (1 # 2)] 0))"
                " (4 # 3) = true.\nProof. vm_compute. reflexivity. Qed.\n")
    assert compiles(prelude_dir, unit("(32 # 15)"), "Bins")  # 1/2 + 2/15 + 3/2
    assert not compiles(prelude_dir, unit("(31 # 15)"), "Bins")


@pytest.mark.slow  # about 15 CPU seconds (the 30-state unit: about 10 s in coqc)
@needs_coqc
def test_gate_with_coq_on_a_30_state_model(tmp_path, capsys):
    """A 30-state strictly proper model (P B = C^T binds) through ``verify gate --coq``:
    the stored certificate has short entries off two pivot rows and coqc accepts it."""
    from decimal import Decimal

    import numpy as np

    from verify.passivity.port_hamiltonian import random_port_hamiltonian

    A, B, C, D = random_port_hamiltonian(30, 2, np.random.default_rng([11, 30]), False)

    def mat(M) -> str:  # each float as its exact decimal expansion
        return "[" + ", ".join("[" + ", ".join(format(Decimal(float(x)), "f") + ".0"
                                               if float(x).is_integer() else
                                               format(Decimal(float(x)), "f") for x in row)
                               + "]" for row in M) + "]"
    model = tmp_path / "ph30.toml"
    model.write_text(f'name = "pH 30"\n\n[state_space]\nA = {mat(A)}\nB = {mat(B)}\n'
                     f"C = {mat(C)}\nD = {mat(D)}\n")
    rc = main(["gate", str(model), "--certificates", str(tmp_path / "c"),
               "--coq", str(tmp_path / "coq")])
    out = capsys.readouterr().out
    assert rc == 0, out
    assert "coq: compiled by coqc, accepted" in out
    [cert] = list((tmp_path / "c").glob("*.json"))
    P = [[mpq(x) for x in row] for row in json.loads(cert.read_text())["P"]]
    bits = sorted(max(int(x.numerator).bit_length(), int(x.denominator).bit_length())
                  for row in P for x in row)
    assert bits[-1] > 100 and bits[-(2 * 2 * 30)] <= 40  # long only in 2 rows and columns
