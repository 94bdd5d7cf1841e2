"""Property-based checks of the paper's dynamic conclusions on random trajectories.

Each test draws a scenario meeting Assumption 1 at t = 0 (verify.strategies.scenarios),
runs the reference simulator with steps h and h/2 and checks a conclusion within the
integrator's estimated error (verify.sim.properties). Assumptions are checked along the
trajectory; an example whose assumptions fail later is discarded with ``assume`` and
the reason is recorded with ``note``/``event``. The number of examples follows the
hypothesis profile (tests/conftest.py): bounded in CI, deeper with
VERIFY_HYPOTHESIS_PROFILE=deep.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from hypothesis import assume, event, given, note, settings

from verify.sim import properties as props
from verify.sim.inputs import Reference
from verify.strategies import scenarios

SECONDS = 3.0
H = 1.0 / 60.0  # the error estimate compares with h/2 = 1/120 s, the paper's loop


def _examples(divisor: int) -> int:
    return max(5, settings.default.max_examples // divisor)


def _conclude(result: props.PropertyResult) -> None:
    note(result.line())
    for name, ok in result.assumptions.items():
        if not ok:
            event(f"assumption failed: {name}")
    assume(result.holds is not None)
    assert result.holds, result.line()


@settings(max_examples=_examples(4))
@given(scenarios(autonomous=("random", "consensus")))
def test_stealthy_input_leaves_dbar_unchanged(scenario):
    _conclude(props.stealthiness(scenario, SECONDS, H))


@settings(max_examples=_examples(4))
@given(scenarios())
def test_quasi_average_axis_is_dbar_and_lemma1_and_lyapunov(scenario):
    pair = props.RunPair.of(scenario, SECONDS, H)
    for check in (props.quasi_average_axis, props.lemma1_invariance,
                  props.lyapunov_decrease):
        _conclude(check(pair))


@settings(max_examples=_examples(4))
@given(scenarios(autonomous=("zero",)))
def test_lyapunov_decrease_with_running_supply(scenario):
    pair = props.RunPair.of(scenario, SECONDS, H)
    _conclude(props.lyapunov_decrease(pair, use_storage=False))


@settings(max_examples=_examples(8))
@given(scenarios(max_bodies=3, autonomous=("zero", "consensus")))
def test_lasalle_dbar_converges_to_reference(scenario):
    pair = props.RunPair.of(scenario, 40.0, 1.0 / 20.0)
    _conclude(props.lasalle_convergence(pair))


def test_lasalle_when_dbar_starts_at_the_reference():
    """Found by the deep profile: dbar(0) = d_r with the leader away; dbar leaves and returns."""
    from verify import so3
    from verify.sim.humans import StaticGainHuman
    from verify.sim.scenario import Scenario

    scenario = Scenario(np.eye(3)[None], 1.0, StaticGainHuman(0.5 * np.eye(2)),
                        Reference.constant(np.eye(3)),
                        R_l0=so3.exp(np.full(3, 1 / np.sqrt(3))))
    result = props.lasalle_convergence(props.RunPair.of(scenario, 40.0, 1.0 / 20.0))
    assert result.holds is True, result.line()


def test_a_broken_projector_is_caught(monkeypatch):
    """Mutation: without A(d) the autonomous input moves dbar, and the check fails."""
    import verify.sim.scenario as scenario_module

    monkeypatch.setattr(scenario_module, "stealthy_input", lambda R, w: w)
    from verify import so3
    from verify.sim.humans import StaticGainHuman
    from verify.sim.inputs import Synchronisation
    from verify.sim.scenario import Scenario

    rng = np.random.default_rng(3)
    R0 = so3.exp(0.5 * rng.standard_normal((4, 3)))
    scenario = Scenario(R0, 2.0, StaticGainHuman(np.eye(2)),
                        Reference.constant(so3.exp(np.array([0.3, 0.2, 0.0]))),
                        autonomous=Synchronisation())
    result = props.stealthiness(scenario, 2.0, H)
    assert result.holds is False
    assert result.violation > 100 * result.tolerance


def test_a_sign_error_in_the_leader_law_is_caught(monkeypatch):
    """Mutation: flipping the coupling in eq. (6b) breaks the Lyapunov decrease."""
    import verify.sim.scenario as scenario_module
    from verify import so3
    from verify.sim.humans import StaticGainHuman
    from verify.sim.scenario import Scenario

    def flipped(self, R_l, R_bar, omega_b):
        return -self.s.k_s * so3.vee(R_l.T @ R_bar) + omega_b

    monkeypatch.setattr(scenario_module.ClosedLoop, "leader_velocity", flipped)
    R0 = so3.exp(np.array([[0.2, 0.1, 0.0]]))
    scenario = Scenario(R0, 3.0, StaticGainHuman(np.eye(2)),
                        Reference.constant(so3.exp(np.array([0.6, -0.4, 0.0]))),
                        R_l0=so3.exp(np.array([0.5, 0.4, 0.0])))
    result = props.lyapunov_decrease(props.RunPair.of(scenario, 3.0, H), use_storage=False)
    assert result.holds is False or result.holds is None


def test_switching_reference_is_checked_per_segment():
    from verify import so3
    from verify.sim.humans import StaticGainHuman
    from verify.sim.scenario import Scenario

    Rs = [so3.exp(np.array([0.3, 0.0, 0.0])), so3.exp(np.array([0.0, 0.4, 0.0]))]
    scenario = Scenario(so3.exp(np.array([[0.1, 0.1, 0.0]])), 2.0,
                        StaticGainHuman(np.eye(2)), Reference.switching(Rs, period=1.5))
    pair = props.RunPair.of(scenario, 3.0, H)
    result = props.lyapunov_decrease(pair, use_storage=False)
    assert result.holds is True, result.line()
    constant = replace(scenario, reference=Reference.constant(Rs[0]))
    assert props.lyapunov_decrease(props.RunPair.of(constant, 3.0, H)).holds is True


def test_the_documented_strategies_example_runs():
    from pathlib import Path

    readme = (Path(__file__).resolve().parents[1] / "docs" / "guide" / "python.md"
              ).read_text()
    start = readme.index("```python\nfrom hypothesis import given") + len("```python\n")
    namespace: dict = {}
    exec(compile(readme[start: readme.index("```", start)], "<docs/guide/python.md block>", "exec"),
         namespace)
    settings(max_examples=3)(namespace["test_lyapunov"])()
