"""Checks of the trials an estimator or a quality test receives, and their per-output view.

For the structures with constant off-diagonal elements (Section 4, "Human Modeling") each
output u_i of H(s) is a separate two-input problem,
u_i = B_i(s)/A_i(s) e_i + c_ij e_j + noise (i != j),
so the data are handed to the estimators one output at a time (:class:`OutputData`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from verify.errors import VerifyInputError
from verify.identify.estimate.structure import Structure
from verify.inputs.experiment import Trial

__all__ = ["MAX_CARRY_GAP", "MID_RESPONSE", "START_WINDOW", "OutputData", "check_trials",
           "dead_time_gaps", "fresh_starts", "mid_response", "output_data", "rest_level"]


@dataclass(frozen=True)
class OutputData:
    """The data of output i: per trial the own input e_i, the other input e_j and u_i.

    ``initial`` says how the estimators treat the start of each trial: "estimate" (the
    initial state is estimated with the other parameters), "zero" (the model starts
    at rest) or "carry" (the model starts where it left the previous trial, coasting
    with zero input over the dead time between them, ``gaps``); ``skip`` samples at the
    start of each trial are left out of the criterion (the model is still simulated
    over them). ``gaps[k]`` is the time in seconds from the last sample of trial k - 1
    to the first of trial k, or None when trial k starts from rest
    (:func:`dead_time_gaps`). ``ahead[k]`` is how long after its last sample trial k's
    input still acts (one step unless the trial says otherwise, :attr:`Trial.end`).
    ``free[k]`` (with "carry") says that trial k's initial state is estimated instead:
    it starts neither from a carried state nor visibly at rest (:func:`mid_response`).
    ``offset`` adds a constant to the output, estimated with the other parameters (an
    uncalibrated stick: the logged u_i is off by a constant; a nuisance parameter, not
    part of H(s)).
    """

    output: int
    own: tuple[np.ndarray, ...]
    other: tuple[np.ndarray, ...]
    y: tuple[np.ndarray, ...]
    h: float
    initial: str = "estimate"
    skip: int = 0
    gaps: tuple[float | None, ...] = ()
    ahead: tuple[float, ...] = ()
    free: tuple[bool, ...] = ()
    offset: bool = False

    @property
    def samples(self) -> int:
        return sum(len(y) for y in self.y)

    def shared(self, zeros: int) -> int:
        """Columns of the regressors shared by all trials: the numerator's zeros + 1, the
        coupling, and the offset when there is one (the trials' initial states follow)."""
        return zeros + 2 + int(self.offset)

    def estimated(self, k: int) -> bool:
        """True if trial k's initial state is a fitted parameter."""
        return self.initial == "estimate" or (
            self.initial == "carry" and k < len(self.free) and self.free[k])


def check_trials(trials: Sequence[Trial], structure: Structure, *, what: str = "estimation"
                 ) -> float:
    """The common sampling period of ``trials``, after checking them for ``structure``.

    One-line :class:`VerifyInputError` for: no trials, arrays of the wrong shape,
    non-finite samples, a non-uniform or unequal sampling step, a trial too short to
    hold the structure's transient (more than 2 (poles + 1) samples are needed), or too
    few samples in all for the parameters and the per-trial initial states.
    """
    if not isinstance(structure, Structure):
        raise VerifyInputError(f"{what} needs a Structure (Structure.paper(), "
                               f"Structure.poles_zeros(p, z)), got {structure!r}")
    if not structure.diagonal_with_constant_coupling:
        raise VerifyInputError(
            f"{what} does not yet support the state-space structure order:{structure.states}; "
            f"use --structure paper or poles:zeros (e.g. 2:1)")
    trials = tuple(trials)
    if not trials:
        raise VerifyInputError(f"{what} needs at least one trial, got none")
    h = None
    for tr in trials:
        if not isinstance(tr, Trial):
            raise VerifyInputError(f"{what} needs Trial records, got {type(tr).__name__}")
        t = np.asarray(tr.t, float)
        e = np.asarray(tr.e, float)
        u = np.asarray(tr.u, float)
        label = f"trial {tr.trial}"
        if t.ndim != 1 or e.shape != (t.shape[0], 2) or u.shape != (t.shape[0], 2):
            raise VerifyInputError(f"{label}: t must be (N,), e and u (N, 2); got t {t.shape}, "
                                   f"e {e.shape}, u {u.shape}")
        if tr.valid is not None and not np.all(np.asarray(tr.valid, bool)):
            raise VerifyInputError(f"{label} has samples marked invalid; remove them with "
                                   "the protocol's preprocessing "
                                   "(verify.identify.data.protocol) first")
        need = 2 * (structure.poles + 1) + 1
        if t.shape[0] < need:
            raise VerifyInputError(f"{label} has {t.shape[0]} samples; a {structure.poles}-pole "
                                   f"model needs at least {need} per trial")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(e)) and np.all(np.isfinite(u))):
            raise VerifyInputError(f"{label} has non-finite samples (NaN or Inf)")
        dt = np.diff(t)
        step = float(dt.mean())
        if not (step > 0 and np.all(np.abs(dt - step) <= 1e-6 * step)):
            raise VerifyInputError(f"{label} is not uniformly sampled (steps from {dt.min():.6g}"
                                   f" to {dt.max():.6g} s)")
        if h is None:
            h = step
        elif abs(step - h) > 1e-6 * h:
            raise VerifyInputError(f"{label} has step {step:.6g} s, the first trial {h:.6g} s; "
                                   f"all trials need one sampling rate")
    per_output = (structure.zeros + 1) + structure.poles + 1 + len(trials) * structure.poles
    total = sum(np.asarray(tr.t).shape[0] for tr in trials)
    if total < 2 * per_output:
        raise VerifyInputError(f"{len(trials)} trials with {total} samples in all are too few: "
                               f"{per_output} parameters per output (with the initial states) "
                               f"need at least {2 * per_output}")
    return float(h)


#: Longest gap (s) between trials over which the operator's state is carried: the
#: longest dead time the protocol removes after a reference change (the threshold rule
#: stops at 2 s; logged start events came 0.2-0.5 s after it in the simulated
#: experiments), with a margin of 0.5 s. A longer gap is a pause: what the operator did
#: in it is not in the log.
MAX_CARRY_GAP = 2.5
#: Mid-response start: the mean of u over the first ``START_WINDOW`` seconds of a trial
#: reaches ``MID_RESPONSE`` of the largest such mean over the trial (:func:`mid_response`).
START_WINDOW = 0.25
MID_RESPONSE = 0.5


def rest_level(trials: Sequence[Trial]) -> np.ndarray:
    """The logged u at rest, per component: the median over ``trials`` of u averaged over
    each trial's last ``START_WINDOW`` seconds.

    A trial of the loop ends settled (the leader has reached the reference and the
    operator's command has decayed), so its last samples are the stick at rest: 0 for a
    calibrated stick, the stick's offset otherwise (an offset must not make a trial that
    begins at rest look mid-response). The median over all samples is not that level:
    the responses take a large share of a 15 s trial.
    """
    ends = []
    for tr in trials:
        u = np.asarray(tr.u, float)
        t = np.asarray(tr.t, float)
        if u.shape[0] < 2:
            continue
        width = min(max(1, round(START_WINDOW / float(t[1] - t[0]))), u.shape[0])
        ends.append(u[-width:].mean(axis=0))
    return np.median(np.array(ends), axis=0) if ends else np.zeros(2)


def mid_response(trial: Trial, rest: np.ndarray | None = None) -> float:
    """How far into a response trial ``trial`` begins: the size of u - ``rest`` (the rest
    level, :func:`rest_level`; 0 when not given) averaged over its first ``START_WINDOW``
    seconds relative to the largest such average over the trial (0: at rest, 1: at the
    peak).

    A trial of the protocol begins at the operator's start event, before the response
    (or continues a previous trial whose state is carried); one that begins with u
    already at ``MID_RESPONSE`` (30 %) of its largest moving average was logged from the
    middle of a response, and starting its model from rest (or from a state coasted
    over a pause) would explain that response with the wrong parameters.
    """
    u = np.asarray(trial.u, float)
    t = np.asarray(trial.t, float)
    if u.shape[0] < 2:
        return 0.0
    if rest is not None:
        u = u - np.asarray(rest, float)
    h = float(t[1] - t[0])
    width = min(max(1, round(START_WINDOW / h)), u.shape[0])
    csum = np.cumsum(np.vstack([np.zeros((1, u.shape[1])), u]), axis=0)
    means = np.linalg.norm((csum[width:] - csum[:-width]) / width, axis=1)
    peak = float(np.max(means))
    return float(means[0] / peak) if peak > 0 else 0.0


def fresh_starts(trials: Sequence[Trial]) -> tuple[bool, ...]:
    """Per trial, True if its initial state must be estimated: it is not carried
    (:func:`dead_time_gaps` gives None: the first trial, a segment after invalid samples,
    a trial after a pause) and it begins mid-response (:func:`mid_response`, measured
    from the log's rest level, :func:`rest_level`)."""
    gaps = dead_time_gaps(trials)
    rest = rest_level(trials)
    return tuple(g is None and mid_response(tr, rest) >= MID_RESPONSE
                 for tr, g in zip(trials, gaps, strict=True))


def dead_time_gaps(trials: Sequence[Trial]) -> tuple[float | None, ...]:
    """Per trial, the dead time (s) since the previous trial's last sample, or None.

    In the protocol of Section 4 the trials of a log follow each other: after a trial's
    last sample the reference changes, the operator does not react until the start
    event (the dead time the protocol removes), and the next trial begins. A trial
    continues the previous one when its trial id differs from the previous one's (the
    segments of one trial split at invalid samples do not: what the operator did
    during those samples is unknown) and its first sample comes later than the
    previous trial's last one (logs whose trials restart the clock do not), the log did
    not pause before it (:attr:`Trial.resumed`, set by the protocol's preparation when
    the raw trials are not back to back: a lab that pauses usually resets the loop to
    rest), and by at most ``MAX_CARRY_GAP`` (for trials that did not come through the
    protocol: a longer gap than any dead time is a pause). Otherwise, and for the first trial,
    None: the trial starts from rest, or from an estimated state when it begins
    mid-response (:func:`fresh_starts`).
    """
    out: list[float | None] = [None] * len(trials)
    for k in range(1, len(trials)):
        prev, cur = trials[k - 1], trials[k]
        gap = float(np.asarray(cur.t, float)[0] - np.asarray(prev.t, float)[-1])
        if (cur.trial != prev.trial and not getattr(cur, "resumed", False)
                and np.isfinite(gap) and 0 < gap <= MAX_CARRY_GAP):
            out[k] = gap
    return tuple(out)


def output_data(trials: Sequence[Trial], i: int, h: float, *, initial: str = "estimate",
                skip: int = 0, offset: bool = False) -> OutputData:
    """The view of output ``i`` (0 or 1) of checked trials (``offset``: a constant on the
    output is estimated too, :class:`OutputData`)."""
    j = 1 - i
    return OutputData(
        i,
        tuple(np.asarray(tr.e, float)[:, i] for tr in trials),
        tuple(np.asarray(tr.e, float)[:, j] for tr in trials),
        tuple(np.asarray(tr.u, float)[:, i] for tr in trials),
        h,
        initial,
        skip,
        dead_time_gaps(trials),
        tuple(h if tr.end is None else max(float(tr.end - np.asarray(tr.t, float)[-1]), 0.0)
              for tr in trials),
        fresh_starts(trials),
        bool(offset),
    )
