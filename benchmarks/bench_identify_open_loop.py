"""Calibration of the model-class test on open-loop data: how often does it reject an
operator that is in the class?

Run: ``python benchmarks/bench_identify_open_loop.py [--seeds 30] [--first-seed 1]
[--trials 4] [--no-offset]``.

Each seed simulates open-loop multisine trials (back to back, each from rest, white noise
on e and u: :func:`verify.identify.data.simulated_experiment.simulate_open_loop_experiment`)
of the two shipped example operators (both in the paper's class), prepares them by the
protocol, estimates H(s) and runs the class test
(:func:`verify.identify.quality.model_class.model_class_test`, which recognises open-loop
data and refits both classes with each trial's initial state estimated). Under the null
hypothesis (the operator is in the class) each output's likelihood ratio, divided by the
test's open-loop factor, should follow roughly chi-square with 2 + T degrees of freedom
(T trials, each with one more initial state in the larger model). Printed: the raw
likelihood ratios' mean over 2 + T (what the factor ``OPEN_LOOP_SCALE`` was set to) and
their quantiles against chi-square(2 + T)'s, the fraction of p-values below 0.05, 0.01 and 1e-3, and
the number of rejections at the test's level (5e-4 per output) with the exact binomial
95 % interval of the false-rejection rate per experiment (the test rejects when either
output does, nominal rate 1e-3). BLAS threads are pinned to 1 unless set.

Measured results are in docs/guide/identify.md ("Is the operator in the class at all?").
"""

from __future__ import annotations

from verify.cli import single_threaded_blas

single_threaded_blas()  # before numpy is imported (verify.cli does not import it)

import argparse  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402
from scipy.stats import beta, chi2  # noqa: E402

from verify.identify.data.example_logs import EXAMPLES  # noqa: E402
from verify.identify.data.protocol import prepare  # noqa: E402
from verify.identify.data.simulated_experiment import simulate_open_loop_experiment  # noqa: E402
from verify.identify.estimate.estimation import estimate_model  # noqa: E402
from verify.identify.estimate.structure import Structure  # noqa: E402
from verify.identify.quality.model_class import (  # noqa: E402
    LEVEL,
    OPEN_LOOP_SCALE,
    model_class_test,
)


def clopper_pearson(hits: int, count: int) -> tuple[float, float]:
    """The exact 95 % interval of a binomial proportion (Clopper & Pearson, 1934)."""
    lo = beta.ppf(0.025, hits, count - hits + 1) if hits > 0 else 0.0
    hi = beta.ppf(0.975, hits + 1, count - hits) if hits < count else 1.0
    return float(lo), float(hi)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=30)
    parser.add_argument("--first-seed", type=int, default=1)
    parser.add_argument("--trials", type=int, default=4)
    parser.add_argument("--no-offset", dest="offset", action="store_false")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    start = time.process_time()
    stats, ps, rejected, open_loop = [], [], [], []
    for seed in range(args.first_seed, args.first_seed + args.seeds):
        for example in EXAMPLES[:2]:
            log = simulate_open_loop_experiment(example.model(), trials=args.trials, seed=seed)
            data = prepare(log, rate="auto", split=(args.trials, 0)).identification
            est = estimate_model(data, Structure.paper(), offset=args.offset)
            test = model_class_test(est, data)
            stats += list(test.statistic)
            ps += list(test.p_value)
            rejected.append(test.rejected)
            open_loop.append(test.open_loop)
            print(f"seed {seed} {example.name}: LR {test.statistic[0]:.3g}, "
                  f"{test.statistic[1]:.3g}; p {test.p_value[0]:.3g}, {test.p_value[1]:.3g}"
                  f"{' REJECTED' if test.rejected else ''} "
                  f"({time.process_time() - start:.0f} s CPU)", flush=True)
    stats_a, ps_a = np.array(stats), np.array(ps)
    count = len(rejected)
    print(f"\n{count} open-loop experiments ({args.seeds} seeds x 2 in-class operators, "
          f"{args.trials} trials x 15 s at 120 Hz, offset "
          f"{'estimated' if args.offset else 'not estimated'}), {len(stats)} outputs; "
          f"recognised as open loop: {sum(open_loop)} of {count}; "
          f"{time.process_time() - start:.0f} s CPU")
    qs = (0.5, 0.9, 0.95, 0.99)
    dof = 2 + args.trials
    print("raw likelihood ratio quantiles " + ", ".join(
        f"{q:g}: {np.quantile(stats_a, q):.3g} (chi2({dof}) {chi2.ppf(q, dof):.3g})"
        for q in qs))
    print(f"mean raw likelihood ratio {stats_a.mean():.3g}, over {dof}: "
          f"{stats_a.mean() / dof:.3g} (the test divides by OPEN_LOOP_SCALE = "
          f"{OPEN_LOOP_SCALE:g}); largest {stats_a.max():.3g}")
    for level in (0.05, 0.01, 1e-3, LEVEL):
        print(f"test's p < {level:g}: {np.sum(ps_a < level)} of {len(ps_a)} outputs "
              f"({100 * np.mean(ps_a < level):.1f} %, nominal {100 * level:g} %)")
    hits = int(sum(rejected))
    lo, hi = clopper_pearson(hits, count)
    print(f"class rejected (level {LEVEL:g} per output): {hits} of {count} experiments; "
          f"exact 95 % interval of the false-rejection rate {100 * lo:.2f}-{100 * hi:.2f} % "
          f"(nominal about 0.1 %)")


if __name__ == "__main__":
    main()
