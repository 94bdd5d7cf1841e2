"""The fit on the paper's basis, and the estimator's basis as a second, labelled figure.

Section 4's fit ratio is the model simulated on the validation input from rest, with no
offset: the figure a reader compares with the paper's. Two logs of the known operator
THETA, where the estimator's basis differs from it:

* an uncalibrated stick (a constant offset on the logged u), identified with the offset
  estimated: the paper's figure has no offset, the second figure adds it;
* trials logged late (they begin mid-response), after reset pauses: the paper's figure
  starts them from rest, the second figure from their estimated initial states.

Each figure is checked against scipy's own simulation (``lsim``) of the estimated model
on that basis, and the second, which fits more, is never the one called the fit.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from identify_loop import THETA
from scipy import linalg, signal

from verify.identify.command import Quality, SecondFit, trial_joins
from verify.identify.data.protocol import prepare
from verify.identify.data.simulated_experiment import (
    simulate_experiment,
    simulate_paused_experiment,
    with_output_offset,
)
from verify.identify.estimate.estimation import estimate_model
from verify.identify.estimate.prediction import element_parameters
from verify.identify.estimate.structure import Structure
from verify.identify.quality.coverage import true_model
from verify.identify.quality.fits import (
    PAPER_BASIS,
    fit_ratio,
    fit_ratios,
    honest_fits,
    paper_fits,
    second_basis,
    trial_ranges,
)
from verify.inputs.experiment import ExperimentLog

STICK = (0.1, -0.05)


def _lsim(est, trials, *, carry: bool, offsets=(0.0, 0.0), free: bool = False):
    """scipy's simulation of ``est`` on ``trials``: the first from rest; a later one from
    the state the previous one left (coasted with zero input over the time between them)
    when ``carry`` and it follows on, else from rest, or (``free``) from the initial
    state that fits its output best (least squares over the free responses)."""
    out = [np.zeros((len(tr.t), 2)) for tr in trials]
    for i in (0, 1):
        b, a, c = element_parameters(est.structure, est.theta, i)
        A, B, C, D = signal.tf2ss(b, np.r_[1.0, a])
        x_end, prev = None, None
        for k, tr in enumerate(trials):
            t = np.asarray(tr.t, float) - float(tr.t[0])
            follows = (carry and prev is not None and tr.trial != prev.trial
                       and not getattr(tr, "resumed", False) and tr.t[0] > prev.t[-1])
            x0 = (linalg.expm(A * float(tr.t[0] - prev.t[-1])) @ x_end if follows
                  else np.zeros(A.shape[0]))
            _, y, xs = signal.lsim((A, B, C, D), tr.e[:, i], t, X0=x0)
            y = y + c * tr.e[:, 1 - i] + offsets[i]
            if free and not follows:
                zero = np.zeros_like(t)
                runs = [signal.lsim((A, B, C, D), zero, t, X0=unit)
                        for unit in np.eye(A.shape[0])]
                basis = np.column_stack([r[1] for r in runs])
                eta = np.linalg.lstsq(basis, tr.u[:, i] - y, rcond=None)[0]
                y = y + basis @ eta
                xs = xs + sum(w * r[2] for w, r in zip(eta, runs, strict=True))
            x_end, prev = xs[-1], tr
            out[k][:, i] = y
    return out


def _fits(trials, yhat) -> list[float]:
    return [fit_ratio(np.concatenate([tr.u[:, i] for tr in trials]),
                      np.concatenate([y[:, i] for y in yhat])) for i in (0, 1)]


@pytest.fixture(scope="module")
def stick():
    """The loop (6 trials of 15 s, split 4:2) as logged and with the stick's offset."""
    log = simulate_experiment(true_model(THETA), trials=6, n=2, seed=5)
    return [prepare(lg, rate="auto", split=(4, 2)) for lg in
            (log, with_output_offset(log, STICK))]


def test_an_offset_is_in_the_second_figure_only(stick):
    plain, shifted = stick
    ident, val = shifted.identification, shifted.validation
    est = estimate_model(ident, Structure.paper(), offset=True)
    _, p_val = paper_fits(est, ident, val)
    paper = fit_ratios(val, p_val)
    # the paper's figure: the model from rest on the validation input, no offset
    assert np.allclose(paper, _fits(val, _lsim(est, val, carry=True)), atol=1.0)
    # the second: identification then validation, state carried, offsets added
    both = _lsim(est, [*ident, *val], carry=True, offsets=est.offsets)
    _, y_val = honest_fits(est, ident, val)
    second = fit_ratios(val, y_val)
    assert np.allclose(second, _fits(val, both[len(ident):]), atol=1.0)
    assert all(s > p + 5 for s, p in zip(second, paper, strict=True))  # the stick's share
    basis = second_basis(est, ident, val)
    assert basis is not None and "offsets added" in basis and "mid-response" not in basis
    # the same data without the stick: its paper fit is what the offset took away
    est_plain = estimate_model(plain.identification, Structure.paper(), offset=True)
    clean = fit_ratios(plain.validation, paper_fits(est_plain, plain.identification,
                                                    plain.validation)[1])
    assert all(c > p + 5 for c, p in zip(clean, paper, strict=True))
    assert second_basis(estimate_model(ident, Structure.paper(), offset=False),
                        ident, val) is None  # no offset, no late trial: one figure


def _cut(log: ExperimentLog, indices: list[int], seconds: float) -> ExperimentLog:
    """``log`` with trials ``indices`` logged only from ``seconds`` after their start."""
    trials = list(log.trials)
    for index in indices:
        tr = trials[index]
        k = int(np.searchsorted(tr.t, tr.start)) + round(seconds * log.rate)
        trials[index] = replace(tr, t=tr.t[k:], e=tr.e[k:], u=tr.u[k:],
                                reference=tr.reference[k:], start=float(tr.t[k]))
    return replace(log, trials=tuple(trials))


def test_late_logged_trials_start_from_rest_in_the_paper_figure():
    log = _cut(simulate_paused_experiment(true_model(THETA), trials=5, n=2, seed=3),
               [2, 3, 4], 1.0)
    prepared = prepare(log, rate="auto", split=(2, 3))
    ident, val = prepared.identification, prepared.validation
    est = estimate_model(ident, Structure.paper(), offset=False)
    _, p_val = paper_fits(est, ident, val)
    paper = fit_ratios(val, p_val)
    assert np.allclose(paper, _fits(val, _lsim(est, val, carry=False)), atol=1.0)
    _, y_val = honest_fits(est, ident, val)
    second = fit_ratios(val, y_val)
    assert np.allclose(second, _fits(val, _lsim(est, val, carry=False, free=True)), atol=1.0)
    assert all(s > p for s, p in zip(second, paper, strict=True))
    basis = second_basis(est, ident, val)
    assert basis is not None and "trials 2–4 estimated" in basis and "offset" not in basis
    warnings = [line for line in trial_joins([*ident, *val]) if line.startswith("warning")]
    assert len(warnings) == 1, warnings  # one line for the three trials
    assert warnings[0].startswith("warning: trials 2–4 begin mid-response (u at ")
    assert "their initial states are estimated" in warnings[0] and len(warnings[0]) < 500


def test_the_fit_line_json_and_table_name_both_bases():
    q = Quality([69.4, 66.15], [66.2, 60.0],
                second=SecondFit("the estimator's: ... with the estimated output offsets "
                                 "added", [70.0, 68.0], [72.5, 71.25]))
    text = q.text()
    assert text.startswith(f"fit (%, {PAPER_BASIS}): identification 69.40, 66.15; "
                           "validation 66.20, 60.00")
    assert "second fit (%, not the paper's basis; the estimator's" in text
    assert "validation 72.50, 71.25" in text
    summary = q.to_json()
    assert summary["validation"] == [66.2, 60.0] and summary["basis"] == PAPER_BASIS
    assert summary["second"]["validation"] == [72.5, 71.25]
    assert "offsets added" in summary["second"]["basis"]
    table = q.table()
    assert table["fit_basis"] == PAPER_BASIS and table["fit_second_validation"] == [72.5,
                                                                                    71.25]
    assert q.decision_fit == [72.5, 71.25]
    alone = Quality([1.0, 2.0], [3.0, 4.0])
    assert alone.to_json()["second"] is None and "fit_second_basis" not in alone.table()
    assert "second" not in alone.text() and alone.decision_fit == [3.0, 4.0]


def test_trial_ranges():
    assert trial_ranges([12, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]) == "2–12"
    assert trial_ranges([1, 3]) == "1, 3"
