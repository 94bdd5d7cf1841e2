"""Campaign scaling: the same runs on a LocalCluster of 1 and of 2 workers, and the
projected time of the paper-scale campaign.

Run: ``python benchmarks/bench_campaign_scaling.py [--spec verify/data/campaigns/paper.toml]
[--sample 16] [--seconds T] [--workers 1 2] [--shared-pair N]``. ``--sample N`` times N
runs spread evenly over a large campaign; ``--seconds`` shortens every run; each session
gets a fresh store in a temporary folder. The default is the paper-scale spec, 16 runs.

Prints, per worker count: the wall time of the session with and without starting (and
warming up) the cluster, runs per second, the speed-up over one worker, and runs per
worker-CPU-second (the CPU time the workers spent, read from each worker process). On a
machine shared with other jobs the wall rate understates what idle cores would give;
the rate per CPU-second does not, so the projection for the whole spec is printed both
ways: from the measured 2-worker wall rate, and from the CPU rate on 2 idle cores.

``--shared-pair N`` also times, in this process, N runs checked with one pair of runs
shared by every property (:func:`verify.sim.checks.check_scenario`) against the earlier
scheme where the stealthiness check simulated its own h / h/2 pair again, and checks
that both give the same verdicts and figures (a ratio, measured in the same process).
"""

from __future__ import annotations

from verify.cli import single_threaded_blas

single_threaded_blas()  # before numpy is imported (verify.cli does not import it)

import argparse  # noqa: E402
import dataclasses  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

from verify.campaign.engine import connect, run_campaign  # noqa: E402
from verify.campaign.execute import execute_run  # noqa: E402
from verify.campaign.runs import expand  # noqa: E402
from verify.campaign.store import ResultStore  # noqa: E402
from verify.inputs.campaign_spec import load_campaign_spec  # noqa: E402

PAPER = Path(__file__).resolve().parents[1] / "verify" / "data" / "campaigns" / "paper.toml"


def _cpu() -> float:
    return time.process_time()


def session(runs, workers: int, warm_up: bool) -> tuple[float, float, int, float]:
    """(total wall, wall after the cluster is up, rows written, worker CPU seconds).

    With ``warm_up`` every worker first runs a 0.1 s copy of the first run, so that
    imports, the gate and compiled kernels are ready before the clock starts.
    """
    with tempfile.TemporaryDirectory() as folder:
        start = time.perf_counter()
        with connect(None, workers) as client:
            client.wait_for_workers(workers)
            if warm_up:
                client.run(execute_run, dataclasses.replace(runs[0], seconds=0.1))
            cpu0 = client.run(_cpu)
            up = time.perf_counter()
            outcome = run_campaign(runs, ResultStore(Path(folder) / "results"),
                                   client=client, progress=False)
            end = time.perf_counter()
            cpu1 = client.run(_cpu)
    assert outcome.complete and not outcome.lost, outcome
    cpu = sum(cpu1[w] - cpu0[w] for w in cpu1 if w in cpu0)
    return end - start, end - up, outcome.written, cpu


def earlier_scheme(run) -> dict[str, str]:
    """The verdicts as checked before one pair was shared: stealthiness re-simulated the
    h / h/2 pair every other check reads (then a pair without the autonomous input)."""
    from verify.campaign.execute import build_human
    from verify.sim import properties as props
    from verify.sim.checks import CHECKS, applicable
    from verify.sim.command import SimulateSettings, build_scenario

    made, _ = build_human(run.human)
    sc = build_scenario(SimulateSettings(n=run.n, k_s=run.k_s, seed=run.seed,
                                         seconds=run.seconds, step=run.step,
                                         autonomous=run.autonomous,
                                         reference=run.reference), made)
    pair = props.RunPair.of(sc, run.seconds, run.step)
    out = {}
    for p in run.properties:
        if not applicable(p, sc):
            out[p] = "n/a"
        elif p == "stealthiness":
            out[p] = str(props.stealthiness(sc, run.seconds, run.step).status)
        else:
            out[p] = str(CHECKS[p](pair).status)
    return out


def shared_pair(runs) -> None:
    from verify.campaign.execute import column

    execute_run(runs[0])  # compile and gate outside the clock
    earlier_scheme(runs[0])
    t0 = time.process_time()
    rows = [execute_run(r) for r in runs]
    shared = time.process_time() - t0
    t0 = time.process_time()
    old = [earlier_scheme(r) for r in runs]
    separate = time.process_time() - t0
    same = all(row[column(p)] == o[p] for row, o in zip(rows, old, strict=True)
               for p in o)
    print(f"one shared pair: {shared:.2f} s CPU for {len(runs)} runs; stealthiness with its "
          f"own pair: {separate:.2f} s; ratio {shared / separate:.2f} "
          f"(-{100 * (1 - shared / separate):.0f} %); same verdicts: {same}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spec", type=Path, default=PAPER)
    parser.add_argument("--seconds", type=float, help="override the run length")
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--sample", type=int, metavar="N", default=16,
                        help="time N runs evenly spread over the campaign (0: all)")
    parser.add_argument("--no-warm-up", action="store_true",
                        help="time the first run of each worker with its start-up costs")
    parser.add_argument("--shared-pair", type=int, metavar="N", default=0,
                        help="also compare one shared pair with the earlier scheme on N runs")
    args = parser.parse_args()
    spec = load_campaign_spec(args.spec)
    if args.seconds is not None:
        spec = dataclasses.replace(spec, seconds=(args.seconds,))
    every = expand(spec)
    runs = every
    if args.sample and args.sample < len(every):
        stride = len(every) / args.sample
        runs = [every[int(i * stride)] for i in range(args.sample)]
    print(f"campaign {spec.name}: {len(every)} runs of {spec.seconds[0]:g} s; timing "
          f"{len(runs)}; properties {', '.join(spec.properties) or 'none'}")
    if args.shared_pair:
        shared_pair(runs[: args.shared_pair])
    print(f"{'workers':>7} {'wall [s]':>9} {'runs [s]':>9} {'runs/s':>8} {'speed-up':>8} "
          f"{'runs/CPU-s':>10}")
    base = None
    rates: dict[int, tuple[float, float]] = {}
    for w in args.workers:
        total, running, rows, cpu = session(runs, w, not args.no_warm_up)
        rate = rows / running
        base = rate if base is None else base
        rates[w] = (rate, rows / cpu if cpu > 0 else float("nan"))
        print(f"{w:>7} {total:>9.1f} {running:>9.1f} {rate:>8.3f} {rate / base:>8.2f} "
              f"{rates[w][1]:>10.3f}", flush=True)
    cpu_rate = max(r[1] for r in rates.values())
    two = rates.get(2, (float("nan"), cpu_rate))[0]
    print(f"projection for {spec.name} ({len(every)} runs): {len(every) / two / 60:.1f} min at "
          f"the measured 2-worker rate; {len(every) / (2 * cpu_rate) / 60:.1f} min on 2 idle "
          "cores (from runs per worker-CPU-second); timings under load from other jobs")


if __name__ == "__main__":
    main()
