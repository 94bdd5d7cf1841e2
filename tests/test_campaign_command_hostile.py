"""Hostile inputs to ``verify campaign`` beyond the spec reader: the output folder, the
store of another campaign, and text that would inject Markdown or HTML into the report.
Each is one line on stderr and exit 2 before any run, or rendered as inert text."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from verify.campaign.execute import execute_run
from verify.campaign.report import Campaign, build_blocks, md_text, render_markdown
from verify.campaign.runs import expand, spec_fingerprint
from verify.campaign.store import ResultStore
from verify.cli import main
from verify.inputs.campaign_spec import load_campaign_spec

SPEC = """name = "{name}"
[sweep]
k_s = [2.0]
n = 2
seeds = [0]
seconds = 0.1
step = "1/60"
[[humans]]
kind = "vr"
label = {label}
[checks]
properties = ["lemma1"]
"""


def spec_file(folder: Path, name: str = "hostile", label: str = '"operator"') -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{name}.toml"
    path.write_text(SPEC.format(name=name, label=label))
    return path


def refused(capsys, argv: list[str], needle: str) -> None:
    code = main(argv)
    err = capsys.readouterr().err
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err and needle in lines[0], err


# ---------------------------------------------------------------- the output folder


def test_out_naming_an_existing_file_is_refused_before_any_run(tmp_path, capsys):
    spec = spec_file(tmp_path)
    out = tmp_path / "report.txt"
    out.write_text("keep me")
    refused(capsys, ["campaign", str(spec), "--out", str(out), "--workers", "1"],
            "exists and is not a folder")
    assert out.read_text() == "keep me"


@pytest.mark.parametrize("inside", ["results", "humans", "figures"])
def test_a_file_where_a_folder_goes_is_refused(tmp_path, capsys, inside):
    spec = spec_file(tmp_path)
    out = tmp_path / "out"
    out.mkdir()
    (out / inside).write_text("x")
    refused(capsys, ["campaign", str(spec), "--out", str(out), "--workers", "1"],
            "is in the way")
    assert not (out / "campaign.md").exists()


def test_a_folder_where_the_report_goes_is_refused(tmp_path, capsys):
    spec = spec_file(tmp_path)
    out = tmp_path / "out"
    (out / "campaign.md").mkdir(parents=True)
    refused(capsys, ["campaign", str(spec), "--out", str(out), "--workers", "1"],
            "is in the way")
    assert not (out / "results").exists()


def test_out_below_a_file_is_refused(tmp_path, capsys):
    spec = spec_file(tmp_path)
    (tmp_path / "plain").write_text("x")
    refused(capsys, ["campaign", str(spec), "--out", str(tmp_path / "plain" / "sub"),
                     "--workers", "1"], "is not a folder")


# ---------------------------------------------------------------- the store's campaign


def test_resume_into_another_campaigns_store_is_refused(tmp_path, capsys):
    first = load_campaign_spec(spec_file(tmp_path, "first"))
    store = ResultStore(tmp_path / "out" / "results")
    store.bind(spec_fingerprint(first), first.name)
    store.append([execute_run(expand(first)[0])])
    second = spec_file(tmp_path, "second")
    refused(capsys, ["campaign", str(second), "--out", str(tmp_path / "out"), "--resume",
                     "--workers", "1"], "holds the store of another campaign ('first'")
    assert store.count() == 1


def test_an_edited_sweep_is_another_campaign_but_comments_are_not(tmp_path):
    path = spec_file(tmp_path)
    base = spec_fingerprint(load_campaign_spec(path))
    path.write_text("# a comment\n" + path.read_text())
    assert spec_fingerprint(load_campaign_spec(path)) == base
    path.write_text(path.read_text().replace("seeds = [0]", "seeds = [0, 1]"))
    assert spec_fingerprint(load_campaign_spec(path)) != base


def test_rows_without_a_campaign_record_are_refused(tmp_path, capsys):
    spec = load_campaign_spec(spec_file(tmp_path))
    store = ResultStore(tmp_path / "out" / "results")
    store.append([execute_run(expand(spec)[0])])  # written with no campaign.json
    refused(capsys, ["campaign", str(spec.path), "--out", str(tmp_path / "out"), "--resume",
                     "--workers", "1"], "no record of their campaign")


@pytest.mark.parametrize("record", ["{not json", '{"name": "x"}', "[1, 2]"])
def test_a_damaged_campaign_record_is_one_line(tmp_path, capsys, record):
    spec = spec_file(tmp_path)
    (tmp_path / "out" / "results").mkdir(parents=True)
    (tmp_path / "out" / "results" / "campaign.json").write_text(record)
    refused(capsys, ["campaign", str(spec), "--out", str(tmp_path / "out"), "--resume",
                     "--workers", "1"], "not a readable campaign record")


# ---------------------------------------------------------------- Markdown injection

EVIL = ['# Heading injected', '<script>alert(1)</script>', '<img src=x onerror=alert(1)>',
        '[click](javascript:alert(1))', '| a | b |', '```', '- list item', '1. first',
        '> quote', '![x](http://e/x.png)', 'a\\\\', '&lt;b&gt;', '=== ']


@pytest.mark.parametrize("evil", EVIL)
def test_md_text_is_inert(evil):
    text = md_text(evil)
    assert "\n" not in text
    assert not re.search(r"(?<!\\)[<>`|&#]", text), text  # every opener escaped
    assert not re.search(r"(?<!\\)\]\(|(?<!\\)\]\[|^\[", text), text  # no link or image
    assert not re.match(r"\s*([-+=>*]|\d+[.)])", text), text  # no block starts


def test_a_humans_label_cannot_inject_into_campaign_md(tmp_path):
    label = '"x\\n# Injected heading\\n<script>alert(1)</script> | cell"'
    spec = load_campaign_spec(spec_file(tmp_path, "evil spec <b>", label))
    runs = expand(spec)
    rows = {r.key: execute_run(r) for r in runs}
    text = render_markdown(build_blocks(Campaign(spec, runs, rows))[0])
    headings = [ln for ln in text.splitlines() if ln.startswith("#")]
    assert headings and all(re.match(r"#{1,2} [A-Z]", h) for h in headings), headings
    assert "Injected heading" not in " ".join(headings)
    assert "<script>" not in text and "<b>" not in text
    assert "\\<script\\>" in text
    table_rows = [ln for ln in text.splitlines() if ln.startswith("| x")]
    assert table_rows and all(ln.count(" | ") == ln.replace("\\|", "").count(" | ")
                              for ln in table_rows)


def test_a_code_block_cannot_be_closed_by_its_content():
    from verify.campaign.report import Code

    text = render_markdown([("code", Code("verify simulate --model 'a```b.toml'"))])
    fence = text.splitlines()[0]
    assert set(fence) == {"`"} and len(fence) > 3 and text.splitlines()[2] == fence


def test_the_campaign_record_is_written_with_the_first_rows(tmp_path):
    spec = load_campaign_spec(spec_file(tmp_path))
    store = ResultStore(tmp_path / "results")
    store.bind(spec_fingerprint(spec), spec.name)
    assert not store.folder.exists()  # a refused or failed start leaves nothing
    store.append([execute_run(expand(spec)[0])])
    assert (store.folder / "campaign.json").is_file()
    ResultStore(store.folder).bind(spec_fingerprint(spec), spec.name)  # same campaign: fine
