"""Error-controlled steps for the closed loop: step doubling of CF4 with dense output.

Each step of size H is taken once and as two halves with the same CF4 stepper; as both
have order 4, their difference divided by 2^4 - 1 = 15 estimates the error of the halves
(Richardson; Hairer, Norsett and Wanner, Solving ODEs I, Section II.4). The value kept is
the extrapolated one (local extrapolation, order 5), formed on the group as
exp(log(Y_halves Y_full^T) / 15) Y_halves, so it stays in SO(3); the estimate then bounds
the error of the halves, a margin over the kept value. The error is measured in the max
norm of

    |Y_halves - Y_full| / (atol + rtol)                     (rotation entries, |.| <= 1)
    |x_halves - x_full| / (atol + rtol max(|x|, |x_new|))    (human state, supply)

and the step is accepted when it is at most 1; the next H is 0.9 err^(-1/5) times this
one, within [0.2, 4] times.

Forced step boundaries: every switch of the reference R_r, and, when the human samples
and holds its command (the VR interface of Section 4), every loop period; the held values
are taken at those boundaries only, so the inputs are the ones of the fixed-step run.

Dense output (the samples every loop period between step ends): quintic Hermite
interpolation from the step's start, its midpoint (which the doubling computes anyway)
and its end. A rotation is written Y(s) = exp(hat(p(s))) Y(t) with p(0) = 0; p is
interpolated from its values and its velocities dexp^{-1}_p(F) at the three nodes, the
Euclidean part x directly; the interpolation error is O(H^6), below the step's error.
"""

from __future__ import annotations

import numpy as np

from verify.errors import DbarUndefinedError, VerifyInputError
from verify.inputs.numbers import real
from verify.sim import kernels
from verify.sim.fused import Stepper
from verify.sim.trajectory import Progress, Recorder, Trajectory, dbar_lost
from verify.so3 import Array

SAFETY, GROW, SHRINK = 0.9, 4.0, 0.2
MAX_REJECTS = 60  # in a row: the step would shrink by 0.2^60, so something is wrong


def _hermite_matrix() -> Array:
    """Coefficients of the quintic Hermite basis on the nodes 0, 1/2, 1.

    Row j of the result holds the monomial coefficients of the basis polynomial that
    carries datum j: values at 0, 1/2, 1, then derivatives at 0, 1/2, 1.
    """
    nodes = (0.0, 0.5, 1.0)
    V = np.zeros((6, 6))
    for r, s in enumerate(nodes):
        V[r] = [s**k for k in range(6)]
        V[3 + r] = [k * s ** (k - 1) if k else 0.0 for k in range(6)]
    return np.linalg.inv(V).T


_HERMITE = _hermite_matrix()


def hermite_weights(s: Array) -> Array:
    """Weights (S, 6) of (v0, vm, v1, d0, dm, d1) in the quintic interpolant at s in [0, 1]."""
    return (np.asarray(s, dtype=float)[:, None] ** np.arange(6)) @ _HERMITE.T


def _validate(rtol: float, atol: float) -> tuple[float, float]:
    rtol, atol = real(rtol, "rtol"), real(atol, "atol")
    for name, v in (("rtol", rtol), ("atol", atol)):
        if v < 0:
            raise VerifyInputError(f"{name} must be >= 0, got {v}")
    if rtol < 1e-14 and atol < 1e-14:
        raise VerifyInputError(f"rtol = {rtol} and atol = {atol} ask for more than double "
                               "precision; give rtol or atol >= 1e-14")
    return rtol, atol


def _boundaries(stepper: Stepper, rec: Recorder, seconds: float) -> Array:
    """Times where a step must end: reference switches, every period of a held command."""
    times = list(rec.scenario.reference.switch_times(seconds))
    if stepper.holds_commands:
        times.extend(rec.t[1:-1])
    times.append(seconds)
    return np.unique(np.asarray(times, dtype=float))


class _Interval:
    """Dense output over one accepted step [t0, t0 + H]."""

    def __init__(self, stepper: Stepper, t0: float, H: float, held, Y0: Array, x0: Array,
                 Ym: Array, xm: Array, Y1: Array, x1: Array) -> None:
        F0, g0 = stepper.field(t0, Y0, x0, held)
        Fm, gm = stepper.field(t0 + 0.5 * H, Ym, xm, held)
        F1, g1 = stepper.field(t0 + H, Y1, x1, held)
        N = Y0.shape[0]
        self.Pm, self.Dm = np.empty((N, 3)), np.empty((N, 3))
        self.P1, self.D1 = np.empty((N, 3)), np.empty((N, 3))
        self.ok = (kernels.log_dexpinv(Ym, Y0, Fm, H, self.Pm, self.Dm)
                   and kernels.log_dexpinv(Y1, Y0, F1, H, self.P1, self.D1))
        self.D0 = H * F0
        self.x = (x0, xm, x1, H * g0, H * gm, H * g1)
        self.Y0, self.t0, self.H = Y0, t0, H

    def samples(self, times: Array, n: int, want_directions: bool
                ) -> tuple[Array, Array, Array, Array | None]:
        """(R-bar and R_l (S, 2, 3, 3), x (S, q), sum d_i (S, 3), d_i or None) at times."""
        W = hermite_weights((np.asarray(times) - self.t0) / self.H)  # (S, 6)
        S = W.shape[0]
        small, sums = np.empty((S, 2, 3, 3)), np.empty((S, 3))
        dirs = np.empty((S if want_directions else 0, n, 3))
        kernels.dense_samples(np.ascontiguousarray(W[:, 1:]), self.Pm, self.P1, self.D0,
                              self.Dm, self.D1, self.Y0, n, small, sums, dirs)
        x = W @ np.stack(self.x)
        return small, x, sums, (dirs if want_directions else None)


def _extrapolated(Y2: Array, x2: Array, Yf: Array, xf: Array) -> tuple[Array, Array]:
    """Richardson's order-5 value from the halves and the full step, on the group:
    exp(log(Y2 Yf^T) / 15) Y2 for the rotations, x2 + (x2 - xf) / 15 for x."""
    N = Y2.shape[0]
    P, unused = np.empty((N, 3)), np.empty((N, 3))
    if not kernels.log_dexpinv(Y2, Yf, unused, 0.0, P, unused):
        return Y2, x2
    Y = np.empty_like(Y2)
    kernels.exp_mul(P, 1.0 / 15.0, Y2, Y)
    return Y, x2 + (x2 - xf) / 15.0


def integrate_adaptive(stepper: Stepper, rec: Recorder, Y: Array, x: Array, seconds: float,
                       *, rtol: float, atol: float, progress: Progress | None = None,
                       extrapolate: bool = True) -> Trajectory:
    """Fill ``rec`` from (Y, x) at t = 0 to ``seconds`` with error-controlled steps."""
    rtol, atol = _validate(rtol, atol)
    n = rec.n
    stops = _boundaries(stepper, rec, seconds)
    samples = rec.t
    T = samples.shape[0]
    held = stepper.hold(0.0, Y)
    rec.record(0, Y, x, held.R_r)
    k_next = 1  # next sample to fill
    t, H = 0.0, float(rec.dt)
    b = 0  # index of the next boundary
    accepted = rejected = rejects_in_row = 0
    while b < stops.shape[0]:
        stop = float(stops[b])
        landing = t + H >= stop - 1e-12 * max(1.0, stop)
        step = stop - t if landing else H
        t_end = stop if landing else t + step
        mid = t + 0.5 * step
        try:
            Yf, xf = stepper.step(t, Y, x, step, held)
            Yh, xh = stepper.step(t, Y, x, mid - t, held)
            # t_end - mid is exact (Sterbenz: mid >= t_end / 2), so the halves end on t_end
            Y2, x2 = stepper.step(mid, Yh, xh, t_end - mid, held)
        except DbarUndefinedError as exc:
            raise dbar_lost(t, exc) from None
        scale_x = atol + rtol * np.maximum(np.abs(x), np.abs(x2))
        err = max(float(np.max(np.abs(Y2 - Yf))) / (atol + rtol),
                  float(np.max(np.abs(x2 - xf) / scale_x, initial=0.0))) / 15.0
        if not np.isfinite(err):
            err = np.inf
        if err > 1.0:
            rejected += 1
            rejects_in_row += 1
            if rejects_in_row > MAX_REJECTS:
                raise RuntimeError(f"step size control failed at t = {t:.6g} s")
            H = step * max(SHRINK, SAFETY * err ** -0.2)
            continue
        if extrapolate:
            Y2, x2 = _extrapolated(Y2, x2, Yf, xf)
        # samples strictly inside (t, t_end), then one on t_end itself
        tol_t = 1e-9 * rec.dt
        k_stop = k_next
        while k_stop < T and samples[k_stop] < t_end - tol_t:
            k_stop += 1
        inner = list(range(k_next, k_stop))
        dense = _Interval(stepper, t, step, held, Y, x, Yh, xh, Y2, x2) if inner else None
        if dense is not None and not dense.ok:  # a body turned by > 2 rad: far too long
            rejected += 1
            H = 0.25 * step
            continue
        rejects_in_row = 0
        accepted += 1
        k_next = k_stop
        if dense is not None:
            want = any(rec.wants_directions(k) for k in inner)
            small, xs, sums, dirs = dense.samples(samples[inner], n, want)
            rec.record_block(slice(inner[0], inner[-1] + 1), small[:, 0], small[:, 1], xs,
                             held.R_r, sums, dirs)
        Y, x, t = Y2, x2, t_end
        if landing:
            b += 1
            held = stepper.hold(t, Y)
        if k_next < T and abs(samples[k_next] - t) <= tol_t:
            rec.record(k_next, Y, x, (held if landing else stepper.hold(t, Y)).R_r)
            k_next += 1
        if progress is not None:
            progress(k_next - 1, T - 1)
        grow = GROW if err == 0.0 else min(GROW, SAFETY * err ** -0.2)
        H = step * grow if not landing else max(H, step * grow)
    return rec.trajectory(Y[:n], steps=accepted, rejected_steps=rejected)
