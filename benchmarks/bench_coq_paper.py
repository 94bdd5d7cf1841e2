"""Cost of compiling the paper's Coq development (Lemma 1, Theorem 1, the certificates).

Writes the development as ``verify coq`` does (``certificates/coq/`` by default, or a
fresh export with ``--export``) into a temporary folder, compiles every file of its
``_CoqProject`` in order with one ``coqc`` at a time, and prints each file's CPU seconds
(user + system, the robust figure on a shared machine), wall seconds and peak memory,
then the totals: the CPU sum is the wall time one core would need, and about twice the
wall time of ``verify coq --check --jobs 2`` on an idle 2-core machine.

    .venv/bin/python benchmarks/bench_coq_paper.py [--export] [--timeout 900]
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from verify.coq.development import LOGICAL_ROOT, coqc_available

ROOT = Path(__file__).resolve().parents[1]
COMMITTED = ROOT / "certificates" / "coq"


def compile_one(folder: Path, rel: str, timeout: float) -> tuple[float, float, float, bool]:
    """(CPU seconds, wall seconds, peak MB, ok) of ``coqc`` on one file."""
    start = time.perf_counter()
    proc = subprocess.Popen(["coqc", "-q", "-R", ".", LOGICAL_ROOT, rel], cwd=folder,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    while True:
        pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
        if pid:
            ok = os.waitstatus_to_exitcode(status) == 0
            break
        if time.perf_counter() - start > timeout:
            proc.kill()
            _, status, usage = os.wait4(proc.pid, 0)
            ok = False
            break
        time.sleep(0.02)
    return (usage.ru_utime + usage.ru_stime, time.perf_counter() - start,
            usage.ru_maxrss / 1024, ok)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--export", action="store_true",
                    help="export the development afresh instead of certificates/coq/")
    ap.add_argument("--timeout", type=float, default=900.0)
    args = ap.parse_args(argv)
    if not coqc_available():
        print("coqc not found", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp) / "dev"
        if args.export:
            from verify.coq.command import development_files
            from verify.coq.export import paper_development_units

            start = time.perf_counter()
            files = development_files(paper_development_units(ROOT / "certificates"))
            print(f"export: {time.perf_counter() - start:.1f} s (wall)")
            folder.mkdir()
            for rel, text in files.items():
                (folder / rel).write_text(text, encoding="utf-8")
        else:
            shutil.copytree(COMMITTED, folder)
        order = [ln for ln in (folder / "_CoqProject").read_text().splitlines()
                 if ln.endswith(".v")]
        print(f"{'file':45s} {'CPU s':>7s} {'wall s':>7s} {'peak MB':>8s}")
        total_cpu = total_wall = peak = 0.0
        for rel in order:
            cpu, wall, mb, ok = compile_one(folder, rel, args.timeout)
            total_cpu, total_wall, peak = total_cpu + cpu, total_wall + wall, max(peak, mb)
            print(f"{rel:45s} {cpu:7.2f} {wall:7.2f} {mb:8.0f}{'' if ok else '  FAILED'}")
            if not ok:
                return 1
        print(f"{'total (one coqc at a time)':45s} {total_cpu:7.2f} {total_wall:7.2f} "
              f"{peak:8.0f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
