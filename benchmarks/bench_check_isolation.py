"""Cost of isolating `verify check FILE` (the file in a child process, each step in a
bounded fork) against loading and checking in one process, in the same run.

    python benchmarks/bench_check_isolation.py [FILE ...] [--repeat N]
    python benchmarks/bench_check_isolation.py --paper [--repeat N]

Default files: the shipped examples. Prints, per file, the wall time of the in-process
path (the baseline: ``load_derivations`` + ``check``) and of the isolated path
(``load_isolated`` + ``check(..., budget=...)``) with quick search settings, and their
ratio. The verdicts must agree. The isolated path runs the file in its sandbox
(namespaces) when they are available.

``--paper``: the paper's Lemma 1 and Theorem 1 derivations checked in-process (quick
settings) built by the Python of ``verify.paper_proofs`` against decoded from the
committed data (``verify/data/derivations``, what ``verify all`` now does): wall and CPU
time of each and their ratio.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

from verify.cli import single_threaded_blas

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _run(path: Path, isolated: bool, store: Path) -> tuple[float, list[str]]:
    from verify.claims.model import CheckContext
    from verify.claims.proofs import search_settings
    from verify.proof import certificate_store, check
    from verify.proof.budget import DEFAULT_BUDGET
    from verify.proof.isolate import load_isolated
    from verify.proof.user_file import load_derivations

    start = time.perf_counter()
    derivations = load_isolated(path) if isolated else load_derivations(path)
    context = CheckContext(seed=20261121, quick=True)
    verdicts = []
    with certificate_store(store, source=f"file:{path.name}"):
        for k, d in enumerate(derivations):
            r = check(d, search_settings(context, 101 * k),
                      budget=DEFAULT_BUDGET if isolated else None)
            verdicts.append(str(r.verdict))
    return time.perf_counter() - start, verdicts


def _paper(from_data: bool) -> tuple[float, float, list[str]]:
    from verify.claims.model import CheckContext
    from verify.claims.proofs import search_settings
    from verify.paper_proofs.data import GROUPS, derivations
    from verify.proof import check

    context = CheckContext(seed=20261121, quick=True)
    wall, cpu = time.perf_counter(), time.process_time()
    verdicts = []
    for k, group in enumerate(GROUPS):
        for d in (derivations(group) if from_data else GROUPS[group]()):
            verdicts.append(str(check(d, search_settings(context, k)).verdict))
    return time.perf_counter() - wall, time.process_time() - cpu, verdicts


def paper(repeat: int) -> None:
    _paper(True)  # imports and caches
    best = {True: (float("inf"), float("inf")), False: (float("inf"), float("inf"))}
    verdicts = {}
    for _ in range(repeat):
        for from_data in (False, True):
            wall, cpu, verdicts[from_data] = _paper(from_data)
            best[from_data] = (min(best[from_data][0], wall), min(best[from_data][1], cpu))
    assert verdicts[True] == verdicts[False], verdicts
    (pw, pc), (dw, dc) = best[False], best[True]
    print(f"paper derivations ({len(verdicts[True])}, "
          f"{verdicts[True].count('verified')} verified): from Python {pw:.2f} s wall "
          f"{pc:.2f} s CPU, from data {dw:.2f} s wall {dc:.2f} s CPU, ratio (CPU) "
          f"{dc / pc:.2f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path,
                        default=[EXAMPLES / "damped_leader.py"])
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--paper", action="store_true",
                        help="the paper's derivations: from Python against from data")
    args = parser.parse_args()
    single_threaded_blas()
    if args.paper:
        paper(args.repeat)
        return
    with tempfile.TemporaryDirectory() as tmp:
        for path in args.files:
            _run(path, False, Path(tmp))  # warm the certificate store and imports
            base = iso = float("inf")
            for _ in range(args.repeat):
                t, v0 = _run(path, False, Path(tmp))
                base = min(base, t)
                t, v1 = _run(path, True, Path(tmp))
                iso = min(iso, t)
                assert v0 == v1, (v0, v1)
            print(f"{path.name}: in-process {base:.2f} s, isolated {iso:.2f} s, "
                  f"ratio {iso / base:.2f} (verdicts {', '.join(v0)})")


if __name__ == "__main__":
    main()
