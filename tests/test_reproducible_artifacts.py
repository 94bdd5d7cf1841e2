"""Reproducible artefacts: `verify all` writes the same bytes twice.

With SOURCE_DATE_EPOCH set, reports (Markdown, HTML, JSON, figures) and certificates are
byte-identical between runs; without it, the reports differ only in their final Run
block (date and timings). Run on the Section 4 claims, which write certificates and
figures, to keep the test short.
"""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import pytest

from verify.cli import main


def snapshot(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*"))
            if p.is_file()}


def run_all(where: Path) -> dict[str, bytes]:
    """`verify all --only sec4` into fresh directories; returns every file written."""
    shutil.rmtree(where / "out", ignore_errors=True)
    assert main(["all", "--only", "sec4", "--out", str(where / "out" / "reports"),
                 "--certificates", str(where / "out" / "certificates")]) == 0
    return snapshot(where / "out")


def without_run_block(name: str, data: bytes) -> bytes:
    """A report with its Run block (date, timings) removed."""
    if name.endswith("report.json"):
        doc = json.loads(data)
        assert set(doc["run"]) >= {"generated", "timings"}
        del doc["run"]
        return json.dumps(doc).encode()
    if name.endswith("report.md"):
        text, _, run = data.decode().partition("\n## Run\n")
        assert run
        return text.encode()
    if name.endswith("report.html"):
        text, _, run = data.decode().partition("<h2>Run</h2>")
        assert run
        return text.encode()
    return data


def test_verify_all_is_byte_identical_with_source_date_epoch(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    first = run_all(tmp_path)
    assert any(name.startswith("certificates/") for name in first)
    assert any(name.endswith(".png") for name in first)
    assert run_all(tmp_path) == first
    md = first["reports/report.md"].decode()
    assert "Generated 2023-11-14T22:13:20+00:00 (SOURCE_DATE_EPOCH)" in md
    assert not re.search(r"\d+\.\d+ s\b", md)  # no timing anywhere

    monkeypatch.delenv("SOURCE_DATE_EPOCH")
    clock = run_all(tmp_path)
    assert clock.keys() == first.keys()
    for name, data in clock.items():
        assert without_run_block(name, data) == without_run_block(name, first[name]), name
    assert json.loads(clock["reports/report.json"])["run"]["timings"]


@pytest.mark.parametrize("value", ["yesterday", "-1", "1e9"])
def test_bad_source_date_epoch_is_one_line_and_exit_2(monkeypatch, capsys, value, tmp_path):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", value)
    assert main(["all", "--only", "sec4.model", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "SOURCE_DATE_EPOCH" in err and len(err.strip().splitlines()) == 1
    assert not list(tmp_path.iterdir())


def test_parallel_claim_checks_give_the_sequential_report(tmp_path, monkeypatch):
    """verify all --jobs 2 renders byte for byte what --jobs 1 renders (fast claims)."""
    from verify.cli import main

    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
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
