"""Growth of the checker's bookkeeping over a derivation with many side conditions.

    python benchmarks/bench_check_bookkeeping.py [N ...]

For each N (default 5 000, 10 000, 20 000, 40 000), a two-step derivation of the paper's
proof language with N conditions is validated (``validate_derivation``) and the union of
its steps' conditions and assumptions is formed (``_union``), as ``check`` does before
any algebra; and N derivations-data ``ddt`` nodes of one tree are decoded. Prints the
seconds and the ratio to the previous N: about 2 per doubling is linear, about 4
quadratic.
"""

from __future__ import annotations

import argparse
import json
import time


def _bookkeeping(n: int) -> float:
    from verify.proof import Context, Derivation, by_algebra
    from verify.proof.checker import _union, step_problem, validate_derivation

    ctx = Context("c")
    x = ctx.scalar("x")
    conditions = tuple(ctx.condition(f"c{k}", x * 0 + k, k) for k in range(n))
    d = Derivation("d", x, ctx, where=conditions).equals(x, by_algebra()) \
        .equals(x, by_algebra())
    start = time.perf_counter()
    validate_derivation(d)
    _union([step_problem(d, s) for s in d.steps])
    return time.perf_counter() - start


def _ddt(n: int) -> float:
    from verify.proof import Context, Derivation, by_algebra, hat, tr
    from verify.proof.rebuild import decode
    from verify.proof.wire import encode

    ctx = Context("c")
    R, w = ctx.rotation("R"), ctx.vector("w")
    ctx.dynamics(R, R @ hat(w))
    ctx.constant(w)
    tree = tr(R)
    for k in range(200):
        tree = tree + tr(R @ R) * k
    data = json.loads(json.dumps(encode([Derivation("d", tree, ctx).equals(
        tree, by_algebra())])))
    top = data["derivations"][0]["start"]
    data["nodes"] += [{"op": "ddt", "shape": "scalar", "value": 0, "args": [top],
                       "label": None}] * n
    start = time.perf_counter()
    decode(data)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sizes", nargs="*", type=int, default=[5000, 10000, 20000, 40000])
    args = parser.parse_args()
    for name, run in (("conditions", _bookkeeping), ("ddt nodes", _ddt)):
        previous = None
        for n in args.sizes:
            t = run(n)
            ratio = "" if previous is None else f", x{t / previous:.2f} over the previous"
            print(f"{n} {name}: {t:.3f} s{ratio}")
            previous = t


if __name__ == "__main__":
    main()
