"""Bound or refused: certificates whose labels no source file confirms (hostile cases).

A certificate's proof is re-checked from what it stores, but its name and descriptive
labels can only be re-derived from the model file it names. Each test forges or moves
a genuine certificate so that file is missing, elsewhere or another model's, and expects
``verify certificates check`` to refuse it (INVALID) or report it UNBOUND with exit 1;
``--allow-unbound`` accepts unbound ones only, and names the labels left unchecked.
Grouped by class: relabelled KYP certificates, detached sources, moved robust
certificates, and what ``--allow-unbound`` must not accept.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from verify.cli import main
from verify.passivity.io.binding import claim_from_fields, file_name, locate_source

ROOT = Path(__file__).resolve().parents[1]
MODELS = ROOT / "verify" / "data" / "models"
EXAMPLE = MODELS / "example_state_space.toml"
NOT_PASSIVE_NAME = "reconstructed k_s = 2.5"  # the shipped model that is not passive


@pytest.fixture(scope="module")
def genuine(tmp_path_factory) -> Path:
    """A genuine KYP certificate of the passive example model, bound to its file."""
    d = tmp_path_factory.mktemp("genuine")
    assert main(["gate", str(EXAMPLE), "--certificates", str(d)]) == 0
    (path,) = d.glob("*.json")
    return path


def _forge(data: dict, folder: Path, **changes) -> Path:
    """Apply ``changes`` and store the file under the name its content asks for."""
    data = {**data, **changes}
    claim = claim_from_fields(data["margin"], data.get("band"))
    path = folder / file_name(data["name"], claim, data["fingerprint"])
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data, indent=1) + "\n")
    return path


def _check(capsys, *args: str | Path) -> tuple[int, str]:
    capsys.readouterr()
    code = main(["certificates", "check", *map(str, args)])
    return code, capsys.readouterr().out


# ------------------------------------------------------------------ relabelled KYP certificates


@pytest.mark.parametrize("source", ["verify/data/models/reconstructed_ks2p5.toml",
                                    "../verify/data/models/reconstructed_ks2p5.toml",
                                    "/nonexistent/reconstructed_ks2p5.toml"])
def test_relabelled_certificate_checked_from_another_folder_is_unbound(
        genuine, tmp_path, monkeypatch, capsys, source):
    """The issue's attack: a valid proof under a non-passive model's name, checked where
    its source is not found. Running from the repository root changes nothing (the
    source is looked up from the certificate, not the working directory)."""
    data = json.loads(genuine.read_text())
    forged = _forge(data, tmp_path / "elsewhere", name=NOT_PASSIVE_NAME, source=source,
                    unverified={})
    for cwd in (tmp_path, ROOT):
        monkeypatch.chdir(cwd)
        code, out = _check(capsys, forged)
        assert code == 1 and out.startswith("UNBOUND"), out
        assert "labels not checked:" in out and f"{forged}: name" in out


def test_relabelled_certificate_next_to_the_named_model_is_refused(genuine, tmp_path,
                                                                   capsys):
    """Where the named file is found, the relabel is refused outright (another model)."""
    repo = tmp_path / "repo"
    model = repo / "verify" / "data" / "models" / "reconstructed_ks2p5.toml"
    model.parent.mkdir(parents=True)
    shutil.copy(MODELS / "reconstructed_ks2p5.toml", model)
    data = json.loads(genuine.read_text())
    forged = _forge(data, repo / "certificates", name=NOT_PASSIVE_NAME,
                    source="verify/data/models/reconstructed_ks2p5.toml", unverified={})
    code, out = _check(capsys, forged)
    assert code == 1 and out.startswith("INVALID") and "denotes another model" in out
    code, out = _check(capsys, "--allow-unbound", forged)  # not an unbound case
    assert code == 1 and out.startswith("INVALID")


# ------------------------------------------------------------------ detached sources


@pytest.mark.parametrize("source", ["", "python"])
def test_certificate_naming_no_file_is_unbound(genuine, tmp_path, capsys, source):
    data = json.loads(genuine.read_text())
    forged = _forge(data, tmp_path, name=NOT_PASSIVE_NAME, source=source)
    code, out = _check(capsys, forged)
    assert code == 1 and "UNBOUND" in out
    code, out = _check(capsys, "--allow-unbound", forged)
    assert code == 0 and "1 unbound, accepted (--allow-unbound)" in out
    assert f"  {forged}: name, unverified.description" in out


def test_moved_genuine_certificate_is_unbound_and_its_copy_in_place_is_valid(tmp_path,
                                                                           capsys):
    """The gate names the model relative to the certificate's folder: moved elsewhere the
    file is unbound; beside a model file at that relative path it is bound again."""
    lab = tmp_path / "lab"
    lab.mkdir()
    shutil.copy(EXAMPLE, lab / "model.toml")
    assert main(["gate", str(lab / "model.toml"), "--certificates", str(lab / "certs")]) == 0
    (genuine,) = (lab / "certs").glob("*.json")
    data = json.loads(genuine.read_text())
    assert data["source"] == "../model.toml"
    moved = tmp_path / "a" / "b" / genuine.name
    moved.parent.mkdir(parents=True)
    shutil.copy(genuine, moved)
    code, out = _check(capsys, moved)
    assert code == 1 and "UNBOUND" in out
    shutil.copy(EXAMPLE, tmp_path / "a" / "model.toml")
    code, out = _check(capsys, moved)
    assert code == 0 and "found relative to the certificate's folder" in out
    found = locate_source(data["source"], moved)
    assert found is not None and found.path.resolve() == (tmp_path / "a" / "model.toml")


# ------------------------------------------------------------------ robust certificates moved


def test_robust_certificate_moved_away_from_its_identification_is_unbound(tmp_path, capsys):
    (shipped,) = (ROOT / "certificates").glob("nonpassive_human-identified-robust-band-*.json")
    moved = tmp_path / shipped.name
    shutil.copy(shipped, moved)
    code, out = _check(capsys, moved)
    assert code == 1 and out.startswith("UNBOUND")
    assert "region = the source's identified coefficients" in out
    code, out = _check(capsys, "--allow-unbound", moved)
    assert code == 0 and "labels not checked:" in out and "name, structure" in out


def test_robust_certificate_in_place_is_bound(capsys):
    (shipped,) = (ROOT / "certificates").glob("nonpassive_human-identified-robust-band-*.json")
    code, out = _check(capsys, shipped)
    assert code == 0 and out.startswith("ok") and "unbound" not in out


# ------------------------------------------------------------------ --allow-unbound refuses


def test_allow_unbound_still_refuses_a_broken_proof(genuine, tmp_path, capsys):
    data = json.loads(genuine.read_text())
    data["P"][0][0] = "1/1000"
    forged = _forge(data, tmp_path, source="")
    code, out = _check(capsys, "--allow-unbound", forged)
    assert code == 1 and out.startswith("INVALID")


# ------------------------------------------------------------------ perturbed within tolerance


@pytest.fixture(scope="module")
def perturbed(tmp_path_factory) -> Path:
    """A certificate of a rounded lossless model passed by --tolerance, bound to its file."""
    d = tmp_path_factory.mktemp("tolerance")
    model = d / "ll.toml"
    model.write_text("[state_space]\nA = [[1e-16, 1.0], [-1.0, 0.0]]\n"
                     "B = [[0.0], [1.0]]\nC = [[0.0, 1.0]]\nD = [[0.0]]\n")
    assert main(["gate", str(model), "--tolerance", "0.1", "--certificates",
                 str(d / "certs")]) == 0
    (path,) = (d / "certs").glob("*.json")
    return path


def test_perturbed_certificate_is_bound_to_its_file_and_perturbation(perturbed, capsys):
    code, out = _check(capsys, perturbed)
    assert code == 0 and "perturbed by a = " in out and "unbound" not in out


@pytest.mark.parametrize("edit, reason", [
    (lambda d: d["perturbation"].update(a="1/1024"), "denotes another model"),
    (lambda d: d.pop("perturbation"), "denotes another model"),
    (lambda d: d.update(name="ll"), "marked perturbed 'll (perturbed within tolerance)'"),
    (lambda d: d["perturbation"].update(d="-1"), "must be >= 0"),
])
def test_perturbed_certificate_edited_is_refused(perturbed, tmp_path, capsys, edit, reason):
    data = json.loads(perturbed.read_text())
    edit(data)
    data["source"] = str((perturbed.parent / data["source"]).resolve())
    forged = _forge(data, tmp_path)
    code, out = _check(capsys, forged)
    assert code == 1 and out.startswith("INVALID") and reason in out, out
