"""``verify simulate``: outputs, summary, and bad input (one line, exit 2)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

MODELS = Path(__file__).resolve().parents[1] / "verify" / "data" / "models"


def run_cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "verify.cli", *args], capture_output=True,
                          text=True, cwd=cwd)


def test_default_run_writes_trajectory_and_four_plots(tmp_path):
    out = run_cli("simulate", "--seconds", "3", "--out", str(tmp_path))
    assert out.returncode == 0, out.stderr
    names = {p.name for p in tmp_path.iterdir()}
    assert names == {"trajectory.npz", "energy.png", "lemma1.png", "dbar_error.png",
                     "sphere.png"}
    data = np.load(tmp_path / "trajectory.npz")
    t = data["t"]
    assert t[-1] == pytest.approx(3.0) and t.shape[0] == 361  # 120 Hz
    assert data["d"].shape[1:] == (8, 3)  # the bodies' directions, n = 8
    # the quasi-average keeps R-bar e3 = dbar (Section 3), recorded independently
    assert np.max(np.abs(data["R_bar"][:, :, 2] - data["dbar"])) < 1e-9
    assert "Lemma 1: min tr(R-bar_r)" in out.stdout
    assert "orthogonality drift" in out.stdout


def test_csv_with_passive_model_uses_certificate_storage_and_checks(tmp_path):
    model = MODELS / "reconstructed_ks3p0.toml"
    out = run_cli("simulate", "--model", str(model), "--ks", "3", "--seconds", "2",
                  "--format", "csv", "--no-plots", "--autonomous", "zero", "--check",
                  "--out", str(tmp_path))
    assert out.returncode == 0, out.stderr
    assert "passive (KYP certificate checked exactly)" in out.stdout
    checks = [line for line in out.stdout.splitlines() if "violation" in line]
    assert len(checks) == 5 and all(": holds;" in line for line in checks[:4]), out.stdout
    assert "LaSalle" in checks[4]  # 2 s is too short for the tenth: a proxy, may fail
    assert [p.name for p in tmp_path.iterdir()] == ["trajectory.csv"]
    table = np.genfromtxt(tmp_path / "trajectory.csv", delimiter=",", names=True)
    assert np.all(np.diff(table["V"]) <= 1e-9)  # Theorem 1 with S_h = x^T P x / 2
    assert np.all(table["V_dot"] <= table["V_dot_bound"] + 1e-12)


def test_non_passive_model_is_reported(tmp_path):
    model = MODELS / "reconstructed_ks2p5.toml"
    out = run_cli("simulate", "--model", str(model), "--seconds", "1", "--no-plots",
                  "--out", str(tmp_path))
    assert out.returncode == 0, out.stderr
    assert "not passive" in out.stdout and "running supply" in out.stdout


def _bad_model(tmp_path: Path) -> Path:
    path = tmp_path / "wide.toml"
    path.write_text("[state_space]\nA = [[-1.0]]\nB = [[1.0, 0.0]]\nC = [[1.0]]\n"
                    "D = [[0.0, 0.0]]\n")
    return path


def _cancelling_network(tmp_path: Path) -> Path:
    path = tmp_path / "cancel.toml"
    path.write_text("quaternions = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]\n")
    return path


BAD = {
    "n = 0": (lambda p: ["--n", "0"], "at least 1"),
    "k_s = 0": (lambda p: ["--ks", "0"], "k_s"),
    "k_s < 0": (lambda p: ["--ks", "-2"], "--ks"),
    "k_s nan": (lambda p: ["--ks", "nan"], "--ks"),
    "seconds": (lambda p: ["--seconds", "-1"], "--seconds"),
    "non-square model": (lambda p: ["--model", str(_bad_model(p))], "square"),
    "undefined dbar": (lambda p: ["--network", str(_cancelling_network(p))], "dbar"),
    "model missing": (lambda p: ["--human", "model"], "--model"),
    "too many steps": (lambda p: ["--seconds", "1e9"], "steps asked"),
    "too many bodies": (lambda p: ["--n", "100000000"], "bodies fit"),
    "nan seconds": (lambda p: ["--seconds", "nan"], "--seconds"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_input_one_line_exit_2_and_nothing_written(tmp_path, case):
    args, expected = BAD[case]
    out_dir = tmp_path / "out"
    out = run_cli("simulate", "--seconds", "1", "--out", str(out_dir), *args(tmp_path))
    assert out.returncode == 2, (out.stdout, out.stderr)
    assert expected in out.stderr
    assert len(out.stderr.strip().splitlines()) == 1 and "Traceback" not in out.stderr
    assert not out_dir.exists()


def test_adaptive_flag_runs_error_controlled_steps(tmp_path, capsys):
    """--adaptive RTOL takes far fewer steps than samples and keeps the sampled output."""

    from verify.cli import main

    model = Path(__file__).resolve().parents[1] / "verify/data/models/reconstructed_ks3p0.toml"
    code = main(["simulate", "--model", str(model), "--seconds", "5", "--adaptive", "1e-8",
                 "--no-plots", "--out", str(tmp_path / "a")])
    out = capsys.readouterr().out
    assert code == 0 and "adaptive steps (rtol 1e-08" in out
    accepted = int(out.split("adaptive steps")[1].split("):")[1].split("accepted")[0])
    assert 0 < accepted < 600  # 600 samples at 120 Hz
    with np.load(tmp_path / "a" / "trajectory.npz") as data:
        assert data["t"].shape == (601,)


def test_adaptive_flag_refuses_a_bad_tolerance_before_running(tmp_path, capsys):
    from verify.cli import main

    assert main(["simulate", "--adaptive", "-1", "--out", str(tmp_path / "b")]) == 2
    captured = capsys.readouterr()
    assert "--adaptive must be a positive number" in captured.err
    assert captured.out == "" and not (tmp_path / "b").exists()


def test_progress_only_on_a_terminal_or_when_asked(tmp_path):
    """stderr is a pipe here: no progress unless --progress (then a line per tenth)."""
    quiet = run_cli("simulate", "--seconds", "6", "--no-plots", "--out", str(tmp_path / "a"))
    assert quiet.returncode == 0 and quiet.stderr == ""
    shown = run_cli("simulate", "--seconds", "6", "--no-plots", "--progress", "--out",
                    str(tmp_path / "b"))
    assert shown.returncode == 0 and "100%" in shown.stderr and "\r" not in shown.stderr


def test_progress_rule_is_shared_with_campaigns():
    import io

    from verify.campaign.progress import CampaignProgress
    from verify.progress import progress_wanted

    class Tty(io.StringIO):
        def isatty(self) -> bool:
            return True

    assert not progress_wanted(io.StringIO()) and progress_wanted(io.StringIO(), forced=True)
    assert progress_wanted(Tty()) and not progress_wanted(Tty(), quiet=True)
    log = io.StringIO()
    bar = CampaignProgress(20, 0, stream=log, forced=True)
    for _ in range(20):
        bar.update(1)
    bar.close()
    lines = log.getvalue().splitlines()
    assert "\r" not in log.getvalue() and 10 <= len(lines) <= 11
    assert lines[-1].startswith("campaign: 20/20 runs")
    assert not CampaignProgress(20, 0, stream=io.StringIO()).enabled


def test_the_slow_engine_says_why():
    from verify.sim.command import SimulateSettings, build_human, build_scenario, engine_line
    from verify.sim.humans import Human

    class Custom(Human):  # a human the kernels do not know
        name = "custom"

        def command(self, t, x, e, R_l, held):
            return np.zeros(3)

    s = SimulateSettings(seconds=1.0)
    sc = build_scenario(s, build_human(s)[0])
    sc.human = Custom()
    assert engine_line(sc) == ("Python field (slow: the kernels do not model the human "
                               "Custom)")


def test_the_engine_is_named_and_the_slow_one_explained(tmp_path):
    fast = run_cli("simulate", "--seconds", "0.5", "--no-plots", "--out", str(tmp_path / "a"))
    assert "engine: compiled kernels (numba)" in fast.stdout
    model = MODELS / "reconstructed_ks3p0.toml"
    slow = run_cli("simulate", "--model", str(model), "--seconds", "0.5", "--no-plots",
                   "--operator-noise", "0.01", "--out", str(tmp_path / "b"))
    assert slow.returncode == 0, slow.stderr
    assert "engine: compiled kernels (numba)" in slow.stdout  # the noisy operator too
    patched = run_cli("simulate", "--seconds", "0.5", "--no-plots", "--autonomous", "random",
                      "--human", "static", "--out", str(tmp_path / "c"))
    assert "engine: compiled" in patched.stdout  # a signal input is compiled as well


def test_help_documents_format_gain_and_where_outputs_go():
    text = run_cli("simulate", "--help").stdout
    flat = " ".join(text.split())
    assert "trajectory.npz" in flat and "default 1)" in flat
    assert "default build/simulation" in flat
    campaign = " ".join(run_cli("campaign", "--help").stdout.split())
    assert "default build/campaigns/" in campaign and "--progress" in campaign


def test_default_output_is_under_build(tmp_path):
    out = run_cli("simulate", "--seconds", "0.2", "--no-plots", cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert (tmp_path / "build" / "simulation" / "trajectory.npz").is_file()
    assert not (tmp_path / "reports").exists()
