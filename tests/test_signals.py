"""SIGTERM and SIGINT end every command within seconds, leave no process, write nothing.

Each command runs as ``python -m verify.cli`` in a session of its own; the signal goes
to the command's process only (as a CI runner's stop does), and afterwards no process of
the session may be left (a zombie, already dead and waiting for its parent, is not a
process that runs or holds the caller's output open).
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: How long a command may take to end after the signal (measured 0.6-5.8 s at a load
#: average of 13 on 2 cores; the campaign's Dask cluster takes longest to close).
STOP_WITHIN = 20.0


def _session(sid: int) -> list[int]:
    """Live (non-zombie) processes of the session ``sid``."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            if os.getsid(int(entry)) != sid:
                continue
            with open(f"/proc/{entry}/stat") as f:
                state = f.read().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if state != "Z":
            found.append(int(entry))
    return found


def _stop(argv: list[str], cwd: Path, ready: Callable[[int, float], bool],
          sig: signal.Signals) -> tuple[int, float, list[int], str]:
    """Start ``verify argv``, wait until ``ready(pid, seconds)``, send ``sig``; return
    (exit code, seconds from the signal to the exit, processes left, stderr)."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.Popen([sys.executable, "-m", "verify.cli", *argv], cwd=cwd,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            env=env, start_new_session=True)
    start = time.monotonic()
    try:
        while not ready(proc.pid, time.monotonic() - start):
            assert proc.poll() is None, proc.communicate()
            assert time.monotonic() - start < 300, "the command never became ready"
            time.sleep(0.1)
        proc.send_signal(sig)
        sent = time.monotonic()
        _, err = proc.communicate(timeout=120)
        took = time.monotonic() - sent
        deadline = time.monotonic() + 3.0  # children that are exiting get a moment
        left = _session(proc.pid)
        while left and time.monotonic() < deadline:
            time.sleep(0.1)
            left = _session(proc.pid)
        return proc.returncode, took, left, err
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        for pid in _session(proc.pid):
            os.kill(pid, signal.SIGKILL)


def _check(code: int, took: float, left: list[int], err: str, sig: signal.Signals) -> None:
    assert code == 128 + sig, (code, err)
    assert took < STOP_WITHIN, took
    assert left == [], left
    assert f"verify: {sig.name}: stopped" in err and "Traceback" not in err, err


def _after(seconds: float) -> Callable[[int, float], bool]:
    return lambda pid, t: t >= seconds


def _gate_model(tmp_path: Path, n: int = 60) -> Path:
    """A passive n-state model, A = -I - S (S skew), C = Bᵀ, that takes the gate seconds."""
    import numpy as np

    rng = np.random.default_rng(1)
    S = np.round(rng.normal(size=(n, n)), 3)
    S = np.triu(S, 1) - np.triu(S, 1).T
    A, B = -np.eye(n) - S, np.round(rng.normal(size=(n, 1)), 3)

    def toml(M) -> str:
        return "[" + ", ".join("[" + ", ".join(f"{x:.3f}" for x in row) + "]"
                               for row in M) + "]"

    path = tmp_path / "m60.toml"
    path.write_text(f'name = "m60"\n[state_space]\nA = {toml(A)}\nB = {toml(B)}\n'
                    f"C = {toml(B.T)}\nD = [[0.0]]\n")
    return path


@pytest.mark.slow
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_gate_on_a_60_state_model_stops(tmp_path, sig):
    """Four copies of a 60-state model (a few seconds each); the signal comes while the
    first is decided."""
    model = _gate_model(tmp_path)
    copies = [tmp_path / f"m{k}.toml" for k in range(4)]
    for k, copy in enumerate(copies):
        copy.write_text(model.read_text().replace('"m60"', f'"m60-{k}"'))
    code, took, left, err = _stop(["gate", *map(str, copies), "--certificates", "certs",
                                   "--json", "g.json"], tmp_path, _after(2.5), sig)
    _check(code, took, left, err, sig)
    assert not (tmp_path / "g.json").exists()  # the summary comes after every model
    _whole_json_only(tmp_path / "certs")


def _whole_json_only(folder: Path) -> None:
    """Certificates written before the signal are whole; no temporary file is left."""
    import json

    for path in folder.glob("*") if folder.exists() else ():
        assert path.suffix == ".json" and not path.name.startswith("."), path
        json.loads(path.read_text())


@pytest.mark.slow
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_all_with_two_jobs_stops_its_pool(tmp_path, sig):
    """The pool's two workers, its forkserver and resource tracker all end; no report
    and no certificate is written after the signal."""
    def workers_started(pid: int, t: float) -> bool:
        return len(_session(pid)) >= 4 and t >= 3.0

    code, took, left, err = _stop(["all", "--jobs", "2", "--only", "sec4", "--quick",
                                   "--out", "out", "--certificates", "certs"], tmp_path,
                                  workers_started, sig)
    _check(code, took, left, err, sig)
    assert not (tmp_path / "out").exists()
    written = sorted((tmp_path / "certs").rglob("*")) if (tmp_path / "certs").exists() else []
    time.sleep(2.0)  # a worker left alive would write its certificate now
    after = sorted((tmp_path / "certs").rglob("*")) if (tmp_path / "certs").exists() else []
    assert after == written
    _whole_json_only(tmp_path / "certs")


@pytest.mark.slow
def test_identify_stops(tmp_path):
    log = tmp_path / "log.npz"
    shutil.copy(ROOT / "verify" / "data" / "logs" / "passive_human.npz", log)
    code, took, left, err = _stop(["identify", str(log), "--out", "out", "--json", "i.json"],
                                  tmp_path, _after(5.0), signal.SIGTERM)
    _check(code, took, left, err, signal.SIGTERM)
    assert not (tmp_path / "out").exists() and not (tmp_path / "i.json").exists()


@pytest.mark.slow
@pytest.mark.parametrize("delay", [2.0, 20.0])  # before and after the cluster started
def test_campaign_stops_its_cluster(tmp_path, delay):
    spec = ROOT / "verify" / "data" / "campaigns" / "small.toml"
    code, took, left, err = _stop(["campaign", str(spec), "--out", "out", "--workers", "2",
                                   "--quiet"], tmp_path, _after(delay), signal.SIGTERM)
    _check(code, took, left, err, signal.SIGTERM)
    empty = [d for d, dirs, files in os.walk(tmp_path / "out") if not dirs and not files]
    assert empty == []
