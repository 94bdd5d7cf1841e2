"""Exact univariate polynomials over Q for the frequency-domain decision (python-flint).

Everything here is exact: FLINT's ``fmpq_poly`` (rational coefficients, gcd, exact
division), Sturm sequences for counting real roots in rational intervals, the Routh table
for the Hurwitz test, and the split of p(jw) into real and imaginary parts. Floating
point never enters; arb balls (rigorous interval arithmetic) appear only in
:func:`approximate_roots`, used to *propose* witness points and sum-of-squares terms that
are then checked exactly.

References: Sturm's theorem and the Routh-Hurwitz criterion as in Basu, Pollack and Roy,
*Algorithms in Real Algebraic Geometry* (2006), Sections 2.2.2 and 9.1.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from contextlib import contextmanager
from fractions import Fraction

import flint
from flint import fmpq, fmpq_poly, fmpz_poly
from gmpy2 import mpq

Poly = fmpq_poly
CPoly = tuple[fmpq_poly, fmpq_poly]  # p = re + j im, both real polynomials in w

ZERO = fmpq_poly([])
ONE = fmpq_poly([1])


def q(x) -> fmpq:
    """An exact rational (int, Fraction, gmpy2 mpq, fmpq or 'p/q' string) as fmpq."""
    if isinstance(x, fmpq):
        return x
    if isinstance(x, str):
        x = Fraction(x)
    return fmpq(int(x.numerator), int(x.denominator))


def to_mpq(x: fmpq) -> mpq:
    return mpq(int(x.p), int(x.q))


def poly(coeffs: Sequence) -> Poly:
    """Polynomial from ascending coefficients."""
    return fmpq_poly([q(c) for c in coeffs])


def coeff_strings(p: Poly) -> list[str]:
    """Ascending coefficients as 'p/q' strings (the JSON form; [] for the zero polynomial)."""
    return [str(c) for c in p.coeffs()]


def from_strings(texts: Sequence[str]) -> Poly:
    if not isinstance(texts, list) or not all(isinstance(t, str) for t in texts):
        raise ValueError("a polynomial is a list of 'p/q' coefficient strings")
    return fmpq_poly([q(Fraction(t)) for t in texts])


def monic(p: Poly) -> Poly:
    return p if p.is_zero() else p / p.leading_coefficient()


def mirror(p: Poly) -> Poly:
    """p(-s)."""
    return fmpq_poly([c if k % 2 == 0 else -c for k, c in enumerate(p.coeffs())])


def squarefree_part(p: Poly) -> Poly:
    """The monic product of the distinct irreducible factors of p (p != 0)."""
    if p.degree() < 1:
        return ONE
    return monic(p / p.gcd(p.derivative()))


def at_jw(p: Poly) -> CPoly:
    """(Re, Im) of p(jw) as real polynomials in w."""
    re, im = [], []
    for k, c in enumerate(p.coeffs()):
        sign = 1 if k % 4 in (0, 1) else -1
        (re if k % 2 == 0 else im).append((k, sign * c))
    out = []
    for part in (re, im):
        coeffs = [fmpq(0)] * (p.degree() + 1 if p.degree() >= 0 else 0)
        for k, c in part:
            coeffs[k] = c
        out.append(fmpq_poly(coeffs))
    return out[0], out[1]


# complex polynomials in w (pairs of real polynomials) --------------------------------

def cmul(a: CPoly, b: CPoly) -> CPoly:
    return a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]


def cadd(a: CPoly, b: CPoly) -> CPoly:
    return a[0] + b[0], a[1] + b[1]


def conj(a: CPoly) -> CPoly:
    return a[0], -a[1]


def times_j_power(a: CPoly, e: int) -> CPoly:
    """j^e a (e may be negative)."""
    for _ in range(e % 4):
        a = (-a[1], a[0])
    return a


# signs, Sturm sequences, root counting -----------------------------------------------

def sign(x) -> int:
    return (x > 0) - (x < 0)


def sturm_sequence(p: Poly) -> list[Poly]:
    """p, p', then negated remainders until the last non-zero one."""
    seq = [p, p.derivative()]
    while not seq[-1].is_zero():
        seq.append(-(seq[-2] % seq[-1]))
    return seq[:-1]


def _variations(signs: list[int]) -> int:
    nz = [s for s in signs if s]
    return sum(1 for a, b in itertools.pairwise(nz) if a != b)


def _signs_at(seq: list[Poly], x) -> list[int]:
    if x == "-inf":
        return [sign(p.leading_coefficient()) * (-1) ** p.degree() for p in seq]
    if x == "+inf":
        return [sign(p.leading_coefficient()) for p in seq]
    return [sign(p(x)) for p in seq]


def count_roots(p: Poly, lo="-inf", hi="+inf", seq: list[Poly] | None = None) -> int:
    """Number of distinct real roots of p != 0 in (lo, hi] (Sturm's theorem)."""
    if p.degree() < 1:
        return 0
    seq = sturm_sequence(p) if seq is None else seq
    return _variations(_signs_at(seq, lo)) - _variations(_signs_at(seq, hi))


def cauchy_bound(p: Poly) -> fmpq:
    """Every root z of p has |z| < 1 + max |a_k / a_n| (a rational bound)."""
    c = p.coeffs()
    lead = abs(c[-1])
    return 1 + max((abs(x) / lead for x in c[:-1]), default=fmpq(0))


def count_real_roots(p: Poly) -> int:
    """Distinct real roots of p != 0, exactly (Descartes bisection inside a root bound)."""
    from verify.passivity.check.interval_roots import count_roots_inside

    if p.degree() < 1:
        return 0
    q_ = squarefree_part(p)
    if all_real_brackets(q_) is not None:
        return q_.degree()
    bound = power_of_two_bound(q_)
    return count_roots_inside(q_, -bound, bound)


def power_of_two_bound(p: Poly) -> fmpq:
    """A power of two above the Cauchy bound: every root z of p has |z| < it, and
    bisection points stay dyadic (short) rationals."""
    bound = cauchy_bound(p)
    k = max(0, int(bound.p // bound.q).bit_length())
    return fmpq(2) ** k


def isolate_real_roots(p: Poly) -> list[tuple[fmpq, fmpq]]:
    """Disjoint rational intervals (a, b], each holding exactly one root of squarefree p,
    in increasing order; a == b for a rational root met exactly.

    Descartes bisection (:mod:`verify.passivity.check.interval_roots`) on (-B, B), B a
    power of two above the Cauchy bound; each interval is then shrunk until
    p(a) p(b) < 0 (a simple root inside, found again by sign changes alone). No Sturm
    sequence is formed.
    """
    from verify.passivity.check.interval_roots import roots_inside

    if p.degree() < 1:
        return []
    fast = all_real_brackets(p)
    if fast is not None:
        return fast
    bound = power_of_two_bound(p)
    return [_bracket(p, u, v) for u, v in roots_inside(p, -bound, bound)]


def all_real_brackets(p: Poly, max_prec: int = 4096) -> list[tuple[fmpq, fmpq]] | None:
    """When every root of squarefree p is real (a lossless model's pole polynomial), its
    isolating intervals proved by sign changes alone; None otherwise.

    arb's certified root balls only propose rational points t_0 < ... < t_D (D = deg p)
    between them; the proof is exact: p(t_(i-1)) p(t_i) < 0 for each i gives a root in
    every (t_(i-1), t_i), D roots in all, so exactly one in each and no other.
    """
    deg = p.degree()
    if deg < 1:
        return None
    bound = power_of_two_bound(p)
    prec = 64
    while prec <= max_prec:
        with precision(prec):
            roots = [r for r, _ in p.complex_roots()]
        if any(not r.imag.contains(0) for r in roots):
            return None  # a root certainly off the real line: not this case
        balls = sorted(roots, key=lambda r: float(r.real.mid()))
        points = [-bound]
        ok = True
        for left, right in itertools.pairwise(balls):
            hi, lo = dyadic_of(left.real.upper()), dyadic_of(right.real.lower())
            if not hi < lo:
                ok = False
                break
            points.append((hi + lo) / 2)
        points.append(bound)
        if ok:
            signs = [sign(p(t)) for t in points]
            if all(x * y < 0 for x, y in itertools.pairwise(signs)):
                return list(itertools.pairwise(points))
        prec *= 4
    return None


def dyadic_of(x) -> fmpq:
    """An arb number (exactly a dyadic rational, e.g. a ball's end) as an fmpq."""
    man, exp = x.mid().man_exp()
    return fmpq(man) * fmpq(2) ** int(exp) if exp >= 0 else fmpq(man, 2 ** int(-exp))


def _bracket(p: Poly, u: fmpq, v: fmpq) -> tuple[fmpq, fmpq]:
    """(a, b) inside the open (u, v), which holds one root of squarefree p, with
    p(a) p(b) < 0; or (r, r) for a rational root met on the way."""
    from verify.passivity.check.interval_roots import off_roots

    return off_roots(p, u, v)


def reduce_mod(g: Poly, rho: Poly) -> tuple[Poly, Poly]:
    """(r, h) = (g mod rho, gcd(r, rho)): what :func:`sign_at_root` needs of g, computed
    once per polynomial and reused at every root of rho."""
    r = g % rho
    return r, (r.gcd(rho) if not r.is_zero() else rho)


def sign_at_root(g: Poly, rho: Poly, interval: tuple[fmpq, fmpq],
                 reduced: tuple[Poly, Poly] | None = None) -> int:
    """The sign of g at the one root w0 of squarefree rho in the interval (a, b].

    g(w0) = 0 iff h = gcd(g mod rho, rho) vanishes at w0; h divides rho, so it is
    squarefree with at most that one root in (a, b]. Otherwise r = g mod rho is expanded
    exactly about the midpoint c of (a, b), and its value there decides once it exceeds
    the bound on the other Taylor terms over the interval; until then (a, b) is halved,
    keeping w0 inside by the sign of rho (exact rational arithmetic throughout).
    """
    from verify.passivity.check.interval_roots import count_roots_inside

    a, b = interval
    if a == b:
        return sign(g(a))
    r, h = reduce_mod(g, rho) if reduced is None else reduced
    if r.is_zero():
        return 0
    if rho(b) == 0:
        return sign(r(b))
    if h.degree() >= 1 and (h(b) == 0 or count_roots_inside(h, a, b) == 1):
        return 0
    if r.degree() < 1:
        return sign(r(b))
    a, b = _bracket(rho, a, b) if rho(a) == 0 else (a, b)
    if a == b:
        return sign(r(a))
    sb = sign(rho(b))
    while True:
        # r(w0) for w0 in (a, b): with r(c + t) = sum s_k t^k (one exact Taylor shift),
        # |r(c + t) - s_0| <= sum_(k >= 1) |s_k| d^k for |t| <= d, so s_0 decides when larger
        c, d = (a + b) / 2, (b - a) / 2
        taylor = r(fmpq_poly([c, 1])).coeffs()
        value = taylor[0]
        if value != 0 and abs(value) > fmpq_poly([0] + [abs(x) for x in taylor[1:]])(d):
            return sign(value)
        slope = taylor[1] if len(taylor) > 1 else fmpq(0)
        if value != 0 and slope != 0:  # aim at the width the first-order term allows
            tight = newton_bracket(rho, (a, b), abs(value) / (8 * abs(slope)))
            if tight is not None:
                a, b = tight
                continue
        for _ in range(16):  # cheap halvings, keeping w0 inside by the sign of rho
            mid = (a + b) / 2
            sm = sign(rho(mid))
            if sm == 0:
                return sign(r(mid))
            if sm == sb:
                b = mid
            else:
                a = mid


def _dyadic_round(x: fmpq, bits: int) -> fmpq:
    return fmpq(int(x.p) * 2**bits // int(x.q), 2**bits)


def newton_bracket(rho: Poly, interval: tuple[fmpq, fmpq], width: fmpq
                   ) -> tuple[fmpq, fmpq] | None:
    """A sub-interval of (a, b), rho(a) rho(b) < 0, no wider than about ``width`` and
    still with a sign change of rho (checked exactly), from Newton steps on dyadic
    points; None when the steps leave (a, b) or do not converge."""
    a, b = interval
    bits = max(8, 8 + int(width.q).bit_length() - int(width.p).bit_length())
    half = fmpq(1, 2**bits) if width >= fmpq(1, 2**bits) else width / 2
    d = rho.derivative()
    w = (a + b) / 2
    sa = sign(rho(a))
    for _ in range(12):
        slope = d(w)
        if slope == 0:
            return None
        w = _dyadic_round(w - rho(w) / slope, bits)
        if not a < w < b:
            return None
        lo, hi = max(a, w - half), min(b, w + half)
        slo, shi = sign(rho(lo)), sign(rho(hi))
        if slo == 0 or shi == 0:
            return (lo, lo) if slo == 0 else (hi, hi)
        if slo == sa and shi != sa:
            return lo, hi
    return None


# Routh-Hurwitz -------------------------------------------------------------------------

def routh_first_column(p: Poly) -> list[fmpq]:
    """First column of the Routh table of p (leading coefficient made positive).

    p is Hurwitz (every root in Re s < 0) iff this column has deg p + 1 entries, all
    positive; the table stops at the first entry that is not positive.

    The rows are kept as integer vectors R_i with the row r_i = R_i / c_i (c_i > 0
    rational): the next row's cross-multiplied entries are divided by their gcd, so
    entries grow like the Hurwitz determinants instead of like a rational remainder
    sequence, and the column entries r_i[0] = R_i[0] / c_i are the exact values.
    """
    c = p.coeffs()[::-1]  # descending
    if c and c[0] < 0:
        c = [-x for x in c]
    if not c:
        return []
    scale = fmpq(1)
    for x in c:
        scale = scale * (x.q // math.gcd(int(scale.p), int(x.q)))
    ints = [int((x * scale).p) for x in c]
    # a row is (integer vector as an fmpz_poly in the column index, its length, c_i)
    rows = [(fmpz_poly(ints[0::2]), len(ints[0::2]), scale),
            (fmpz_poly(ints[1::2]), len(ints[1::2]), scale)]
    column = [fmpq(ints[0]) / scale]
    for _ in range(len(c) - 1):
        (top, nt, ct), (bottom, nb, cb) = rows[-2], rows[-1]
        b0 = bottom[0] if nb else 0
        if not nb or b0 <= 0:
            column.append(fmpq(b0) / cb if nb else fmpq(0))
            return column
        column.append(fmpq(b0) / cb)
        # entries k < nt - 1: b0 top[k + 1] - top[0] bottom[k + 1]
        cross = b0 * top.right_shift(1) - top[0] * bottom.right_shift(1)
        g = cross.content() if not cross.is_zero() else 1
        rows.append((fmpz_poly([x // g for x in cross.coeffs()]), nt - 1,
                     ct * fmpq(b0) / g))
    return column


def is_hurwitz(p: Poly) -> bool:
    column = routh_first_column(p)
    return len(column) == p.degree() + 1 and all(x > 0 for x in column)


# approximate roots (arb balls; proposals only) -------------------------------------------

@contextmanager
def precision(bits: int):
    """FLINT's working precision for arb/acb within the block."""
    old = flint.ctx.prec
    flint.ctx.prec = bits
    try:
        yield
    finally:
        flint.ctx.prec = old


def approximate_roots(p: Poly, prec: int = 64) -> list:
    """Rigorous acb enclosures of the roots of p (each listed once), at ``prec`` bits."""
    with precision(prec):
        return [r for r, _ in p.complex_roots()]


def dyadic(x) -> fmpq:
    """The midpoint of an arb ball as an exact rational."""
    man, exp = x.mid().man_exp()
    return fmpq(man) * fmpq(2) ** int(exp) if exp >= 0 else fmpq(man, 2 ** int(-exp))


def has_real_root(p: Poly) -> bool:
    """Whether p has a real root, from FLINT's certified complex root isolation
    (``arb_fmpz_poly_complex_roots``: isolating balls, real roots with an exactly zero
    imaginary part)."""
    if p.degree() < 1:
        return False
    return any(r.imag == 0 for r in approximate_roots(squarefree_part(p), prec=64))


def refine_root(p: Poly, interval: tuple[fmpq, fmpq], width: fmpq) -> tuple[fmpq, fmpq]:
    """Halve the isolating interval (a, b] of a root of squarefree p below ``width``
    (sign changes of p; a == b when the root is met exactly)."""
    a, b = interval
    if a == b or b - a <= width:
        return a, b
    if p(b) == 0:
        return b, b
    if p(a) == 0:
        a, b = _bracket(p, a, b)
    sb = sign(p(b))
    while b - a > width:
        mid = (a + b) / 2
        sm = sign(p(mid))
        if sm == 0:
            return mid, mid
        if sm == sb:
            b = mid
        else:
            a = mid
    return a, b
