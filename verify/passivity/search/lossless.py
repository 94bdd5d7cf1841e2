"""The storage of a lossless model, solved exactly from its Krylov matrix (no float, no SDP).

A lossless model (D + Dᵀ = 0, every pole on the imaginary axis) has M(P) = 0 at its
storage: Aᵀ P + P A = 0 and P B = Cᵀ (the KYP lemma with equality, the paper's
Section 4). Then P A = −Aᵀ P gives P Aᵏ B = (−Aᵀ)ᵏ Cᵀ for every k, so

    P K = L,   K = [B, A B, A² B, ...],   L = [Cᵀ, −Aᵀ Cᵀ, (Aᵀ)² Cᵀ, ...],

and when (A, B) is controllable n independent columns of K determine P uniquely. The
columns of K grow by the bits of A at each power, so K is never formed over Q: it is
built modulo word-size primes (FLINT ``nmod_mat``), P is solved modulo each prime,
lifted by Chinese remaindering and rational reconstruction (with a running common
denominator), and the candidate is checked exactly: Aᵀ P + P A = 0 and P B = Cᵀ
over the integers (:func:`verify.passivity.check.kyp_int.negated_kyp_matrix` is then the
zero matrix). The final word is :func:`verify.passivity.check.certificate.check_kyp`
(P symmetric, P > 0 and M(P) <= 0, exactly): nothing computed modulo a prime is
trusted, it only proposes.

The route gives up, with the reason, when D + Dᵀ ≠ 0, when K has rank below n modulo
two primes (not controllable: the storage is then not unique), when the solution
modulo a prime already fails the equations (the model is not lossless), or when the
reconstruction has not settled within :data:`MAX_PRIMES` primes.
"""

from __future__ import annotations

from dataclasses import dataclass

import gmpy2
from flint import nmod_mat
from gmpy2 import mpq, mpz

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel, check_kyp
from verify.passivity.check.kyp_int import IntMatrix, negated_kyp_matrix

#: primes tried before the route gives up (about 62 bits each)
MAX_PRIMES = 64
_FIRST_PRIME = 2**62


@dataclass(frozen=True)
class LosslessSearch:
    """An exactly checked P (M(P) = 0, P > 0), or None with the reason."""

    P: ex.RationalMatrix | None
    reason: str
    primes: int = 0


def _primes(denominators: list[int]):
    p = mpz(_FIRST_PRIME)
    while True:
        p = gmpy2.prev_prime(p) if hasattr(gmpy2, "prev_prime") else _prev_prime(p)
        if all(d % p for d in denominators):
            yield int(p)


def _prev_prime(p: mpz) -> mpz:
    q = p - 1
    while not gmpy2.is_prime(q):
        q -= 1
    return q


def _mod(M: IntMatrix, rows: int, cols: int, p: int) -> nmod_mat:
    """M = Z / d modulo p (p does not divide d)."""
    return nmod_mat(M.Z, p) * pow(M.d, -1, p) if rows and cols else nmod_mat(rows, cols, p)


def _hstack(blocks: list[nmod_mat], rows: int, p: int) -> nmod_mat:
    lists = [b.tolist() for b in blocks]
    cols = sum(b.ncols() for b in blocks)
    return nmod_mat(rows, cols, [int(x) for i in range(rows) for rows_ in lists
                                 for x in rows_[i]], p)


@dataclass(frozen=True)
class _Selection:
    """The Krylov columns used: pivot column indices of K (block k, port j at k m + j)."""

    columns: list[int]
    blocks: int


def _krylov(A: nmod_mat, X0: nmod_mat, blocks: int) -> list[nmod_mat]:
    out, X = [X0], X0
    for _ in range(blocks - 1):
        X = A * X
        out.append(X)
    return out


def _select(A: nmod_mat, B: nmod_mat, n: int, p: int) -> _Selection | None:
    """The first n independent columns of K modulo p, or None (rank < n)."""
    m = B.ncols()
    blocks = n if m else 0
    if not blocks:
        return None
    K = _hstack(_krylov(A, B, blocks), n, p)
    R, rank = K.rref()
    if rank < n:
        return None
    rows = R.tolist()
    columns = [next(j for j, x in enumerate(row) if int(x)) for row in rows[:n]]
    return _Selection(columns, max(columns) // m + 1)


def _columns(blocks: list[nmod_mat], columns: list[int], n: int, m: int, p: int) -> nmod_mat:
    lists = [b.tolist() for b in blocks]
    return nmod_mat(n, len(columns), [int(lists[c // m][i][c % m]) for i in range(n)
                                      for c in columns], p)


def _solve_mod(model: ExactModel, sel: _Selection, p: int) -> list[list[int]] | str:
    """P modulo p from P K_sel = L_sel, or the reason it fails there."""
    n, m = model.n, model.m
    Ai, Bi, Ci, _ = model.integer
    A, B, C = _mod(Ai, n, n, p), _mod(Bi, n, m, p), _mod(Ci, m, n, p)
    K = _columns(_krylov(A, B, sel.blocks), sel.columns, n, m, p)
    L = _columns(_krylov(-A.transpose(), C.transpose(), sel.blocks), sel.columns, n, m, p)
    try:
        P = K.transpose().solve(L.transpose()).transpose()  # P K = L
    except ZeroDivisionError:
        return "the selected Krylov columns are singular modulo a prime"
    if P != P.transpose():
        return "the solution of P K = L is not symmetric modulo a prime"
    if P * B != C.transpose():
        return "the solution of P K = L misses P B = Cᵀ modulo a prime"
    AtP = A.transpose() * P
    if AtP + AtP.transpose() != nmod_mat(n, n, p):
        return "the solution of P K = L misses Aᵀ P + P A = 0 modulo a prime"
    return [[int(x) for x in row] for row in P.tolist()]


def _reconstruct(values: list[list[int]], modulus: int) -> ex.RationalMatrix | None:
    """Rational reconstruction (Wang) of every entry, with a running common denominator
    (an entry that is already y / den with a small y costs one product)."""
    half = modulus // 2
    bound = int(gmpy2.isqrt(half))
    den = mpz(1)
    out = []
    for row in values:
        line = []
        for v in row:
            y = (v * den) % modulus
            y = y - modulus if y > half else y
            if abs(y) <= bound:
                line.append(mpq(y, den))
                continue
            r0, r1, t0, t1 = mpz(modulus), mpz(v * den % modulus), mpz(0), mpz(1)
            while r1 > bound:
                q = r0 // r1
                r0, r1, t0, t1 = r1, r0 - q * r1, t1, t0 - q * t1
            if t1 == 0 or abs(t1) > bound or gmpy2.gcd(r1, t1) != 1:
                return None
            if t1 < 0:
                r1, t1 = -r1, -t1
            line.append(mpq(r1, t1 * den))
            den *= t1
            if den > bound:
                return None
        out.append(line)
    return out


def _equations_hold(model: ExactModel, P: ex.RationalMatrix) -> bool:
    """P symmetric and M(P) = 0 exactly (integer products, FLINT)."""
    if not ex.is_symmetric(P):
        return False
    rows, _d = negated_kyp_matrix(*model.integer, P=P)
    return not any(any(row) for row in rows)


def lossless_certificate(model: ExactModel, *, max_primes: int = MAX_PRIMES
                         ) -> LosslessSearch:
    """The exactly checked storage P of a lossless model (M(P) = 0), or the reason none was
    found. See the module docstring for the route."""
    n, m = model.n, model.m
    if any(x + y for row, col in zip(model.D, ex.transpose(model.D), strict=True)
           for x, y in zip(row, col, strict=True)):
        return LosslessSearch(None, "D + Dᵀ ≠ 0, so the model is not lossless")
    if n == 0 or m == 0:
        return LosslessSearch(None, "no state or no input: nothing to solve")
    Ai, Bi, Ci, _ = model.integer
    primes = _primes([Ai.d, Bi.d, Ci.d])
    sel, used = None, 0
    for _ in range(2):
        p = next(primes)
        used += 1
        A, B = _mod(Ai, n, n, p), _mod(Bi, n, m, p)
        sel = _select(A, B, n, p)
        if sel is not None:
            break
    if sel is None:
        return LosslessSearch(None, "the Krylov matrix [B, AB, ...] has rank below n modulo "
                              "two primes: (A, B) is likely not controllable, so the "
                              "lossless storage is not unique", used)
    values: list[list[int]] | None = None
    modulus = 1
    attempt = 1
    for count in range(1, max_primes + 1):
        residues = _solve_mod(model, sel, p)
        if isinstance(residues, str):
            return LosslessSearch(None, f"{residues}: no lossless storage", used)
        if values is None:
            values = residues
        else:
            inverse = pow(modulus, -1, p)
            values = [[v + modulus * ((r - v) * inverse % p) for v, r in
                       zip(vrow, rrow, strict=True)]
                      for vrow, rrow in zip(values, residues, strict=True)]
        modulus *= p
        if count in (attempt, max_primes):  # reconstruct after 1, 2, 4, 8, ... primes
            attempt *= 2
            P = _reconstruct(values, modulus)
            if P is not None and _equations_hold(model, P):
                check = check_kyp(model, P)
                if not check.ok:
                    return LosslessSearch(None, f"the lossless storage (M(P) = 0) fails "
                                          f"the exact check: {check.reason}", used)
                return LosslessSearch(P, f"{check.reason} (lossless storage from the Krylov "
                                      f"equations P K = L, solved modulo {used} prime(s) "
                                      "and reconstructed)", used)
        if count < max_primes:
            p = next(primes)
            used += 1
    return LosslessSearch(None, f"the reconstruction of P did not settle within {used} "
                          "primes", used)


__all__ = ["MAX_PRIMES", "LosslessSearch", "lossless_certificate"]
