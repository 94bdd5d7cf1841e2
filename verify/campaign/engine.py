"""Run a campaign on Dask ``distributed``: one task per run, rows stored as they finish.

Default engine: a :class:`distributed.LocalCluster` on this machine (worker processes
with one thread each, since a run is single-threaded NumPy). With an address the same
tasks go to an existing scheduler (``dask scheduler`` and ``dask worker`` processes on
any machines that can import ``verify``); a run carries its model file's bytes, so
workers need no shared file system.

Each run is a task whose key is derived from the run key, so the scheduler sees one task
per run. Results are collected with ``as_completed`` and appended to the
:class:`~verify.campaign.store.ResultStore` in small batches (a part file at least every
``flush_seconds``), so an interruption loses only the rows of the current batch, and
runs already stored are skipped on the next invocation. When a worker dies the scheduler
runs its tasks again elsewhere (up to its ``allowed-failures``); the store drops a second
row of a key, so nothing is stored twice. A task that the scheduler gives up on (a
worker killed repeatedly while running it) gets no row: it is reported as lost and runs
again on ``--resume``.
"""

from __future__ import annotations

import contextlib
import itertools
import logging
import time
import uuid
import warnings
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from typing import Any, TextIO

from verify.campaign.execute import execute_run
from verify.campaign.progress import CampaignProgress
from verify.campaign.runs import Run
from verify.campaign.store import ResultStore
from verify.errors import VerifyInputError
from verify.stopping import deferred_stop

TASK_PREFIX = "verify-run-"
CONNECT_TIMEOUT = "15s"  # to reach an existing scheduler


@dataclass
class CampaignOutcome:
    """What a session of a campaign did."""

    total: int  # runs of the campaign
    stored_before: int  # of them, found in the store and skipped
    written: int = 0  # rows appended by this session
    raised: int = 0  # of them, runs whose simulation raised (the row holds the error)
    lost: list[tuple[str, str]] = field(default_factory=list)  # (key, why): no row
    seconds: float = 0.0
    workers: int = 0
    engine: str = ""

    @property
    def complete(self) -> bool:
        return self.stored_before + self.written == self.total


@contextlib.contextmanager
def _quiet_distributed() -> Iterator[None]:
    """Keep distributed's own log lines (worker restarts, closing) off the terminal."""
    logger = logging.getLogger("distributed")
    level = logger.level
    logger.setLevel(logging.CRITICAL)
    try:
        with warnings.catch_warnings():  # e.g. "Sending large graph": not the user's concern
            warnings.filterwarnings("ignore", module=r"distributed(\..*)?")
            warnings.filterwarnings("ignore", category=UserWarning, message=".*[Ll]arge graph")
            yield
    finally:
        logger.setLevel(level)


@contextlib.contextmanager
def connect(scheduler: str | None = None, workers: int = 2) -> Iterator[Any]:
    """A Dask client: on the scheduler at ``scheduler``, or on a new LocalCluster of
    ``workers`` processes (closed on exit)."""
    from distributed import Client, LocalCluster

    if scheduler is not None:
        try:
            client = Client(scheduler, timeout=CONNECT_TIMEOUT, set_as_default=False)
        except (OSError, TimeoutError, ValueError) as exc:
            raise VerifyInputError(f"--scheduler {scheduler}: cannot connect to a Dask "
                                   f"scheduler ({' '.join(str(exc).split())}); start one with "
                                   "'dask scheduler' and give its tcp://HOST:PORT") from None
        try:
            yield client
        finally:
            client.close()
        return
    if workers < 1:
        raise VerifyInputError(f"--workers must be at least 1, got {workers}")
    cluster = client = None
    try:
        with deferred_stop():  # a half-started cluster cannot be closed: start it whole
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                   dashboard_address=":0", silence_logs=logging.CRITICAL)
            client = Client(cluster, set_as_default=False)
        yield client
    finally:
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()


def _why(future: Any, result: Any) -> str:
    exc = result[1] if isinstance(result, tuple) and len(result) == 3 else result
    if not isinstance(exc, BaseException):
        with contextlib.suppress(Exception):
            exc = future.exception(timeout=1)
    return f"{type(exc).__name__}: {' '.join(str(exc).split())}"[:500]


def run_campaign(
    runs: Iterable[Run],
    store: ResultStore,
    *,
    client: Any = None,
    scheduler: str | None = None,
    workers: int = 2,
    progress: bool = True,
    force_progress: bool = False,
    stream: TextIO | None = None,
    function: Callable[[Run], dict[str, Any]] = execute_run,
    on_rows: Callable[[list[dict[str, Any]], Any], None] | None = None,
    batch_rows: int = 64,
    flush_seconds: float = 2.0,
    total: int | None = None,
    window: int | None = None,
) -> CampaignOutcome:
    """Run every run whose key is not in ``store`` and append its row as it finishes.

    Parameters
    ----------
    runs : iterable of Run
        The campaign (keys distinct: :func:`verify.campaign.runs.iter_runs`); consumed
        lazily, so a generator of a million runs costs no more client memory than ten.
    store : ResultStore
        Where rows go; its keys are skipped (resuming is the default behaviour).
    client : distributed.Client, optional
        Use this client (not closed here); else ``scheduler`` or a new LocalCluster.
    scheduler : str, optional
        Address of an existing scheduler, ``tcp://HOST:PORT``.
    workers : int
        Worker processes of the LocalCluster (one thread each).
    progress : bool
        Show the one-line progress on ``stream`` (stderr) when it is a terminal, or with
        ``force_progress`` anywhere (:mod:`verify.campaign.progress`).
    function : callable
        The task (default :func:`verify.campaign.execute.execute_run`).
    on_rows : callable, optional
        Called with each batch of rows after it is stored, and the client.
    total : int, optional
        How many runs ``runs`` holds (default ``len(runs)``), for progress and outcome.
    window : int, optional
        Runs submitted and not yet finished, at most (default 4 per worker, at least 8):
        the scheduler holds this many tasks, not the whole sweep.

    Returns
    -------
    CampaignOutcome
    """
    start = time.perf_counter()
    if total is None:
        runs = list(runs)
        total = len(runs)
    stored = store.keys()
    skipped = [0]

    def unstored(runs: Iterable[Run]) -> Iterator[Run]:
        for r in runs:
            if r.key in stored:
                skipped[0] += 1
            else:
                yield r

    fresh = unstored(runs)
    first_run = next(fresh, None)
    outcome = CampaignOutcome(total=total, stored_before=0)
    if first_run is None:
        outcome.stored_before = total
        return outcome
    pending = itertools.chain([first_run], fresh)
    owned = connect(scheduler, workers) if client is None else contextlib.nullcontext(client)
    buffer: list[dict[str, Any]] = []
    first = 0.0
    counted = {"submitted": 0}
    bar: CampaignProgress | None = None

    def flush(client: Any) -> None:
        nonlocal buffer
        if not buffer:
            return
        rows, buffer = buffer, []
        outcome.written += store.append(rows)
        if on_rows is not None:
            on_rows(rows, client)

    with _quiet_distributed(), owned as dask:
        from distributed import as_completed

        outcome.engine = str(getattr(dask.scheduler, "address", "") or "")
        outcome.workers = len(dask.scheduler_info().get("workers", {}))
        limit = window or max(8, 4 * max(1, outcome.workers or workers))
        # Task keys name the run and this session: a session interrupted on a long-lived
        # cluster may leave its cancelled tasks there for a while, and a resumed session
        # must not be handed their cancellation.
        session = uuid.uuid4().hex[:8]
        run_of: dict[str, str] = {}
        live: dict[str, Any] = {}  # a consumed future is dropped (its result freed)
        done = as_completed([], loop=dask.loop, with_results=True, raise_errors=False)

        def submit(count: int) -> None:
            for run in itertools.islice(pending, count):
                task = f"{TASK_PREFIX}{run.key}-{session}"
                run_of[task] = run.key
                future = dask.submit(function, run, key=task, pure=False)
                live[task] = future
                done.add(future)
                counted["submitted"] += 1

        try:
            submit(limit)
            bar = CampaignProgress(total, skipped[0], stream=stream, enabled=progress,
                                   forced=force_progress)
            bar.update(force=True)
            while live:
                batch = done.next_batch(block=False)
                for future, result in batch:
                    live.pop(future.key, None)
                    key = run_of.pop(future.key, "")
                    if future.status != "finished" or not isinstance(result, dict):
                        outcome.lost.append((key, _why(future, result)))
                        continue
                    if not buffer:
                        first = time.perf_counter()
                    buffer.append(result)
                    outcome.raised += result.get("error") is not None
                    bar.already = skipped[0]
                    bar.update(1, result.get("error") is not None)
                if batch:
                    submit(limit - len(live))
                if buffer and (len(buffer) >= batch_rows
                               or time.perf_counter() - first >= flush_seconds):
                    flush(dask)
                bar.update()
                if not batch:
                    time.sleep(0.05)
            flush(dask)
        finally:
            outcome.stored_before = skipped[0]
            try:
                flush(dask)  # rows in hand are results: keep them even when interrupted
            finally:
                with contextlib.suppress(Exception):
                    dask.cancel(list(live.values()), force=True)
                if bar is not None:
                    bar.close()
                outcome.seconds = time.perf_counter() - start
    return outcome


__all__ = ["CampaignOutcome", "connect", "run_campaign"]
