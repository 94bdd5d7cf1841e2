"""Start-up of ``verify gate`` on small models, against ``python -c "import control"``.

Run: ``python benchmarks/bench_startup.py [--repeats 5] [--files 10]``. Each command runs
as a fresh process (what a CI job pays per call), ``--repeats`` times, interleaved so a
load change hits every command alike; the table gives the median wall and CPU (user +
sys of the child) seconds and the ratio to the baseline ``python -c "import control"``
measured in the same run. Commands:

- ``python -c pass``: the interpreter alone;
- ``import control``: the baseline (python-control, the library a lab would otherwise use);
- ``import verify.cli``: the command's own import;
- ``gate example``: ``verify gate`` on the shipped 2-state example (KYP route: Riccati and
  an exact check; no cvxpy, scipy.stats, scipy.optimize or sympy imported);
- ``gate ks3.0``: the passive k_s = 3.0 reconstruction (4 states, transfer-function file);
- ``gate N files``: ``verify gate`` on ``--files`` copies of the example in one process
  (many models decided by one start-up);
- ``verify list``: the claims' ids and paper references (read from the written-out
  index ``verify/claims/index.py``, so no module of checks is imported).

Certificates go to a temporary folder. BLAS threads are pinned to 1. ``--root DIR`` times
another checkout of the package (e.g. an older commit, unpacked with ``git archive``).
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _run(argv: list[str], env: dict[str, str], cwd: str) -> tuple[float, float]:
    """(wall seconds, child CPU seconds) of one process; it must exit 0. It runs in
    ``cwd`` (a temporary folder), so ``-m verify.cli`` finds the package through
    PYTHONPATH and not through the caller's working directory."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(argv, env=env, capture_output=True, text=True, cwd=cwd)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} exited {done.returncode}: {done.stderr.strip()}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--files", type=int, default=10)
    parser.add_argument("--root", type=Path, default=ROOT,
                        help="the checkout whose verify package is timed (default: this one)")
    args = parser.parse_args()
    root = args.root.resolve()
    models = root / "verify" / "data" / "models"
    env = dict(os.environ, PYTHONPATH=str(root), OPENBLAS_NUM_THREADS="1",
               OMP_NUM_THREADS="1", MKL_NUM_THREADS="1")
    py = sys.executable
    with tempfile.TemporaryDirectory() as tmp:
        copies = []
        for k in range(args.files):
            copy = Path(tmp) / f"model{k}.toml"
            shutil.copy(models / "example_state_space.toml", copy)
            copies.append(str(copy))
        certs = ["--certificates", str(Path(tmp) / "certs")]
        gate = [py, "-m", "verify.cli", "gate"]
        commands = {
            "python -c pass": [py, "-c", "pass"],
            "import control": [py, "-c", "import control"],
            "import verify.cli": [py, "-c", "import verify.cli"],
            "gate example": [*gate, str(models / "example_state_space.toml"), *certs],
            "gate ks3.0": [*gate, str(models / "reconstructed_ks3p0.toml"), *certs],
            f"gate {args.files} files": [*gate, *copies, *certs],
            "verify list": [py, "-m", "verify.cli", "list"],
        }
        times: dict[str, list[tuple[float, float]]] = {name: [] for name in commands}
        for argv in commands.values():  # warm the file cache once
            _run(argv, env, tmp)
        for _ in range(args.repeats):
            for name, argv in commands.items():
                times[name].append(_run(argv, env, tmp))
    base_wall = statistics.median(w for w, _ in times["import control"])
    base_cpu = statistics.median(c for _, c in times["import control"])
    print(f"{'command':<22}{'wall s':>9}{'cpu s':>9}{'wall/ctl':>10}{'cpu/ctl':>9}")
    for name, samples in times.items():
        wall = statistics.median(w for w, _ in samples)
        cpu = statistics.median(c for _, c in samples)
        print(f"{name:<22}{wall:9.3f}{cpu:9.3f}{wall / base_wall:10.2f}"
              f"{cpu / base_cpu:9.2f}")
    print(f"(median of {args.repeats} fresh processes each; os.getloadavg() = "
          f"{', '.join(f'{x:.1f}' for x in os.getloadavg())})")


if __name__ == "__main__":
    main()
