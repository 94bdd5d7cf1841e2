"""The passivity test of `verify identify`: how often it rejects, per truth, and its cost.

For a passive operator (the shipped passive_human truth) and two non-passive ones (a lossy
diagonal element, Re h_2(jw) < 0 above 2 rad/s; skew violated only through the coupling,
c12 + c21 = 0.4), over seeds: synthetic experiments (``identify_models.open_loop_log``,
4 trials of 15 s at 120 Hz, white noise on e and u), the protocol (decimation to 20 Hz,
3:1 split), the estimator, then the test (:mod:`verify.identify.robust.passive_fit`). Printed per
truth: the rejection rate at 5 % (the test's size for the passive truth, its power for
the others) with an exact binomial 95 % interval, the median p-value, and the test's time
as a ratio to the estimator's, measured in the same process.

    PYTHONPATH=. python benchmarks/bench_identify_passive_fit.py [--seeds 10]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from fractions import Fraction
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from identify_models import open_loop_log

from verify.identify.data.protocol import prepare
from verify.identify.estimate.estimation import estimate_model
from verify.identify.estimate.structure import Structure
from verify.identify.robust.passive_fit import passivity_test
from verify.passivity.model import from_transfer_function

TRUTHS = {
    "passive (shipped passive_human)": [1.2, 0.8, 2.0, 1.5, 1.2, 0.8, 2.0, 1.5, 0.05, -0.05],
    "lossy element 2 (a1 b1 < b0)": [1.2, 0.8, 2.0, 1.5, 0.5, 1.0, 1.0, 2.0, 0.05, -0.05],
    "coupling only (c12 + c21 = 0.4)": [1.2, 0.8, 2.0, 1.5, 1.2, 0.8, 2.0, 1.5, 0.3, 0.1],
}


def _interval(k: int, n: int) -> tuple[float, float]:
    """Clopper-Pearson 95 % interval of a binomial proportion."""
    from scipy.stats import beta

    lo = 0.0 if k == 0 else float(beta.ppf(0.025, k, n - k + 1))
    hi = 1.0 if k == n else float(beta.ppf(0.975, k + 1, n - k))
    return lo, hi


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--noise", type=float, default=0.01)
    args = parser.parse_args(argv)
    print(f"{'truth':<34} {'rejected':>9} {'95 % interval':>15} {'median p':>10} "
          f"{'test/estimate time':>19}")
    for name, theta in TRUTHS.items():
        num, den = Structure.paper().transfer_matrix([Fraction(str(x)) for x in theta])
        model = from_transfer_function(num, den)
        rejected, ps, t_est, t_test = 0, [], 0.0, 0.0
        for seed in range(args.seeds):
            log = open_loop_log(model, trials=4, noise=args.noise, seed=100 + seed)
            prepared = prepare(log, rate=None, split=(3, 1))
            start = time.perf_counter()
            est = estimate_model(prepared.identification, Structure.paper())
            t_est += time.perf_counter() - start
            start = time.perf_counter()
            test = passivity_test(prepared.identification, est.theta)
            t_test += time.perf_counter() - start
            rejected += test.rejected
            ps.append(test.p_value)
        lo, hi = _interval(rejected, args.seeds)
        print(f"{name:<34} {rejected:>4}/{args.seeds:<4} {f'[{lo:.2f}, {hi:.2f}]':>15} "
              f"{statistics.median(ps):10.3g} {t_test / t_est:19.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
