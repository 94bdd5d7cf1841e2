"""Bounded work: a unit of the checker's own work (one step) in a forked process.

The checker decides a step with exact algebra whose cost the derivation chooses (degrees,
Groebner bases of its conditions, real roots); a step may ask for more than any machine
has. :func:`run_bounded` runs such a unit in a child forked from the checker (the
checker's own code and objects only, never a derivation file's code) with an address-space
limit (``resource.setrlimit``) and a wall-clock and CPU deadline; when the child runs out
of either, dies, or is killed, the caller gets :class:`BudgetExceededError` and reports the
step *inconclusive: budget exceeded*. The defaults (120 s, 4 GB) are those of
``verify check``; see ``verify/proof/TRUSTED.md``.

A fork copies one thread: a solver whose thread pool was started in the parent (Clarabel's
rayon pool, after an SOS search ran there) waits forever in the child, until the budget
ends it. ``verify check`` and ``verify certificates check`` never run a solver in the
parent; a library caller of ``check(..., budget=...)`` should not either.
"""

from __future__ import annotations

import faulthandler
import os
import pickle
import select
import signal
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from verify.process_tree import die_with_parent


@dataclass(frozen=True)
class Budget:
    """Time (``seconds``: wall clock and CPU) and memory (``memory``: bytes of address
    space beyond what the process had mapped when the work starts) of one unit of work."""

    seconds: float = 120.0
    memory: int = 4 * 2**30

    def __post_init__(self) -> None:
        if not (self.seconds > 0 and self.memory > 0):
            raise ValueError("a budget is positive")

    def describe(self) -> str:
        return f"{self.seconds:g} s, {self.memory / 2**30:g} GB"


DEFAULT_BUDGET = Budget()


class BudgetExceededError(Exception):
    """The unit of work ran out of time or memory, or its process died."""


def _mapped_bytes() -> int:
    try:
        with open("/proc/self/statm", encoding="ascii") as f:
            return int(f.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0


def run_bounded(work: Callable[[], Any], budget: Budget) -> Any:
    """``work()`` in a forked child under ``budget``; its result (pickled by our own
    code in the child, of our own classes) or BudgetExceededError."""
    import resource

    limit = _mapped_bytes() + budget.memory
    r, w = os.pipe()
    try:
        pid = os.fork()
    except OSError as exc:
        os.close(r)
        os.close(w)
        raise BudgetExceededError(f"no process for the work ({exc.strerror or exc})") from None
    if pid == 0:  # the child: compute, hand the result over, exit without cleanup
        status = 0
        try:
            die_with_parent()  # no work outlives the checker that asked for it
            os.close(r)
            faulthandler.disable()  # a crash here is reported by the parent, in one line
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, 1)
            os.dup2(null, 2)  # e.g. FLINT's message before it aborts
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
            cpu = max(1, int(budget.seconds + 0.999))
            resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 5))
            try:
                payload = pickle.dumps(("ok", work()))
            except MemoryError:
                payload = pickle.dumps(("memory", None))
            except BaseException as exc:
                payload = pickle.dumps(("error", f"{type(exc).__name__}: {exc}"[:500]))
            view = memoryview(payload)
            while view:
                view = view[os.write(w, view):]
        except BaseException:
            status = 1
        finally:
            os._exit(status)
    os.close(w)
    chunks: list[bytes] = []
    deadline = time.monotonic() + budget.seconds
    timed_out = False
    try:
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                timed_out = True
                break
            ready, _, _ = select.select([r], [], [], left)
            if not ready:
                continue
            chunk = os.read(r, 1 << 20)
            if not chunk:
                break
            chunks.append(chunk)
    except BaseException:  # a stop (KeyboardInterrupt): the work is not waited for
        timed_out = True
        raise
    finally:
        os.close(r)
        if timed_out:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        _, status = os.waitpid(pid, 0)
    if timed_out:
        raise BudgetExceededError(f"time budget of {budget.seconds:g} s exceeded")
    died = BudgetExceededError(f"memory or time budget ({budget.describe()}) exceeded, or "
                               "the work's process died")
    if os.WIFSIGNALED(status) or os.waitstatus_to_exitcode(status) != 0 or not chunks:
        raise died
    try:
        kind, value = pickle.loads(b"".join(chunks))
    except Exception:
        raise died from None
    if kind == "memory":
        raise BudgetExceededError(f"memory budget of {budget.memory / 2**30:g} GB exceeded")
    if kind == "error":
        raise RuntimeError(value)
    return value
