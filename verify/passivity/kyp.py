"""Find a KYP certificate numerically, then make it exact (untrusted search, trusted check).

1. Balance the state coordinates with a diagonal similarity of powers of two (exact, so
   the certificate maps back without rounding): badly scaled models (poles near 1e12
   and 1e-4 together) become tractable.
2. Solve the KYP LMI with cvxpy + Clarabel, maximising a margin t: P >= t I and
   -M(P) >= t on every direction where a margin is possible (the state block and the
   range of D + D^T), t <= 1. (No trace normalisation: for a strictly proper model
   P B = C^T fixes the scale of P.) Directions in the kernel of S = D + D^T carry the
   equality (P B - C^T) N = 0 instead (N spans ker S; for a strictly proper model
   N = I and the constraint is P B = C^T exactly).
3. Round P to dyadic rationals, restore the equality constraints exactly by a symmetric
   rank-2k correction (Peyrl-Parrilo style projection), and check P > 0, M(P) <= 0 by
   exact LDL^T (:mod:`verify.passivity.certificate`). Several rounding precisions are
   tried; the solver's status never decides anything.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from fractions import Fraction

import cvxpy as cp
import numpy as np
import scipy.linalg as sla
import sympy as sp
from gmpy2 import mpq

from verify.passivity import exact as ex
from verify.passivity.certificate import ExactModel, check_kyp


@dataclass
class KypSearch:
    P: ex.RationalMatrix | None
    margin: float | None
    status: str
    reason: str


def _kernel_basis(S: ex.RationalMatrix) -> ex.RationalMatrix:
    """Exact rational basis of ker S as columns (m x k); k may be 0."""
    vecs = ex.to_sympy(S).nullspace()
    if not vecs:
        return [[] for _ in range(len(S))]
    return ex.from_sympy(sp.Matrix.hstack(*vecs))


def _balance(A: np.ndarray) -> np.ndarray:
    """Diagonal scaling T (powers of 2) so that T^-1 A T is balanced."""
    if A.shape[0] == 0:
        return np.ones(0)
    _, (scaling, _) = sla.matrix_balance(A, permute=False, separate=True)
    return np.asarray(scaling, dtype=float)


def solve_numeric(A, B, C, D, N: np.ndarray) -> tuple[np.ndarray | None, float | None, str]:
    """Max-margin KYP solution in the given coordinates (cvxpy + Clarabel)."""
    n, m = A.shape[0], D.shape[0]
    S = D + D.T
    P = cp.Variable((n, n), symmetric=True)
    t = cp.Variable()
    M = cp.bmat([[A.T @ P + P @ A, P @ B - C.T], [B.T @ P - C, -S]])
    # margin on the state block and on the range of S (not on ker S)
    if N.shape[1]:
        Q, _ = np.linalg.qr(N)
        range_proj = np.eye(m) - Q @ Q.T
        range_proj[np.abs(range_proj) < 1e-12] = 0.0  # no margin asked where S vanishes
    else:
        range_proj = np.eye(m)
    E = sla.block_diag(np.eye(n), range_proj)
    cons = [P >> t * np.eye(n), -M >> t * E, t <= 1.0]  # (a trace bound upsets Clarabel)
    if N.shape[1]:
        cons.append((P @ B - C.T) @ N == 0)
    prob = cp.Problem(cp.Maximize(t), cons)
    try:
        with warnings.catch_warnings():  # an inaccurate solution is caught by the exact check
            warnings.simplefilter("ignore")
            prob.solve(solver=cp.CLARABEL)
    except (cp.error.SolverError, ValueError) as exc:
        return None, None, f"solver error: {exc}"
    if P.value is None:
        return None, None, f"solver status {prob.status}"
    return np.asarray(P.value), float(t.value), str(prob.status)


def riccati_candidate(A, B, C, D) -> np.ndarray | None:
    """An interior KYP candidate from two Riccati solutions, O(n^3) (no SDP).

    With S = D + D^T > 0 (regularised to S + 2 eps I when singular), the KYP LMI's
    boundary is the Riccati equation A^T P + P A + (P B - C^T) S^-1 (B^T P - C) = 0. Its
    stabilising and anti-stabilising solutions bound the feasible P (available storage
    and required supply); their midpoint is an interior point when the two differ. The
    candidate is only a proposal: it is rounded, projected and checked exactly.
    """
    n, m = A.shape[0], D.shape[0]
    S = D + D.T
    w = np.linalg.eigvalsh(S)
    scale = max(1.0, float(np.abs(C @ B).max()) if n else 1.0)
    if w[0] <= 1e-9 * max(1.0, abs(w[-1])):
        S = S + 2e-7 * scale * np.eye(m)
    try:
        with np.errstate(all="ignore"):
            # scipy solves A'X + XA - (XB + s) R^-1 (B'X + s') + Q = 0; with X = -P this is
            # the KYP Riccati equation. Stabilising solution: X1. Anti-stabilising: -Y with
            # Y the stabilising solution for (-A, B, s = -C^T).
            X1 = sla.solve_continuous_are(A, B, np.zeros((n, n)), S, s=C.T)
            Y = sla.solve_continuous_are(-A, B, np.zeros((n, n)), S, s=-C.T)
    except (np.linalg.LinAlgError, ValueError):
        return None
    P = (-X1 + Y) / 2  # midpoint of the two extreme solutions P1 = -X1 and P2 = Y
    if not np.all(np.isfinite(P)):
        return None
    return (P + P.T) / 2


def _project_equalities(P: ex.RationalMatrix, G: ex.RationalMatrix, target: ex.RationalMatrix):
    """Symmetric exact correction so that P G = target (G full column rank, G^T target sym)."""
    R = ex.add(target, ex.matmul(P, G), -1)
    Hq = ex.from_sympy(ex.to_sympy(ex.matmul(ex.transpose(G), G)).inv())
    RH = ex.matmul(R, Hq)
    GH = ex.matmul(G, Hq)
    GtR = ex.matmul(ex.transpose(G), R)
    term1 = ex.matmul(RH, ex.transpose(G))
    term2 = ex.matmul(GH, ex.transpose(R))
    term3 = ex.matmul(ex.matmul(GH, GtR), ex.matmul(Hq, ex.transpose(G)))
    delta = ex.add(ex.add(term1, term2), term3, -1)
    return ex.add(P, delta)


def _roundings(P_float: np.ndarray):
    """Rational candidates near P: dyadic at several precisions, then short fractions.

    Short continued-fraction rationals recover exact solutions on the boundary of the LMI
    (e.g. a lossless direction that pins an entry of P to 2), which no dyadic rounding of
    a floating-point P meets exactly.
    """
    scale = max(1.0, float(np.max(np.abs(P_float))))
    for bits in (24, 36, 48, 60):
        step_bits = max(bits - int(np.ceil(np.log2(scale))), 8)
        yield f"{bits}-bit", ex.rationalize(P_float, step_bits)
    for limit in (16, 1000, 10**6):
        yield f"continued-fraction (denominators <= {limit})", [
            [mpq(Fraction(float(x)).limit_denominator(limit)) for x in row] for row in P_float
        ]


def find_certificate(model: ExactModel, A, B, C, D) -> KypSearch:
    """Search, round, project and check; returns an exactly checked P or the reason."""
    n, m = model.n, model.m
    S = ex.add(model.D, ex.transpose(model.D))
    N_exact = _kernel_basis(S)
    k = len(N_exact[0]) if m else 0
    if n == 0:
        ok = check_kyp(model, [])
        return KypSearch([] if ok.ok else None, None, "static", ok.reason)
    scaling = _balance(A)
    T, Ti = np.diag(scaling), np.diag(1.0 / scaling)
    Ab, Bb, Cb = Ti @ A @ T, Ti @ B, C @ T
    N = np.array([[float(x) for x in row] for row in N_exact]) if k else np.zeros((m, 0))
    if k:
        G = ex.matmul(model.B, N_exact)
        target = ex.matmul(ex.transpose(model.C), N_exact)
        GtT = ex.matmul(ex.transpose(G), target)
        if not ex.is_symmetric(GtT):
            return KypSearch(None, None, "structure",
                             "N^T C B N is not symmetric, so P B N = C^T N has no symmetric P")
        if ex.to_sympy(ex.matmul(ex.transpose(G), G)).det() == 0:
            return KypSearch(None, None, "structure", "B N is rank deficient (not handled)")
    last, margin, status = "not tried", None, "riccati"
    for method in ("riccati", "sdp"):
        if method == "riccati":
            Pb = riccati_candidate(Ab, Bb, Cb, D)
        else:
            Pb, margin, status = solve_numeric(Ab, Bb, Cb, D, N)
        if Pb is None:
            last = f"no {method} candidate ({status})"
            continue
        P_float = Ti.T @ Pb @ Ti  # back to the model's coordinates
        P_float = (P_float + P_float.T) / 2
        for label, P in _roundings(P_float):
            P = [[(P[i][j] + P[j][i]) / 2 for j in range(n)] for i in range(n)]
            if k:
                P = _project_equalities(P, G, target)
            result = check_kyp(model, P)
            if result.ok:
                return KypSearch(P, margin, status,
                                 f"{result.reason} ({method} candidate, {label} rounding)")
            last = f"{method}: {result.reason}"
    return KypSearch(None, margin, status,
                     f"the rounded numerical solutions fail the exact check: {last}")
