"""KYP certificates: the exact check, and their JSON form under ``certificates/``.

A certificate of passivity for a minimal realisation (A, B, C, D) of H(s) is a rational
symmetric P with

    P > 0   and   M(P) = [[A^T P + P A, P B - C^T], [B^T P - C, -(D + D^T)]] <= 0,

the KYP (positive-real) lemma; x^T P x / 2 is then a storage function of the human
(Theorem 1's S_h). :func:`check_kyp` decides both conditions with no solver: M(P) is
formed exactly (:mod:`verify.passivity.check.kyp_int`), and its definiteness is proved
by a verified floating-point Cholesky with Rump's rounding-error bound
(:mod:`verify.passivity.check.float_cholesky`, the theorem in
``verify/passivity/TRUSTED.md``) or, failing that, decided in exact arithmetic
(:mod:`verify.passivity.check.psd`). The JSON form of a
certificate, bound to its claim and source file, is in
:mod:`verify.passivity.io.certificate_files`.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property
from typing import Any

import numpy as np
from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check.float_cholesky import verified_pd_nearest, verified_pd_rows
from verify.passivity.check.kyp_int import IntMatrix, SplitP, int_matrix, negated_kyp_matrix
from verify.passivity.check.psd import psd_exact


@dataclass(frozen=True)
class ExactModel:
    """Exact rational (A, B, C, D) of a model; n may be 0."""

    A: ex.RationalMatrix
    B: ex.RationalMatrix
    C: ex.RationalMatrix
    D: ex.RationalMatrix

    @property
    def n(self) -> int:
        return len(self.A)

    @property
    def m(self) -> int:
        return len(self.D)

    def fingerprint(self) -> str:
        """sha256 of the exact data (binds a certificate to its model)."""
        text = json.dumps([ex.to_strings(x) for x in (self.A, self.B, self.C, self.D)])
        return hashlib.sha256(text.encode()).hexdigest()

    def to_json(self) -> dict[str, Any]:
        return {k: ex.to_strings(getattr(self, k)) for k in ("A", "B", "C", "D")}

    @cached_property
    def integer(self) -> tuple[IntMatrix, IntMatrix, IntMatrix, IntMatrix]:
        """(A, B, C, D), each an integer matrix over its own denominator (exact; kept)."""
        n, m = self.n, self.m
        return (int_matrix(self.A, n, n), int_matrix(self.B, n, m),
                int_matrix(self.C, m, n), int_matrix(self.D, m, m))


def exact_model(A, B, C, D) -> ExactModel:
    n, m = len(A), len(D)
    return ExactModel(
        ex.to_rational(A) if n else [],
        ex.to_rational(B) if n else [],
        ex.to_rational(C) if n else [[] for _ in range(m)],
        ex.to_rational(D),
    )


def kyp_matrix(model: ExactModel, P: ex.RationalMatrix) -> ex.RationalMatrix:
    """M(P) of the KYP lemma, exactly."""
    A, B, C, D = model.A, model.B, model.C, model.D
    S = ex.add(D, ex.transpose(D))
    if model.n == 0:
        return ex.scale(-1, S)
    AtP = ex.matmul(ex.transpose(A), P)
    top_left = ex.add(AtP, ex.transpose(AtP))
    off = ex.add(ex.matmul(P, B), ex.transpose(C), -1)
    return ex.block([[top_left, off], [ex.transpose(off), ex.scale(-1, S)]])


def _split_inputs(model: ExactModel, M: ex.RationalMatrix) -> ex.RationalMatrix:
    """E^T M E with E = diag(I, [N R]), N and R exact bases of ker S and range S.

    A congruence by an invertible E keeps (semi)definiteness, and it makes the rows of
    ker S exactly zero when P B N = C^T N holds, so the PSD test can drop them instead
    of deciding a singular matrix (the dominance certificate needs a margin).
    """
    S = ex.add(model.D, ex.transpose(model.D))
    N = ex.kernel_basis(S)
    n, m = model.n, model.m
    if not m or not N[0] or not any(x for row in S for x in row):
        return M  # S = 0 or S > 0: nothing to split
    E_in = [n_row + r_row for n_row, r_row in zip(N, ex.range_basis(S), strict=True)]
    E = ex.block([[_identity(n), ex.zeros(n, m)], [ex.zeros(m, n), E_in]])
    return ex.matmul(ex.matmul(ex.transpose(E), M), E)


def _identity(n: int) -> ex.RationalMatrix:
    return [[mpq(int(i == j)) for j in range(n)] for i in range(n)]


@dataclass(frozen=True)
class KypCheck:
    ok: bool
    reason: str


def check_kyp(model: ExactModel, P: ex.RationalMatrix) -> KypCheck:
    """Exact decision of P = P^T > 0 and M(P) <= 0."""
    n = model.n
    if (n and ex.shape(P) != (n, n)) or (not n and any(P)):
        return KypCheck(False, f"P must be {n} x {n}")
    if n and not ex.is_symmetric(P):
        return KypCheck(False, "P is not symmetric")
    fast = verified_kyp(model, P) if n else None
    if fast is not None:
        return fast
    if n:
        pd = psd_exact(P, strict=True)
        if not pd.ok:
            return KypCheck(False, f"P is not positive definite ({pd.reason})")
    negm = ex.scale(-1, _split_inputs(model, kyp_matrix(model, P)))
    nsd = psd_exact(negm)
    if not nsd.ok:
        return KypCheck(False, f"the KYP matrix is not negative semidefinite ({nsd.reason})")
    p_part = f"P: {pd.reason}; " if n else ""
    return KypCheck(True, f"P > 0 and the KYP matrix is <= 0 in exact arithmetic ({p_part}"
                    f"-M(P): {nsd.reason})")


VERIFIED_REASON = ("P > 0 and the KYP matrix is <= 0: M(P) formed exactly, then P and "
                   "-M(P) (its exactly zero rows dropped) proved positive definite by a "
                   "verified floating-point Cholesky (Rump's bound)")


def verified_kyp(model: ExactModel, P: ex.RationalMatrix) -> KypCheck | None:
    """The fast sufficient check: a passing KypCheck when Rump's test proves P > 0 and
    -M(P) >= 0 (:mod:`verify.passivity.check.float_cholesky`), else None (then the exact
    routes decide)."""
    n = model.n
    if not n or ex.shape(P) != (n, n) or not ex.is_symmetric(P):
        return None
    Pi = int_matrix(P, n, n)
    if not verified_pd_rows(Pi.rows, Pi.d):
        return None
    return _negated_part(model, P=P, Pi=Pi)


def _negated_part(model: ExactModel, **given) -> KypCheck | None:
    """The -M(P) >= 0 half of :func:`verified_kyp` (P as rationals or split)."""
    rows, d = negated_kyp_matrix(*model.integer, **given)
    keep = [i for i, row in enumerate(rows) if any(row)]
    if not keep:
        return KypCheck(True, "P > 0 (verified floating-point Cholesky) and M(P) = 0")
    reduced = [[rows[i][j] for j in keep] for i in keep]
    if not verified_pd_rows(reduced, d):
        return None
    return KypCheck(True, VERIFIED_REASON)


def verified_kyp_split(model: ExactModel, sp: SplitP) -> KypCheck | None:
    """:func:`verified_kyp` for P = L + H given split (:class:`SplitP`, P symmetric by
    construction: the caller's): the same two verified float tests, without forming P's
    long integers everywhere."""
    n = model.n
    if not n or sp.light.Z.nrows() != n or not _split_symmetric(sp):
        return None
    F, diagonal = _nearest(sp)
    if not verified_pd_nearest(F, diagonal):
        return None
    return _negated_part(model, split=sp)


def _split_symmetric(sp: SplitP) -> bool:
    """P = L + H is exactly symmetric: L is, and H's heavy rows match its columns."""
    L = sp.light.rows
    if any(L[i][j] != L[j][i] for i in range(len(L)) for j in range(i)):
        return False
    R, d1, Cm, d2 = sp.rows.rows, sp.rows.d, sp.cols.rows, sp.cols.d
    k = len(sp.heavy)
    if any(R[a][sp.heavy[b]] != R[b][sp.heavy[a]] for a in range(k) for b in range(a)):
        return False
    return all(Fraction(R[a][j], d1) == Fraction(Cm[b][a], d2)
               for b, j in enumerate(sp.others) for a in range(k))


def _nearest(sp: SplitP) -> tuple[np.ndarray, list[Fraction]]:
    """The nearest doubles of P = L + H and P's exact diagonal (int / int is correctly
    rounded; H's entries are added exactly first)."""
    L, dL = sp.light.rows, sp.light.d
    F = np.array([[z / dL for z in row] for row in L], dtype=float)
    exact: dict[tuple[int, int], Fraction] = {}
    for a, i in enumerate(sp.heavy):
        for j, h in enumerate(sp.rows.rows[a]):
            exact[i, j] = Fraction(L[i][j], dL) + Fraction(h, sp.rows.d)
    for b, i in enumerate(sp.others):
        for a, j in enumerate(sp.heavy):
            exact[i, j] = Fraction(L[i][j], dL) + Fraction(sp.cols.rows[b][a], sp.cols.d)
    for (i, j), x in exact.items():
        F[i, j] = x.numerator / x.denominator
    diagonal = [exact.get((i, i), Fraction(L[i][i], dL)) for i in range(len(L))]
    return F, diagonal


@dataclass(frozen=True)
class Certificate:
    """A checked KYP matrix P for ``model`` (the file form is in
    :mod:`verify.passivity.io.certificate_files`)."""

    name: str
    source: str
    model: ExactModel
    P: ex.RationalMatrix
    meta: dict
