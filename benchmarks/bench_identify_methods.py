"""The identification method against a plain output-error fit started from ARX.

Run: ``python benchmarks/bench_identify_methods.py [--seeds 20] [--n 8]``.

On the same seeded closed-loop experiments (as ``bench_identify_coverage.py``: the
paper's protocol with a known operator in the paper's class), two estimators:
``riv+pem`` (SRIVC and a grid of starting denominators, bounded output-error refinement,
each trial started at rest with a 1 s burn-in, :mod:`verify.identify.estimation`) and ``arx+oe``
(discrete ARX least squares converted to continuous time, then output-error least
squares with zero initial states, :mod:`verify.identify.baseline`). Printed per
parameter: bias (mean minus true), standard deviation and root-mean-square error over
the seeds, and how often each method lands far off (an estimate more than 10 times the
largest true magnitude away). BLAS threads are pinned to 1 unless set.
"""

from __future__ import annotations

from verify.cli import single_threaded_blas

single_threaded_blas()  # before numpy is imported (verify.cli does not import it)

import argparse  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from collections.abc import Sequence  # noqa: E402

import numpy as np  # noqa: E402

from verify.identify.coverage import Study, run_study  # noqa: E402

THETA_TRUE = (1.2, 0.8, 2.0, 1.5, 1.2, 0.8, 2.0, 1.5, 0.05, -0.05)


def bias_table(study: Study, methods: Sequence[str]) -> str:
    far = 10 * np.max(np.abs(study.theta_true))
    lines = [f"{'parameter':>10} {'true':>7} " + " ".join(
        f"{m + ' bias':>14} {m + ' sd':>12} {m + ' rmse':>13}" for m in methods)]
    est = {m: study.estimates(m) for m in methods}
    for k, name in enumerate(study.names):
        row = f"{name:>10} {study.theta_true[k]:7.3f} "
        for m in methods:
            x = est[m][:, k]
            bias = x.mean() - study.theta_true[k]
            row += (f"{bias:14.4g} {x.std(ddof=1):12.4g} "
                    f"{np.sqrt(np.mean((x - study.theta_true[k]) ** 2)):13.4g} ")
        lines.append(row)
    for m in methods:
        off = int(np.sum(np.any(np.abs(est[m] - study.theta_true) > far, axis=1)))
        failed = sum(m in r.failed for r in study.repetitions)
        lines.append(f"{m}: {len(est[m])} estimates, {off} far off, {failed} failed")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=20)
    parser.add_argument("--first-seed", type=int, default=1000)
    parser.add_argument("--n", type=int, default=8)
    parser.add_argument("--trials", type=int, default=6)
    args = parser.parse_args()
    methods = ("riv+pem", "arx+oe")
    warnings.simplefilter("ignore")
    start = time.perf_counter()
    study = run_study(THETA_TRUE, range(args.first_seed, args.first_seed + args.seeds),
                      methods=methods, n=args.n, trials=args.trials)
    print(f"{args.seeds} experiments, n = {args.n}, {args.trials} trials, "
          f"{time.perf_counter() - start:.0f} s")
    print(bias_table(study, methods))


if __name__ == "__main__":
    main()
