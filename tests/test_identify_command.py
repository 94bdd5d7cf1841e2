"""`verify identify`: exit codes, files, JSON, JUnit, certificates, bad input.

The logs here are fast synthetic open-loop experiments with the shipped operators
(:func:`identify_models.open_loop_log`, 4 trials); the closed-loop shipped logs are
exercised by the ``sec4.identification`` claim.
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from fractions import Fraction
from pathlib import Path

import pytest
from identify_models import open_loop_log

from verify.cli import main
from verify.identify.data.example_logs import EXAMPLES
from verify.inputs.experiment_log import write_log


@pytest.fixture(scope="module")
def logs(tmp_path_factory) -> dict[str, Path]:
    """Short synthetic experiments (4 trials of 15 s) with the shipped operators."""
    d = tmp_path_factory.mktemp("logs")
    return {ex.name: write_log(_apart(open_loop_log(ex.model(), trials=4, seed=ex.seed)),
                               d / f"{ex.name}.npz") for ex in EXAMPLES}


def _apart(log):
    """Each synthetic trial starts at rest: logged 1000 s apart, so the command's carried
    state has decayed to rest by the next trial (not back to back, as in the loop)."""
    from dataclasses import replace

    trials = tuple(replace(tr, t=tr.t + 1000.0 * k, start=tr.start + 1000.0 * k)
                   for k, tr in enumerate(log.trials))
    return replace(log, trials=trials)


@pytest.fixture(scope="module")
def passive_run(logs, tmp_path_factory):
    d = tmp_path_factory.mktemp("run")
    out = d / "out"
    code = main(["identify", str(logs["passive_human"]), "--split", "2:2", "--band", "0:1",
                 "--out", str(out), "--json", str(d / "s.json"), "--junit", str(d / "j.xml")])
    return code, d, out


def test_passive_operator_on_a_band_exits_0_with_checked_certificates(passive_run, capsys):
    code, _, out = passive_run
    assert code == 0
    assert (out / "model.toml").is_file()
    assert {p.name for p in (out / "figures").iterdir()} == {"validation.png", "bode.png",
                                                              "nu.png"}
    certs = sorted(p.name for p in out.glob("*.json"))
    assert any("-robust-band-0-1-" in c for c in certs)  # the requested band
    assert any("-band-0-1-" in c and "robust" not in c for c in certs)  # the nominal one
    assert main(["certificates", "check", str(out)]) == 0
    assert "0 of" not in capsys.readouterr().out


def test_json_summary_fields(passive_run):
    _, d, _ = passive_run
    s = json.loads((d / "s.json").read_text())
    assert s["structure"] == "paper" and s["split"] == [2, 2]
    assert len(s["fit"]["identification"]) == 2 and len(s["fit"]["validation"]) == 2
    assert s["nominal"]["verdict"] == "passive" and s["robust"]["verdict"] == "passive"
    assert s["robust"]["band"] == ["0", "1"] and s["robust"]["leaves"] >= 1
    assert Path(s["robust"]["certificate"]).is_file()
    assert s["passed"] is True
    assert s["estimate"]["names"][-2:] == ["c12", "c21"]
    assert [Fraction(x) for x in s["estimate"]["written"]]  # exact decimals, as written
    w_max = s["largest_band"]["w_max"]
    assert w_max is not None and Fraction(w_max) >= 1
    assert "never exactly 0" in s["high_frequency"]
    # what checked each verdict, as a CI reads it (verify gate --coq compiles units)
    assert s["nominal"]["kernel"] == "exact-python"
    assert s["robust"]["kernel"] == "exact-python"
    assert "coq_theorem" in s["robust"] and "kernel" in s["largest_band"]


def test_junit_has_the_nominal_and_robust_cases(passive_run):
    _, d, _ = passive_run
    suite = ET.parse(d / "j.xml").getroot()
    assert suite.get("tests") == "2" and suite.get("failures") == "0"
    kernels = [p.get("value") for p in suite.iter("property") if p.get("name") == "kernel"]
    assert kernels == ["exact-python", "exact-python"]


def test_all_frequencies_fail_for_the_paper_class_exit_1(logs, tmp_path, capsys):
    out = tmp_path / "out"
    code = main(["identify", str(logs["passive_human"]), "--split", "2:2", "--out", str(out),
                 "--json", str(tmp_path / "s.json")])
    assert code == 1
    text = capsys.readouterr().out
    assert "not passive at all frequencies" in text and "proved on [0," in text
    s = json.loads((tmp_path / "s.json").read_text())
    # the centre fails at high frequency; the region decides only if c12 + c21 excludes 0
    assert s["robust"]["verdict"] in ("not passive", "inconclusive")
    assert s["robust"]["witness"] is not None and s["robust"]["answer"]
    assert main(["certificates", "check", str(out)]) == 0  # the largest band's certificate


def test_non_passive_operator_fails_with_a_junit_failure(logs, tmp_path):
    out = tmp_path / "out"
    code = main(["identify", str(logs["nonpassive_human"]), "--split", "2:2", "--band",
                 "0:5", "--out", str(out), "--junit", str(tmp_path / "j.xml"),
                 "--json", str(tmp_path / "s.json")])
    assert code == 1
    suite = ET.parse(tmp_path / "j.xml").getroot()
    assert suite.get("failures") == "2"
    failure = suite.find("testcase/failure")
    assert failure is not None and "not passive" in failure.get("message")
    s = json.loads((tmp_path / "s.json").read_text())
    assert s["robust"]["verdict"] == "not passive"
    assert Fraction(s["robust"]["witness"]["omega"]) <= 5
    assert Path(s["robust"]["refutation_certificate"]).is_file()  # the whole region fails
    assert main(["certificates", "check", str(out)]) == 0


@pytest.mark.parametrize("extra", [
    ["--band", "2:1"], ["--band", "x"], ["--split", "0:2"], ["--split", "6"],
    ["--structure", "2:5"], ["--structure", "order:2"], ["--rate", "-3"], ["--rate", "7"],
])
def test_bad_input_exits_2_and_writes_nothing(logs, tmp_path, extra, capsys):
    out = tmp_path / "out"
    code = main(["identify", str(logs["passive_human"]), "--split", "2:2", "--out", str(out),
                 "--json", str(tmp_path / "s.json"), "--junit", str(tmp_path / "j.xml"),
                 *extra])
    assert code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "error" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == []


def test_bad_logs_exit_2_and_write_nothing(tmp_path, capsys):
    bad = tmp_path / "bad.csv"
    bad.write_text("time,trial\n0,0\n")
    missing = tmp_path / "missing.npz"
    for path in (bad, missing):
        assert main(["identify", str(path), "--out", str(tmp_path / "out")]) == 2
        assert not (tmp_path / "out").exists()


def test_a_foreign_output_directory_is_refused(logs, tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    assert main(["identify", str(logs["passive_human"]), "--split", "2:2", "--out",
                 str(out)]) == 2
    assert (out / "notes.txt").read_text() == "mine"


def test_identification_claim_replaces_its_stale_certificates_in_the_store(tmp_path):
    """After the estimate changes, the store's earlier robust certificates of a shipped
    model are bound to a model file that no longer holds their region; the claim removes
    them (and nothing else) and writes the new ones only into the store."""
    from verify.claims import CheckContext, Verdict, run_claims
    from verify.claims.catalog import REGISTRY

    store = tmp_path / "certificates"
    store.mkdir()
    stale = store / "passive_human-identified-robust-band-0-6.63-000000000000.json"
    stale.write_text("{}")
    unrelated = store / "reconstructed-ks3.0-kyp-all.json"
    unrelated.write_text("{}")
    claim = REGISTRY.get("sec4.identification")
    run = run_claims([claim], CheckContext(quick=True, out_dir=tmp_path / "reports",
                                           certificates_dir=store))
    assert run.results[0].outcome.verdict is Verdict.VERIFIED
    assert not stale.exists() and unrelated.exists()
    unrelated.unlink()
    fresh = sorted(store.glob("*-identified-robust-*.json"))
    assert [p.name.split("-identified-")[0] for p in fresh] == [
        "nonpassive_human", "nonpassive_human", "passive_human"]  # + the region refutation
    assert any("-robust-refuted-" in p.name for p in fresh)
    assert not list((tmp_path / "reports").rglob("*.json"))  # one copy, in the store
    assert main(["certificates", "check", str(store)]) == 0
