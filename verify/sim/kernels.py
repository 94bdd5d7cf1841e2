"""Compiled kernels of the closed loop: one CF4 step of Sections 2-3 as a fused loop.

The field is the one of :class:`verify.sim.scenario.ClosedLoop` (eqs. (1), (4), (6a),
(6b), the stealthy projector A(d) of Section 2 and the supply of Theorem 1), written as
loops over the bodies so that a stage costs one pass over memory with no temporaries,
compiled with numba. The human enters through a common form that covers the shipped
models: omega_h^b = pad(C x + D e[:k]) + R_l^T c_s, x' = A x + B e[:k], with c_s a
spatial command given per stage (the held command of the VR interface, or an open-loop
signal), so an LTI model, a static gain, the VR operator and a given signal all use the
same kernel.

The Lie-group step is the commutator-free method of order 4 of Celledoni, Marthinsen
and Owren (2003), as in :mod:`verify.sim.lie_group`; the exponential is Rodrigues'
formula with series for small angles (the coefficients of :func:`verify.so3.exp`).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from verify.so3 import Array

#: LLVM may fuse a * b + c into one rounding (FMA); no other fast-math licence, so NaN
#: and infinity keep their IEEE meaning
_CONTRACT = {"contract"}

#: autonomous input kinds the kernel knows (Section 2, eq. (3))
AUTO_ZERO, AUTO_CONSENSUS, AUTO_GIVEN = 0, 1, 2
#: status codes of a step
OK, DBAR_UNDEFINED = 0, 1


# Taylor coefficients of sin t / t and (1 - cos t) / t^2 in powers of t^2
_A1, _A2, _A3, _A4, _A5 = (-1 / 6, 1 / 120, -1 / 5040, 1 / 362880, -1 / 39916800)
_B1, _B2, _B3, _B4, _B5 = (-1 / 24, 1 / 720, -1 / 40320, 1 / 3628800, -1 / 479001600)


@njit(cache=True, inline="always", fastmath=_CONTRACT)
def _affine_row(M: Array, N: Array, x: Array, e: Array, r: int, m: int, k: int) -> float:
    """Row r of M x + N e (x of length m, the first k components of e): the LTI human's
    output C x + D e and state rate A x + B e."""
    acc = 0.0
    for j in range(m):
        acc += M[r, j] * x[j]
    for j in range(k):
        acc += N[r, j] * e[j]
    return acc


@njit(cache=True, inline="always", fastmath=_CONTRACT)
def _rodrigues_coefficients(t2: float) -> tuple[float, float]:
    """(sin t / t, (1 - cos t) / t^2) for t^2 = |w|^2, accurate at every angle.

    Below t = 0.1 they come from their Taylor series (six terms; the first omitted term
    is below t^12 / 6e9 < 2e-22), above from sin; the simulator's steps rotate by far
    less than 0.1 rad, so they need no trigonometric call.
    """
    if t2 < 0.01:
        a = 1.0 + t2 * (_A1 + t2 * (_A2 + t2 * (_A3 + t2 * (_A4 + t2 * _A5))))
        b = 0.5 + t2 * (_B1 + t2 * (_B2 + t2 * (_B3 + t2 * (_B4 + t2 * _B5))))
        return a, b
    t = math.sqrt(t2)
    s = math.sin(0.5 * t) / t
    return math.sin(t) / t, 2.0 * s * s


@njit(cache=True, fastmath=_CONTRACT)
def exp_mul(W: Array, scale: float, Y: Array, out: Array) -> None:
    """out[i] = exp(scale * hat(W[i])) @ Y[i] for a batch (W (m, 3), Y and out (m, 3, 3)).

    Rodrigues' formula exp(hat(w)) = c I + a hat(w) + b w w^T with c = 1 - b t^2 (as in
    :func:`verify.so3.exp`), applied to the columns of Y without forming the matrix.
    """
    for i in range(W.shape[0]):
        w0, w1, w2 = scale * W[i, 0], scale * W[i, 1], scale * W[i, 2]
        t2 = w0 * w0 + w1 * w1 + w2 * w2
        a, b = _rodrigues_coefficients(t2)
        c = 1.0 - b * t2
        bx, by, bz = b * w0, b * w1, b * w2
        ax, ay, az = a * w0, a * w1, a * w2
        xy, xz, yz = bx * w1, bx * w2, by * w2
        e00, e01, e02 = c + bx * w0, xy - az, xz + ay
        e10, e11, e12 = xy + az, c + by * w1, yz - ax
        e20, e21, e22 = xz - ay, yz + ax, c + bz * w2
        for col in range(3):
            y0, y1, y2 = Y[i, 0, col], Y[i, 1, col], Y[i, 2, col]
            out[i, 0, col] = e00 * y0 + e01 * y1 + e02 * y2
            out[i, 1, col] = e10 * y0 + e11 * y1 + e12 * y2
            out[i, 2, col] = e20 * y0 + e21 * y1 + e22 * y2


@njit(cache=True, inline="always", fastmath=_CONTRACT)
def _vee_at_b(P: Array, Q: Array) -> tuple[float, float, float]:
    """sk(P^T Q)^vee for two 3 x 3 matrices."""
    m01 = P[0, 0] * Q[0, 1] + P[1, 0] * Q[1, 1] + P[2, 0] * Q[2, 1]
    m10 = P[0, 1] * Q[0, 0] + P[1, 1] * Q[1, 0] + P[2, 1] * Q[2, 0]
    m02 = P[0, 0] * Q[0, 2] + P[1, 0] * Q[1, 2] + P[2, 0] * Q[2, 2]
    m20 = P[0, 2] * Q[0, 0] + P[1, 2] * Q[1, 0] + P[2, 2] * Q[2, 0]
    m12 = P[0, 1] * Q[0, 2] + P[1, 1] * Q[1, 2] + P[2, 1] * Q[2, 2]
    m21 = P[0, 2] * Q[0, 1] + P[1, 2] * Q[1, 1] + P[2, 2] * Q[2, 1]
    return 0.5 * (m21 - m12), 0.5 * (m02 - m20), 0.5 * (m10 - m01)


@njit(cache=True, fastmath=_CONTRACT)
def stealthy_body_field(R: Array, Omega: Array, omega_tilde: Array, F: Array,
                        work: Array, tol: float) -> int:
    """F[i] = omega~ + R_i (A(d) Omega)_i (spatial); A(d) = I - Q Q^T as in
    :func:`verify.system.stealthy.range_basis` (Q from CGS2 on the two columns of W~ E).

    ``work`` has shape (n, 4). Returns :data:`DBAR_UNDEFINED` when |sum d_i| <= tol n.
    """
    n = R.shape[0]
    s0 = s1 = s2 = 0.0
    for i in range(n):
        s0 += R[i, 0, 2]
        s1 += R[i, 1, 2]
        s2 += R[i, 2, 2]
    norm = math.sqrt(s0 * s0 + s1 * s1 + s2 * s2)
    if not norm > tol * n:
        return DBAR_UNDEFINED
    u0, u1, u2 = s0 / norm, s1 / norm, s2 / norm
    # E: orthonormal basis of the plane orthogonal to u (the helper axis of least |u_k|)
    au = (abs(u0), abs(u1), abs(u2))
    k = 0
    if au[1] < au[k]:
        k = 1
    if au[2] < au[k]:
        k = 2
    h0, h1, h2 = (1.0 if k == 0 else 0.0), (1.0 if k == 1 else 0.0), (1.0 if k == 2 else 0.0)
    a0, a1, a2 = u1 * h2 - u2 * h1, u2 * h0 - u0 * h2, u0 * h1 - u1 * h0
    an = math.sqrt(a0 * a0 + a1 * a1 + a2 * a2)
    a0, a1, a2 = a0 / an, a1 / an, a2 / an
    c0, c1, c2 = u1 * a2 - u2 * a1, u2 * a0 - u0 * a2, u0 * a1 - u1 * a0
    # columns of B = W~ E: block i is e3 x (R_i^T E_k) = (-(R_i^T E_k)_1, (R_i^T E_k)_0, 0)
    bb11 = bb12 = 0.0
    for i in range(n):
        m0a = R[i, 0, 0] * a0 + R[i, 1, 0] * a1 + R[i, 2, 0] * a2
        m1a = R[i, 0, 1] * a0 + R[i, 1, 1] * a1 + R[i, 2, 1] * a2
        m0c = R[i, 0, 0] * c0 + R[i, 1, 0] * c1 + R[i, 2, 0] * c2
        m1c = R[i, 0, 1] * c0 + R[i, 1, 1] * c1 + R[i, 2, 1] * c2
        work[i, 0], work[i, 1] = -m1a, m0a  # b1 (third entry 0)
        work[i, 2], work[i, 3] = -m1c, m0c  # b2
        bb11 += m1a * m1a + m0a * m0a
    inv1 = 1.0 / math.sqrt(bb11)
    for i in range(n):
        work[i, 0] *= inv1
        work[i, 1] *= inv1
        bb12 += work[i, 0] * work[i, 2] + work[i, 1] * work[i, 3]
    # v = b2 - q1 (q1 . b2), then once more (CGS2)
    r = 0.0
    for i in range(n):
        work[i, 2] -= work[i, 0] * bb12
        work[i, 3] -= work[i, 1] * bb12
        r += work[i, 0] * work[i, 2] + work[i, 1] * work[i, 3]
    vv = 0.0
    for i in range(n):
        work[i, 2] -= work[i, 0] * r
        work[i, 3] -= work[i, 1] * r
        vv += work[i, 2] * work[i, 2] + work[i, 3] * work[i, 3]
    inv2 = 1.0 / math.sqrt(vv)
    p1 = p2 = 0.0
    for i in range(n):
        work[i, 2] *= inv2
        work[i, 3] *= inv2
        p1 += work[i, 0] * Omega[i, 0] + work[i, 1] * Omega[i, 1]
        p2 += work[i, 2] * Omega[i, 0] + work[i, 3] * Omega[i, 1]
    for i in range(n):
        o0 = Omega[i, 0] - p1 * work[i, 0] - p2 * work[i, 2]
        o1 = Omega[i, 1] - p1 * work[i, 1] - p2 * work[i, 3]
        o2 = Omega[i, 2]
        for c in range(3):
            F[i, c] = omega_tilde[c] + R[i, c, 0] * o0 + R[i, c, 1] * o1 + R[i, c, 2] * o2
    return OK


@njit(cache=True, fastmath=_CONTRACT)
def consensus(R: Array, gain: float, out: Array) -> None:
    """Ring synchronisation omega_i = gain (sk(R_i^T R_(i+1))^vee - sk(R_(i-1)^T R_i)^vee)."""
    n = R.shape[0]
    if n < 2:
        out[:, :] = 0.0
        return
    f0, f1, f2 = _vee_at_b(R[n - 1], R[0])  # the last body's "ahead" term
    p0, p1, p2 = f0, f1, f2
    for i in range(n):
        if i < n - 1:
            v0, v1, v2 = _vee_at_b(R[i], R[i + 1])
        else:
            v0, v1, v2 = f0, f1, f2
        out[i, 0] = gain * (v0 - p0)
        out[i, 1] = gain * (v1 - p1)
        out[i, 2] = gain * (v2 - p2)
        p0, p1, p2 = v0, v1, v2


@njit(cache=True, fastmath=_CONTRACT)
def closed_loop_field(Y: Array, x: Array, k_s: float, R_r: Array, c_s: Array,
                      hA: Array, hB: Array, hC: Array, hD: Array, auto: int, gain: float,
                      Oa: Array, tol: float, F: Array, g: Array, Omega: Array,
                      work: Array, u_add: Array) -> int:
    """(F, g) of the closed loop at (Y, x): the field of ``ClosedLoop.field`` (see module).

    ``u_add`` (ports,) is added to the human's output C x + D e (a held operator noise,
    :class:`verify.sim.noisy_humans.ReactingNoisyHuman`; empty for the other humans)."""
    n = Y.shape[0] - 2
    m = x.shape[0] - 1
    k = hD.shape[0]
    Rb, Rl = Y[n], Y[n + 1]
    v0, v1, v2 = _vee_at_b(Rb, Rl)  # sk(R-bar^T R_l)^vee
    ot = np.empty(3)
    for r in range(3):
        ot[r] = k_s * (Rb[r, 0] * v0 + Rb[r, 1] * v1 + Rb[r, 2] * v2)  # eq. (6a)
    e = np.empty(3)
    e[0], e[1], e[2] = _vee_at_b(Rl, R_r)  # e = sk(R_l^T R_r)^vee
    ob = np.zeros(3)  # omega_h^b
    for r in range(k):
        ob[r] = _affine_row(hC, hD, x, e, r, m, k)  # C x + D e
    for r in range(u_add.shape[0]):
        ob[r] += u_add[r]
    for r in range(3):
        ob[r] += Rl[0, r] * c_s[0] + Rl[1, r] * c_s[1] + Rl[2, r] * c_s[2]
    l0, l1, l2 = _vee_at_b(Rl, Rb)
    l0, l1, l2 = k_s * l0 + ob[0], k_s * l1 + ob[1], k_s * l2 + ob[2]  # eq. (6b)
    for r in range(3):
        F[n, r] = ot[r]
        F[n + 1, r] = Rl[r, 0] * l0 + Rl[r, 1] * l1 + Rl[r, 2] * l2
    for r in range(m):
        g[r] = _affine_row(hA, hB, x, e, r, m, k)  # A x + B e
    g[m] = e[0] * ob[0] + e[1] * ob[1] + e[2] * ob[2]
    R = Y[:n]
    if auto == AUTO_ZERO:
        for i in range(n):
            F[i, 0], F[i, 1], F[i, 2] = ot[0], ot[1], ot[2]
        return OK
    if auto == AUTO_CONSENSUS:
        consensus(R, gain, Omega)
        return stealthy_body_field(R, Omega, ot, F, work, tol)
    return stealthy_body_field(R, Oa, ot, F, work, tol)


def workspace(n: int, q: int) -> tuple[Array, Array, Array, Array, Array]:
    """Scratch arrays of :func:`cf4_step` for n bodies and q Euclidean states."""
    N = n + 2
    return (np.empty((3, N, 3, 3)), np.empty((5, N, 3)), np.empty((7, q)), np.empty((n, 3)),
            np.empty((n, 4)))


@njit(cache=True, fastmath=_CONTRACT)
def cf4_step(Y: Array, x: Array, h: float, k_s: float, R_r: Array, c_stage: Array,
             hA: Array, hB: Array, hC: Array, hD: Array, auto: int, gain: float,
             Oa_stage: Array, tol: float, Y_out: Array, x_out: Array, Ys: Array, Fs: Array,
             xs: Array, Om: Array, work: Array, u_add: Array) -> int:
    """One CF4 step (Celledoni-Marthinsen-Owren) of the closed loop from (Y, x) over h.

    ``c_stage`` (4, 3) and ``Oa_stage`` (4, n, 3) (or (4, 0, 3)) give the spatial human
    command and the given autonomous input at the stage times t, t + h/2, t + h/2, t + h.
    Same stages as :func:`verify.sim.lie_group.cf4_mixed_step`. ``Ys`` ... ``work`` are
    the scratch arrays of :func:`workspace`.
    """
    N = Y.shape[0]
    q = x.shape[0]
    F1, F2, F3, F4, W = Fs[0], Fs[1], Fs[2], Fs[3], Fs[4]
    g1, g2, g3, g4 = xs[3], xs[4], xs[5], xs[6]
    Y2, Y3, Y4 = Ys[0], Ys[1], Ys[2]
    x2, x3, x4 = xs[0], xs[1], xs[2]

    def field(Ys, xs, s, F, g):
        return closed_loop_field(Ys, xs, k_s, R_r, c_stage[s], hA, hB, hC, hD, auto, gain,
                                 Oa_stage[s], tol, F, g, Om, work, u_add)

    if field(Y, x, 0, F1, g1) != OK:
        return DBAR_UNDEFINED
    exp_mul(F1, 0.5 * h, Y, Y2)
    for j in range(q):
        x2[j] = x[j] + 0.5 * h * g1[j]
    if field(Y2, x2, 1, F2, g2) != OK:
        return DBAR_UNDEFINED
    exp_mul(F2, 0.5 * h, Y, Y3)
    for j in range(q):
        x3[j] = x[j] + 0.5 * h * g2[j]
    if field(Y3, x3, 2, F3, g3) != OK:
        return DBAR_UNDEFINED
    for i in range(N):
        for c in range(3):
            W[i, c] = 2.0 * F3[i, c] - F1[i, c]
    exp_mul(W, 0.5 * h, Y2, Y4)
    for j in range(q):
        x4[j] = x2[j] + 0.5 * h * (2.0 * g3[j] - g1[j])
    if field(Y4, x4, 3, F4, g4) != OK:
        return DBAR_UNDEFINED
    for i in range(N):
        for c in range(3):
            W[i, c] = 3.0 * F1[i, c] + 2.0 * F2[i, c] + 2.0 * F3[i, c] - F4[i, c]
    exp_mul(W, h / 12.0, Y, Y2)  # first factor, Y2 reused
    for i in range(N):
        for c in range(3):
            W[i, c] = -F1[i, c] + 2.0 * F2[i, c] + 2.0 * F3[i, c] + 3.0 * F4[i, c]
    exp_mul(W, h / 12.0, Y2, Y_out)
    for j in range(q):
        x_out[j] = x[j] + h / 6.0 * (g1[j] + 2.0 * g2[j] + 2.0 * g3[j] + g4[j])
    return OK


#: status of :func:`cf4_run`: the VR command left the kernel's branch (Python takes the step)
NEEDS_PYTHON = 2


@njit(cache=True, fastmath=_CONTRACT)
def cf4_run(Y: Array, x: Array, k0: int, k1: int, h: float, k_s: float, rotations: Array,
            segment: Array, held_kind: int, k_omega: float, saturation: float, tilt: float,
            hA: Array, hB: Array, hC: Array, hD: Array, auto: int, gain: float, tol: float,
            out_Rbar: Array, out_Rl: Array, out_Rr: Array, out_x: Array, out_s: Array,
            dirs: Array, every: int, Y_out: Array, x_out: Array, Ys: Array, Fs: Array,
            xs: Array, Om: Array, work: Array) -> tuple[int, int]:
    """Steps k0 .. k1 - 1 of a fixed-step run in one call, recording each sample first.

    Step k holds R_r = rotations[segment[k]] and, for the VR operator (``held_kind`` 1),
    its command from :func:`vr_command`; the stages are those of :func:`cf4_step` with
    no given input. Sample k stores R-bar, R_l, R_r, x, s = sum_i d_i (summed in body
    order, as ``sum(axis=0)``) and, every ``every`` samples, the d_i. (Y, x) are advanced
    in place. Returns (k, status): k = k1 and OK, or the step k where the run stopped
    (DBAR_UNDEFINED; NEEDS_PYTHON when the VR command left the kernel's branch; sample k
    is then not recorded).
    """
    n = Y.shape[0] - 2
    q = x.shape[0]
    c_stage = np.zeros((4, 3))
    c = np.zeros(3)
    no_input = np.zeros((4, 0, 3))
    no_add = np.zeros(0)
    for k in range(k0, k1):
        R_r = rotations[segment[k]]
        if held_kind == 1:
            if not vr_command(Y[n + 1], R_r, k_omega, saturation, tilt, c):
                return k, NEEDS_PYTHON
            for j in range(4):
                c_stage[j, 0], c_stage[j, 1], c_stage[j, 2] = c[0], c[1], c[2]
        for r in range(3):
            for col in range(3):
                out_Rbar[k, r, col] = Y[n, r, col]
                out_Rl[k, r, col] = Y[n + 1, r, col]
                out_Rr[k, r, col] = R_r[r, col]
        for j in range(q):
            out_x[k, j] = x[j]
        s0, s1, s2 = Y[0, 0, 2], Y[0, 1, 2], Y[0, 2, 2]
        for i in range(1, n):
            s0 += Y[i, 0, 2]
            s1 += Y[i, 1, 2]
            s2 += Y[i, 2, 2]
        out_s[k, 0], out_s[k, 1], out_s[k, 2] = s0, s1, s2
        if every > 0 and k % every == 0:
            for i in range(n):
                for r in range(3):
                    dirs[k // every, i, r] = Y[i, r, 2]
        if cf4_step(Y, x, h, k_s, R_r, c_stage, hA, hB, hC, hD, auto, gain, no_input, tol,
                    Y_out, x_out, Ys, Fs, xs, Om, work, no_add) != OK:
            return k, DBAR_UNDEFINED
        Y[:] = Y_out
        x[:] = x_out
    return k1, OK


@njit(cache=True, fastmath=_CONTRACT)
def vr_command(R_l: Array, R_r: Array, k_omega: float, saturation: float, tilt: float,
               out: Array) -> bool:
    """The held spatial command of the VR operator (:class:`verify.sim.humans.VROperator`).

    With the grip attitude R_0 = I, log(R_t R_0^T) = log(exp(v)) = v for the tilt vector v
    while |v| < pi (principal branch), so the command is k_omega v, saturated. Returns
    False (``out`` untouched) when |v| >= 3, near the cut, where the caller uses the model.
    """
    dl0, dl1, dl2 = R_l[0, 2], R_l[1, 2], R_l[2, 2]
    dr0, dr1, dr2 = R_r[0, 2], R_r[1, 2], R_r[2, 2]
    a0, a1, a2 = dl1 * dr2 - dl2 * dr1, dl2 * dr0 - dl0 * dr2, dl0 * dr1 - dl1 * dr0
    s = math.sqrt(a0 * a0 + a1 * a1 + a2 * a2)
    c = dl0 * dr0 + dl1 * dr1 + dl2 * dr2
    if s < 1e-15:
        out[0] = out[1] = out[2] = 0.0
        return True
    f = tilt * math.atan2(s, c) / s
    v0, v1, v2 = f * a0, f * a1, f * a2
    if math.sqrt(v0 * v0 + v1 * v1 + v2 * v2) >= 3.0:
        return False
    v0, v1, v2 = k_omega * v0, k_omega * v1, k_omega * v2
    norm = math.sqrt(v0 * v0 + v1 * v1 + v2 * v2)
    if norm > saturation:
        r = saturation / norm
        v0, v1, v2 = v0 * r, v1 * r, v2 * r
    out[0], out[1], out[2] = v0, v1, v2
    return True


@njit(cache=True, inline="always", fastmath=_CONTRACT)
def _mm(A: Array, B: Array, r: int, c: int) -> float:
    """(A B^T)[r, c] for 3 x 3 matrices."""
    return A[r, 0] * B[c, 0] + A[r, 1] * B[c, 1] + A[r, 2] * B[c, 2]


@njit(cache=True, fastmath=_CONTRACT)
def log_dexpinv(Y1: Array, Y0: Array, F: Array, scale: float, P: Array, D: Array) -> bool:
    """P[i] = log(Y1[i] Y0[i]^T) and D[i] = scale * dexp^{-1}_{P[i]}(F[i]).

    For Y(s) = exp(hat(p(s))) Y0 with spatial velocity F (Y' = hat(F) Y), the chart's
    velocity is p' = dexp^{-1}_p(F) = F - p x F / 2 + alpha(|p|) p x (p x F), with
    alpha(t) = (1 - (t/2) cot(t/2)) / t^2 (Iserles, Munthe-Kaas, Norsett and Zanna,
    Acta Numerica 2000, Section 2.4). Returns False when some angle exceeds 2 rad (the
    caller then shortens the step).
    """
    for i in range(Y1.shape[0]):
        A, B = Y1[i], Y0[i]
        s0 = 0.5 * (_mm(A, B, 2, 1) - _mm(A, B, 1, 2))
        s1 = 0.5 * (_mm(A, B, 0, 2) - _mm(A, B, 2, 0))
        s2 = 0.5 * (_mm(A, B, 1, 0) - _mm(A, B, 0, 1))
        cs = 0.5 * (_mm(A, B, 0, 0) + _mm(A, B, 1, 1) + _mm(A, B, 2, 2) - 1.0)
        sn = math.sqrt(s0 * s0 + s1 * s1 + s2 * s2)
        t = math.atan2(sn, cs)
        if t > 2.0:
            return False
        t2 = t * t
        # t / sin t and alpha(t) by series for small t (next terms below 1e-16 relative)
        f = 1.0 + t2 * (1.0 / 6.0 + t2 * (7.0 / 360.0)) if t2 < 1e-6 else t / math.sin(t)
        if t2 < 1e-2:
            alpha = 1.0 / 12.0 + t2 * (1.0 / 720.0 + t2 * (1.0 / 30240.0 + t2 / 1209600.0))
        else:
            alpha = (1.0 - 0.5 * t / math.tan(0.5 * t)) / t2
        p0, p1, p2 = f * s0, f * s1, f * s2
        P[i, 0], P[i, 1], P[i, 2] = p0, p1, p2
        v0, v1, v2 = F[i, 0], F[i, 1], F[i, 2]
        c0, c1, c2 = p1 * v2 - p2 * v1, p2 * v0 - p0 * v2, p0 * v1 - p1 * v0
        cc0, cc1, cc2 = p1 * c2 - p2 * c1, p2 * c0 - p0 * c2, p0 * c1 - p1 * c0
        D[i, 0] = scale * (v0 - 0.5 * c0 + alpha * cc0)
        D[i, 1] = scale * (v1 - 0.5 * c1 + alpha * cc1)
        D[i, 2] = scale * (v2 - 0.5 * c2 + alpha * cc2)
    return True


@njit(cache=True, fastmath=_CONTRACT)
def dense_samples(Wt: Array, Pm: Array, P1: Array, D0: Array, Dm: Array, D1: Array,
                  Y0: Array, n: int, small: Array, sums: Array, dirs: Array) -> None:
    """The samples of a quintic Hermite dense output (see :mod:`verify.sim.adaptive`).

    For sample s with weights Wt[s] of (value at 1/2, value at 1, velocity at 0, 1/2, 1),
    p_i = sum of the weighted data and Y_i = exp(hat(p_i)) Y0[i]. Writes the rotations
    n and n + 1 (R-bar, R_l) to small[s], the sum of the bodies' d_i = Y_i e3 to sums[s],
    and, when ``dirs`` has S rows, the d_i themselves.
    """
    N = Y0.shape[0]
    keep = dirs.shape[0] == Wt.shape[0]
    for s in range(Wt.shape[0]):
        a, b, c, d, e = Wt[s, 0], Wt[s, 1], Wt[s, 2], Wt[s, 3], Wt[s, 4]
        s0 = s1 = s2 = 0.0
        for i in range(N):
            w0 = a * Pm[i, 0] + b * P1[i, 0] + c * D0[i, 0] + d * Dm[i, 0] + e * D1[i, 0]
            w1 = a * Pm[i, 1] + b * P1[i, 1] + c * D0[i, 1] + d * Dm[i, 1] + e * D1[i, 1]
            w2 = a * Pm[i, 2] + b * P1[i, 2] + c * D0[i, 2] + d * Dm[i, 2] + e * D1[i, 2]
            t2 = w0 * w0 + w1 * w1 + w2 * w2
            ca, cb = _rodrigues_coefficients(t2)
            cc = 1.0 - cb * t2
            if i < n:
                v0, v1, v2 = Y0[i, 0, 2], Y0[i, 1, 2], Y0[i, 2, 2]
                wv = cb * (w0 * v0 + w1 * v1 + w2 * v2)
                r0 = cc * v0 + ca * (w1 * v2 - w2 * v1) + wv * w0
                r1 = cc * v1 + ca * (w2 * v0 - w0 * v2) + wv * w1
                r2 = cc * v2 + ca * (w0 * v1 - w1 * v0) + wv * w2
                s0 += r0
                s1 += r1
                s2 += r2
                if keep:
                    dirs[s, i, 0], dirs[s, i, 1], dirs[s, i, 2] = r0, r1, r2
            else:
                for col in range(3):
                    v0, v1, v2 = Y0[i, 0, col], Y0[i, 1, col], Y0[i, 2, col]
                    wv = cb * (w0 * v0 + w1 * v1 + w2 * v2)
                    small[s, i - n, 0, col] = cc * v0 + ca * (w1 * v2 - w2 * v1) + wv * w0
                    small[s, i - n, 1, col] = cc * v1 + ca * (w2 * v0 - w0 * v2) + wv * w1
                    small[s, i - n, 2, col] = cc * v2 + ca * (w0 * v1 - w1 * v0) + wv * w2
        sums[s, 0], sums[s, 1], sums[s, 2] = s0, s1, s2


@njit(cache=True, fastmath=_CONTRACT)
def vr_commands(R_l: Array, R_r: Array, k_omega: float, saturation: float, tilt: float,
                out: Array) -> Array:
    """:func:`vr_command` for a batch (T, 3, 3); returns a mask of the rows it filled."""
    done = np.empty(R_l.shape[0], dtype=np.bool_)
    for k in range(R_l.shape[0]):
        done[k] = vr_command(R_l[k], R_r[k], k_omega, saturation, tilt, out[k])
    return done
