"""Exact witnesses for the frequency-domain decision's negative verdicts.

A failed condition (c) of :mod:`verify.passivity.check.frequency_domain` leaves a polynomial
Q(w) = E_k(w) / |c(jw)|^(2j) that is negative somewhere. Root enclosures (arb) of its
odd-multiplicity factors propose rational points beside a sign change; the first w* with
Q(w*) < 0 exactly and w* not a pole is kept, and H(jw*) + H(jw*)^H is then formed exactly:
for small models from the state-space data by elimination
(:func:`verify.passivity.check.witness.hermitian_part_at`, independent of the polynomial
route), for larger ones from the exact transfer matrix; and a rational vector v = a + jb with
v^H (H(jw*) + H(jw*)^H) v < 0 is found exactly (a rounded eigenvector, else a symmetric
elimination that tracks its congruence). The pole-condition failures carry exact facts
instead (an entry with a pole in Re s > 0, a repeated axis pole, a residue's sign).
"""

from __future__ import annotations

from flint import fmpq, fmpq_poly
from gmpy2 import mpq

from verify.inputs.number_text import approx_text
from verify.inputs.numbers import fraction
from verify.passivity.check import exact as ex
from verify.passivity.check import qpoly as qp
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.witness import (
    Witness,
    hermitian_part_at,
    negative_direction,
    vector_witness,
)


def exact_negative_vector(M: ex.RationalMatrix) -> tuple[list[mpq], mpq] | None:
    """A rational v with v^T M v < 0 for symmetric M, by elimination T^T M T; None if
    M >= 0. Exact: the value is recomputed from M itself."""
    n = len(M)
    S = [row[:] for row in M]
    T = [[mpq(int(i == j)) for j in range(n)] for i in range(n)]  # columns: directions

    def col(k):
        return [T[i][k] for i in range(n)]

    found = None
    for k in range(n):
        if S[k][k] < 0:
            found = col(k)
            break
        if S[k][k] == 0:
            other = next((i for i in range(k + 1, n) if S[k][i] != 0), None)
            if other is None:
                continue
            if S[other][other] < 0:
                found = col(other)
                break
            t = -(S[other][other] + 1) / (2 * S[k][other])
            found = [t * x + y for x, y in zip(col(k), col(other), strict=True)]
            break
        for i in range(k + 1, n):
            f = S[i][k] / S[k][k]
            if f == 0:
                continue
            # e_i <- e_i - f e_k: rows and columns of S, columns of T
            for j in range(n):
                S[i][j] -= f * S[k][j]
            for j in range(n):
                S[j][i] -= f * S[j][k]
            for j in range(n):
                T[j][i] -= f * T[j][k]
    if found is None:
        return None
    value = sum((found[i] * M[i][j] * found[j] for i in range(n) for j in range(n)), mpq(0))
    return (found, value) if value < 0 else None


def hermitian_part_from(tm, w: fmpq) -> ex.RationalMatrix | None:
    """[[Re, -Im], [Im, Re]] of H(jw) + H(jw)^H from the exact H = N / d (None at a pole)."""
    dr, di = (p(w) for p in qp.at_jw(tm.d))
    norm = dr * dr + di * di
    if norm == 0:
        return None
    m = len(tm.N)
    Hr = [[None] * m for _ in range(m)]
    Hi = [[None] * m for _ in range(m)]
    for i in range(m):
        for k in range(m):
            nr, ni = (p(w) for p in qp.at_jw(tm.N[i][k]))
            Hr[i][k] = (nr * dr + ni * di) / norm
            Hi[i][k] = (ni * dr - nr * di) / norm
    P = [[qp.to_mpq(Hr[i][k] + Hr[k][i]) for k in range(m)] for i in range(m)]
    S = [[qp.to_mpq(Hi[i][k] - Hi[k][i]) for k in range(m)] for i in range(m)]
    return ex.block([[P, ex.scale(-1, S)], [S, P]])


STATE_SPACE_CHECK_LIMIT = 20  # states up to which H(jw*) is also solved from (A, B, C, D)


def frequency_vector_witness(model: ExactModel, w: fmpq, note: str, tm=None
                             ) -> Witness | None:
    """The exact vector witness at the rational frequency w (None if jw is a pole or
    H(jw) + H(jw)^H >= 0). H(jw) comes from the state-space data by exact elimination for
    small models, else from the exact transfer matrix tm (cheaper: no 2n x 2n solve)."""
    if tm is not None and model.n > STATE_SPACE_CHECK_LIMIT:
        M = hermitian_part_from(tm, w)
    else:
        M = hermitian_part_at(model, fraction(w))
    if M is None:
        return None
    found = negative_direction(M) or exact_negative_vector(M)
    if found is None:
        return None
    v, value = found
    return vector_witness(w, approx_text(w), approx_text(value, 3), v, value,
                          model.m, note)


def negative_points(Q: fmpq_poly, avoid: fmpq_poly):
    """Rational w with Q(w) < 0 and avoid(w) != 0, nearest sign changes first."""
    _content, factors = Q.factor_squarefree()
    for i in range(-8, 9):  # Q < 0 on an interval, or everywhere but at its roots
        base = fmpq(2) ** i if i >= 0 else fmpq(1, 2 ** -i)
        for w in (base, base * 3 / 2):
            if Q(w) < 0 and avoid(w) != 0:
                yield w
    for prec in (64, 256, 1024, 4096):
        for g, e in factors:
            if e % 2 == 0:
                continue
            for r in qp.approximate_roots(g, prec):
                if r.imag != 0:
                    continue
                mid = qp.dyadic(r.real)
                scale = abs(mid) + 1
                for i in range(2, prec, 2):
                    delta = scale / fmpq(2) ** i
                    for w in (abs(mid + delta), abs(mid - delta)):  # E_k is even in w
                        if Q(w) < 0 and avoid(w) != 0:
                            yield w
                            return


def frequency_witness_for(model: ExactModel, Q: fmpq_poly, avoid: fmpq_poly, k: int,
                          tm=None) -> Witness | None:
    for w in negative_points(Q, avoid):
        found = frequency_vector_witness(
            model, w, f"E_{k}(ω*) < 0: the sum of the {k} x {k} principal minors", tm)
        if found is not None:
            return found
    return None


def near_axis_pole_witness(model: ExactModel, rho: fmpq_poly, tm=None) -> Witness | None:
    """Beside a pole jw0 with a non-Hermitian residue, H + H^H ~ -j(K - K^H)/(w - w0)
    has a negative eigenvalue on one side; try rational points on both sides."""
    for interval in qp.isolate_real_roots(rho):
        for i in range(4, 120, 4):
            delta = (abs(interval[1]) + 1) / fmpq(2) ** i
            lo, hi = qp.refine_root(rho, interval, delta / 4)
            for w in (hi + delta, lo - delta):
                if rho(w) == 0:
                    continue
                found = frequency_vector_witness(
                    model, w, "beside an imaginary-axis pole with a non-Hermitian residue", tm)
                if found is not None:
                    return found
    return None
