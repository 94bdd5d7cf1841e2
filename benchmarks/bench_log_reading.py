"""Experiment-log reading: peak memory and time of a large CSV log, against a baseline.

Run: ``python benchmarks/bench_log_reading.py [--mb 200] [--trials 12]``. Writes a CSV log
of about ``--mb`` MB (120 Hz, every column of the format, floats written with ``repr``) in
a temporary folder, then reads it in a fresh child process with
:func:`verify.inputs.experiment_log.read_log` and prints the child's peak resident memory
(``ru_maxrss``) and wall time. The baseline, in the same way, is a child that only imports
the package and NumPy, and one that reads the same file's bytes into memory; the ratios
say how much of the peak is the log's numbers (8 bytes a value) rather than its text.
Timings on a shared machine vary with the load.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

CHILD = """
import resource, sys, time
from pathlib import Path
mode, path = sys.argv[1], Path(sys.argv[2])
import numpy
import verify.inputs.experiment_log as log_module
start = time.perf_counter()
if mode == "read":
    log = log_module.read_log(path)
    rows = sum(len(tr.t) for tr in log.trials)
elif mode == "bytes":
    rows = len(path.read_bytes())
else:
    rows = 0
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, time.perf_counter() - start, rows)
"""


def write_csv(path: Path, megabytes: float, trials: int) -> int:
    """A valid log of about ``megabytes`` MB; returns the number of samples."""
    import numpy as np

    header = "time,trial,e1,e2,u1,u2,r1,r2,r3,valid,start\n"
    rng = np.random.default_rng(0)
    target = megabytes * 1e6
    written, n = 0, 0
    with path.open("w") as handle:
        handle.write("# rate = 120.0\n" + header)
        per_trial = None
        for trial in range(trials):
            rows = []
            k = 0
            while per_trial is None or k < per_trial:
                t = (n + trial * 240) / 120.0
                x = rng.standard_normal(7).tolist()
                rows.append(f"{t!r},{trial},{x[0]!r},{x[1]!r},{x[2]!r},{x[3]!r},"
                            f"{x[4]!r},{x[5]!r},{x[6]!r},1,{int(k == 5)}\n")
                k += 1
                n += 1
                if per_trial is None and len(rows) == 1000:
                    line = sum(map(len, rows)) / 1000
                    per_trial = int(target / line / trials)
                if len(rows) == 10_000:
                    handle.write("".join(rows))
                    written += sum(map(len, rows))
                    rows = []
            handle.write("".join(rows))
    return n


def child(mode: str, path: Path) -> tuple[float, float, int]:
    done = subprocess.run([sys.executable, "-c", CHILD, mode, str(path)],
                          capture_output=True, text=True)
    if done.returncode:
        raise SystemExit(f"the {mode} child failed: {done.stderr.strip().splitlines()[-1]}")
    out = done.stdout.split()
    return int(out[0]) / 1024, float(out[1]), int(out[2])  # MiB (Linux: ru_maxrss in KiB)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mb", type=float, default=200.0)
    parser.add_argument("--trials", type=int, default=12)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "large.csv"
        start = time.perf_counter()
        samples = write_csv(path, args.mb, args.trials)
        size = path.stat().st_size / 1e6
        print(f"wrote {size:.0f} MB, {samples} samples in {args.trials} trials "
              f"({time.perf_counter() - start:.0f} s)")
        base, _, _ = child("import", path)
        text, _, _ = child("bytes", path)
        peak, seconds, rows = child("read", path)
        assert rows == samples
        print(f"baseline (import only): peak {base:.0f} MiB")
        print(f"file bytes in memory:   peak {text:.0f} MiB ({text / base:.2f} x baseline)")
        print(f"read_log:               peak {peak:.0f} MiB ({peak / base:.2f} x baseline, "
              f"{(peak - base) / size:.2f} MiB per MB of log), {seconds:.1f} s, "
              f"{samples / seconds / 1e3:.0f} k rows/s")


if __name__ == "__main__":
    main()
