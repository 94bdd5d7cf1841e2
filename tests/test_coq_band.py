"""Exact-band certificates checked by Coq's kernel (``BandCert.v``): witnesses, the
exporter's refusals, and attacks on the exported unit.

Tests that run ``coqc`` skip where it is not installed. The prelude is compiled once per
module; each attacked unit is then compiled alone.
"""

from __future__ import annotations

import json
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest
from coq_tools import compiles, run_coqc
from flint import fmpq, fmpq_poly
from gmpy2 import mpq

from verify.cli import main
from verify.coq import interval_witness as iw
from verify.coq.audit import audit_assumptions
from verify.coq.band_fd import band_fd_unit_from_file, band_unit, sign_polynomials
from verify.coq.development import coqc_available
from verify.coq.export import export_certificates
from verify.coq.kyp import CoqExportError
from verify.passivity.check.band_fd import band_polynomials
from verify.passivity.check.certificate import ExactModel

ROOT = Path(__file__).resolve().parents[1]
CERTS = ROOT / "certificates"
KS25 = CERTS / "reconstructed-k_s-2.5-band-0-1.5-f0739b7ae628.json"
MODELS = ROOT / "verify" / "data" / "models"

needs_coqc = pytest.mark.skipif(not coqc_available(), reason="coqc not installed")


def exact(A, B, C, D) -> ExactModel:
    return ExactModel(*([[mpq(Fraction(x)) for x in row] for row in M] for M in (A, B, C, D)))


def ks25() -> ExactModel:
    from verify.passivity.check.fd_certificate import model_from_json

    return model_from_json(json.loads(KS25.read_text()))


def poly(*coeffs) -> fmpq_poly:
    return fmpq_poly([fmpq(Fraction(c).numerator, Fraction(c).denominator) for c in coeffs])


# ---------------------------------------------------------------- witnesses (no coqc)


def test_witness_for_a_polynomial_with_roots_at_both_ends():
    p = poly(0, 2, -1)  # x (2 - x) on [0, 2]: zero at both ends, positive inside
    w = iw.find(p, fmpq(0), fmpq(2))
    assert w is not None and iw.check(p, fmpq(0), fmpq(2), w)


def test_an_irrational_tangency_inside_goes_into_the_square_factor():
    p = poly(4, 0, -4, 0, 1) * poly(1, 1)  # (x^2 - 2)^2 (x + 1) on [0, 3]
    w = iw.find(p, fmpq(0), fmpq(3))
    assert w is not None and w.g == poly(-2, 0, 1) and iw.check(p, fmpq(0), fmpq(3), w)


def test_no_witness_for_a_polynomial_negative_inside():
    p = poly(-1, 0, 1)  # x^2 - 1 < 0 on [0, 1)
    assert iw.find(p, fmpq(0), fmpq(2)) is None


def test_a_changed_witness_number_or_a_wider_interval_fails_the_replica():
    p = poly(3, -1)  # 3 - x on [0, 2]
    w = iw.find(p, fmpq(0), fmpq(2))
    assert w is not None
    piece = w.pieces[0]
    c, i, j = piece.terms[0]
    bad = iw.NonnegWitness(w.g, w.q, (iw.Piece(piece.u, piece.v,
                                                ((c + 1, i, j), *piece.terms[1:])),))
    assert not iw.check(p, fmpq(0), fmpq(2), bad)
    assert not iw.check(p, fmpq(0), fmpq(3), w)


def test_sign_polynomials_agree_with_the_exact_band_decision():
    """Coq's sign polynomials (trace and determinant of the Hermitian numerator) have the
    signs of the exact checker's F_k (computed another way) at rational frequencies."""
    model = ks25()
    mine = sign_polynomials(model)
    theirs = band_polynomials(model).F
    assert len(mine) == len(theirs) == 2
    for w in (fmpq(0), fmpq(1, 3), fmpq(3, 2), fmpq(2), fmpq(5, 2), fmpq(7)):
        assert [(p(w) > 0) - (p(w) < 0) for p in mine] == \
            [(F(w) > 0) - (F(w) < 0) for F in theirs], w
    assert mine[0](fmpq(3)) < 0  # beyond w = 2 the model is not passive


# ---------------------------------------------------------------- the exporter's refusals


def _tampered(tmp_path: Path, edit, name: str | None = None) -> Path:
    data = json.loads(KS25.read_text())
    edit(data)
    out = tmp_path / (name or KS25.name)
    out.write_text(json.dumps(data, indent=1))
    return out


def test_the_exporter_refuses_a_widened_band(tmp_path):
    def edit(data):
        data["band"] = ["0", "3"]
    with pytest.raises(CoqExportError, match="not exported"):
        band_fd_unit_from_file(_tampered(tmp_path, edit))


def test_the_exporter_refuses_a_changed_coefficient_of_the_model(tmp_path):
    def edit(data):
        data["model"]["A"][1][0] = "-3"
    with pytest.raises(CoqExportError, match="fingerprint"):
        band_fd_unit_from_file(_tampered(tmp_path, edit))


def test_the_exporter_refuses_a_certificate_of_another_model(tmp_path):
    """The k_s = 3.0 model under the k_s = 2.5 certificate's name and data."""
    other = json.loads((CERTS / "reconstructed-k_s-3.0-99babda880e6.json").read_text())

    def edit(data):
        data["model"] = other["model"]
        data["fingerprint"] = other["fingerprint"]
    with pytest.raises(CoqExportError, match="not exported"):
        band_fd_unit_from_file(_tampered(tmp_path, edit))


def test_the_exporter_finds_no_witness_beyond_the_passive_band():
    """Bypassing the Python checker: the claim on [0, 3] is false, no unit is written."""
    with pytest.raises(CoqExportError, match="no witness"):
        band_unit("X", model=ks25(), band=(Fraction(0), Fraction(3)), margin=Fraction(0),
                  label="x", source="x", fingerprint="x", origin="x")


def test_three_ports_are_refused_with_the_reason():
    model = exact([[-1]], [[1, 0, 0]], [[1], [0], [0]], [[1, 0, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(CoqExportError, match="one or two ports"):
        band_unit("X", model=model, band=(Fraction(0), Fraction(1)), margin=Fraction(0),
                  label="x", source="x", fingerprint="x", origin="x")


def test_the_paper_band_certificate_is_exported_not_listed():
    export = export_certificates([KS25])
    assert [u.name for u in export.units] == ["Cert_reconstructed_k_s_2_5_band_0_1_5_f0739b7ae628"]
    assert not export.not_exported
    text = export.units[0].text
    assert "Theorem passive_on_band : band_passive 4 2 A B C D w1 w2." in text
    assert "f0739b7ae628a192db3b213a05f7ac7f6403c55126008a80f1164da6071094aa" in text


# ---------------------------------------------------------------- coqc


@pytest.fixture(scope="module")
def paper_unit():
    return band_fd_unit_from_file(KS25).text


@needs_coqc
def test_coqc_accepts_the_paper_band_certificate_with_only_real_axioms(prelude_dir,
                                                                        paper_unit):
    assert compiles(prelude_dir, paper_unit, "Band25")
    done = _coqc_text(prelude_dir, "From VerifyCoq Require Band25.\n"
                      "Print Assumptions Band25.passive_on_band.\n")
    assert done.returncode == 0
    audit = audit_assumptions(done.stdout)
    assert audit.ok and audit.axioms, done.stdout


def _coqc_text(folder: Path, text: str) -> subprocess.CompletedProcess:
    (folder / "Probe.v").write_text(text)
    return run_coqc(folder, "Probe.v")


@needs_coqc
@pytest.mark.parametrize("old, new", [
    ("Definition w2 : Q := (3 # 2).", "Definition w2 : Q := (3 # 1)."),  # a widened band
    ("Definition w2 : Q := (3 # 2).", "Definition w2 : Q := (7 # 4)."),  # wider, still true
    ("[(-2 # 1); (-1 # 1); (0 # 1); (0 # 1)]", "[(-3 # 1); (-1 # 1); (0 # 1); (0 # 1)]"),
    # ^ a changed coefficient of the model (A), the witnesses kept
    ("[(-1 # 20); (0 # 20)]", "[(-1 # 20); (-1 # 20)]"),  # a changed coefficient of D
    ("((4096 # 243), 1%nat, 5%nat)", "((4097 # 243), 1%nat, 5%nat)"),  # a witness number
    ("Definition certs : list nonneg_cert := [cert1; cert2].",
     "Definition certs : list nonneg_cert := [cert1].")  # a dropped witness
])
def test_coqc_rejects_a_tampered_band_unit(prelude_dir, paper_unit, old, new):
    assert old in paper_unit
    assert not compiles(prelude_dir, paper_unit.replace(old, new, 1))


@needs_coqc
def test_coqc_rejects_the_witnesses_of_another_model(prelude_dir, paper_unit):
    """The k_s = 3.0 model's own unit on the same band compiles; its witnesses under the
    k_s = 2.5 model do not."""
    from verify.passivity.check.fd_certificate import model_from_json

    other = model_from_json(json.loads((CERTS / "reconstructed-k_s-3.0-99babda880e6.json")
                                       .read_text()))
    text = band_unit("Other", model=other, band=(Fraction(0), Fraction(3, 2)),
                     margin=Fraction(0), label="k_s = 3.0", source="x", fingerprint="x",
                     origin="test").text
    assert compiles(prelude_dir, text, "Other")
    start, end = "Definition cert1", "Definition certs"
    mixed = (paper_unit[:paper_unit.index(start)] + text[text.index(start):text.index(end)]
             + paper_unit[paper_unit.index(end):])
    assert mixed != paper_unit
    assert not compiles(prelude_dir, mixed)


@needs_coqc
def test_one_port_and_static_gain_units(prelude_dir):
    """H = (s + 2) / (s + 1) and a static gain 1 are passive on [0, 10]; -1 is not."""
    one = exact([[-1]], [[1]], [[1]], [[1]])
    gain = exact([], [], [[]], [[1]])
    for name, model in (("One", one), ("Gain", gain)):
        unit = band_unit(name, model=model, band=(Fraction(0), Fraction(10)),
                         margin=Fraction(0), label=name, source="x", fingerprint="x",
                         origin="test")
        assert compiles(prelude_dir, unit.text, name)
    with pytest.raises(CoqExportError, match="no witness"):
        band_unit("Neg", model=exact([], [], [[]], [[-1]]), band=(Fraction(0), Fraction(1)),
                  margin=Fraction(0), label="x", source="x", fingerprint="x", origin="x")


@needs_coqc
def test_gate_band_with_coq_writes_and_compiles_the_exact_band_unit(tmp_path, capsys):
    model = MODELS / "reconstructed_ks2p5.toml"
    rc = main(["gate", str(model), "--band", "0:3/2", "--margin=-1/10",
               "--certificates", str(tmp_path / "c"), "--coq", str(tmp_path / "coq")])
    out = capsys.readouterr().out
    assert rc == 0, out
    assert "coq: compiled by coqc, accepted" in out
    [unit] = [p for p in (tmp_path / "coq").iterdir() if p.name.startswith("Cert_")]
    text = unit.read_text()
    assert "Definition nu0 : Q := (-1 # 10)." in text
    assert "Theorem passive_on_band : band_passive 4 2 A B C D_shifted w1 w2." in text


# ---------------------------------------------------------------- positive-real certificates


def test_half_line_witness_with_a_bounded_part_and_its_replica():
    p = poly(4, 0, -4, 0, 1) * poly(1, 1) * poly(5, -4, 1)  # (x^2-2)^2 (x+1) (x^2-4x+5)
    w = iw.find_ray(p, fmpq(0))
    assert w is not None and iw.check_ray(p, fmpq(0), w)
    assert not iw.check_ray(p * poly(1, -1), fmpq(0), w)  # another polynomial
    assert iw.find_ray(poly(-1, 0, 1), fmpq(0)) is None  # x^2 - 1 < 0 on [0, 1)
    assert iw.find_ray(poly(1, 0, -1), fmpq(0)) is None  # 1 - x^2 < 0 beyond 1


@pytest.fixture(scope="module")
def pr_certificate(tmp_path_factory):
    """A positive-real certificate of the k_s = 3.0 model (the exact frequency route)."""
    from verify.passivity.check.fd_certificate import model_from_json
    from verify.passivity.fd_decision import decide_positive_real
    from verify.passivity.gate import store_pr_certificate

    model = model_from_json(json.loads((CERTS / "reconstructed-k_s-3.0-99babda880e6.json")
                                       .read_text()))
    verdict, reason, cert, _ = decide_positive_real(model, "k_s = 3.0", "")
    assert verdict == "passive" and cert is not None, reason
    path, _ = store_pr_certificate(cert, Fraction(0), tmp_path_factory.mktemp("pr"))
    return path


def test_positive_real_certificates_are_exported_with_their_pole_conditions(pr_certificate):
    from verify.coq.command import development_files

    export = export_certificates([pr_certificate])
    assert len(export.units) == 1 and not export.not_exported
    text = export.units[0].text
    assert "Theorem frequency_inequality : fdi_holds 4 2 A B C D." in text
    assert "Theorem stable : hurwitz 4 A." in text  # A Hurwitz: no pole with Re s >= 0
    assert export.units[0].theorems == ("frequency_inequality", "stable")
    assert not export.partly
    listed = json.loads(development_files(export)["NOT_EXPORTED.json"])
    assert listed == {"not_exported": []}


def test_a_positive_real_certificate_with_an_axis_pole_is_exported_in_part(tmp_path):
    from verify.coq.command import development_files
    from verify.passivity.fd_decision import decide_positive_real
    from verify.passivity.gate import store_pr_certificate

    integrator = exact([[0]], [[1]], [[1]], [[1]])  # 1/s + 1: positive real, pole at 0
    verdict, reason, cert, _ = decide_positive_real(integrator, "integrator", "")
    assert verdict == "passive" and cert is not None, reason
    path, _ = store_pr_certificate(cert, Fraction(0), tmp_path)
    export = export_certificates([path])
    assert export.units[0].theorems == ("frequency_inequality",)
    [partly] = export.partly
    assert partly.file == path.name and "pole conditions" in partly.reason
    listed = json.loads(development_files(export)["NOT_EXPORTED.json"])
    assert listed["not_kernel_checked"][0]["file"] == path.name


def test_the_exporter_refuses_a_tampered_positive_real_certificate(tmp_path, pr_certificate):
    from verify.coq.positive_real import pr_unit_from_file

    data = json.loads(pr_certificate.read_text())
    data["model"]["D"][0][1] = "1/10"
    bad = tmp_path / pr_certificate.name
    bad.write_text(json.dumps(data, indent=1))
    with pytest.raises(CoqExportError):
        pr_unit_from_file(bad)


@needs_coqc
def test_coqc_accepts_a_positive_real_unit_and_rejects_a_changed_one(prelude_dir,
                                                                     pr_certificate):
    from verify.coq.positive_real import pr_unit_from_file

    text = pr_unit_from_file(pr_certificate).text
    assert compiles(prelude_dir, text, "PR")
    # a Lyapunov witness that is not one: -LP is not positive definite
    lp = text.index("Definition LP : matQ :=")
    assert not compiles(prelude_dir, text[:lp] + text[lp:].replace("[(", "[(-", 1), "PR")
    old = "[(-1 # 20); (0 # 20)]"
    assert old in text
    assert not compiles(prelude_dir, text.replace(old, "[(-3 # 20); (0 # 20)]", 1))
    # a static gain -1/10 with the witnesses of another polynomial
    neg = text.replace("fdi_holds 4 2 A B C D.", "fdi_holds 4 2 A B C Dn.", 1).replace(
        "fdi_check_sound 4 2 A B C D certs", "fdi_check_sound 4 2 A B C Dn certs", 1)
    neg = neg.replace("(** Witnesses", "Definition Dn : matQ := msub D (scaled_identity 2 1)."
                      "\n(** Witnesses", 1)
    assert not compiles(prelude_dir, neg)
