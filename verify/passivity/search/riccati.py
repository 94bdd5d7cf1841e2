"""Interior points of a regular KYP LMI from Riccati equations with a margin, O(n^3).

For S > 0 the KYP LMI [[A^T P + P A, P B - C^T], [B^T P - C, -S]] <= 0 is, by a Schur
complement, the Riccati inequality

    Ric(P) = A^T P + P A + (P B - C^T) S^-1 (B^T P - C) <= 0.

A solution of the *equation* Ric(P) = 0 sits on the boundary of the LMI (its Schur
complement has rank m only), and so does the midpoint of two of them; rounding such a
point breaks the LMI. Solving Ric(P) = -W with W = w I > 0 instead gives a point with
margin w in every direction. Ric is convex, so the midpoint of the stabilising and the
anti-stabilising solutions of Ric(P) = -W has Ric <= -W as well, plus extra margin
where the two differ. The margin w is tried from large to small: too large a w has no
solution (the Hamiltonian gets imaginary-axis eigenvalues). Candidates are screened in
floating point here and decided exactly by the caller.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import scipy.linalg as sla


def stabilising_solution(A, B, C, S, W) -> np.ndarray | None:
    """The stabilising (smallest) solution of Ric(P) = -W from one ordered real Schur
    form of the Hamiltonian matrix, or None (imaginary-axis eigenvalues, W too large; a
    singular basis; a residual that is not small).

    With F = A - B S^-1 C, G = B S^-1 B^T and Q = C^T S^-1 C + W, Ric(P) = -W reads
    F^T X + X F - X G X - Q = 0 for X = -P, whose Hamiltonian is H = [[F, -G], [Q, -F^T]].
    A basis [U1; U2] of its stable invariant subspace gives X = U2 U1^-1 (A. J. Laub,
    IEEE Trans. Automat. Control 24 (1979) 913-921). One Schur decomposition of H costs
    about two eigenvalue computations of it, where scipy's ``solve_continuous_are``
    runs a QZ decomposition of a larger pencil. Ric(P) <= -W < 0 gives the KYP LMI a
    margin, so the solution itself is a candidate (no midpoint needed).
    """
    n = A.shape[0]
    try:
        with np.errstate(all="ignore"):
            Si = np.linalg.inv(S)
            F = A - B @ Si @ C
            H = np.block([[F, -(B @ Si @ B.T)], [C.T @ Si @ C + W, -F.T]])
            if not np.all(np.isfinite(H)):
                return None
            _T, Z, sdim = sla.schur(H, output="real", sort="lhp")
            if sdim != n:
                return None
            U1, U2 = Z[:n, :n], Z[n:, :n]
            P = -np.linalg.solve(U1.T, U2.T).T
            P = (P + P.T) / 2
            if not np.all(np.isfinite(P)):
                return None
            K = P @ B - C.T
            residual = A.T @ P + P @ A + K @ Si @ K.T + W
            scale = np.abs(A.T @ P).max() + np.abs(K).max() ** 2 * np.abs(Si).max() + \
                np.abs(W).max()
    except (np.linalg.LinAlgError, ValueError):
        return None
    if not np.isfinite(scale) or np.abs(residual).max() > 1e-8 * scale:
        return None
    return P


def riccati_pair(A, B, C, S, W) -> tuple[np.ndarray, np.ndarray] | None:
    """The two extreme solutions of Ric(P) = -W, or None when scipy finds none.

    scipy solves A^T X + X A - (X B + s) R^-1 (B^T X + s^T) + Q = 0. With X = -P and
    s = C^T this is Ric(P) = Q (stabilising solution: the smaller P); with -A for A,
    X = P and s = -C^T it is Ric(P) = Q again (the larger P).
    """
    try:
        with np.errstate(all="ignore"):
            low = -sla.solve_continuous_are(A, B, -W, S, s=C.T)
            high = sla.solve_continuous_are(-A, B, -W, S, s=-C.T)
    except (np.linalg.LinAlgError, ValueError):
        return None
    if not (np.all(np.isfinite(low)) and np.all(np.isfinite(high))):
        return None
    return (low + low.T) / 2, (high + high.T) / 2


def lmi_margin(A, B, C, S, P) -> float:
    """-lambda_max of the KYP matrix and lambda_min of P, the smaller (floating point)."""
    M = np.block([[A.T @ P + P @ A, P @ B - C.T], [B.T @ P - C, -S]])
    top = float(np.linalg.eigvalsh((M + M.T) / 2)[-1])
    low = float(np.linalg.eigvalsh(P)[0]) if P.size else np.inf
    return min(-top, low)


#: margins w = rho 10^-k tried first, one Schur form each (k): a large margin survives
#: rounding, a small one exists for more models
FIRST_MARGINS = (3, 6, 1, 9)


def margin_candidates(A, B, C, S, steps: int = 9) -> Iterator[tuple[np.ndarray, float]]:
    """Strictly feasible P for the regular KYP LMI, largest margin first, with the margin
    w used; nothing is yielded when the LMI has no strictly feasible point found so."""
    n = A.shape[0]
    if n == 0:
        yield np.zeros((0, 0)), 0.0
        return
    try:  # S is positive definite in floating point, but may be badly conditioned
        with np.errstate(all="ignore"):
            Sinv = np.linalg.inv(S)
            # ||C^T S^-1 C||_2 from the m x m matrix S^-1 C C^T (same nonzero spectrum
            # for symmetric S): no n x n singular value decomposition
            rho = float(np.max(np.abs(np.linalg.eigvals(Sinv @ (C @ C.T)))))
            if not np.isfinite(rho) or rho == 0.0:
                rho = max(float(np.linalg.norm(A, 2)), 1.0)
    except (np.linalg.LinAlgError, ValueError):
        return
    if not np.isfinite(rho):
        return
    order = FIRST_MARGINS + tuple(j for j in range(steps) if j not in FIRST_MARGINS)
    for j in order:  # one Schur form each, at margins likely to work first
        w = rho * 10.0 ** (-j)
        P = stabilising_solution(A, B, C, S, w * np.eye(n))
        if P is not None:
            yield P, w
    for j in range(steps):
        w = rho * 10.0 ** (-j)
        pair = riccati_pair(A, B, C, S, w * np.eye(n))  # QZ: slower, more robust
        if pair is None:
            continue
        low, high = pair
        for P in ((low + high) / 2, low, high):
            if lmi_margin(A, B, C, S, P) > 0:
                yield P, w
                break
