"""verify.stopping.child_processes: the kernel's children lists and the /proc scan agree."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from verify.stopping import _children_by_scan, child_processes

pytestmark = pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="no /proc")


def test_a_started_child_is_found_both_ways_and_gone_after_it_ends():
    child = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(30)"])
    try:
        assert child.pid in child_processes(os.getpid())
        assert child.pid in _children_by_scan(os.getpid())
    finally:
        child.kill()
        child.wait()
    assert child.pid not in child_processes(os.getpid())
    assert child.pid not in _children_by_scan(os.getpid())


def test_no_process_and_no_pid_have_no_children():
    assert child_processes(None) == []
    assert child_processes(2**22 + 12345) == []  # above pid_max: no such process
