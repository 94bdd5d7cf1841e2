"""The SO(3) kernel: orthogonality, exp/log round trips (also within 1e-6 of pi), batches."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.linalg import expm

from verify import so3
from verify.errors import NotARotationError, VerifyInputError
from verify.strategies import rotations, rotations_near_angle

vectors = st.lists(st.floats(-10, 10, allow_nan=False), min_size=3, max_size=3).map(np.array)


@given(vectors, vectors)
def test_hat_is_the_cross_product_and_vee_inverts_it(v, w):
    assert np.allclose(so3.hat(v) @ w, np.cross(v, w), atol=1e-12)
    assert np.array_equal(so3.vee(so3.hat(v)), v)
    assert np.array_equal(so3.hat(v), -so3.hat(v).T)


@given(vectors)
def test_exp_matches_matrix_exponential_and_is_a_rotation(w):
    R = so3.exp(w)
    assert np.allclose(R, expm(so3.hat(w)), atol=1e-11 * (1 + np.linalg.norm(w) ** 2))
    assert so3.orthogonality_error(R) < 1e-14
    assert abs(np.linalg.det(R) - 1) < 1e-14


@given(st.floats(0, np.pi - 1e-9), vectors)
def test_log_inverts_exp_inside_the_ball(theta, axis):
    if np.linalg.norm(axis) < 1e-6:
        axis = np.array([1.0, 0, 0])
    w = axis / np.linalg.norm(axis) * theta
    assert np.allclose(so3.log(so3.exp(w)), w, atol=1e-12)


@given(rotations_near_angle(np.pi, spread=1e-6))
def test_log_is_accurate_within_1e6_of_pi(R):
    w = so3.log(R)
    assert np.linalg.norm(w) <= np.pi + 1e-15
    # round trip on the group (the sign of w is ambiguous only at exactly pi)
    assert np.max(np.abs(so3.exp(w) - R)) < 1e-14
    assert abs(np.linalg.norm(w) - so3.rotation_angle(R)) < 1e-12


def test_log_near_pi_recovers_the_axis_and_angle():
    axis = np.array([1.0, 2.0, -2.0]) / 3.0
    for gap in (1e-6, 1e-9, 1e-12, 0.0):
        w = axis * (np.pi - gap)
        got = so3.log(so3.exp(w))
        if gap == 0.0:
            got = got if got @ axis > 0 else -got  # both signs are the principal log at pi
        assert np.max(np.abs(got - w)) < 1e-13, gap


@given(rotations(), rotations())
def test_geodesic_distance_is_symmetric_and_matches_log(R1, R2):
    d = so3.geodesic_distance(R1, R2)
    assert abs(d - so3.geodesic_distance(R2, R1)) < 1e-12
    assert abs(d - np.linalg.norm(so3.log(R1.T @ R2))) < 1e-9
    assert 0 <= d <= np.pi


def test_batch_shapes_are_preserved():
    rng = np.random.default_rng(0)
    w = rng.standard_normal((4, 5, 3))
    R = so3.exp(w)
    assert R.shape == (4, 5, 3, 3)
    assert so3.log(R).shape == (4, 5, 3)
    assert np.allclose(so3.log(R)[2, 3], so3.log(R[2, 3]))
    assert so3.hat(w).shape == (4, 5, 3, 3)
    assert so3.vee(so3.hat(w)).shape == (4, 5, 3)
    assert so3.rotation_angle(R).shape == (4, 5)
    assert so3.random_rotations((2, 3), rng).shape == (2, 3, 3, 3)
    assert so3.project(R + 1e-3).shape == (4, 5, 3, 3)


def test_random_rotations_are_rotations_and_roughly_uniform():
    R = so3.random_rotations(20000, np.random.default_rng(1))
    assert so3.orthogonality_error(R).max() < 1e-14
    assert np.all(np.abs(np.linalg.det(R) - 1) < 1e-14)
    # Haar measure: E[tr R] = 0 and the angle density is (1 - cos t)/pi: E[angle] = pi/2 + 2/pi
    assert abs(np.trace(R, axis1=1, axis2=2).mean()) < 0.03
    assert abs(so3.rotation_angle(R).mean() - (np.pi / 2 + 2 / np.pi)) < 0.02


@given(rotations())
def test_projection_returns_the_nearest_rotation(R):
    noisy = R + 1e-4 * np.arange(9).reshape(3, 3) / 9
    P = so3.project(noisy)
    assert so3.orthogonality_error(P) < 1e-14 and np.linalg.det(P) > 0
    assert np.max(np.abs(P - R)) < 1e-3
    assert np.allclose(so3.project(R), R, atol=1e-14)


def test_projection_of_a_reflection_is_a_rotation():
    P = so3.project(np.diag([1.0, 1.0, -1.0]))
    assert abs(np.linalg.det(P) - 1) < 1e-14


def test_check_rotations_rejects_bad_input_with_clear_messages():
    with pytest.raises(NotARotationError, match="index 1"):
        so3.check_rotations(np.stack([np.eye(3), 2 * np.eye(3)]))
    with pytest.raises(NotARotationError, match="det"):
        so3.check_rotations(np.diag([1.0, 1.0, -1.0]))
    with pytest.raises(VerifyInputError, match="NaN"):
        so3.check_rotations(np.full((3, 3), np.nan))
    with pytest.raises(VerifyInputError, match="shape"):
        so3.check_rotations(np.eye(2))
    assert so3.check_rotations(np.eye(3)).shape == (3, 3)


def test_sk_and_sym_split_a_matrix():
    M = np.arange(9.0).reshape(3, 3)
    assert np.allclose(so3.sk(M) + so3.sym(M), M)
    assert np.allclose(so3.sk(M), -so3.sk(M).T)
    assert np.allclose(so3.sym(M), so3.sym(M).T)
