"""Sparse multivariate polynomials with exact rational coefficients (gmpy2 ``mpq``).

A polynomial is a ``dict`` from exponent tuples to non-zero ``mpq`` coefficients over a
fixed, named list of variables. This is the one polynomial type of :mod:`verify.sos`:
the search reads its coefficients as floats, the trusted check multiplies and compares
them exactly, and certificates store them as ``[[exponents...], "p/q"]`` pairs in a
canonical order (so equal polynomials give equal bytes).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from gmpy2 import mpq

Monomial = tuple[int, ...]
Poly = dict[Monomial, mpq]


def constant(c, n: int) -> Poly:
    c = mpq(c)
    return {(0,) * n: c} if c else {}


def add(*polys: Poly) -> Poly:
    out: Poly = {}
    for p in polys:
        for m, c in p.items():
            v = out.get(m, 0) + c
            if v:
                out[m] = v
            else:
                out.pop(m, None)
    return out


def scale(c, p: Poly) -> Poly:
    c = mpq(c)
    return {m: c * v for m, v in p.items()} if c else {}


def mono_mul(a: Monomial, b: Monomial) -> Monomial:
    return tuple(x + y for x, y in zip(a, b, strict=True))


def mul(p: Poly, q: Poly) -> Poly:
    out: Poly = {}
    for m1, c1 in p.items():
        for m2, c2 in q.items():
            m = mono_mul(m1, m2)
            v = out.get(m, 0) + c1 * c2
            if v:
                out[m] = v
            else:
                out.pop(m, None)
    return out


def power(p: Poly, k: int, n: int) -> Poly:
    out = constant(1, n)
    for _ in range(k):
        out = mul(out, p)
    return out


def degree(p: Poly) -> int:
    return max((sum(m) for m in p), default=0)


def from_ring(element) -> Poly:
    """A sympy ``PolyElement`` over QQ as a :data:`Poly` (same generator order)."""
    out: Poly = {}
    for m, c in element.terms():
        out[tuple(int(e) for e in m)] = mpq(int(c.numerator), int(c.denominator))
    return out


def to_json(p: Poly) -> list:
    """Canonical JSON form: sorted ``[[exponents], "p/q"]`` pairs."""
    return [[list(m), str(p[m])] for m in sorted(p)]


def from_json(data, n: int, what: str = "polynomial") -> Poly:
    """Parse :func:`to_json` output strictly; ValueError (one line) when malformed."""
    if not isinstance(data, list):
        raise ValueError(f"{what} must be a list of [exponents, coefficient] pairs")
    out: Poly = {}
    for term in data:
        if not (isinstance(term, list) and len(term) == 2):
            raise ValueError(f"{what}: a term must be [exponents, coefficient]")
        exps, coeff = term
        out_m = monomial_from_json(exps, n, what)
        c = rational(coeff, what)
        if out_m in out:
            raise ValueError(f"{what}: monomial {list(out_m)} appears twice")
        if c:
            out[out_m] = c
    return out


def monomial_from_json(exps, n: int, what: str) -> Monomial:
    if not (isinstance(exps, list) and len(exps) == n
            and all(isinstance(e, int) and not isinstance(e, bool) and 0 <= e <= 64
                    for e in exps)):
        raise ValueError(f"{what}: exponents must be {n} integers in [0, 64]")
    return tuple(exps)


def rational(text, what: str) -> mpq:
    """An exact rational from a "p/q" or "p" string (no floats, no expressions)."""
    if not isinstance(text, str) or len(text) > 4000:
        raise ValueError(f"{what}: a coefficient must be a string 'p/q'")
    body = text[1:] if text.startswith("-") else text
    num, _, den = body.partition("/")
    if not num.isdigit() or (den and not den.isdigit()) or (_ and not den):
        raise ValueError(f"{what}: {text[:40]!r} is not a rational 'p/q'")
    if den and int(den) == 0:
        raise ValueError(f"{what}: zero denominator in {text[:40]!r}")
    return mpq(text)


def monomials_of_degree(n_vars: int, d: int) -> Iterable[Monomial]:
    """Exponent tuples of total degree d in ``n_vars`` variables (lexicographic)."""
    if n_vars == 0:
        if d == 0:
            yield ()
        return
    for first in range(d, -1, -1):
        for rest in monomials_of_degree(n_vars - 1, d - first):
            yield (first, *rest)


def to_text(p: Poly, names: Sequence[str]) -> str:
    """Readable form for messages (not parsed anywhere)."""
    if not p:
        return "0"
    parts = []
    for m in sorted(p, reverse=True):
        mono = "*".join(f"{names[i]}^{e}" if e > 1 else names[i] for i, e in enumerate(m) if e)
        parts.append(f"({p[m]})" + (f"*{mono}" if mono else ""))
    return " + ".join(parts)
