"""Witnesses of semidefiniteness for the Coq check of ``QCert.v`` (untrusted search).

Coq proves ``x^T M x >= eps |x|^2`` for every real x from a witness ``(eps, terms)``: it
computes the residual ``R = M - eps I - sum_k d_k l_k l_k^T`` itself and checks, on
exact rationals, that every ``d_k >= 0`` and that R is diagonally dominant
(``sum_(j != i) (|R_ij| + |R_ji|) <= 2 R_ii``). This module only *proposes* witnesses,
so nothing here is trusted; :func:`residual_dominant` repeats Coq's check in Python so
that the exporter refuses a matrix for which Coq would fail.

Two ways to find one, as in the exact checker (:mod:`verify.passivity.check.psd`):

- an exact LDLᵀ factorisation of ``M - eps I`` (zero pivots allowed when their row is
  zero): the residual is then exactly 0. Used for small matrices with small entries,
  where the numbers stay short;
- a rounded Cholesky factor of ``M - (eps + delta) I`` with dyadic entries: the residual
  is about ``delta I`` plus rounding, diagonally dominant when M has room. Its terms
  are short integers, so Coq's arithmetic stays cheap for large models.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check import intmat

#: Exact LDLᵀ is tried first up to this size and entry length (bits of numerator or
#: denominator); beyond it the rounded factor, whose Coq check is cheaper.
EXACT_MAX_SIZE = 12
EXACT_MAX_BITS = 128


@dataclass(frozen=True)
class Witness:
    """``eps`` and terms ``(d_k, l_k)`` standing for ``eps I + sum_k d_k l_k l_kᵀ``."""

    eps: mpq
    terms: tuple[tuple[mpq, tuple[mpq, ...]], ...]
    method: str


def _bits(m: ex.RationalMatrix) -> int:
    return max((max(x.numerator.bit_length(), x.denominator.bit_length())
                for row in m for x in row), default=0)


def residual(m: ex.RationalMatrix, w: Witness) -> ex.RationalMatrix:
    """``M - eps I - sum_k d_k l_k l_kᵀ``, exactly (what Coq computes)."""
    n = len(m)
    r = [[m[i][j] - (w.eps if i == j else 0) for j in range(n)] for i in range(n)]
    for d, vec in w.terms:
        nz = [(i, x) for i, x in enumerate(vec) if x != 0]
        for i, xi in nz:
            dxi = d * xi
            row = r[i]
            for j, xj in nz:
                row[j] -= dxi * xj
    return r


def residual_dominant(m: ex.RationalMatrix, w: Witness) -> bool:
    """Coq's check, repeated: d_k >= 0, eps >= 0 and the residual diagonally dominant."""
    if w.eps < 0 or any(d < 0 for d, _ in w.terms):
        return False
    if any(len(vec) != len(m) for _, vec in w.terms):
        return False
    r = residual(m, w)
    n = len(m)
    return all(
        sum((abs(r[i][j]) + abs(r[j][i]) for j in range(n) if j != i), mpq(0)) <= 2 * r[i][i]
        for i in range(n)
    )


def _ldl_terms(m: ex.RationalMatrix) -> list[tuple[mpq, tuple[mpq, ...]]] | None:
    """Exact LDLᵀ of symmetric M (zero pivots only with a zero row): the terms
    ``(d_k, column k of L)``, or None when a pivot is negative."""
    n = len(m)
    a = [row[:] for row in m]
    terms = []
    for k in range(n):
        d = a[k][k]
        if d < 0:
            return None
        if d == 0:
            if any(a[i][k] != 0 for i in range(k + 1, n)):
                return None
            continue
        col = [mpq(0)] * k + [mpq(1)] + [a[i][k] / d for i in range(k + 1, n)]
        for i in range(k + 1, n):
            if col[i] == 0:
                continue
            f = col[i] * d
            for j in range(k + 1, n):
                a[i][j] -= f * col[j]
        terms.append((d, tuple(col)))
    return terms


def _exact(m: ex.RationalMatrix, eps: mpq) -> Witness | None:
    n = len(m)
    shifted = [[m[i][j] - (eps if i == j else 0) for j in range(n)] for i in range(n)]
    terms = _ldl_terms(shifted)
    return None if terms is None else Witness(eps, tuple(terms), "exact LDLᵀ")


def _dyadic_below(x: float) -> mpq:
    """A power of two in (x/2, x] for x > 0."""
    return mpq(2) ** int(np.floor(np.log2(x)))


def _rounded(m: ex.RationalMatrix, strict: bool) -> Witness | None:
    """Rounded Cholesky factor of M - (eps + delta) I, columns as integers / 2^e."""
    n = len(m)
    F = intmat.to_float(intmat.from_rational(m))
    if not np.all(np.isfinite(F)):
        return None
    lam = float(np.linalg.eigvalsh(F)[0])
    scale = float(np.max(np.abs(F))) or 1.0
    if lam <= 1e-11 * scale * n:
        return None
    eps = _dyadic_below(lam / 4) if strict else mpq(0)
    try:
        Lf = np.linalg.cholesky(F - (float(eps) + lam / 2) * np.eye(n))
    except np.linalg.LinAlgError:
        return None
    e = 40 - int(np.ceil(np.log2(float(np.max(np.abs(Lf))))))
    Li = np.rint(np.ldexp(Lf, e))
    d = mpq(2) ** (-2 * e)
    terms = tuple((d, tuple(mpq(int(Li[i, j])) for i in range(n))) for j in range(n))
    return Witness(eps, terms, "rounded Cholesky factor, dominant residual")


def _embed(w: Witness, keep: Sequence[int], n: int) -> Witness:
    """The witness of the matrix with its zero rows and columns put back."""
    def spread(vec: tuple[mpq, ...]) -> tuple[mpq, ...]:
        out = [mpq(0)] * n
        for k, i in enumerate(keep):
            out[i] = vec[k]
        return tuple(out)
    return Witness(w.eps, tuple((d, spread(v)) for d, v in w.terms), w.method)


def psd_witness(m: ex.RationalMatrix, *, strict: bool = False) -> Witness | None:
    """A witness that Coq's check accepts for M >= 0 (``strict``: with eps > 0, so M > 0),
    or None when none was found (then M is not certified, whatever its truth)."""
    n = len(m)
    if not ex.is_symmetric(m):
        return None
    keep = [i for i, row in enumerate(m) if any(x != 0 for x in row)]
    if strict and len(keep) < n:
        return None
    reduced = [[m[i][j] for j in keep] for i in keep]
    if not reduced:
        return Witness(mpq(0), (), "zero matrix")
    small = len(reduced) <= EXACT_MAX_SIZE and _bits(reduced) <= EXACT_MAX_BITS
    candidates = []
    if small:
        candidates.append(lambda: _exact_with_shift(reduced, strict))
    candidates.append(lambda: _rounded(reduced, strict))
    if not small:
        candidates.append(lambda: _exact_with_shift(reduced, strict))
    for make in candidates:
        w = make()
        if w is not None and (not strict or w.eps > 0):
            w = _embed(w, keep, n)
            if residual_dominant(m, w):
                return w
    return None


def _exact_with_shift(m: ex.RationalMatrix, strict: bool) -> Witness | None:
    """Exact LDLᵀ of M (eps = 0) or, when strict, of M - eps I for a dyadic eps below
    a quarter of the smallest eigenvalue (halved until the factorisation succeeds)."""
    if not strict:
        return _exact(m, mpq(0))
    F = np.array([[float(x) for x in row] for row in m])
    if not np.all(np.isfinite(F)):
        return None
    lam = float(np.linalg.eigvalsh(F)[0])
    if lam <= 0:
        return None
    eps = _dyadic_below(lam / 4)
    for _ in range(8):
        w = _exact(m, eps)
        if w is not None:
            return w
        eps /= 4
    return None
