"""An independent implementation of the closed loop: unit quaternions and scipy's DOP853.

Written apart from :mod:`verify.sim` (no import from it) to check the simulator and to
compare speed at equal accuracy (benchmarks/bench_simulator.py). Same closed loop as
Sections 2-3 of the paper with a continuous-time LTI human and a constant reference:

* bodies: spatial velocity omega~ + R_i (A(d) Omega~_a)_i, Omega~_a the ring
  synchronisation input, A(d) = I - W W^+ from an SVD of W = ((d dbar/d d) S)^T;
* R-bar: omega~ = k_s R-bar sk(R-bar^T R_l)^vee (eq. (6a));
* R_l: body velocity k_s sk(R_l^T R-bar)^vee + omega_h^b (eq. (6b));
* human: x' = A x + B e, omega_h^b = C x + D e (first k components of e =
  sk(R_l^T R_r)^vee), and the supply w' = e . omega_h^b.

Rotations are unit quaternions q = (w, x, y, z) with q' = (0, F)/2 * q for a spatial
velocity F; the field uses q / |q| so the integrator's drift off the unit sphere does not
enter. The integrator is ``scipy.integrate.solve_ivp(method="DOP853")``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp


def quat_to_matrix(q: np.ndarray) -> np.ndarray:
    """Rotation matrices of quaternions (..., 4), normalised first."""
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], -2)


def matrix_to_quat(R: np.ndarray) -> np.ndarray:
    """Quaternions (w >= 0 branch by Shepperd's method) of rotation matrices (..., 3, 3)."""
    R = np.asarray(R, dtype=float).reshape(-1, 3, 3)
    out = np.empty((R.shape[0], 4))
    for i, M in enumerate(R):
        tr = np.trace(M)
        k = int(np.argmax([tr, M[0, 0], M[1, 1], M[2, 2]]))
        if k == 0:
            r = np.sqrt(1 + tr)
            out[i] = [r / 2, (M[2, 1] - M[1, 2]) / (2 * r), (M[0, 2] - M[2, 0]) / (2 * r),
                      (M[1, 0] - M[0, 1]) / (2 * r)]
        else:
            a = k - 1
            b, c = (a + 1) % 3, (a + 2) % 3
            r = np.sqrt(1 + M[a, a] - M[b, b] - M[c, c])
            v = np.empty(4)
            v[0] = (M[c, b] - M[b, c]) / (2 * r)
            v[1 + a] = r / 2
            v[1 + b] = (M[a, b] + M[b, a]) / (2 * r)
            v[1 + c] = (M[a, c] + M[c, a]) / (2 * r)
            out[i] = v
    return out


def _skew_vee(M: np.ndarray) -> np.ndarray:
    """(M - M^T)/2 as a vector, for (..., 3, 3)."""
    return 0.5 * np.stack([M[..., 2, 1] - M[..., 1, 2], M[..., 0, 2] - M[..., 2, 0],
                           M[..., 1, 0] - M[..., 0, 1]], -1)


def _left_multiply(F: np.ndarray, q: np.ndarray) -> np.ndarray:
    """(0, F) * q / 2 for batches F (m, 3), q (m, 4)."""
    w, v = q[:, 0], q[:, 1:]
    out = np.empty_like(q)
    out[:, 0] = -np.einsum("ij,ij->i", F, v)
    out[:, 1:] = w[:, None] * F + np.cross(F, v)
    return 0.5 * out


@dataclass
class QuaternionLoop:
    """The closed loop with n bodies, gain k_s, LTI human (A, B, C, D), reference R_r."""

    n: int
    k_s: float
    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    R_r: np.ndarray
    consensus_gain: float = 1.0

    def _projected(self, R: np.ndarray, omega: np.ndarray) -> np.ndarray:
        """A(d) omega with A = I - U2 U2^T, U2 the left singular vectors of W (rank 2)."""
        d = R[:, :, 2]
        s = d.sum(axis=0)
        dbar = s / np.linalg.norm(s)
        P = np.eye(3) - np.outer(dbar, dbar)
        e3_hat = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
        W = (e3_hat @ np.transpose(R, (0, 2, 1)) @ P).reshape(-1, 3)
        U = np.linalg.svd(W, full_matrices=False)[0][:, :2]
        flat = omega.reshape(-1)
        return (flat - U @ (U.T @ flat)).reshape(-1, 3)

    def _consensus(self, R: np.ndarray) -> np.ndarray:
        if self.n < 2:
            return np.zeros((self.n, 3))
        nxt, prv = np.roll(R, -1, axis=0), np.roll(R, 1, axis=0)
        RT = np.transpose(R, (0, 2, 1))
        return self.consensus_gain * (_skew_vee(RT @ nxt) + _skew_vee(RT @ prv))

    def rhs(self, t: float, z: np.ndarray) -> np.ndarray:
        n, m = self.n, self.A.shape[0]
        k = self.D.shape[0]
        q = z[: 4 * (n + 2)].reshape(n + 2, 4)
        xh = z[4 * (n + 2): 4 * (n + 2) + m]
        R = quat_to_matrix(q)
        bodies, R_bar, R_l = R[:n], R[n], R[n + 1]
        omega_t = self.k_s * R_bar @ _skew_vee(R_bar.T @ R_l)
        e = _skew_vee(R_l.T @ self.R_r)
        omega_b = np.zeros(3)
        omega_b[:k] = self.C @ xh + self.D @ e[:k]
        omega_l = self.k_s * _skew_vee(R_l.T @ R_bar) + omega_b
        F = np.empty((n + 2, 3))
        F[:n] = omega_t + np.einsum("nij,nj->ni", bodies,
                                    self._projected(bodies, self._consensus(bodies)))
        F[n], F[n + 1] = omega_t, R_l @ omega_l
        dz = np.empty_like(z)
        dz[: 4 * (n + 2)] = _left_multiply(F, q).reshape(-1)
        dz[4 * (n + 2): 4 * (n + 2) + m] = self.A @ xh + self.B @ e[:k]
        dz[-1] = e @ omega_b
        return dz

    def initial(self, R0: np.ndarray, R_bar0: np.ndarray, R_l0: np.ndarray,
                x0: np.ndarray) -> np.ndarray:
        q = matrix_to_quat(np.concatenate([R0, R_bar0[None], R_l0[None]]))
        return np.concatenate([q.reshape(-1), x0, [0.0]])

    def solve(self, z0: np.ndarray, seconds: float, t_eval: np.ndarray, rtol: float = 1e-10,
              atol: float = 1e-12):
        """solve_ivp with DOP853; returns scipy's result (``.y`` at ``t_eval``, ``.nfev``)."""
        return solve_ivp(self.rhs, (0.0, seconds), z0, method="DOP853", t_eval=t_eval,
                         rtol=rtol, atol=atol)

    def rotations(self, z: np.ndarray) -> np.ndarray:
        """All n + 2 rotation matrices of a state vector."""
        return quat_to_matrix(z[: 4 * (self.n + 2)].reshape(self.n + 2, 4))
