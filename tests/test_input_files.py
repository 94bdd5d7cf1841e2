"""Paths that name something other than a regular file: refused unread, in one line.

A FIFO blocks a reader until a writer appears and ``/dev/zero`` never ends; every file
reader of the input layer opens through :mod:`verify.inputs.files`.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from verify.errors import VerifyInputError
from verify.inputs.files import open_regular, read_bounded
from verify.inputs.model_file import MAX_MODEL_FILE_BYTES
from verify.passivity.io.model_file import load_model

MODEL = Path(__file__).resolve().parents[1] / "verify" / "data" / "models" / \
    "reconstructed_ks3p0.toml"


def _special(tmp_path: Path, kind: str) -> tuple[Path, str]:
    path = tmp_path / f"{kind}.toml"
    if kind == "fifo":
        os.mkfifo(path)
        return path, "is a FIFO (named pipe), not a regular file"
    if kind == "device":
        path.symlink_to("/dev/zero")
        return path, "is a device, not a regular file"
    if kind == "directory":
        path.mkdir()
        return path, "is a directory, not a regular file"
    with open(path, "wb") as handle:  # sparse: costs neither disk nor memory
        handle.truncate(MAX_MODEL_FILE_BYTES + 1)
    return path, "the file has 16.0 MiB, above the limit of 16.0 MiB"


KINDS = ["fifo", "device", "directory", "huge"]


@pytest.mark.parametrize("kind", KINDS)
def test_model_file_paths_that_are_not_small_regular_files(tmp_path, kind):
    path, needle = _special(tmp_path, kind)
    with pytest.raises(VerifyInputError) as info:
        load_model(path)
    message = str(info.value)
    assert message.startswith(str(path)) and needle in message and "\n" not in message


@pytest.mark.parametrize("kind", KINDS)
def test_the_gate_exits_2_with_one_line(tmp_path, capsys, kind):
    from verify.cli import main

    path, needle = _special(tmp_path, kind)
    assert main(["gate", str(path), "--certificates", str(tmp_path / "certs")]) == 2
    err = capsys.readouterr().err
    assert needle in err and err.count("\n") == 1 and "Traceback" not in err
    assert not (tmp_path / "certs").exists()


def test_a_regular_model_file_still_loads():
    assert load_model(MODEL).m == 2


def test_read_bounded_stops_at_the_bound_even_if_the_file_grows(tmp_path, monkeypatch):
    path = tmp_path / "grows.txt"
    path.write_bytes(b"x" * 10)
    real = os.fstat

    class Small:  # the size the directory reports is stale: the read must still stop
        def __init__(self, info):
            self.st_mode, self.st_size = info.st_mode, 0

    monkeypatch.setattr(os, "fstat", lambda fd: Small(real(fd)))
    with pytest.raises(VerifyInputError, match="more than 5 bytes"):
        read_bounded(path, max_bytes=5)
    assert read_bounded(path, max_bytes=10) == b"x" * 10


def test_open_regular_missing_file(tmp_path):
    with pytest.raises(VerifyInputError, match=r"absent\.toml: cannot read \(No such file"):
        open_regular(tmp_path / "absent.toml")


def test_certificate_paths_that_are_not_regular_files(tmp_path):
    from verify.passivity.io.strict_json import CertificateFormatError, read_strict

    fifo = tmp_path / "c.json"
    os.mkfifo(fifo)
    with pytest.raises(CertificateFormatError, match="is a FIFO"):
        read_strict(fifo)
