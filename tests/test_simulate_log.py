"""``verify simulate --log``: the run's trials as an experiment log, consistent with the run."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from verify.inputs.experiment_log import read_log
from verify.passivity.io.model_file import load_model

MODEL = Path(__file__).resolve().parents[1] / "verify" / "data" / "models" / \
    "reconstructed_ks3p0.toml"


def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "verify.cli", *args], capture_output=True,
                          text=True)


def _e(data) -> np.ndarray:
    M = np.einsum("kji,kjl->kil", data["R_l"], data["R_r"])  # R_l^T R_r
    return 0.5 * np.stack([M[:, 2, 1] - M[:, 1, 2], M[:, 0, 2] - M[:, 2, 0]], axis=1)


def test_switching_run_gives_one_trial_per_reference(tmp_path):
    log_path = tmp_path / "log.csv"
    out = run_cli("simulate", "--human", "static", "--gain", "0.7", "--n", "2", "--seconds",
                  "16", "--reference", "switching", "--autonomous", "zero", "--no-plots",
                  "--out", str(tmp_path / "run"), "--log", str(log_path))
    assert out.returncode == 0, out.stderr
    assert str(log_path) in out.stdout
    header = next(line for line in log_path.read_text().splitlines() if line[0] != "#")
    assert header == "time,trial,e1,e2,u1,u2,r1,r2,r3"  # no start events for this human
    log = read_log(log_path)
    assert log.rate == pytest.approx(120.0, rel=1e-9)
    data = np.load(tmp_path / "run" / "trajectory.npz")
    first, second = log.trials
    assert (first.trial, second.trial) == (0, 1)
    assert first.t.shape == (1800,) and second.t.shape == (121,)  # [0, 15) and [15, 16]
    t = np.concatenate([first.t, second.t])
    np.testing.assert_array_equal(t, data["t"])
    e = np.concatenate([first.e, second.e])
    np.testing.assert_allclose(e, _e(data), rtol=0, atol=1e-15)
    np.testing.assert_array_equal(np.concatenate([first.u, second.u]), 0.7 * e)  # u = K e
    ref = np.concatenate([first.reference, second.reference])
    np.testing.assert_array_equal(ref, data["R_r"][:, :, 2])
    assert not np.allclose(first.reference[0], second.reference[0])  # the reference switched


def test_model_human_with_noises_in_npz(tmp_path):
    log_path = tmp_path / "log.npz"
    out = run_cli("simulate", "--model", str(MODEL), "--n", "2", "--seconds", "3",
                  "--autonomous", "zero", "--no-plots", "--out", str(tmp_path / "run"),
                  "--log", str(log_path), "--operator-noise", "0.05",
                  "--measurement-noise", "0.01")
    assert out.returncode == 0, out.stderr
    assert "operator noise 0.05" in out.stdout
    (trial,) = read_log(log_path).trials
    data = np.load(tmp_path / "run" / "trajectory.npz")
    model = load_model(MODEL)
    x = data["human_state"]
    assert x.shape == (361, model.n) and trial.u.shape == (361, 2)
    # u = C x + D e + operator noise, logged with measurement noise on e and u
    residual = trial.u - x @ model.C.T - trial.e @ model.D.T
    assert np.std(residual) == pytest.approx(np.hypot(0.05, 0.01), rel=0.2)
    noise_e = trial.e - _e(data)
    assert np.std(noise_e) == pytest.approx(0.01, rel=0.2)


@pytest.mark.parametrize(("args", "message"), [
    (["--log", "run.txt"], "name the log .csv or .npz"),
    (["--log", "x.csv", "--operator-noise", "0.1"], "--operator-noise needs an LTI human"),
    (["--measurement-noise", "0.1"], "applies to the logged signals: give --log"),
    (["--log", "x.csv", "--model", str(MODEL), "--operator-noise", "-1"], "numbers >= 0"),
])
def test_bad_log_settings_are_one_line_and_write_nothing(tmp_path, args, message):
    args = [str(tmp_path / a) if a in ("run.txt", "x.csv") else a for a in args]
    out = run_cli("simulate", "--seconds", "1", "--no-plots", "--out", str(tmp_path / "run"),
                  *args)
    assert out.returncode == 2
    assert message in out.stderr and len(out.stderr.strip().splitlines()) == 1
    assert list(tmp_path.iterdir()) == []
