"""min nu(w) by Hamiltonian level crossings vs the log sweep + refinement it supplements.

Run: ``python benchmarks/bench_nu_minimum.py [n ...]``. For random stable models of n
states and 2 ports (plus, per size, one with a lightly damped resonance that makes a dip
of relative width ~1e-5), it prints the wall time of each method and how far each found
minimum lies above the better of the two (0 means it found the lower value).
"""

from __future__ import annotations

import sys
import time

import numpy as np

from verify.passivity.decision import candidate_frequencies
from verify.passivity.search.hamiltonian import nu_minimum

SIZES = (2, 8, 20, 50)


def random_model(n: int, rng: np.random.Generator, notch: bool):
    A = rng.standard_normal((n, n))
    A -= (np.max(np.linalg.eigvals(A).real) + 0.2) * np.eye(n)
    B, C = rng.standard_normal((n, 2)), rng.standard_normal((2, n))
    D = 3.0 * np.eye(2)
    if notch:  # append a resonance at w0 with damping z whose real part dips to -depth
        z, w0 = 1e-5, 3.7
        A = np.block([[A, np.zeros((n, 2))],
                      [np.zeros((2, n)), np.array([[0, 1], [-w0**2, -2 * z * w0]])]])
        B = np.vstack([B, [[0, 0], [1, 0]]])
        C = np.hstack([C, [[0, -(10.0 + 3.0) * 2 * z * w0], [0, 0]]])
    return A, B, C, D


def main(sizes) -> None:
    rng = np.random.default_rng(2026)
    print(f"{'n':>4} {'model':>8} {'hamiltonian s':>14} {'sweep s':>9} "
          f"{'ham. above best':>16} {'sweep above best':>17}")
    for n in sizes:
        for notch in (False, True):
            A, B, C, D = random_model(n, rng, notch)
            t = time.perf_counter()
            ham = nu_minimum(A, B, C, D).value
            t_ham = time.perf_counter() - t
            t = time.perf_counter()
            sweep = candidate_frequencies(A, B, C, D)[1][1]
            t_sweep = time.perf_counter() - t
            best = min(ham, sweep)
            print(f"{n:>4} {'notch' if notch else 'random':>8} {t_ham:>14.4f} {t_sweep:>9.4f} "
                  f"{ham - best:>16.3g} {sweep - best:>17.3g}")


if __name__ == "__main__":
    main([int(x) for x in sys.argv[1:]] or SIZES)
