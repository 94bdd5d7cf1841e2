"""The KYP equality constraints solved exactly once, leaving a regular KYP problem.

Let S = D + D^T, N an exact basis of ker S (k columns) and R an exact basis of range S.
The KYP matrix has a zero diagonal block on ker S, so every certificate satisfies the
equality P B' = C'^T with B' = B N and C' = N^T C (for a strictly proper model, N = I
and this is P B = C^T). When G0 = C' B' is symmetric positive definite, the symmetric
solutions of the equality are exactly

    P = P0 + V Y V^T,   P0 = C'^T G0^-1 C',   V^T B' = 0,   Y = Y^T free,

because in the coordinates z = T x with T = [C'; V^T] every solution is block diagonal,
diag(G0^-1, Y). P0 and V are exact rationals, so *any* rounded Y gives a P that meets
the equality exactly: no projection, and no loss of margin to one.

In those coordinates, with the rows of ker S deleted (they are zero), the KYP LMI reads
as the KYP LMI of an auxiliary system of order n - k in the unknown Y:

    [[Aa^T Y + Y Aa, Y Ba - Ca^T], [Ba^T Y - Ca, -Sa]] <= 0,

    Aa = A22,  Ba = [A21, B2r],  Ca = [-G0^-1 A12; C2r],
    Sa = [[F, -(G0^-1 B1r - C1r^T)], [., Sr]],  F = -(A11^T G0^-1 + G0^-1 A11),

(A = T A T^-1 in blocks k, n - k; Br = T B R, Cr = R^T C T^-1, Sr = R^T S R). When Sa is
positive definite that problem is regular and Riccati equations solve it
(:mod:`verify.passivity.search.riccati`). The auxiliary system is floating point: it only
steers the search; the certificate P is assembled exactly and checked exactly.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.linalg as sla

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.psd import psd_exact


@dataclass(frozen=True)
class Reduction:
    """P = P0 + V Y V^T meets the equality constraints for every symmetric Y; (Aa, Ba, Ca,
    Sa) is the regular KYP problem in Y (floating point).

    V is stored by its structure: its rows ``pivots`` hold X (k x (n - k)), its rows
    ``free`` the identity, so V Y V^T has blocks Y, X Y and X Y X^T (cheap, exact).
    """

    P0_parts: tuple[ex.RationalMatrix, ex.RationalMatrix] | None  # (C', G0^-1); None: 0
    pivots: list[int]
    free: list[int]
    X: ex.RationalMatrix
    Aa: np.ndarray
    Ba: np.ndarray
    Ca: np.ndarray
    Sa: np.ndarray

    @cached_property
    def P0(self) -> ex.RationalMatrix:
        """P0 = C'ᵀ G0⁻¹ C' (exact; formed on first use)."""
        n = len(self.pivots) + len(self.free)
        if self.P0_parts is None:
            return ex.zeros(n, n)
        Cp, K = self.P0_parts
        return ex.matmul(ex.matmul(ex.transpose(Cp), K), Cp)

    @cached_property
    def P0_float(self) -> np.ndarray:
        """P0 in floating point (it only steers the search)."""
        n = len(self.pivots) + len(self.free)
        if self.P0_parts is None:
            return np.zeros((n, n))
        Cp, K = self.P0_parts
        Cf = _floats(Cp, len(Cp), n)
        return Cf.T @ _floats(K, len(K), len(K)) @ Cf

    def assemble(self, Y: ex.RationalMatrix) -> ex.RationalMatrix:
        """P0 + V Y V^T, exactly (Y symmetric gives P symmetric)."""
        P = [row[:] for row in self.P0]
        if not Y:
            return P
        XY = ex.matmul(self.X, Y) if self.pivots else []
        XYXt = ex.matmul(XY, ex.transpose(self.X)) if self.pivots else []
        for a, i in enumerate(self.free):
            for b, j in enumerate(self.free):
                P[i][j] += Y[a][b]
        for a, i in enumerate(self.pivots):
            for b, j in enumerate(self.free):
                P[i][j] += XY[a][b]
                P[j][i] += XY[a][b]
            for b, j in enumerate(self.pivots):
                P[i][j] += XYXt[a][b]
        return P


@dataclass(frozen=True)
class NoCertificate:
    """The equality constraints admit no P > 0 (an exact argument, given as ``reason``)."""

    reason: str


@dataclass(frozen=True)
class NotReducible:
    """The reduction does not apply (``reason``); the caller searches without it."""

    reason: str


def _inverse(M: ex.RationalMatrix) -> ex.RationalMatrix:
    return ex.inverse(M)


def _floats(M: ex.RationalMatrix, rows: int, cols: int) -> np.ndarray:
    return np.array([[float(x) for x in row] for row in M]).reshape(rows, cols)


def null_basis_of_transpose(Bp: ex.RationalMatrix, n: int, k: int):
    """Exact V with V^T B' = 0, as (pivots, free, X): rows ``pivots`` of a well-conditioned
    k x k block B1 of B' hold X = -(B2 B1^-1)^T, the other rows the identity. None if no
    such block is found."""
    Bf = _floats(Bp, n, k)
    _q, _r, piv = sla.qr(Bf.T, pivoting=True)
    pivots = sorted(int(i) for i in piv[:k])
    free = [i for i in range(n) if i not in set(pivots)]
    B1 = [Bp[i] for i in pivots]
    if ex.determinant(B1) == 0:
        return None
    if not free:
        return pivots, free, [[] for _ in range(k)]  # B' square and invertible: no Y
    B2 = [Bp[i] for i in free]
    X = ex.scale(-1, ex.transpose(ex.matmul(B2, _inverse(B1))))  # k x (n-k)
    return pivots, free, X


def v_matrix(n: int, pivots: list[int], free: list[int], X: ex.RationalMatrix) -> np.ndarray:
    """V in floating point (for the coordinate change only)."""
    V = np.zeros((n, len(free)))
    for a, i in enumerate(pivots):
        V[i] = [float(x) for x in X[a]]
    for b, i in enumerate(free):
        V[i, b] = 1.0
    return V


def equality_directions(model: ExactModel) -> ex.RationalMatrix | NoCertificate:
    """An exact basis N' (m x k') of the input directions on which P B N' = C^T N' binds.

    N spans ker S. For z with B N z = 0 the equality reads 0 = C^T N z: if that fails no
    P exists (an exact argument); if it holds, the direction u = N z enters neither the
    state nor the output (H(s) u = D u) and its rows of the KYP matrix are zero for every
    P, so it is dropped. What remains, N' = N W with W spanning range((B N)^T), has
    B N' of full column rank (this is what makes one-state models with two identical
    input columns, B B^T rank deficient, decidable).
    """
    S = ex.add(model.D, ex.transpose(model.D))
    N = ex.kernel_basis(S)
    k = len(N[0]) if model.m else 0
    if k == 0 or model.n == 0:
        return N
    Bp = ex.matmul(model.B, N)
    Z = ex.kernel_basis(Bp)
    if not Z or not Z[0]:
        return N
    CtNZ = ex.matmul(ex.matmul(ex.transpose(model.C), N), Z)
    if any(x != 0 for row in CtNZ for x in row):
        return NoCertificate("a direction u in ker(D + Dᵀ) has B u = 0 but C u ≠ 0, so "
                             "P B u = Cᵀ u has no solution")
    W = ex.range_basis(ex.transpose(Bp))
    if not W or not W[0]:
        return [[] for _ in range(model.m)]
    return ex.matmul(N, W)


def reduce_kyp(model: ExactModel) -> Reduction | NoCertificate | NotReducible:
    """The exact parametrisation and the auxiliary problem; :class:`NotReducible` says why
    the reduction does not apply (the caller then searches without it)."""
    n, m = model.n, model.m
    S = ex.add(model.D, ex.transpose(model.D))
    N = equality_directions(model)
    if isinstance(N, NoCertificate):
        return N
    k = len(N[0]) if m else 0
    Sf = _floats(S, m, m)
    Af, Bf, Cf = _floats(model.A, n, n), _floats(model.B, n, m), _floats(model.C, m, n)
    R = ex.range_basis(S)
    r = len(R[0]) if R and R[0] else 0
    Rf = _floats(R, m, r) if r else np.zeros((m, 0))
    if k == 0:
        if r == m:  # S > 0: no equality constraint
            return Reduction(None, [], list(range(n)), [], Af, Bf, Cf, Sf)
        if r == 0:
            return NotReducible("B = 0 on ker(D + Dᵀ) and D + Dᵀ = 0")
        # the kernel directions were all dropped: the problem lives on range S
        return Reduction(None, [], list(range(n)), [], Af, Bf @ Rf, Rf.T @ Cf,
                         Rf.T @ Sf @ Rf)
    Bp = ex.matmul(model.B, N)
    Cp = ex.matmul(ex.transpose(N), model.C)
    G0 = ex.matmul(Cp, Bp)
    if not ex.is_symmetric(G0):
        return NoCertificate("Nᵀ C B N is not symmetric, so P B N = Cᵀ N has no symmetric P")
    if not psd_exact(G0).ok:
        return NoCertificate("Nᵀ C B N is not positive semidefinite, so no P > 0 has "
                             "P B N = Cᵀ N (it would equal (B N)ᵀ P (B N))")
    if not psd_exact(G0, strict=True).ok:
        return NotReducible("Nᵀ C B N is singular")
    basis = null_basis_of_transpose(Bp, n, k)
    if basis is None:
        return NotReducible("no well-conditioned k x k block of B N")
    pivots, free, X = basis
    K = _inverse(G0)
    # the auxiliary system, in floating point (it only steers the search)
    T = np.vstack([_floats(Cp, k, n), v_matrix(n, pivots, free, X).T])
    try:
        Ti = np.linalg.inv(T)
    except np.linalg.LinAlgError:
        return NotReducible("the coordinate change [C'; Vᵀ] is numerically singular")
    Kf = _floats(K, k, k)
    At, Btr, Ctr = T @ Af @ Ti, T @ Bf @ Rf, Rf.T @ Cf @ Ti
    Sr = Rf.T @ Sf @ Rf
    A11, A12, A21, A22 = At[:k, :k], At[:k, k:], At[k:, :k], At[k:, k:]
    B1r, B2r, C1r, C2r = Btr[:k], Btr[k:], Ctr[:, :k], Ctr[:, k:]
    F = -(A11.T @ Kf + Kf @ A11)
    cross = -(Kf @ B1r - C1r.T)
    Sa = np.block([[F, cross], [cross.T, Sr]])
    Sa = (Sa + Sa.T) / 2
    w = np.linalg.eigvalsh(Sa)
    if w[0] <= 1e-12 * max(1.0, abs(w[-1])):
        return NotReducible("the auxiliary problem is singular (Sa is not positive definite)")
    Ba = np.hstack([A21, B2r])
    Ca = np.vstack([-Kf @ A12, C2r])
    return Reduction((Cp, K), pivots, free, X, A22, Ba, Ca, Sa)
