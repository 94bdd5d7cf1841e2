"""Quality of an identified model: fit ratios and residual tests (Section 4).

* Fit ratio per output (Section 4, "Human Modeling", the figure the paper quotes):
  100 (1 - ||y - yhat|| / ||y - mean(y)||), 2-norms over all samples of all trials of
  the data set, mean(y) over the same samples. yhat is the model *simulated* from the
  measured input e from a stated initial condition, never re-fitted to the data.
  **The fit** is the paper's (:func:`paper_fits`, :data:`PAPER_BASIS`): the model
  simulated on each data set's own input from rest, its first trial at rest and each
  later one from the state the model left the previous one in (or from rest, as below,
  when they do not follow on), with no offset and no estimated initial state: the figure
  a reader compares with the paper's Table 2. When the estimate uses offsets or trials
  whose initial states it estimates, the fit on the estimator's own basis is a *second*
  figure, labelled with that basis (:func:`second_basis`):
  :func:`honest_fits` runs the model over the identification and then the validation
  trials in log order, the first trial from rest and each later one from the state the
  model left the previous one in (coasted over the dead time between them, or from rest
  when the trials do not follow on, :func:`verify.identify.estimate.trial_data.dead_time_gaps`).
  The one exception is a trial that begins mid-response after a pause or at the log's
  start (:func:`verify.identify.estimate.trial_data.fresh_starts`): its initial state is
  fitted, since neither rest nor a carried state is what the operator was in; the
  command's warning names such trials. When the estimate has offsets (constants on the
  logged outputs, :attr:`Estimate.offsets`), the simulated output includes them: they are
  the stick's, not the operator's, and are added as estimated, never refitted. The
  identifiability gate decides with this figure (an uncalibrated stick does not make a
  model unidentifiable), and says so.
* Residual tests are diagnostics: they are reported, never a reason to stop. A test that
  cannot be computed (e.g. a noise-free input that does not vary enough at the tested
  lags, or an identically zero residual) is reported as not computed, with the reason.
* The residual tests (Ljung-Box whiteness and input-residual cross-correlation,
  :mod:`verify.identify.estimate.residual_tests`, which the estimator also uses to choose
  a noise model) take the model's prediction errors: the output error y - yhat, filtered
  by the noise model's whitening filter D(q) when the estimate has one
  (:attr:`Estimate.noise_model`, the first p samples of each trial dropped).

Defaults: M = 20 lags, level 0.95.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy import signal

from verify.errors import VerifyInputError
from verify.identify.estimate.prediction import predict
from verify.identify.estimate.residual_tests import (
    LAGS,
    LEVEL,
    CrossCorrelationTest,
    WhitenessTest,
    cross_correlation,
    whiteness,
)
from verify.identify.estimate.result import Estimate
from verify.inputs.experiment import Trial

__all__ = ["PAPER_BASIS", "Quality", "assess", "fit_ratio", "fit_ratios", "honest_fits",
           "paper_fits",
           "second_basis", "trial_ranges"]

#: How the fit (the paper's, Section 4) is simulated.
PAPER_BASIS = ("the paper's (Section 4): the model simulated on each data set's logged "
               "input e from rest, each later trial from the state the model left the "
               "previous one in, no offset, no estimated initial state")


@dataclass(frozen=True)
class Quality:
    """Fit ratios (%) per output and the residual tests of one data set."""

    fit: np.ndarray
    whiteness: tuple[WhitenessTest, ...]
    cross_correlation: tuple[CrossCorrelationTest, ...]
    samples: int
    initial: str = "carry"
    not_computed: tuple[str, ...] = ()

    @property
    def residuals_pass(self) -> bool:
        return not self.not_computed and all(
            t.passed for t in (*self.whiteness, *self.cross_correlation))


def fit_ratio(y: np.ndarray, yhat: np.ndarray) -> float:
    """100 (1 - ||y - yhat|| / ||y - mean(y)||) over all samples (Section 4).

    >>> round(fit_ratio(np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 1.0])), 4)
    29.2893
    """
    y = np.asarray(y, float).ravel()
    yhat = np.asarray(yhat, float).ravel()
    spread = np.linalg.norm(y - y.mean())
    if not spread > 0:
        raise VerifyInputError("the fit ratio is undefined for a constant output "
                               "(||y - mean(y)|| = 0)")
    return float(100.0 * (1.0 - np.linalg.norm(y - yhat) / spread))


def honest_fits(estimate: Estimate, identification: Sequence[Trial],
                validation: Sequence[Trial] = ()) -> tuple[list[np.ndarray],
                                                          list[np.ndarray]]:
    """The model simulated on the logged input (module docstring): (yhat per
    identification trial, yhat per validation trial), the trials taken in log order,
    identification first, the state carried across trials that follow on."""
    trials = [*identification, *validation]
    yhat = predict(estimate.structure, estimate.theta, trials, initial="carry",
                   offsets=estimate.offsets)
    return list(yhat[:len(identification)]), list(yhat[len(identification):])


def fit_ratios(trials: Sequence[Trial], yhat: Sequence[np.ndarray]) -> list[float]:
    """The fit ratio of each output over all samples of ``trials`` (:func:`fit_ratio`)."""
    u = [np.asarray(tr.u, float) for tr in trials]
    return [fit_ratio(np.concatenate([x[:, i] for x in u]),
                      np.concatenate([np.asarray(x)[:, i] for x in yhat])) for i in (0, 1)]


def paper_fits(estimate: Estimate, identification: Sequence[Trial],
               validation: Sequence[Trial] = ()) -> tuple[list[np.ndarray],
                                                          list[np.ndarray]]:
    """The model simulated as the paper defines its fit (:data:`PAPER_BASIS`): each data
    set on its own, from rest, no offset, and a trial that begins mid-response from rest
    too (or from the state carried into it) rather than from a fitted state."""
    out = []
    for trials in (identification, validation):
        out.append(list(predict(estimate.structure, estimate.theta, trials, initial="carry",
                                fresh=False)) if trials else [])
    return out[0], out[1]


def trial_ranges(ids: Sequence[int]) -> str:
    """Trial ids as ranges: ``[2, 3, 4, 7]`` -> "2–4, 7".

    >>> trial_ranges([2, 3, 4, 5, 9, 11, 12])
    '2–5, 9, 11–12'
    """
    ids = sorted(set(int(i) for i in ids))
    parts: list[str] = []
    k = 0
    while k < len(ids):
        j = k
        while j + 1 < len(ids) and ids[j + 1] == ids[j] + 1:
            j += 1
        parts.append(str(ids[k]) if j == k else f"{ids[k]}–{ids[j]}")
        k = j + 1
    return ", ".join(parts)


def second_basis(estimate: Estimate, identification: Sequence[Trial],
                 validation: Sequence[Trial] = ()) -> str | None:
    """The basis of :func:`honest_fits` in words when it is not the paper's (offsets
    added, or initial states estimated for trials that begin mid-response), else None."""
    from verify.identify.estimate.trial_data import fresh_starts

    trials = [*identification, *validation]
    fresh = sorted({tr.trial for tr, f in zip(trials, fresh_starts(trials), strict=True)
                    if f})
    used = []
    if estimate.offsets:
        used.append("the estimated output offsets added")
    if fresh:
        noun = "trial" if len(fresh) == 1 else "trials"
        used.append(f"the initial states of {noun} {trial_ranges(fresh)} estimated (they "
                    "begin mid-response)")
    if not used:
        return None
    return ("the estimator's: the model simulated on the logged input e over the "
            "identification and then the validation trials, state carried across trials "
            "that follow on, with " + " and ".join(used))


def assess(estimate: Estimate, trials: Sequence[Trial], *, yhat: Sequence[np.ndarray] | None
           = None, initial: str = "carry", lags: int = LAGS, level: float = LEVEL) -> Quality:
    """Fit ratios and residual tests of ``estimate`` on ``trials`` (module docstring).

    ``yhat``: the model's output per trial (e.g. from :func:`honest_fits`); by default
    the model simulated on ``trials`` alone from the ``initial`` condition ("carry":
    from rest, then carried; "zero"; "estimate": each trial's free response re-fitted,
    a figure that absorbs transients and is never a decision's basis)."""
    if yhat is None:
        yhat = predict(estimate.structure, estimate.theta, trials, initial=initial,
                       offsets=estimate.offsets)
    elif initial == "estimate":
        raise ValueError("a given yhat is a simulation, not a re-initialised fit")
    u = [np.asarray(tr.u, float) for tr in trials]
    e = [np.asarray(tr.e, float) for tr in trials]
    fits = np.array(fit_ratios(trials, yhat))
    white = []
    cross = []
    skipped: list[str] = []
    for i in (0, 1):
        w = np.asarray(estimate.noise_model[i] if estimate.noise_model else (1.0,), float)
        lag = len(w) - 1
        res = [signal.lfilter(w, [1.0], x[:, i] - np.asarray(p)[:, i])[lag:]
               for x, p in zip(u, yhat, strict=True)]
        try:
            white.append(whiteness(res, output=i + 1, lags=lags, level=level))
        except VerifyInputError as exc:
            skipped.append(f"whiteness of output {i + 1}: {exc}")
        for j in (0, 1):
            try:
                cross.append(cross_correlation(res, [x[lag:, j] for x in e], output=i + 1,
                                               input=j + 1, lags=lags, level=level))
            except VerifyInputError as exc:
                skipped.append(f"cross-correlation of output {i + 1} with input {j + 1}: "
                               f"{exc}")
    return Quality(fits, tuple(white), tuple(cross), sum(len(x) for x in u), initial,
                   tuple(skipped))
