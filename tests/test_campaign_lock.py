"""One writer per campaign store: a second campaign waits or (``--no-wait``) exits 2
naming the holder; a killed holder's lock is taken over; each key is stored once, counted
by reading the Parquet parts raw (as pandas, DuckDB or Spark would, no deduplication)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pyarrow.parquet as pq
import pytest

from verify.campaign.lock import LOCK_NAME, StoreLock
from verify.cli import main
from verify.errors import VerifyInputError

ROOT = Path(__file__).resolve().parents[1]

TINY = """name = "tiny"
[sweep]
k_s = [1.5, 2.0, 2.5]
n = 2
seeds = [0, 1]
seconds = 0.2
step = "1/60"
[[humans]]
kind = "vr"
[checks]
properties = ["lemma1"]
"""


def raw_keys(store: Path) -> list[str]:
    """Every row's key in every part file, duplicates kept."""
    keys: list[str] = []
    for part in sorted(store.glob("part-*.parquet")):
        keys += pq.read_table(part, columns=["key"]).column("key").to_pylist()
    return keys


def _holder(folder: Path) -> subprocess.Popen:
    """A process that takes the store's lock and keeps it (prints "held" once it has)."""
    code = ("import sys, time\nfrom pathlib import Path\n"
            "from verify.campaign.lock import StoreLock\n"
            f"lock = StoreLock(Path({str(folder)!r})).acquire()\n"
            "print('held', flush=True)\ntime.sleep(120)\n")
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True,
                            env=dict(os.environ, PYTHONPATH=str(ROOT)))
    assert proc.stdout.readline().strip() == "held"
    return proc


def test_a_second_lock_is_refused_naming_the_holder(tmp_path):
    with StoreLock(tmp_path / "results"):
        with pytest.raises(VerifyInputError) as refused:
            StoreLock(tmp_path / "results", wait=False).acquire()
    message = str(refused.value)
    assert f"PID {os.getpid()} on host " in message and " since 20" in message
    assert "\n" not in message
    assert not (tmp_path / "results" / LOCK_NAME).exists()  # a clean release removes it


def test_a_waiting_lock_gets_it_when_the_holder_ends(tmp_path, capsys):
    import threading

    holder = _holder(tmp_path)
    try:
        lock = StoreLock(tmp_path, poll_seconds=0.05)
        start = time.monotonic()
        threading.Timer(0.8, holder.terminate).start()  # SIGTERM: it ends, not releasing
        lock.acquire()
        assert time.monotonic() - start >= 0.7
        assert f"in use by PID {holder.pid} on host" in capsys.readouterr().err
        assert lock.taken_over.startswith(f"PID {holder.pid} on host ")
        lock.release()
    finally:
        holder.kill()
        holder.wait()


def test_a_killed_holders_lock_is_taken_over(tmp_path):
    holder = _holder(tmp_path)
    holder.send_signal(signal.SIGKILL)
    holder.wait()
    assert (tmp_path / LOCK_NAME).exists()  # its text stays; the kernel's lock went
    with StoreLock(tmp_path, wait=False) as lock:
        assert lock.taken_over.startswith(f"PID {holder.pid} on host ")
    with StoreLock(tmp_path, wait=False) as lock:  # released cleanly: nothing to take over
        assert lock.taken_over == ""


def test_campaign_no_wait_exits_2_naming_the_holder(tmp_path, capsys):
    spec = tmp_path / "tiny.toml"
    spec.write_text(TINY)
    holder = _holder(tmp_path / "out" / "results")
    try:
        code = main(["campaign", str(spec), "--out", str(tmp_path / "out"), "--no-wait",
                     "--quiet"])
    finally:
        holder.kill()
        holder.wait()
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1, err
    assert f"PID {holder.pid} on host" in err[0] and "--no-wait" in err[0]
    assert raw_keys(tmp_path / "out" / "results") == []


def _campaign(spec: Path, out: Path, *extra: str) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "verify.cli", "campaign", str(spec),
                             "--out", str(out), "--workers", "1", "--quiet", *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=dict(os.environ, PYTHONPATH=str(ROOT)))


def _two_at_once(spec: Path, out: Path, *extra: str) -> tuple[list, list[str]]:
    first = _campaign(spec, out, *extra)
    deadline = time.monotonic() + 120
    while not (out / "results" / LOCK_NAME).exists():  # the first holds the lock
        assert first.poll() is None and time.monotonic() < deadline, first.communicate()
        time.sleep(0.05)
    second = _campaign(spec, out, *extra)
    done = [(*p.communicate(timeout=600), p.returncode) for p in (first, second)]
    return done, raw_keys(out / "results")


def test_two_campaigns_on_one_store_store_each_key_once(tmp_path):
    spec = tmp_path / "tiny.toml"
    spec.write_text(TINY)
    (first, second), keys = _two_at_once(spec, tmp_path / "out", "--resume")
    assert first[2] == 0 and second[2] == 0, (first, second)
    assert "waiting for it" in second[1], second[1]
    assert len(keys) == 6 and len(set(keys)) == 6, keys
    assert "6 of 6 runs stored (0 this session" in second[0], second[0]


@pytest.mark.slow
def test_two_small_campaigns_at_once_leave_48_rows(tmp_path):
    """The shipped small campaign, started twice at once: 48 rows in the raw parts."""
    spec = ROOT / "verify" / "data" / "campaigns" / "small.toml"
    (first, second), keys = _two_at_once(spec, tmp_path / "out", "--resume")
    assert first[2] in (0, 1) and second[2] in (0, 1), (first, second)
    assert len(keys) == 48 and len(set(keys)) == 48
