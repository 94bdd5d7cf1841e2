"""lambda_min atoms in exact arithmetic: one generator per spectrum, up to a positive scale.

The exact algebra cannot hold lambda_min(M) as a rational function; it holds an opaque
generator per atom. Two atoms whose arguments have the same spectrum up to a positive
factor c (lambda_min(M) and lambda_min(sym M); lambda_min(2A) and lambda_min(A);
lambda_min(Q A Q^T) and lambda_min(A) for a rotation Q) are the same number up to that
factor, and are given one generator here, so that identities between them are decided.

The test is exact: the characteristic polynomials of the symmetric parts agree after
scaling, i.e. tr X = c tr Y, e2(X) = c^2 e2(Y), det X = c^3 det Y as rational functions
of the parameters (e2 the sum of the principal 2x2 minors). Equal characteristic
polynomials give equal eigenvalues with multiplicity, so lambda_min(X) = c lambda_min(Y)
for c > 0 (Horn and Johnson, *Matrix Analysis*, 2nd ed., Sec. 1.2). A float probe only
proposes which pairs to compare and the factor c; it never decides.

A constant argument (no parameter, no other atom) with a rational smallest eigenvalue
becomes that constant, so that e.g. lambda_min(I) = 5 is seen to be false.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import sympy as sp

from verify.proof.evaluate import to_float
from verify.proof.exact import KnownFraction, constant

PROBE_TOLERANCE = 1e-7


@dataclass
class Atom:
    """A canonical lambda_min: its value and the spectrum of its argument at the probe."""

    value: KnownFraction
    entries: list[KnownFraction]  # sym part: (11, 22, 33, 12, 13, 23)
    probe: np.ndarray | None  # eigenvalues at the probe point, ascending


def sym_entries(matrix) -> list[KnownFraction]:
    """Upper triangle of (M + M^T)/2 as six exact entries."""
    half = Fraction(1, 2)
    out = [matrix[i][i] for i in range(3)]
    for i, j in ((0, 1), (0, 2), (1, 2)):
        out.append((matrix[i][j] + matrix[j][i]) * half)
    return out


def _full(e: list) -> list[list]:
    a11, a22, a33, a12, a13, a23 = e
    return [[a11, a12, a13], [a12, a22, a23], [a13, a23, a33]]


def charpoly_coefficients(e: list[KnownFraction]) -> tuple:
    """(tr, e2, det) of the symmetric matrix with upper triangle ``e``."""
    a11, a22, a33, a12, a13, a23 = e
    tr = a11 + a22 + a33
    e2 = a11 * a22 - a12 * a12 + a11 * a33 - a13 * a13 + a22 * a33 - a23 * a23
    det = (a11 * (a22 * a33 - a23 * a23) - a12 * (a12 * a33 - a23 * a13)
           + a13 * (a12 * a23 - a22 * a13))
    return tr, e2, det


def _probe_point(ngens: int) -> list[float]:
    """A fixed generic point (no chart denominator vanishes at a real point but q = 0)."""
    return [((7 * i + 3) % 11 - 5 + 0.5) / (i % 4 + 2) for i in range(ngens)]


def _float_value(x: KnownFraction, point: list[float]) -> float:
    def ev(poly) -> float:
        total = 0.0
        for monom, c in poly.terms():
            term = to_float(Fraction(int(c.numerator), int(c.denominator)))
            for k, e in enumerate(monom):
                if e:
                    term *= point[k] ** e
            total += term
        return total

    with np.errstate(all="ignore"):
        return ev(x.num) / ev(x.denominator())


def _spectrum(entries: list[KnownFraction]) -> np.ndarray | None:
    point = _probe_point(len(entries[0].den.ring.gens))
    try:
        m = np.array(_full([_float_value(x, point) for x in entries]), dtype=float)
        if not np.all(np.isfinite(m)):
            return None
        return np.linalg.eigvalsh(m)
    except (OverflowError, ZeroDivisionError, np.linalg.LinAlgError):
        return None


def _constant_lambda_min(entries: list[KnownFraction]) -> Fraction | None:
    if not all(x.num.is_ground and x.denominator().is_ground for x in entries):
        return None
    values = []
    for x in entries:
        n, d = x.num.LC if x.num else 0, x.denominator().LC
        values.append(sp.Rational(int(sp.QQ(n).numerator), int(sp.QQ(n).denominator))
                      / sp.Rational(int(sp.QQ(d).numerator), int(sp.QQ(d).denominator)))
    lam = sp.Symbol("lam")
    roots = sp.Poly(sp.Matrix(_full(values)).charpoly(lam).as_expr(), lam).real_roots()
    smallest = roots[0]
    if not smallest.is_Rational:
        return None
    return Fraction(int(smallest.p), int(smallest.q))


def _scale_of(x: np.ndarray | None, y: np.ndarray | None) -> Fraction | None:
    """A positive factor c with spectrum(x) = c spectrum(y) at the probe, if one fits."""
    if x is None or y is None:
        return None
    nx, ny = float(np.linalg.norm(x)), float(np.linalg.norm(y))
    if ny == 0.0:
        return Fraction(1) if nx == 0.0 else None
    c = nx / ny
    if c <= 0 or not np.isfinite(c):
        return None
    if np.max(np.abs(x - c * y)) > PROBE_TOLERANCE * (1 + nx):
        return None
    return Fraction(c).limit_denominator(10**6)


def _same_up_to(x: list[KnownFraction], y: list[KnownFraction], c: Fraction) -> bool:
    """Exact: charpoly(sym X)(lam) = c^3 charpoly(sym Y)(lam / c)."""
    cx, cy = charpoly_coefficients(x), charpoly_coefficients(y)
    return all((a - b * c**k).is_zero() for k, (a, b) in enumerate(zip(cx, cy, strict=True), 1))


def canonical(atoms: list[Atom], matrix, generator: KnownFraction) -> Atom:
    """The value of lambda_min(matrix): a known atom scaled, a constant, or ``generator``."""
    entries = sym_entries(matrix)
    const = _constant_lambda_min(entries)
    if const is not None:
        return Atom(constant(const, generator.den), entries, None)
    probe = _spectrum(entries)
    for known in atoms:
        c = _scale_of(probe, known.probe)
        if c is not None and _same_up_to(entries, known.entries, c):
            return Atom(known.value * c, entries, probe)
    atom = Atom(generator, entries, probe)
    atoms.append(atom)
    return atom
