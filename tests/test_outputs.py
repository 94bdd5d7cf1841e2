"""Outputs that never destroy a user's file, and OS errors that are one line, exit 2.

The cases a careless or hostile user found: an output naming an input of the same call,
a device, a directory, a folder that cannot be written or a full disk; a model in a batch
that crashes the tool; numbers beyond the float range or Python's digit limit; a log the
system refuses to read; ``verify certificates check`` on things that are not files.
"""

from __future__ import annotations

import errno
import json
import os
import shutil
import socket
import stat
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest

from verify.artefacts.atomic import OutputError, write_atomic
from verify.artefacts.outputs import OutputPlan
from verify.cli import main

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "verify" / "data" / "models" / "example_state_space.toml"
LOG = ROOT / "verify" / "data" / "logs" / "passive_human.npz"


@pytest.fixture
def model(tmp_path) -> Path:
    path = tmp_path / "m.toml"
    shutil.copy(MODEL, path)
    return path


def _device_copy(path: Path) -> Path:
    """A copy of /dev/full (character device 1, 7) at ``path``, or skip without root."""
    try:
        os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(1, 7))
    except (PermissionError, OSError) as exc:
        pytest.skip(f"mknod not permitted here ({exc})")
    return path


def _one_error_line(capsys) -> str:
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("verify: error: "), err
    assert "internal error" not in err
    return lines[0]


# ------------------------------------------------------------------ inputs kept


@pytest.mark.parametrize("flag", ["--json", "--junit"])
def test_gate_refuses_to_write_over_its_own_model(model, tmp_path, capsys, flag):
    before = model.read_bytes()
    assert main(["gate", str(model), flag, str(model), "--certificates",
                 str(tmp_path / "c")]) == 2
    assert "is an input of this call" in _one_error_line(capsys)
    assert model.read_bytes() == before
    assert not (tmp_path / "c").exists()  # refused before any work


def test_hard_and_symbolic_links_to_an_input_are_the_input(model, tmp_path, capsys):
    os.link(model, tmp_path / "hard.json")
    (tmp_path / "soft.json").symlink_to(model)
    before = model.read_bytes()
    for alias in ("hard.json", "soft.json"):
        assert main(["gate", str(model), "--json", str(tmp_path / alias), "--certificates",
                     str(tmp_path / "c")]) == 2
        assert "is an input of this call" in _one_error_line(capsys)
    assert model.read_bytes() == before


def test_identify_refuses_to_write_over_its_log(tmp_path, capsys):
    log = tmp_path / "log.npz"
    shutil.copy(LOG, log)
    before = log.read_bytes()
    for flag in ("--json", "--junit"):
        assert main(["identify", str(log), "--out", str(tmp_path / "out"), flag,
                     str(log)]) == 2
        assert "is an input of this call" in _one_error_line(capsys)
    assert log.read_bytes() == before


def test_identify_refuses_an_out_folder_that_holds_its_log(tmp_path, capsys):
    """--out is replaced whole, so a log inside it would be deleted."""
    (tmp_path / "out").mkdir()
    log = tmp_path / "out" / "log.npz"
    shutil.copy(LOG, log)
    assert main(["identify", str(log), "--out", str(tmp_path / "out")]) == 2
    assert "holds an input of this call" in _one_error_line(capsys)
    assert log.exists()


def test_two_outputs_of_one_call_are_refused(model, tmp_path, capsys):
    out = tmp_path / "same.xml"
    assert main(["gate", str(model), "--json", str(out), "--junit", str(out),
                 "--certificates", str(tmp_path / "c")]) == 2
    assert "is also written as --json" in _one_error_line(capsys)


def test_campaign_refuses_a_spec_that_is_one_of_its_reports(tmp_path, capsys):
    """The spec hard-linked as --out's campaign.md: the report would replace it."""
    shutil.copytree(ROOT / "verify" / "data" / "models", tmp_path / "models")
    (tmp_path / "specs").mkdir()
    spec = tmp_path / "specs" / "small.toml"
    shutil.copy(ROOT / "verify" / "data" / "campaigns" / "small.toml", spec)
    out = tmp_path / "out"
    out.mkdir()
    os.link(spec, out / "campaign.md")
    before = spec.read_bytes()
    assert main(["campaign", str(spec), "--out", str(out), "--quiet"]) == 2
    assert "is an input of this call" in _one_error_line(capsys)
    assert spec.read_bytes() == before
    assert sorted(p.name for p in out.iterdir()) == ["campaign.md"]


# ------------------------------------------------------------------ devices, folders


def test_a_device_is_never_replaced(model, tmp_path, capsys):
    dev = _device_copy(tmp_path / "full")
    assert main(["gate", str(model), "--json", str(dev), "--certificates",
                 str(tmp_path / "c")]) == 2
    assert "is a device" in _one_error_line(capsys)
    assert stat.S_ISCHR(os.lstat(dev).st_mode)
    with pytest.raises(OutputError, match="is a device"):  # the writer itself refuses too
        write_atomic(dev, "x")
    assert stat.S_ISCHR(os.lstat(dev).st_mode)
    link = tmp_path / "link.json"  # a symbolic link to the device is the device
    link.symlink_to(dev)
    assert main(["gate", str(model), "--junit", str(link), "--certificates",
                 str(tmp_path / "c")]) == 2
    assert "is a device" in _one_error_line(capsys)
    assert stat.S_ISCHR(os.lstat(dev).st_mode) and link.is_symlink()


def test_fifo_socket_and_directory_are_refused(model, tmp_path, capsys):
    os.mkfifo(tmp_path / "fifo")
    sock = socket.socket(socket.AF_UNIX)
    sock.bind(str(tmp_path / "sock"))
    try:
        for name, kind in (("fifo", "FIFO"), ("sock", "socket"), (".", "is a directory")):
            assert main(["gate", str(model), "--junit", str(tmp_path / name),
                         "--certificates", str(tmp_path / "c")]) == 2
            assert kind in _one_error_line(capsys)
    finally:
        sock.close()
    assert stat.S_ISFIFO(os.lstat(tmp_path / "fifo").st_mode)


def test_dash_is_standard_output_for_the_gate(model, tmp_path, capsys):
    assert main(["gate", str(model), "--json", "-", "--certificates",
                 str(tmp_path / "c")]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)[0]["verdict"] == "passive"  # only the JSON on stdout
    assert "PASS" in err
    assert not (tmp_path / "-").exists()


@pytest.mark.parametrize("command", ["gate", "identify", "simulate", "campaign", "all"])
def test_an_output_under_a_file_is_one_line_before_any_work(tmp_path, capsys, command,
                                                            model):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    bad = blocker / "sub" / "out"
    argv = {
        "gate": ["gate", str(model), "--json", str(bad), "--certificates", str(tmp_path)],
        "identify": ["identify", str(LOG), "--out", str(bad)],
        "simulate": ["simulate", "--seconds", "0.1", "--out", str(bad)],
        "campaign": ["campaign", str(ROOT / "verify" / "data" / "campaigns" / "small.toml"),
                     "--out", str(bad), "--quiet"],
        "all": ["all", "--only", "sec2.d-dot", "--out", str(bad)],
    }[command]
    assert main(argv) == 2
    assert "not a folder" in _one_error_line(capsys)
    assert blocker.read_text() == "x"


# ------------------------------------------------------------------ write errors


def test_a_failing_write_leaves_no_temporary_file_and_no_new_folder(tmp_path, monkeypatch):
    def full(fd):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(os, "fsync", full)
    with pytest.raises(OutputError, match=r"new/deeper/x.json: cannot write \(No space"):
        write_atomic(tmp_path / "new" / "deeper" / "x.json", "{}")
    assert list(tmp_path.iterdir()) == []


def test_an_unwritable_folder_is_refused_before_the_work(model, tmp_path, capsys,
                                                         monkeypatch):
    """The probe writes (and removes) a small file: a write error there refuses the call
    before any model is decided."""
    import verify.artefacts.outputs as outputs

    real = os.write

    def refused(fd, data):
        if data.startswith(b"verify: probe"):
            raise OSError(errno.EROFS, os.strerror(errno.EROFS))
        return real(fd, data)

    monkeypatch.setattr(outputs.os, "write", refused)
    assert main(["gate", str(model), "--json", str(tmp_path / "g.json"), "--certificates",
                 str(tmp_path / "c")]) == 2
    assert "Read-only file system" in _one_error_line(capsys)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.toml"]


def test_an_immutable_folder_is_refused(model, tmp_path, capsys):
    locked = tmp_path / "locked"
    locked.mkdir()
    if subprocess.run(["chattr", "+i", str(locked)], capture_output=True).returncode:
        pytest.skip("chattr +i not permitted here")
    try:
        assert main(["gate", str(model), "--json", str(locked / "g.json"),
                     "--certificates", str(tmp_path / "c")]) == 2
        assert "cannot write in" in _one_error_line(capsys)
    finally:
        subprocess.run(["chattr", "-i", str(locked)], check=True)
    assert list(locked.iterdir()) == []


@pytest.fixture
def full_filesystem(tmp_path):
    """A 256 KiB tmpfs filled to the last byte (root only; skipped otherwise)."""
    mount = tmp_path / "full"
    mount.mkdir()
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", str(mount)],
                      capture_output=True).returncode:
        pytest.skip("mounting a tmpfs is not permitted here")
    try:
        with open(mount / "filler", "wb", buffering=0) as f:
            try:
                while True:
                    f.write(b"\0" * 512)
            except OSError:
                pass
        yield mount
    finally:
        subprocess.run(["umount", str(mount)], check=True)


def test_a_full_file_system_is_refused_before_the_work(model, full_filesystem, capsys):
    assert main(["gate", str(model), "--json", str(full_filesystem / "g.json"),
                 "--certificates", str(full_filesystem / "c")]) == 2
    assert "No space left on device" in _one_error_line(capsys)
    assert sorted(p.name for p in full_filesystem.iterdir()) == ["filler"]


def test_a_full_file_system_during_a_campaign_leaves_no_empty_folder(tmp_path, capsys,
                                                                     monkeypatch):
    import verify.campaign.command as command

    def fails(s, spec, out, *rest):
        # the store's folder exists already: the campaign holds its lock in it
        (out / "results").mkdir(parents=True, exist_ok=True)
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(out / "results"))

    monkeypatch.setattr(command, "_run", fails)
    out = tmp_path / "out"
    assert main(["campaign", str(ROOT / "verify" / "data" / "campaigns" / "small.toml"),
                 "--out", str(out), "--quiet"]) == 2
    assert "No space left on device" in _one_error_line(capsys)
    assert not out.exists()


# ------------------------------------------------------------------ batches, numbers


def test_a_crashing_model_keeps_the_others_verdicts(tmp_path, capsys, monkeypatch):
    import verify.passivity.gate as gate

    paths = []
    for name in ("A", "B", "C"):
        p = tmp_path / f"{name}.toml"
        p.write_text(MODEL.read_text().replace('name = "example state space"',
                                               f'name = "{name}"'))
        paths.append(p)
    real = gate.decide

    def crashes_on_b(model, margin, **options):
        if model.name == "B":
            raise OverflowError("integer division result too large for a float")
        return real(model, margin, **options)

    monkeypatch.setattr(gate, "decide", crashes_on_b)
    code = main(["gate", *map(str, paths), "--json", str(tmp_path / "g.json"), "--junit",
                 str(tmp_path / "g.xml"), "--certificates", str(tmp_path / "c")])
    assert code == 3
    out = capsys.readouterr().out
    assert "PASS A" in out and "PASS C" in out and "ERROR B" in out
    data = {d["name"]: d for d in json.loads((tmp_path / "g.json").read_text())}
    assert data["A"]["verdict"] == data["C"]["verdict"] == "passive"
    assert data["B"]["verdict"] == "error" and "OverflowError" in data["B"]["error"]
    assert 'errors="1"' in (tmp_path / "g.xml").read_text()


def test_a_witness_beyond_the_float_range_is_shown_not_floated(tmp_path):
    """H(s) = 1/(s+1) - 10^-2000: negative real part above about 10^1000 rad/s; the
    witness at 10^1500 is formatted without converting 10^1500 to a float."""
    from flint import fmpq

    from verify.inputs.number_text import unlimited_int_text
    from verify.passivity.check.fd_witness import frequency_vector_witness
    from verify.passivity.io.model_file import load_model

    path = tmp_path / "h.toml"
    path.write_text('name = "h"\n[state_space]\nA = [[-1]]\nB = [[1]]\nC = [[1]]\n'
                    "D = [[-1e-2000]]\n")
    with unlimited_int_text():
        found = frequency_vector_witness(load_model(path).exact, fmpq(10**1500), "")
    assert found is not None and "≈ 1e+1500 rad/s" in found.summary
    assert Fraction(found.data["omega"]) == 10**1500


def test_a_model_with_a_4400_digit_integer_is_gated(tmp_path, capsys):
    path = tmp_path / "big.toml"
    path.write_text('name = "big"\n[state_space]\nA = [[-' + "1" * 4400 + "]]\n"
                    "B = [[1]]\nC = [[1]]\nD = [[0]]\n")
    assert main(["gate", str(path), "--certificates", str(tmp_path / "c")]) == 0
    assert "PASS big" in capsys.readouterr().out


def test_the_band_bound_is_stated(model, tmp_path, capsys):
    assert main(["gate", str(model), "--band", "0:1e12", "--certificates",
                 str(tmp_path / "c")]) == 0
    capsys.readouterr()
    assert main(["gate", str(model), "--band", "0:1000000000001", "--certificates",
                 str(tmp_path / "c")]) == 2
    assert "at most 10^12 rad/s" in _one_error_line(capsys)


# ------------------------------------------------------------------ readers


@pytest.mark.parametrize("suffix", [".csv", ".npz"])
def test_a_log_the_system_cannot_read_is_one_line(tmp_path, capsys, suffix):
    """/proc/self/mem reports itself as a regular file and fails every read with EIO."""
    log = tmp_path / f"mem{suffix}"
    log.symlink_to("/proc/self/mem")
    assert main(["identify", str(log), "--out", str(tmp_path / "out")]) == 2
    assert "cannot read (Input/output error)" in _one_error_line(capsys)
    assert not (tmp_path / "out").exists()


def test_a_model_the_system_cannot_read_is_one_line(tmp_path, capsys):
    path = tmp_path / "m.toml"
    path.symlink_to("/proc/self/mem")
    assert main(["gate", str(path), "--certificates", str(tmp_path / "c")]) == 2
    assert "cannot read" in _one_error_line(capsys)


def test_the_output_plan_api(tmp_path):
    """The documented use: inputs named, each output checked once, then written."""
    source = tmp_path / "in.toml"
    source.write_text("x")
    plan = OutputPlan(inputs=[source])
    plan.file("--json", tmp_path / "new" / "out.json")
    plan.folder("--out", tmp_path / "dir")
    with pytest.raises(OutputError, match="is an input"):
        plan.file("--junit", source)
    plan.write(tmp_path / "new" / "out.json", "{}\n")
    assert (tmp_path / "new" / "out.json").read_text() == "{}\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.toml", "new"]  # no probe left


def test_an_inconclusive_reason_never_quotes_rounding_noise():
    """A lossless model (A skew, C = Bᵀ, D = 0) has ν(ω) = 0 exactly; whatever its float
    evaluation gives lies inside the rounding bound, and the reason then gives no number
    (a 150-state model's reason once quoted ν ≈ -5e16)."""
    import numpy as np

    from verify.passivity.decision import nu_estimate_text
    from verify.passivity.search.hamiltonian import nu_rounding_bound, nu_values

    rng = np.random.default_rng(2)
    n = 60
    S = np.triu(np.round(rng.normal(size=(n, n)), 3), 1)
    A, B = S - S.T, np.round(rng.normal(size=(n, 1)), 3)
    C, D = B.T.copy(), np.zeros((1, 1))
    for omega in (0.178, 1.0, 7.5):
        bound = nu_rounding_bound(A, B, C, D, omega)
        noise = float(nu_values(A, B, C, D, np.array([omega]))[0])
        assert abs(noise) <= bound  # the float value of an exact 0 is inside the bound
        text = nu_estimate_text(A, B, C, D, (omega, -bound / 2))
        assert "within the rounding error" in text and f"{-bound / 2:.3g}" not in text
        assert f"{-10 * bound:.3g}" in nu_estimate_text(A, B, C, D, (omega, -10 * bound))


def test_a_claim_whose_certificate_cannot_be_written_ends_the_run(tmp_path):
    """A full disk while a check writes its certificate is not an inconclusive claim."""
    from verify.claims.model import CheckContext, Claim
    from verify.claims.runner import run_claim

    def writes(context):
        write_atomic(tmp_path / "file" / "x.json", "{}")  # under a regular file

    (tmp_path / "file").write_text("x")
    claim = Claim(id="test.output", section="none", paper_ref="none", paper_says="",
                  statement="a claim that writes", method="", scope="", check=writes)
    with pytest.raises(OutputError, match="not a folder"):
        run_claim(claim, CheckContext(seed=1, quick=True))
