"""A frequency witness proved by a verified floating-point solve (large models).

For a rational w and a Gaussian-rational v = a + jb, the quantity

    q = v^H (H(jw) + H(jw)^H) v = 2 (a^T D a + b^T D b) - 2 Re(r^H u),
    r^H = v^H C (A + jw I),   u = K^-1 B v,   K = A^2 + w^2 I

(because (jw I - A)^-1 = -(A + jw I) K^-1) needs no exact solve to have its sign proved.
With R a dyadic approximate inverse of K, the exact residual E = I - R K gives, when
theta = ||E||_inf < 1, the bound ||K^-1||_inf <= ||R||_inf / (1 - theta) (a Neumann
series; Rump, *Verification methods*, Acta Numerica 19, 2010, Section 10). A rounded
solution u~ of K u = B v leaves the exact residual rho = B v - K u~, and
|u - u~|_inf <= ||K^-1||_inf |rho|_inf, so

    q <= q~ + 2 (|r_re|_1 |u_a - u~_a|_inf + |r_im|_1 |u_b - u~_b|_inf)

with q~ evaluated exactly at u~. Every quantity on the right is an exact rational; the
only O(n^3) work is the integer product R K (FLINT). When the right side is negative, q < 0
is proved. Floating point only proposes R, u~ and v; a poor proposal makes the bound fail
(then the exact solve of :func:`verify.passivity.check.witness.response_at` decides), never pass.
"""

from __future__ import annotations

from fractions import Fraction

import flint
import numpy as np
from gmpy2 import mpq, mpz

from verify.passivity.check import exact as ex
from verify.passivity.check import intmat
from verify.passivity.check.certificate import ExactModel


def _dyadic(x: np.ndarray, bits: int = 52) -> tuple[list[int], int]:
    """Integers z and an exponent e with z / 2^e the rounding of x (common exponent)."""
    top = float(np.max(np.abs(x))) if x.size else 0.0
    if top == 0.0 or not np.isfinite(top):
        return [0] * x.size, 0
    e = bits - int(np.frexp(top)[1])
    return [int(z) for z in np.rint(np.ldexp(x, e)).ravel()], e


def _inf_norm_int(M: flint.fmpz_mat) -> int:
    return max(sum(abs(int(M[i, j])) for j in range(M.ncols())) for i in range(M.nrows()))


def _vec_inf(v) -> mpq:
    return max((abs(x) for x in v), default=mpq(0))


def _vec_one(v) -> mpq:
    return sum((abs(x) for x in v), mpq(0))


def bounded_form(model: ExactModel, w: Fraction, a: list[mpq], b: list[mpq]
                 ) -> mpq | None:
    """An exact upper bound of v^H (H(jw) + H(jw)^H) v (module doc); None when the
    verification of the float solve fails (K nearly singular in floating point)."""
    n, m = model.n, model.m
    A_int = intmat.from_rational(model.A)
    da = int(A_int.d)
    Za = intmat.to_fmpz_mat(A_int)
    p, q = w.numerator, w.denominator
    s = q * q * da * da  # K = K_int / s
    K_int = Za * Za * (q * q)
    for i in range(n):
        K_int[i, i] += p * p * da * da
    Af = intmat.to_float(A_int)
    try:
        wf = float(w)
    except OverflowError:  # beyond the float range: no float solve to verify
        return None
    with np.errstate(all="ignore"):
        Kf = Af @ Af + wf * wf * np.eye(n)
        try:
            Rf = np.linalg.inv(Kf)
        except np.linalg.LinAlgError:
            return None
    if not np.all(np.isfinite(Rf)):
        return None
    Rz, er = _dyadic(Rf)
    R_int = flint.fmpz_mat(n, n, Rz)  # R = R_int / 2^er
    # E = I - R K = (2^er s I - R_int K_int) / (2^er s)
    RK = R_int * K_int
    if er >= 0:
        E_num = -RK
        big = (1 << er) * s
        for i in range(n):
            E_num[i, i] += big
        theta = Fraction(_inf_norm_int(E_num), big)
    else:  # R = R_int * 2^-er
        E_num = -RK * (1 << -er)
        for i in range(n):
            E_num[i, i] += s
        theta = Fraction(_inf_norm_int(E_num), s)
    if theta >= Fraction(1, 2):
        return None
    R_norm = Fraction(_inf_norm_int(R_int), 1) / (Fraction(2) ** er)
    k_inv = mpq(R_norm / (1 - theta))  # ||K^-1||_inf
    # right-hand sides B a, B b (exact) and rounded solutions
    Bm = model.B
    Ba = [sum((Bm[i][j] * a[j] for j in range(m)), mpq(0)) for i in range(n)]
    Bb = [sum((Bm[i][j] * b[j] for j in range(m)), mpq(0)) for i in range(n)]
    errors = []
    sols = []
    for g in (Ba, Bb):
        gf = np.array([float(x) for x in g])
        with np.errstate(all="ignore"):
            uf = np.linalg.solve(Kf, gf)
        if not np.all(np.isfinite(uf)):
            return None
        uz, eu = _dyadic(uf, 60)
        u = [mpq(z, 1) / (mpq(2) ** eu) for z in uz]
        # rho = g - K u = g - K_int uz / (s 2^eu)
        Ku = K_int * flint.fmpz_mat(n, 1, uz)
        denom = mpq(s) * (mpq(2) ** eu)
        rho = [g[i] - mpq(int(Ku[i, 0])) / denom for i in range(n)]
        errors.append(k_inv * _vec_inf(rho))
        sols.append(u)
    ua, ub = sols
    # r^H = v^H C (A + jw I): real part a^T C A + w b^T C, imaginary w a^T C - b^T C A
    wq = mpq(w)
    Ct = ex.transpose(model.C)
    aC = [sum((a[k] * Ct[i][k] for k in range(m)), mpq(0)) for i in range(n)]
    bC = [sum((b[k] * Ct[i][k] for k in range(m)), mpq(0)) for i in range(n)]
    At = ex.transpose(model.A)
    aCA = [sum((At[i][k] * aC[k] for k in range(n) if At[i][k]), mpq(0)) for i in range(n)]
    bCA = [sum((At[i][k] * bC[k] for k in range(n) if At[i][k]), mpq(0)) for i in range(n)]
    r_re = [aCA[i] + wq * bC[i] for i in range(n)]
    r_im = [wq * aC[i] - bCA[i] for i in range(n)]
    D = model.D
    dform = sum((a[i] * D[i][j] * a[j] + b[i] * D[i][j] * b[j]
                 for i in range(m) for j in range(m)), mpq(0))
    approx = 2 * dform - 2 * (sum((r_re[i] * ua[i] for i in range(n)), mpq(0))
                              - sum((r_im[i] * ub[i] for i in range(n)), mpq(0)))
    return approx + 2 * (_vec_one(r_re) * errors[0] + _vec_one(r_im) * errors[1])


def float_direction(A: np.ndarray, B: np.ndarray, C: np.ndarray, D: np.ndarray,
                    w: float) -> tuple[list[mpq], list[mpq]] | None:
    """Gaussian-rational a + jb from the eigenvector of the smallest eigenvalue of the float
    H(jw) + H(jw)^H (only a proposal)."""
    n = A.shape[0]
    with np.errstate(all="ignore"):
        try:
            H = C @ np.linalg.solve(1j * w * np.eye(n) - A, B) + D
        except np.linalg.LinAlgError:
            return None
    if not np.all(np.isfinite(H)):
        return None
    vals, vecs = np.linalg.eigh(H + H.conj().T)
    if vals[0] >= 0:
        return None
    v = vecs[:, 0] / np.max(np.abs(vecs[:, 0]))
    az, ea = _dyadic(v.real, 40)
    bz, eb = _dyadic(v.imag, 40) if np.any(v.imag) else ([0] * len(v), 0)
    return ([mpq(mpz(z), 1) / mpq(2) ** ea for z in az],
            [mpq(mpz(z), 1) / mpq(2) ** eb for z in bz])


__all__ = ["bounded_form", "float_direction"]
