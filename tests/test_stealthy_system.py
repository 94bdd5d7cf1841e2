"""Section 2 objects numerically, on hypothesis networks n = 1..200 and near-cancelling ones."""

import casadi as ca
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as hst

from verify import so3
from verify.errors import DbarUndefinedError, VerifyInputError
from verify.strategies import near_cancelling_networks, networks
from verify.system import laws
from verify.system import stealthy as st

EPS = np.finfo(float).eps


def _bound(R):
    return st.projector_rounding_bound(R)[0]


@given(
    hst.one_of(networks(max_bodies=200), near_cancelling_networks(max_bodies=200)),
    hst.integers(0, 2**31),
)
def test_structured_projector_is_stealthy(R, seed):
    x = np.random.default_rng(seed).standard_normal(3 * R.shape[0])
    y = st.apply_projector(R, x)
    assert np.linalg.norm(st.dbar_rate_unscaled(R, y.reshape(-1, 3))) <= _bound(R) * np.linalg.norm(
        x
    )
    # idempotent: A(Ax) = Ax
    assert np.linalg.norm(st.apply_projector(R, y) - y) <= _bound(R) * np.linalg.norm(x)


@given(
    hst.one_of(networks(max_bodies=40), near_cancelling_networks(max_bodies=40)),
    hst.integers(0, 2**31),
)
def test_dense_and_structured_projectors_agree(R, seed):
    x = np.random.default_rng(seed).standard_normal(3 * R.shape[0])
    A = st.projector_dense(R)
    assert np.linalg.norm(A @ x - st.apply_projector(R, x)) <= _bound(R) * np.linalg.norm(x)
    assert np.max(np.abs(A - A.T)) <= _bound(R)
    assert abs(np.trace(A) - (3 * R.shape[0] - 2)) <= 3 * R.shape[0] * _bound(R)


@given(networks(max_bodies=60))
def test_w_annihilates_dbar_and_has_rank_two(R):
    W = st.w_matrix(R)
    assert np.linalg.norm(W @ st.dbar(R)) <= 1e3 * EPS * np.linalg.norm(W)
    sv = np.linalg.svd(W, compute_uv=False)
    assert sv[2] <= 1e3 * EPS * sv[0] < sv[1]


@given(networks(max_bodies=30))
def test_dbar_jacobian_matches_casadi(R):
    n = R.shape[0]
    d = ca.SX.sym("d", 3 * n)
    s = sum(d[3 * i : 3 * i + 3] for i in range(n))
    J_ad = np.array(
        ca.Function("J", [d], [ca.jacobian(s / ca.norm_2(s), d)])(st.directions(R).reshape(-1))
    )
    J = st.dbar_jacobian(R)
    assert np.max(np.abs(J_ad - J)) <= 1e-12 * np.max(np.abs(J))


@given(networks(max_bodies=50), hst.integers(0, 2**31))
def test_dbar_turns_with_the_human_command_only(R, seed):
    rng = np.random.default_rng(seed)
    omega_tilde = rng.standard_normal(3)
    omega = laws.human_body_velocities(R, omega_tilde) + st.stealthy_input(
        R, rng.standard_normal((R.shape[0], 3))
    )
    rate = st.dbar_jacobian(R) @ (st.s_matrix(R) @ omega.reshape(-1))
    scale = 1 + np.abs(omega).max() * R.shape[0] / np.linalg.norm(st.direction_sum(R))
    assert np.max(np.abs(rate - np.cross(omega_tilde, st.dbar(R)))) <= _bound(R) * scale


def test_paper_gram_matrix_is_numerically_singular():
    R = so3.random_rotations(5, np.random.default_rng(3))
    W = st.w_matrix(R)
    assert np.linalg.cond(W.T @ W) > 1e12  # exactly singular: W dbar = 0


def test_undefined_dbar_is_a_clear_error():
    opposite = so3.quaternion_to_matrix(np.array([[1.0, 0, 0, 0], [0.0, 1, 0, 0]]))
    with pytest.raises(DbarUndefinedError, match="undefined"):
        st.dbar(opposite)
    with pytest.raises(DbarUndefinedError):
        st.apply_projector(opposite, np.ones(6))
    with pytest.raises(VerifyInputError, match="at least one body"):
        st.as_network(np.zeros((0, 3, 3)))


def test_quasi_average_initial_points_along_dbar():
    rng = np.random.default_rng(5)
    for _ in range(20):
        R = so3.random_rotations(7, rng)
        Rb = laws.quasi_average_initial(R, yaw=rng.uniform(-3, 3))
        assert np.allclose(Rb[:, 2], st.dbar(R), atol=1e-14)
        assert so3.orthogonality_error(Rb) < 1e-14
    assert np.allclose(laws.rotation_taking_e3_to(np.array([0, 0, -1.0]))[:, 2], [0, 0, -1])


def test_interface_and_leader_laws_match_the_paper_formulas():
    rng = np.random.default_rng(6)
    Rb, Rl = so3.random_rotations(2, rng)
    k = 2.5
    w = laws.interface_velocity(Rb, Rl, k)
    M = Rb.T @ Rl
    assert np.allclose(
        w, k * Rb @ np.array([M[2, 1] - M[1, 2], M[0, 2] - M[2, 0], M[1, 0] - M[0, 1]]) / 2
    )
    # eq. (7): hat(omega~) R-bar = k_s R-bar sk(R-bar^T R_l)
    assert np.allclose(so3.hat(w) @ Rb, k * Rb @ so3.sk(M), atol=1e-14)
    wh = rng.standard_normal(3)
    assert np.allclose(laws.leader_velocity(Rl, Rb, k, wh), k * so3.vee(Rl.T @ Rb) + Rl.T @ wh)
    with pytest.raises(VerifyInputError, match="k_s"):
        laws.interface_velocity(Rb, Rl, -1.0)
    with pytest.raises(VerifyInputError, match="k_s"):
        laws.interface_velocity(Rb, Rl, float("nan"))
