"""Public hypothesis strategies for users' own test suites.

>>> from hypothesis import given
>>> from verify.strategies import networks, scenarios
>>> @given(networks(max_bodies=50))
... def test_my_controller(R): ...

* rotations: :func:`rotations`, :func:`rotations_near_angle`, :func:`rotations_within`;
* networks (n, 3, 3) with a well-defined dbar: :func:`networks`,
  :func:`near_cancelling_networks`;
* LTI models (``verify.passivity.model.LTIModel``): :func:`passive_lti_models`,
  :func:`non_passive_lti_models`;
* simulator humans meeting the passivity item of Assumption 1: :func:`passive_humans`;
* closed-loop scenarios (``verify.sim.scenario.Scenario``) meeting Assumption 1 at
  t = 0: :func:`scenarios`.
"""

from __future__ import annotations

import numpy as np
from hypothesis import assume
from hypothesis import strategies as st
from hypothesis.errors import InvalidArgument
from hypothesis.extra import numpy as hnp

from verify.sim.inputs import AUTONOMOUS_KINDS
from verify.so3 import exp, quaternion_to_matrix
from verify.system.stealthy import DBAR_RELATIVE_TOLERANCE
from verify.validation import integer_at_least, message, one_of, real_in

_unit_floats = st.floats(-1.0, 1.0, allow_nan=False, allow_infinity=False, width=64)


def _quaternion_rows(n: int):
    return hnp.arrays(np.float64, (n, 4), elements=_unit_floats)


def _to_rotations(q: np.ndarray) -> np.ndarray:
    q = q.copy()
    small = np.linalg.norm(q, axis=-1) < 1e-3
    q[small] = np.array([1.0, 0.0, 0.0, 0.0])
    return quaternion_to_matrix(q)


def rotations() -> st.SearchStrategy[np.ndarray]:
    """Single rotation matrices (3, 3), from quaternions with shrinkable entries."""
    return _quaternion_rows(1).map(lambda q: _to_rotations(q)[0])


def rotations_near_angle(angle: float, *, spread: float = 1e-6) -> st.SearchStrategy[np.ndarray]:
    """Rotations whose angle lies within ``spread`` of ``angle`` (e.g. pi for the log).

    ``angle`` is a rotation angle in [0, pi]; angles drawn past either end are folded
    back to it (a rotation by pi + e is one by pi - e about the opposite axis).
    """
    real_in("angle", angle, 0.0, np.pi, error=InvalidArgument,
            fix="rotation angles lie in [0, pi]; for theta > pi use 2*pi - theta")
    real_in("spread", spread, 0.0, np.pi, error=InvalidArgument)
    return _rotations_near_angle(float(angle), float(spread))


@st.composite
def _rotations_near_angle(draw, angle: float, spread: float) -> np.ndarray:
    axis = draw(hnp.arrays(np.float64, 3, elements=_unit_floats))
    if np.linalg.norm(axis) < 1e-3:
        axis = np.array([0.0, 0.0, 1.0])
    offset = draw(st.floats(-spread, spread, allow_nan=False))
    theta = float(np.clip(angle + offset, 0.0, np.pi))
    return exp(axis / np.linalg.norm(axis) * theta)


def networks(*, min_bodies: int = 1, max_bodies: int = 200) -> st.SearchStrategy[np.ndarray]:
    """Networks (n, 3, 3) with a well-defined dbar."""
    integer_at_least("min_bodies", min_bodies, 1, error=InvalidArgument)
    integer_at_least("max_bodies", max_bodies, min_bodies, error=InvalidArgument)
    return _networks(min_bodies, max_bodies)


@st.composite
def _networks(draw, min_bodies: int, max_bodies: int) -> np.ndarray:
    n = draw(st.integers(min_bodies, max_bodies))
    R = _to_rotations(draw(_quaternion_rows(n)))
    s = np.linalg.norm(R[:, :, 2].sum(axis=0))
    assume(s > 1e3 * DBAR_RELATIVE_TOLERANCE * n)
    return R


def near_cancelling_networks(*, max_bodies: int = 200) -> st.SearchStrategy[np.ndarray]:
    """Networks whose directions nearly cancel: |sum d_i| from 1e-6 to 1e-2."""
    integer_at_least("max_bodies", max_bodies, 2, error=InvalidArgument)
    return _near_cancelling_networks(max_bodies)


@st.composite
def _near_cancelling_networks(draw, max_bodies: int) -> np.ndarray:
    from verify.random_networks import near_cancelling_network

    n = draw(st.integers(2, max_bodies))
    residual = 10.0 ** draw(st.floats(-6.0, -2.0))
    seed = draw(st.integers(0, 2**32 - 1))
    return near_cancelling_network(np.random.default_rng(seed), n, residual)


# --------------------------------------------------------------------------- human models

_gains = st.floats(0.3, 3.0, allow_nan=False)


def _matrix(shape: tuple[int, int], bound: float = 1.0):
    return hnp.arrays(np.float64, shape, elements=st.floats(-bound, bound, allow_nan=False,
                                                              width=64))


def passive_lti_models(*, max_states: int = 3, ports: int = 2) -> st.SearchStrategy:
    """Passive LTI models (port-Hamiltonian with a strictly passive feedthrough).

    The free matrices are drawn and assembled by
    :func:`verify.passivity.port_hamiltonian.port_hamiltonian` (x^T Q x / 2 is a storage;
    D + D^T > 0 keeps the KYP LMI strictly feasible after floating-point rounding of the
    entries).
    """
    integer_at_least("max_states", max_states, 1, error=InvalidArgument)
    integer_at_least("ports", ports, 1, error=InvalidArgument)
    return _passive_lti_models(max_states, ports)


@st.composite
def _passive_lti_models(draw, max_states: int, ports: int):
    from verify.passivity.port_hamiltonian import port_hamiltonian

    n = draw(st.integers(1, max_states))
    J = draw(_matrix((n, n)))
    L = draw(_matrix((n, n)))
    M = draw(_matrix((n, n)))
    G = draw(_matrix((n, ports), 2.0))
    N = draw(_matrix((ports, ports)))
    return port_hamiltonian(J, L, M, G, N, draw(_gains))


def non_passive_lti_models(*, max_states: int = 3, ports: int = 2) -> st.SearchStrategy:
    """Stable LTI models that are not passive.

    Either a passive model with its feedthrough pushed negative (nu(inf) < 0), or a
    lagging diagonal c / (s + a)^2 per port, whose phase passes -90 degrees.
    """
    integer_at_least("max_states", max_states, 1, error=InvalidArgument)
    integer_at_least("ports", ports, 1, error=InvalidArgument)
    return _non_passive_lti_models(max_states, ports)


@st.composite
def _non_passive_lti_models(draw, max_states: int, ports: int):
    from verify.passivity.model import from_state_space

    if draw(st.booleans()):
        base = draw(_passive_lti_models(max_states, ports))
        shift = draw(st.floats(0.5, 3.0)) + float(np.max(np.linalg.eigvalsh(
            0.5 * (base.D + base.D.T))))
        return from_state_space(base.A, base.B, base.C, base.D - shift * np.eye(ports),
                                name="port-Hamiltonian with negative feedthrough")
    a = draw(st.floats(0.5, 3.0))
    c = draw(st.floats(1.0, 10.0))
    # c / (s + a)^2 per port: x1' = -a x1 + u, x2' = -a x2 + x1, y = c x2
    A1 = np.array([[-a, 0.0], [1.0, -a]])
    A = np.kron(np.eye(ports), A1)
    B = np.kron(np.eye(ports), np.array([[1.0], [0.0]]))
    C = np.kron(np.eye(ports), np.array([[0.0, c]]))
    return from_state_space(A, B, C, np.zeros((ports, ports)), name="second-order lag")


def passive_humans(*, max_states: int = 3) -> st.SearchStrategy:
    """Human models for the simulator that satisfy the passivity item of Assumption 1.

    A static gain K with K + K^T > 0, or an LTI model with an exactly checked KYP
    certificate from the passivity gate (its P gives the storage x^T P x / 2).
    """
    integer_at_least("max_states", max_states, 1, error=InvalidArgument)
    return _passive_humans(max_states)


@st.composite
def _passive_humans(draw, max_states: int):
    from verify.sim.humans import LTIHuman, StaticGainHuman

    if draw(st.booleans()):
        k = draw(_gains)
        skew = draw(st.floats(-1.0, 1.0))
        return StaticGainHuman(np.array([[k, skew], [-skew, k]]))
    from verify.passivity.decision import PASSIVE

    human, decision = LTIHuman.gated(draw(_passive_lti_models(max_states, 2)))
    assume(decision.verdict == PASSIVE)
    return human


# --------------------------------------------------------------------------- scenarios


@st.composite
def rotations_within(draw, center: np.ndarray, max_angle: float) -> np.ndarray:
    """Rotations center @ exp(w) with |w| <= max_angle (uniform-ish in the ball)."""
    axis = draw(hnp.arrays(np.float64, 3, elements=_unit_floats))
    norm = float(np.linalg.norm(axis))
    if norm < 1e-3:
        axis, norm = np.array([0.0, 0.0, 1.0]), 1.0
    angle = draw(st.floats(0.0, max_angle))
    return np.asarray(center) @ exp(axis / norm * angle)


def scenarios(*, max_bodies: int = 6, humans: st.SearchStrategy | None = None,
              autonomous: tuple[str, ...] = AUTONOMOUS_KINDS) -> st.SearchStrategy:
    """Closed-loop scenarios meeting Assumption 1 at t = 0.

    The bodies are spread within 60 degrees of a common attitude (so dbar is well
    defined); R-bar(0) is their quasi-average with a drawn yaw; R_r is within 90 degrees
    of R-bar(0) (tr(R-bar_r) >= 1, Lemma 1's boundary included) and R_l(0) within 80
    degrees of R_r (sym(R_rl) > 0 needs less than 90).
    """
    integer_at_least("max_bodies", max_bodies, 1, error=InvalidArgument)
    if humans is not None and not isinstance(humans, st.SearchStrategy):
        raise InvalidArgument(message("a strategy of humans, such as passive_humans()",
                                      "humans", humans, "did you mean passive_humans()?"))
    if isinstance(autonomous, str) or not autonomous:
        raise InvalidArgument(message("a non-empty tuple of autonomous-input kinds",
                                      "autonomous", autonomous, f"e.g. {AUTONOMOUS_KINDS}"))
    for kind in autonomous:
        one_of("autonomous", kind, AUTONOMOUS_KINDS, InvalidArgument)
    return _scenarios(max_bodies, humans, tuple(autonomous))


@st.composite
def _scenarios(draw, max_bodies: int, humans, autonomous: tuple[str, ...]):
    from verify.sim.inputs import Reference, autonomous_input
    from verify.sim.scenario import Scenario
    from verify.system.laws import quasi_average_initial

    n = draw(st.integers(1, max_bodies))
    center = draw(rotations())
    R0 = np.stack([draw(rotations_within(center, np.pi / 3)) for _ in range(n)])
    yaw = draw(st.floats(-np.pi, np.pi))
    R_bar0 = quasi_average_initial(R0, yaw)
    R_r = draw(rotations_within(R_bar0, np.pi / 2))  # tr(R_r^T R-bar) >= 1 up to rounding
    assume(np.trace(R_r.T @ R_bar0) >= 1.0)
    R_l0 = draw(rotations_within(R_r, np.deg2rad(80)))
    human = draw(humans if humans is not None else passive_humans())
    kind = draw(st.sampled_from(list(autonomous)))
    seed = draw(st.integers(0, 2**31 - 1))
    k_s = draw(st.floats(0.5, 5.0))
    return Scenario(R0, k_s, human, Reference.constant(R_r), R_l0=R_l0,
                    autonomous=autonomous_input(kind, n, seed), rbar_yaw=yaw)
