"""Cost of isolating `verify check FILE` (the file in a child process, each step in a
bounded fork) against loading and checking in one process, in the same run.

    python benchmarks/bench_check_isolation.py [FILE ...] [--repeat N]

Default files: the shipped examples. Prints, per file, the wall time of the in-process
path (the baseline: ``load_derivations`` + ``check``) and of the isolated path
(``load_isolated`` + ``check(..., budget=...)``) with quick search settings, and their
ratio. The verdicts must agree.
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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path,
                        default=[EXAMPLES / "damped_leader.py"])
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    single_threaded_blas()
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
