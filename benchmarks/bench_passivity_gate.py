"""Passivity gate vs python-control's ``ispassive`` on random port-Hamiltonian models.

Run: ``python benchmarks/bench_passivity_gate.py [n ...]`` (needs ``pip install -e '.[bench]'``
for cvxopt, which python-control's ``ispassive`` uses). Both tools see the same models in
the same process; the script prints, per size, each tool's verdict, whether it is right
and the wall time, and the time ratio.

Models: x' = (J - R) Q x + G u, y = G^T Q x, with J skew, R = L L^T/n + 0.1 I > 0 and
Q = diag(2^k), k in {-2..2}. Q diagonal with powers of two keeps C = G^T Q exact in
floating point, so the exact model is passive (P = Q solves the KYP LMI with margin).
A sign-flipped output (y = -G^T Q x) gives a non-passive twin. The truth is known.
"""

from __future__ import annotations

import sys
import time

import numpy as np

from verify.passivity.decide import NOT_PASSIVE, PASSIVE, decide
from verify.passivity.model import from_state_space

SIZES = (4, 16, 30, 60, 100)


def port_hamiltonian(n: int, m: int, rng: np.random.Generator, flip: bool = False):
    J = rng.standard_normal((n, n))
    J = J - J.T
    L = rng.standard_normal((n, n))
    R = L @ L.T / n + 0.1 * np.eye(n)
    Q = np.diag(2.0 ** rng.integers(-2, 3, n))
    G = rng.standard_normal((n, m))
    C = G.T @ Q
    return (J - R) @ Q, G, -C if flip else C, np.zeros((m, m))


def timed(f):
    start = time.perf_counter()
    try:
        value = f()
    except Exception as exc:  # a tool failing is a result, not a crash of the benchmark
        value = f"error: {type(exc).__name__}"
    return value, time.perf_counter() - start


def main(sizes) -> None:
    import control

    rng = np.random.default_rng(20261121)
    print(f"{'n':>4} {'truth':>12} {'verify':>14} {'s':>8} {'ispassive':>10} {'s':>8} {'ratio':>8}")
    for n in sizes:
        for flip in (False, True):
            A, B, C, D = port_hamiltonian(n, 2, rng, flip)
            truth = NOT_PASSIVE if flip else PASSIVE
            model = from_state_space(A, B, C, D, name=f"pH n={n}")
            ours, t_ours = timed(lambda: decide(model).verdict)  # noqa: B023
            theirs, t_theirs = timed(
                lambda: control.ispassive(control.ss(A, B, C, D))  # noqa: B023
            )
            theirs_text = theirs if isinstance(theirs, str) else (
                PASSIVE if theirs else NOT_PASSIVE)
            ratio = t_theirs / t_ours if t_ours > 0 else float("inf")
            print(f"{n:>4} {truth:>12} {ours:>14} {t_ours:8.2f} {theirs_text:>10} "
                  f"{t_theirs:8.2f} {ratio:8.1f}", flush=True)


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or SIZES)
