"""Exact minimal realisations over Q: transfer matrices, and non-minimal state spaces.

No floating point appears anywhere here: the same input gives the same exact matrices on
every machine. Polynomials and matrices are FLINT's (python-flint ``fmpq_poly``,
``fmpq_mat``), converted to and from the model's ``mpq`` at the edges.

Transfer matrix -> (A, B, C, D) (:func:`transfer_function_realization`)
------------------------------------------------------------------------
1. Each element num/den is reduced by the exact gcd of num and den over Q, its
   denominator made monic, and split as D_ij + r_ij / den_ij with deg r_ij < deg den_ij.
2. Column j is realised in controllable canonical form of d_j = lcm_i den_ij: A_j is the
   companion matrix of d_j, b_j = e_k (k = deg d_j) drives input j, and row i of C_j holds
   the coefficients of r_ij d_j / den_ij, since (sI - A_j)^-1 e_k = (1, s, ..., s^(k-1))^T
   / d_j(s). The block-diagonal stack is controllable, as every column block is.
3. The unobservable subspace is removed exactly: W, the reduced row echelon basis of the
   row space of the observability matrix (the smallest A-invariant row space holding
   the rows of C; skipped when a rank modulo a prime proves observability), maps x to
   x' = W x with A' = (W A)[:, pivots], B' = W B and
   C' = C[:, pivots] (W has the identity at its pivot columns). A quotient of a
   controllable system is controllable, so (A', B', C', D) is minimal (Kalman, 1963).
4. Check (:func:`check_realization`): D is the same, and the Markov parameters C A^k B
   equal those of every element for k < deg den_ij + n. The difference of the two
   elements is a strictly proper rational function whose denominator has degree at most
   deg den_ij + n; its Laurent coefficients at infinity obey a linear recurrence of that
   order, so when that many vanish it is identically zero: the two transfer matrices are
   equal as rational functions (a polynomial identity over Q).

Non-minimal state spaces (:func:`minimal_part`)
-----------------------------------------------
Controllable and observable subspaces are computed exactly (the controllable part by
the dual of step 3). The common case, a minimal realisation, is settled first by ranks
modulo a large prime: a reduction mod p is a ring homomorphism on rationals whose
denominators p does not divide, so full rank of the Krylov matrices mod p proves full
rank over Q. Otherwise the invariant subspace is computed modulo several primes, lifted
by Chinese remaindering and rational reconstruction, and verified exactly
(:func:`_invariant_row_space`); exact elimination over Q, whose rationals swell on dense
data, is only the fallback. The hidden modes are the roots of chi_A / chi_A', and their location
(open left half-plane, imaginary axis, open right half-plane) is decided exactly: axis
roots as the real roots of gcd(Re h(jw), Im h(jw)), the others by rigorous complex root
isolation (FLINT/Arb), refined until no ball meets the axis.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import pairwise
from typing import Any

import flint
import gmpy2
import numpy as np
from flint import fmpq, fmpq_mat, fmpq_poly, nmod_mat
from gmpy2 import mpq

from verify.errors import VerifyInputError
from verify.inputs.numbers import Rational, rational
from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel

# --------------------------------------------------------------------------- conversions


def _q(x: Rational) -> fmpq:
    return fmpq(int(x.numerator), int(x.denominator))


def _mpq(x: fmpq) -> Rational:
    return mpq(int(x.p), int(x.q))


def _fm(M: ex.RationalMatrix, rows: int, cols: int) -> fmpq_mat:
    return fmpq_mat(rows, cols, [_q(x) for row in M for x in row])


def _lists(M: fmpq_mat) -> ex.RationalMatrix:
    return [[_mpq(M[i, j]) for j in range(M.ncols())] for i in range(M.nrows())]


def _poly(coeffs_descending: list[Rational]) -> fmpq_poly:
    return fmpq_poly([_q(c) for c in reversed(coeffs_descending)])


def _coeff(p: fmpq_poly, k: int) -> fmpq:
    return p[k] if 0 <= k <= p.degree() else fmpq(0)


# --------------------------------------------------------------------------- input grids


def _grid(value: Any, label: str, ctx: str) -> list[list[list[Rational]]]:
    """An m_out x m_in grid of non-empty coefficient lists of exact rationals."""
    shape_hint = f"expected {label}[i][j] = coefficients of element (i, j)"
    if not isinstance(value, list | tuple) and not hasattr(value, "tolist"):
        raise VerifyInputError(f"{ctx}: {label}: {shape_hint}, got {value!r:.40}")
    rows = value.tolist() if hasattr(value, "tolist") else value
    if not isinstance(rows, list | tuple) or not rows:
        raise VerifyInputError(f"{ctx}: {label}: {shape_hint}, got {rows!r:.40}")
    grid: list[list[list[Rational]]] = []
    for i, row in enumerate(rows):
        row = row.tolist() if hasattr(row, "tolist") else row
        if not isinstance(row, list | tuple) or not row:
            raise VerifyInputError(
                f"{ctx}: {label}[{i}]: {shape_hint}, a non-empty list per output row"
            )
        cells = []
        for j, coeffs in enumerate(row):
            where = f"{ctx}: {label}[{i}][{j}]"
            coeffs = coeffs.tolist() if hasattr(coeffs, "tolist") else coeffs
            if not isinstance(coeffs, list | tuple):
                raise VerifyInputError(
                    f"{where}: expected a list of coefficients (descending powers of s), "
                    "got a number (nesting too shallow)"
                )
            if not coeffs:
                raise VerifyInputError(f"{where}: empty coefficient list")
            cell = []
            for k, c in enumerate(coeffs):
                if isinstance(c, list | tuple):
                    raise VerifyInputError(
                        f"{where}[{k}]: expected a number, got a list (nesting too deep)"
                    )
                cell.append(rational(c, f"{where}[{k}]"))
            cells.append(cell)
        if grid and len(cells) != len(grid[0]):
            raise VerifyInputError(
                f"{ctx}: {label}: rows of different lengths ({label}[0] has {len(grid[0])} "
                f"entries, {label}[{i}] has {len(cells)})"
            )
        grid.append(cells)
    return grid


@dataclass(frozen=True)
class _Element:
    """num/den of one element, exactly: den monic, gcd(num, den) = 1 (num = 0: den = 1)."""

    num: fmpq_poly
    den: fmpq_poly

    @property
    def feedthrough(self) -> fmpq:
        return self.num.leading_coefficient() if self.num.degree() == self.den.degree() \
            and not self.num.is_zero() else fmpq(0)

    @property
    def remainder(self) -> fmpq_poly:
        """The strictly proper numerator r in num/den = D + r/den."""
        return self.num - self.feedthrough * self.den


def _elements(num: Any, den: Any, ctx: str) -> list[list[_Element]]:
    N, Dg = _grid(num, "num", ctx), _grid(den, "den", ctx)
    shape_n, shape_d = (len(N), len(N[0])), (len(Dg), len(Dg[0]))
    if shape_n != shape_d:
        raise VerifyInputError(
            f"{ctx}: num is {shape_n[0]} x {shape_n[1]} but den is {shape_d[0]} x {shape_d[1]}; "
            "they need the same m x m nesting"
        )
    if shape_n[0] != shape_n[1]:
        raise VerifyInputError(
            f"{ctx}: H must be square (m inputs = m outputs), but num/den are "
            f"{shape_n[0]} x {shape_n[1]}"
        )
    out = []
    for i, (nrow, drow) in enumerate(zip(N, Dg, strict=True)):
        row = []
        for j, (nc, dc) in enumerate(zip(nrow, drow, strict=True)):
            nu, de = _poly(nc), _poly(dc)
            if de.is_zero():
                raise VerifyInputError(f"{ctx}: den[{i}][{j}]: zero denominator")
            if not nu.is_zero() and nu.degree() > de.degree():
                raise VerifyInputError(
                    f"{ctx}: element ({i}, {j}) is improper: numerator degree {nu.degree()} "
                    f"> denominator degree {de.degree()} (H must be proper)"
                )
            row.append(_reduced(nu, de))
        out.append(row)
    return out


def _reduced(num: fmpq_poly, den: fmpq_poly) -> _Element:
    """num/den in lowest terms with a monic denominator (exact gcd over Q)."""
    if num.is_zero():
        return _Element(fmpq_poly([]), fmpq_poly([1]))
    g = num.gcd(den)  # monic
    num, den = num // g, den // g
    lead = den.leading_coefficient()
    return _Element(num / lead, den / lead)


# --------------------------------------------------------------------------- realisation


def _companion_columns(elements: list[list[_Element]]) -> tuple[fmpq_mat, fmpq_mat, fmpq_mat,
                                                                  fmpq_mat]:
    """Step 2: one controllable canonical block per column (not observable in general)."""
    m = len(elements)
    D = fmpq_mat(m, m, [el.feedthrough for row in elements for el in row])
    blocks = []  # (j, d_j, C column block as rows of coefficients)
    for j in range(m):
        column = [elements[i][j] for i in range(m)]
        d = fmpq_poly([1])
        for el in column:
            if not el.remainder.is_zero():
                d = d * el.den // d.gcd(el.den)  # lcm, monic
        k = d.degree()
        if k == 0:
            continue
        rows = []
        for el in column:
            r = el.remainder
            numer = r * (d // el.den) if not r.is_zero() else fmpq_poly([])
            rows.append([_coeff(numer, t) for t in range(k)])
        blocks.append((j, d, rows))
    n = sum(d.degree() for _, d, _ in blocks)
    A, B, C = fmpq_mat(n, n), fmpq_mat(n, m), fmpq_mat(m, n)
    at = 0
    for j, d, rows in blocks:
        k = d.degree()
        for t in range(k - 1):
            A[at + t, at + t + 1] = 1
        for t in range(k):
            A[at + k - 1, at + t] = -_coeff(d, t)
        B[at + k - 1, j] = 1
        for i, coeffs in enumerate(rows):
            for t, c in enumerate(coeffs):
                C[i, at + t] = c
        at += k
    return A, B, C, D


def _rref_rows(M: fmpq_mat) -> tuple[fmpq_mat, list[int]]:
    """The non-zero rows of the reduced row echelon form of M, and their pivot columns."""
    R, rank = M.rref()
    cols = M.ncols()
    pivots = []
    for i in range(rank):
        pivots.append(next(c for c in range(cols) if R[i, c] != 0))
    W = fmpq_mat(rank, cols, [R[i, c] for i in range(rank) for c in range(cols)])
    return W, pivots


def _stack(top: fmpq_mat, bottom: fmpq_mat) -> fmpq_mat:
    cols = top.ncols()
    entries = [top[i, c] for i in range(top.nrows()) for c in range(cols)]
    entries += [bottom[i, c] for i in range(bottom.nrows()) for c in range(cols)]
    return fmpq_mat(top.nrows() + bottom.nrows(), cols, entries)


def _columns(M: fmpq_mat, cols: list[int]) -> fmpq_mat:
    return fmpq_mat(M.nrows(), len(cols), [M[i, c] for i in range(M.nrows()) for c in cols])


def _observable_quotient(A: fmpq_mat, B: fmpq_mat, C: fmpq_mat
                         ) -> tuple[fmpq_mat, fmpq_mat, fmpq_mat]:
    """Step 3: (A', B', C') on R^n / (unobservable subspace), exactly.

    An observable (A, C), the common case, is recognised modulo a prime first
    (:func:`_observable_mod_p`) and returned unchanged. Otherwise the row space of the
    observability matrix is found by :func:`_invariant_row_space`.
    """
    n = A.nrows()
    if n == 0 or _observable_mod_p(A, C):
        return A, B, C
    W, pivots = _invariant_row_space(A, C)
    if len(pivots) == n:
        return A, B, C
    return _columns(W * A, pivots), W * B, _columns(C, pivots)


#: Most primes used by the multimodular row space before exact elimination takes over.
_MAX_PRIMES = 256


def _invariant_row_space(A: fmpq_mat, C: fmpq_mat) -> tuple[fmpq_mat, list[int]]:
    """The RREF basis W of S = span of the rows of C, CA, CA^2, ... and its pivots, exactly.

    Multimodular: S is computed modulo primes p (cheap, word-size arithmetic), the RREF
    entries are lifted by Chinese remaindering and rational reconstruction, and the
    candidate W is *verified exactly*: C = C[:, piv] W and W A = (W A)[:, piv] W show
    that span W contains C and is A-invariant, so it contains S; and its dimension is a
    rank modulo p of the observability matrix, which is at most dim S. Hence span W = S.
    Floating point plays no part; a failed reconstruction only asks for more primes.
    Data whose answer would need more than ``_MAX_PRIMES`` primes fall back to exact
    elimination (:func:`_invariant_row_space_exact`).
    """
    n = A.nrows()
    p, rank, pivots = 2**61 + 2**40, -1, None  # primes just above 2^61, not _PRIME
    residues: list[tuple[int, list[list[int]]]] = []
    next_try = 1
    for _ in range(4 * _MAX_PRIMES):
        p = int(gmpy2.next_prime(p))
        Ap, Cp = _fmpq_mod(A, p), _fmpq_mod(C, p)
        if Ap is None or Cp is None:
            continue
        Wp, piv = _invariant_row_space_mod(Ap, Cp, p)
        if len(piv) > rank:
            rank, pivots, residues, next_try = len(piv), piv, [], 1
        if len(piv) < rank or piv != pivots:
            continue  # an unlucky prime: rank or pivots differ from the best seen
        residues.append((p, [[int(Wp[i, c]) for c in range(n)] for i in range(rank)]))
        if len(residues) >= next_try:
            next_try *= 2
            W = _reconstruct(residues, rank, n)
            if W is not None and _spans_invariant_row_space(W, pivots, A, C):
                return W, pivots
        if len(residues) > _MAX_PRIMES:
            break
    return _invariant_row_space_exact(A, C)


def _fmpq_mod(M: fmpq_mat, p: int) -> nmod_mat | None:
    """M modulo p, or None when p divides a denominator."""
    entries = []
    for i in range(M.nrows()):
        for j in range(M.ncols()):
            x = M[i, j]
            d = int(x.q) % p
            if d == 0:
                return None
            entries.append(int(x.p) * pow(d, -1, p) % p)
    return nmod_mat(M.nrows(), M.ncols(), entries, p)


def _invariant_row_space_mod(A: nmod_mat, C: nmod_mat, p: int) -> tuple[nmod_mat, list[int]]:
    """RREF of span(C, CA, CA^2, ...) over Z/p: add W A until the rank stops growing."""
    n = A.nrows()
    W, rank = C.rref()
    while True:
        top = [[int(W[i, c]) for c in range(n)] for i in range(rank)]
        WA = nmod_mat(rank, n, [x for row in top for x in row], p) * A if rank else None
        rows = top + ([[int(WA[i, c]) for c in range(n)] for i in range(rank)] if rank else [])
        if not rows:
            return nmod_mat(0, n, [], p), []
        W2, rank2 = nmod_mat(len(rows), n, [x for row in rows for x in row], p).rref()
        if rank2 == rank:
            break
        W, rank = W2, rank2
    pivots = [next(c for c in range(n) if int(W[i, c]) != 0) for i in range(rank)]
    return W, pivots


def rational_reconstruction(a: int, m: int) -> fmpq | None:
    """x/y with x = a y (mod m), |x|, y <= sqrt(m/2) (Wang's algorithm), or None."""
    bound = int(gmpy2.isqrt(m // 2))
    r0, r1, t0, t1 = m, a % m, 0, 1
    while r1 > bound:
        q = r0 // r1
        r0, r1, t0, t1 = r1, r0 - q * r1, t1, t0 - q * t1
    if t1 == 0 or abs(t1) > bound or gmpy2.gcd(r1, t1) != 1:
        return None
    return fmpq(r1, t1) if t1 > 0 else fmpq(-r1, -t1)


def _reconstruct(residues: list[tuple[int, list[list[int]]]], rows: int, cols: int
                 ) -> fmpq_mat | None:
    """Chinese remaindering of the RREF residues, then rational reconstruction."""
    modulus, values = 1, [[0] * cols for _ in range(rows)]
    for p, table in residues:
        inverse = pow(modulus, -1, p)
        for i in range(rows):
            for c in range(cols):
                v = values[i][c]
                values[i][c] = v + modulus * ((table[i][c] - v) * inverse % p)
        modulus *= p
    entries = []
    for i in range(rows):
        for c in range(cols):
            x = rational_reconstruction(values[i][c], modulus)
            if x is None:
                return None
            entries.append(x)
    return fmpq_mat(rows, cols, entries)


def _spans_invariant_row_space(W: fmpq_mat, pivots: list[int], A: fmpq_mat,
                               C: fmpq_mat) -> bool:
    """Exactly: rows of C lie in span W, and span W is A-invariant."""
    if _columns(W, pivots) != fmpq_mat(len(pivots), len(pivots),
                                       [int(i == j) for i in range(len(pivots))
                                        for j in range(len(pivots))]):
        return False
    WA = W * A
    return C == _columns(C, pivots) * W and WA == _columns(WA, pivots) * W


def _invariant_row_space_exact(A: fmpq_mat, C: fmpq_mat) -> tuple[fmpq_mat, list[int]]:
    """The same row space by exact elimination over Q (slow for large dense data).

    S_(k+1) = S_k + F_k A, where F_k are the rows that entered S_k: only those are
    multiplied by A.
    """
    n = A.nrows()
    W, pivots = _rref_rows(C)
    frontier = W
    while len(pivots) < n:
        W2, piv2 = _rref_rows(_stack(W, frontier * A))
        if len(piv2) == len(pivots):
            break
        new = [r for r, c in enumerate(piv2) if c not in set(pivots)]
        frontier = fmpq_mat(len(new), n, [W2[r, c] for r in new for c in range(n)])
        W, pivots = W2, piv2
    return W, pivots


def _fmpq_mod_p(M: fmpq_mat) -> nmod_mat | None:
    """M reduced modulo the prime, or None when the prime divides a denominator."""
    return _fmpq_mod(M, _PRIME)


def _observable_mod_p(A: fmpq_mat, C: fmpq_mat) -> bool:
    """True proves (A, C) observable; False decides nothing."""
    Ap, Cp = _fmpq_mod_p(A), _fmpq_mod_p(C)
    return Ap is not None and Cp is not None and _krylov_full_rank_nmod(
        Ap.transpose(), Cp.transpose())


def _controllable_part(A: fmpq_mat, B: fmpq_mat, C: fmpq_mat
                       ) -> tuple[fmpq_mat, fmpq_mat, fmpq_mat]:
    """The restriction to the controllable subspace, by duality with the quotient."""
    At, Ct, Bt = _observable_quotient(A.transpose(), C.transpose(), B.transpose())
    return At.transpose(), Bt.transpose(), Ct.transpose()


def _markov(el: _Element, count: int) -> list[fmpq]:
    """The first Laurent coefficients h_k of r/den = sum_k h_k s^-(k+1) (den monic)."""
    d = el.den.degree()
    r = el.remainder
    h: list[fmpq] = []
    for k in range(count):
        value = _coeff(r, d - 1 - k)
        for i in range(1, min(k, d) + 1):
            value -= _coeff(el.den, d - i) * h[k - i]
        h.append(value)
    return h


def check_realization(elements: list[list[_Element]], A: fmpq_mat, B: fmpq_mat,
                      C: fmpq_mat, D: fmpq_mat) -> str | None:
    """Step 4: None when C (sI - A)^-1 B + D equals the elements exactly, else why not."""
    m, n = len(elements), A.nrows()
    for i in range(m):
        for j in range(m):
            if D[i, j] != elements[i][j].feedthrough:
                return f"feedthrough D[{i}][{j}] differs"
    count = max(el.den.degree() for row in elements for el in row) + n
    expected = [[_markov(el, count) for el in row] for row in elements]
    X = B
    for k in range(count):
        M = C * X if n else fmpq_mat(m, m)
        for i in range(m):
            for j in range(m):
                if M[i, j] != expected[i][j][k]:
                    return f"Markov parameter {k} of element ({i}, {j}) differs"
        X = A * X if n else X
    return None


def _exact(A: fmpq_mat, B: fmpq_mat, C: fmpq_mat, D: fmpq_mat) -> ExactModel:
    n, m = A.nrows(), D.nrows()
    return ExactModel(_lists(A) if n else [], _lists(B) if n else [],
                      _lists(C) if n else [[] for _ in range(m)], _lists(D))


def transfer_function_realization(num: Any, den: Any, ctx: str) -> tuple[ExactModel, str]:
    """The exact minimal realisation of num/den (module docstring) and a line naming it."""
    elements = _elements(num, den, ctx)
    A, B, C, D = _companion_columns(elements)
    A, B, C = _observable_quotient(A, B, C)
    problem = check_realization(elements, A, B, C, D)
    if problem is not None:  # a bug, not bad input: the construction is exact
        raise AssertionError(f"{ctx}: exact realisation check failed: {problem}")
    return _exact(A, B, C, D), (f"exact minimal realisation over Q of the transfer "
                                f"function ({A.nrows()} states)")


# --------------------------------------------------------------------------- minimality

#: A Mersenne prime below 2^64 for the modular rank test.
_PRIME = 2**61 - 1


def _krylov_full_rank_nmod(A: nmod_mat, B: nmod_mat) -> bool:
    """rank [B, AB, ..., A^(n-1) B] = n modulo p (which proves it over Q).

    The first ceil(n/m) blocks can already have rank n (the generic case); more blocks
    are added, doubling, only when they do not.
    """
    n, m = A.nrows(), B.ncols()
    if m == 0:
        return n == 0
    blocks = [B.tolist()]
    X, wanted = B, -(-n // m)
    while True:
        while len(blocks) < wanted:
            X = A * X
            blocks.append(X.tolist())
        rows = [int(x) for i in range(n) for block in blocks for x in block[i]]
        if nmod_mat(n, len(blocks) * m, rows, _PRIME).rank() == n:
            return True
        if len(blocks) >= n:
            return False
        wanted = min(n, 2 * wanted)


#: A prime below 2^26 for the fast modular rank test in numpy int64: products of two
#: residues stay below 2^52, and sums of up to 2^11 of them below 2^63.
_SMALL_PRIME = 67108859
#: up to this many states the int64 Krylov products cannot overflow (n p^2 < 2^63)
_SMALL_PRIME_STATES = 2048


def _residues(M, rows: int, cols: int) -> np.ndarray | None:
    """An integer matrix over a denominator (``IntMatrix``) modulo the small prime
    (int64), or None when the prime divides the denominator."""
    p = _SMALL_PRIME
    if M.d % p == 0:
        return None
    inv = pow(M.d, -1, p)
    out = np.array([[z % p for z in row] for row in M.rows], dtype=np.int64)
    return (out.reshape(rows, cols) * inv) % p


def rank_mod_p(M: np.ndarray, p: int = _SMALL_PRIME) -> int:
    """The rank of an integer matrix modulo the prime p (FLINT ``nmod_mat``, exact)."""
    rows, cols = M.shape
    if rows == 0 or cols == 0:
        return 0
    return nmod_mat(rows, cols, (np.asarray(M, dtype=np.int64) % p).ravel().tolist(),
                    p).rank()


def _krylov_full_rank_mod_p(A: np.ndarray, B: np.ndarray) -> bool:
    """rank [B, AB, ..., A^(k-1) B] = n modulo p for some k <= n (which proves
    controllability over Q).

    The first ceil(n/m) blocks can already have rank n (the generic case); more blocks
    are added, doubling, only when they do not.
    """
    p = _SMALL_PRIME
    n, m = A.shape[0], B.shape[1]
    if m == 0:
        return n == 0
    blocks = [B % p]
    wanted = -(-n // m)
    while True:
        while len(blocks) < wanted:
            blocks.append(A.dot(blocks[-1]) % p)
        if rank_mod_p(np.hstack(blocks)) == n:
            return True
        if len(blocks) >= n:
            return False
        wanted = min(n, 2 * wanted)


def _minimal_mod_p(model: ExactModel) -> bool:
    """True proves (A, B) controllable and (A, C) observable; False decides nothing."""
    n, m = model.n, model.m
    if n > _SMALL_PRIME_STATES:
        return False
    Ai, Bi, Ci, _ = model.integer
    A, B, C = (_residues(X, r, c) for X, r, c in ((Ai, n, n), (Bi, n, m), (Ci, m, n)))
    return A is not None and B is not None and C is not None and _krylov_full_rank_mod_p(
        A, B) and _krylov_full_rank_mod_p(np.ascontiguousarray(A.T),
                                          np.ascontiguousarray(C.T))


def is_minimal(model: ExactModel) -> bool:
    """Whether (A, B) is controllable and (A, C) observable, decided exactly."""
    return minimal_part(model).hidden == 0


@dataclass(frozen=True)
class MinimalPart:
    """The minimal part of a realisation and what was removed (exact).

    ``uncontrollable`` modes are outside the controllable subspace; ``unobservable``
    ones are the unobservable modes of the controllable part. ``hidden_poly`` is
    chi_A / chi_A' (descending coefficients, exact strings), ``hidden_rhp`` /
    ``hidden_axis`` count its roots with Re s > 0 / Re s = 0 (with multiplicity).
    """

    model: ExactModel
    uncontrollable: int
    unobservable: int
    hidden_rhp: int
    hidden_axis: int
    hidden_poly: tuple[str, ...]

    @property
    def hidden(self) -> int:
        return self.uncontrollable + self.unobservable

    def summary(self) -> str:
        """One sentence on the hidden modes (empty for a minimal realisation)."""
        if not self.hidden:
            return ""
        where = []
        if self.hidden_rhp:
            where.append(f"{self.hidden_rhp} in Re s > 0")
        if self.hidden_axis:
            where.append(f"{self.hidden_axis} on the imaginary axis")
        stable = self.hidden - self.hidden_rhp - self.hidden_axis
        if stable:
            where.append(f"{stable} in Re s < 0")
        return (f"the given realisation is not minimal (exactly: {self.uncontrollable} "
                f"uncontrollable, {self.unobservable} unobservable mode(s); "
                + ", ".join(where) + ")")


def _real_root_count(g: fmpq_poly) -> int:
    """Distinct real roots of g (Sturm's theorem, exact)."""
    if g.degree() < 1:
        return 0
    g = g // g.gcd(g.derivative())
    chain = [g, g.derivative()]
    while chain[-1].degree() > 0:
        chain.append(-(chain[-2] % chain[-1]))
    chain = [p for p in chain if not p.is_zero()]

    def changes(signs: list[int]) -> int:
        signs = [x for x in signs if x]
        return sum(a != b for a, b in pairwise(signs))

    lead = [1 if p.leading_coefficient() > 0 else -1 for p in chain]
    at_minus = [x if p.degree() % 2 == 0 else -x for x, p in zip(lead, chain, strict=True)]
    return changes(at_minus) - changes(lead)


def _hidden_roots(h: fmpq_poly) -> tuple[int, int]:
    """(roots with Re s > 0, roots with Re s = 0) of h, with multiplicity, exactly."""
    rhp = axis = 0
    if h.degree() < 1:
        return 0, 0
    _, factors = h.factor_squarefree()
    for f, mult in factors:
        # f(jw) = Re + j Im as polynomials in w: coefficients of s^k times j^k
        re_c, im_c = [], []
        for k in range(f.degree() + 1):
            c, sign = _coeff(f, k), (1, 1, -1, -1)[k % 4]
            re_c.append(sign * c if k % 2 == 0 else fmpq(0))
            im_c.append(sign * c if k % 2 == 1 else fmpq(0))
        g = fmpq_poly(re_c).gcd(fmpq_poly(im_c))
        on_axis = _real_root_count(g)
        old = flint.ctx.prec
        try:
            prec = 64
            while True:
                flint.ctx.prec = prec
                roots = [r for r, _ in f.complex_roots()]
                signs = [(r.real > 0, r.real < 0) for r in roots]
                decided = [p or q for p, q in signs]
                if sum(not x for x in decided) == on_axis:
                    rhp += mult * sum(p for p, _ in signs)
                    break
                prec *= 2
                if prec > 1 << 16:  # cannot happen for squarefree f; a guard
                    raise AssertionError("root isolation did not separate the axis")
        finally:
            flint.ctx.prec = old
        axis += mult * on_axis
    return rhp, axis


def minimal_part(model: ExactModel) -> MinimalPart:
    """Kalman decomposition over Q: the controllable and observable part (exact)."""
    n, m = model.n, model.m
    if n == 0 or _minimal_mod_p(model):
        return MinimalPart(model, 0, 0, 0, 0, ("1",))
    A, B, C = _fm(model.A, n, n), _fm(model.B, n, m), _fm(model.C, m, n)
    Ac, Bc, Cc = _controllable_part(A, B, C)
    Am, Bm, Cm = _observable_quotient(Ac, Bc, Cc)
    nc, nm = Ac.nrows(), Am.nrows()
    if nm == n:
        return MinimalPart(model, 0, 0, 0, 0, ("1",))
    chi = A.charpoly()
    h = chi // Am.charpoly() if nm else chi
    rhp, axis = _hidden_roots(h)
    D = _fm(model.D, m, m)
    return MinimalPart(_exact(Am, Bm, Cm, D), n - nc, nc - nm, rhp, axis,
                       tuple(str(_mpq(_coeff(h, k))) for k in range(h.degree(), -1, -1)))


__all__ = ["MinimalPart", "check_realization", "is_minimal", "minimal_part",
           "transfer_function_realization"]
