"""Stopping a command on SIGINT or SIGTERM: how every command ends when it is told to.

A CI runner or batch system stops a job with SIGTERM, a person with Ctrl-C (SIGINT).
Inside :class:`StopSignals` (the command line wraps every command in it) both raise
``KeyboardInterrupt`` in the main thread, so one ``except``/``finally`` path stops worker
processes and writes nothing more; the exit code is then 128 + the signal (130, 143).
Every file is written through a temporary file and a rename
(:mod:`verify.artefacts.atomic`), so what was written before the signal is whole.

A step that must not be cut in two (starting a Dask cluster, whose half-built state
cannot be closed) runs inside :func:`deferred_stop`: a signal there is held and raised
as soon as the step is done. An import in progress is such a step too, without being
marked: a ``KeyboardInterrupt`` raised inside one leaves a half-initialised module, and
libraries guard optional imports with a bare ``except:`` (mpmath's import of gmpy2)
that would swallow the stop and let the command run on. A signal that finds the main
thread importing is delivered again 20 ms later, until the import is done.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

#: The signals that stop a command.
STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)

_deferring = 0
_pending: list[int] = []
_retry_scheduled = False
#: How long a signal that found an import in progress waits before it is tried again.
RETRY_SECONDS = 0.02


def _importing(frame: Any) -> bool:
    """True when ``frame`` (the main thread's, as a signal handler gets it) runs inside an
    import: a frame of :mod:`importlib`'s bootstrap is on its stack."""
    while frame is not None:
        if frame.f_code.co_filename.startswith("<frozen importlib._bootstrap"):
            return True
        frame = frame.f_back
    return False


def _retry(signum: int) -> None:
    """Send ``signum`` again, to the main thread itself (so that a blocking call there,
    a sleep or a wait, is interrupted as by the first)."""
    global _retry_scheduled
    _retry_scheduled = False
    with contextlib.suppress(Exception):  # (the process may be ending: nothing to do)
        signal.pthread_kill(threading.main_thread().ident, signum)


class StopSignals:
    """While inside, SIGINT and SIGTERM raise ``KeyboardInterrupt`` (once; a second
    signal does not cut the cleanup of the first); :meth:`exit_code` is 128 + the
    signal."""

    def __init__(self) -> None:
        self.signum = int(signal.SIGINT)
        self.fired = False
        self._previous: dict[int, Any] = {}

    def _handler(self, signum: int, frame: Any) -> None:
        global _retry_scheduled
        if self.fired:
            return
        if _deferring:
            if not _pending:
                _pending.append(signum)
            return
        if _importing(frame):  # not inside an import: try again once it is done
            if not _retry_scheduled:
                _retry_scheduled = True
                timer = threading.Timer(RETRY_SECONDS, _retry, (signum,))
                timer.daemon = True
                timer.start()
            return
        self.fired, self.signum = True, signum
        raise KeyboardInterrupt

    def __enter__(self) -> StopSignals:
        global _active
        if threading.current_thread() is threading.main_thread():
            self._previous = {s: signal.signal(s, self._handler) for s in STOP_SIGNALS}
            _active = self
        return self

    def __exit__(self, *exc: object) -> None:
        global _active
        for s, previous in self._previous.items():
            signal.signal(s, previous)
        if _active is self:
            _active = None

    def name(self) -> str:
        return signal.Signals(self.signum).name

    def exit_code(self) -> int:
        return 128 + int(self.signum)


_active: StopSignals | None = None


@contextmanager
def deferred_stop() -> Iterator[None]:
    """Hold a stop signal until the block is done, then raise it (``KeyboardInterrupt``).

    Without an active :class:`StopSignals` (a library caller), this does nothing."""
    global _deferring
    _deferring += 1
    try:
        yield
    finally:
        _deferring -= 1
        if _deferring == 0 and _pending:
            signum = _pending.pop()
            if _active is not None and not _active.fired:
                _active.fired, _active.signum = True, signum
                raise KeyboardInterrupt  # the signal outranks an error of the block




def forget_caught_interrupt() -> None:
    """Clear CPython's record of an unhandled ``KeyboardInterrupt`` once the command has
    handled it.

    CPython 3.11 sets ``_Py_UnhandledKeyboardInterrupt`` when the interrupt passes
    through C code that runs Python code (an extension module being imported, for
    instance) even when Python code then catches it, and at exit the interpreter then
    kills itself with SIGINT: the caller would see "killed by SIGINT" instead of the exit
    code 128 + the signal the stop message promised. Nothing is done on interpreters
    without that variable."""
    import ctypes

    with contextlib.suppress(AttributeError, ValueError, OSError):
        ctypes.c_int.in_dll(ctypes.pythonapi, "_Py_UnhandledKeyboardInterrupt").value = 0


def child_processes(pid: int | None) -> list[int]:
    """The processes whose parent is ``pid``: the kernel's children list of each of its
    threads (``/proc/PID/task/TID/children``), or, on a kernel without those lists, a
    scan of ``/proc/*/stat`` for live processes with that parent; empty without /proc."""
    if pid is None:
        return []
    try:
        tasks = os.listdir(f"/proc/{pid}/task")
    except OSError:
        return []
    found: list[int] = []
    for tid in tasks:
        try:
            with open(f"/proc/{pid}/task/{tid}/children", encoding="ascii") as f:
                found.extend(int(p) for p in f.read().split())
        except FileNotFoundError:
            return _children_by_scan(pid)  # the kernel keeps no children lists
        except (OSError, ValueError):
            continue  # the thread ended meanwhile
    return found


def _children_by_scan(pid: int) -> list[int]:
    found = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            with contextlib.suppress(OSError, IndexError, ValueError):
                with open(f"/proc/{entry}/stat") as f:
                    fields = f.read().rsplit(")", 1)[1].split()
                if int(fields[1]) == pid and fields[0] != "Z":
                    found.append(int(entry))
    return found


__all__ = ["STOP_SIGNALS", "StopSignals", "child_processes", "deferred_stop",
           "forget_caught_interrupt"]
