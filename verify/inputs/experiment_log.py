"""Experiment logs of the operator's input e and output u_h: the format, its reader and writer.

This docstring is the reference of the format. A log holds one or more *trials*
(Section 4, "Human Modeling": one trial per reference d_r), each uniformly sampled.

Columns (one value per sample)
------------------------------
======== ======== ==========================================================================
name     required meaning
======== ======== ==========================================================================
time     yes      seconds; strictly increasing within a trial, constant step
trial    yes      integer trial id; the rows of a trial are contiguous; trials are taken
                  in the order of the file (the identification/validation split follows it)
e1, e2   yes      the operator's input: first two components of sk(R_l^T R_r)^vee (rad)
u1, u2   yes      the operator's output: first two components of omega_h^b (rad/s)
r1 r2 r3 no       the reference direction d_r = R_r e3 (all three or none)
valid    no       1 = usable sample, 0 = not (dropped by the protocol; a trial is split there)
start    no       1 on the sample where the operator pressed "start" after the reference
                  change (at most one per trial), 0 elsewhere
======== ======== ==========================================================================

Sampling: within a trial every step must equal the trial's mean step
(t_last - t_first) / (N - 1) within a relative 1e-6; all trials must have the same step
(relative 1e-6). The rate is 1 / step, or the ``rate`` metadata when given (which must
agree with the step, relative 1e-6). A trial needs at least ``min_samples`` samples
(the caller passes what the model order needs; at least 2).

CSV (``.csv``)
--------------
UTF-8 text; the first line that is not a comment is the header (column names separated
by commas, in any order, surrounding spaces ignored); then one row per sample. Lines
whose first non-blank character is ``#`` are comments anywhere in the file; a comment
``# rate = 120`` gives the rate in Hz (other ``# key = value`` comments are kept as
notes and otherwise ignored). Numbers are decimal literals (``-1.5``, ``2e-3``,
``.5``); ``nan``, ``inf``, empty cells, underscores and text are refused. ``trial``,
``valid`` and ``start`` are integers written without a decimal point. The writer
prints every float with Python's ``repr`` (the shortest text that reads back to the same
double), so a CSV round trip is bit exact. Example::

    # verify experiment log
    # rate = 120.0
    time,trial,e1,e2,u1,u2,start
    0.0,0,0.12,-0.03,0.0,0.01,0
    0.008333333333333333,0,0.1199,-0.0301,0.002,0.011,0

NPZ (``.npz``)
--------------
A NumPy ``.npz`` archive (compressed or not) with one 1-D array per column, under the
column's name, all of one length; numeric dtypes only (``trial`` an integer dtype,
``valid`` and ``start`` integer or bool with values 0/1); an optional 0-d ``rate``
array. Object arrays are refused (the archive is loaded with ``allow_pickle=False``).
The writer uses compression and a fixed zip timestamp, so equal logs give equal bytes.

Errors
------
Every defect is one line (:class:`verify.errors.VerifyInputError`, exit 2 through the
CLI) naming the file, the row (CSV line number, or NPZ entry) or column, and the fix.
:func:`write_log` writes a temporary file and renames it: a failed write leaves nothing.
"""

from __future__ import annotations

import csv
import io
import itertools
import math
import re
import zipfile
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from verify.errors import VerifyInputError
from verify.identify.experiment import ExperimentLog, Trial
from verify.report.atomic import write_atomic

REQUIRED = ("time", "trial", "e1", "e2", "u1", "u2")
REFERENCE = ("r1", "r2", "r3")
FLAGS = ("valid", "start")
COLUMNS = (*REQUIRED, *REFERENCE, *FLAGS)
#: Relative tolerance on the sampling step (within a trial, between trials, vs the rate).
STEP_TOLERANCE = 1e-6

_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")
_INTEGER = re.compile(r"[+-]?\d+")
_NONFINITE = re.compile(r"[+-]?(nan|inf|infinity)", re.IGNORECASE)
_ZIP_TIME = (1980, 1, 1, 0, 0, 0)

__all__ = ["COLUMNS", "REQUIRED", "STEP_TOLERANCE", "read_log", "read_logs", "write_log"]


def _fail(where: str, what: str) -> VerifyInputError:
    return VerifyInputError(f"{where}: {what}")


def _suffix(path: Path) -> str:
    suffix = path.suffix.lower()
    if suffix not in (".csv", ".npz"):
        raise VerifyInputError(f"{path}: unknown log format {path.suffix or '(no suffix)'!r}; "
                               "name the file .csv or .npz")
    return suffix


# ----------------------------------------------------------------------------------- reading


def read_log(path: str | Path, *, min_samples: int = 2) -> ExperimentLog:
    """The trials of one log file (format in the module docstring).

    ``min_samples`` is the fewest samples a trial may have (what the model order needs;
    at least 2). Any defect raises a one-line :class:`VerifyInputError`.
    """
    path = Path(path)
    suffix = _suffix(path)
    if not isinstance(min_samples, int) or isinstance(min_samples, bool) or min_samples < 2:
        raise VerifyInputError(f"min_samples must be an integer >= 2, got {min_samples!r}")
    if not path.is_file():
        raise VerifyInputError(f"{path}: no such log file; check the path")
    if suffix == ".csv":
        columns, rows, rate = _read_csv(path)
    else:
        columns, rows, rate = _read_npz(path)
    return _assemble(path, columns, rows, rate, min_samples)


def read_logs(paths: Sequence[str | Path], *, min_samples: int = 2) -> ExperimentLog:
    """The trials of several log files, in the order given (then file order).

    All files must have the same rate (relative 1e-6). Trial ids are kept when they are
    distinct across the files; otherwise every trial is renumbered 0, 1, 2, ... in
    reading order.
    """
    paths = list(paths)
    if not paths:
        raise VerifyInputError("no log files given; pass one or more .csv or .npz logs")
    logs = [read_log(p, min_samples=min_samples) for p in paths]
    rate = logs[0].rate
    for p, log in zip(paths, logs, strict=True):
        if abs(log.rate - rate) > STEP_TOLERANCE * rate:
            raise VerifyInputError(
                f"{p}: rate {log.rate:g} Hz differs from {rate:g} Hz of {paths[0]}; "
                "resample the logs to one rate before combining them")
    trials = [tr for log in logs for tr in log.trials]
    if len({tr.trial for tr in trials}) != len(trials):
        trials = [Trial(k, tr.t, tr.e, tr.u, tr.reference, tr.valid, tr.start)
                  for k, tr in enumerate(trials)]
    return ExperimentLog(tuple(trials), rate, "; ".join(str(p) for p in paths))


def _header(path: Path, names: list[str], where: str) -> list[str]:
    names = [n.strip() for n in names]
    seen: set[str] = set()
    for name in names:
        if name not in COLUMNS:
            raise _fail(where, f"unknown column {name!r}; the columns are {', '.join(COLUMNS)} "
                        "(see verify.inputs.experiment_log)")
        if name in seen:
            raise _fail(where, f"column {name!r} appears twice; keep one")
        seen.add(name)
    missing = [n for n in REQUIRED if n not in seen]
    if missing:
        raise _fail(where, f"missing column{'s' if len(missing) > 1 else ''} "
                    f"{', '.join(missing)}; a log needs {', '.join(REQUIRED)}")
    ref = [n for n in REFERENCE if n in seen]
    if ref and len(ref) != 3:
        raise _fail(where, f"reference columns {', '.join(ref)} without the others; give all "
                    "of r1, r2, r3 or none")
    return names


def _read_csv(path: Path) -> tuple[dict[str, np.ndarray], np.ndarray, float | None]:
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise VerifyInputError(f"{path}: not UTF-8 text (byte {exc.start}); save the log as "
                               "UTF-8 CSV") from None
    rate: float | None = None
    names: list[str] | None = None
    cells: list[list[str]] = []
    lines: list[int] = []
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            key, eq, value = stripped[1:].partition("=")
            if eq and key.strip() == "rate":
                value = value.strip()
                if not _NUMBER.fullmatch(value) or not float(value) > 0:
                    raise _fail(f"{path}: line {number}", f"rate {value!r} is not a positive "
                                "number; write e.g. '# rate = 120'")
                rate = float(value)
            continue
        row = next(csv.reader([line]))
        if names is None:
            names = _header(path, row, f"{path}: line {number} (header)")
            continue
        if len(row) != len(names):
            raise _fail(f"{path}: line {number}", f"{len(row)} cells, the header has "
                        f"{len(names)}; give one value per column")
        cells.append(row)
        lines.append(number)
    if names is None:
        raise VerifyInputError(f"{path}: empty log (no header line); the first line must name "
                               f"the columns, e.g. {','.join(REQUIRED)}")
    if not cells:
        raise VerifyInputError(f"{path}: the log has a header but no samples; add data rows")
    columns: dict[str, np.ndarray] = {}
    for j, name in enumerate(names):
        integer = name in ("trial", *FLAGS)
        pattern = _INTEGER if integer else _NUMBER
        values = []
        for row, number in zip(cells, lines, strict=True):
            cell = row[j].strip()
            if not pattern.fullmatch(cell):
                raise _fail(f"{path}: line {number}, column {name!r}",
                            _bad_cell(cell, integer))
            values.append(cell)
        columns[name] = (np.array([int(v) for v in values], dtype=np.int64) if integer
                         else np.array([float(v) for v in values], dtype=np.float64))
        if not integer and not np.all(np.isfinite(columns[name])):
            k = int(np.flatnonzero(~np.isfinite(columns[name]))[0])
            raise _fail(f"{path}: line {lines[k]}, column {name!r}",
                        f"{cells[k][j].strip()!r} is beyond the float range; give a finite "
                        "number")
    return columns, np.array(lines), rate


def _bad_cell(cell: str, integer: bool) -> str:
    if not cell:
        return "empty cell; give a value"
    if _NONFINITE.fullmatch(cell):
        return f"NaN or Inf ({cell!r}) is not allowed; give a finite number or mark the sample " \
               "invalid (valid = 0) with any finite value"
    if integer:
        if _NUMBER.fullmatch(cell):
            return f"{cell!r} is not an integer; write a whole number without a decimal point"
        return f"{cell!r} is not an integer; write a whole number"
    return f"{cell!r} is not a number; write a decimal such as -0.25 or 1.5e-3"


def _read_npz(path: Path) -> tuple[dict[str, np.ndarray], np.ndarray, float | None]:
    try:
        archive = np.load(path, allow_pickle=False)
    except (OSError, ValueError, zipfile.BadZipFile, EOFError) as exc:
        first = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise VerifyInputError(f"{path}: not a readable .npz archive ({first}); write it with "
                               "numpy.savez or verify simulate --log") from None
    if not isinstance(archive, np.lib.npyio.NpzFile):
        raise VerifyInputError(f"{path}: a single .npy array, not an .npz archive; save the "
                               "columns with numpy.savez(path, time=..., trial=..., ...)")
    arrays: dict[str, np.ndarray] = {}
    with archive:
        names = list(archive.files)
        if not names:
            raise VerifyInputError(f"{path}: empty archive; it needs the arrays "
                                   f"{', '.join(REQUIRED)}")
        for name in names:
            try:
                arrays[name] = archive[name]
            except ValueError:
                raise VerifyInputError(
                    f"{path}: array {name!r} holds Python objects (pickled), which are not "
                    "loaded; store numbers (float64, int64 or bool)") from None
            except (OSError, zipfile.BadZipFile, EOFError) as exc:
                raise VerifyInputError(f"{path}: array {name!r} is unreadable ({exc}); "
                                       "rewrite the archive") from None
    rate = None
    if "rate" in arrays:
        r = arrays.pop("rate")
        if r.shape != () or r.dtype.kind not in "iuf" or not (np.isfinite(r) and r > 0):
            raise _fail(f"{path}: array 'rate'", f"must be one positive number (0-d array), "
                        f"got shape {r.shape}, dtype {r.dtype}")
        rate = float(r)
    _header(path, list(arrays), f"{path}")
    lengths = {arr.shape for arr in arrays.values()}
    for name, arr in arrays.items():
        if arr.ndim != 1:
            raise _fail(f"{path}: array {name!r}", f"must be 1-D (one value per sample), got "
                        f"shape {arr.shape}")
    if len(lengths) > 1:
        raise _fail(path, "arrays of different lengths "
                    + ", ".join(f"{n}: {a.shape[0]}" for n, a in arrays.items())
                    + "; give every column one value per sample")
    if next(iter(lengths))[0] == 0:
        raise VerifyInputError(f"{path}: the log has no samples; add data")
    columns: dict[str, np.ndarray] = {}
    for name, arr in arrays.items():
        where = f"{path}: array {name!r}"
        kind = arr.dtype.kind
        if name in ("trial", *FLAGS):
            if kind == "b" and name in FLAGS:
                arr = arr.astype(np.int64)
            elif kind not in "iu":
                raise _fail(where, f"dtype {arr.dtype} is not an integer type; store whole "
                            "numbers as int64" + (" (or bool)" if name in FLAGS else ""))
            columns[name] = arr.astype(np.int64)
        else:
            if kind not in "iuf":
                raise _fail(where, f"dtype {arr.dtype} is not a real number type; store float64")
            arr = arr.astype(np.float64)
            bad = np.flatnonzero(~np.isfinite(arr))
            if bad.size:
                raise _fail(f"{where}[{bad[0]}]", f"NaN or Inf ({arr[bad[0]]}) is not allowed; "
                            "give a finite number or mark the sample invalid (valid = 0)")
            columns[name] = arr
    return columns, np.arange(next(iter(lengths))[0]), rate


def _row(path: Path, rows: np.ndarray, k: int) -> str:
    if path.suffix.lower() == ".csv":
        return f"{path}: line {rows[k]}"
    return f"{path}: entry {rows[k]}"


def _assemble(path: Path, columns: dict[str, np.ndarray], rows: np.ndarray,
              rate: float | None, min_samples: int) -> ExperimentLog:
    trial = columns["trial"]
    for name in FLAGS:
        if name in columns:
            bad = np.flatnonzero((columns[name] != 0) & (columns[name] != 1))
            if bad.size:
                raise _fail(f"{_row(path, rows, bad[0])}, column {name!r}",
                            f"{columns[name][bad[0]]} is not 0 or 1; write 1 (yes) or 0 (no)")
    breaks = np.flatnonzero(np.diff(trial) != 0) + 1
    bounds = [0, *breaks.tolist(), trial.shape[0]]
    seen: dict[int, int] = {}
    trials: list[Trial] = []
    step0: float | None = None
    for a, b in itertools.pairwise(bounds):
        tid = int(trial[a])
        where = f"{_row(path, rows, a)}, trial {tid}"
        if tid in seen:
            raise _fail(where, f"trial {tid} appears again after other trials (first at "
                        f"{_row(path, rows, seen[tid]).split(': ', 1)[1]}); keep each trial's "
                        "rows together")
        seen[tid] = a
        n = b - a
        if n < min_samples:
            raise _fail(where, f"trial {tid} has {n} sample{'s' if n != 1 else ''}; at least "
                        f"{min_samples} are needed (the model order and the protocol need "
                        "them); drop the trial or record longer")
        t = columns["time"][a:b]
        d = np.diff(t)
        if np.any(d <= 0):
            k = int(np.flatnonzero(d <= 0)[0]) + 1
            kind = "repeats" if d[k - 1] == 0 else "goes back"
            raise _fail(f"{_row(path, rows, a + k)}, column 'time'",
                        f"time {float(t[k])!r} {kind} within trial {tid} (previous "
                        f"{float(t[k - 1])!r}); "
                        "time must increase strictly within a trial")
        step = (t[-1] - t[0]) / (n - 1)
        off = np.abs(d - step) > STEP_TOLERANCE * step
        if np.any(off):
            k = int(np.flatnonzero(off)[0]) + 1
            raise _fail(f"{_row(path, rows, a + k)}, column 'time'",
                        f"unequal sampling in trial {tid}: step {d[k - 1]:.9g} s vs the trial's "
                        f"mean step {step:.9g} s (tolerance: relative {STEP_TOLERANCE:g}); "
                        "resample the trial uniformly")
        if step0 is None:
            step0 = step
        elif abs(step - step0) > STEP_TOLERANCE * step0:
            raise _fail(where, f"trial {tid} has step {step:.9g} s, the first trial "
                        f"{step0:.9g} s (tolerance: relative {STEP_TOLERANCE:g}); resample the "
                        "trials to one rate")
        start = None
        if "start" in columns:
            marks = np.flatnonzero(columns["start"][a:b])
            if marks.size > 1:
                raise _fail(f"{_row(path, rows, a + marks[1])}, column 'start'",
                            f"a second start event in trial {tid} (first at time "
                            f"{float(t[marks[0]])!r}); mark one start per trial")
            start = float(t[marks[0]]) if marks.size else None
        reference = (np.stack([columns[r][a:b] for r in REFERENCE], axis=1)
                     if "r1" in columns else None)
        valid = columns["valid"][a:b].astype(bool) if "valid" in columns else None
        e = np.stack([columns["e1"][a:b], columns["e2"][a:b]], axis=1)
        u = np.stack([columns["u1"][a:b], columns["u2"][a:b]], axis=1)
        trials.append(Trial(tid, t.copy(), e, u, reference, valid, start))
    assert step0 is not None
    if rate is None:
        rate = 1.0 / step0
    elif abs(rate * step0 - 1.0) > STEP_TOLERANCE:
        raise VerifyInputError(f"{path}: the rate metadata says {rate:g} Hz but the time step "
                               f"is {step0:.9g} s ({1 / step0:.9g} Hz); fix the rate or the "
                               "time column")
    return ExperimentLog(tuple(trials), float(rate), str(path))


# ----------------------------------------------------------------------------------- writing


def _columns(log: ExperimentLog) -> dict[str, np.ndarray]:
    if not log.trials:
        raise VerifyInputError("the log has no trials; nothing to write")
    out: dict[str, list[np.ndarray]] = {name: [] for name in COLUMNS}
    with_ref = all(tr.reference is not None for tr in log.trials)
    with_valid = any(tr.valid is not None for tr in log.trials)
    with_start = any(tr.start is not None for tr in log.trials)
    for tr in log.trials:
        n = tr.t.shape[0]
        out["time"].append(np.asarray(tr.t, dtype=np.float64))
        out["trial"].append(np.full(n, int(tr.trial), dtype=np.int64))
        for k in range(2):
            out[f"e{k + 1}"].append(np.asarray(tr.e[:, k], dtype=np.float64))
            out[f"u{k + 1}"].append(np.asarray(tr.u[:, k], dtype=np.float64))
        if with_ref:
            for k in range(3):
                out[f"r{k + 1}"].append(np.asarray(tr.reference[:, k], dtype=np.float64))
        if with_valid:
            valid = np.ones(n, bool) if tr.valid is None else np.asarray(tr.valid, bool)
            out["valid"].append(valid.astype(np.int64))
        if with_start:
            mark = np.zeros(n, np.int64)
            if tr.start is not None:
                k = int(np.argmin(np.abs(tr.t - tr.start)))
                if abs(tr.t[k] - tr.start) > STEP_TOLERANCE * max(tr.step, 1e-300):
                    raise VerifyInputError(f"trial {tr.trial}: start time {tr.start!r} is not "
                                           "a sample time; put the start event on a sample")
                mark[k] = 1
            out["start"].append(mark)
    return {name: np.concatenate(parts) for name, parts in out.items() if parts}


def _csv_bytes(log: ExperimentLog, columns: dict[str, np.ndarray]) -> bytes:
    buf = io.StringIO()
    buf.write("# verify experiment log (format: verify.inputs.experiment_log)\n")
    buf.write(f"# rate = {float(log.rate)!r}\n")
    source = " ".join(str(log.source).split())
    if source:
        buf.write(f"# source = {source}\n")
    names = list(columns)
    buf.write(",".join(names) + "\n")
    lists = [columns[n].tolist() for n in names]  # Python int / float: repr is exact
    for row in zip(*lists, strict=True):
        buf.write(",".join(map(repr, row)) + "\n")
    return buf.getvalue().encode("utf-8")


def _npz_bytes(log: ExperimentLog, columns: dict[str, np.ndarray]) -> bytes:
    buf = io.BytesIO()
    arrays = {**columns, "rate": np.array(float(log.rate))}
    with zipfile.ZipFile(buf, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for name, arr in arrays.items():
            info = zipfile.ZipInfo(f"{name}.npy", date_time=_ZIP_TIME)
            info.compress_type = zipfile.ZIP_DEFLATED
            with archive.open(info, "w", force_zip64=True) as handle:
                np.lib.format.write_array(handle, np.array(arr, order="C"),
                                          allow_pickle=False)
    return buf.getvalue()


def write_log(log: ExperimentLog, path: str | Path) -> Path:
    """Write ``log`` as CSV or NPZ (by the suffix), atomically (temporary file + rename).

    CSV floats are written with ``repr`` (bit-exact round trip); NPZ is compressed with a
    fixed timestamp (equal logs, equal bytes). Returns the path written.
    """
    path = Path(path)
    suffix = _suffix(path)
    if not (isinstance(log.rate, int | float) and math.isfinite(log.rate) and log.rate > 0):
        raise VerifyInputError(f"the log's rate must be a positive number, got {log.rate!r}")
    columns = _columns(log)
    for name, arr in columns.items():
        if arr.dtype.kind == "f" and not np.all(np.isfinite(arr)):
            raise VerifyInputError(f"column {name!r} has NaN or Inf; the format allows finite "
                                   "numbers only (mark bad samples with valid = 0)")
    data = _csv_bytes(log, columns) if suffix == ".csv" else _npz_bytes(log, columns)
    write_atomic(path, data)
    return path

