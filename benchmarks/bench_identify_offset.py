"""Should `verify identify` estimate a constant offset per output? Coverage and point error
with and without it, on data with and without an offset.

Run: ``python benchmarks/bench_identify_offset.py [--seeds 20] [--first-seed 2000] [--n 2]
[--offset 0.1 -0.05]``.

Each seed simulates the paper's closed loop (Section 4, n bodies, 120 Hz, 6
identification trials of 15 s, operator noise in the loop and measurement noise at the
generator's defaults) with the shipped passive example operator, once; the same log is
prepared by the protocol as logged and with ``--offset`` added to the logged u (an
uncalibrated stick, :func:`verify.identify.data.simulated_experiment.with_output_offset`),
and each is estimated with and without the offset term
(:func:`verify.identify.estimate.estimation.estimate_model`, ``offset=``). Printed per
case: the fraction of seeds whose 95 % interval holds each true parameter (lowest over
the parameters, and which), the joint 95 % ellipsoid's coverage, the root-mean-square
error of the parameters relative to the truth (mean over parameters) and the largest
|z| = |estimate - truth| / se; for the estimated offsets their coverage too. BLAS
threads are pinned to 1 unless set.

Measured results are in docs/guide/identify.md ("Offsets").
"""

from __future__ import annotations

from verify.cli import single_threaded_blas

single_threaded_blas()  # before numpy is imported (verify.cli does not import it)

import argparse  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402
from scipy.stats import chi2  # noqa: E402

from verify.identify.data.protocol import prepare  # noqa: E402
from verify.identify.data.simulated_experiment import (  # noqa: E402
    simulate_experiment,
    with_output_offset,
)
from verify.identify.estimate.estimation import estimate_model  # noqa: E402
from verify.identify.estimate.structure import Structure  # noqa: E402
from verify.identify.quality.coverage import true_model  # noqa: E402

#: The shipped passive example operator (verify/data/logs/passive_human.toml).
THETA_TRUE = np.array([1.2, 0.8, 2.0, 1.5, 1.2, 0.8, 2.0, 1.5, 0.05, -0.05])
Z95 = 1.959963984540054


def one_seed(seed: int, n: int, offset: tuple[float, float], trials: int) -> dict:
    """Per (data, estimator) case: theta, se, covariance, offsets and their errors."""
    log = simulate_experiment(true_model(THETA_TRUE), trials=trials, n=n, seed=seed)
    out = {}
    for data_label, lg in (("no offset in data", log),
                           ("offset in data", with_output_offset(log, offset))):
        data = prepare(lg, rate="auto", split=(trials, 0)).identification
        for est_label, flag in (("estimated", True), ("not estimated", False)):
            est = estimate_model(data, Structure.paper(), offset=flag)
            out[(data_label, est_label)] = est
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=20)
    parser.add_argument("--first-seed", type=int, default=2000)
    parser.add_argument("--n", type=int, default=2)
    parser.add_argument("--trials", type=int, default=6)
    parser.add_argument("--offset", type=float, nargs=2, default=[0.1, -0.05])
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    offset = (args.offset[0], args.offset[1])
    results: dict = {}
    start = time.process_time()
    for seed in range(args.first_seed, args.first_seed + args.seeds):
        for key, est in one_seed(seed, args.n, offset, args.trials).items():
            results.setdefault(key, []).append(est)
        print(f"seed {seed} done ({time.process_time() - start:.0f} s CPU)", flush=True)
    names = Structure.paper().names()
    print(f"\n{args.seeds} seeds from {args.first_seed}: n = {args.n}, {args.trials} "
          f"identification trials x 15 s at 120 Hz, offset {offset[0]:g}, {offset[1]:g} on "
          f"u; {time.process_time() - start:.0f} s CPU")
    for (data_label, est_label), ests in results.items():
        theta = np.array([e.theta for e in ests])
        se = np.array([e.standard_errors() for e in ests])
        z = (theta - THETA_TRUE) / se
        cover = np.mean(np.abs(z) <= Z95, axis=0)
        joint = np.mean([float((e.theta - THETA_TRUE) @ np.linalg.solve(
            e.covariance, e.theta - THETA_TRUE)) <= chi2.ppf(0.95, len(THETA_TRUE))
            for e in ests])
        rmse = np.sqrt(np.mean((theta - THETA_TRUE) ** 2, axis=0)) / np.abs(THETA_TRUE)
        worst = int(np.argmin(cover))
        line = (f"{data_label:>18}, offset {est_label:>13}: coverage lowest "
                f"{100 * cover[worst]:.0f} % ({names[worst]}), joint {100 * joint:.0f} %, "
                f"relative RMSE mean {rmse.mean():.4f} (largest {rmse.max():.4f}, "
                f"{names[int(np.argmax(rmse))]}), largest |z| {np.max(np.abs(z)):.3g}")
        if ests[0].offsets:
            true = np.array(offset) if data_label == "offset in data" else np.zeros(2)
            off = np.array([e.offsets for e in ests])
            oerr = np.array([e.offset_errors for e in ests])
            ocov = np.mean(np.abs(off - true) <= Z95 * oerr, axis=0)
            line += (f"; offsets covered {100 * ocov[0]:.0f} %, {100 * ocov[1]:.0f} %, "
                     f"mean se {oerr.mean():.2g}")
        print(line, flush=True)


if __name__ == "__main__":
    main()
