"""The reference simulator: mixed SO(3) x R^k steps, human models, inputs, strategies."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings

from verify import so3
from verify.errors import DbarUndefinedError, VerifyInputError
from verify.passivity.decision import NOT_PASSIVE, PASSIVE, decide
from verify.sim.humans import LTIHuman, StaticGainHuman, VROperator
from verify.sim.inputs import Reference, Synchronisation, autonomous_input
from verify.sim.lie_group import cf4_mixed_step
from verify.sim.run import simulate
from verify.sim.scenario import Scenario
from verify.strategies import non_passive_lti_models, passive_humans, passive_lti_models


def _lti_scenario(seed: int = 2) -> Scenario:
    rng = np.random.default_rng(seed)
    A = np.array([[-0.5, 2.0], [-2.0, -0.5]])
    human = LTIHuman(A, np.array([[1.0, 0.0], [0.0, 1.0]]), np.eye(2), 0.2 * np.eye(2))
    return Scenario(so3.exp(0.4 * rng.standard_normal((3, 3))), 2.0, human,
                    Reference.constant(so3.exp(np.array([0.7, -0.3, 0.2]))),
                    R_l0=so3.exp(np.array([0.2, 0.5, 0.0])),
                    autonomous=autonomous_input("random", 3, seed))


def test_mixed_step_has_order_four_in_rotations_and_human_state():
    scenario = _lti_scenario()
    ref = simulate(scenario, 1.0, 1 / 1920)
    errors = []
    for h in (1 / 20, 1 / 40, 1 / 80):
        run = simulate(scenario, 1.0, h)
        errors.append(max(np.abs(run.final_bodies - ref.final_bodies).max(),
                          np.abs(run.x[-1] - ref.x[-1]).max()))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(orders > 3.6), orders


def test_mixed_step_is_rk4_on_the_euclidean_part():
    """With no rotation velocity, x' = -x must be advanced exactly as classical RK4."""
    h = 0.1

    def f(t, Y, x):
        return np.zeros((1, 3)), -x

    _, x1 = cf4_mixed_step(f, 0.0, np.eye(3)[None], np.array([1.0]), h)
    rk4 = 1 - h + h**2 / 2 - h**3 / 6 + h**4 / 24
    assert x1[0] == pytest.approx(rk4, abs=1e-15)


def test_rotations_stay_in_so3_over_long_runs():
    run = simulate(_lti_scenario(4), 20.0)
    R = np.concatenate([run.R_bar, run.R_l, run.final_bodies])
    assert so3.orthogonality_error(R).max() < 1e-12
    assert np.abs(np.linalg.det(R) - 1).max() < 1e-12


def test_vr_operator_saturates_and_holds_its_command():
    op = VROperator()
    R_r = np.eye(3)
    R_l = so3.exp(np.array([2.0, 0.0, 0.0]))  # far from the reference: saturated
    w = op.hold(0.0, R_l, R_r)
    assert np.linalg.norm(w) == pytest.approx(1.0)
    # the command turns d_l towards d_r: the rotation axis is d_l x d_r
    assert np.cross(R_l @ so3.E3, R_r @ so3.E3) @ w > 0
    small = op.hold(0.0, so3.exp(np.array([0.1, 0.0, 0.0])), R_r)
    assert np.linalg.norm(small) == pytest.approx(0.8 * 0.1, rel=1e-9)  # k_omega * angle
    assert np.allclose(op.command(0.0, np.zeros(0), np.zeros(3), R_l, w), R_l.T @ w)


def test_two_port_human_leaves_the_third_command_at_zero():
    human = StaticGainHuman(np.array([[1.0, 0.5], [-0.5, 2.0]]))
    out = human.command(0.0, np.zeros(0), np.array([1.0, 1.0, 5.0]), np.eye(3), None)
    assert out[2] == 0.0 and np.allclose(out[:2], [1.5, 1.5])
    assert StaticGainHuman(-np.eye(2)).storage(np.zeros(0)) is None  # not passive


@pytest.mark.parametrize("bad", [np.ones((2, 3)), np.ones((4, 4)), np.full((2, 2), np.nan)])
def test_bad_human_models_are_rejected(bad):
    with pytest.raises(VerifyInputError):
        StaticGainHuman(bad)


def test_scenario_validation():
    human, ref = StaticGainHuman(), Reference.constant(np.eye(3))
    with pytest.raises(VerifyInputError, match="at least one body"):
        Scenario(np.zeros((0, 3, 3)), 1.0, human, ref).validate()
    with pytest.raises(VerifyInputError, match="k_s"):
        Scenario(np.eye(3)[None], 0.0, human, ref).validate()
    flipped = np.stack([np.eye(3), np.diag([1.0, -1.0, -1.0])])
    with pytest.raises(DbarUndefinedError):
        Scenario(flipped, 1.0, human, ref).validate()


def test_consensus_input_on_a_ring_matches_the_definition():
    R = so3.random_rotations(5, np.random.default_rng(1))
    got = Synchronisation(gain=0.7)(0.0, R)
    for i in range(5):
        expected = sum(so3.vee(R[i].T @ R[j]) for j in ((i - 1) % 5, (i + 1) % 5))
        assert np.allclose(got[i], 0.7 * expected, atol=1e-14)


@settings(max_examples=8)
@given(passive_lti_models())
def test_passive_model_strategy_gives_passive_models(model):
    assert decide(model).verdict == PASSIVE


@settings(max_examples=8)
@given(non_passive_lti_models())
def test_non_passive_model_strategy_gives_non_passive_models(model):
    assert decide(model).verdict == NOT_PASSIVE
    assert np.all(np.linalg.eigvals(model.A).real < 0)  # stable: the failure is not a pole


@settings(max_examples=5)
@given(passive_humans())
def test_passive_human_storage_rate_is_below_the_supply(human):
    rng = np.random.default_rng(0)
    for _ in range(20):
        x, e = rng.standard_normal(human.state_size), rng.standard_normal(3)
        supply = e @ human.command(0.0, x, e, np.eye(3), None)
        assert human.storage_rate(x, e) <= supply + 1e-9 * (1 + x @ x + e @ e)


def test_directions_cancelling_mid_run_is_flagged_as_an_assumption_failure():
    """Two bodies spread apart symmetrically: the input is stealthy (dbar stays e3) but
    sum d_i shrinks through 0 (claim sec2.dbar-stays-defined); then dbar flips."""
    from verify.sim import properties as props
    from verify.sim.inputs import Autonomous

    class SpreadApart(Autonomous):
        name = "spread apart"

        def __call__(self, t, R):
            return np.array([[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]])

    R0 = so3.exp(np.array([[1.4, 0.0, 0.0], [-1.4, 0.0, 0.0]]))
    scenario = Scenario(R0, 1.0, StaticGainHuman(), Reference.constant(np.eye(3)),
                        autonomous=SpreadApart())
    run = simulate(scenario, 0.4)
    assert run.coherence.min() < 1e-2
    assert run.dbar[-1] @ so3.E3 < 0 < run.R_bar[-1][:, 2] @ so3.E3  # dbar flipped, R-bar not
    result = props.quasi_average_axis(props.RunPair.of(scenario, 0.4))
    assert result.holds is None and not all(result.assumptions.values())


def test_open_loop_signal_human_keeps_rbar_axis_on_dbar():
    """Section 3: R-bar e3 = dbar for any human command, here a given signal."""
    from verify.sim.humans import SignalHuman
    from verify.sim.inputs import SignalInput, smooth_random_signal

    rng = np.random.default_rng(9)
    R0 = so3.exp(0.4 * rng.standard_normal((5, 3)))
    scenario = Scenario(R0, 2.5, SignalHuman(smooth_random_signal(rng, (3,))),
                        Reference.constant(np.eye(3)), R_l0=so3.random_rotations(1, rng)[0],
                        autonomous=SignalInput(smooth_random_signal(rng, (5, 3), amplitude=0.2)))
    run = simulate(scenario, 2.0)
    assert np.abs(run.R_bar[:, :, 2] - run.dbar).max() < 1e-8
    assert np.abs(run.R_l[-1] - run.R_l[0]).max() > 1e-2  # the signal did move the leader
