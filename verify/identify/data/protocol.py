"""The data preparation of Section 4 ("Human Modeling"): dead time, decimation, split.

Before estimating H(s) the paper (i) removes, after each reference change, the data up
to the moment the operator pressed the start button (a cognitive dead time specific to
the experiment), (ii) decimates the 120 Hz data, and (iii) uses the first 6 trials for
identification and the last 6 for validation. :func:`prepare` does the same:

1. **Dead time.** Each trial begins at a reference change. ``dead_time="event"`` drops
   the samples before the trial's logged start event; ``"threshold"`` (for logs without
   events) drops the samples before the first time the operator's output visibly moves:
   with u smoothed by a trailing moving average over ``SMOOTHING`` seconds, the start is
   the first sample where |u_s(t) - u_s(t_0)| reaches ``THRESHOLD`` (30 %) of its largest
   value over the trial, and at most ``MAX_DEAD_TIME`` seconds after the change. The rule
   errs late rather than early: a late start only drops informative samples, while an
   early one would keep samples the operator did not yet respond to, which fit no model.
   The average is trailing (samples up to t only). On simulated experiments with the
   default noises it starts 0.14-0.41 s after the true start event, never before it in
   30 trials; 0.1 s and 20 % started early in a third of them.
   ``"auto"`` (the default) uses the events when every trial has one, else the threshold.
2. **Invalid samples.** Samples with valid = 0 are dropped and the trial is split at them
   into segments (each a :class:`Trial` with the trial's id); a segment too short for
   the filter and the estimator is dropped, with a note.
3. **Decimation.** The same zero-phase anti-aliasing low-pass is applied to e and u,
   then every q-th sample is kept, with q = rate_in / rate_out an integer. The filter
   (:func:`anti_aliasing_filter`) is a Chebyshev type II low-pass of order 8 whose stop
   band (60 dB, 120 dB after the forward and backward pass of
   :func:`scipy.signal.sosfiltfilt`) begins at the new Nyquist frequency. The ends are
   padded by odd reflection over 3 (order + 1) output samples; content above the new
   Nyquist frequency at a segment's last sample leaves an edge transient that fades
   within about 1 s (it is the same for e and u, which see the same filter). The default output rate
   ``DEFAULT_RATE`` = 20 Hz keeps the new Nyquist frequency (10 Hz, 63 rad/s) far above
   the bandwidth of a human operator in this task (the paper's identified models and the
   shipped ones have their poles near 1-2 rad/s, a human tracking loop rarely exceeds a
   few Hz) while cutting the sample count six-fold, which keeps the estimation well
   conditioned (poles near 1 rad/s sit at z ~ 0.95 rather than 0.99). The paper says
   only that the data were decimated "to 10 rad/s"; pass ``rate`` to follow another
   reading of it. With ``rate="auto"`` (the command's default) a log is kept at its own rate
   up to ``AUTO_MAX_RATE`` and decimated to at most that rate above it (only to bound the
   computation): the output-error criterion needs no low-pass to cope with measurement
   noise, and decimation costs accuracy. Measured on 12 simulated closed-loop
   experiments of a known operator (``benchmarks/bench_identify_methods.py``): at the
   logged 120 Hz every parameter is as accurate as a plain output-error fit, at 20 Hz
   c12 is 1.4x and at 40 Hz 1.2x less accurate; noise-free logs lose a factor 25 at
   20 Hz (1e-4 against 4e-6 relative), to the filter's edge transients. The fit at
   120 Hz is also faster (7 s against 12 s for a shipped log). ``rate="off"`` never
   decimates.
4. **Per-trial clocks.** A log whose time restarts in each trial (a common way to log
   trials) is put on one clock first (:func:`one_clock`): each trial whose first sample
   is not later than the previous trial's last one is shifted to begin one sampling step
   after it, as in the protocol, where each trial begins at the reference change that
   ends the previous one. The estimator and the fits then carry the operator's state
   across the removed dead time (:func:`verify.identify.estimate.trial_data.dead_time_gaps`)
   instead of starting such trials from rest; a note says so. A trial whose first sample
   comes more than 1.5 steps after the previous trial's last one follows a *pause* in
   the log (:func:`paused_trials`: a lab that stops between trials, often resetting the
   loop); it is marked :attr:`Trial.resumed`, and its state is not carried over the
   pause (a note names those trials).
5. **Split.** The first ``split[0]`` trials (in log order) identify, the next ``split[1]``
   validate (Section 4: 6 and 6).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, replace

import numpy as np
from scipy import signal

from verify.errors import VerifyInputError
from verify.inputs.experiment import ExperimentLog, Trial
from verify.inputs.numbers import positive_real

DEFAULT_RATE = 20.0  # Hz, after decimation (see the module docstring)
DEFAULT_SPLIT = (6, 6)  # trials for identification and validation (Section 4)
SMOOTHING = 0.25  # s, moving average of u in the threshold rule
THRESHOLD = 0.3  # fraction of the trial's largest change of the smoothed u
MAX_DEAD_TIME = 2.0  # s, the threshold rule never removes more
FILTER_ORDER = 8  # the Chebyshev type II anti-aliasing filter
STOPBAND_DB = 60.0  # its attenuation above the new Nyquist frequency (doubled by filtfilt)
#: Fewest decimated samples a segment needs for the model (``prepare``'s default).
MIN_MODEL_SAMPLES = 8
#: Fewest input samples a segment needs for the forward-backward filter (its padding).
MIN_FILTER_SAMPLES = 3 * (FILTER_ORDER + 1) + 1
DEAD_TIME_RULES = ("auto", "event", "threshold")
#: Highest rate ``rate="auto"`` keeps; a faster log is decimated to at most this rate.
AUTO_MAX_RATE = 250.0


@dataclass(frozen=True)
class Prepared:
    """Trials ready for estimation, at ``rate`` Hz, with notes on what was removed.

    ``identification`` and ``validation`` hold segments (a trial split at invalid samples
    gives several segments with the same id); ``dead_time`` the seconds removed at the
    start of each trial, in log order; ``decimation`` the factor q; ``rule`` the
    dead-time rule used ("event" or "threshold").
    """

    identification: tuple[Trial, ...]
    validation: tuple[Trial, ...]
    rate: float
    notes: tuple[str, ...]
    dead_time: tuple[float, ...] = ()
    decimation: int = 1
    rule: str = "event"


def one_clock(trials: tuple[Trial, ...]) -> tuple[tuple[Trial, ...], int]:
    """The trials on one clock (module docstring, step 4), and how many were shifted.

    A trial is shifted when its id differs from the previous trial's and its first
    sample is not after the previous trial's last one; its start event moves with it.
    """
    out: list[Trial] = []
    shifted = 0
    for tr in trials:
        if out and tr.trial != out[-1].trial and tr.t[0] <= out[-1].t[-1]:
            offset = float(out[-1].t[-1] + out[-1].step - tr.t[0])
            tr = replace(tr, t=tr.t + offset,
                         start=None if tr.start is None else tr.start + offset)
            shifted += 1
        out.append(tr)
    return tuple(out), shifted


def paused_trials(trials: tuple[Trial, ...]) -> tuple[bool, ...]:
    """Per trial (on one clock), True if the log pauses before it: its first sample comes
    more than 1.5 steps after the previous trial's last one (module docstring, step 4).
    A log of the protocol has its trials back to back (the next trial begins at the
    reference change one step after the last sample); a gap is a pause in logging (a
    reset, a break), over which nothing about the operator's state is known."""
    out = [False]
    for prev, tr in itertools.pairwise(trials):
        gap = float(tr.t[0] - prev.t[-1])
        out.append(tr.trial != prev.trial and gap > 1.5 * prev.step)
    return tuple(out[: len(trials)])


def chosen_rate(log: ExperimentLog, target: float = AUTO_MAX_RATE) -> tuple[float, str]:
    """The rate ``rate="auto"`` uses, and why (module docstring, step 3): the log's own
    rate up to ``target``; above it the highest log.rate / q <= ``target``, q an integer."""
    q = max(1, int(np.floor(log.rate / target + 1e-9)))
    if q == 1:
        return float(log.rate), (f"kept at the logged {log.rate:g} Hz (the output-error fit "
                                 "needs no decimation, and decimation costs accuracy)")
    return log.rate / q, (f"decimated to {log.rate / q:g} Hz (logs above {target:g} Hz are "
                          "decimated only to bound the computation)")


def decimation_of(log: ExperimentLog, rate: float | str | None) -> tuple[int, str]:
    """The decimation factor q for ``rate`` (Hz, "auto", "off" or None for
    ``DEFAULT_RATE``; module docstring, step 3) and why it was chosen ("" when given)."""
    why = ""
    if rate == "auto":
        rate, why = chosen_rate(log)
    elif rate == "off":
        rate, why = log.rate, "--rate off"
    return decimation_factor(log.rate, DEFAULT_RATE if rate is None else rate), why


def decimation_factor(rate_in: float, rate_out: float) -> int:
    """q = rate_in / rate_out, refused unless it is an integer (relative 1e-9)."""
    rate_out = positive_real(rate_out, "the decimated rate (--rate)")
    q = rate_in / rate_out
    if q < 1 - 1e-9:
        raise VerifyInputError(f"--rate {rate_out:g} Hz is above the log's {rate_in:g} Hz; "
                               "decimation only lowers the rate")
    if abs(q - round(q)) > 1e-9 * q:
        divisors = [rate_in / k for k in range(1, 13) if (rate_in / k) >= 1]
        raise VerifyInputError(
            f"--rate {rate_out:g} Hz: {rate_in:g} Hz / {rate_out:g} Hz = {q:.6g} is not an "
            f"integer; choose a rate that divides {rate_in:g} Hz, e.g. "
            + ", ".join(f"{d:g}" for d in divisors[1:6]))
    return round(q)


def threshold_start(trial: Trial) -> int:
    """Index of the first sample after the dead time by the threshold rule (module doc).

    The moving average is trailing (it uses samples up to t only), so the rule cannot see
    the response before it happens.
    """
    step = trial.step
    n = trial.t.shape[0]
    width = min(max(1, round(SMOOTHING / step)), n)
    csum = np.cumsum(np.vstack([np.zeros((1, 2)), trial.u]), axis=0)
    smooth = (csum[width:] - csum[:-width]) / width  # smooth[i] = mean of u[i .. i + width - 1]
    change = np.zeros(n)
    change[width - 1:] = np.linalg.norm(smooth - smooth[0], axis=1)
    limit = min(round(MAX_DEAD_TIME / step), n - 1)
    peak = float(np.max(change))
    if peak == 0.0:
        return limit
    hit = np.flatnonzero(change >= THRESHOLD * peak)
    return int(min(hit[0], limit))


def _segments(trial: Trial, first: int) -> list[tuple[int, int]]:
    """[a, b) runs of valid samples from index ``first`` on."""
    n = trial.t.shape[0]
    ok = np.ones(n, bool) if trial.valid is None else np.asarray(trial.valid, bool).copy()
    ok[:first] = False
    edges = np.diff(np.concatenate([[0], ok.astype(np.int8), [0]]))
    return list(zip(np.flatnonzero(edges == 1).tolist(), np.flatnonzero(edges == -1).tolist(),
                    strict=True))


def _decimate(trial: Trial, a: int, b: int, q: int, resumed: bool = False) -> Trial:
    t = trial.t[a:b]
    e, u = trial.e[a:b], trial.u[a:b]
    ref = None if trial.reference is None else trial.reference[a:b]
    if q > 1:
        sos = anti_aliasing_filter(q)
        pad = min(t.shape[0] - 1, 3 * q * (FILTER_ORDER + 1))
        e = signal.sosfiltfilt(sos, e, axis=0, padlen=pad)[::q]
        u = signal.sosfiltfilt(sos, u, axis=0, padlen=pad)[::q]
        t = t[::q]
        ref = None if ref is None else ref[::q]
    return Trial(trial.trial, t.copy(), np.ascontiguousarray(e), np.ascontiguousarray(u),
                 reference=None if ref is None else ref.copy(),
                 end=float(trial.t[b - 1] + trial.step), resumed=resumed)


def anti_aliasing_filter(q: int) -> np.ndarray:
    """Second-order sections of the low-pass used before keeping every q-th sample.

    Chebyshev type II of order ``FILTER_ORDER``, stop band from the new Nyquist frequency
    (1/q of the old one) on with ``STOPBAND_DB`` attenuation; its pass band is monotone
    (flat within 4e-5 up to 0.4 of the new Nyquist frequency, run forwards and backwards),
    unlike a Chebyshev type I whose ripple scales slow signals by up to 1 %.
    """
    return signal.cheby2(FILTER_ORDER, STOPBAND_DB, 1.0 / q, output="sos")


def _split(split, count: int) -> tuple[int, int]:
    try:
        a, b = (int(v) for v in split)
        ok = all(float(v) == int(v) for v in split) and not any(isinstance(v, bool)
                                                                 for v in split)
    except (TypeError, ValueError):
        ok = False
    if not ok:
        raise VerifyInputError(f"--split must be two whole numbers A:B (trials for "
                               f"identification and validation), got {split!r}; e.g. --split 6:6")
    if a < 1 or b < 0 or a + b > count:
        raise VerifyInputError(
            f"--split {a}:{b} needs {a + b} trials (at least 1 for identification) but the "
            f"log has {count}; e.g. --split {max(1, count - count // 2)}:{count // 2}")
    return a, b


def prepare(
    log: ExperimentLog,
    *,
    rate: float | None = None,
    split: tuple[int, int] = DEFAULT_SPLIT,
    dead_time: str = "auto",
    min_samples: int = MIN_MODEL_SAMPLES,
) -> Prepared:
    """The protocol of Section 4 applied to ``log`` (steps in the module docstring).

    Parameters
    ----------
    log
        The experiment's trials, in order, at ``log.rate`` Hz.
    rate
        Target rate in Hz after decimation (``DEFAULT_RATE`` when None), ``log.rate / rate``
        an integer; "auto" (:func:`chosen_rate`) or "off" (no decimation).
    split
        (identification trials, validation trials), taken in log order.
    dead_time
        "auto", "event" or "threshold" (module docstring).
    min_samples
        Segments with fewer samples after decimation are dropped (with a note); the
        caller passes what the model order needs.

    Returns
    -------
    Prepared
    """
    if dead_time not in DEAD_TIME_RULES:
        raise VerifyInputError(f"dead-time rule {dead_time!r} is unknown; choose one of "
                               f"{', '.join(DEAD_TIME_RULES)}")
    if not (isinstance(min_samples, int) and min_samples >= 2):
        raise VerifyInputError(f"min_samples must be an integer >= 2, got {min_samples!r}")
    trials, shifted = one_clock(log.trials)
    a, b = _split(split, len(trials))
    q, why = decimation_of(log, rate)
    rate_out = log.rate / q
    with_events = [tr.start is not None for tr in trials]
    rule = dead_time
    if rule == "auto":
        rule = "event" if all(with_events) else "threshold"
    elif rule == "event" and not all(with_events):
        missing = next(tr.trial for tr, has in zip(trials, with_events, strict=True) if not has)
        raise VerifyInputError(f"dead-time rule 'event': trial {missing} has no start event; "
                               "log the start column or use the threshold rule")
    notes = [f"dead time removed by the {rule} rule",
             f"decimated {log.rate:g} Hz -> {rate_out:g} Hz (q = {q}, zero-phase Chebyshev "
             f"type II order {FILTER_ORDER}, stop band from {rate_out / 2:g} Hz)" if q > 1
             else f"not decimated ({log.rate:g} Hz)"]
    if why:
        notes.append(f"rate: {why}")
    if shifted:
        notes.append(f"the log's clock restarts in {shifted} trial(s): trials taken as logged "
                     "back to back (each begins one step after the previous one ends, at the "
                     "reference change), so the operator's state is carried over the dead time")
    if a + b < len(trials):
        notes.append(f"trials {', '.join(str(tr.trial) for tr in trials[a + b:])} unused "
                     f"(split {a}:{b} of {len(trials)})")
    dead: list[float] = []
    parts: list[list[Trial]] = [[], []]
    paused = paused_trials(trials)
    if any(paused):
        after = ", ".join(str(tr.trial) for tr, p in zip(trials, paused, strict=True) if p)
        notes.append(f"the log pauses before trial(s) {after} (more than one step after "
                     "the previous trial's last sample): the operator's state is not "
                     "carried over a pause")
    for index, tr in enumerate(trials[: a + b]):
        if rule == "event":
            first = int(np.searchsorted(tr.t, tr.start - 1e-9 * tr.step))
        else:
            first = threshold_start(tr)
        dead.append(float(first * tr.step))
        runs = _segments(tr, first)
        if tr.valid is not None and len(runs) > 1:
            notes.append(f"trial {tr.trial}: split into {len(runs)} segments at invalid samples")
        for s, e in runs:
            if e - s < MIN_FILTER_SAMPLES or (e - s + q - 1) // q < min_samples:
                notes.append(f"trial {tr.trial}: segment of {e - s} samples at t = "
                             f"{tr.t[s]:.4g} s dropped (shorter than the filter or the model "
                             "needs)")
                continue
            parts[0 if index < a else 1].append(_decimate(tr, s, e, q, paused[index]))
    if not parts[0]:
        raise VerifyInputError("no identification data left after the dead time, invalid "
                               "samples and short segments were removed; check the log's valid "
                               "and start columns")
    return Prepared(tuple(parts[0]), tuple(parts[1]), rate_out, tuple(notes), tuple(dead), q,
                    rule)
