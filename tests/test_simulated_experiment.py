"""Simulated identification experiments: trials, start events, the human's signals."""

import math

import numpy as np
import pytest

from verify.errors import VerifyInputError
from verify.identify.data.simulated_experiment import (
    experiment_scenario,
    simulate_experiment,
)
from verify.passivity.model import from_transfer_function
from verify.sim.experiment_log import trajectory_trials
from verify.sim.run import simulate
from verify.so3 import vee

PASSIVE = from_transfer_function([[[1.2, 0.8], [0.05]], [[-0.05], [1.2, 0.8]]],
                                 [[[1, 2, 1.5], [1]], [[1], [1, 2, 1.5]]], name="passive")


def _run(operator_noise=0.05, seconds=1.0, trials=2, seed=3):
    scenario = experiment_scenario(PASSIVE, k_s=3.0, n=3, trials=trials, trial_seconds=seconds,
                                   rate=120.0, operator_noise=operator_noise,
                                   reaction=(0.2, 0.5), seed=seed)
    return scenario, simulate(scenario, trials * seconds, 1 / 120)


def test_trials_carry_the_signals_the_human_saw_and_produced():
    scenario, traj = _run()
    human = scenario.human
    trials = trajectory_trials(traj, until=2.0)
    assert [tr.trial for tr in trials] == [0, 1]
    assert [tr.t.shape[0] for tr in trials] == [120, 120]
    k = 0
    for tr in trials:
        for i in range(tr.t.shape[0]):
            e = vee(traj.R_l[k].T @ traj.R_r[k])
            np.testing.assert_array_equal(tr.e[i], e[:2])
            x = traj.x[k, :-1]
            u = human.C @ x + human.noise[k]
            if tr.start is None or tr.t[i] >= tr.start:
                u = u + human.D @ e[:2]
            np.testing.assert_allclose(tr.u[i], u, rtol=0, atol=1e-15)
            np.testing.assert_array_equal(tr.reference[i], traj.R_r[k][:, 2])
            k += 1
    # reaction times: uniform in [0.2, 0.5] s, whole loop periods, start after the switch
    for tr, react in zip(trials, human.reaction, strict=True):
        assert 24 <= react <= 60
        assert tr.start == pytest.approx(tr.t[0] + react / 120, abs=1e-12)


def test_operator_noise_acts_inside_the_loop():
    _, quiet = _run(operator_noise=0.0)
    _, noisy = _run(operator_noise=0.05)
    # the noise moves the leader, so e (not only u) differs: closed-loop data
    a = trajectory_trials(quiet, until=2.0)[1].e
    b = trajectory_trials(noisy, until=2.0)[1].e
    assert np.max(np.abs(a - b)) > 1e-3


def test_experiment_is_seeded_and_shaped():
    kw = dict(n=3, trials=3, trial_seconds=1.0, seed=5)
    log = simulate_experiment(PASSIVE, **kw)
    again = simulate_experiment(PASSIVE, **kw)
    other = simulate_experiment(PASSIVE, **{**kw, "seed": 6})
    assert log.rate == 120.0 and len(log.trials) == 3
    for tr, tr2, tr3 in zip(log.trials, again.trials, other.trials, strict=True):
        assert tr.t.shape == (120,) and tr.e.shape == (120, 2) and tr.u.shape == (120, 2)
        np.testing.assert_allclose(np.diff(tr.t), 1 / 120, rtol=1e-9)
        np.testing.assert_array_equal(tr.e, tr2.e)
        np.testing.assert_array_equal(tr.u, tr2.u)
        assert not np.array_equal(tr.u, tr3.u)
        assert tr.t[0] < tr.start < tr.t[0] + 0.51
    assert "passive" in log.source and "seed 5" in log.source


def test_measurement_noise_is_outside_the_loop():
    kw = dict(n=3, trials=1, trial_seconds=1.0, seed=2)
    clean = simulate_experiment(PASSIVE, measurement_noise=0.0, **kw).trials[0]
    noisy = simulate_experiment(PASSIVE, measurement_noise=0.01, **kw).trials[0]
    d = noisy.e - clean.e
    assert 0.005 < np.std(d) < 0.02  # added on top of the same closed-loop run
    assert math.isclose(np.std(noisy.u - clean.u), 0.01, rel_tol=0.3)


@pytest.mark.parametrize("kw", [dict(trial_seconds=1.004), dict(operator_noise=-1.0),
                                dict(reaction=(0.5, 0.2)), dict(trials=0), dict(k_s=0.0)])
def test_bad_settings_are_one_line_errors(kw):
    with pytest.raises(VerifyInputError) as info:
        simulate_experiment(PASSIVE, **{"n": 2, "trials": 1, "trial_seconds": 1.0, **kw})
    assert "\n" not in str(info.value)
