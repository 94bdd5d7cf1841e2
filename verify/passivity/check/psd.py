"""Exact positive (semi)definiteness of a symmetric rational matrix, fast when there is room.

The test tries a verified floating-point Cholesky factorisation first, then a
*dominance certificate*, and falls back to an exact fraction-free LDL^T on the integer
numerators (:func:`verify.passivity.check.ldl_int.psd_integer`), so its answer is always
exact:

1. Rows and columns that are exactly zero are dropped (M is PSD iff the rest is).
2. Rump's test (:mod:`verify.passivity.check.float_cholesky`): a floating-point Cholesky
   of the rounded M - cI that runs to completion, with c a proved bound on every
   rounding error, proves M > 0 (hence M >= 0). It costs one float factorisation and
   needs a margin above c (about n^2 unit roundoffs of |M|).
3. If the float copy has a clearly negative eigenvalue, a rounded eigenvector v with
   v^T M v < 0 (exactly) refutes M >= 0.
4. A floating-point Cholesky factor of M - delta I (delta half the smallest eigenvalue
   estimate) is rounded to a dyadic matrix L. Then E = M - L L^T is formed *exactly*
   over integers (:mod:`verify.passivity.check.intmat`). If E has a non-negative diagonal that
   dominates each row (E_ii >= sum_{j != i} |E_ij|), E is PSD by Gershgorin's theorem, so
   M = L L^T + E is PSD; strict dominance makes E, hence M, positive definite.

Floating point only proposes L and v; a bad L or v makes the certificate fail, never pass. The
certificate needs a margin (about n^2 unit roundoffs of |M|); matrices on the boundary
of the cone go to the fraction-free LDL^T (FLINT's fraction-free LU when it decides,
else symmetric Bareiss elimination with zero pivots), whose integers grow to k times the
entries' bit length at step k.
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpz

from verify.passivity.check import exact as ex
from verify.passivity.check import intmat
from verify.passivity.check.float_cholesky import verified_pd
from verify.passivity.check.ldl_int import psd_integer

_FLOAT_MARGIN = 1e-11  # smallest eigenvalue, relative to |M|, worth a dominance attempt


def _nonzero_indices(m: ex.RationalMatrix) -> list[int]:
    return [i for i, row in enumerate(m) if any(x != 0 for x in row)]


def _negative_direction(s: intmat.ScaledInt, F: np.ndarray) -> bool:
    """True when a rounded eigenvector v of the float copy has v^T M v < 0 exactly."""
    _w, V = np.linalg.eigh(F)
    v = V[:, 0] / np.max(np.abs(V[:, 0]))
    for bits in (20, 40, 52):
        vi = np.array([mpz(int(x)) for x in np.rint(np.ldexp(v, bits))], dtype=object)
        if vi.dot(s.Z.dot(vi)) < 0:  # the sign of v^T M v (d > 0)
            return True
    return False


def _dominance_certificate(m: ex.RationalMatrix, strict: bool) -> bool | None:
    """Exactly checked evidence: True proves M >= 0 (M > 0 if strict) by dominance, False
    refutes it by a rational vector with v^T M v < 0; None when neither was found."""
    n = len(m)
    s = intmat.normalised(intmat.from_rational(m))  # c M, c = 2^k: same definiteness
    F = intmat.to_float(s)
    scale = float(np.max(np.abs(F)))
    if not np.isfinite(scale) or scale == 0.0:
        return None
    lam = float(np.linalg.eigvalsh(F)[0])
    if lam < -_FLOAT_MARGIN * scale * n and _negative_direction(s, F):
        return False
    lam = float(np.linalg.eigvalsh(F)[0])
    if lam <= _FLOAT_MARGIN * scale * n:
        return None
    try:
        Lf = np.linalg.cholesky(F - (lam / 2) * np.eye(n))
    except np.linalg.LinAlgError:
        return None
    # scale so that every entry is an integer below 2^52 after rounding: exact in floats
    e = 51 - int(np.ceil(np.log2(float(np.max(np.abs(Lf))))))
    Li = np.array([[mpz(int(x)) for x in row] for row in np.rint(np.ldexp(Lf, e))],
                  dtype=object)
    # M = Z / d and L = Li / 2^e, so (M - L L^T) d 2^(2e) = Z 2^(2e) - d Li Li^T
    LLt = intmat.int_dot(Li, np.ascontiguousarray(Li.T))
    E = s.Z * (mpz(1) << (2 * e)) - s.d * LLt if e >= 0 else (
        s.Z - s.d * LLt * (mpz(1) << (-2 * e)))
    absE = np.abs(E)
    diag = np.array([E[i, i] for i in range(n)], dtype=object)
    off = absE.sum(axis=1) - np.abs(diag)
    if strict:
        return True if all(diag[i] > off[i] for i in range(n)) else None
    return True if all(diag[i] >= off[i] for i in range(n)) else None


def psd_exact(m: ex.RationalMatrix, *, strict: bool = False) -> ex.LdlResult:
    """Exact decision of M >= 0 (``strict``: M > 0) for a symmetric rational matrix M."""
    if not ex.is_symmetric(m):
        return ex.LdlResult(False, "matrix is not symmetric")
    keep = _nonzero_indices(m)
    if strict and len(keep) < len(m):
        return ex.LdlResult(False, "a row is zero, so the matrix is singular")
    reduced = [[m[i][j] for j in keep] for i in keep]
    if not reduced:
        return ex.LdlResult(True, "the matrix is zero")
    if len(reduced) > 2 and verified_pd(intmat.from_rational(reduced)):
        return ex.LdlResult(True, "verified floating-point Cholesky (Rump's bound)")
    evidence = _dominance_certificate(reduced, strict) if len(reduced) > 2 else None
    if evidence is True:
        return ex.LdlResult(True, "M - L Lᵀ diagonally dominant, L a rounded Cholesky factor")
    if evidence is False:
        return ex.LdlResult(False, "a rational vector v has vᵀ M v < 0")
    # M = Z / d with d > 0: Z has M's definiteness, decided without fractions
    return psd_integer(intmat.from_rational(reduced).Z.tolist(), strict=strict)
