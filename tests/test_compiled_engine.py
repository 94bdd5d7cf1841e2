"""The compiled closed-loop kernels against the Python field they copy (ClosedLoop)."""

from __future__ import annotations

import numpy as np
import pytest

from verify import so3
from verify.errors import DbarUndefinedError, VerifyInputError
from verify.sim import kernels
from verify.sim.fused import CompiledStepper, Stepper, stepper
from verify.sim.humans import Human, LTIHuman, SignalHuman, StaticGainHuman, VROperator
from verify.sim.inputs import Autonomous, Reference, autonomous_input, smooth_random_signal
from verify.sim.lie_group import cf4_mixed_step
from verify.sim.run import simulate
from verify.sim.scenario import ClosedLoop, Scenario


def _humans(rng):
    A = np.array([[-0.5, 2.0], [-2.0, -0.5]])
    return {
        "lti": LTIHuman(A, np.array([[1.0, 0.3], [0.0, 1.0]]), np.eye(2), 0.2 * np.eye(2)),
        "lti3": LTIHuman(-np.eye(3), np.eye(3), 0.5 * np.eye(3), 0.1 * np.eye(3)),
        "static": StaticGainHuman(np.array([[1.0, 0.5], [-0.5, 2.0]])),
        "vr": VROperator(),
        "signal": SignalHuman(smooth_random_signal(rng, (3,))),
    }


def _scenario(human: Human, autonomous: str, n: int = 5, seed: int = 1,
              reference: Reference | None = None) -> Scenario:
    rng = np.random.default_rng(seed)
    return Scenario(so3.exp(0.5 * rng.standard_normal((n, 3))), 2.5, human,
                    reference or Reference.constant(so3.exp(np.array([0.6, -0.4, 0.3]))),
                    R_l0=so3.exp(np.array([0.3, 0.5, -0.2])),
                    autonomous=autonomous_input(autonomous, n, seed))


@pytest.mark.parametrize("autonomous", ["zero", "consensus", "random"])
@pytest.mark.parametrize("which", ["lti", "lti3", "static", "vr", "signal"])
def test_compiled_field_equals_the_python_field(which, autonomous):
    rng = np.random.default_rng(7)
    scenario = _scenario(_humans(rng)[which], autonomous).validate()
    compiled = stepper(scenario, "compiled")
    assert isinstance(compiled, CompiledStepper)
    loop = ClosedLoop(scenario)
    Y, x = scenario.initial_state()
    Y = so3.exp(0.3 * rng.standard_normal((Y.shape[0], 3))) @ Y  # a generic state
    x = x + rng.standard_normal(x.shape[0])
    for t in (0.0, 0.37):
        held = loop.hold(t, Y)
        F, g = loop.field(held)(t, Y, x)
        Fc, gc = compiled.field(t, Y, x, compiled.hold(t, Y))
        assert np.abs(Fc - F).max() < 1e-13 * (1 + np.abs(F).max())
        assert np.abs(gc - g).max() < 1e-13 * (1 + np.abs(g).max())


@pytest.mark.parametrize("which", ["lti", "vr", "signal"])
def test_compiled_runs_agree_with_python_runs(which):
    rng = np.random.default_rng(3)
    refs = Reference.switching([so3.exp(v) for v in 0.8 * rng.standard_normal((3, 3))], 0.5)
    scenario = _scenario(_humans(rng)[which], "consensus", reference=refs)
    a = simulate(scenario, 1.2, engine="compiled")
    b = simulate(scenario, 1.2, engine="python")
    for name in ("R_bar", "R_l", "R_r", "x", "dbar", "coherence", "final_bodies"):
        assert np.abs(getattr(a, name) - getattr(b, name)).max() < 1e-12, name


def test_python_engine_is_the_definition_bit_for_bit():
    """engine='python' steps exactly as CF4 on ClosedLoop.field (the previous simulator)."""
    scenario = _scenario(VROperator(), "consensus", n=4).validate()
    run = simulate(scenario, 0.25, engine="python")
    loop = ClosedLoop(scenario)
    Y, x = scenario.initial_state()
    dt = run.h
    for k in range(run.t.shape[0] - 1):
        held = loop.hold(k * dt, Y)
        assert np.array_equal(run.R_bar[k], Y[scenario.n]) and np.array_equal(run.x[k], x)
        Y, x = cf4_mixed_step(loop.field(held), k * dt, Y, x, dt)
    assert np.array_equal(run.final_bodies, Y[: scenario.n])
    assert np.array_equal(run.R_l[-1], Y[scenario.n + 1]) and np.array_equal(run.x[-1], x)


def test_the_compiled_vr_hold_is_the_models_hold():
    op = VROperator()
    compiled = stepper(_scenario(op, "zero"), "compiled")
    rng = np.random.default_rng(0)
    n = compiled.n
    for _ in range(50):
        Y = np.concatenate([np.eye(3)[None].repeat(n + 1, 0), so3.random_rotations(1, rng)])
        R_r = so3.random_rotations(1, rng)[0]
        compiled.rotations[0] = R_r
        ours = compiled.hold(0.0, Y).human
        assert np.abs(ours - op.hold(0.0, Y[n + 1], R_r)).max() < 1e-14


def test_unknown_parts_fall_back_to_the_python_field():
    class Custom(Human):
        def command(self, t, x, e, R_l, held):
            return np.array([e[0], 0.0, 0.0])

    class Pull(Autonomous):
        def __call__(self, t, R):
            return np.ones((R.shape[0], 3))

    scenario = _scenario(Custom(), "zero")
    assert type(stepper(scenario)) is Stepper
    with pytest.raises(VerifyInputError, match="compiled engine"):
        stepper(scenario, "compiled")
    scenario = _scenario(StaticGainHuman(), "zero")
    scenario.autonomous = Pull()
    assert type(stepper(scenario)) is Stepper
    with pytest.raises(VerifyInputError, match="unknown engine"):
        simulate(scenario, 0.1, engine="fast")


def test_a_replaced_law_falls_back_to_the_python_field(monkeypatch):
    """Mutation tests replace ClosedLoop's laws; the compiled copy must not hide that."""
    import verify.sim.scenario as scenario_module

    scenario = _scenario(StaticGainHuman(), "consensus")
    assert isinstance(stepper(scenario), CompiledStepper)
    monkeypatch.setattr(scenario_module, "stealthy_input", lambda R, w: w)
    assert type(stepper(scenario)) is Stepper
    monkeypatch.undo()
    monkeypatch.setattr(ClosedLoop, "leader_velocity", lambda self, R_l, R_bar, w: w)
    assert type(stepper(scenario)) is Stepper


def test_compiled_field_reports_cancelling_directions():
    R0 = so3.exp(np.array([[1.4, 0.0, 0.0], [-1.4, 0.0, 0.0]]))
    scenario = Scenario(R0, 1.0, StaticGainHuman(), Reference.constant(np.eye(3)),
                        autonomous=autonomous_input("consensus", 2))
    compiled = stepper(scenario.validate(), "compiled")
    Y, x = scenario.initial_state()
    Y[:2] = so3.exp(np.array([[np.pi / 2, 0.0, 0.0], [-np.pi / 2, 0.0, 0.0]]))  # d = +-e2
    with pytest.raises(DbarUndefinedError):
        compiled.field(0.0, Y, x, compiled.hold(0.0, Y))
    with pytest.raises(DbarUndefinedError):
        compiled.step(0.0, Y, x, 0.01, compiled.hold(0.0, Y))


@pytest.mark.parametrize("scale", [0.0, 1e-9, 1e-4, 0.0999, 0.1001, 1.0, 3.0, np.pi])
def test_kernel_exponential_matches_rodrigues_on_both_sides_of_the_series(scale):
    rng = np.random.default_rng(11)
    W = rng.standard_normal((50, 3))
    W *= scale / np.linalg.norm(W, axis=1, keepdims=True)
    Y = so3.random_rotations(50, rng)
    out = np.empty_like(Y)
    kernels.exp_mul(W, 1.0, Y, out)
    assert np.abs(out - so3.exp(W) @ Y).max() < 4e-16 * (1 + 4 * scale)
    assert so3.orthogonality_error(out).max() < 2e-15


def test_compiled_long_run_keeps_rotations_in_so3():
    scenario = _scenario(_humans(np.random.default_rng(2))["lti"], "consensus", n=6)
    run = simulate(scenario, 20.0, engine="compiled")
    R = np.concatenate([run.R_bar, run.R_l, run.final_bodies])
    assert so3.orthogonality_error(R).max() < 1e-12
    assert np.abs(np.linalg.det(R) - 1).max() < 1e-12


@pytest.mark.parametrize("which", ["lti", "storage", "static", "vr", "signal"])
def test_batched_energy_equals_the_per_sample_definition(which):
    from verify.sim.energy import energy

    rng = np.random.default_rng(4)
    humans = _humans(rng)
    humans["storage"] = LTIHuman(-np.eye(2), np.eye(2), np.eye(2), np.zeros((2, 2)),
                                 P=np.eye(2))  # 1/(s+1) I with its KYP storage |x|^2/2
    refs = Reference.switching([so3.exp(v) for v in 0.8 * rng.standard_normal((3, 3))], 0.6)
    run = simulate(_scenario(humans[which], "consensus", reference=refs), 1.5)
    for prefer in (True, False):
        fast, slow = energy(run, prefer), energy(run, prefer, batched=False)
        assert fast.uses_storage == slow.uses_storage == (prefer and which in ("storage",
                                                                               "static"))
        assert np.abs(fast.V_dot - slow.V_dot).max() < 1e-13 * (1 + np.abs(slow.V).max())
        if slow.uses_storage:
            assert np.abs(fast.S_h_storage - slow.S_h_storage).max() < 1e-15
        assert np.array_equal(fast.V_dot_bound, slow.V_dot_bound)


# ---------------------------------------------------------------- whole-run kernel


def _step_by_step(monkeypatch):
    """Disable the whole-run kernel: every step through the stepper, one call each."""
    import verify.sim.run as run_module

    monkeypatch.setattr(run_module, "run_fixed",
                        lambda stepper, rec, Y, x, k0, k1, dt: (Y, x, k0, -1))


@pytest.mark.parametrize("which", ["lti", "lti3", "static", "vr"])
@pytest.mark.parametrize("autonomous", ["zero", "consensus"])
def test_whole_run_kernel_equals_the_step_loop(which, autonomous, monkeypatch):
    """cf4_run takes the same steps as the per-step loop: states bitwise equal, dbar to
    rounding (one norm formula differs), with directions and a switching reference."""
    rng = np.random.default_rng(3)
    ref = Reference.switching([so3.exp(v) for v in 0.8 * rng.standard_normal((3, 3))], 0.4)
    sc = _scenario(_humans(rng)[which], autonomous, reference=ref)
    fast = simulate(sc, 1.1, 1 / 120, direction_every=5)
    with monkeypatch.context() as m:
        _step_by_step(m)
        slow = simulate(sc, 1.1, 1 / 120, direction_every=5)
    for name in ("R_bar", "R_l", "R_r", "x", "d", "final_bodies"):
        assert np.array_equal(getattr(fast, name), getattr(slow, name)), name
    assert np.allclose(fast.dbar, slow.dbar, rtol=0, atol=1e-15)
    assert np.allclose(fast.coherence, slow.coherence, rtol=1e-15, atol=0)


def test_whole_run_kernel_hands_the_vr_branch_cut_to_python(monkeypatch):
    """With d_r opposite d_l the VR tilt is near pi, outside the kernel's branch: those
    steps go through the model's hold, and the run equals the per-step loop."""
    R_r = so3.exp(np.array([np.pi - 0.01, 0.0, 0.0]))  # d_r almost -e3, the leader at e3
    sc = Scenario(so3.exp(0.05 * np.random.default_rng(0).standard_normal((3, 3))), 2.0,
                  VROperator(), Reference.constant(R_r), R_l0=np.eye(3))
    held = kernels.vr_command(np.eye(3), R_r, 0.8, 1.0, 1.0, np.empty(3))
    assert not held  # the case is really the fallback
    fast = simulate(sc, 0.5, 1 / 120)
    with monkeypatch.context() as m:
        _step_by_step(m)
        slow = simulate(sc, 0.5, 1 / 120)
    assert np.array_equal(fast.R_l, slow.R_l) and np.array_equal(fast.x, slow.x)


def test_whole_run_kernel_stops_where_dbar_is_lost():
    """A state whose directions cancel, handed to the kernel at step 5: it stops there
    with DBAR_UNDEFINED (simulate then raises with t = 5 dt)."""
    from verify.sim.fused import run_fixed
    from verify.sim.trajectory import Recorder

    sc = Scenario(so3.exp(0.1 * np.ones((2, 3))), 2.0, StaticGainHuman(np.eye(2)),
                  Reference.constant(np.eye(3)), R_l0=np.eye(3),
                  autonomous=autonomous_input("consensus", 2))  # A(d) needs dbar
    st = stepper(sc)
    Y, x = sc.initial_state()
    Y[1] = Y[0] @ so3.exp(np.array([np.pi, 0.0, 0.0]))  # d_2 = -d_1
    rec = Recorder(sc, 10, 0.01, x.shape[0], 0)
    _, _, k, status = run_fixed(st, rec, Y, x, 5, 10, 0.01)
    assert (k, status) == (5, kernels.DBAR_UNDEFINED)
    assert np.array_equal(rec.R_l[5], np.eye(3))  # sample 5 is the state the step left from


# ---------------------------------------------------------------- the noisy operator


@pytest.mark.parametrize("adaptive", [False, True])
def test_noisy_operator_compiled_equals_the_python_field(adaptive):
    """ReactingNoisyHuman on the kernels (opt-in, engine="compiled"): held noise on the
    output and no B e, D e before each reaction, as the Python field to rounding."""
    from verify.sim.noisy_humans import ReactingNoisyHuman

    rng = np.random.default_rng(5)
    ref = Reference.switching([so3.exp(v) for v in 0.7 * rng.standard_normal((3, 3))], 0.5)
    A = np.array([[-0.5, 2.0], [-2.0, -0.5]])
    human = ReactingNoisyHuman(A, np.array([[1.0, 0.3], [0.0, 1.0]]), np.eye(2),
                               0.2 * np.eye(2), noise=0.05 * rng.standard_normal((200, 2)),
                               reaction=[10, 25, 5], reference=ref, h=1 / 120)
    sc = _scenario(human, "consensus", reference=ref)
    assert not isinstance(stepper(sc), CompiledStepper)  # "auto" keeps the definition
    assert isinstance(stepper(sc, "compiled"), CompiledStepper)
    kw = {"adaptive": True, "rtol": 1e-9, "atol": 1e-11} if adaptive else {}
    fast = simulate(sc, 1.4, 1 / 120, engine="compiled", **kw)
    slow = simulate(sc, 1.4, 1 / 120, engine="python", **kw)
    assert np.max(np.abs(fast.R_l - slow.R_l)) < 1e-12
    assert np.max(np.abs(fast.x - slow.x)) < 1e-12
    assert np.max(np.abs(fast.dbar - slow.dbar)) < 1e-12
