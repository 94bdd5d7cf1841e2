"""The report of a campaign, and the ``verify simulate`` command it prints for each run:
the reproduced run's figures equal the campaign row's, and the report is reproducible."""

from __future__ import annotations

import random
import re
from pathlib import Path

import numpy as np
import pytest

from verify.campaign.execute import column, convergence_time, execute_run
from verify.campaign.report import TIMINGS_HEADING, Campaign, build_blocks, render_markdown
from verify.campaign.reproduce import simulate_arguments
from verify.campaign.runs import expand, write_family_files
from verify.cli import main
from verify.inputs.campaign_spec import load_campaign_spec
from verify.sim.properties import largest_rise

MODELS = Path(__file__).resolve().parents[1] / "verify" / "data" / "models"

SPEC = f"""name = "report test"
description = "tiny runs for the report tests"
[sweep]
k_s = [2.0, 3.0]
n = 3
seeds = [4]
seconds = 0.5
step = "1/60"
reference = {{reference}}
[[humans]]
model = "{(MODELS / 'reconstructed_ks2p5.toml').as_posix()}"
[[humans]]
family = "random-passive"
count = 1
seed = 2
[[humans]]
kind = "vr"
[[humans]]
kind = "static"
gain = 0.7
[checks]
properties = ["quasi-average", "lemma1", "lyapunov", "lasalle"]
"""

CHECK_NAMES = {"R-bar e3 = dbar": "quasi-average", "Lemma 1 invariance": "lemma1",
               "Lyapunov decrease": "lyapunov", "LaSalle convergence": "lasalle"}
STATUS = {"holds": "held", "FAILS": "failed", "assumption failed": "assumption-failed"}


@pytest.fixture(scope="module")
def campaign(tmp_path_factory):
    folder = tmp_path_factory.mktemp("campaign")
    (folder / "spec.toml").write_text(SPEC.replace("{reference}", '["constant"]'))
    spec = load_campaign_spec(folder / "spec.toml")
    runs = write_family_files(expand(spec), folder / "humans")
    rows = {r.key: execute_run(r) for r in runs}
    return Campaign(spec, runs, rows), folder


def reproduce(run, out: Path, capsys) -> tuple[dict, dict[str, str]]:
    args = simulate_arguments(run, out=str(out))
    assert main([*args, "--format", "npz"]) == 0
    printed = capsys.readouterr().out
    checks = {}
    for line in printed.splitlines():
        for prefix, prop in CHECK_NAMES.items():
            found = re.match(rf"\s*{re.escape(prefix)}.*?: (holds|FAILS|assumption failed)",
                             line)
            if found:
                checks[prop] = STATUS[found.group(1)]
    data = np.load(out / "trajectory.npz")
    figures = {
        "convergence_time": convergence_time(data["t"], data["dbar_error"],
                                             run.convergence_threshold),
        "dbar_error_end": float(data["dbar_error"][-1]),
        "min_tr_Rbar_r": float(np.min(data["tr_Rbar_r"])),
        "max_V_rise": max(0.0, largest_rise(data["V"])),
        "supply_end": float(data["supply"][-1]),
    }
    return figures, checks


def test_every_row_is_reproduced_by_its_command(campaign, tmp_path, capsys):
    c, _ = campaign
    kinds = set()
    for run in c.runs[::2]:  # one k_s per human: every kind of human
        kinds.add(run.human.kind)
        row = c.rows[run.key]
        assert row["error"] is None
        figures, checks = reproduce(run, tmp_path / run.key, capsys)
        for name, value in figures.items():
            assert row[name] == value, (run.human.label, name, row[name], value)
        for prop in run.properties:
            assert checks[prop] == row[column(prop)], (run.human.label, prop)
    assert kinds == {"model", "vr", "static"}


def test_a_changed_seed_is_not_reproduced(campaign, tmp_path, capsys):
    """The comparison above can fail: another seed gives other figures."""
    from dataclasses import replace

    c, _ = campaign
    run = c.runs[0]
    figures, _ = reproduce(replace(run, seed=run.seed + 1), tmp_path / "other", capsys)
    assert figures["supply_end"] != c.rows[run.key]["supply_end"]


def test_report_text_and_figures_are_reproducible(campaign):
    c, folder = campaign
    blocks, figures, commands = build_blocks(c, cwd=folder)
    shuffled = list(c.rows.items())
    random.Random(1).shuffle(shuffled)
    again = Campaign(c.spec, list(c.runs), dict(shuffled))
    blocks2, figures2, commands2 = build_blocks(again, cwd=folder)
    assert render_markdown(blocks) == render_markdown(blocks2)
    assert figures == figures2 and commands == commands2
    assert set(figures) == {"figures/properties.png", "figures/convergence.png"}
    text = render_markdown(blocks)
    assert TIMINGS_HEADING not in text and "wall" not in text


def test_report_content(campaign):
    c, folder = campaign
    text = render_markdown(build_blocks(c, cwd=folder)[0])
    assert "| reconstructed k_s = 2.5 | " in text and "| not passive |" in text
    assert "random-passive seed 2 [passive]" in text
    assert "VR operator [not established]" in text and "static gain 0.7 [passive]" in text
    failed = [r for r in c.runs if any(c.rows[r.key][column(p)] == "failed"
                                       for p in r.properties)]
    assert f"## Runs that failed a property ({len(failed)})" in text
    for r in failed[:10]:
        assert r.key[:12] in text
    commands = build_blocks(c, cwd=folder)[2].splitlines()
    assert len(commands) == len(c.runs)
    assert all(line.split("  ", 1)[1].startswith("verify simulate --n 3 --ks ")
               for line in commands)
    assert "--model humans/random-passive-seed-2-" in "\n".join(commands)


def test_switching_reference_marks_lasalle_not_applicable(tmp_path):
    """R_r switches every 15 s: a run of 16 s has two references and no LaSalle check."""
    text = SPEC.replace("{reference}", '"switching"').replace("seconds = 0.5", "seconds = 16")
    (tmp_path / "spec.toml").write_text(text.replace('step = "1/60"', "step = 0.1"))
    spec = load_campaign_spec(tmp_path / "spec.toml")
    run = next(r for r in expand(spec) if r.human.kind == "static")
    row = execute_run(run)
    assert row["error"] is None and row["lasalle"] == "n/a" and row["lemma1"] == "held"


def test_a_run_that_raises_is_a_row(tmp_path):
    from dataclasses import replace

    (tmp_path / "spec.toml").write_text(SPEC.replace("{reference}", '"constant"'))
    run = next(r for r in expand(load_campaign_spec(tmp_path / "spec.toml"))
               if r.human.kind == "model")
    broken = replace(run, human=replace(run.human, text=b"[state_space]\nA = [[1.0]]\n",
                                        sha256="0" * 64))
    row = execute_run(broken)
    assert row["key"] == run.key and row["error"].startswith("VerifyInputError")
    assert row["convergence_time"] is None and row["wall_time"] >= 0


def test_html_has_the_main_reports_style_and_wraps_commands():
    """The campaign report reads like report.html (its style sheet) and a long command
    wraps instead of being cut off."""
    from verify.artefacts.html_style import REPORT_CSS
    from verify.campaign.report import Code, render_html

    long = "verify simulate " + " ".join(f"--flag{i} value" for i in range(60))
    page = render_html([("h1", "t <x>"), ("code", Code(long))], "t")
    assert REPORT_CSS in page and "white-space:pre-wrap" in page
    assert long in page and "&lt;x&gt;" in page and "<x>" not in page


def _status_counts(**given):
    from verify.campaign.report import ANYWAY, NOT_ANYWAY

    counts = {"held": 0, "failed": 0, "assumption-failed": 0, "unresolved": 0, "error": 0,
              "n/a": 0, ANYWAY: 0, NOT_ANYWAY: 0}
    counts.update({k.replace("_", "-"): v for k, v in given.items()})
    return counts


def test_cell_wording_says_what_held_outside_the_assumptions():
    """A conclusion that held although the assumption failed reads as held, not as
    '0/4 held' (the old wording read as a failure)."""
    from verify.campaign.report import ANYWAY, NOT_ANYWAY, _cell_text, cell_category

    outside = _status_counts(assumption_failed=4)
    outside[ANYWAY] = 4
    text = _cell_text(outside, 4)
    assert text == "outside the assumptions in all 4: conclusion held in 4"
    assert "0/4" not in text and "held in 0" not in text
    assert cell_category(outside, 4) == "held-outside"
    mixed = _status_counts(held=2, failed=1, assumption_failed=1)
    mixed[NOT_ANYWAY] = 1
    assert _cell_text(mixed, 4) == ("held in 2 of 3 within the assumptions, FAILED in 1; "
                                    "outside the assumptions in 1: conclusion held in 0, "
                                    "failed in 1")
    assert cell_category(mixed, 4) == "failed"
    assert _cell_text(_status_counts(held=3), 3) == "held in 3 of 3"
    assert cell_category(_status_counts(held=3), 3) == "held"
    assert cell_category(_status_counts(held=2, unresolved=1), 3) == "unresolved"


def test_tables_colour_cells_and_never_break_words():
    from verify.campaign.report import CATEGORIES, Table, render_html, render_markdown

    table = Table(["setting", "k_s = 2"], [["reconstructed", "held in 2 of 2"]],
                  [["", "held"]])
    page = render_html([("table", table), ("legend", [("held", "held in every run")])], "t")
    assert "<td class='held'>held in 2 of 2</td>" in page
    assert "div.wide td,div.wide th{overflow-wrap:normal;word-break:normal" in page
    colour = dict((n, c) for n, c, _ in CATEGORIES)["held"]
    assert f"td.held{{background:{colour}}}" in page and "held in every run" in page
    assert "held in every run" in render_markdown([("legend", [("held", "held in every run")])])
