"""Reference simulator benchmark: old and new engines side by side, adaptive vs DOP853.

Run: ``python benchmarks/bench_simulator.py [--sizes 10 100 1000 10000] [--seconds 2]``.

"old" is ``simulate(..., engine="python")``, the Python field of ClosedLoop stepped by
CF4 (bit-for-bit the simulator before the compiled kernels); "new" is the default
(``engine="auto"``: the compiled kernels of verify/sim/kernels.py). Reports, in one
process:

1. the 180 s scenario of Section 4 (n = 8 bodies, 120 Hz loop, VR operator, reference
   switching every 15 s, consensus autonomous input), old and new: wall time, wall per
   simulated second, and the drift max |R^T R - I|, |det R - 1| (no re-projection); the
   same scenario with an LTI human, fixed step and adaptive;
2. wall time per simulated second for n = 10 ... 10000 bodies, zero and consensus
   autonomous input, old and new (below 1 is faster than real time);
3. the observed order of both engines (errors against h = 1/1920);
4. equal-accuracy comparison at n = 8, 100, 1000 (LTI human, consensus input, constant
   reference, 10 s, samples at 120 Hz): the adaptive mode at several tolerances, the
   fixed step, and the independent quaternion implementation integrated by scipy's
   DOP853 (benchmarks/quaternion_reference.py); errors are the largest deviation of
   R-bar, x (every sample) and the bodies (at the end) from a run with h = 1/1920, which
   tests/test_adaptive_simulation.py ties to the DOP853 implementation.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from quaternion_reference import QuaternionLoop

from verify import so3
from verify.sim import properties as props
from verify.sim.humans import LTIHuman, StaticGainHuman, VROperator
from verify.sim.inputs import Reference, autonomous_input
from verify.sim.run import simulate
from verify.sim.scenario import Scenario

A_H = np.array([[-0.5, 2.0], [-2.0, -0.5]])


def _lti_human() -> LTIHuman:
    return LTIHuman(A_H, np.eye(2), np.eye(2), 0.2 * np.eye(2))


def _bodies(n: int, rng: np.random.Generator) -> np.ndarray:
    v = rng.standard_normal((n, 3))
    v *= (np.pi / 4) * rng.random((n, 1)) / np.linalg.norm(v, axis=1, keepdims=True)
    return so3.exp(v)


def paper_scenario(seed: int = 0, human=None) -> Scenario:
    rng = np.random.default_rng(seed)
    refs = [so3.exp(v) for v in 0.8 * rng.standard_normal((12, 3))]
    return Scenario(_bodies(8, rng), 3.0, human or VROperator(),
                    Reference.switching(refs, 15.0), autonomous=autonomous_input("consensus", 8))


def _timed(fn, *args, **kwargs):
    start = time.perf_counter()
    out = fn(*args, **kwargs)
    return out, time.perf_counter() - start


def _drift(traj) -> tuple[float, float]:
    R = np.concatenate([traj.final_bodies, traj.R_bar, traj.R_l])
    return float(so3.orthogonality_error(R).max()), float(np.abs(np.linalg.det(R) - 1).max())


def per_second(n: int, kind: str, seconds: float, engine: str = "auto",
               adaptive: bool = False) -> float:
    rng = np.random.default_rng(n)
    scenario = Scenario(_bodies(n, rng), 3.0, StaticGainHuman(np.eye(2)),
                        Reference.constant(so3.exp(np.array([0.4, 0.2, 0.0]))),
                        autonomous=autonomous_input(kind, n))
    _, wall = _timed(simulate, scenario, seconds, engine=engine, adaptive=adaptive)
    return wall / seconds


def observed_order(engine: str) -> list[tuple[float, float]]:
    rng = np.random.default_rng(5)
    scenario = Scenario(_bodies(6, rng), 3.0, StaticGainHuman(np.eye(2)),
                        Reference.constant(so3.exp(np.array([0.9, -0.5, 0.0]))),
                        R_l0=so3.exp(np.array([0.3, 0.6, 0.0])),
                        autonomous=autonomous_input("random", 6, 3))
    ref = simulate(scenario, 1.0, 1 / 1920, engine=engine).final_bodies
    return [(h, float(np.abs(simulate(scenario, 1.0, h, engine=engine).final_bodies
                             - ref).max())) for h in (1 / 30, 1 / 60, 1 / 120)]


def paper_section(args) -> None:
    print("1. paper scenario (n = 8, 180 s at 120 Hz, switching reference, consensus input)")
    for label, engine in (("old", "python"), ("new", "auto")):
        traj, wall = _timed(simulate, paper_scenario(), 180.0, engine=engine)
        orth, det = _drift(traj)
        print(f"   VR operator, {label} ({engine:>6}): {wall:7.2f} s wall, "
              f"{wall / 180:.4f} s per simulated second; drift max|R^T R - I| = "
              f"{orth:.1e}, max|det R - 1| = {det:.1e}")
    pair, wall = _timed(props.RunPair.of, paper_scenario(), 180.0)
    result, wall_check = _timed(props.lyapunov_decrease, pair)
    print(f"   VR operator, new, with the property check (runs at h and h/2, Lyapunov terms "
          f"of both): {wall:.2f} s + {wall_check:.2f} s ({result.line().split(';')[0]})")
    lti = paper_scenario(human=_lti_human())
    for label, kw in (("new fixed step", {}),
                      ("new adaptive rtol 1e-8", {"adaptive": True, "rtol": 1e-8})):
        traj, wall = _timed(simulate, lti, 180.0, **kw)
        orth, det = _drift(traj)
        print(f"   LTI human, {label}: {wall:7.2f} s wall ({traj.steps} steps); drift "
              f"{orth:.1e}, {det:.1e}")


def scaling_section(args) -> None:
    print(f"2. wall time per simulated second ({args.seconds:g} simulated s each; static-gain "
          "human, 120 Hz); < 1 is faster than real time")
    print(f"   {'input':<9} {'n':>6}  {'old':>9}  {'new':>9}  {'speed-up':>8}  "
          f"{'new adaptive':>12}")
    for kind in ("zero", "consensus"):
        for n in args.sizes:
            old = per_second(n, kind, args.seconds, "python")
            new = per_second(n, kind, args.seconds)
            ada = per_second(n, kind, args.seconds, adaptive=True)
            print(f"   {kind:<9} {n:>6}  {old:8.4f}s  {new:8.4f}s  {old / new:7.1f}x  "
                  f"{ada:11.4f}s")


def order_section(args) -> None:
    print("3. integrator order (CF4, errors at t = 1 s against h = 1/1920)")
    for engine in ("python", "auto"):
        errors = observed_order(engine)
        for (h, e), (_, e2) in zip(errors, [*errors[1:], (None, None)], strict=True):
            order = "" if e2 is None else f"   observed order {np.log2(e / e2):.2f}"
            print(f"   {engine:>6} h = 1/{round(1 / h):<4} error {e:.3e}{order}")


def equal_accuracy_section(args) -> None:
    seconds = 10.0
    print(f"4. equal accuracy, {seconds:g} s, LTI human, consensus input, constant reference "
          "(wall per simulated second; error vs h = 1/1920)")
    R_r = so3.exp(np.array([0.7, -0.3, 0.2]))
    R_l0 = so3.exp(np.array([0.2, 0.5, 0.0]))
    for n in args.accuracy_sizes:
        rng = np.random.default_rng(n)
        R0 = _bodies(n, rng)
        scenario = Scenario(R0, 2.0, _lti_human(), Reference.constant(R_r), R_l0=R_l0,
                            autonomous=autonomous_input("consensus", n))
        truth = simulate(scenario, seconds, 1 / 1920)
        every = 16

        def error(R_bar, x, bodies, truth=truth, every=every):
            return max(np.abs(R_bar - truth.R_bar[::every]).max(),
                       np.abs(x - truth.x[::every]).max(),
                       np.abs(bodies - truth.final_bodies).max())

        rows = []
        for rtol in (1e-7, 1e-8, 1e-9, 1e-10):
            tr, wall = _timed(simulate, scenario, seconds, adaptive=True, rtol=rtol,
                              atol=1e-2 * rtol)
            rows.append((f"ours adaptive rtol {rtol:g}", wall, f"{tr.steps} steps",
                         error(tr.R_bar, tr.x, tr.final_bodies)))
        tr, wall = _timed(simulate, scenario, seconds)
        rows.append(("ours fixed h = 1/120", wall, f"{tr.steps} steps",
                     error(tr.R_bar, tr.x, tr.final_bodies)))
        Y0, x0 = scenario.validate().initial_state()
        h = scenario.human
        loop = QuaternionLoop(n, 2.0, h.A, h.B, h.C, h.D, R_r)
        z0 = loop.initial(R0, Y0[n], R_l0, x0[:-1])
        for rtol in (1e-6, 1e-8, 1e-10):
            res, wall = _timed(loop.solve, z0, seconds, truth.t[::every], rtol=rtol,
                               atol=1e-2 * rtol)
            Rs = np.array([loop.rotations(res.y[:, j]) for j in range(res.y.shape[1])])
            rows.append((f"DOP853 quaternions rtol {rtol:g}", wall,
                         f"{res.nfev} evaluations",
                         error(Rs[:, n], res.y[4 * (n + 2):].T, Rs[-1, :n])))
        for label, wall, work, err in rows:
            print(f"   n = {n:>4}  {label:<30} {wall / seconds:8.4f} s/s  error {err:.1e}  "
                  f"({work})")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[10, 100, 1000, 10000])
    parser.add_argument("--accuracy-sizes", type=int, nargs="+", default=[8, 100, 1000])
    parser.add_argument("--seconds", type=float, default=2.0,
                        help="simulated seconds per size in section 2 (default 2)")
    parser.add_argument("--skip-paper", action="store_true")
    args = parser.parse_args()
    simulate(paper_scenario(), 0.05)  # load (or compile) the kernels before timing
    simulate(paper_scenario(human=_lti_human()), 0.05, adaptive=True)
    if not args.skip_paper:
        paper_section(args)
    scaling_section(args)
    order_section(args)
    equal_accuracy_section(args)


if __name__ == "__main__":
    main()
