"""The SO(3) kernel used by every other module (paper, Section 2: R_i in SO(3), eq. (1)).

All functions are vectorised over leading batch dimensions: a vector argument has shape
``(..., 3)`` and a matrix argument ``(..., 3, 3)``.

* ``hat`` (the paper's wedge) maps R^3 to skew-symmetric matrices, ``vee`` is its inverse;
* ``sk`` and ``sym`` are the skew and symmetric parts, sk(A) = (A - A^T)/2 (Section 3);
* ``exp`` is Rodrigues' formula, ``log`` the principal logarithm, accurate up to and at
  a rotation angle of pi (it goes through scipy's quaternion extraction, Markley's method);
* ``rotation_angle`` / ``geodesic_distance`` use atan2 of the skew and symmetric parts,
  which is accurate at every angle (arccos of the trace is not, near 0 and pi);
* ``project`` returns the nearest rotation in the Frobenius norm (SVD);
* ``check_rotations`` rejects non-finite input, wrong shapes and non-rotations.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial.transform import Rotation

from verify.errors import NotARotationError, VerifyInputError
from verify.validation import message

Array = NDArray[np.float64]

#: Default tolerance on max |R^T R - I| and |det R - 1| for accepting a matrix as a rotation.
ROTATION_TOLERANCE = 1e-9

E3 = np.array([0.0, 0.0, 1.0])


def hat(v: ArrayLike) -> Array:
    """Skew-symmetric matrix of ``v`` (shape ``(..., 3)`` -> ``(..., 3, 3)``): hat(v) w = v x w."""
    v = np.asarray(v, dtype=float)
    if v.ndim == 0 or v.shape[-1] != 3:
        raise VerifyInputError(message(
            "vectors of shape (..., 3)", "v", v, "pass 3-vectors (hat maps R^3 to so(3)); "
            "for a quaternion (w, x, y, z) use quaternion_to_matrix",
            detail=f"shape {v.shape}"))
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    zero = np.zeros_like(x)
    return np.stack(
        [
            np.stack([zero, -z, y], axis=-1),
            np.stack([z, zero, -x], axis=-1),
            np.stack([-y, x, zero], axis=-1),
        ],
        axis=-2,
    )


def vee(M: ArrayLike) -> Array:
    """Inverse of :func:`hat` applied to the skew part of ``M``: vee(M) = vee(sk(M)).

    For a skew-symmetric ``M`` this is the exact inverse of ``hat``; for a general square
    matrix it is the paper's ``sk(M)^vee``.
    """
    M = np.asarray(M, dtype=float)
    return 0.5 * np.stack(
        [
            M[..., 2, 1] - M[..., 1, 2],
            M[..., 0, 2] - M[..., 2, 0],
            M[..., 1, 0] - M[..., 0, 1],
        ],
        axis=-1,
    )


def transpose(M: ArrayLike) -> Array:
    """Transpose of the last two axes."""
    return np.swapaxes(np.asarray(M, dtype=float), -1, -2)


def sk(M: ArrayLike) -> Array:
    """Skew-symmetric part (M - M^T)/2 (paper, after eq. (6))."""
    M = np.asarray(M, dtype=float)
    return 0.5 * (M - transpose(M))


def sym(M: ArrayLike) -> Array:
    """Symmetric part (M + M^T)/2 (paper, proof of Lemma 1)."""
    M = np.asarray(M, dtype=float)
    return 0.5 * (M + transpose(M))


def _flat_vectors(v: Array) -> tuple[Array, tuple[int, ...]]:
    return v.reshape(-1, 3), v.shape[:-1]


def exp(w: ArrayLike) -> Array:
    """Rodrigues' formula exp(hat(w)) = cos(t) I + sinc(t) hat(w) + ((1 - cos t)/t^2) w w^T.

    t = |w|. The coefficients are written with ``np.sinc`` so they are accurate for every
    t, including t -> 0 (no cancellation) and t near pi; cos t is formed as
    1 - t^2 (1 - cos t)/t^2. The nine entries are assembled directly (no batched matrix
    products), which matters for the simulator's large networks.
    """
    w = np.asarray(w, dtype=float)
    if w.shape[-1:] != (3,):
        raise VerifyInputError(f"exp expects vectors of shape (..., 3), got {w.shape}")
    t2 = np.sum(w * w, axis=-1)
    t = np.sqrt(t2)
    a = np.sinc(t / np.pi)  # sin(t)/t
    b = 0.5 * np.sinc(t / (2.0 * np.pi)) ** 2  # (1 - cos t)/t^2 = 2 sin^2(t/2)/t^2
    c = 1.0 - b * t2  # cos t
    x, y, z = w[..., 0], w[..., 1], w[..., 2]
    bx, by, bz = b * x, b * y, b * z
    ax, ay, az = a * x, a * y, a * z
    xy, xz, yz = bx * y, bx * z, by * z
    R = np.empty((*w.shape[:-1], 3, 3))
    R[..., 0, 0], R[..., 0, 1], R[..., 0, 2] = c + bx * x, xy - az, xz + ay
    R[..., 1, 0], R[..., 1, 1], R[..., 1, 2] = xy + az, c + by * y, yz - ax
    R[..., 2, 0], R[..., 2, 1], R[..., 2, 2] = xz - ay, yz + ax, c + bz * z
    return R


def log(R: ArrayLike) -> Array:
    """Principal logarithm as a rotation vector (``(..., 3, 3)`` -> ``(..., 3)``), |w| <= pi.

    Uses scipy's quaternion extraction (Markley's method), which stays accurate for
    rotation angles at and near pi where the textbook formula theta/(2 sin theta) fails.
    """
    R = np.asarray(R, dtype=float)
    flat = R.reshape(-1, 3, 3)
    if flat.shape[0] == 0:
        return np.zeros((*R.shape[:-2], 3))
    w = Rotation.from_matrix(flat).as_rotvec()
    return w.reshape((*R.shape[:-2], 3))


def rotation_angle(R: ArrayLike) -> Array:
    """Rotation angle in [0, pi] of ``R``, as atan2(|sk(R)^vee|, (tr R - 1)/2)."""
    R = np.asarray(R, dtype=float)
    s = np.linalg.norm(vee(R), axis=-1)
    c = 0.5 * (np.trace(R, axis1=-2, axis2=-1) - 1.0)
    return np.arctan2(s, c)


def geodesic_distance(R1: ArrayLike, R2: ArrayLike) -> Array:
    """Geodesic (bi-invariant) distance: the rotation angle of R1^T R2, in [0, pi]."""
    return rotation_angle(transpose(R1) @ np.asarray(R2, dtype=float))


def random_rotations(size: int | tuple[int, ...], rng: np.random.Generator) -> Array:
    """Haar-uniform random rotations of batch shape ``size``.

    Normalised Gaussian quaternions are uniform on S^3, hence their rotations are uniform
    on SO(3).
    """
    shape = (size,) if isinstance(size, int) else tuple(size)
    q = rng.standard_normal((*shape, 4))
    return quaternion_to_matrix(q)


def quaternion_to_matrix(q: ArrayLike) -> Array:
    """Rotation of the quaternion q = (w, x, y, z), normalised first (shape (..., 4)).

    R(q) = I + 2 (w hat(v) + hat(v)^2) / |q|^2 with v = (x, y, z), the rational form that
    :mod:`verify.symbolic` uses exactly.
    """
    q = np.asarray(q, dtype=float)
    if q.shape[-1:] != (4,):
        raise VerifyInputError(f"quaternions must have shape (..., 4), got {q.shape}")
    norm2 = np.sum(q * q, axis=-1)
    if np.any(~np.isfinite(q)):
        raise VerifyInputError("quaternion contains NaN or Inf")
    if np.any(norm2 == 0.0):
        raise VerifyInputError("the zero quaternion is not a rotation")
    K = hat(q[..., 1:])
    eye = np.broadcast_to(np.eye(3), K.shape)
    return eye + 2.0 * (q[..., 0, None, None] * K + K @ K) / norm2[..., None, None]


def project(M: ArrayLike) -> Array:
    """Nearest rotation to ``M`` in the Frobenius norm: U diag(1, 1, det(U V^T)) V^T."""
    M = np.asarray(M, dtype=float)
    U, _, Vt = np.linalg.svd(M)
    det = np.linalg.det(U @ Vt)
    D = np.ones(M.shape[:-1])
    D[..., 2] = det
    return (U * D[..., None, :]) @ Vt


def orthogonality_error(R: ArrayLike) -> Array:
    """max |R^T R - I| entrywise, per matrix of the batch."""
    R = np.asarray(R, dtype=float)
    E = transpose(R) @ R - np.eye(3)
    return np.max(np.abs(E), axis=(-2, -1))


def check_rotations(
    R: ArrayLike, name: str = "rotation", tolerance: float = ROTATION_TOLERANCE
) -> Array:
    """Return ``R`` as a float array after checking it is a batch of rotations.

    Raises :class:`~verify.errors.VerifyInputError` for a wrong shape or non-finite
    entries and :class:`~verify.errors.NotARotationError` when max |R^T R - I| or
    |det R - 1| exceeds ``tolerance``; the message names the first offending index.
    """
    from verify.inputs.numbers import real_array

    arr = real_array(R, name)  # finite real numbers, or one line naming the entry
    if arr.ndim < 2 or arr.shape[-2:] != (3, 3):
        raise VerifyInputError(f"{name}: expected shape (..., 3, 3), got {arr.shape}")
    orth = orthogonality_error(arr)
    det_err = np.abs(np.linalg.det(arr) - 1.0)
    bad_mask = (orth > tolerance) | (det_err > tolerance)
    if np.any(bad_mask):
        first = np.argwhere(bad_mask)
        idx = tuple(first[0]) if first.size else ()
        o = float(orth[idx]) if idx else float(orth)
        d = float(np.linalg.det(arr[idx])) if idx else float(np.linalg.det(arr))
        raise NotARotationError(
            f"{name} {_index(first)} is not in SO(3): max|R^T R - I| = {o:.3g}, "
            f"det R = {d:.12g} (tolerance {tolerance:g})"
        )
    return arr


def _index(positions: np.ndarray) -> str:
    if positions.size == 0:
        return ""
    return "at index " + ",".join(str(int(i)) for i in positions[0])
