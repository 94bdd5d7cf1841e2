"""Simulated model output on measured inputs, with the trials' initial states.

For one output of the constant-coupling structures (Section 4, "Human Modeling"),

    yhat_i = B_i(s)/A_i(s) e_i + c_ij e_j [+ o_i] + (a free response of A_i per trial),

simulated from the measured inputs (first-order hold, :mod:`verify.identify.estimate.ct_filters`).
o_i an optional constant offset of the logged output (``OutputData.offset``: an
uncalibrated stick). For a fixed denominator A_i the output is linear in the numerator,
the coupling, the offset and the initial state of each trial, so those are solved by
linear least squares and only A_i is searched (variable projection, Golub & Pereyra,
SIAM J. Numer. Anal. 10(2), 1973).

How a trial starts (``OutputData.initial``): "estimate" fits each trial's free response
(n numbers per trial; a re-initialised figure that absorbs transients, never what the
command reports or decides with); "carry" starts each trial in the state the model ended
the previous trial in, carried with the last sample's input (linearly extrapolated) until
the trial's end (:attr:`verify.inputs.experiment.Trial.end`) and then coasted with
zero input over the rest of the dead time the protocol removed
(:func:`verify.identify.estimate.trial_data.dead_time_gaps`), which is what the estimator and
Section 4's fits use by default (:mod:`verify.identify.estimate.estimation`,
:func:`verify.identify.quality.fits.honest_fits`); with "carry", a trial that is not
carried (the first, or one after a pause) and begins mid-response has its initial state
fitted as with "estimate" (``OutputData.free``,
:func:`verify.identify.estimate.trial_data.fresh_starts`); "zero" starts every trial at
rest.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import numpy as np
from scipy import signal

from verify.identify.estimate.ct_filters import Filter
from verify.identify.estimate.structure import Structure
from verify.identify.estimate.trial_data import OutputData, check_trials, output_data
from verify.inputs.experiment import Trial

#: How a trial's initial state is treated (module docstring).
INITIAL_STATES = ("carry", "estimate", "zero")

__all__ = ["INITIAL_STATES", "design", "element_parameters", "fit_linear", "lengths", "predict",
           "predict_output", "used", "whiten"]


def design(a: np.ndarray, data: OutputData, zeros: int) -> np.ndarray:
    """Regressors of output data for denominator ``a``, shape (N, p + T n) with
    p = ``data.shared(zeros)``.

    Columns: s^k/A e_i for k = zeros..0, then e_j, then a column of ones when
    ``data.offset``, then per trial the n free responses of A (zero outside that trial).
    With ``data.initial == "carry"`` the filter of a trial
    with a dead-time gap starts from the state the previous trial ended in, coasted over
    the gap (:class:`verify.identify.estimate.trial_data.OutputData`); otherwise from rest.
    """
    a = np.asarray(a, float)
    n = len(a)
    filt = Filter(a, data.h)
    T = len(data.y)
    total = data.samples
    p = data.shared(zeros)
    X = np.zeros((total, p + T * n))
    if data.offset:
        X[:, zeros + 2] = 1.0
    row = 0
    end = None
    lead = data.h
    for k, (own, other) in enumerate(zip(data.own, data.other, strict=True)):
        N = len(own)
        with np.errstate(over="ignore", invalid="ignore"):  # unstable candidates overflow
            gap = data.gaps[k] if data.initial == "carry" and k < len(data.gaps) else None
            z0 = None if gap is None or end is None else filt.coast(end, max(gap - lead,
                                                                            0.0))
            Z = filt.filtered(own, z0)
            free = filt.free(N)
            # the last sample's input acts until the reference changes (data.ahead[k] s
            # later, one step for undecimated data): the state is carried to there with
            # the input extrapolated linearly, then coasted over the rest of the gap
            lead = data.ahead[k] if k < len(data.ahead) else data.h
            slope = (own[-1] - own[-2]) / data.h if N >= 2 else 0.0
            end = filt.held(Z[-1, :n], own[-1], lead, slope)
        X[row:row + N, : zeros + 1] = Z[:, zeros::-1]
        X[row:row + N, zeros + 1] = other
        col = p + k * n
        X[row:row + N, col:col + n] = free
        row += N
    return X


def whiten(M: np.ndarray, data: OutputData, w: np.ndarray | None) -> np.ndarray:
    """Rows of M (aligned with the samples of ``data``) filtered by the FIR whitening
    filter D(q) = 1 + w_1 q^-1 + ... + w_p q^-p within each trial, the first p rows of
    each trial dropped (they would need samples before the trial). ``None``: M as is."""
    if w is None or len(w) <= 1:
        return M
    p = len(w) - 1
    parts = []
    row = 0
    for own in data.own:
        N = len(own)
        parts.append(signal.lfilter(w, [1.0], M[row:row + N], axis=0)[p:])
        row += N
    return np.concatenate(parts)


def used(M: np.ndarray, data: OutputData, w: np.ndarray | None) -> np.ndarray:
    """:func:`whiten`, then the first ``data.skip`` samples of each trial left out."""
    Mw = whiten(M, data, w)
    lag = 0 if w is None else len(w) - 1
    drop = max(data.skip - lag, 0)
    if drop == 0:
        return Mw
    keep = []
    row = 0
    for own in data.own:
        N = len(own) - lag
        keep.append(np.arange(row + drop, row + N))
        row += N
    return Mw[np.concatenate(keep)]


def lengths(data: OutputData, w: np.ndarray | None) -> list[int]:
    """Rows per trial of :func:`used`."""
    lag = 0 if w is None else len(w) - 1
    return [len(own) - max(lag, data.skip) for own in data.own]


def fit_linear(a: np.ndarray, data: OutputData, zeros: int, w: np.ndarray | None = None
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(beta, residual, X): the least-squares numerator, coupling, offset and initial
    states for
    denominator ``a`` (columns as :func:`design`), the residual and X.

    With a whitening filter ``w`` (see :func:`whiten`) the least squares and the
    returned residual are those of the whitened equations (the prediction errors of a
    Box-Jenkins model with noise 1/D(q) times white noise); without, the output error
    y - X beta. The initial states are eliminated trial by trial (projection onto the
    orthogonal complement of the trial's free responses), so the shared least-squares
    problem has only ``data.shared(zeros)`` columns.
    """
    X = design(a, data, zeros)
    y = np.concatenate(data.y)
    p = data.shared(zeros)
    n = len(a)
    if not np.all(np.isfinite(X)):
        return np.full(X.shape[1], np.nan), np.full(used(y, data, w).shape, np.inf), X
    Xw = used(X, data, w)
    yw = used(y, data, w)
    Xp = Xw[:, :p].copy()
    yp = yw.copy()
    bases = []
    row = 0
    for k, count in enumerate(lengths(data, w)):
        rows = slice(row, row + count)
        bases.append(rows)
        row += count
        if not data.estimated(k):
            continue
        Q = np.linalg.qr(Xw[rows, p + k * n:p + (k + 1) * n])[0]
        Xp[rows] -= Q @ (Q.T @ Xp[rows])
        yp[rows] -= Q @ (Q.T @ yp[rows])
    scale = np.linalg.norm(Xp, axis=0)
    scale[scale == 0] = 1.0
    shared = np.linalg.lstsq(Xp / scale, yp, rcond=None)[0] / scale
    beta = np.zeros(X.shape[1])
    beta[:p] = shared
    if not any(data.estimated(k) for k in range(len(bases))):
        return beta, yp - Xp @ shared, X
    for k, rows in enumerate(bases):
        if not data.estimated(k):
            continue
        F = Xw[rows, p + k * n:p + (k + 1) * n]
        beta[p + k * n:p + (k + 1) * n] = np.linalg.lstsq(F, yw[rows] - Xw[rows, :p] @ shared,
                                                          rcond=None)[0]
    return beta, yp - Xp @ shared, X


def element_parameters(structure: Structure, theta: Sequence[float], i: int
                       ) -> tuple[np.ndarray, np.ndarray, float]:
    """(b descending, a descending without the leading 1, c) of output ``i`` from theta."""
    theta = np.asarray(theta, float)
    per = structure.zeros + 1 + structure.poles
    block = theta[i * per:(i + 1) * per]
    return block[: structure.zeros + 1], block[structure.zeros + 1:], float(theta[-2 + i])


def predict_output(b: np.ndarray, a: np.ndarray, c: float, data: OutputData, *,
                   initial: str = "estimate", offset: float = 0.0,
                   fresh: bool = True) -> np.ndarray:
    """The model's output i over all trials (concatenated) from the measured inputs.

    ``initial``: "estimate" (each trial's initial state by least squares), "carry" or
    "zero" (module docstring); ``offset``: the constant added to the output (an
    estimated offset of the logged output, not refitted here); ``fresh`` False: with
    "carry", a trial that begins mid-response starts from rest too (Section 4's fit
    ratio as the paper defines it), its initial state not fitted.
    """
    if initial not in INITIAL_STATES:
        raise ValueError(f"initial must be one of {', '.join(INITIAL_STATES)}, got {initial!r}")
    zeros = len(b) - 1
    data = replace(data, initial=initial, offset=False, free=data.free if fresh else ())
    X = design(a, data, zeros)
    forced = X[:, : zeros + 1] @ np.asarray(b, float) + c * X[:, zeros + 1] + float(offset)
    n = len(a)
    p = data.shared(zeros)
    columns = [col for k in range(len(data.y)) if data.estimated(k)
               for col in range(p + k * n, p + (k + 1) * n)]
    if not columns:
        return forced
    F = X[:, columns]
    y = np.concatenate(data.y)
    eta = np.linalg.lstsq(F, y - forced, rcond=None)[0]
    return forced + F @ eta


def predict(structure: Structure, theta: Sequence[float], trials: Sequence[Trial], *,
            initial: str = "estimate", offsets: Sequence[float] = (),
            fresh: bool = True) -> list[np.ndarray]:
    """The model's (N, 2) output per trial, simulated from the trials' measured inputs,
    plus ``offsets`` (one constant per output, :attr:`Estimate.offsets`; none: zero);
    ``fresh`` as :func:`predict_output`."""
    h = check_trials(trials, structure, what="the simulation of a model")
    sizes = [np.asarray(tr.t).shape[0] for tr in trials]
    columns = []
    for i in (0, 1):
        b, a, c = element_parameters(structure, theta, i)
        columns.append(predict_output(b, a, c, output_data(trials, i, h), initial=initial,
                                      offset=float(offsets[i]) if len(offsets) else 0.0,
                                      fresh=fresh))
    both = np.column_stack(columns)
    return np.split(both, np.cumsum(sizes)[:-1])
