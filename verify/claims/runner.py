"""The claim runner: run registered checks and collect their results in order.

The runner never lets a crashing check pass: an exception becomes an INCONCLUSIVE
outcome that names the error, except an output that cannot be written (a full disk),
which ends the run as it ends every command (one line, exit 2). Worker processes find
the claims by id in the full registry of :mod:`verify.claims.catalog`.
"""

from __future__ import annotations

import contextlib
import os
import signal
import time
import traceback
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from verify.artefacts.atomic import OutputError
from verify.claims.model import (
    CheckContext,
    Claim,
    ClaimResult,
    Evidence,
    EvidenceKind,
    Outcome,
    Verdict,
)
from verify.claims.registry import REGISTRY
from verify.process_tree import die_with_parent, stop_helper
from verify.stopping import child_processes


@dataclass(frozen=True)
class RunResult:
    """All claim results of one run, in registry order."""

    results: tuple[ClaimResult, ...]
    seconds: float
    seed: int

    def counts(self) -> dict[str, int]:
        out = {v.value: 0 for v in Verdict}
        for r in self.results:
            out[r.outcome.verdict.value] += 1
        return out

    def all_verified(self) -> bool:
        return all(r.outcome.verdict is Verdict.VERIFIED for r in self.results)


def run_claim(claim: Claim, context: CheckContext) -> ClaimResult:
    """Run one check; a crash yields INCONCLUSIVE with the error as evidence."""
    start = time.perf_counter()
    try:
        outcome = claim.check(context)
        if not isinstance(outcome, Outcome):
            raise TypeError(f"check returned {type(outcome).__name__}, not Outcome")
    except OutputError:  # a full disk is not a verdict on the claim: the run stops (exit 2)
        raise
    except Exception as exc:  # a broken check must never count as a pass
        outcome = Outcome(
            verdict=Verdict.INCONCLUSIVE,
            finding=f"The check itself failed ({type(exc).__name__}: {exc}); no verdict.",
            evidence=(
                Evidence(
                    EvidenceKind.NUMERICAL,
                    "traceback of the failed check",
                    {"traceback": traceback.format_exc(limit=5)},
                    passed=False,
                ),
            ),
        )
    return ClaimResult(claim, outcome, time.perf_counter() - start)


def _run_by_id(claim_id: str, context: CheckContext) -> tuple[Outcome, float]:
    """Run one registered claim in a worker process (claims travel by id)."""
    from verify.claims.catalog import REGISTRY as FULL  # registers the claims here

    result = run_claim(FULL.get(claim_id), context)
    return result.outcome, result.seconds


def run_claims(
    claims: Iterable[Claim],
    context: CheckContext,
    progress: Callable[[ClaimResult], None] | None = None,
    *,
    jobs: int = 1,
) -> RunResult:
    """Run the given claims and collect their results in the given order.

    With ``jobs`` > 1 the checks run in that many worker processes. Each check depends
    only on the context (its seed, its output folders), never on another check, so the
    results, and the report rendered from them, are the same as a run with one job;
    ``progress`` still sees them in order.
    The workers are fresh interpreters (the ``forkserver`` start method), so a script
    that calls this with ``jobs`` > 1 needs the usual ``if __name__ == "__main__":``
    guard.
    """
    claims = list(claims)
    start = time.perf_counter()
    results: list[ClaimResult] = []
    registered = all(c.id in REGISTRY.ids() and REGISTRY.get(c.id) is c for c in claims)
    if jobs <= 1 or len(claims) <= 1 or not registered:  # workers find claims by id
        for claim in claims:
            result = run_claim(claim, context)
            results.append(result)
            if progress is not None:
                progress(result)
        return RunResult(tuple(results), time.perf_counter() - start, context.seed)
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    # workers start from a fresh interpreter (forkserver), not a fork of this process: a
    # fork keeps locks of native thread pools (clarabel's rayon pool once a solver ran
    # here) whose threads it does not copy, and the worker's first solve then waits forever
    start_method = multiprocessing.get_context("forkserver")
    # each worker dies with its parent (the forkserver, which ends with this process)
    pool = ProcessPoolExecutor(max_workers=min(jobs, len(claims)), mp_context=start_method,
                               initializer=die_with_parent)
    try:
        futures = [pool.submit(_run_by_id, c.id, context) for c in claims]
        for claim, future in zip(claims, futures, strict=True):
            outcome, seconds = future.result()
            result = ClaimResult(claim, outcome, seconds)
            results.append(result)
            if progress is not None:
                progress(result)
    except BaseException:  # a signal (KeyboardInterrupt), or an output that failed
        stop_pool(pool)
        raise
    pool.shutdown(wait=True)
    return RunResult(tuple(results), time.perf_counter() - start, context.seed)


def stop_pool(pool, grace: float = 2.0) -> None:
    """End a process pool now: queued checks are cancelled, the workers (and so any file
    they were about to write) are terminated, and the forkserver that started them is
    stopped (the resource tracker ends by itself when this process does), so no process
    of the call outlives it (a survivor would keep the caller's stdout open and hang a CI
    step that waits for it)."""
    import multiprocessing.forkserver as forkserver

    workers = list((getattr(pool, "_processes", None) or {}).values())
    for w in workers:  # first, so that no worker takes the next queued check
        with contextlib.suppress(Exception):
            w.terminate()
    pool.shutdown(wait=False, cancel_futures=True)
    deadline = time.monotonic() + grace
    for w in workers:
        with contextlib.suppress(Exception):
            w.join(max(0.0, deadline - time.monotonic()))
            if w.is_alive():
                w.kill()
                w.join(1.0)
    for child in child_processes(getattr(forkserver._forkserver, "_forkserver_pid", None)):
        with contextlib.suppress(OSError):  # a worker still being started
            os.kill(child, signal.SIGKILL)
    stop_helper(forkserver._forkserver, "_forkserver_pid", "_forkserver_alive_fd", grace)
    # The resource tracker is left to end by itself: this process is now the only holder
    # of its pipe, so it ends as this process exits, after the pool's semaphores are
    # released here (stopped earlier, it would release them first, and each release at
    # exit would print a traceback).


