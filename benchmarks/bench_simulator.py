"""Reference simulator benchmark: the paper's scenario, scaling in n, order and drift.

Run: ``python benchmarks/bench_simulator.py [--sizes 10 100 1000 10000] [--seconds 2]``.

Reports, in one process:

1. the 180 s scenario of Section 4 (n = 8 bodies, 120 Hz loop, VR operator, reference
   switching every 15 s, consensus autonomous input): wall time and the ratio
   wall / simulated time (below 1 is faster than real time);
2. wall time per simulated second for n = 10 ... 10000 bodies, with zero and with
   consensus autonomous input, as ratios against the n = 10 run of the same kind;
3. the integrator's observed order (errors against a fine reference at h, h/2, h/4)
   and the orthogonality drift max |R^T R - I| and |det R - 1| after the 180 s run.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from verify import so3
from verify.sim.humans import StaticGainHuman, VROperator
from verify.sim.inputs import Reference, autonomous_input
from verify.sim.run import simulate
from verify.sim.scenario import Scenario


def _bodies(n: int, rng: np.random.Generator) -> np.ndarray:
    v = rng.standard_normal((n, 3))
    v *= (np.pi / 4) * rng.random((n, 1)) / np.linalg.norm(v, axis=1, keepdims=True)
    return so3.exp(v)


def paper_scenario(seed: int = 0) -> Scenario:
    rng = np.random.default_rng(seed)
    refs = [so3.exp(v) for v in 0.8 * rng.standard_normal((12, 3))]
    return Scenario(_bodies(8, rng), 3.0, VROperator(), Reference.switching(refs, 15.0),
                    autonomous=autonomous_input("consensus", 8))


def per_second(n: int, kind: str, seconds: float) -> float:
    rng = np.random.default_rng(n)
    scenario = Scenario(_bodies(n, rng), 3.0, StaticGainHuman(np.eye(2)),
                        Reference.constant(so3.exp(np.array([0.4, 0.2, 0.0]))),
                        autonomous=autonomous_input(kind, n))
    start = time.perf_counter()
    simulate(scenario, seconds)
    return (time.perf_counter() - start) / seconds


def observed_order() -> list[tuple[float, float]]:
    rng = np.random.default_rng(5)
    scenario = Scenario(_bodies(6, rng), 3.0, StaticGainHuman(np.eye(2)),
                        Reference.constant(so3.exp(np.array([0.9, -0.5, 0.0]))),
                        R_l0=so3.exp(np.array([0.3, 0.6, 0.0])),
                        autonomous=autonomous_input("random", 6, 3))
    ref = simulate(scenario, 1.0, 1 / 1920).final_bodies
    out = []
    for h in (1 / 30, 1 / 60, 1 / 120):
        out.append((h, float(np.abs(simulate(scenario, 1.0, h).final_bodies - ref).max())))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[10, 100, 1000, 10000])
    parser.add_argument("--seconds", type=float, default=2.0,
                        help="simulated seconds per size (default 2)")
    parser.add_argument("--skip-paper", action="store_true")
    args = parser.parse_args()

    if not args.skip_paper:
        start = time.perf_counter()
        traj = simulate(paper_scenario(), 180.0)
        wall = time.perf_counter() - start
        R = np.concatenate([traj.final_bodies, traj.R_bar[-1:], traj.R_l[-1:]])
        print(f"paper scenario (n = 8, 180 s at 120 Hz, VR operator, switching reference): "
              f"{wall:.1f} s wall, {wall / 180:.3f} s per simulated second")
        print(f"  drift after 21600 steps: max|R^T R - I| = "
              f"{so3.orthogonality_error(R).max():.2e}, max|det R - 1| = "
              f"{np.abs(np.linalg.det(R) - 1).max():.2e} (no re-projection)")

    print("wall time per simulated second (120 Hz); ratio against n = "
          f"{args.sizes[0]} of the same kind; < 1 s is faster than real time")
    for kind in ("zero", "consensus"):
        base = None
        for n in args.sizes:
            t = per_second(n, kind, args.seconds)
            base = base or t
            print(f"  {kind:<9} n = {n:>6}: {t:8.3f} s   ratio {t / base:7.1f}   "
                  f"{'real time' if t <= 1 else 'slower than real time'}")

    errors = observed_order()
    print("integrator order (CF4, errors at t = 1 s against h = 1/1920):")
    for (h, e), (_, e2) in zip(errors, [*errors[1:], (None, None)], strict=True):
        order = "" if e2 is None else f"   observed order {np.log2(e / e2):.2f}"
        print(f"  h = 1/{round(1 / h):<4} error {e:.3e}{order}")


if __name__ == "__main__":
    main()
