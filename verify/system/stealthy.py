"""Section 2 of the paper: the collective direction d, S(d), dbar, its Jacobian, W(d), A(d).

Notation (paper, Section 2): R_i in SO(3) are the body attitudes, d_i = R_i e3,
s = sum_i d_i and dbar = s / |s|. Facts used below (each is a registered claim in
:mod:`verify.claims.section2`, checked exactly):

* the block S_i = -R_i hat(e3), so d_i' = S_i omega_i;
* d dbar / d d_i = P / |s| with P = I - dbar dbar^T, the same block for every i;
* W = ((d dbar / d d) S)^T has blocks W_i = hat(e3) R_i^T P / |s|, hence W dbar = 0:
  W^T W is singular for every network, so the paper's (W^T W)^{-1} does not exist;
* W has rank exactly 2 whenever dbar is defined; the repaired projector is
  A = I - W W^+ (Moore-Penrose), equal to I - W M^{-1} W^T with M = W^T W + c dbar dbar^T
  for any c > 0.

S and A depend on the attitudes R_i, not on d alone (a yaw of body i about d_i turns
block i by a body-frame rotation), so the functions here take the attitudes.

Two ways to apply A: :func:`projector_dense` builds the 3n x 3n matrix from an SVD of W
(the reference) and :func:`apply_projector` applies it in O(n) through a QR factorisation
of the 3n x 2 matrix W E, E an orthonormal basis of the plane orthogonal to dbar.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from verify.errors import DbarUndefinedError, VerifyInputError
from verify.so3 import E3, Array, check_rotations, hat, transpose

#: |sum d_i| must exceed ``DBAR_RELATIVE_TOLERANCE * n`` for dbar to count as defined.
DBAR_RELATIVE_TOLERANCE = 1e-9

_HAT_E3 = hat(E3)


def directions(R: ArrayLike) -> Array:
    """The pointing directions d_i = R_i e3 (shape (n, 3)), paper Section 2."""
    return np.asarray(R, dtype=float)[..., :, 2]


def as_network(R: ArrayLike, *, check: bool = True) -> Array:
    """Attitudes of a network as an (n, 3, 3) array, checked to lie in SO(3)."""
    arr = check_rotations(R, name="body attitude") if check else np.asarray(R, dtype=float)
    if arr.ndim != 3:
        raise VerifyInputError(f"a network is an (n, 3, 3) array of attitudes, got {arr.shape}")
    if arr.shape[0] == 0:
        raise VerifyInputError("a network needs at least one body (n >= 1)")
    return arr


def s_blocks(R: ArrayLike) -> Array:
    """Diagonal blocks S_i = -R_i hat(e3) of S(d) (shape (n, 3, 3))."""
    return -np.asarray(R, dtype=float) @ _HAT_E3


def s_matrix(R: ArrayLike) -> Array:
    """The block-diagonal S(d) in R^{3n x 3n} (dense; for references and small n)."""
    blocks = s_blocks(R)
    n = blocks.shape[0]
    S = np.zeros((3 * n, 3 * n))
    for i in range(n):
        S[3 * i : 3 * i + 3, 3 * i : 3 * i + 3] = blocks[i]
    return S


def direction_sum(R: ArrayLike) -> Array:
    """s = sum_i d_i."""
    return directions(R).sum(axis=0)


def dbar(R: ArrayLike, tolerance: float = DBAR_RELATIVE_TOLERANCE) -> Array:
    """The average direction dbar = s / |s| (paper, Section 2).

    Raises :class:`~verify.errors.DbarUndefinedError` when |s| <= tolerance * n, where the
    direction is undefined (s = 0) or dominated by rounding.
    """
    s = direction_sum(R)
    n = np.asarray(R).shape[0]
    norm = float(np.linalg.norm(s))
    if not norm > tolerance * n:
        raise DbarUndefinedError(
            f"dbar is undefined: |sum d_i| = {norm:.3g} <= {tolerance:g} * n (n = {n}); "
            "the bodies' directions cancel out"
        )
    return s / norm


def dbar_jacobian_block(R: ArrayLike) -> Array:
    """The common block d dbar / d d_i = (I - dbar dbar^T) / |s| (3 x 3)."""
    u = dbar(R)
    s_norm = float(np.linalg.norm(direction_sum(R)))
    return (np.eye(3) - np.outer(u, u)) / s_norm


def dbar_jacobian(R: ArrayLike) -> Array:
    """d dbar / d d in R^{3 x 3n}: the block of :func:`dbar_jacobian_block` repeated n times."""
    n = np.asarray(R).shape[0]
    return np.tile(dbar_jacobian_block(R), (1, n))


def w_blocks(R: ArrayLike, *, scaled: bool = True) -> Array:
    """Blocks W_i = (J_i S_i)^T = hat(e3) R_i^T P / |s| of W(d) (shape (n, 3, 3)).

    With ``scaled=False`` the factor 1/|s| is left out; A(d) does not depend on it.
    """
    R = np.asarray(R, dtype=float)
    u = dbar(R)
    P = np.eye(3) - np.outer(u, u)
    blocks = _HAT_E3 @ transpose(R) @ P
    if scaled:
        blocks = blocks / float(np.linalg.norm(direction_sum(R)))
    return blocks


def w_matrix(R: ArrayLike, *, scaled: bool = True) -> Array:
    """W(d) = ((d dbar / d d) S(d))^T in R^{3n x 3} (paper, Section 2)."""
    return w_blocks(R, scaled=scaled).reshape(-1, 3)


def projector_dense(R: ArrayLike) -> Array:
    """Dense reference for the repaired stealthy projector A = I - W W^+ (3n x 3n).

    W^+ is taken from the SVD of W keeping its two non-zero singular values: rank W = 2
    exactly whenever dbar is defined (claim ``sec2.w-rank-two``), so no rcond guess.
    """
    W = w_matrix(R, scaled=False)
    U, _, _ = np.linalg.svd(W, full_matrices=False)
    U2 = U[:, :2]
    A = -(U2 @ U2.T)
    A[np.diag_indices_from(A)] += 1.0
    return A


def _tangent_basis(u: Array) -> Array:
    """An orthonormal basis E (3 x 2) of the plane orthogonal to the unit vector u."""
    helper = np.eye(3)[int(np.argmin(np.abs(u)))]
    a = np.cross(u, helper)
    a /= np.linalg.norm(a)
    return np.stack([a, np.cross(u, a)], axis=1)


def range_basis(R: ArrayLike) -> Array:
    """Orthonormal basis Q (3n x 2) of range W, in O(n).

    Since W~ dbar = 0, W~ = B E^T with E an orthonormal basis of the plane orthogonal to
    dbar and B = W~ E (blocks hat(e3) R_i^T E, because P E = E). B has full column rank
    2 (claim ``sec2.w-rank-two``). Q comes from Gram-Schmidt with one re-orthogonalisation
    (CGS2) on the two columns of B: as accurate as a Householder QR (orthogonality to
    rounding, span error of order eps * kappa(W), no squaring of the condition number as
    the normal equations with W^T W would have), and a few vector operations in O(n).
    """
    R = np.asarray(R, dtype=float)
    E = _tangent_basis(dbar(R))
    M = np.tensordot(R, E, axes=([1], [0]))  # M_i = R_i^T E, one (3n x 3) @ (3 x 2) product
    zero = np.zeros(M.shape[0])
    # column k of B: the blocks hat(e3) M_i[:, k] = e3 x M_i[:, k], kept contiguous
    b1, b2 = (np.stack([-M[:, 1, k], M[:, 0, k], zero], axis=1).reshape(-1) for k in (0, 1))
    q1 = b1 / np.sqrt(_dot(b1, b1))
    v = b2 - q1 * _dot(q1, b2)
    v -= q1 * _dot(q1, v)  # the second pass restores orthogonality lost to cancellation
    return np.column_stack([q1, v / np.sqrt(_dot(v, v))])


def _dot(x: Array, y: Array) -> float:
    """x . y for long vectors (einsum: BLAS ddot was found 100x slower on busy machines)."""
    return float(np.einsum("i,i->", x, y))


def apply_projector(R: ArrayLike, x: ArrayLike) -> Array:
    """Apply the repaired projector A = I - W W^+ = I - Q Q^T to ``x`` in O(n).

    ``x`` has shape (3n,) or (3n, k); Q is :func:`range_basis`.
    """
    x = np.asarray(x, dtype=float)
    Q = range_basis(R)
    return x - Q @ (Q.T @ x)


def dbar_rate_unscaled(R: ArrayLike, omega: ArrayLike) -> Array:
    """|s| dbar' = P sum_i S_i omega_i for body velocities ``omega`` (eq. (3) times |s|).

    ``omega`` has shape (n, 3) or (n, 3, k); the result (3,) or (3, k). Leaving out 1/|s|
    keeps the residual of the stealthy identity on the scale of its inputs.
    """
    u = dbar(R)
    P = np.eye(3) - np.outer(u, u)
    return P @ np.einsum("nij,nj...->i...", s_blocks(R), np.asarray(omega, dtype=float))


def projector_rounding_bound(R: ArrayLike) -> tuple[float, float]:
    """Rounding bound per unit input for applying A, and kappa = s1/s2 of W~.

    A backward-stable application of an orthogonal projector built from a rank-2 W~ has
    forward error of order eps * kappa(W~), with a dimension factor 3n from the sums;
    the constant 10 covers the few operations per entry: bound = 10 * 3n * eps * kappa.
    """
    sv = np.linalg.svd(w_matrix(R, scaled=False), compute_uv=False)
    kappa = float(sv[0] / sv[1])
    return 10.0 * 3 * np.asarray(R).shape[0] * float(np.finfo(float).eps) * kappa, kappa


def stealthy_input(R: ArrayLike, omega_tilde_a: ArrayLike) -> Array:
    """Autonomous body velocities Omega_a = A(d) Omega~_a as an (n, 3) array."""
    R = np.asarray(R, dtype=float)
    w = np.asarray(omega_tilde_a, dtype=float).reshape(-1)
    return apply_projector(R, w).reshape(R.shape[0], 3)
