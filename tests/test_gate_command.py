"""`verify gate` and `verify certificates check`: exit codes, outputs, tampering."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from fractions import Fraction
from pathlib import Path

import pytest

from verify.cli import main

MODELS = Path(__file__).resolve().parents[1] / "verify" / "data" / "models"


def test_gate_on_shipped_models_writes_checked_certificates_and_reports(tmp_path, capsys):
    certs = tmp_path / "certs"
    code = main(["gate", *map(str, sorted(MODELS.glob("*.toml"))), "--certificates",
                 str(certs), "--json", str(tmp_path / "g.json"), "--junit",
                 str(tmp_path / "g.xml")])
    assert code == 1  # the reconstructed k_s = 2.5 model is not passive
    data = {d["name"]: d for d in json.loads((tmp_path / "g.json").read_text())}
    assert data["reconstructed k_s = 3.0"]["verdict"] == "passive"
    bad = data["reconstructed k_s = 2.5"]
    assert bad["verdict"] == "not passive" and bad["witness"]["kind"] == "frequency"
    assert Fraction(bad["witness"]["omega"]) > 2  # the violation is only above 2 rad/s
    suite = ET.parse(tmp_path / "g.xml").getroot()
    assert suite.get("tests") == "3" and suite.get("failures") == "1"
    assert main(["certificates", "check", str(certs)]) == 0
    assert len(list(certs.glob("*.json"))) == 2


def test_gate_exit_0_when_all_passive(tmp_path):
    assert main(["gate", str(MODELS / "reconstructed_ks3p0.toml"), "--certificates",
                 str(tmp_path)]) == 0


def test_tampered_certificate_is_rejected(tmp_path, capsys):
    main(["gate", str(MODELS / "example_state_space.toml"), "--certificates", str(tmp_path)])
    (path,) = tmp_path.glob("*.json")
    data = json.loads(path.read_text())
    data["P"][0][0] = "1/1000"
    path.write_text(json.dumps(data))
    assert main(["certificates", "check", str(tmp_path)]) == 1
    assert "INVALID" in capsys.readouterr().out
    data = json.loads(path.read_text())
    data["model"]["A"][0][0] = "-5"  # the model edited: fingerprint no longer matches
    path.write_text(json.dumps(data))
    assert main(["certificates", "check", str(path)]) == 1


@pytest.mark.parametrize(
    "args, message",
    [
        (["--margin", "abc"], "not a finite number"),
        (["--band", "2:1"], "need W1 < W2"),
        (["--band", "1:1"], "need W1 < W2"),
        (["--band=-1:2"], "must be >= 0"),
        (["--band", "-1:2"], "must be >= 0"),
        (["--band", "nan:2"], "not a finite number"),
        (["--band", "0:inf"], "not a finite number"),
        (["--band", "a:b"], "not a finite number"),
        (["--band", "1"], "expected W1:W2"),
        (["--band", "0:1e400"], "at most 10^12 rad/s"),
    ],
)
def test_bad_options_exit_2(args, message, capsys):
    assert main(["gate", str(MODELS / "example_state_space.toml"), *args]) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.strip().splitlines()) == 1


def test_bad_model_file_exits_2_and_malformed_certificate_is_refused(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("[state_space]\nA = [[nan]]\nB = [[1.0]]\nC = [[1.0]]\nD = [[0.0]]\n")
    assert main(["gate", str(bad)]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1
    broken = tmp_path / "c.json"
    broken.write_text("{not json")
    assert main(["certificates", "check", str(broken)]) == 1  # a refusal, in one line
    assert f"INVALID {broken}: malformed: not valid JSON" in capsys.readouterr().out


def test_gate_indices_are_printed_and_written(tmp_path, capsys):
    out_json = tmp_path / "g.json"
    assert main(["gate", str(MODELS / "reconstructed_ks3p0.toml"), "--indices",
                 "--certificates", str(tmp_path), "--json", str(out_json)]) == 0
    out = capsys.readouterr().out
    assert "ν_IFP = 0 exactly" in out and "ρ_OFP = 0 exactly" in out
    (data,) = json.loads(out_json.read_text())
    assert data["indices"]["IFP"]["lower"] == "0" and data["indices"]["OFP"]["exact"]


def test_frequency_domain_certificate_is_written_bound_and_kept(tmp_path, monkeypatch, capsys):
    """With the KYP search out of the way, the gate decides by positive realness, writes a
    verify-pr-certificate/1 file under the name its claim asks for, keeps it on a rerun,
    and `verify certificates check` refuses it once the source file denotes another model.
    """
    import verify.passivity.decision as decide_module

    monkeypatch.setattr(decide_module, "find_certificate", lambda *args: None)
    monkeypatch.chdir(tmp_path)
    model = Path("lossless.toml")
    model.write_text("[transfer_function]\nnum = [[[2, 18, 24, 26]]]\nden = [[[1, 4, 2, 8]]]\n")
    assert main(["gate", str(model), "--certificates", "certs"]) == 0
    (cert,) = Path("certs").glob("*.json")
    assert json.loads(cert.read_text())["schema"] == "verify-pr-certificate/1"
    before = cert.read_bytes()
    assert main(["gate", str(model), "--certificates", "certs"]) == 0
    assert "(kept: already a valid certificate" in capsys.readouterr().out
    assert cert.read_bytes() == before
    assert main(["certificates", "check", "certs"]) == 0
    assert json.loads(cert.read_text())["source"] == "../lossless.toml"
    assert ("source ../lossless.toml found relative to the certificate's folder: the "
            "stored model is exactly the one it denotes") in capsys.readouterr().out
    model.write_text("[transfer_function]\nnum = [[[2, 18, 24, 27]]]\nden = [[[1, 4, 2, 8]]]\n")
    assert main(["certificates", "check", "certs"]) == 1
    assert "denotes another model" in capsys.readouterr().out


def test_margin_refutation_speaks_of_h_minus_nu_i(tmp_path, capsys):
    """With --margin the model decided is H - nu I: the reason says so, not "D + Dᵀ"."""
    assert main(["gate", str(MODELS / "example_state_space.toml"), "--margin", "0.1",
                 "--certificates", str(tmp_path)]) == 1
    out = capsys.readouterr().out
    assert "H − νI is not passive for ν = 1/10: D + Dᵀ − 2νI is not PSD" in out
    assert "D + Dᵀ is not PSD" not in out
    assert main(["gate", str(MODELS / "reconstructed_ks2p5.toml"), "--margin=-1/100",
                 "--certificates", str(tmp_path)]) == 1
    assert "H − νI is not passive for ν = -1/100 (evidence for H − νI" in \
        capsys.readouterr().out
    assert main(["gate", str(MODELS / "reconstructed_ks2p5.toml"), "--certificates",
                 str(tmp_path)]) == 1
    assert "νI" not in capsys.readouterr().out  # no margin: nothing about it


def test_gate_by_default_writes_under_the_git_ignored_build_folder(tmp_path, monkeypatch,
                                                                    capsys):
    """README example commands leave a checkout clean: the gate's default certificate
    folder is build/certificates, which the repository's .gitignore ignores."""
    import subprocess

    from verify.cli import GATE_CERTIFICATES

    monkeypatch.chdir(tmp_path)
    lossless = tmp_path / "work" / "ll.toml"  # not passive as written, passes --tolerance
    lossless.parent.mkdir()
    lossless.write_text("[state_space]\nA = [[1e-16, 1.0], [-1.0, 0.0]]\n"
                        "B = [[0.0], [1.0]]\nC = [[0.0, 1.0]]\nD = [[0.0]]\n")
    assert main(["gate", str(MODELS / "example_state_space.toml")]) == 0
    assert main(["gate", str(lossless), "--tolerance", "0.1"]) == 0
    written = sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*") if p.is_file())
    assert written and all(p.parts[:2] == ("build", "certificates") or p == Path("work/ll.toml")
                           for p in written), written
    assert str(GATE_CERTIFICATES) in capsys.readouterr().out
    ignored = subprocess.run(["git", "check-ignore", "-q", f"{GATE_CERTIFICATES}/x.json"],
                             cwd=MODELS.parents[2], capture_output=True)
    assert ignored.returncode == 0  # git ignores it in this repository
    # with no path, `verify certificates check` looks in build/certificates too
    assert main(["certificates", "check", "--allow-unbound"]) == 0
    assert "build/certificates/example-state-space-" in capsys.readouterr().out
