"""The complete exact route at 30-120 states: time and peak memory, beside python-control.

Run: ``python benchmarks/bench_passivity_complete.py [--sizes 30,60,90,120]
[--families lossless,tangent,nonpassive] [--control-max 60] [--band 0:3/2]
[--timeout 900]``. Each (family, size, tool) runs in its own process, so the peak RSS
printed is that run's alone (``ru_maxrss`` of the child); a run past ``--timeout`` seconds
is reported as such. Timings are wall-clock on whatever machine runs this, one BLAS
thread; on a shared machine they vary with the load.

Families (two ports, seeded by size, built in floats whose values are exact binary
rationals, so the exact model is the intended one):

- ``lossless``: x' = J Q x + G u, y = G^T Q x (J skew, Q = diag(2^k)): every pole on the
  imaginary axis, nu = 0 wherever defined: passive, and no strict certificate exists;
- ``tangent``: port 1 a dissipative port-Hamiltonian part (n - 3 states), port 2 the
  3-state H_t = (s^2/2 + s/2 + 1) / (s + 1)^3 whose Re H_t(jw) = (w^2 - 1)^2 / (1 + w^2)^3
  touches 0 at w = 1: passive, nu = 0 at w = 1 and at infinity;
- ``dense``: lossless like ``lossless``, but J and G small integers and Q = R Rᵀ + 2²⁰ I
  dense with integers of about 37 bits (R integers below 2^15), so that J Q is exact in
  floats and no short rounding of a float candidate is the storage P = Q;
- ``nonpassive``: ``tangent`` with port 2 H_t - eps/(s + 1), eps = 2^-40: nu < 0 only
  within about 1e-6 of w = 1, down to -eps/2 (below any float tolerance of the gate).

Columns: ``decide`` is :func:`verify.passivity.decision.decide` (what ``verify gate`` runs),
``band`` :func:`verify.passivity.band.decide_band` on ``--band``, ``ctl`` python-control's
``ispassive`` (cvxopt SDP, floating point; ``pip install cvxopt``), up to ``--control-max``
states; ``ratio`` is ctl / decide, both measured in fresh processes of this script.
"""

from __future__ import annotations

from verify.cli import single_threaded_blas

single_threaded_blas()  # before numpy is imported

import argparse  # noqa: E402
import json  # noqa: E402
import resource  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from fractions import Fraction  # noqa: E402

import numpy as np  # noqa: E402

FAMILIES = ("lossless", "tangent", "nonpassive", "dense")
EXPECTED = {"lossless": "passive", "tangent": "passive", "nonpassive": "not passive",
            "dense": "passive"}
SEED = 20261124


def build(family: str, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng([SEED, n, FAMILIES.index(family)])
    if family == "dense":  # lossless, Q dense with 37-bit integers: J Q exact in floats
        J = rng.integers(-9, 10, (n, n)).astype(float)
        J = J - J.T
        R = rng.integers(-(2**15), 2**15, (n, n)).astype(float)
        Q = R @ R.T + 2.0**20 * np.eye(n)
        G = rng.integers(-9, 10, (n, 2)).astype(float)
        return J @ Q, G, G.T @ Q, np.zeros((2, 2))
    if family == "lossless":
        J = rng.standard_normal((n, n))
        J = J - J.T
        Q = np.diag(2.0 ** rng.integers(-2, 3, n))
        G = rng.standard_normal((n, 2))
        return J @ Q, G, G.T @ Q, np.zeros((2, 2))
    from verify.passivity.port_hamiltonian import random_port_hamiltonian

    A1, B1, C1, _ = random_port_hamiltonian(n - 3, 1, rng)
    # H_t = (s^2/2 + s/2 + 1) / (s + 1)^3, controllable canonical form
    At = np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [-1.0, -3.0, -3.0]])
    Bt = np.array([[0.0], [0.0], [1.0]])
    Ct = np.array([[1.0, 0.5, 0.5]])
    if family == "nonpassive":  # H_t - eps / (s + 1), eps = 2^-40
        eps = 2.0**-40
        Ct = np.array([[1.0 - eps, 0.5 - 2 * eps, 0.5 - eps]])
    A = np.block([[A1, np.zeros((n - 3, 3))], [np.zeros((3, n - 3)), At]])
    B = np.block([[B1, np.zeros((n - 3, 1))], [np.zeros((3, 1)), Bt]])
    C = np.block([[C1, np.zeros((1, 3))], [np.zeros((1, n - 3)), Ct]])
    return A, B, C, np.zeros((2, 2))


def run_one(tool: str, family: str, n: int, band: str) -> dict:
    """One decision, imports done before the clock starts."""
    A, B, C, D = build(family, n)
    if tool == "ctl":
        import control

        def run() -> str:
            return "passive" if control.ispassive(control.ss(A, B, C, D)) else "not passive"
    else:
        from verify.passivity.band import decide_band, parse_band
        from verify.passivity.decision import decide
        from verify.passivity.model import from_state_space

        def run() -> str:
            model = from_state_space(A, B, C, D, name=f"{family} {n}")
            if tool == "decide":
                return str(decide(model).verdict)
            return str(decide_band(model, parse_band(band)).verdict)
    start = time.perf_counter()
    verdict = run()
    seconds = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return {"verdict": verdict, "seconds": seconds, "peak_mb": peak}


def in_child(tool: str, family: str, n: int, band: str, timeout: float) -> dict:
    cmd = [sys.executable, __file__, "--one", tool, family, str(n), band]
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout,
                             check=False)
    except subprocess.TimeoutExpired:
        return {"verdict": f"timeout {timeout:.0f} s", "seconds": None, "peak_mb": None}
    if out.returncode != 0:
        tail = (out.stderr.strip().splitlines() or ["?"])[-1]
        return {"verdict": f"error: {tail[:60]}", "seconds": None, "peak_mb": None}
    return json.loads(out.stdout.strip().splitlines()[-1])


def _cell(r: dict) -> str:
    if r["seconds"] is None:
        return f"{r['verdict']:>24}"
    return f"{r['verdict']:>12} {r['seconds']:7.2f} s {r['peak_mb']:5.0f} MB"


def main() -> None:
    if len(sys.argv) > 1 and sys.argv[1] == "--one":
        tool, family, n, band = sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
        print(json.dumps(run_one(tool, family, n, band)))
        return
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--sizes", default="30,60,90,120")
    p.add_argument("--families", default=",".join(FAMILIES))
    p.add_argument("--control-max", type=int, default=60)
    p.add_argument("--band", default="0:3/2")
    p.add_argument("--no-band", action="store_true")
    p.add_argument("--timeout", type=float, default=900.0)
    args = p.parse_args()
    Fraction(args.band.split(":")[1])  # fail early on a malformed band
    tools = ["decide"] + ([] if args.no_band else ["band"]) + ["ctl"]
    print(f"{'family':>10} {'n':>4} " + " ".join(f"{t:>30}" for t in tools) + "   ratio")
    for family in args.families.split(","):
        for n in (int(x) for x in args.sizes.split(",")):
            row = {}
            for tool in tools:
                if tool == "ctl" and n > args.control_max:
                    row[tool] = {"verdict": "skipped", "seconds": None, "peak_mb": None}
                    continue
                row[tool] = in_child(tool, family, n, args.band, args.timeout)
            wrong = [t for t in tools if row[t]["seconds"] is not None
                     and row[t]["verdict"] != EXPECTED[family]]
            ratio = ""
            if row["ctl"]["seconds"] and row["decide"]["seconds"]:
                ratio = f"{row['ctl']['seconds'] / row['decide']['seconds']:.1f}x"
            print(f"{family:>10} {n:>4} " + " ".join(f"{_cell(row[t]):>30}" for t in tools)
                  + f"   {ratio}" + (f"  WRONG {wrong}" if wrong else ""), flush=True)


if __name__ == "__main__":
    main()
