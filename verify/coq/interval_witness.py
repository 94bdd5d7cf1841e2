"""Witnesses that a real polynomial is non-negative on an interval (untrusted search).

Coq's ``nonneg_ok`` (``BandCert.v``) proves p(x) >= 0 for a <= x <= b from
``(g, q, pieces)``: it checks, by computing with polynomials over Q, that p = g^2 q and
that on each piece [u, v] (the pieces run from a to b, each starting where the last ended)

    q(x) = sum_k c_k (x - u)^(i_k) (v - x)^(j_k),   every c_k >= 0,

a Bernstein form, non-negative on [u, v] term by term (:func:`find`); on a half line
[a, oo) (``ray_nonneg_ok``) the last piece is [u, oo) with q(x) = sum_k c_k (x - u)^(i_k),
every c_k >= 0 (:func:`find_ray`). This module only proposes such
witnesses; :func:`check` repeats Coq's computation so that the exporter refuses a
polynomial Coq would refuse.

The search: the squarefree decomposition p = content * prod g_i^e_i puts the even part
into g (g = prod g_i^(e_i // 2)) and leaves q = content * prod_(e_i odd) g_i, which has
only simple roots. When p >= 0 on [a, b], q has no root inside (a, b) (it would change
sign there) and is positive there; its Bernstein coefficients on [u, v] are then all
>= 0 once the pieces are short enough (also at a simple root at a or b), so the
interval is bisected until they are. When p < 0 somewhere inside, no witness exists and
the search gives up after :data:`MAX_DEPTH` bisections or :data:`MAX_PIECES` pieces.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import comb

from flint import fmpq, fmpq_poly

#: Bisection depth and number of pieces after which the search gives up.
MAX_DEPTH = 40
MAX_PIECES = 4096


@dataclass(frozen=True)
class Piece:
    """q(x) = sum c (x - u)^i (v - x)^j on [u, v], the terms as (c, i, j)."""

    u: fmpq
    v: fmpq
    terms: tuple[tuple[fmpq, int, int], ...]


@dataclass(frozen=True)
class NonnegWitness:
    """p = g^2 q, and q in Bernstein form on each piece of [a, b]."""

    g: fmpq_poly
    q: fmpq_poly
    pieces: tuple[Piece, ...]


def bernstein_terms(q: fmpq_poly, u: fmpq, v: fmpq) -> tuple[tuple[fmpq, int, int], ...]:
    """The c_i with q(x) = sum_i c_i (x - u)^i (v - x)^(n - i), n = deg q (exactly).

    With x = u + h t (h = v - u) and q(u + h t) = sum_j a_j t^j, the Bernstein
    coefficients are b_i = sum_(j <= i) C(i, j) / C(n, j) a_j, and c_i = C(n, i) b_i / h^n.
    """
    n = max(q.degree(), 0)
    if q.is_zero():
        return ()
    h = v - u
    shifted = q(fmpq_poly([u, h]))  # q(u + h t)
    a = [shifted[j] for j in range(n + 1)]
    hn = h ** n
    out = []
    for i in range(n + 1):
        b = sum((fmpq(comb(i, j), comb(n, j)) * a[j] for j in range(i + 1)), fmpq(0))
        c = b * comb(n, i) / hn
        out.append((c, i, n - i))
    return tuple(out)


def _split(p: fmpq_poly) -> tuple[fmpq_poly, fmpq_poly]:
    """(g, q) with p = g^2 q and q squarefree up to a constant (p non-zero)."""
    content, factors = p.factor_squarefree()
    g = fmpq_poly([1])
    q = fmpq_poly([content])
    for f, e in factors:
        e = int(e)
        g *= f ** (e // 2)
        if e % 2:
            q *= f
    return g, q


def find(p: fmpq_poly, a: fmpq, b: fmpq) -> NonnegWitness | None:
    """A witness that p >= 0 on [a, b] (a < b), or None when none was found (then p is
    negative somewhere inside, or the budget was spent)."""
    if p.is_zero():
        return NonnegWitness(fmpq_poly([]), fmpq_poly([]), (Piece(a, b, ()),))
    g, q = _split(p)
    pieces: list[Piece] = []
    stack = [(a, b, 0)]
    while stack:  # depth first, left to right: the pieces come out in order
        u, v, depth = stack.pop()
        terms = bernstein_terms(q, u, v)
        if all(c >= 0 for c, _, _ in terms):
            pieces.append(Piece(u, v, tuple(t for t in terms if t[0] != 0)))
            if len(pieces) > MAX_PIECES:
                return None
            continue
        if depth >= MAX_DEPTH:
            return None
        mid = (u + v) / 2
        stack.append((mid, v, depth + 1))
        stack.append((u, mid, depth + 1))
    witness = NonnegWitness(g, q, tuple(pieces))
    return witness if check(p, a, b, witness) else None


@dataclass(frozen=True)
class RayWitness:
    """p = g^2 q; q in Bernstein form on pieces of [a, u] (none when u = a) and
    q(x) = sum c (x - u)^i with every c >= 0 on [u, oo), the terms as (c, i)."""

    g: fmpq_poly
    q: fmpq_poly
    pieces: tuple[Piece, ...]
    u: fmpq
    ray: tuple[tuple[fmpq, int], ...]


#: Doublings of the half line's start before the search gives up.
MAX_DOUBLINGS = 256


def taylor(q: fmpq_poly, u: fmpq) -> list[fmpq]:
    """The coefficients of q(x + u), lowest degree first (q(x) = sum c_i (x - u)^i)."""
    shifted = q(fmpq_poly([u, 1]))
    return [shifted[i] for i in range(max(shifted.degree(), -1) + 1)]


def find_ray(p: fmpq_poly, a: fmpq) -> RayWitness | None:
    """A witness that p >= 0 on [a, oo), or None when none was found.

    The half line starts at the first u = a, max(1, a), 2 u, 4 u, ... where every Taylor
    coefficient of q at u is >= 0 (true from some u on when q's leading coefficient is
    positive: beyond every real root of q and its derivatives); [a, u] is then cut into
    Bernstein pieces as in :func:`find`.
    """
    if p.is_zero():
        return RayWitness(fmpq_poly([]), fmpq_poly([]), (), a, ())
    g, q = _split(p)
    u = a
    for step in range(MAX_DOUBLINGS + 1):
        coeffs = taylor(q, u)
        if all(c >= 0 for c in coeffs):
            break
        u = max(fmpq(1), a) if step == 0 else (u * 2 if u > 0 else fmpq(1))
    else:
        return None
    ray = tuple((c, i) for i, c in enumerate(coeffs) if c != 0)
    pieces: tuple[Piece, ...] = ()
    if u != a:
        bounded = find(p, a, u)
        if bounded is None:
            return None
        if bounded.g != g or bounded.q != q:
            return None  # the same split of p, so the same q on both parts
        pieces = bounded.pieces
    witness = RayWitness(g, q, pieces, u, ray)
    return witness if check_ray(p, a, witness) else None


def check_ray(p: fmpq_poly, a: fmpq, w: RayWitness) -> bool:
    """Coq's ``ray_nonneg_ok``, repeated."""
    if p != w.g * w.g * w.q:
        return False
    if w.pieces:
        if not check(p, a, w.u, NonnegWitness(w.g, w.q, w.pieces)):
            return False
    elif w.u != a:
        return False
    total = fmpq_poly([])
    for c, i in w.ray:
        if c < 0:
            return False
        total += c * fmpq_poly([-w.u, 1]) ** i
    return total == w.q


def _bern(piece: Piece) -> fmpq_poly:
    total = fmpq_poly([])
    for c, i, j in piece.terms:
        total += c * fmpq_poly([-piece.u, 1]) ** i * fmpq_poly([piece.v, -1]) ** j
    return total


def check(p: fmpq_poly, a: fmpq, b: fmpq, w: NonnegWitness) -> bool:
    """Coq's ``nonneg_ok``, repeated: p = g^2 q, the pieces chain from a to b, and on each
    q equals its terms with non-negative weights."""
    if p != w.g * w.g * w.q or not w.pieces:
        return False
    start = a
    for piece in w.pieces:
        if piece.u != start or _bern(piece) != w.q:
            return False
        if any(c < 0 for c, _, _ in piece.terms):
            return False
        start = piece.v
    return start == b
