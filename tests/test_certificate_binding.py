"""Certificates bound to their claims: every mislabelled kind is refused, shipped ones pass.

Each test builds a genuine certificate with ``verify gate`` in a temporary directory,
mislabels it in one way, and expects ``verify certificates check`` to refuse it with one
line naming the file and the reason (exit 1). The certificate's bytes must depend only on
the model and the claim.
"""

from __future__ import annotations

import json
import os
import shutil
from fractions import Fraction
from pathlib import Path

import pytest

from verify.certificates.registry import SCHEMAS, check_stored_certificate
from verify.cli import main
from verify.passivity import load_model
from verify.passivity.gate import run_band_gate
from verify.passivity.io.binding import Claim, file_name, statement

ROOT = Path(__file__).resolve().parents[1]
MODELS = ROOT / "verify" / "data" / "models"
EXAMPLE = MODELS / "example_state_space.toml"
KS30, KS25 = MODELS / "reconstructed_ks3p0.toml", MODELS / "reconstructed_ks2p5.toml"

#: Shipped before models were realised exactly: its stored model is a floating-point
#: realisation of the transfer function that this machine's libraries no longer reproduce
#: bit for bit, so it is (rightly) not bound to its source file. It disappears when
#: certificates/ is regenerated from exact realisations.
FLOAT_REALISED: set[str] = set()


def gate(*args: str | Path) -> None:
    assert main(["gate", *map(str, args)]) in (0, 1)


@pytest.fixture(scope="module")
def made(tmp_path_factory) -> dict[str, Path]:
    """Genuine certificates: KYP, KYP with a margin, band; made once per module."""
    d = tmp_path_factory.mktemp("certs")
    gate(EXAMPLE, "--certificates", d)
    gate(EXAMPLE, "--margin=-1/4", "--certificates", d)
    # the band route that holds P and Q (the exact route's certificate has its own
    # hostile cases in test_band_exact_hostile.py)
    run_band_gate([load_model(KS25)], (Fraction(0), Fraction(3, 2)), Fraction(0), d,
                  exact_first=False)
    files = sorted(d.glob("*.json"))
    kinds = {}
    for f in files:
        data = json.loads(f.read_text())
        kinds["band" if "band" in data else "margin" if data["margin"] != "0" else "kyp"] = f
    assert set(kinds) == {"kyp", "margin", "band"}
    return kinds


@pytest.fixture
def cert(made, tmp_path):
    """A fresh copy of one genuine certificate: cert("kyp") -> (path, data)."""
    def copy(kind: str = "kyp") -> tuple[Path, dict]:
        path = tmp_path / made[kind].name
        shutil.copy(made[kind], path)
        return path, json.loads(path.read_text())
    return copy


def refused(path: Path, capsys, reason: str) -> None:
    """`verify certificates check PATH` refuses with one line naming the file and reason."""
    capsys.readouterr()
    assert main(["certificates", "check", str(path)]) == 1
    out = capsys.readouterr().out.strip().splitlines()
    bad = [line for line in out if line.startswith("INVALID")]
    assert len(bad) == 1 and str(path) in bad[0] and reason in bad[0], out


def write(path: Path, data: dict) -> Path:
    path.write_text(json.dumps(data, indent=1) + "\n")
    return path


def rename_to_content(path: Path, data: dict) -> Path:
    """Move the file to the name its (edited) content asks for, so only the edit counts."""
    from verify.passivity.io.binding import claim_from_fields

    claim = claim_from_fields(data.get("margin", "0"), data.get("band"))
    new = path.with_name(file_name(data["name"], claim, data["fingerprint"]))
    path.rename(new)
    return write(new, data)


# ---------------------------------------------------------------------- genuine ones pass


def test_fresh_certificates_pass_and_are_bound_to_their_source(made, capsys):
    for path in made.values():
        c = check_stored_certificate(path)
        assert c.ok, c.reason
        assert "exactly the one" in c.reason  # the source file was found and compared
    assert main(["certificates", "check", str(next(iter(made.values())).parent)]) == 0


@pytest.mark.parametrize("path", sorted((ROOT / "certificates").glob("*.json")),
                         ids=lambda p: p.name)
def test_shipped_certificates_pass(path, monkeypatch):
    if path.name in FLOAT_REALISED:
        pytest.xfail("stored model is a float realisation not reproduced here")
    monkeypatch.chdir(ROOT)
    c = check_stored_certificate(path)
    assert c.ok, c.reason


def test_a_static_gain_certificate(tmp_path):
    model = tmp_path / "gain.toml"
    model.write_text('name = "gain"\n[state_space]\nA = []\nB = []\nC = []\n'
                     "D = [[1, 1], [-1, 0]]\n")
    gate(model, "--certificates", tmp_path)
    (path,) = tmp_path.glob("*.json")
    assert check_stored_certificate(path).ok


# ------------------------------------------------------------------- mislabelled: refused


def test_wrong_name_is_refused(cert, capsys):
    path, data = cert()
    data["name"] = "someone else's model"
    refused(write(path, data), capsys, "file name does not match")
    refused(rename_to_content(path, data), capsys, "not the source file's model name")


def test_source_naming_another_model_file_is_refused(cert, capsys):
    path, data = cert()
    data["source"] = str(KS30)
    refused(write(path, data), capsys, "denotes another model")


def test_source_file_edited_after_certification_is_refused(tmp_path, capsys):
    model = tmp_path / "m.toml"
    model.write_text(EXAMPLE.read_text())
    gate(model, "--certificates", tmp_path)
    (path,) = tmp_path.glob("*.json")
    assert check_stored_certificate(path).ok
    model.write_text(EXAMPLE.read_text().replace("[-1.0, 0.0]", "[-1.5, 0.0]"))
    refused(path, capsys, "denotes another model")
    model.write_text("not = [toml")
    refused(path, capsys, "is not a valid model file")


def test_unverified_field_contradicting_the_source_is_refused(cert, capsys):
    path, data = cert()
    data["unverified"]["description"] = "measured on the paper's operator"
    refused(write(path, data), capsys, "unverified.description")


def test_margin_1000_is_refused(cert, capsys):
    path, data = cert()
    data["margin"] = "1000"
    refused(write(path, data), capsys, "file name does not match")
    path = rename_to_content(path, data)
    refused(path, capsys, "statement is not the one derived")
    data["statement"] = statement(Claim(margin=1000))
    refused(write(path, data), capsys, "does not prove passive with margin 1000")


def test_margin_claim_needs_its_own_proof(cert, capsys):
    """A certificate of H + I/4 (margin -1/4) proves neither margin 1/4 nor margin 0."""
    path, data = cert("margin")
    assert check_stored_certificate(path).ok
    for margin in ("1/4", "0"):
        edited = dict(data, margin=margin, statement=statement(Claim(margin=Fraction(margin))))
        new = rename_to_content(path, edited)
        assert not check_stored_certificate(new).ok
        path = new


def test_free_statement_is_refused(cert, capsys):
    path, data = cert()
    data["statement"] = "strictly passive with margin 5"
    refused(write(path, data), capsys, "statement is not the one derived")


def test_legacy_meta_margin_other_than_zero_is_refused(tmp_path, capsys):
    # a schema-1 certificate as shipped before models were read exactly (source detached)
    shipped = Path(__file__).parent / "data" / "legacy" / "reconstructed-k_s-3.0-dfa80a2f58eb.json"
    assert check_stored_certificate(shipped).status == "unbound"  # its source is not shipped
    assert check_stored_certificate(shipped, allow_unbound=True).ok
    data = json.loads(shipped.read_text())
    data["meta"]["margin"] = "1000"
    refused(write(tmp_path / shipped.name, data), capsys, "margin 0 only")
    data = json.loads(shipped.read_text())
    data["statement"] = "strictly passive with margin 5"
    refused(write(tmp_path / shipped.name, data), capsys, "statement is not the one derived")


def test_duplicate_key_is_refused_even_when_both_values_agree(cert, capsys):
    path, data = cert()
    text = json.dumps(data, indent=1)
    p_text = json.dumps(data["P"])
    path.write_text(text.replace('"P":', f'"P": {p_text},\n "P":', 1))
    refused(path, capsys, "duplicate key 'P'")
    bad = json.dumps([["1000"] * len(row) for row in data["P"]])
    path.write_text(text.replace('"P":', f'"P": {bad},\n "P":', 1))  # json keeps the last
    refused(path, capsys, "duplicate key 'P'")


@pytest.mark.parametrize("where", ["top", "model", "unverified", "P-object"])
def test_unknown_field_is_refused(cert, capsys, where):
    kind = "band" if where == "P-object" else "kyp"
    path, data = cert(kind)
    {"top": data, "model": data["model"], "unverified": data["unverified"],
     "P-object": data["P"]}[where]["verified_by"] = "me"
    refused(write(path, data), capsys, "unknown field(s) 'verified_by'")


def test_missing_field_is_refused(cert, capsys):
    path, data = cert()
    del data["fingerprint"]
    refused(write(path, data), capsys, "missing field(s) 'fingerprint'")


def test_empty_directory_is_not_success(tmp_path, capsys):
    (tmp_path / "notes.txt").write_text("no certificates here")
    assert main(["certificates", "check", str(tmp_path)]) == 1
    captured = capsys.readouterr()
    assert captured.out == "" and len(captured.err.strip().splitlines()) == 1
    assert "no certificate found" in captured.err and str(tmp_path) in captured.err
    assert main(["certificates", "check", str(tmp_path / "missing")]) == 2


def test_tampered_matrices_are_refused(cert, capsys):
    path, data = cert()
    data["P"][0][0] = "1/1000"
    refused(write(path, data), capsys, "does not prove passive")
    path, data = cert("band")
    data["Q"]["re"][0][0] = "-1"
    refused(write(path, data), capsys, "does not prove passive on [0, 3/2]")


def test_band_edited_is_refused(cert, capsys):
    path, data = cert("band")
    data["band"] = ["0", "5"]
    refused(write(path, data), capsys, "file name does not match")
    data["statement"] = statement(Claim(band=(0, 5)))
    refused(rename_to_content(path, data), capsys, "does not prove passive on [0, 5]")


def test_renamed_file_is_refused(cert, capsys):
    path, _ = cert()
    renamed = path.with_name("my-certificate.json")
    path.rename(renamed)
    refused(renamed, capsys, "file name does not match the content")


def test_model_edited_is_refused_by_fingerprint(cert, capsys):
    path, data = cert()
    data["model"]["A"][0][0] = "-5"
    refused(write(path, data), capsys, "fingerprint does not match")


@pytest.mark.parametrize("text, reason", [
    ("{not json", "not valid JSON"),
    ("[1, 2]", "not an object"),
    ('{"schema": "verify-kyp-certificate/9"}', "unknown schema"),
    ('{"schema": "verify-kyp-certificate/2", "x": NaN}', "NaN"),
    ("[" * 100000 + "]" * 100000, "not valid JSON"),
    (b"\xff\xfe{}", "not UTF-8"),
])
def test_malformed_files_are_refused_in_one_line(tmp_path, capsys, text, reason):
    path = tmp_path / "c.json"
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text)
    refused(path, capsys, reason)


@pytest.mark.parametrize("entry, reason", [
    ("2/4", "not in lowest terms"), ("1e3", "is not a rational"), ("3/1", "lowest terms"),
    (" 1", "is not a rational"), (1, "expected a rational as a string"),
    ("9" * 200_000, "is not a rational"),
])
def test_non_canonical_rationals_are_refused(cert, capsys, entry, reason):
    path, data = cert()
    data["P"][0][0] = entry
    refused(write(path, data), capsys, reason)


def test_one_bad_file_does_not_hide_the_others(made, cert, capsys):
    path, data = cert()
    data["statement"] = "strictly passive"
    write(path, data)
    shutil.copy(made["band"], path.parent / made["band"].name)
    capsys.readouterr()
    assert main(["certificates", "check", str(path.parent)]) == 1
    lines = capsys.readouterr().out.splitlines()
    assert sum(line.startswith(f"INVALID {path}: statement") for line in lines) == 1
    assert sum(line.startswith("ok ") for line in lines) == 1
    assert lines[-1].startswith("1 of 2 certificate(s) valid")


def test_schema_registry_is_one_line_per_kind():
    assert {"verify-kyp-certificate/1", "verify-kyp-certificate/2",
            "verify-gkyp-certificate/1", "verify-gkyp-certificate/2"} <= set(SCHEMAS)
    assert all(callable(check) for check in SCHEMAS.values())


# -------------------------------------------------------------------------- reproducible


def test_certificate_bytes_depend_only_on_model_and_claim(tmp_path, made):
    for run in ("a", "b"):
        gate(EXAMPLE, "--certificates", tmp_path / run)
        gate(EXAMPLE, "--margin=-1/4", "--certificates", tmp_path / run)
        gate(KS25, "--band", "0:1.5", "--certificates", tmp_path / run)
    a = {p.name: p.read_bytes() for p in (tmp_path / "a").glob("*.json")}
    b = {p.name: p.read_bytes() for p in (tmp_path / "b").glob("*.json")}
    assert a == b and len(a) == 3  # same layout (model file relative to the folder)

    def but_source(data: bytes) -> dict:
        out = json.loads(data)
        assert not Path(out.pop("source")).is_absolute()
        return out

    # elsewhere, only the source's path relative to the certificate's folder differs (the
    # band certificate made here is the exact route's, the module's one the GKYP route's)
    same = {p.name: but_source(p.read_bytes()) for kind, p in made.items() if kind != "band"}
    assert len(same) == 2 and {k: but_source(a[k]) for k in same} == same
    mask = os.umask(0)
    os.umask(mask)
    assert all((p.stat().st_mode & 0o777) == 0o666 & ~mask for p in (tmp_path / "a").iterdir())


def test_a_valid_existing_certificate_is_kept_and_a_broken_one_replaced(tmp_path, monkeypatch,
                                                                        capsys):
    # a copy of the repository's layout: certificates/ and the model file it names
    repo = tmp_path / "repo"
    model = repo / "verify" / "data" / "models" / KS30.name
    model.parent.mkdir(parents=True)
    shutil.copy(KS30, model)
    monkeypatch.chdir(repo)
    (shipped,) = (ROOT / "certificates").glob("reconstructed-k_s-3.0-*.json")
    kept = repo / "certificates" / shipped.name
    kept.parent.mkdir()
    shutil.copy(shipped, kept)
    capsys.readouterr()
    # the shipped file names its source from the repository root, the gate would write
    # ../verify/...: the same file, so the same claim, and the valid file is kept
    gate("verify/data/models/reconstructed_ks3p0.toml", "--certificates", "certificates")
    assert kept.read_bytes() == shipped.read_bytes()  # valid, same claim: kept
    assert "(kept: already a valid certificate" in capsys.readouterr().out
    data = json.loads(shipped.read_text())
    data["P"][0][0] = "1"
    write(kept, data)
    gate("verify/data/models/reconstructed_ks3p0.toml", "--certificates", "certificates")
    fresh = json.loads(kept.read_text())
    assert fresh["schema"] == "verify-kyp-certificate/2"
    assert check_stored_certificate(kept).ok


def test_source_not_found_is_unbound_and_refused_unless_allowed(cert, capsys):
    """A source that cannot be found binds nothing: unbound, exit 1; with --allow-unbound
    accepted, and the summary names the labels left unchecked."""
    path, data = cert()
    data["source"] = "elsewhere/model.toml"
    c = check_stored_certificate(write(path, data))
    assert not c.ok and c.status == "unbound"
    assert "source elsewhere/model.toml not found" in c.reason
    assert c.unchecked == ("name", "unverified.description")
    capsys.readouterr()
    assert main(["certificates", "check", str(path)]) == 1
    out = capsys.readouterr().out
    assert out.startswith("UNBOUND") and "1 unbound, not accepted" in out
    assert main(["certificates", "check", "--allow-unbound", str(path)]) == 0
    out = capsys.readouterr().out
    assert "1 unbound, accepted (--allow-unbound); labels not checked:" in out
    assert f"  {path}: name, unverified.description" in out
