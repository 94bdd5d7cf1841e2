"""The processes of one call: every one dies with its parent, and a stop ends them all.

A command may start processes of its own: the claim runner's pool (a multiprocessing
forkserver, its workers and the resource tracker), Dask's worker processes, the forked
child of a bounded unit of work (:mod:`verify.proof.budget`), ``coqc``. A CI runner or a
user's ``kill`` signals the command's process only, not its group, so two guarantees are
kept here, on Linux (elsewhere they reduce to what the callers do themselves):

* **A child dies with its parent.** :func:`die_with_parent` asks the kernel
  (``prctl(PR_SET_PDEATHSIG)``) to kill the calling process when its parent ends; it is
  the ``initializer`` of every process pool, the ``preexec_fn`` of every external tool
  and the first step of every forked child, so no process of a call can outlive the
  process that started it, even one killed with SIGKILL. (Dask's worker processes and
  the multiprocessing forkserver and resource tracker already end when a pipe from
  their parent closes.)
* **A stop ends the whole tree before it is reported.** The top process makes itself
  the "subreaper" of its descendants (``prctl(PR_SET_CHILD_SUBREAPER)``), so an orphan
  (a pool worker whose forkserver ended first) is re-parented to it rather than to init,
  and :func:`end_tree` finds every descendant in ``/proc``, sends it SIGTERM, SIGKILL
  after a grace period, and waits until none is left. The command line calls it before
  it prints its stop message, so that message ("nothing was written after it") is true.
"""

from __future__ import annotations

import contextlib
import ctypes
import os
import signal
import sys
import time

#: prctl options (linux/prctl.h).
PR_SET_PDEATHSIG = 1
PR_SET_CHILD_SUBREAPER = 36


def _prctl(option: int, value: int) -> bool:
    """``prctl(option, value)``; False where there is no such call (not Linux) or it fails."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        return libc.prctl(option, ctypes.c_ulong(value), ctypes.c_ulong(0),
                          ctypes.c_ulong(0), ctypes.c_ulong(0)) == 0
    except (OSError, AttributeError):
        return False


def die_with_parent(sig: int = signal.SIGKILL) -> None:
    """Have the kernel send ``sig`` to this process when its parent ends.

    Called first thing in a child (a pool's ``initializer``, a ``preexec_fn``, the body
    of a fork). A parent that ended before the call left the child with another parent
    already (init, or the top process as subreaper, both alive): when the parent is init,
    the child ends at once. The kernel keeps the setting across ``exec``."""
    if _prctl(PR_SET_PDEATHSIG, int(sig)) and os.getppid() == 1:
        os.kill(os.getpid(), sig)


def adopt_orphans() -> bool:
    """Make this process the subreaper of its descendants: one whose parent ends is
    re-parented to it (so :func:`end_tree` still finds it), not to init."""
    return _prctl(PR_SET_CHILD_SUBREAPER, 1)


def _stat(pid: int) -> tuple[str, int, int] | None:
    """(state, parent, start time) of a process from ``/proc/PID/stat``; None if gone."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii", errors="replace") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return fields[0], int(fields[1]), int(fields[19])
    except (OSError, IndexError, ValueError):
        return None


def _parents() -> dict[int, int]:
    """Parent of every live (non-zombie) process, from ``/proc/PID/stat``."""
    found: dict[int, int] = {}
    try:
        entries = os.listdir("/proc")
    except OSError:
        return found
    for entry in entries:
        if entry.isdigit():
            stat = _stat(int(entry))
            if stat is not None and stat[0] not in ("Z", "X"):
                found[int(entry)] = stat[1]
    return found


def descendants(pid: int | None = None) -> list[int]:
    """The live descendants of ``pid`` (default: this process), parents before children."""
    root = os.getpid() if pid is None else pid
    parents = _parents()
    children: dict[int, list[int]] = {}
    for child, parent in parents.items():
        children.setdefault(parent, []).append(child)
    out: list[int] = []
    todo = list(children.get(root, []))
    while todo:
        p = todo.pop(0)
        out.append(p)
        todo.extend(children.get(p, []))
    return out


def _reap(pids: set[int]) -> None:
    """Collect the exit status of those of ``pids`` that are ended children of this
    process (re-parented orphans included), so that none stays a zombie. Only these:
    a ``waitpid(-1)`` would take the status another part of the program waits for."""
    for p in list(pids):
        with contextlib.suppress(ChildProcessError, OSError):
            os.waitpid(p, os.WNOHANG)


def _signal_all(pids: list[int], sig: int) -> None:
    for p in pids:
        with contextlib.suppress(OSError):
            os.kill(p, sig)


def end_tree(grace: float = 3.0, *, keep: tuple[int, ...] = ()) -> list[int]:
    """End every descendant of this process except those in ``keep`` (and theirs):
    SIGTERM, then SIGKILL to any still alive after ``grace`` seconds; wait until none is
    left. A process once found is followed even when its parent's end re-parents it out
    of the tree (to init, when this process is not their subreaper). Returns the
    processes that were found."""
    followed: dict[int, int] = {}  # pid -> start time (a reused pid is another process)

    def alive() -> list[int]:
        kept = set(keep)
        for k in keep:
            kept.update(descendants(k))
        for p in descendants():
            if p not in kept and p not in followed:
                stat = _stat(p)
                if stat is not None:
                    followed[p] = stat[2]
        out = []
        for p, started in followed.items():
            stat = _stat(p)
            if stat is not None and stat[0] not in ("Z", "X") and stat[2] == started:
                out.append(p)
        return out

    left = alive()
    if not left:
        return []
    signalled = set(left)
    _signal_all(left, signal.SIGTERM)
    deadline = time.monotonic() + grace
    while True:
        _reap(set(followed))
        left = alive()
        if not left:
            return sorted(followed)
        if time.monotonic() > deadline:
            _signal_all(left, signal.SIGKILL)
            if time.monotonic() > deadline + 5.0:  # unkillable (in the kernel): give up
                return sorted(followed)
        else:
            _signal_all([p for p in left if p not in signalled], signal.SIGTERM)
            signalled.update(left)
        time.sleep(0.02)


def stop_helper(owner, pid_name: str, fd_name: str, grace: float) -> None:
    """Stop a multiprocessing helper (forkserver, resource tracker) as its own ``_stop``
    does, by closing the descriptor whose end it waits for, but without waiting for it
    forever: after ``grace`` seconds it is killed."""
    pid, fd = getattr(owner, pid_name, None), getattr(owner, fd_name, None)
    if pid is None:
        return
    if fd is not None:
        with contextlib.suppress(OSError):
            os.close(fd)
        setattr(owner, fd_name, None)
    deadline = time.monotonic() + grace
    with contextlib.suppress(ChildProcessError, OSError):
        while os.waitpid(pid, os.WNOHANG) == (0, 0):
            if time.monotonic() > deadline:
                os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
                break
            time.sleep(0.02)
    setattr(owner, pid_name, None)


def stop_resource_tracker(grace: float = 2.0) -> None:
    """End multiprocessing's resource tracker of this process, after the finalizers that
    release the resources it tracks have run (so it has nothing to report)."""
    if "multiprocessing" not in sys.modules:
        return
    from multiprocessing import resource_tracker, util

    tracker = resource_tracker._resource_tracker
    pid = getattr(tracker, "_pid", None)
    if pid is None:
        return
    with contextlib.suppress(Exception):
        util._run_finalizers(0)
    stop_helper(tracker, "_pid", "_fd", grace)


def tracker_pid() -> int | None:
    """The pid of this process's multiprocessing resource tracker, if it runs."""
    tracker = sys.modules.get("multiprocessing.resource_tracker")
    return getattr(getattr(tracker, "_resource_tracker", None), "_pid", None)


class CallProcesses:
    """The processes one call of the command line starts: :meth:`end` ends those that
    did not exist when the call began (a library caller's own processes, such as a test's
    Dask cluster, are left alone), the resource tracker last, since the others use it
    until they end."""

    def __init__(self) -> None:
        self.before = tuple(descendants())
        self.tracker_before = tracker_pid()

    def end(self, grace: float = 3.0) -> list[int]:
        tracker = tracker_pid()
        fresh_tracker = tracker is not None and tracker != self.tracker_before
        keep = self.before + ((tracker,) if tracker is not None else ())
        found = end_tree(grace, keep=keep)
        if fresh_tracker:
            stop_resource_tracker()
            found += end_tree(grace, keep=self.before)
        return found


__all__ = ["CallProcesses", "adopt_orphans", "descendants", "die_with_parent", "end_tree",
           "stop_resource_tracker", "tracker_pid"]
