"""Error-controlled steps (verify.sim.adaptive) and the independent quaternion reference."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from verify import so3
from verify.errors import VerifyInputError
from verify.inputs.time_grid import step_count
from verify.sim import kernels
from verify.sim.adaptive import hermite_weights, integrate_adaptive
from verify.sim.fused import stepper
from verify.sim.humans import LTIHuman, VROperator
from verify.sim.inputs import Reference, autonomous_input
from verify.sim.run import simulate
from verify.sim.scenario import Scenario
from verify.sim.trajectory import Recorder

A_H = np.array([[-0.5, 2.0], [-2.0, -0.5]])


def _lti(n: int = 4, seed: int = 3, reference: Reference | None = None,
         autonomous: str = "consensus") -> Scenario:
    rng = np.random.default_rng(seed)
    return Scenario(so3.exp(0.4 * rng.standard_normal((n, 3))), 2.0,
                    LTIHuman(A_H, np.eye(2), np.eye(2), 0.2 * np.eye(2)),
                    reference or Reference.constant(so3.exp(np.array([0.7, -0.3, 0.2]))),
                    R_l0=so3.exp(np.array([0.2, 0.5, 0.0])),
                    autonomous=autonomous_input(autonomous, n, seed))


def _errors(run, ref, every: int) -> dict[str, float]:
    return {name: float(np.abs(getattr(run, name) - getattr(ref, name)[::every]).max())
            for name in ("R_bar", "R_l", "x", "dbar", "coherence")}


def test_adaptive_samples_meet_the_tolerance_against_a_fine_fixed_step_run():
    scenario = _lti()
    ref = simulate(scenario, 5.0, 1 / 1920)  # CF4 error ~1e-14 here
    previous = np.inf
    for rtol in (1e-6, 1e-8, 1e-10):
        run = simulate(scenario, 5.0, adaptive=True, rtol=rtol, atol=1e-2 * rtol)
        assert run.t.shape == ref.t[::16].shape and np.allclose(run.t, ref.t[::16])
        worst = max(_errors(run, ref, 16).values())
        assert worst < 10 * rtol, (rtol, worst)
        assert worst < previous
        previous = worst
        assert np.abs(run.final_bodies - ref.final_bodies).max() < 10 * rtol
        assert run.steps < step_count(5.0, 1 / 120)  # fewer steps than the loop rate
    R = np.concatenate([run.R_bar, run.R_l, run.final_bodies])
    assert so3.orthogonality_error(R).max() < 1e-12


def test_adaptive_directions_are_sampled_like_the_fixed_run():
    scenario = _lti(n=3)
    fixed = simulate(scenario, 1.0, direction_every=7)
    run = simulate(scenario, 1.0, adaptive=True, rtol=1e-10, direction_every=7)
    assert np.array_equal(run.direction_times, fixed.direction_times)
    assert np.abs(run.d - fixed.d).max() < 1e-8


def _logged(scenario: Scenario, seconds: float, **kw):
    """Run the adaptive integrator recording every step (t, h) and every hold time."""
    s = stepper(scenario.validate())
    steps, holds = [], []
    step, hold = s.step, s.hold

    def logged_step(t, Y, x, h, held):
        steps.append((t, h))
        return step(t, Y, x, h, held)

    def logged_hold(t, Y):
        holds.append(t)
        return hold(t, Y)

    s.step, s.hold = logged_step, logged_hold
    n_steps = step_count(seconds, 1 / 120)
    Y, x = scenario.initial_state()
    rec = Recorder(scenario, n_steps, seconds / n_steps, x.shape[0], 0)
    run = integrate_adaptive(s, rec, Y, x, seconds, rtol=kw.get("rtol", 1e-8),
                             atol=kw.get("atol", 1e-10))
    return run, steps, holds


def test_reference_switches_are_step_ends():
    rng = np.random.default_rng(5)
    period = 0.7071  # not a multiple of the loop period or of any natural step
    refs = Reference.switching([so3.exp(v) for v in 0.6 * rng.standard_normal((4, 3))], period)
    run, steps, _ = _logged(_lti(reference=refs), 2.5)
    switches = refs.switch_times(2.5)
    assert len(switches) == 3
    for ts in switches:
        # no step crosses a switch (beyond the rounding of t + h)
        assert not any(t < ts and t + h - ts > 4 * np.spacing(ts) for t, h in steps), ts
        assert any(t == ts for t, _ in steps), ts  # and a step starts exactly there
    # each sample's R_r is the reference of its time
    for k, t in enumerate(run.t):
        assert np.array_equal(run.R_r[k], refs.at(t))


def test_a_held_command_is_taken_at_every_loop_period_only():
    rng = np.random.default_rng(6)
    scenario = Scenario(so3.exp(0.4 * rng.standard_normal((3, 3))), 3.0, VROperator(),
                        Reference.switching([np.eye(3), so3.exp(np.array([0.8, 0.0, 0.0]))],
                                            0.5), autonomous=autonomous_input("consensus", 3))
    run, steps, holds = _logged(scenario, 1.0)
    grid = run.t
    assert np.array_equal(np.unique(holds), grid)  # held values taken on the grid only
    for t, h in steps:
        k = np.searchsorted(grid, t, side="right")
        assert k >= len(grid) or t + h <= grid[k] * (1 + 1e-15), (t, h)
    fixed = simulate(scenario, 1.0)
    # the same held inputs as the fixed-step run: they agree to the integration error
    assert max(_errors(run, fixed, 1).values()) < 1e-7


def test_log_and_dexpinv_kernel():
    """p = log(Y1 Y0^T) and p' = dexp^{-1}_p(F): exp(p + s p') Y0 moves with velocity F."""
    rng = np.random.default_rng(9)
    p = rng.standard_normal((20, 3))
    p *= rng.uniform(0.0, 1.9, (20, 1)) / np.linalg.norm(p, axis=1, keepdims=True)
    p[0] = 0.0
    F = rng.standard_normal((20, 3))
    Y0 = so3.random_rotations(20, rng)
    Y1 = so3.exp(p) @ Y0
    P, D = np.empty((20, 3)), np.empty((20, 3))
    assert kernels.log_dexpinv(Y1, Y0, F, 1.0, P, D)
    assert np.abs(P - p).max() < 1e-14
    eps = 1e-6
    dR = (so3.exp(p + eps * D) - so3.exp(p - eps * D)) / (2 * eps)
    velocity = so3.vee(dR @ so3.transpose(so3.exp(p)))
    assert np.abs(velocity - F).max() < 1e-8
    far = so3.exp(np.array([[2.5, 0.0, 0.0]])) @ Y0[:1]
    assert not kernels.log_dexpinv(far, Y0[:1], F[:1], 1.0, P[:1], D[:1])


def test_hermite_weights_reproduce_quintics():
    rng = np.random.default_rng(1)
    c = rng.standard_normal(6)
    poly = np.polynomial.Polynomial(c)
    data = np.array([poly(0), poly(0.5), poly(1), poly.deriv()(0), poly.deriv()(0.5),
                     poly.deriv()(1)])
    s = np.linspace(0, 1, 13)
    assert np.abs(hermite_weights(s) @ data - poly(s)).max() < 1e-13


@pytest.mark.parametrize("rtol, atol", [(-1e-8, 1e-10), (np.nan, 1e-10), (1e-8, np.inf),
                                        (0.0, 0.0), (1e-17, 1e-18), ("1e-8", 1e-10),
                                        (None, 1e-10), (1e-8, [1e-10])])
def test_bad_tolerances_are_rejected(rtol, atol):
    with pytest.raises(VerifyInputError):
        simulate(_lti(n=2), 0.1, adaptive=True, rtol=rtol, atol=atol)


def test_independent_quaternion_dop853_implementation_agrees():
    """benchmarks/quaternion_reference.py (quaternions, solve_ivp DOP853) vs ours."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
    try:
        from quaternion_reference import QuaternionLoop
    finally:
        sys.path.pop(0)
    n, seconds = 4, 2.0
    scenario = _lti(n=n).validate()
    Y0, x0 = scenario.initial_state()
    human = scenario.human
    loop = QuaternionLoop(n, scenario.k_s, human.A, human.B, human.C, human.D,
                          scenario.reference.rotations[0])
    z0 = loop.initial(Y0[:n], Y0[n], Y0[n + 1], x0[:-1])
    assert np.abs(loop.rotations(z0) - Y0).max() < 1e-15
    res = loop.solve(z0, seconds, np.array([1.0, seconds]), rtol=1e-12, atol=1e-14)
    for kw in ({"h": 1 / 960}, {"adaptive": True, "rtol": 1e-11, "atol": 1e-13}):
        run = simulate(scenario, seconds, **kw)
        for j, k in ((0, run.t.shape[0] // 2), (1, -1)):
            assert abs(run.t[k] - res.t[j]) < 1e-12
            R = loop.rotations(res.y[:, j])
            assert np.abs(R[n] - run.R_bar[k]).max() < 1e-10, kw
            assert np.abs(R[n + 1] - run.R_l[k]).max() < 1e-10, kw
            assert np.abs(res.y[4 * (n + 2):, j] - run.x[k]).max() < 1e-10, kw
        assert np.abs(loop.rotations(res.y[:, -1])[:n] - run.final_bodies).max() < 1e-10, kw
