"""The exact PSD fallback: fraction-free LDLᵀ on integers against rational LDLᵀ.

Run: ``python benchmarks/bench_exact_ldl.py [--sizes 30,60,100]``.

For each size n, three symmetric matrices like the ones the KYP check's exact fallback
receives (entries dyadic rationals with 52-bit mantissas over a common 2^60, as a rounded
certificate's):

- ``strict``: Rᵀ R + 2⁻²⁰ I (positive definite, R random dyadic);
- ``semidefinite``: G Gᵀ with G of rank n − 2, two of its rows sums of earlier rows, so
  the elimination meets zero pivots with zero rows in the middle;
- ``outside``: ``semidefinite`` with 2⁻⁶⁰ taken off a diagonal entry at a zero pivot (not
  PSD; the margin is below any float test).

Columns: ``mpq`` is :func:`verify.passivity.check.exact.psd_ldl` (rational LDLᵀ, the
route before), ``int`` is :func:`verify.passivity.check.ldl_int.psd_integer` on the
integer numerators (FLINT fraction-free LU, else symmetric Bareiss), both timed in this
process after the integer conversion; ``ratio`` = mpq / int. Both must give the same
answer (``agree``). Wall-clock seconds on whatever machine runs this.
"""

from __future__ import annotations

import argparse
import random
import time

from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check import intmat
from verify.passivity.check.ldl_int import psd_integer

SEED = 20261129


def _dyadic(rng: random.Random) -> mpq:
    return mpq(rng.randrange(-(2**52), 2**52), 2**60)


def matrices(n: int) -> dict[str, ex.RationalMatrix]:
    rng = random.Random(SEED + n)
    R = [[_dyadic(rng) for _ in range(n)] for _ in range(n)]
    strict = ex.matmul(ex.transpose(R), R)
    strict = [[x + (mpq(1, 2**20) if i == j else 0) for j, x in enumerate(row)]
              for i, row in enumerate(strict)]
    G = [[_dyadic(rng) for _ in range(n - 2)] for _ in range(n)]
    G[2] = [a + b for a, b in zip(G[0], G[1], strict=True)]  # zero pivot 2, zero row
    G[n // 2] = [a - b for a, b in zip(G[3], G[1], strict=True)]
    semi = ex.matmul(G, ex.transpose(G))
    outside = [row[:] for row in semi]
    outside[2][2] -= mpq(1, 2**60)
    return {"strict": strict, "semidefinite": semi, "outside": outside}


def timed(fn, *args, **kw):
    start = time.perf_counter()
    out = fn(*args, **kw)
    return out, time.perf_counter() - start


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--sizes", default="30,60,100")
    args = p.parse_args()
    print(f"{'n':>4} {'matrix':>13} {'mpq (s)':>9} {'int (s)':>9} {'ratio':>7} "
          f"{'psd':>5} agree")
    for n in (int(x) for x in args.sizes.split(",")):
        for name, X in matrices(n).items():
            Z = intmat.from_rational(X).Z.tolist()
            strict = name == "strict"
            a, t_mpq = timed(ex.psd_ldl, X, strict=strict)
            b, t_int = timed(psd_integer, Z, strict=strict)
            print(f"{n:>4} {name:>13} {t_mpq:9.3f} {t_int:9.3f} {t_mpq / t_int:7.1f} "
                  f"{b.ok!s:>5} {a.ok == b.ok}", flush=True)


if __name__ == "__main__":
    main()
