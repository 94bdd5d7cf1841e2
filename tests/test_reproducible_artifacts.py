"""Reproducible artefacts: `verify all` writes the same bytes twice.

With no environment variable, reports (Markdown, HTML, JSON, LaTeX, figures) and
certificates are byte-identical between runs: the date and the timings go to standard
output and to the run record (build/run.json), never into a report. `--only` writes to
build/only unless --out says otherwise. Run on the fast Section 4 claims, which write
certificates and figures, to keep the test short.
"""

from __future__ import annotations

import json
import math
import random
import re
import shutil
from pathlib import Path

import pytest

from verify.cli import main


def snapshot(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*"))
            if p.is_file()}


#: Section 4's claims that write certificates and figures in seconds (the identification
#: from logs has its own reproducibility tests below, in a child process).
SECTION4_FAST = ("sec4.reconstructed-models", "sec4.nu-curves-indices", "sec4.nu-criterion",
                 "sec4.model-class")


def run_all(where: Path) -> dict[str, bytes]:
    """`verify all` on :data:`SECTION4_FAST` into fresh directories; returns every file
    written."""
    shutil.rmtree(where / "out", ignore_errors=True)
    only = [arg for claim in SECTION4_FAST for arg in ("--only", claim)]
    assert main(["all", *only, "--out", str(where / "out" / "reports"),
                 "--certificates", str(where / "out" / "certificates")]) == 0
    return snapshot(where / "out")


def test_verify_all_is_byte_identical_with_no_environment(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
    first = run_all(tmp_path)
    assert any(name.startswith("certificates/") for name in first)
    assert any(name.endswith(".png") or name.endswith(".svg") for name in first)
    record = json.loads((tmp_path / "build" / "run.json").read_text())
    assert record["timings"] and record["generated"]
    assert "date and timings: build/run.json" in capsys.readouterr().out
    assert run_all(tmp_path) == first
    for name in ("reports/report.md", "reports/report.html", "reports/appendix.tex"):
        text = first[name].decode()
        assert not re.search(r"\d+\.\d+ s\b|Generated |\b20\d\d-\d\d-\d\dT", text), name
    assert "run" not in json.loads(first["reports/report.json"])
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")  # has no say any more
    assert run_all(tmp_path) == first


def test_only_never_writes_over_the_full_report(tmp_path, monkeypatch):
    """--only with no --out writes to build/only/reports and its certificates there."""
    monkeypatch.chdir(tmp_path)
    for name in ("reports/report.md", "certificates/keep.json"):
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text("full\n")
    assert main(["all", "--quick", "--jobs", "1", "--only", "sec4.nu-criterion"]) == 0
    assert (tmp_path / "reports" / "report.md").read_text() == "full\n"
    assert sorted(p.name for p in (tmp_path / "reports").iterdir()) == ["report.md"]
    assert sorted(p.name for p in (tmp_path / "certificates").iterdir()) == ["keep.json"]
    assert (tmp_path / "build" / "only" / "reports" / "report.md").is_file()
    assert main(["all", "--quick", "--jobs", "1", "--only", "sec4.nu-criterion", "--out",
                 "mine", "--run-record", "mine/when.json"]) == 0
    assert (tmp_path / "mine" / "report.md").is_file()
    record = json.loads((tmp_path / "mine" / "when.json").read_text())
    assert list(record["timings"]) == ["sec4.nu-criterion"]
    assert "mine/report.md" in record["reports"]


def test_parallel_claim_checks_give_the_sequential_report(tmp_path, monkeypatch):
    """verify all --jobs 2 renders byte for byte what --jobs 1 renders (fast claims)."""
    from verify.cli import main

    outs = []
    for jobs in ("1", "2"):
        out = tmp_path / f"jobs{jobs}"
        args = ["all", "--quick", "--jobs", jobs, "--out", str(out), "--certificates",
                str(tmp_path / "certs"), "--only", "sec2.d-dot", "--only", "thm1.phi",
                "--only", "sec4.nu-criterion"]
        assert main(args) == 0
        outs.append(out)
    for name in ("report.md", "report.json", "report.html"):
        a = (outs[0] / name).read_text().replace(str(outs[0]), "OUT")
        b = (outs[1] / name).read_text().replace(str(outs[1]), "OUT")
        assert a == b, name


def test_jobs_below_one_is_bad_input(tmp_path, capsys):
    from verify.cli import main

    assert main(["all", "--jobs", "0", "--out", str(tmp_path)]) == 2
    assert "--jobs must be at least 1" in capsys.readouterr().err


# ---------------------------------------------------------------- another machine, emulated
#
# A lab's CI and a colleague's laptop differ in BLAS threads and in the BLAS kernels their
# CPU selects, which changes the order of floating-point sums. Both are emulated in child
# processes: OPENBLAS_NUM_THREADS / OMP_NUM_THREADS 1 against 2, and OpenBLAS's kernels for
# the machine against those of another core type (OPENBLAS_CORETYPE, which changes the
# last bits of products and solves). The artefacts written must not change.

FAST_CLAIMS = ("sec4.nu-curves-indices", "sec4.reconstructed-models", "thm1.phi")


def _verify_all_in_child(where: Path, *, threads: int, coretype: str | None,
                         claims: tuple[str, ...], quick: bool) -> dict[str, bytes]:
    import os
    import subprocess
    import sys

    where.mkdir(parents=True)
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("OPENBLAS", "OMP_", "MKL_"))}
    env.update(OPENBLAS_NUM_THREADS=str(threads),
               OMP_NUM_THREADS=str(threads), MKL_NUM_THREADS=str(threads),
               PYTHONPATH=str(Path(__file__).resolve().parents[1]))
    if coretype:
        env["OPENBLAS_CORETYPE"] = coretype
    args = [sys.executable, "-m", "verify.cli", "all", "--latex", "--jobs", "1",
            "--out", "reports", "--certificates", "certificates"]
    args += ["--quick"] * quick
    for claim in claims:
        args += ["--only", claim]
    done = subprocess.run(args, cwd=where, env=env, capture_output=True, text=True,
                          timeout=1200, check=False)
    if done.returncode != 0:  # not an AssertionError: the expected failure is the bytes
        raise RuntimeError(done.stdout[-2000:] + done.stderr[-2000:])
    files = snapshot(where)
    assert "build/run.json" in files  # the date and timings, the one file meant to differ
    return {name: data for name, data in files.items() if not name.startswith("build/")}


def _differences(a: dict[str, bytes], b: dict[str, bytes]) -> list[str]:
    return sorted({*a, *b} - {n for n in a.keys() & b.keys() if a[n] == b[n]})


def test_another_blas_gives_the_same_bytes(tmp_path):
    """Fast claims that write certificates, figures, derivations and the appendix."""
    here = _verify_all_in_child(tmp_path / "here", threads=1, coretype=None,
                                claims=FAST_CLAIMS, quick=True)
    there = _verify_all_in_child(tmp_path / "there", threads=2, coretype="Sandybridge",
                                 claims=FAST_CLAIMS, quick=True)
    assert any(n.startswith("certificates/") for n in here)
    assert {"reports/appendix.tex", "reports/figures/nu_reconstructed.svg",
            "reports/figures/nu_reconstructed.pdf"} <= here.keys()
    assert _differences(here, there) == []


def _identify_in_child(log: Path, where: Path, *, threads: int, coretype: str | None
                       ) -> dict[str, bytes]:
    """`verify identify` in a child process run in ``where`` (the same relative --out in
    every run: certificates record the model file's path)."""
    import os
    import subprocess
    import sys

    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("OPENBLAS", "OMP_", "MKL_"))}
    env.update(OPENBLAS_NUM_THREADS=str(threads), OMP_NUM_THREADS=str(threads),
               MKL_NUM_THREADS=str(threads),
               PYTHONPATH=str(Path(__file__).resolve().parents[1]))
    if coretype:
        env["OPENBLAS_CORETYPE"] = coretype
    where.mkdir(parents=True)
    done = subprocess.run([sys.executable, "-m", "verify.cli", "identify", str(log),
                           "--split", "3:3", "--band", "0:2", "--out", "out"], cwd=where,
                          env=env, capture_output=True, text=True, timeout=600, check=False)
    if done.returncode not in (0, 1):
        raise RuntimeError(done.stdout[-2000:] + done.stderr[-2000:])
    return snapshot(where / "out")


def test_another_blas_gives_the_same_identification_bytes(tmp_path):
    """`verify identify` on a closed-loop log: model file (its covariance), passive fit,
    certificates and figures. The estimator's and the passive fit's difference quotients
    once turned the regressors' float noise into changed digits on another BLAS."""
    from identify_loop import loop_log

    log = loop_log(tmp_path / "loop.npz", trials=6)  # 8 trials cost half again, same paths
    here = _identify_in_child(log, tmp_path / "here", threads=1, coretype=None)
    there = _identify_in_child(log, tmp_path / "there", threads=2, coretype="Sandybridge")
    assert {"model.toml", "passive_model.toml"} <= here.keys()
    assert _differences(here, there) == []


@pytest.mark.slow
def test_another_blas_gives_the_same_bytes_for_every_claim(tmp_path):
    """The whole `verify all` (with the identification from simulated logs), twice."""
    here = _verify_all_in_child(tmp_path / "here", threads=1, coretype=None, claims=(),
                                quick=False)
    there = _verify_all_in_child(tmp_path / "there", threads=2, coretype="Sandybridge",
                                 claims=(), quick=False)
    assert _differences(here, there) == []


# ---------------------------------------------------------------- floats as reports write them

def test_report_floats_are_canonical_far_above_float_noise():
    from verify.report.canonical import canonical_data, canonical_float

    rng = random.Random(3)
    for _ in range(2000):
        x = rng.uniform(-1e3, 1e3) * 10.0 ** rng.randint(-20, 20)
        assert canonical_float(x) == canonical_float(x * (1 + 1e-13))  # fails ~1e-9 of x
    assert canonical_float(4.1e-16) == canonical_float(2.3e-16) == 1e-15
    assert canonical_float(-3e-14) == -1e-13 and canonical_float(-0.0) == 0.0
    assert math.copysign(1, canonical_float(-0.0)) == 1
    data = {"max_error_over_bound": 0.04225, "fit": [67.36474448015959, 1.0, "1/3", 7],
            "nested": {"estimate": -2.87984e-10, "flag": True}}
    assert canonical_data(data) == {"max_error_over_bound": 0.1, "fit": [67.36, 1.0, "1/3", 7],
                                    "nested": {"estimate": -2.88e-10, "flag": True}}
