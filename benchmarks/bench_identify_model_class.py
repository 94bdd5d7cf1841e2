"""The class test of `verify identify`: how often it rejects the paper's class, per truth.

Truths in the paper's class (the shipped passive and non-passive operators) and outside it
(a passive third-order operator; a non-passive third-order one, 3/((s + 1)(s^2 + s + 4)),
Re h(jw) < 0 above sqrt(2) rad/s), over seeds: the paper's closed loop with 2 bodies and
8 trials of 15 s at 120 Hz (``simulate_experiment`` with its default noises), the
protocol at the logged rate (4:4 split), the estimator, then the test
(:mod:`verify.identify.quality.model_class`). Printed per truth: how often the class is
rejected at the command's level (its size for the in-class truths, its power for the
others) with an exact binomial 95 % interval, the median and largest likelihood ratio of
the two outputs, and the test's time as a ratio to the estimator's, in the same process.
With ``--verdicts``, the whole command (all frequencies) on the same logs, per truth: how
often the class's region gave a confident answer (a region-wide refutation or a proof),
how often that answer was withdrawn, and the answers given.

    PYTHONPATH=. python benchmarks/bench_identify_model_class.py [--seeds 6] [--verdicts]
"""

from __future__ import annotations

import argparse
import json
import statistics
import tempfile
import time
from collections import Counter
from fractions import Fraction
from pathlib import Path

from verify.cli import main as verify_main
from verify.identify.data.protocol import prepare
from verify.identify.data.simulated_experiment import simulate_experiment
from verify.identify.estimate.estimation import estimate_model
from verify.identify.estimate.structure import Structure
from verify.identify.quality.model_class import model_class_test
from verify.inputs.experiment_log import write_log
from verify.passivity.model import from_transfer_function


def _diagonal(num: list[str], den: list[str], c: str = "0.05"):
    b, a, k = [Fraction(x) for x in num], [Fraction(x) for x in den], Fraction(c)
    return from_transfer_function([[b, [k]], [[-k], b]], [[a, [1]], [[1], a]])


def _paper(theta: list[float]):
    num, den = Structure.paper().transfer_matrix([Fraction(str(x)) for x in theta])
    return from_transfer_function(num, den)


TRUTHS = {
    "in class, passive (passive_human)":
        _paper([1.2, 0.8, 2.0, 1.5, 1.2, 0.8, 2.0, 1.5, 0.05, -0.05]),
    "in class, not passive (nonpassive_human)":
        _paper([0.5, 1.0, 1.0, 2.0, 0.5, 1.0, 1.0, 2.0, 0.05, -0.05]),
    "third order, passive": _diagonal(["1", "2", "2"], ["1", "2", "3", "2"]),
    "third order, not passive above 1.41": _diagonal(["3"], ["1", "2", "5", "4"]),
}


def _interval(k: int, n: int) -> tuple[float, float]:
    """Clopper-Pearson 95 % interval of a binomial proportion."""
    from scipy.stats import beta

    lo = 0.0 if k == 0 else float(beta.ppf(0.025, k, n - k + 1))
    hi = 1.0 if k == n else float(beta.ppf(0.975, k + 1, n - k))
    return lo, hi


def _verdicts(seeds: int) -> None:
    print(f"{'truth':<42} {'class answer confident':>22} {'withdrawn':>10}  answers given")
    for name, model in TRUTHS.items():
        confident, withdrawn, answers = 0, 0, Counter()
        for seed in range(seeds):
            with tempfile.TemporaryDirectory() as tmp:
                log = write_log(simulate_experiment(model, trials=8, n=2, seed=200 + seed),
                                Path(tmp) / "log.npz")
                verify_main(["identify", str(log), "--split", "4:4", "--out",
                             str(Path(tmp) / "out"), "--json", str(Path(tmp) / "s.json")])
                robust = json.loads((Path(tmp) / "s.json").read_text())["robust"]
            confident += robust["withdrawn"] or robust["verdict"] != "inconclusive"
            withdrawn += robust["withdrawn"]
            answers[robust["verdict"]] += 1
        given = ", ".join(f"{v}: {k}" for v, k in sorted(answers.items()))
        print(f"{name:<42} {confident:>18}/{seeds:<3} {withdrawn:>6}/{seeds:<3}  {given}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=6)
    parser.add_argument("--verdicts", action="store_true")
    args = parser.parse_args(argv)
    if args.verdicts:
        _verdicts(args.seeds)
        return 0
    print(f"{'truth':<42} {'rejected':>9} {'95 % interval':>15} {'median LR':>10} "
          f"{'max LR':>8} {'test/estimate time':>19}")
    for name, model in TRUTHS.items():
        rejected, ratios, t_est, t_test = 0, [], 0.0, 0.0
        for seed in range(args.seeds):
            log = simulate_experiment(model, trials=8, n=2, seed=200 + seed)
            prepared = prepare(log, rate="auto", split=(4, 4))
            start = time.perf_counter()
            est = estimate_model(prepared.identification, Structure.paper())
            t_est += time.perf_counter() - start
            start = time.perf_counter()
            test = model_class_test(est, prepared.identification)
            t_test += time.perf_counter() - start
            rejected += test.rejected
            ratios += list(test.statistic)
        lo, hi = _interval(rejected, args.seeds)
        print(f"{name:<42} {rejected:>4}/{args.seeds:<4} {f'[{lo:.2f}, {hi:.2f}]':>15} "
              f"{statistics.median(ratios):10.3g} {max(ratios):8.3g} "
              f"{t_test / t_est:19.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
