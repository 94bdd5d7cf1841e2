"""Benchmark: structured O(n) application of A(d) against the dense 3n x 3n reference.

Both run in the same process on the same networks; the report is the time ratio
dense / structured for n = 10, 100, 1000, 10000 (the dense reference builds the full
matrix from an SVD of W, then multiplies; at n = 10000 it needs about 7.2 GB).

    python benchmarks/bench_stealthy_projector.py [--sizes 10 100 1000 10000] [--max-dense-gb 9]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from verify import so3
from verify.system import stealthy as st


def best_time(fn, repeats: int) -> float:
    best = np.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[10, 100, 1000, 10000])
    parser.add_argument("--max-dense-gb", type=float, default=9.0)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    print(
        f"{'n':>6} {'structured [s]':>15} {'dense build+apply [s]':>22} {'ratio':>9} "
        f"{'max |diff|':>11}"
    )
    for n in args.sizes:
        R = so3.random_rotations(n, rng)
        x = rng.standard_normal(3 * n)
        repeats = 20 if n <= 1000 else 3
        t_struct = best_time(lambda R=R, x=x: st.apply_projector(R, x), repeats)
        dense_gb = 8 * (3 * n) ** 2 / 1e9
        if dense_gb > args.max_dense_gb:
            print(f"{n:>6} {t_struct:>15.3e} {f'skipped ({dense_gb:.1f} GB)':>22}")
            continue
        t_dense = best_time(lambda R=R, x=x: st.projector_dense(R) @ x, repeats if n < 10000 else 1)
        diff = float(np.abs(st.projector_dense(R) @ x - st.apply_projector(R, x)).max())
        print(
            f"{n:>6} {t_struct:>15.3e} {t_dense:>22.3e} {t_dense / t_struct:>9.3g} {diff:>11.2e}",
            flush=True,
        )


if __name__ == "__main__":
    main()
