"""``verify campaign SPEC.toml``: validate, expand, run on Dask, store, report.

Everything the spec names is checked before the first run starts (bad input: one line,
exit 2). One campaign at a time writes a store (:mod:`verify.campaign.lock`): a second
waits for the first, or with ``--no-wait`` exits 2 naming the holder. The output folder
holds ``results/`` (the Parquet store), ``humans/`` (model files of drawn family
members), ``campaign.md``, ``campaign.html``, ``figures/`` and ``commands.txt``. Exit 0
when every run has a row and none raised; 1 when a run raised or was lost (its row is
missing: ``--resume`` runs it again); 2 on bad input.
"""

from __future__ import annotations

import os
import sys
from dataclasses import dataclass
from pathlib import Path

from verify.errors import VerifyInputError


@dataclass
class CampaignSettings:
    spec: Path
    out: Path | None = None
    scheduler: str | None = None
    workers: int | None = None
    resume: bool = False
    quiet: bool = False
    progress: bool = False  # progress on stderr even when it is not a terminal
    wait: bool = True  # for another campaign writing the same store (else exit 2)


def default_workers() -> int:
    """Worker processes of the embedded LocalCluster: the cores, at most 8."""
    return max(1, min(os.cpu_count() or 1, 8))


#: where a campaign writes when no --out is given (git-ignored build output)
DEFAULT_OUT = Path("build") / "campaigns"
#: what the command writes inside --out: these names must be folders or files as listed
_FOLDERS = ("results", "humans", "figures")
_FILES = ("campaign.md", "campaign.html", "commands.txt")


def check_out(out: Path) -> None:
    """Refuse, before any run, an --out the command could not write into: an existing
    non-folder, or one of its outputs in the way as the wrong kind of file."""
    if out.exists() and not out.is_dir():
        raise VerifyInputError(f"--out {out}: exists and is not a folder; name a folder "
                               "(it is created if missing)")
    for parent in out.parents:
        if parent.exists():
            if not parent.is_dir():
                raise VerifyInputError(f"--out {out}: {parent} is not a folder")
            break
    for name in _FOLDERS:
        if (out / name).exists() and not (out / name).is_dir():
            raise VerifyInputError(f"--out {out}: {out / name} is in the way (a file where "
                                   "the campaign writes a folder); move it or choose another "
                                   "--out")
    for name in _FILES:
        if (out / name).exists() and not (out / name).is_file():
            raise VerifyInputError(f"--out {out}: {out / name} is in the way (not a regular "
                                   "file); move it or choose another --out")


def _check_address(address: str) -> str:
    text = address.strip()
    scheme, sep, rest = text.partition("://")
    host, colon, port = (rest if sep else text).rpartition(":")
    if (sep and scheme not in ("tcp", "tls", "ucx", "inproc", "ws", "wss")) or not colon \
            or not host or not port.isdigit():
        raise VerifyInputError(f"--scheduler {address!r}: expected an address such as "
                               "tcp://127.0.0.1:8786 (from 'dask scheduler')")
    return text


def run_campaign_command(s: CampaignSettings) -> int:
    from verify.artefacts.atomic import remove_empty
    from verify.artefacts.outputs import OutputPlan
    from verify.campaign.models import load_spec

    scheduler = _check_address(s.scheduler) if s.scheduler is not None else None
    workers = default_workers() if s.workers is None else s.workers
    if scheduler is None and workers < 1:
        raise VerifyInputError(f"--workers must be at least 1, got {workers}")
    if scheduler is not None and s.workers is not None:
        raise VerifyInputError("--workers sizes the embedded LocalCluster; with --scheduler "
                               "the cluster's own workers run the campaign (drop --workers)")
    spec = load_spec(s.spec)
    out = s.out if s.out is not None else DEFAULT_OUT / s.spec.stem
    check_out(out)
    outputs = OutputPlan(inputs=[s.spec])  # the spec is never among the outputs
    outputs.folder("--out", out)
    for name in _FILES:
        outputs.file("--out", out / name)
    fresh = [p for p in (out, *(out / name for name in _FOLDERS))
             if not os.path.lexists(p)]
    try:
        from verify.campaign.lock import StoreLock

        # one writer per store: the lock is held from before the stored keys are read
        # until the last row is appended and the report written
        with StoreLock(out / "results", wait=s.wait) as lock:
            if lock.taken_over:
                print(f"verify campaign: took over the store's lock from {lock.taken_over}, "
                      "which ended without releasing it", file=sys.stderr, flush=True)
            return _run(s, spec, out, scheduler, workers)
    except BaseException:  # no empty folder left by a run that failed or was stopped
        remove_empty(fresh)
        raise


def _run(s: CampaignSettings, spec, out: Path, scheduler: str | None, workers: int) -> int:
    from verify.campaign.engine import run_campaign
    from verify.campaign.execute import FAILED, UNRESOLVED, column
    from verify.campaign.progress import clock
    from verify.campaign.report import Campaign, write_report
    from verify.campaign.runs import (
        distinct_humans,
        iter_runs,
        place_family_files,
        run_total,
        spec_fingerprint,
    )
    from verify.campaign.store import ResultStore

    store = ResultStore(out / "results")
    stored = store.keys()
    if stored and not s.resume:
        mine = sum(1 for r in iter_runs(spec) if r.key in stored)
        raise VerifyInputError(
            f"{store.folder} already holds {len(stored)} rows ({mine} of this campaign); "
            "pass --resume to continue without repeating them, or choose another --out")
    store.bind(spec_fingerprint(spec), spec.name)
    humans = place_family_files(distinct_humans(spec), out / "humans")
    total = run_total(spec, humans)
    engine = (f"the Dask scheduler at {scheduler}" if scheduler
              else f"a LocalCluster of {workers} worker process(es), 1 thread each")
    print(f"verify campaign: {spec.name}: {total} runs; properties "
          f"{', '.join(spec.properties) or 'none'}; on {engine}", flush=True)
    if stored:
        print(f"  resuming: {len(stored)} rows already in {store.folder}", flush=True)
    try:
        # SIGTERM arrives here as KeyboardInterrupt too (the command line's handler)
        outcome = run_campaign(iter_runs(spec, humans), store, scheduler=scheduler,
                               workers=workers, progress=not s.quiet,
                               force_progress=s.progress, stream=sys.stderr,
                               total=total)
    except KeyboardInterrupt:
        print(f"verify campaign: interrupted; {len(store.keys())} rows stored in "
              f"{store.folder}; rerun with --resume to continue", file=sys.stderr)
        raise
    runs = list(iter_runs(spec, humans))
    rows = {row["key"]: row for row in store.rows([r.key for r in runs])}
    ran = outcome.written
    session = {
        "engine": engine,
        "workers": str(outcome.workers or "-"),
        "runs this session": str(ran),
        "wall time of this session": f"{outcome.seconds:.1f} s",
        "runs per second": f"{ran / outcome.seconds:.3g}" if outcome.seconds and ran else "-",
    }
    paths = write_report(Campaign(spec, runs, rows), out, session)
    failed = sum(1 for row in rows.values() if any(
        row.get(column(p)) == FAILED for p in spec.properties))
    unresolved = sum(1 for row in rows.values() if any(
        row.get(column(p)) == UNRESOLVED for p in spec.properties))
    print(f"  {len(rows)} of {len(runs)} runs stored ({ran} this session in "
          f"{clock(outcome.seconds)}); {failed} failed a property; {unresolved} not resolved "
          f"by the integration; {outcome.raised} raised"
          + (f"; {len(outcome.lost)} lost" if outcome.lost else ""))
    for key, why in outcome.lost[:5]:
        print(f"  lost {key}: {why}", file=sys.stderr)
    print(f"  store: {store.folder}; report: {paths[-2]}, {paths[-1]}")
    errors = sum(1 for row in rows.values() if row.get("error"))
    return 0 if len(rows) == len(runs) and not errors else 1


__all__ = ["DEFAULT_OUT", "CampaignSettings", "check_out", "default_workers",
           "run_campaign_command"]
