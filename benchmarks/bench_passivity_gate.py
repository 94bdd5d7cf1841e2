"""Passivity gate vs python-control's ``ispassive`` on random port-Hamiltonian models.

Run: ``python benchmarks/bench_passivity_gate.py [--sizes 4,16,30,60,100] [--no-control]``
(needs ``pip install -e '.[bench]'`` for cvxopt, which python-control's ``ispassive``
uses; at n = 100 it takes minutes). Both tools see the same models in the same process;
the script prints, per model, each tool's verdict, whether it is right, the wall time
and the time ratio (python-control / ours). Our time includes the exact check of the
certificate or witness (``decide`` returns only exactly checked evidence); the benchmark
re-checks a certificate once more, untimed, with :func:`check_kyp`.

Models: x' = (J - R) Q x + G u, y = G^T Q x, with J skew, R = L L^T/n + 0.1 I > 0 and
Q = diag(2^k), k in {-2..2}. Q diagonal with powers of two keeps C = G^T Q exact in
floating point, so the exact model is passive (P = Q solves the KYP LMI with margin).
A sign-flipped output (y = -G^T Q x) gives a non-passive twin. The truth is known; the
gate is not told Q. Each size has its own seed, so any subset of sizes gives the same
models.

BLAS threads are pinned to 1 for both tools unless OPENBLAS_NUM_THREADS / OMP_NUM_THREADS
are set: on a loaded machine threaded BLAS makes timings erratic (a 10x spread).
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import argparse  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

from verify.passivity.certificate import check_kyp  # noqa: E402
from verify.passivity.decide import NOT_PASSIVE, PASSIVE, decide  # noqa: E402
from verify.passivity.model import from_state_space  # noqa: E402

SIZES = (4, 16, 30, 60, 100)
SEED = 20261121


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


def ours(A, B, C, D, n: int) -> tuple[str, float, bool]:
    """Verdict, seconds, and whether the evidence re-checks exactly."""
    model = from_state_space(A, B, C, D, name=f"pH n={n}")
    d, seconds = timed(lambda: decide(model))
    if isinstance(d, str):
        return d, seconds, False
    if d.verdict == PASSIVE:
        evidence = d.certificate is not None and check_kyp(d.certificate.model,
                                                           d.certificate.P).ok
    else:
        evidence = d.witness is not None
    return d.verdict, seconds, evidence


def theirs(A, B, C, D) -> tuple[str, float]:
    import control

    value, seconds = timed(lambda: control.ispassive(control.ss(A, B, C, D)))
    text = value if isinstance(value, str) else (PASSIVE if value else NOT_PASSIVE)
    return text, seconds


def main(sizes, with_control: bool = True) -> None:
    head = (f"{'n':>4} {'truth':>12} {'verify':>12} {'ok':>3} {'s':>8} "
            f"{'ispassive':>12} {'ok':>3} {'s':>8} {'ratio':>8}")
    print(head)
    for n in sizes:
        for flip in (False, True):
            rng = np.random.default_rng([SEED, n])
            A, B, C, D = port_hamiltonian(n, 2, rng, flip)
            truth = NOT_PASSIVE if flip else PASSIVE
            verdict, t_ours, evidence = ours(A, B, C, D, n)
            ok = "yes" if verdict == truth and evidence else "NO"
            if with_control:
                their_verdict, t_theirs = theirs(A, B, C, D)
                their_ok = "yes" if their_verdict == truth else "NO"
                ratio = f"{t_theirs / t_ours:8.1f}" if t_ours > 0 else "inf"
                tail = f"{their_verdict:>12} {their_ok:>3} {t_theirs:8.2f} {ratio:>8}"
            else:
                tail = f"{'-':>12} {'-':>3} {'-':>8} {'-':>8}"
            print(f"{n:>4} {truth:>12} {verdict:>12} {ok:>3} {t_ours:8.2f} {tail}",
                  flush=True)


def _sizes(text: str) -> list[int]:
    try:
        sizes = [int(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"--sizes {text!r}: comma-separated integers") from None
    if not sizes or min(sizes) < 1:
        raise argparse.ArgumentTypeError("--sizes needs positive integers")
    return sizes


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=_sizes, default=list(SIZES),
                        help="comma-separated state dimensions (default 4,16,30,60,100)")
    parser.add_argument("--no-control", action="store_true",
                        help="skip python-control's ispassive (ours only)")
    args = parser.parse_args()
    main(args.sizes, with_control=not args.no_control)
