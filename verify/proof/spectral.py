"""lambda_min atoms in exact arithmetic: one generator per spectrum, up to a positive scale.

The exact algebra cannot hold lambda_min(M) as a rational function; it holds an opaque
generator per atom. Two atoms whose arguments have the same spectrum up to a positive
factor c (lambda_min(M) and lambda_min(sym M); lambda_min(2A) and lambda_min(A);
lambda_min(Q A Q^T) and lambda_min(A) for a rotation Q) are the same number up to that
factor (and a shift s: lambda_min(A + s I) = lambda_min(A) + s), and are given one
generator here, so that identities between them are decided.

The test is exact: sym X - s I and c sym Y have the same characteristic polynomial,
i.e. tr, e2 (the sum of the principal 2x2 minors) and det agree, as rational functions
of the parameters. Equal characteristic polynomials give equal eigenvalues with
multiplicity, so lambda_min(X) = c lambda_min(Y) + s for c > 0 (Horn and Johnson,
*Matrix Analysis*, 2nd ed., Sec. 1.2). The identities hold on the charts' dense image,
hence everywhere by continuity. A float probe only proposes which pairs to compare and
(c, s); it never decides. sym M = a I exactly gives lambda_min(M) = a.

A constant argument (no parameter, no other atom) with a rational smallest eigenvalue
becomes that constant, so that e.g. lambda_min(I) = 5 is seen to be false.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import sympy as sp

from verify.inputs.numbers import fraction
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
            term = to_float(c)
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
    return fraction(smallest)


def _affine_fit(x: np.ndarray | None, y: np.ndarray | None):
    """(c, s), c > 0, with spectrum(x) = c spectrum(y) + s at the probe, if one fits."""
    if x is None or y is None:
        return None
    dx, dy = x - x.mean(), y - y.mean()
    nx, ny = float(np.linalg.norm(dx)), float(np.linalg.norm(dy))
    if ny == 0.0 or nx == 0.0:
        return None  # a multiple of I: handled exactly by _scalar_multiple
    c = nx / ny
    shift = float(x.mean() - c * y.mean())
    if not (np.isfinite(c) and np.isfinite(shift)):
        return None
    if np.max(np.abs(x - c * y - shift)) > PROBE_TOLERANCE * (1 + np.abs(x).max()):
        return None
    return Fraction(c).limit_denominator(10**6), Fraction(shift).limit_denominator(10**6)


def _shifted(e: list[KnownFraction], s: Fraction) -> list[KnownFraction]:
    return [e[0] - s, e[1] - s, e[2] - s, *e[3:]]


def _same_up_to(x: list[KnownFraction], y: list[KnownFraction], c: Fraction,
                s: Fraction) -> bool:
    """Exact: sym X - s I and c sym Y have one characteristic polynomial."""
    cx, cy = charpoly_coefficients(_shifted(x, s)), charpoly_coefficients(y)
    return all((a - b * c**k).is_zero() for k, (a, b) in enumerate(zip(cx, cy, strict=True), 1))


def _scalar_multiple(e: list[KnownFraction]) -> KnownFraction | None:
    """a when sym M = a I exactly (then lambda_min(M) = a)."""
    a11, a22, a33, *off = e
    if all(x.is_zero() for x in off) and (a11 - a22).is_zero() and (a11 - a33).is_zero():
        return a11
    return None


def canonical(atoms: list[Atom], matrix, generator: KnownFraction) -> Atom:
    """The value of lambda_min(matrix): a known atom scaled, a constant, or ``generator``."""
    entries = sym_entries(matrix)
    const = _constant_lambda_min(entries)
    if const is not None:
        return Atom(constant(const, generator.den), entries, None)
    diagonal = _scalar_multiple(entries)
    if diagonal is not None:
        return Atom(diagonal, entries, None)
    probe = _spectrum(entries)
    for known in atoms:
        fit = _affine_fit(probe, known.probe)
        if fit is not None and fit[0] > 0 and _same_up_to(entries, known.entries, *fit):
            return Atom(known.value * fit[0] + fit[1], entries, probe)
    atom = Atom(generator, entries, probe)
    atoms.append(atom)
    return atom
