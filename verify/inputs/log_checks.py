"""Checks of an experiment log's trials and values, shared by the CSV and NPZ readers.

The format, its sampling rule and its limits are documented in
:mod:`verify.inputs.experiment_log` (Section 4, "Human Modeling": one trial per
reference, uniformly sampled). Here: the column names, the limits on every value
(:func:`float_problem`, :func:`check_limits`) and :class:`TrialChecker`, which checks each
trial when its last sample has been read and collects the trials into an
:class:`~verify.inputs.experiment.ExperimentLog`.
"""

from __future__ import annotations

import math
import sys

import numpy as np

from verify.errors import VerifyInputError
from verify.inputs.experiment import ExperimentLog, Trial

REQUIRED = ("time", "trial", "e1", "e2", "u1", "u2")
REFERENCE = ("r1", "r2", "r3")
FLAGS = ("valid", "start")
COLUMNS = (*REQUIRED, *REFERENCE, *FLAGS)
#: Relative tolerance on the sampling step (within a trial, between trials, vs the rate).
STEP_TOLERANCE = 1e-6

#: Limits on what a log may hold (verify.inputs.experiment_log, "Limits").
MAX_TIME = 1e9
MIN_STEP = 1e-6
RESOLUTION = 2.0**-30
MAX_VALUE = 1e9
MAX_TRIAL_ID = 10**12
MAX_NPZ_BYTES = 2**30
TINY = sys.float_info.min
INTEGER_COLUMNS = ("trial", *FLAGS)


def fail(where: str, what: str) -> VerifyInputError:
    return VerifyInputError(f"{where}: {what}")


def check_header(path: str, names: list[str], where: str) -> list[str]:
    names = [n.strip() for n in names]
    seen: set[str] = set()
    for name in names:
        if name not in COLUMNS:
            raise fail(where, f"unknown column {short(name)!r}; the columns are "
                       f"{', '.join(COLUMNS)} (see verify.inputs.experiment_log)")
        if name in seen:
            raise fail(where, f"column {name!r} appears twice; keep one")
        seen.add(name)
    missing = [n for n in REQUIRED if n not in seen]
    if missing:
        raise fail(where, f"missing column{'s' if len(missing) > 1 else ''} "
                   f"{', '.join(missing)}; a log needs {', '.join(REQUIRED)}")
    ref = [n for n in REFERENCE if n in seen]
    if ref and len(ref) != 3:
        raise fail(where, f"reference columns {', '.join(ref)} without the others; give all "
                   "of r1, r2, r3 or none")
    return names


def short(text: str, width: int = 40) -> str:
    return text if len(text) <= width else text[: width - 3] + "..."


def limit_of(name: str) -> float:
    return MAX_TIME if name == "time" else MAX_VALUE


def float_problem(name: str, text: str, x: float) -> str | None:
    """Why the value ``x`` (written ``text``) of column ``name`` is refused, if it is."""
    size = abs(x)
    if size != size or size == math.inf:
        return f"{short(text)!r} is beyond the float range; give a finite number"
    if size > limit_of(name):
        unit = "s" if name == "time" else ""
        fix = ("write times relative to the experiment's start" if name == "time" else
               "log e in rad and u_h in rad/s")
        return (f"{short(text)!r} exceeds the limit {limit_of(name):g}{unit} in size for "
                f"column {name!r}; {fix}")
    if 0 < size < TINY:
        return (f"{short(text)!r} is below the normal float range ({TINY:.4g}); write 0 or "
                "a value of at least that size")
    return None


def int_problem(name: str, text: str, k: int) -> str | None:
    if name == "trial" and abs(k) > MAX_TRIAL_ID:
        return (f"trial id {short(text)} exceeds the limit {MAX_TRIAL_ID} in size; number "
                "the trials 0, 1, 2, ...")
    if name in FLAGS and k not in (0, 1):
        return f"{short(text)} is not 0 or 1; write 1 (yes) or 0 (no)"
    return None


def check_limits(name: str, arr: np.ndarray, where: str) -> None:
    """The limits (:mod:`verify.inputs.experiment_log`, "Limits") on a float column, for
    NPZ arrays and for the writer."""
    size = np.abs(arr)
    bad = np.flatnonzero((size > limit_of(name)) | ((size > 0) & (size < TINY)))
    if bad.size:
        x = float(arr[bad[0]])
        raise fail(f"{where}[{bad[0]}]", float_problem(name, repr(x), x) or "")


class TrialChecker:
    """Checks each trial as it is completed and collects them (Section 4: one trial per
    reference). ``kind`` is "line" (CSV) or "entry" (NPZ), for messages."""

    def __init__(self, source: str, kind: str, min_samples: int) -> None:
        self.source, self.kind, self.min_samples = source, kind, min_samples
        self.seen: dict[int, int] = {}
        self.trials: list[Trial] = []
        self.step0: float | None = None
        self.spread0 = 0.0
        #: per trial kept: whether its times were accepted only within their written
        #: precision (then :meth:`log` puts them on the reader's grid)
        self.rounded: list[bool] = []
        self.decimal: list[bool] = []  # times written as decimals (CSV), not binary

    def _at(self, row: int) -> str:
        return f"{self.source}: {self.kind} {row}"

    def finish(self, tid: int, cols: dict[str, np.ndarray], rows: np.ndarray,
               exponent: int | None) -> None:
        """Check one trial (rows ``rows`` of the file) and keep it.

        ``exponent``: the times are written to 10**exponent s (CSV), or None when they
        are binary floats (NPZ).
        """
        where = f"{self._at(rows[0])}, trial {tid}"
        if tid in self.seen:
            raise fail(where, f"trial {tid} appears again after other trials (first at "
                       f"{self.kind} {self.seen[tid]}); keep each trial's rows together")
        self.seen[tid] = int(rows[0])
        n = rows.shape[0]
        if n < self.min_samples:
            raise fail(where, f"trial {tid} has {n} sample{'s' if n != 1 else ''}; at least "
                       f"{self.min_samples} are needed (the model order and the protocol "
                       "need them); drop the trial or record longer")
        for name in FLAGS:
            if name in cols:
                bad = np.flatnonzero((cols[name] != 0) & (cols[name] != 1))
                if bad.size:
                    raise fail(f"{self._at(rows[bad[0]])}, column {name!r}",
                               f"{cols[name][bad[0]]} is not 0 or 1; write 1 (yes) or 0 (no)")
        t = cols["time"]
        d = np.diff(t)
        if np.any(d <= 0):
            k = int(np.flatnonzero(d <= 0)[0]) + 1
            kind = "repeats" if d[k - 1] == 0 else "goes back"
            raise fail(f"{self._at(rows[k])}, column 'time'",
                       f"time {float(t[k])!r} {kind} within trial {tid} (previous "
                       f"{float(t[k - 1])!r}); time must increase strictly within a trial")
        step = float((t[-1] - t[0]) / (n - 1))
        size = float(max(abs(t[0]), abs(t[-1])))
        if step < MIN_STEP or step < RESOLUTION * size:
            raise fail(where, f"trial {tid} has a time step of {step:.3g} s, below "
                       f"{max(MIN_STEP, RESOLUTION * size):.3g} s (the limit is {MIN_STEP:g} "
                       f"s, and {RESOLUTION:.3g} of the largest time so that float times "
                       "resolve the step); check the time unit (seconds) or write times "
                       "relative to the experiment's start")
        written = 0.0 if exponent is None else 10.0 ** exponent
        slack = 8 * np.finfo(float).eps * size
        off = np.abs(d - step) > STEP_TOLERANCE * step
        rounded = bool(np.any(off))
        worst = 0
        if np.any(off) and written > 0:
            residual = np.abs(t - (t[0] + np.arange(n) * step))
            worst = int(np.argmax(residual))
            if residual[worst] <= written + slack:
                off[:] = False  # equal within the written precision (module docstring)
        if np.any(off):
            # point at the first step clearly unlike most (a gap, a jump), else at the time
            # farthest from the grid (written precision), else at the first step off
            typical = float(np.median(d))
            odd = np.abs(d - typical) > max(STEP_TOLERANCE * typical, 4 * written + slack)
            k = (int(np.flatnonzero(odd)[0]) + 1 if np.any(odd) else worst if worst > 0
                 else int(np.flatnonzero(off)[0]) + 1)
            allowance = (f", or every time within {written:g} s (its written precision) of "
                         "the equally spaced grid" if written > 0 else "")
            raise fail(f"{self._at(rows[k])}, column 'time'",
                       f"unequal sampling in trial {tid}: step {d[k - 1]:.9g} s vs the "
                       f"trial's mean step {step:.9g} s (tolerance: relative "
                       f"{STEP_TOLERANCE:g}{allowance}); resample the trial uniformly")
        spread = (written + slack) / (n - 1)  # how far the mean step may be from the grid's
        if self.step0 is None:
            self.step0, self.spread0 = step, spread
        elif abs(step - self.step0) > STEP_TOLERANCE * self.step0:
            rounded = True  # the steps agree only within the written precision (below)
        if self.step0 is not None and (
                abs(step - self.step0) > max(STEP_TOLERANCE * self.step0,
                                             spread + self.spread0)):
            raise fail(where, f"trial {tid} has step {step:.9g} s, the first trial "
                       f"{self.step0:.9g} s (tolerance: relative {STEP_TOLERANCE:g}); "
                       "resample the trials to one rate")
        start = None
        if "start" in cols:
            marks = np.flatnonzero(cols["start"])
            if marks.size > 1:
                raise fail(f"{self._at(rows[marks[1]])}, column 'start'",
                           f"a second start event in trial {tid} (first at time "
                           f"{float(t[marks[0]])!r}); mark one start per trial")
            start = float(t[marks[0]]) if marks.size else None
        reference = (np.stack([cols[r] for r in REFERENCE], axis=1)
                     if "r1" in cols else None)
        valid = cols["valid"].astype(bool) if "valid" in cols else None
        e = np.stack([cols["e1"], cols["e2"]], axis=1)
        u = np.stack([cols["u1"], cols["u2"]], axis=1)
        self.trials.append(Trial(tid, np.array(t, dtype=np.float64), e, u, reference, valid,
                                 start))
        self.rounded.append(rounded)
        self.decimal.append(written > 0)

    def log(self, rate: float | None) -> ExperimentLog:
        """The log of the trials read, at ``rate`` (metadata) or the rate of the step."""
        assert self.step0 is not None
        step, spread = self.step0, self.spread0
        if rate is None:
            rate = simplest_rate(step, spread)
        elif abs(rate * step - 1.0) > max(STEP_TOLERANCE, spread / step):
            raise VerifyInputError(f"{self.source}: the rate metadata says {rate:g} Hz but the "
                                   f"time step is {step:.9g} s ({1 / step:.9g} Hz); fix the "
                                   "rate or the time column")
        # once one trial is read as the grid, every trial written as decimals is (so all
        # trials share the step 1 / rate exactly, not each its own mean step)
        regrid = [r or (any(self.rounded) and d)
                  for r, d in zip(self.rounded, self.decimal, strict=True)]
        return ExperimentLog(tuple(on_grid(tr, float(rate)) if g else tr
                                   for tr, g in zip(self.trials, regrid, strict=True)),
                             float(rate), self.source)


def on_grid(trial: Trial, rate: float) -> Trial:
    """``trial`` with its times on the reader's grid t_0 + k / rate (its start event
    moved with its sample).

    Used for the trials whose written times are equally spaced only within their written
    precision (:mod:`verify.inputs.experiment_log`, "Sampling"): the reader has decided
    that they are samples of that grid, so it hands on the grid, and every later check
    (the estimator's uniform sampling, the protocol's decimation, the start event's
    sample) sees exactly equal steps instead of re-testing the rounded ones.
    """
    n = trial.t.shape[0]
    t = float(trial.t[0]) + np.arange(n) / rate
    start = trial.start
    if start is not None:
        start = float(t[int(np.argmin(np.abs(trial.t - start)))])
    return Trial(trial.trial, t, trial.e, trial.u, trial.reference, trial.valid, start,
                 trial.end)


def simplest_rate(step: float, spread: float) -> float:
    """The rate with the fewest significant digits that the step allows.

    The mean step is known to within ``spread`` (written precision of the times); the
    rate is then known to within the interval of 1/step, and the shortest decimal in it
    is the rate (so times written to 6 decimals at 120 Hz give 120 exactly, and the
    decimation of the protocol finds an integer factor).
    """
    exact = 1.0 / step
    if spread <= 0:
        return exact
    lo, hi = 1.0 / (step + spread), 1.0 / max(step - spread, step / 2)
    for digits in range(1, 18):
        candidate = float(f"{exact:.{digits}g}")
        if lo <= candidate <= hi:
            return candidate
    return exact


__all__ = ["COLUMNS", "FLAGS", "INTEGER_COLUMNS", "MAX_NPZ_BYTES", "MAX_TIME", "MAX_TRIAL_ID",
           "MAX_VALUE", "MIN_STEP", "REFERENCE", "REQUIRED", "RESOLUTION", "STEP_TOLERANCE",
           "TrialChecker", "check_header", "check_limits", "fail", "float_problem",
           "int_problem", "limit_of", "on_grid", "short", "simplest_rate"]
