"""The Lie-group integrators on SO(3): CF4 has order 4, Lie-Euler order 1, no drift."""

import numpy as np

from verify import so3
from verify.sim.lie_group import cf4_step, integrate, lie_euler_step


def _field(t, Y):
    """A smooth, state-dependent, time-varying spatial velocity for a batch of rotations."""
    return (np.sin(t) * np.array([0.3, -0.2, 0.5])
            + 0.8 * so3.vee(Y) + 0.4 * np.roll(Y[:, :, 2], 1, axis=0))


def _start(seed=4, m=5):
    return so3.random_rotations(m, np.random.default_rng(seed))


def test_cf4_converges_at_order_four_and_euler_at_order_one():
    Y0 = _start()
    ref = integrate(_field, Y0, 1.0, 1 / 960)
    errs = [np.abs(integrate(_field, Y0, 1.0, h) - ref).max() for h in (1 / 15, 1 / 30, 1 / 60)]
    orders = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    assert np.all(orders > 3.5), orders
    e1 = [np.abs(integrate(_field, Y0, 1.0, h, step=lie_euler_step) - ref).max()
          for h in (1 / 60, 1 / 120)]
    assert 0.8 < np.log2(e1[0] / e1[1]) < 1.3


def test_rotations_stay_orthogonal_without_projection():
    Y = integrate(_field, _start(seed=7), 5.0, 1 / 120)
    assert so3.orthogonality_error(Y).max() < 1e-12
    assert np.all(np.abs(np.linalg.det(Y) - 1) < 1e-12)


def test_constant_rotation_is_exact():
    w = np.array([0.3, -0.2, 0.5])
    Y = integrate(lambda t, Y: np.broadcast_to(w, (1, 3)), np.eye(3)[None], 2.0, 0.1, step=cf4_step)
    assert np.abs(Y[0] - so3.exp(2.0 * w)).max() < 1e-14
