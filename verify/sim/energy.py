"""The Lyapunov quantities of Lemma 1 and Theorem 1 along a trajectory.

* h = tr(R-bar_r) - 1 with R-bar_r = R_r^T R-bar (Lemma 1: R-bar_r + R-bar_r^T >= 0 iff h >= 0);
* phi(R) = tr(I - R)/2, S_r = phi(R-bar_r), S_rl = phi(R_rl), R_rl = R_r^T R_l;
* S_h: beta + w with w = int e^T omega_h^b dt (the running integral of the proof) or,
  for an LTI human with a KYP certificate, the storage x^T P x / 2;
* the bound of eq. (9): V' <= -(k_s/2) [lmin(R-bar_r + R-bar_r^T) + lmin(R_rl + R_rl^T)]
  phi(R_l^T R-bar);
* V' itself, computed from the vector field at a state (no time differencing).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from verify.sim import fused, kernels
from verify.sim.humans import LTIHuman
from verify.sim.scenario import ClosedLoop
from verify.sim.trajectory import Trajectory
from verify.so3 import Array, hat, transpose, vee


def phi(R: Array) -> Array:
    """phi(R) = tr(I - R)/2 for a batch of rotations (proof of Theorem 1)."""
    return 0.5 * (3.0 - np.trace(R, axis1=-2, axis2=-1))


def lambda_min_sym2(R: Array) -> Array:
    """lambda_min(R + R^T) for a batch."""
    return np.linalg.eigvalsh(R + transpose(R))[..., 0]


@dataclass
class Energy:
    """Lyapunov terms sampled along a trajectory (arrays of length T)."""

    h: Array  # tr(R-bar_r) - 1 (Lemma 1)
    lmin_rl: Array  # lambda_min(R_rl + R_rl^T): Assumption 1, second item, wants > 0
    S_r: Array
    S_rl: Array
    S_h_integral: Array  # w(t) (S_h up to the constant beta)
    S_h_storage: Array | None  # x^T P x / 2 when the human carries a storage
    V_dot: Array  # from the vector field, with the S_h chosen below
    V_dot_bound: Array  # eq. (9)
    uses_storage: bool

    @property
    def V(self) -> Array:
        S_h = self.S_h_storage if self.uses_storage else self.S_h_integral
        return self.S_r + self.S_rl + S_h


def _batched(traj: Trajectory, uses: bool) -> tuple[Array, Array | None] | None:
    """(V', storage) for all samples at once, for the humans the compiled field models.

    The same terms as the per-sample loop of :func:`energy`, with the laws written out
    as in :mod:`verify.sim.kernels` (omega_l = k_s sk(R_l^T R-bar)^vee + omega_h^b,
    omega_h^b = pad(C x + D e) + R_l^T c_s); None when ClosedLoop's laws were replaced or
    the human is of another kind (the loop is then the definition used).
    """
    s = traj.scenario
    human = s.human
    form = fused.human_form(human)
    if form is None or form[4] == "noisy" or not fused.laws_unmodified():
        return None  # the noisy operator's held values are read by the loop below
    A, B, C, D, command = form
    Rb, Rl, Rr, x = traj.R_bar, traj.R_l, traj.R_r, traj.human_state
    T, k = traj.t.shape[0], D.shape[0]
    omega_t = s.k_s * np.einsum("tij,tj->ti", Rb, vee(transpose(Rb) @ Rl))  # eq. (6a)
    e = vee(transpose(Rl) @ Rr)
    omega_b = np.zeros((T, 3))
    if k:
        omega_b[:, :k] = x @ C.T + e[:, :k] @ D.T
    if command != "none":
        if command == "held":  # the VR command held at each sample time
            c_s = np.empty((T, 3))
            done = kernels.vr_commands(np.ascontiguousarray(Rl), np.ascontiguousarray(Rr),
                                       float(human.k_omega), float(human.saturation),
                                       float(human.tilt), c_s)
            for j in np.flatnonzero(~done):
                c_s[j] = human.hold(traj.t[j], Rl[j], Rr[j])
        else:
            c_s = np.array([human.signal(t) for t in traj.t]).reshape(T, 3)
        omega_b += np.einsum("tji,tj->ti", Rl, c_s)
    omega_l = s.k_s * vee(transpose(Rl) @ Rb) + omega_b  # eq. (6b)
    dS_r = -0.5 * np.einsum("tij,tij->t", Rr, hat(omega_t) @ Rb)  # eq. (4)
    dS_rl = -0.5 * np.einsum("tij,tij->t", Rr, Rl @ hat(omega_l))
    storage = None
    if uses:
        if type(human) is LTIHuman:
            P = human.P
            storage = 0.5 * np.einsum("ti,ij,tj->t", x, P, x)
            dS_h = np.einsum("ti,ij,tj->t", x, P, x @ A.T + e[:, :k] @ B.T)
        else:  # a passive static gain: no state, zero storage
            storage, dS_h = np.zeros(T), np.zeros(T)
    else:
        dS_h = np.einsum("ti,ti->t", e, omega_b)
    return dS_r + dS_rl + dS_h, storage


def energy(traj: Trajectory, prefer_storage: bool = True, *, batched: bool = True
           ) -> Energy:
    """Evaluate every Lyapunov term along ``traj``.

    With ``prefer_storage`` and a human that has a storage function, S_h is that storage
    (needed for LaSalle, finding ``thm1.storage-function``); otherwise the running supply.
    ``batched`` evaluates V' for all samples at once when the human is one the compiled
    field models (rounding-level differences from the per-sample loop, which is used
    otherwise and with ``batched=False``).
    """
    s = traj.scenario
    human, n = s.human, s.n
    Rr_T = transpose(traj.R_r)
    Rbar_r = Rr_T @ traj.R_bar
    R_rl = Rr_T @ traj.R_l
    x_h = traj.human_state
    uses = prefer_storage and human.storage(x_h[0]) is not None
    fast = _batched(traj, uses) if batched else None
    if fast is not None:
        V_dot, storage = fast
        return _energy(traj, Rbar_r, R_rl, storage, V_dot, uses)
    storage = np.array([human.storage(x) for x in x_h]) if uses else None

    loop = ClosedLoop(s)
    T = traj.t.shape[0]
    V_dot = np.empty(T)
    Y = np.empty((n + 2, 3, 3))
    Y[:n] = np.eye(3)  # the bodies do not enter V
    for k in range(T):
        Y[n], Y[n + 1] = traj.R_bar[k], traj.R_l[k]
        held = loop.hold(traj.t[k], Y)  # the reference and command the run held at t_k
        omega_tilde, e, omega_b = loop.signals(traj.t[k], Y, traj.x[k], held)
        Rbar_dot = hat(omega_tilde) @ traj.R_bar[k]  # eq. (4)
        omega_l = loop.leader_velocity(traj.R_l[k], traj.R_bar[k], omega_b)  # eq. (6b)
        Rl_dot = traj.R_l[k] @ hat(omega_l)
        Rr = traj.R_r[k]
        dS_r = -0.5 * np.trace(Rr.T @ Rbar_dot)
        dS_rl = -0.5 * np.trace(Rr.T @ Rl_dot)
        if uses:
            dS_h = human.storage_rate(x_h[k], e)
        else:
            dS_h = float(e @ omega_b)
        V_dot[k] = dS_r + dS_rl + dS_h
    return _energy(traj, Rbar_r, R_rl, storage, V_dot, uses)


def _energy(traj: Trajectory, Rbar_r: Array, R_rl: Array, storage: Array | None,
            V_dot: Array, uses: bool) -> Energy:
    k_s = traj.scenario.k_s
    lmin_rl = lambda_min_sym2(R_rl)
    bound = -0.5 * k_s * (lambda_min_sym2(Rbar_r) + lmin_rl) * phi(
        transpose(traj.R_l) @ traj.R_bar)
    return Energy(
        h=np.trace(Rbar_r, axis1=-2, axis2=-1) - 1.0,
        lmin_rl=lmin_rl,
        S_r=phi(Rbar_r),
        S_rl=phi(R_rl),
        S_h_integral=traj.supply,
        S_h_storage=storage,
        V_dot=V_dot,
        V_dot_bound=bound,
        uses_storage=uses,
    )

