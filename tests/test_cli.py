"""The verify command: help, reports, bad input (one line, exit 2)."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from verify.cli import BLAS_THREAD_VARIABLES, SMALL_MATRIX_COMMANDS, main

DATA = Path(__file__).resolve().parents[1] / "verify" / "data" / "networks"


def run_cli(*args, cwd=None):
    return subprocess.run(
        [sys.executable, "-m", "verify.cli", *args], capture_output=True, text=True, cwd=cwd
    )


def test_help_lists_every_command():
    out = run_cli("--help")
    assert out.returncode == 0
    for cmd in ("all", "network", "check", "gate", "certificates", "simulate"):
        assert cmd in out.stdout


#: Claims of each verdict and with derivations, fast (the whole run is in
#: test_symbolic_and_claims and in the README's main command).
SAMPLE = ("sec2.wtw-invertible", "sec2.stealthiness", "lemma1.trace-inequality",
          "lemma1.nagumo-gradient", "lemma1.h-dot", "lemma1.boundary", "thm1.v-dot",
          "thm1.phi")


def test_all_writes_reports_and_strict_fails_on_refuted_claims(tmp_path, capsys):
    only = [arg for claim in SAMPLE for arg in ("--only", claim)]
    assert main(["all", "--quick", *only, "--out", str(tmp_path), "--certificates",
                 str(tmp_path / "certificates")]) == 0  # not into the checkout's certificates/
    data = json.loads((tmp_path / "report.json").read_text())
    verdicts = {c["id"]: c["verdict"] for c in data["claims"]}
    assert verdicts["sec2.wtw-invertible"] == "refuted"
    assert verdicts["sec2.stealthiness"] == "verified-with-repair"
    assert verdicts["lemma1.trace-inequality"] == "refuted"
    assert verdicts["thm1.v-dot"] == "verified"
    assert verdicts["lemma1.nagumo-gradient"] == "verified-with-repair"
    steps = [
        s
        for c in data["claims"]
        for e in c["evidence"]
        if e["kind"] == "derivation"
        for s in e["data"]["steps"]
    ]
    assert len(steps) > 20 and all(s["verdict"] in ("verified", "refuted") for s in steps)
    md = (tmp_path / "report.md").read_text()
    assert "Repaired statement" in md and "sec2.stealthiness" in md
    page = (tmp_path / "report.html").read_text()
    assert "<table class='summary'>" in page and "<table class='proof'>" in page
    assert "<h2>Run</h2>" not in page and "## Run" not in md  # no date, no timings
    assert not list(tmp_path.glob(".*.tmp"))
    assert main(["all", "--quick", "--out", str(tmp_path), "--only", "sec2.wtw", "--strict"]) == 1
    assert main(["all", "--quick", "--out", str(tmp_path), "--only", "sec2.d-dot", "--strict"]) == 0


def test_network_command_on_shipped_examples(capsys):
    assert main(["network", *map(str, sorted(DATA.glob("*.toml")))]) == 0
    out = capsys.readouterr().out
    assert out.count("ok") >= 2 and "rank 2" in out


BAD_FILES = {
    "cancelling.toml": ("quaternions = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]", "undefined"),
    "not_rotation.toml": (
        "rotations = [[[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]]",
        "not in SO(3)",
    ),
    "reflection.toml": (
        "rotations = [[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]]]",
        "not in SO(3)",
    ),
    "nan.toml": ("quaternions = [[nan, 0.0, 0.0, 0.0]]", "NaN"),
    "text.toml": ('quaternions = [["1", 0.0, 0.0, 0.0]]', "expected a real number"),
    "bool.toml": ("quaternions = [[true, 0.0, 0.0, 0.0]]", "expected a real number"),
    "shape.toml": ("quaternions = [[1.0, 0.0, 0.0]]", "shape"),
    "ragged.toml": ("rotations = [[[1.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]]", "ragged"),
    "zero.toml": ("quaternions = [[0.0, 0.0, 0.0, 0.0]]", "zero"),
    "empty.toml": ("quaternions = []", "at least one body"),
    "both.toml": ("quaternions = [[1.0, 0, 0, 0]]\nrotations = []", "exactly one"),
    "unknown.toml": ("quaternions = [[1.0, 0, 0, 0]]\nexec = 1", "unknown key"),
    "syntax.toml": ("quaternions = [[1.0, 0", "not valid TOML"),
}


@pytest.mark.parametrize("name", sorted(BAD_FILES))
def test_bad_network_files_give_one_line_and_exit_2(tmp_path, name):
    text, expected = BAD_FILES[name]
    path = tmp_path / name
    path.write_text(text + "\n")
    out = run_cli("network", str(path))
    assert out.returncode == 2, out.stderr
    assert expected in out.stderr
    assert len(out.stderr.strip().splitlines()) == 1
    assert "Traceback" not in out.stderr and out.stdout == ""


def test_missing_file_and_projection_option(tmp_path, capsys):
    assert main(["network", str(tmp_path / "absent.toml")]) == 2
    assert "cannot read" in capsys.readouterr().err
    rough = tmp_path / "rough.toml"
    rough.write_text("rotations = [[[1.0, 0.0001, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]]\n")
    assert main(["network", str(rough)]) == 2
    assert main(["network", "--project", str(rough)]) == 0
    assert "projected onto SO(3)" in capsys.readouterr().out


def test_no_command_prints_help_and_exits_2(capsys):
    assert main([]) == 2


@pytest.mark.parametrize("preset, expected", [(None, "1"), ("3", "3")])
def test_identification_commands_use_one_blas_thread_unless_told(preset, expected):
    """The identification's many small least-squares problems gain nothing from a
    multithreaded BLAS and lose on a busy machine; `verify identify` and `verify all`
    ask for one thread before numpy loads, and a user's own setting wins."""
    import os

    env = {k: v for k, v in os.environ.items()
           if k not in BLAS_THREAD_VARIABLES}
    if preset is not None:
        env["OPENBLAS_NUM_THREADS"] = preset
    code = ("import os, sys; from verify import cli; "
            "assert 'numpy' not in sys.modules; cli.single_threaded_blas(); "
            "import numpy; print(os.environ['OPENBLAS_NUM_THREADS'])")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                         text=True, check=True)
    assert out.stdout.strip() == expected
    assert {"identify", "all"} <= set(SMALL_MATRIX_COMMANDS)
