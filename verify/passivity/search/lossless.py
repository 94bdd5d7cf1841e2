"""The storage of a lossless model, solved exactly from its Krylov matrix (no float, no SDP).

A lossless model (D + Dᵀ = 0, every pole on the imaginary axis) has M(P) = 0 at its
storage: Aᵀ P + P A = 0 and P B = Cᵀ (the KYP lemma with equality, the paper's
Section 4). Then P A = −Aᵀ P gives P Aᵏ B = (−Aᵀ)ᵏ Cᵀ for every k, so

    P K = L,   K = [B, A B, A² B, ...],   L = [Cᵀ, −Aᵀ Cᵀ, (Aᵀ)² Cᵀ, ...],

and when (A, B) is controllable n independent columns of K determine P uniquely (the
columns are chosen once, modulo the first prime, as the first independent ones). The
columns of K grow by the bits of A at each power, so K is never formed over Q: it is
built modulo primes below 2²⁶ (numpy int64 products, FLINT ``nmod_mat`` for the
echelon form and the solve), P is solved modulo each prime,
lifted by Chinese remaindering and rational reconstruction (with a running common
denominator), and the candidate is checked exactly: Aᵀ P + P A = 0 and P B = Cᵀ
over the integers (:func:`verify.passivity.check.kyp_int.negated_kyp_matrix` is then the
zero matrix). The final word is :func:`verify.passivity.check.certificate.check_kyp`
(P symmetric, P > 0 and M(P) <= 0, exactly): nothing computed modulo a prime is
trusted, it only proposes.

The route gives up, with the reason, when D + Dᵀ ≠ 0, when K has rank below n modulo
two primes (not controllable: the storage is then not unique), when C B is not
symmetric, when the solution modulo two primes fails the equations (the model is not
lossless; one failure alone may be a prime that divides P's denominators), or when the
reconstruction has not settled within :data:`MAX_PRIMES` primes.
"""

from __future__ import annotations

from dataclasses import dataclass

import gmpy2
import numpy as np
from flint import nmod_mat
from gmpy2 import mpq, mpz

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel, check_kyp
from verify.passivity.check.kyp_int import IntMatrix, negated_kyp_matrix
from verify.passivity.check.realization import rational_reconstruction

#: primes tried before the route gives up (26 bits each)
MAX_PRIMES = 256
#: primes below 2^26: residue products stay below 2^52 and sums of up to 2^11 of them
#: below 2^63, so numpy int64 products are exact up to this many states
_FIRST_PRIME = 2**26
MAX_STATES = 2048


@dataclass(frozen=True)
class LosslessSearch:
    """An exactly checked P (M(P) = 0, P > 0), or None with the reason."""

    P: ex.RationalMatrix | None
    reason: str
    primes: int = 0


def _primes(denominators: list[int]):
    p = _FIRST_PRIME
    while True:
        p -= 1
        while not gmpy2.is_prime(p):
            p -= 1
        if all(d % p for d in denominators):
            yield p


def _mod(M: IntMatrix, rows: int, cols: int, p: int) -> np.ndarray:
    """M = Z / d modulo p as int64 (p does not divide d)."""
    out = np.array([z % p for row in M.rows for z in row], dtype=np.int64)
    return (out.reshape(rows, cols) * pow(M.d, -1, p)) % p


def _nmod(M: np.ndarray, p: int) -> nmod_mat:
    rows, cols = M.shape
    return nmod_mat(rows, cols, M.ravel().tolist(), p)


def _krylov(A: np.ndarray, X: np.ndarray, blocks: int, p: int) -> np.ndarray:
    """[X, A X, ..., A^(blocks-1) X] modulo p."""
    out = [X]
    for _ in range(blocks - 1):
        out.append(A.dot(out[-1]) % p)
    return np.hstack(out)


def _select(A: np.ndarray, B: np.ndarray, p: int) -> list[int] | None:
    """The first n independent columns of K = [B, AB, ...] modulo p (column k m + j is
    Aᵏ B e_j), or None (rank < n). ceil(n/m) blocks first, doubling up to n."""
    n, m = B.shape
    wanted = -(-n // m)
    while True:
        R, rank = _nmod(_krylov(A, B, wanted, p), p).rref()
        if rank == n:
            return [next(j for j, x in enumerate(row) if int(x)) for row in R.tolist()[:n]]
        if wanted >= n:
            return None
        wanted = min(n, 2 * wanted)


def _solve_mod(model: ExactModel, columns: list[int], p: int) -> np.ndarray | str | None:
    """P modulo p from P K_sel = L_sel, the reason it fails the equations there, or None
    when the selected columns are singular modulo this prime (it is skipped)."""
    n, m = model.n, model.m
    Ai, Bi, Ci, _ = model.integer
    A, B, C = _mod(Ai, n, n, p), _mod(Bi, n, m, p), _mod(Ci, m, n, p)
    blocks = max(columns) // m + 1
    K = _krylov(A, B, blocks, p)[:, columns]
    L = _krylov((-A.T) % p, np.ascontiguousarray(C.T), blocks, p)[:, columns]
    try:
        Pt = _nmod(K.T.copy(), p).solve(_nmod(L.T.copy(), p))  # Kᵀ Pᵀ = Lᵀ
    except ZeroDivisionError:
        return None
    P = np.array([int(x) for x in Pt.entries()], dtype=np.int64).reshape(n, n).T
    if not np.array_equal(P, P.T):
        return "the solution of P K = L is not symmetric modulo a prime"
    if not np.array_equal(P.dot(B) % p, C.T % p):
        return "the solution of P K = L misses P B = Cᵀ modulo a prime"
    AtP = A.T.dot(P) % p
    if np.any((AtP + AtP.T) % p):
        return "the solution of P K = L misses Aᵀ P + P A = 0 modulo a prime"
    return P


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
            x = rational_reconstruction(int(v * den % modulus), int(modulus))
            if x is None:
                return None
            t1 = mpz(int(x.q))  # x = r1 / t1 in lowest terms, t1 > 0
            line.append(mpq(int(x.p), t1 * den))
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
    if n > MAX_STATES:
        return LosslessSearch(None, f"more than {MAX_STATES} states")
    CB = ex.matmul(model.C, model.B)  # = Bᵀ P B for any P with P B = Cᵀ
    if not ex.is_symmetric(CB):
        return LosslessSearch(None, "C B is not symmetric, so no symmetric P has P B = Cᵀ")
    Ai, Bi, Ci, _ = model.integer
    primes = _primes([Ai.d, Bi.d, Ci.d])
    columns, used = None, 0
    for _ in range(2):
        p = next(primes)
        used += 1
        columns = _select(_mod(Ai, n, n, p), _mod(Bi, n, m, p), p)
        if columns is not None:
            break
    if columns is None:
        return LosslessSearch(None, "the Krylov matrix [B, AB, ...] has rank below n modulo "
                              "two primes: (A, B) is likely not controllable, so the "
                              "lossless storage is not unique", used)
    values: list[list[int]] | None = None
    failed: str | None = None
    modulus = 1
    attempt = 1
    for count in range(1, max_primes + 1):
        residues = _solve_mod(model, columns, p)
        if residues is None:  # an unlucky prime for these columns
            p, used = next(primes), used + 1
            continue
        if isinstance(residues, str):
            if values is None and failed is None:  # p might divide P's denominators
                failed, p, used = residues, next(primes), used + 1
                continue
            return LosslessSearch(None, f"{residues}: no lossless storage", used)
        if values is None:
            values = residues.tolist()
        else:
            residues = residues.tolist()
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
                                      f"equations P K = L, solved modulo {count} prime(s) "
                                      "and reconstructed)", count)
        p, used = next(primes), used + 1
    return LosslessSearch(None, f"the reconstruction of P did not settle within "
                          f"{max_primes} primes", used)


__all__ = ["MAX_PRIMES", "LosslessSearch", "lossless_certificate"]
