"""The shipped example logs: well formed, small, and what their generator makes."""

import numpy as np
import pytest

from verify.identify.data.example_logs import EXAMPLES, LOGS, WRITTEN_DECIMALS, main
from verify.identify.data.simulated_experiment import (
    MEASUREMENT_NOISE,
    OPERATOR_NOISE,
    add_measurement_noise,
    experiment_scenario,
)
from verify.inputs.experiment_log import read_log
from verify.passivity.decision import PASSIVE, decide
from verify.passivity.io.model_file import load_model
from verify.sim.experiment_log import trajectory_trials
from verify.sim.run import simulate


def test_shipped_logs_are_small_and_in_the_protocol():
    files = sorted(LOGS.iterdir())
    assert [p.name for p in files] == sorted(f"{ex.name}{s}" for ex in EXAMPLES
                                             for s in (".npz", ".toml"))
    assert sum(p.stat().st_size for p in files) < 4_000_000
    for ex in EXAMPLES:
        log = read_log(LOGS / f"{ex.name}.npz")
        assert log.rate == 120.0 and [tr.trial for tr in log.trials] == list(range(12))
        for tr in log.trials:
            assert tr.t.shape == (1800,) and tr.e.shape == (1800, 2)
            assert tr.t[0] == pytest.approx(15.0 * tr.trial)
            assert 0.2 <= tr.start - tr.t[0] <= 0.5 + 1 / 120
            assert tr.reference is not None and tr.valid is None


@pytest.mark.parametrize("ex", EXAMPLES, ids=lambda ex: ex.name)
def test_ground_truth_model_files(ex):
    model = load_model(LOGS / f"{ex.name}.toml")
    assert model.meta["k_s"] == ex.k_s
    assert model.exact == ex.model().exact  # the file spells the simulated model exactly
    assert (decide(model).verdict == PASSIVE) == ex.passive
    text = (LOGS / f"{ex.name}.toml").read_text()
    assert text.startswith("# SIMULATION GROUND TRUTH") and text == ex.toml()


def test_first_trial_is_what_the_generator_simulates():
    ex = EXAMPLES[0]
    scenario = experiment_scenario(ex.model(), k_s=ex.k_s, n=8, trials=12, trial_seconds=15.0,
                                   rate=120.0, operator_noise=OPERATOR_NOISE,
                                   reaction=(0.2, 0.5), seed=ex.seed)
    traj = simulate(scenario, 15.0, 1 / 120)
    (fresh,) = add_measurement_noise(trajectory_trials(traj, until=15.0), MEASUREMENT_NOISE,
                                     ex.seed)
    shipped = read_log(LOGS / f"{ex.name}.npz").trials[0]
    assert fresh.start == shipped.start
    np.testing.assert_array_equal(fresh.t, shipped.t)
    # written to WRITTEN_DECIMALS decimals: within half a unit of the last one
    half = 0.5 * 10.0**-WRITTEN_DECIMALS + 1e-12
    np.testing.assert_allclose(fresh.e, shipped.e, rtol=0, atol=half)
    np.testing.assert_allclose(fresh.u, shipped.u, rtol=0, atol=half)
    np.testing.assert_array_equal(shipped.e, np.round(shipped.e, WRITTEN_DECIMALS))
    np.testing.assert_array_equal(shipped.u, np.round(shipped.u, WRITTEN_DECIMALS))


@pytest.mark.slow
def test_example_logs_regenerate_byte_for_byte():
    assert main(["--check"]) == 0
