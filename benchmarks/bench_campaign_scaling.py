"""Campaign scaling: the same 48-run campaign on a LocalCluster of 1 and of 2 workers.

Run: ``python benchmarks/bench_campaign_scaling.py [--seconds 30] [--workers 1 2]
[--spec verify/data/campaigns/small.toml] [--sample N]``. ``--seconds`` shortens every
run (the default is the spec's 30 s); ``--sample N`` times N runs spread evenly over a
large campaign (``--spec verify/data/campaigns/paper.toml --sample 16``); each session
gets a fresh store in a temporary folder.

Prints, per worker count: the wall time of the session with and without starting (and
warming up) the cluster, runs per second, and the speed-up over one worker. The runs are
single-threaded NumPy, so on a machine with c idle cores the speed-up should approach
min(c, workers); cores shared with other processes show up as a smaller speed-up.
"""

from __future__ import annotations

import argparse
import dataclasses
import tempfile
import time
from pathlib import Path

from verify.campaign.engine import connect, run_campaign
from verify.campaign.execute import execute_run
from verify.campaign.runs import expand
from verify.campaign.store import ResultStore
from verify.inputs.campaign_spec import load_campaign_spec

SMALL = Path(__file__).resolve().parents[1] / "verify" / "data" / "campaigns" / "small.toml"


def session(runs, workers: int, warm_up: bool) -> tuple[float, float, int]:
    """(total wall, wall after the cluster is up, rows written) of one session.

    With ``warm_up`` every worker first runs a 0.1 s copy of the first run, so that
    imports, the gate and compiled kernels are ready before the clock starts.
    """
    with tempfile.TemporaryDirectory() as folder:
        start = time.perf_counter()
        with connect(None, workers) as client:
            client.wait_for_workers(workers)
            if warm_up:
                client.run(execute_run, dataclasses.replace(runs[0], seconds=0.1))
            up = time.perf_counter()
            outcome = run_campaign(runs, ResultStore(Path(folder) / "results"),
                                   client=client, progress=False)
            end = time.perf_counter()
    assert outcome.complete and not outcome.lost, outcome
    return end - start, end - up, outcome.written


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spec", type=Path, default=SMALL)
    parser.add_argument("--seconds", type=float, help="override the run length")
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--sample", type=int, metavar="N",
                        help="time N runs evenly spread over the campaign (for paper.toml)")
    parser.add_argument("--no-warm-up", action="store_true",
                        help="time the first run of each worker with its start-up costs")
    args = parser.parse_args()
    spec = load_campaign_spec(args.spec)
    if args.seconds is not None:
        spec = dataclasses.replace(spec, seconds=(args.seconds,))
    runs = expand(spec)
    if args.sample is not None and args.sample < len(runs):
        stride = len(runs) / args.sample
        runs = [runs[int(i * stride)] for i in range(args.sample)]
    print(f"campaign {spec.name}: {len(runs)} runs of {spec.seconds[0]:g} s, properties "
          f"{', '.join(spec.properties) or 'none'}")
    print(f"{'workers':>7} {'wall [s]':>9} {'runs [s]':>9} {'runs/s':>8} {'speed-up':>8}")
    base = None
    for w in args.workers:
        total, running, rows = session(runs, w, not args.no_warm_up)
        rate = rows / running
        base = rate if base is None else base
        print(f"{w:>7} {total:>9.1f} {running:>9.1f} {rate:>8.3f} {rate / base:>8.2f}",
              flush=True)


if __name__ == "__main__":
    main()
