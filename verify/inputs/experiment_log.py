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
h = (t_last - t_first) / (N - 1) within a relative 1e-6, or, in a CSV file, every time
must lie within its written precision of the equally spaced grid t_first + k h (the
precision is the last decimal place written in the trial's time column: times written
with 6 decimals, 0.008333, 0.016667, ... at 120 Hz, are equally spaced within 1e-6 s, one
unit of the last digit, the most two values rounded from one grid can differ from the
straight line through the trial's ends). Such a trial is then *read as that grid*: its
times become t_first + k / rate (the rate below) and its start event moves to its
sample's grid time, so nothing downstream (the protocol's decimation, the estimator's
check of uniform sampling) re-tests the rounded steps (a trial whose steps agree with
the first trial's only within that precision is put on the grid too). All trials must
have the same step (relative 1e-6, widened by what the written precision leaves unknown
of each mean step). The rate
is the ``rate`` metadata when given (it must agree with the step to the same tolerance),
else the decimal with the fewest significant digits that the step allows (120 for the
6-decimal example). A trial needs at least ``min_samples`` samples (the caller passes
what the model order needs; at least 2); a shorter trial is an error, never dropped.

Limits (each refused with one line, before the value is used)
--------------------------------------------------------------
Times at most ``MAX_TIME`` = 1e9 s in size, a step of at least ``MIN_STEP`` = 1e-6 s
(rate at most 1 MHz) and at least ``RESOLUTION`` = 2^-30 of the largest time (so float
times resolve it); e, u, r values at most ``MAX_VALUE`` = 1e9 in size; no non-zero value
below the normal float range (2.2e-308: subnormal numbers); trial ids at most
``MAX_TRIAL_ID`` = 10^12 in size; a CSV cell at most 40 digits before and after the point
and a 4-digit exponent (integers: 18 digits); an NPZ archive at most ``MAX_NPZ_BYTES``
(1 GiB) uncompressed, judged from the zip directory and each member's .npy header before
any data is decompressed. A CSV file is read in one streaming pass that stops at the first
defect; its memory is that of the numbers read (8 bytes a value), not of the text (a
line is at most ``MAX_LINE`` = 10 000 characters).

CSV (``.csv``)
--------------
UTF-8 text (a byte-order mark is ignored); the first line that is not a comment is the
header (column names separated by commas, in any order, surrounding spaces ignored);
then one row per sample. Lines whose first non-blank character is ``#`` are comments
anywhere in the file; a comment
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
from array import array
from collections.abc import Iterable, Iterator, Sequence
from pathlib import Path

import numpy as np

from verify.artefacts.atomic import write_atomic
from verify.errors import VerifyInputError
from verify.inputs.experiment import ExperimentLog, Trial
from verify.inputs.files import open_regular
from verify.inputs.log_checks import (
    COLUMNS,
    INTEGER_COLUMNS,
    MAX_NPZ_BYTES,
    MAX_TIME,
    MAX_TRIAL_ID,
    MAX_VALUE,
    MIN_STEP,
    REQUIRED,
    STEP_TOLERANCE,
    TrialChecker,
    check_header,
    check_limits,
    fail,
    float_problem,
    int_problem,
    short,
)
from verify.inputs.log_npz import read_npz

#: Limits of the CSV form (module docstring, "Limits").
MAX_CELL = 64
MAX_LINE = 10_000
_ZIP_TIME = (1980, 1, 1, 0, 0, 0)

__all__ = ["COLUMNS", "MAX_CELL", "MAX_LINE", "MAX_NPZ_BYTES", "MAX_TIME", "MAX_TRIAL_ID",
           "MAX_VALUE", "MIN_STEP", "REQUIRED", "STEP_TOLERANCE", "read_csv_lines", "read_log",
           "read_logs", "write_log"]


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
    at least 2). Any defect raises a one-line :class:`VerifyInputError`. A CSV file is
    read in one streaming pass that stops at the first defect; an NPZ archive's member
    sizes are checked from its headers before anything is decompressed.
    """
    path = Path(path)
    suffix = _suffix(path)
    _check_min_samples(min_samples)
    if not path.exists():
        raise VerifyInputError(f"{path}: no such log file; check the path")
    try:  # a read the system refuses (EIO, a file that vanishes) is one line, exit 2
        if suffix == ".csv":
            with open_regular(path) as handle:
                text = io.TextIOWrapper(handle, encoding="utf-8-sig", newline="")
                return read_csv_lines(_bounded_lines(text, str(path)), source=str(path),
                                      min_samples=min_samples)
        with open_regular(path) as handle:
            columns, rate = read_npz(path, handle)
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        raise VerifyInputError(f"{path}: cannot read ({reason})") from None
    builder = TrialChecker(str(path), "entry", min_samples)
    trial = columns["trial"]
    bounds = [0, *(np.flatnonzero(np.diff(trial) != 0) + 1).tolist(), trial.shape[0]]
    for a, b in itertools.pairwise(bounds):
        builder.finish(int(trial[a]), {k: v[a:b] for k, v in columns.items()},
                       np.arange(a, b), None)
    return builder.log(rate)


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


def _bounded_lines(text: io.TextIOBase, source: str) -> Iterator[str]:
    """The lines of a text file, each read with a bound (a file with no line breaks
    cannot fill memory)."""
    number = 0
    while True:
        line = text.readline(MAX_LINE + 1)
        if not line:
            return
        number += 1
        if len(line) > MAX_LINE:
            raise VerifyInputError(f"{source}: line {number} is longer than {MAX_LINE} "
                                   "characters; a log row holds one short number per column")
        yield line


def _check_min_samples(min_samples: object) -> None:
    if not isinstance(min_samples, int) or isinstance(min_samples, bool) or min_samples < 2:
        raise VerifyInputError(f"min_samples must be an integer >= 2, got {min_samples!r}")


# Cells: decimal literals with bounded digits (a longer cell is refused before conversion).
_NUM = r"[+-]?(?:\d{1,40}(?:\.\d{0,40})?|\.\d{1,40})(?:[eE][+-]?\d{1,4})?"
_INT = r"[+-]?\d{1,18}"
_NUMBER = re.compile(_NUM)
_INTEGER = re.compile(_INT)
_LOOSE = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")
_TIME_DIGITS = re.compile(r"[+-]?\d*(?:\.(\d*))?(?:[eE]([+-]?\d+))?")
_NONFINITE = re.compile(r"[+-]?(nan|inf|infinity)", re.IGNORECASE)


def _bad_cell(name: str, cell: str) -> str:
    """The message for a cell that does not match its column's pattern, or is refused."""
    integer = name in INTEGER_COLUMNS
    if not cell:
        return "empty cell; give a value"
    if len(cell) > MAX_CELL:
        return (f"a cell of {len(cell)} characters (limit {MAX_CELL}); write the number "
                "with fewer digits")
    if _NONFINITE.fullmatch(cell):
        return f"NaN or Inf ({cell!r}) is not allowed; give a finite number or mark the sample " \
               "invalid (valid = 0) with any finite value"
    if integer:
        if _INTEGER.fullmatch(cell):
            return int_problem(name, cell, int(cell)) or "unreadable integer"
        if re.fullmatch(r"[+-]?\d+", cell):
            return (f"{short(cell)!r} has more than 18 digits; number the trials 0, 1, "
                    "2, ...")
        if _NUMBER.fullmatch(cell):
            return f"{cell!r} is not an integer; write a whole number without a decimal point"
        return f"{short(cell)!r} is not an integer; write a whole number"
    if _NUMBER.fullmatch(cell):
        return float_problem(name, cell, float(cell)) or "unreadable number"
    if _LOOSE.fullmatch(cell):
        return (f"{short(cell)!r} has more digits than a log allows (40 before and after "
                "the point, 4 in the exponent); write the number with fewer digits")
    return f"{short(cell)!r} is not a number; write a decimal such as -0.25 or 1.5e-3"


def read_csv_lines(lines: Iterable[str], *, source: str, min_samples: int = 2
                   ) -> ExperimentLog:
    """The trials of a CSV log given as lines of text (``read_log`` passes the open file).

    One pass: each row is checked as it is read and each trial when its last row has
    been read, so the first defect ends the reading (nothing after it is consumed), and
    memory holds the trials read so far, not the text. ``source`` names the log in
    messages. A UTF-8 byte-order mark before the first line is ignored.
    """
    _check_min_samples(min_samples)
    builder = TrialChecker(source, "line", min_samples)
    rate: float | None = None
    names: list[str] | None = None
    row_pattern: re.Pattern[str] | None = None
    kinds: list[tuple[int, str]] = []
    current: dict[str, array] = {}
    line_numbers = array("q")
    trial_id: int | None = None
    exponent = 0  # the finest written precision of the trial's times: 10**exponent s
    number = 0
    iterator = iter(lines)
    while True:
        try:
            line = next(iterator)
        except StopIteration:
            break
        except UnicodeDecodeError as exc:
            raise VerifyInputError(f"{source}: not UTF-8 text (byte {exc.start} of the block "
                                   f"after line {number}); save the log as UTF-8 CSV") from None
        number += 1
        if number == 1:
            line = line.removeprefix("\ufeff")
        stripped = line.strip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            key, eq, value = stripped[1:].partition("=")
            if eq and key.strip() == "rate":
                rate = _rate_comment(source, number, value.strip())
            continue
        if '"' in stripped:
            cells = [c.strip() for c in _csv_cells(stripped, source, number)]
            stripped = ",".join(cells)
        if names is None:
            cells = _csv_cells(stripped, source, number)
            names = check_header(source, cells, f"{source}: line {number} (header)")
            row_pattern = re.compile(r"\s*,\s*".join(
                f"({_INT})" if n in INTEGER_COLUMNS else f"({_NUM})" for n in names))
            kinds = list(enumerate(names))
            current = {n: array("q" if n in INTEGER_COLUMNS else "d") for n in names}
            continue
        assert row_pattern is not None
        match = row_pattern.fullmatch(stripped)
        if match is None:
            _diagnose(source, number, names, stripped)
        cells = match.groups()
        tid = int(cells[names.index("trial")])
        if tid != trial_id:
            if trial_id is not None:
                builder.finish(trial_id, _arrays(current), np.frombuffer(line_numbers,
                                                                         np.int64), exponent)
                current = {n: array(a.typecode) for n, a in current.items()}
                line_numbers = array("q")
            trial_id, exponent = tid, 0
        for j, name in kinds:
            text = cells[j]
            if name in INTEGER_COLUMNS:
                k = int(text)
                problem = int_problem(name, text, k)
                if problem:
                    raise fail(f"{source}: line {number}, column {name!r}", problem)
                current[name].append(k)
            else:
                x = float(text)
                problem = float_problem(name, text, x)
                if problem:
                    raise fail(f"{source}: line {number}, column {name!r}", problem)
                current[name].append(x)
                if name == "time":
                    digits = _TIME_DIGITS.fullmatch(text)
                    written = int(digits.group(2) or 0) - len(digits.group(1) or "")
                    exponent = min(exponent, written)
        line_numbers.append(number)
    if names is None:
        raise VerifyInputError(f"{source}: empty log (no header line); the first line must "
                               f"name the columns, e.g. {','.join(REQUIRED)}")
    if trial_id is None:
        raise VerifyInputError(f"{source}: the log has a header but no samples; add data rows")
    builder.finish(trial_id, _arrays(current), np.frombuffer(line_numbers, np.int64), exponent)
    return builder.log(rate)


def _csv_cells(text: str, source: str, number: int) -> list[str]:
    """The cells of one CSV line (quotes as CSV allows); a malformed line is one line."""
    try:
        return next(csv.reader([text]))
    except csv.Error as exc:
        raise fail(f"{source}: line {number}", f"not a CSV row ({exc}); write numbers "
                   "separated by commas, one row per line") from None


def _arrays(current: dict[str, array]) -> dict[str, np.ndarray]:
    return {n: np.frombuffer(a, np.int64 if a.typecode == "q" else np.float64)
            for n, a in current.items()}


def _rate_comment(source: str, number: int, value: str) -> float:
    rate = float(value) if _NUMBER.fullmatch(value) else math.nan
    if not (0 < rate <= 1 / MIN_STEP):
        raise fail(f"{source}: line {number}", f"rate {short(value)!r} is not a positive "
                   f"number of at most {1 / MIN_STEP:g} Hz; write e.g. '# rate = 120'")
    return rate


def _diagnose(source: str, number: int, names: list[str], stripped: str) -> None:
    """Raise the error of a row that does not match the header's pattern."""
    cells = _csv_cells(stripped, source, number) if stripped else []
    if len(cells) != len(names):
        raise fail(f"{source}: line {number}", f"{len(cells)} cells, the header has "
                   f"{len(names)}; give one value per column")
    for name, cell in zip(names, cells, strict=True):
        cell = cell.strip()
        pattern = _INTEGER if name in INTEGER_COLUMNS else _NUMBER
        if not pattern.fullmatch(cell):
            raise fail(f"{source}: line {number}, column {name!r}", _bad_cell(name, cell))
    raise fail(f"{source}: line {number}", "unreadable row; give one number per column")


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
    fixed timestamp (equal logs, equal bytes). A log the reader would refuse (NaN, values
    beyond the limits of the module docstring) is refused here, before anything is
    written. Returns the path written.
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
        if arr.dtype.kind == "f":  # never write a log the reader refuses
            check_limits(name, arr, f"column {name!r}")
        elif name == "trial" and arr.size and int(np.abs(arr).max()) > MAX_TRIAL_ID:
            raise VerifyInputError(f"column 'trial': an id exceeds the limit {MAX_TRIAL_ID}")
    data = _csv_bytes(log, columns) if suffix == ".csv" else _npz_bytes(log, columns)
    write_atomic(path, data)
    return path

