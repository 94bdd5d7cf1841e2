"""Exact real roots of a rational polynomial inside a rational interval (Descartes' rule).

The finite-band decision (paper, Section 4: nu(w) >= nu0 on a band [w1, w2]) needs, for a
squarefree polynomial h, whether h has a root in the open interval (a, b). Sturm
sequences answer that but grow coefficients quadratically in the degree; here the
question is answered by Descartes' rule of signs after the Moebius map
w = (a + b x) / (1 + x), which sends (a, b) onto (0, oo):

    T(x) = (1 + x)^D h((a + b x) / (1 + x)),   D = deg h,

has as many positive roots as h has roots in (a, b), and at most ``var(T)`` of them (the
number of sign changes of its coefficient list), with the same parity. Zero variations
prove "no root"; one proves exactly one. Otherwise the interval is halved
(Vincent-Collins-Akritas bisection, Collins and Akritas, SYMSAC 1976; termination by the
one- and two-circle theorems, e.g. Basu, Pollack and Roy, *Algorithms in Real Algebraic
Geometry*, 2006, Section 10.2). Each step is two Taylor shifts of an integer polynomial in
FLINT; nothing is rebuilt per step beyond that, and no sequence of remainders is formed.

A proof of "no root in (a, b)" is the list of breakpoints a = t_0 < ... < t_r = b the
bisection ended on: h(t_i) != 0 at the inner points, and var(T) = 0 on every piece.
:func:`check_no_root` re-checks such a list with two Taylor shifts per piece.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

from flint import fmpq, fmpq_poly, fmpz_poly

_SHIFT_ONE = fmpz_poly([1, 1])


def _integer(p: fmpq_poly) -> fmpz_poly:
    """p times the lcm of its coefficient denominators (same roots, same signs)."""
    return fmpz_poly(p.numer().coeffs()) if not p.is_zero() else fmpz_poly([])


def _variations(coeffs) -> int:
    signs = [c > 0 for c in coeffs if c != 0]
    return sum(1 for x, y in itertools.pairwise(signs) if x != y)


def _unit(p: fmpq_poly, a: fmpq, b: fmpq) -> fmpz_poly:
    """g(y) = p(a + (b - a) y) with integer coefficients: roots in (0, 1) <-> (a, b)."""
    return _integer(p(fmpq_poly([a, b - a])))


def _descartes(g: fmpz_poly, degree: int) -> int:
    """Sign changes of (1 + x)^degree g(1 / (1 + x)): a bound on the roots of g in (0, 1)."""
    c = g.coeffs() + [0] * (degree + 1 - len(g.coeffs()))
    return _variations(fmpz_poly(c[::-1])(_SHIFT_ONE).coeffs())


def sign_variations(p: fmpq_poly, a: fmpq, b: fmpq) -> int:
    """var(T) for p on (a, b): an upper bound on its roots there, of the same parity."""
    if p.degree() < 1:
        return 0
    return _descartes(_unit(p, fmpq(a), fmpq(b)), p.degree())


@dataclass(frozen=True)
class Inside:
    """The bisection's answer for squarefree h on (a, b).

    ``root`` is None when h has no root in (a, b), and then ``breakpoints`` proves it;
    otherwise it is ``(u, v)`` with u < v: exactly one root of h in (u, v), or u == v a
    rational root.
    """

    root: tuple[fmpq, fmpq] | None
    breakpoints: list[fmpq]


def _bisect(h: fmpq_poly, a: fmpq, b: fmpq, max_steps: int):
    """Pieces of (a, b), left to right: ("empty", lo, hi) with var = 0, ("one", lo, hi)
    with exactly one root inside, ("root", w, w) a rational root at a split point."""
    deg = h.degree()
    stack: list = [(_unit(h, a, b), fmpq(0), fmpq(1))]  # g on the piece (lo, hi) of (0, 1)
    steps = 0
    while stack:
        steps += 1
        if steps > max_steps:
            raise RuntimeError("root isolation did not terminate (is h squarefree?)")
        g, lo, hi = stack.pop()
        x, y = a + (b - a) * lo, a + (b - a) * hi
        if g is None:
            yield "root", x, y
            continue
        v = _descartes(g, deg)
        if v == 0:
            yield "empty", x, y
            continue
        if v == 1:
            yield "one", x, y
            continue
        # halves: g_L(y) = 2^deg g(y / 2) and g_R(y) = g_L(y + 1) (signs kept)
        left = fmpz_poly([c * 2 ** (deg - k) for k, c in enumerate(g.coeffs())])
        right = left(_SHIFT_ONE)
        mid = (lo + hi) / 2
        stack.append((right, mid, hi))
        if right(0) == 0:  # h vanishes at the midpoint: a rational root
            stack.append((None, mid, mid))
        stack.append((left, lo, mid))


def roots_inside(h: fmpq_poly, a, b, *, max_steps: int = 1_000_000):
    """The roots of squarefree h in the open interval (a, b), left to right, exactly.

    Yields ``(u, v)``: exactly one root in (u, v) with u < v, or u == v a rational root
    met as a split point. ``max_steps`` only guards against a non-squarefree input
    (RuntimeError); for squarefree h the bisection ends (two-circle theorem).
    """
    a, b = fmpq(a), fmpq(b)
    if not a < b:
        raise ValueError("need a < b")
    if h.is_zero():
        raise ValueError("the zero polynomial")
    if h.degree() < 1:
        return
    for kind, x, y in _bisect(h, a, b, max_steps):
        if kind != "empty":
            yield x, y


def first_root_inside(h: fmpq_poly, a, b, *, max_steps: int = 1_000_000) -> Inside:
    """The first root of squarefree h in (a, b), or the breakpoints proving there is none."""
    a, b = fmpq(a), fmpq(b)
    if not a < b:
        raise ValueError("need a < b")
    if h.is_zero():
        raise ValueError("the zero polynomial")
    if h.degree() < 1:
        return Inside(None, [a, b])
    points = [a]
    for kind, x, y in _bisect(h, a, b, max_steps):
        if kind != "empty":
            return Inside((x, y), [])
        points.append(y)
    return Inside(None, points)


def count_roots_inside(h: fmpq_poly, a, b, *, closed: bool = False) -> int:
    """Distinct roots of squarefree h in (a, b), or in [a, b] with ``closed``, exactly."""
    a, b = fmpq(a), fmpq(b)
    ends = (h(a) == 0) + (h(b) == 0) if closed and not h.is_zero() else 0
    return ends + sum(1 for _ in roots_inside(h, a, b))


def check_no_root(h: fmpq_poly, a, b, breakpoints: list[fmpq]) -> str | None:
    """None when ``breakpoints`` proves h has no root in (a, b), else the reason."""
    a, b = fmpq(a), fmpq(b)
    if len(breakpoints) < 2 or breakpoints[0] != a or breakpoints[-1] != b:
        return "the breakpoints do not run from one end of the interval to the other"
    if any(not x < y for x, y in itertools.pairwise(breakpoints)):
        return "the breakpoints are not increasing"
    if h.is_zero():
        return "the polynomial is zero"
    if h.degree() < 1:
        return None
    if any(h(t) == 0 for t in breakpoints[1:-1]):
        return "the polynomial vanishes at an inner breakpoint"
    for x, y in itertools.pairwise(breakpoints):
        if sign_variations(h, x, y) != 0:
            return f"Descartes' rule does not exclude a root in ({x}, {y})"
    return None


def off_roots(h, u: fmpq, v: fmpq) -> tuple[fmpq, fmpq]:
    """The open (u, v), holding exactly one root of squarefree h, bisected until neither
    end is a root of h (root counts decide the half); (r, r) for a rational root met on
    the way, and (u, u) as given."""
    if u == v:
        return u, v
    while h(u) == 0 or h(v) == 0:
        mid = (u + v) / 2
        if h(mid) == 0:
            return mid, mid
        if count_roots_inside(h, u, mid) == 1:
            v = mid
        else:
            u = mid
    return u, v


def refine(h: fmpq_poly, interval: tuple[fmpq, fmpq], width: fmpq) -> tuple[fmpq, fmpq]:
    """Shrink the open (u, v), holding exactly one root of squarefree h (or u == v, a
    rational root), below ``width``; the ends may be roots of h themselves. Exact:
    root counts until both ends are non-roots, then sign changes."""
    u, v = off_roots(h, *interval)
    if u == v:
        return u, v
    su = h(u)
    while v - u > width:
        mid = (u + v) / 2
        sm = h(mid)
        if sm == 0:
            return mid, mid
        if (sm > 0) == (su > 0):
            u, su = mid, sm
        else:
            v = mid
    return u, v
