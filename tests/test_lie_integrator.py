"""The Lie-group integrator: order 4, orthogonality kept without re-projection."""

import numpy as np

from verify import so3
from verify.sim.closed_loop import OpenLoopHumanSystem, smooth_random_signal
from verify.sim.lie_group import cf4_step, integrate, lie_euler_step
from verify.system.laws import quasi_average_initial
from verify.system.stealthy import dbar


def _system(seed=4, n=5):
    rng = np.random.default_rng(seed)
    R0 = so3.random_rotations(n, rng)
    system = OpenLoopHumanSystem(
        n, 2.5, smooth_random_signal(rng, (3,)), smooth_random_signal(rng, (n, 3), amplitude=0.3)
    )
    Y0 = np.concatenate([R0, quasi_average_initial(R0)[None], so3.random_rotations(1, rng)])
    return system, Y0


def test_cf4_converges_at_order_four_and_euler_at_order_one():
    system, Y0 = _system()
    f = system.spatial_velocities
    ref = integrate(f, Y0, 1.0, 1 / 960)
    errs = [np.abs(integrate(f, Y0, 1.0, h) - ref).max() for h in (1 / 15, 1 / 30, 1 / 60)]
    orders = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    assert np.all(orders > 3.5), orders
    e1 = [
        np.abs(integrate(f, Y0, 1.0, h, step=lie_euler_step) - ref).max() for h in (1 / 60, 1 / 120)
    ]
    assert 0.8 < np.log2(e1[0] / e1[1]) < 1.3


def test_rotations_stay_orthogonal_without_projection():
    system, Y0 = _system(seed=7)
    Y = integrate(system.spatial_velocities, Y0, 5.0, 1 / 120)
    assert so3.orthogonality_error(Y).max() < 1e-12
    assert np.all(np.abs(np.linalg.det(Y) - 1) < 1e-12)


def test_quasi_average_axis_tracks_dbar():
    system, Y0 = _system(seed=9)
    n = system.n
    Y = integrate(system.spatial_velocities, Y0, 2.0, 1 / 120)
    assert np.linalg.norm(Y[n][:, 2] - dbar(Y[:n])) < 1e-8


def test_constant_rotation_is_exact():
    w = np.array([0.3, -0.2, 0.5])
    Y = integrate(lambda t, Y: np.broadcast_to(w, (1, 3)), np.eye(3)[None], 2.0, 0.1, step=cf4_step)
    assert np.abs(Y[0] - so3.exp(2.0 * w)).max() < 1e-14
