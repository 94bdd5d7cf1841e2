"""Finite-band passivity certificates (generalized KYP lemma): exact check and JSON form.

Section 4 of the paper reads passivity of the human model off nu(w) >= 0; over a band
[w1, w2] only, the statement is H(jw) + H(jw)^H >= 0 for all w in [w1, w2]. By the
generalized KYP lemma (Iwasaki & Hara, IEEE TAC 50(1), 2005, Theorem 2) it follows from
Hermitian P and Q with

    Q >= 0   and   L(P, Q) = N^H (Phi (x) P + Psi (x) Q) N + Theta <= 0,

    N = [[A, B], [I, 0]],  Phi = [[0, 1], [1, 0]],  Psi = [[-1, j wc], [-j wc, -w1 w2]],
    wc = (w1 + w2)/2,      Theta = -[[0, C^T], [C, D + D^T]].

Why it suffices (the direction a certificate needs; no stability assumption): for w in
the band with jw not a pole, put x = (jwI - A)^-1 B u and z = (x, u). Then N z = (jw x, x),
so z^H L z = (lambda + conj lambda) x^H P x + psi(w) x^H Q x - u^H (H + H^H) u with
lambda = jw, where the first term vanishes and psi(w) = -(w - w1)(w - w2) >= 0 on the
band. L <= 0 and Q >= 0 thus give u^H (H(jw) + H(jw)^H) u >= 0. With Q = 0 this is the
ordinary KYP matrix of :mod:`verify.passivity.check.certificate`.

P and Q have Gaussian-rational entries (real and imaginary parts rational); the band ends
are rational. :func:`check_gkyp` decides both conditions exactly through the real
embedding X = Xr + j Xi  ->  [[Xr, -Xi], [Xi, Xr]] (Hermitian X >= 0 iff its embedding
is PSD), by exact LDL^T; no solver, no floating point.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel, KypCheck

#: A complex rational matrix as (real part, imaginary part).
ComplexMatrix = tuple[ex.RationalMatrix, ex.RationalMatrix]


def embed(X: ComplexMatrix) -> ex.RationalMatrix:
    """Real form [[Re, -Im], [Im, Re]] of a complex matrix (same quadratic form)."""
    Xr, Xi = X
    return ex.block([[Xr, ex.scale(-1, Xi)], [Xi, Xr]])


def is_hermitian(X: ComplexMatrix) -> bool:
    Xr, Xi = X
    n = len(Xr)
    return (ex.shape(Xr) == ex.shape(Xi) == (n, n) and ex.is_symmetric(Xr)
            and all(Xi[i][j] == -Xi[j][i] for i in range(n) for j in range(n)))


def gkyp_matrix(model: ExactModel, P: ComplexMatrix, Q: ComplexMatrix,
                band: tuple[Fraction, Fraction]) -> ComplexMatrix:
    """L(P, Q) of the module docstring, exactly, as (real part, imaginary part)."""
    n, m = model.n, model.m
    w1, w2 = mpq(band[0]), mpq(band[1])
    wc, w12 = (w1 + w2) / 2, w1 * w2
    (Pr, Pi), (Qr, Qi) = P, Q
    # W = Phi (x) P + Psi (x) Q = [[-Q, P + j wc Q], [P - j wc Q, -w1 w2 Q]]
    Wr = ex.block([[ex.scale(-1, Qr), ex.add(Pr, ex.scale(-wc, Qi))],
                   [ex.add(Pr, ex.scale(wc, Qi)), ex.scale(-w12, Qr)]])
    Wi = ex.block([[ex.scale(-1, Qi), ex.add(Pi, ex.scale(wc, Qr))],
                   [ex.add(Pi, ex.scale(-wc, Qr)), ex.scale(-w12, Qi)]])
    eye = [[mpq(int(i == j)) for j in range(n)] for i in range(n)]
    N = ex.block([[model.A, model.B], [eye, ex.zeros(n, m)]])
    Nt = ex.transpose(N)
    S = ex.add(model.D, ex.transpose(model.D))
    Theta = ex.block([[ex.zeros(n, n), ex.scale(-1, ex.transpose(model.C))],
                      [ex.scale(-1, model.C), ex.scale(-1, S)]])
    Lr = ex.add(ex.matmul(ex.matmul(Nt, Wr), N), Theta)
    Li = ex.matmul(ex.matmul(Nt, Wi), N)
    return Lr, Li


def check_gkyp(model: ExactModel, P: ComplexMatrix, Q: ComplexMatrix,
               band: tuple[Fraction, Fraction]) -> KypCheck:
    """Exact decision of P, Q Hermitian, Q >= 0 and L(P, Q) <= 0 for 0 <= w1 < w2."""
    n = model.n
    if not (0 <= band[0] < band[1]):
        return KypCheck(False, "the band must satisfy 0 <= w1 < w2")
    if n == 0:
        S = ex.add(model.D, ex.transpose(model.D))
        ok = ex.psd_ldl(S).ok
        return KypCheck(ok, "static gain: D + Dᵀ is PSD" if ok else "D + Dᵀ is not PSD")
    for name, X in (("P", P), ("Q", Q)):
        if ex.shape(X[0]) != (n, n) or not is_hermitian(X):
            return KypCheck(False, f"{name} must be a Hermitian {n} x {n} matrix")
    q = ex.psd_ldl(embed(Q))
    if not q.ok:
        return KypCheck(False, f"Q is not positive semidefinite ({q.reason})")
    Lr, Li = gkyp_matrix(model, P, Q, band)
    neg = ex.psd_ldl(ex.scale(-1, embed((Lr, Li))))
    if not neg.ok:
        return KypCheck(False, f"the generalized KYP matrix is not <= 0 ({neg.reason})")
    return KypCheck(True, "Q >= 0 and the generalized KYP matrix is <= 0, by exact LDLᵀ of "
                    "the real embeddings")


@dataclass(frozen=True)
class BandCertificate:
    """A checked finite-band certificate and the model and band it is about."""

    name: str
    source: str
    model: ExactModel
    band: tuple[Fraction, Fraction]
    P: ComplexMatrix
    Q: ComplexMatrix
    meta: dict


__all__ = ["BandCertificate", "ComplexMatrix", "check_gkyp", "embed", "gkyp_matrix",
           "is_hermitian"]
