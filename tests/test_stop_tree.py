"""A stop stops every process of the call, and nothing is written after its message.

The signal goes to the top ``verify`` process only (as a CI runner's timeout or a user's
``kill`` does). Every process of the call is found by a marker in its environment (which
each child inherits, whatever session, group or parent it ends up with), so a process
that left the group or was re-parented to init is still counted. "Nothing written after
it": no file of the output folder is newer than the moment the command exited, and none
appears or changes in the seconds after.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
import uuid
from pathlib import Path

import pytest

from verify.process_tree import descendants, end_tree

ROOT = Path(__file__).resolve().parents[1]
MARK = "VERIFY_TEST_CALL"


def _marked(mark: str) -> list[int]:
    """Live (non-zombie) processes whose environment holds ``MARK=mark``."""
    needle = f"{MARK}={mark}".encode()
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/environ", "rb") as f:
                if needle not in f.read().split(b"\0"):
                    continue
            with open(f"/proc/{entry}/stat") as f:
                state = f.read().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if state not in ("Z", "X"):
            found.append(int(entry))
    return found


def _files(folder: Path) -> dict[str, int]:
    if not folder.exists():
        return {}
    return {str(p): p.stat().st_mtime_ns for p in folder.rglob("*")}


def _stop_at(argv: list[str], cwd: Path, sig: signal.Signals, *, after: float = 0.0,
             processes: int = 1) -> tuple[int, str, list[int], int]:
    """Start ``verify argv``; once ``after`` seconds passed and ``processes`` processes
    of the call run, send ``sig`` to its PID; return (exit code, stderr, processes of the
    call alive after the exit, the exit time in ns)."""
    mark = uuid.uuid4().hex
    env = dict(os.environ, PYTHONPATH=str(ROOT), **{MARK: mark})
    proc = subprocess.Popen([sys.executable, "-m", "verify.cli", *argv], cwd=cwd,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            env=env)
    start = time.monotonic()
    try:
        while time.monotonic() - start < after or len(_marked(mark)) < processes:
            assert proc.poll() is None, ("ended before the signal", proc.communicate())
            assert time.monotonic() - start < 300, "the command never became ready"
            time.sleep(0.05)
        proc.send_signal(sig)
        _, err = proc.communicate(timeout=120)
        ended = time.time_ns()
        return proc.returncode, err, _marked(mark), ended
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        for pid in _marked(mark):  # a failed test leaves nothing behind either
            os.kill(pid, signal.SIGKILL)


def _check(argv: list[str], tmp_path: Path, sig: signal.Signals, out: Path, **when) -> str:
    code, err, left, ended = _stop_at(argv, tmp_path, sig, **when)
    assert left == [], f"processes of the call alive after its exit: {left}"
    before = _files(out)
    newer = [p for p, t in before.items() if t > ended]
    assert newer == [], f"written after the exit: {newer}"
    assert "Traceback" not in err, err
    if "stopped" in err:  # (the command may also have ended before the signal came)
        assert code == 128 + sig and f"verify: {sig.name}: stopped" in err, (code, err)
    else:
        assert code in (0, 1), (code, err)
    time.sleep(1.5)  # a survivor would write now
    assert _files(out) == before
    return err


def test_end_tree_ends_children_and_grandchildren():
    """end_tree ends a child and its grandchild, which ignores SIGTERM (so SIGKILL after
    the grace), and leaves the processes it is told to keep."""
    keep = tuple(descendants())
    code = ("import os, signal, subprocess, sys, time\n"
            "p = subprocess.Popen([sys.executable, '-c', "
            "'import signal, time; signal.signal(signal.SIGTERM, signal.SIG_IGN); "
            "print(1, flush=True); time.sleep(60)'], stdout=subprocess.PIPE)\n"
            "p.stdout.readline(); print(p.pid, flush=True); time.sleep(60)\n")
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    grandchild = int(child.stdout.readline())
    assert grandchild in descendants()
    found = end_tree(grace=0.5, keep=keep)
    assert {child.pid, grandchild} <= set(found)
    assert child.wait(5) is not None
    try:  # gone, or a zombie (re-parented to init, which reaps it)
        with open(f"/proc/{grandchild}/stat") as f:
            assert f.read().rsplit(")", 1)[1].split()[0] in ("Z", "X")
    except FileNotFoundError:
        pass


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_a_signal_during_an_import_is_not_swallowed(tmp_path, sig):
    """A module whose import swallows KeyboardInterrupt with a bare ``except:`` (as
    mpmath's guard around importing gmpy2 does) gets the signal while it is imported:
    the stop comes once the import is done, instead of being lost."""
    (tmp_path / "swallowing.py").write_text(
        "import os, signal, time\n"
        "try:\n"
        f"    os.kill(os.getpid(), {int(sig)})\n"
        "    time.sleep(0.5)\n"
        "except:  # noqa: E722\n"
        "    pass\n")
    code = (f"import sys, time\nsys.path.insert(0, {str(tmp_path)!r})\n"
            "from verify.stopping import StopSignals\n"
            "stop = StopSignals()\n"
            "try:\n"
            "    with stop:\n"
            "        import swallowing\n"
            "        time.sleep(10)\n"
            "        print('ran on')\n"
            "except KeyboardInterrupt:\n"
            "    print('stopped', stop.name())\n")
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=str(ROOT)), timeout=60)
    assert done.stdout.strip() == f"stopped {sig.name}", (done.stdout, done.stderr)
    assert time.monotonic() - start < 8


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_all_stops_its_pool_workers_and_helpers(tmp_path, sig):
    """Once the pool's forkserver, resource tracker and workers run (5 processes), a
    signal to the top process ends them all before the stop message."""
    out = tmp_path / "D"
    _check(["all", "--jobs", "2", "--only", "sec2", "--quick", "--out", str(out),
            "--certificates", str(out / "certs"), "--run-record", str(out / "run.json"),
            "--no-latex"], tmp_path, sig, out, processes=5)


#: Seconds after the start of ``verify all`` at which the slow test stops it: every
#: 0.75 s of the first 15 s (imports, the pool starting, the first claims).
STOP_TIMES = [0.5 + 0.75 * k for k in range(20)]


@pytest.mark.slow
@pytest.mark.parametrize("k", range(len(STOP_TIMES)))
def test_all_stopped_at_many_times(tmp_path, k):
    sig = (signal.SIGTERM, signal.SIGINT)[k % 2]
    out = tmp_path / "D"
    _check(["all", "--out", str(out), "--certificates", str(out / "certs"),
            "--run-record", str(out / "run.json")], tmp_path, sig, out,
           after=STOP_TIMES[k])


@pytest.mark.slow
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_identify_stops_everything(tmp_path, sig):
    log = tmp_path / "log.npz"
    shutil.copy(ROOT / "verify" / "data" / "logs" / "passive_human.npz", log)
    out = tmp_path / "out"
    _check(["identify", str(log), "--out", str(out), "--json", str(out / "i.json")],
           tmp_path, sig, out, after=5.0)


@pytest.mark.slow
@pytest.mark.parametrize("after", [1.0, 4.0])
def test_gate_stops_everything(tmp_path, after):
    from test_signals import _gate_model

    model = _gate_model(tmp_path)  # four copies: a few seconds each
    copies = [tmp_path / f"m{k}.toml" for k in range(4)]
    for k, copy in enumerate(copies):
        copy.write_text(model.read_text().replace('"m60"', f'"m60-{k}"'))
    out = tmp_path / "certs"
    _check(["gate", *map(str, copies), "--certificates", str(out)], tmp_path,
           signal.SIGTERM, out, after=after)


@pytest.mark.slow
@pytest.mark.parametrize("after", [2.0, 12.0])  # before and after the cluster started
def test_campaign_stops_everything(tmp_path, after):
    spec = ROOT / "verify" / "data" / "campaigns" / "small.toml"
    out = tmp_path / "store"
    _check(["campaign", str(spec), "--out", str(out), "--workers", "2", "--quiet"],
           tmp_path, signal.SIGTERM, out, after=after)


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("coqc") is None, reason="coqc is not installed")
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_coq_check_stops_coqc(tmp_path, sig):
    """Once a coqc runs (two processes of the call), the signal ends it too."""
    out = tmp_path / "coq"
    _check(["coq", str(ROOT / "certificates"), "--out", str(out), "--check", "--jobs", "2"],
           tmp_path, sig, out, processes=2)
