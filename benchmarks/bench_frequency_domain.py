"""Timing of the exact frequency-domain decision (python-flint) against model size.

Random port-Hamiltonian models (passive: A = (J - R) Q, B = G, C = G^T Q, D + D^T >= 0)
with rational entries, and the same models with C negated and D = 0 (not passive), for
n = 2, 10, 30, 60 states and m = 1, 2, 5 ports. Also the exact transfer matrix by
FLINT against the sympy Faddeev-LeVerrier of :mod:`verify.passivity.check.witness`.

    PYTHONPATH=. python benchmarks/bench_frequency_domain.py [--sizes 2 10 30] [--ports 1 2]
"""

from __future__ import annotations

import argparse
import time
from fractions import Fraction

import numpy as np
from gmpy2 import mpq

from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.frequency_domain import transfer_matrix
from verify.passivity.fd_decision import decide_positive_real


def random_ph(seed: int, n: int, m: int, negate: bool = False) -> ExactModel:
    rng = np.random.default_rng(seed)

    def rat(shape):
        return [[Fraction(int(rng.integers(-9, 10)), int(rng.integers(1, 5)))
                 for _ in range(shape[1])] for _ in range(shape[0])]

    def mul(X, Y):
        return [[sum((X[i][k] * Y[k][j] for k in range(len(Y))), Fraction(0))
                 for j in range(len(Y[0]))] for i in range(len(X))]

    def tr(X):
        return [list(r) for r in zip(*X, strict=True)]

    J0, R0, Q0, G, S = rat((n, n)), rat((n, n)), rat((n, n)), rat((n, m)), rat((m, m))
    J = [[J0[i][j] - J0[j][i] for j in range(n)] for i in range(n)]
    R = mul(R0, tr(R0))
    Qm = [[x + (i == j) for j, x in enumerate(row)] for i, row in enumerate(mul(Q0, tr(Q0)))]
    A = mul([[J[i][j] - R[i][j] for j in range(n)] for i in range(n)], Qm)
    C = mul(tr(G), Qm)
    D = [[a + b - c for a, b, c in zip(r1, r2, r3, strict=True)]
         for r1, r2, r3 in zip(mul(S, tr(S)), S, tr(S), strict=True)]
    if negate:  # -G(s) for the strictly proper passive G: not positive real
        C = [[-x for x in row] for row in C]
        D = [[Fraction(0)] * m for _ in range(m)]

    def q(X):
        return [[mpq(x) for x in row] for row in X]

    return ExactModel(q(A), q(G), q(C), q(D))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", type=int, nargs="*", default=[2, 10, 30, 60])
    ap.add_argument("--ports", type=int, nargs="*", default=[1, 2, 5])
    ap.add_argument("--sympy", action="store_true", help="also time the sympy transfer matrix")
    args = ap.parse_args()
    print("| n | m | passive: s | certificate | not passive: s | witness | "
          "flint H(s): s |" + (" sympy H(s): s |" if args.sympy else ""))
    print("|---|---|---|---|---|---|---|" + ("---|" if args.sympy else ""))
    for n in args.sizes:
        for m in args.ports:
            good, bad = random_ph(n * 100 + m, n, m), random_ph(n * 100 + m, n, m, True)
            t = time.perf_counter()
            v1, _r, cert, _w = decide_positive_real(good)
            t1 = time.perf_counter() - t
            kinds = sorted({("sturm" if f[2] == "sturm" else "sos") for c in
                            cert.analysis.certificates for f in c.factors
                            if f[1] % 2}) if cert else []
            t = time.perf_counter()
            v2, _r, _c, w = decide_positive_real(bad)
            t2 = time.perf_counter() - t
            t = time.perf_counter()
            transfer_matrix(good)
            t3 = time.perf_counter() - t
            row = (f"| {n} | {m} | {t1:.2f} ({v1}) | {'+'.join(kinds) or '-'} | "
                   f"{t2:.2f} ({v2}) | {w.kind if w else '-'} | {t3:.3f} |")
            if args.sympy:
                from verify.passivity.check.witness import _transfer_matrix

                t = time.perf_counter()
                _transfer_matrix(good)
                row += f" {time.perf_counter() - t:.2f} |"
            print(row, flush=True)


if __name__ == "__main__":
    main()
