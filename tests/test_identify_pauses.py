"""Trials after a pause, and logging that starts mid-response (Section 4's trials).

Data simulated from known operators: the paper's closed loop with the loop reset to rest
between trials (:func:`simulate_paused_experiment`), and an open-loop operator whose
trial begins with its state far from rest (scipy's own simulation, independent of the
estimator).
"""

from __future__ import annotations

import itertools
from dataclasses import replace

import numpy as np
import pytest
from identify_loop import THETA
from scipy import signal

from verify.identify.command import trial_joins
from verify.identify.data.protocol import prepare
from verify.identify.data.simulated_experiment import simulate_paused_experiment
from verify.identify.estimate import trial_data
from verify.identify.estimate.estimation import estimate_model
from verify.identify.estimate.structure import Structure
from verify.identify.quality.coverage import true_model
from verify.inputs.experiment import ExperimentLog, Trial


def _cut(log: ExperimentLog, index: int, seconds: float) -> ExperimentLog:
    """``log`` with trial ``index`` logged only from ``seconds`` after its start event."""
    trials = list(log.trials)
    tr = trials[index]
    k = int(np.searchsorted(tr.t, tr.start)) + round(seconds * log.rate)
    trials[index] = replace(tr, t=tr.t[k:], e=tr.e[k:], u=tr.u[k:],
                            reference=tr.reference[k:], start=float(tr.t[k]))
    return replace(log, trials=tuple(trials))


@pytest.fixture(scope="module", params=[3, 4, 7])
def paused(request):
    """Four 15 s trials of the loop (n = 2) separated by 2-5 s reset pauses."""
    return simulate_paused_experiment(true_model(THETA), trials=4, n=2, seed=request.param)


def test_a_pause_is_not_coasted_over(paused):
    data = prepare(paused, rate="auto", split=(4, 0)).identification
    gaps = [float(b.t[0] - a.t[-1]) for a, b in itertools.pairwise(data)]
    assert min(gaps) > 2.0  # the pauses are 2-5 s
    assert [tr.resumed for tr in data] == [False, True, True, True]
    assert trial_data.dead_time_gaps(data) == (None,) * 4
    joins = " ".join(trial_joins(data))
    assert "1, 2, 3 follow a pause in the log" in joins and "warning" not in joins


def test_back_to_back_trials_are_still_carried():
    from verify.identify.data.simulated_experiment import simulate_experiment

    log = simulate_experiment(true_model(THETA), trials=3, n=2, seed=3)
    data = prepare(log, rate="auto", split=(3, 0)).identification
    assert not any(tr.resumed for tr in data)
    gaps = trial_data.dead_time_gaps(data)
    assert gaps[0] is None and all(g is not None and 0 < g < 1 for g in gaps[1:])


def test_protocol_trials_do_not_start_mid_response(paused):
    data = prepare(paused, rate="auto", split=(4, 0)).identification
    ratios = [trial_data.mid_response(tr) for tr in data]
    assert max(ratios) < trial_data.MID_RESPONSE
    assert not any(trial_data.fresh_starts(data))


def test_logging_that_starts_mid_response_is_flagged(paused):
    cut = _cut(paused, 1, 1.0)  # logging resumes 1 s into the operator's response
    data = prepare(cut, rate="auto", split=(4, 0)).identification
    assert trial_data.mid_response(data[1]) >= trial_data.MID_RESPONSE
    assert trial_data.fresh_starts(data) == (False, True, False, False)
    warnings = [line for line in trial_joins(data) if line.startswith("warning")]
    assert len(warnings) == 1 and "trial 1" in warnings[0] and "mid-response" in warnings[0]


def _open_loop_from_a_state(x0_scale: float) -> tuple[Trial, ...]:
    """Two open-loop trials of the known operator THETA (noise-free), 30 s apart; the
    second begins with the operator's state at ``x0_scale`` (a response under way)."""
    num, den = Structure.paper().transfer_matrix(list(THETA))
    rate, seconds = 50.0, 15.0
    rng = np.random.default_rng(2)
    out = []
    for k in range(2):
        t = 30.0 * k + np.arange(round(seconds * rate)) / rate
        f = rng.uniform(0.2, 3.0, (2, 6))
        p = rng.uniform(0, 2 * np.pi, (2, 6))
        e = np.column_stack([np.sin(np.outer(t - t[0], f[i]) + p[i]).sum(axis=1) * 0.1
                             for i in range(2)])
        u = np.zeros_like(e)
        for i in (0, 1):
            system = signal.StateSpace(*signal.tf2ss([float(x) for x in num[i][i]],
                                                     [float(x) for x in den[i][i]]))
            x0 = np.zeros(2) if k == 0 else x0_scale * np.array([1.0, -0.5])
            _, y, _ = signal.lsim(system, e[:, i], t - t[0], X0=x0, interp=True)
            u[:, i] = y + float(num[i][1 - i][0]) * e[:, 1 - i]
        out.append(Trial(k, t, e, u, start=float(t[0])))
    return tuple(out)


def test_a_mid_response_start_has_its_state_estimated():
    """Noise-free data of a known operator whose second trial begins far from rest: with
    that trial's state estimated the parameters come back (to the first-order-hold
    discretisation's accuracy); started from rest they do not."""
    trials = _open_loop_from_a_state(3.0)
    assert trial_data.fresh_starts(trials) == (False, True)
    est = estimate_model(trials, Structure.paper())
    assert np.max(np.abs(est.theta - THETA) / np.abs(THETA)) < 2e-3
    from verify.identify.estimate import estimation

    original = estimation.output_data

    def from_rest(*args, **kwargs):
        return replace(original(*args, **kwargs), free=())

    try:
        estimation.output_data = from_rest
        wrong = estimate_model(trials, Structure.paper())
    finally:
        estimation.output_data = original
    assert np.max(np.abs(wrong.theta - THETA) / np.abs(THETA)) > 10 * np.max(
        np.abs(est.theta - THETA) / np.abs(THETA))


def test_the_passive_fit_uses_the_estimated_state_of_a_mid_response_trial(monkeypatch):
    """The passivity test's fits carry the estimator's nuisance parameters: the second
    trial begins far from rest, and with its initial state fitted the test's free model
    is the estimator's (the operator, to the discretisation's accuracy); simulated from
    rest instead it is far off. Each of the test's four fits is announced."""
    from verify.identify.robust import passive_fit

    trials = _open_loop_from_a_state(3.0)
    est = estimate_model(trials, Structure.paper())
    said: list[str] = []
    test = passive_fit.passivity_test(trials, est.theta, offset=bool(est.offsets),
                                      stage=said.append)
    good = np.max(np.abs(test.theta_free - THETA) / np.abs(THETA))
    assert good < 5e-3
    assert [line.split("(fit ")[1] for line in said] == ["1 of 4)", "2 of 4)", "3 of 4)",
                                                         "4 of 4)"]
    original = passive_fit.nuisance_columns
    monkeypatch.setattr(passive_fit, "nuisance_columns",
                        lambda data, poles=2: original(replace(data, free=()), poles))
    wrong = passive_fit.passivity_test(trials, est.theta, offset=bool(est.offsets))
    assert np.max(np.abs(wrong.theta_free - THETA) / np.abs(THETA)) > 10 * good
