"""Exact rational functions with known denominators, for fast exact identity tests.

Every variable of the proof language is parametrised by rational functions whose
denominators are products of a few known polynomials that never vanish on real
parameters: |q|^2 for a quaternion, 1 + a^2 + b^2 for a stereographic unit vector,
1 + t^2 for a half-angle tangent. An expression's value is kept as

    numerator / prod_k f_k^{e_k}

with the numerator a sparse polynomial over QQ (sympy's ``PolyElement``) and the
exponents e_k of the known factors f_k. Sums take the largest exponent of each factor
(no polynomial gcd is ever computed), products add exponents. The value is zero
exactly when the numerator is the zero polynomial, because the denominator is a
product of non-vanishing factors. A generic sympy fraction field does the same job
~1000 times slower (it cancels a gcd after every operation).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

from sympy import QQ
from sympy.polys.rings import PolyElement, PolyRing


@dataclass
class Denominators:
    """The known non-vanishing factors of one ring (appended as variables appear)."""

    ring: PolyRing
    factors: list[PolyElement]

    def register(self, factor: PolyElement) -> int:
        self.factors.append(factor)
        return len(self.factors) - 1


class KnownFraction:
    """numerator / prod f_k^e_k with fixed known factors f_k (see module docstring)."""

    __slots__ = ("den", "exps", "num")

    def __init__(self, num: PolyElement, exps: tuple[int, ...], den: Denominators):
        self.num = num
        self.exps = exps
        self.den = den

    # -- helpers -----------------------------------------------------------------------
    def _padded(self, n: int) -> tuple[int, ...]:
        return self.exps + (0,) * (n - len(self.exps))

    def _lift(self, target: tuple[int, ...]) -> PolyElement:
        num = self.num
        for k, (want, have) in enumerate(zip(target, self._padded(len(target)), strict=True)):
            if want > have:
                num = num * self.den.factors[k] ** (want - have)
        return num

    def _coerce(self, other) -> KnownFraction:
        if isinstance(other, KnownFraction):
            return other
        return KnownFraction(self.den.ring(QQ(Fraction(other).numerator,
                                                Fraction(other).denominator)), (), self.den)

    # -- arithmetic --------------------------------------------------------------------
    def __add__(self, other) -> KnownFraction:
        other = self._coerce(other)
        if not other.num:
            return self
        if not self.num:
            return other
        n = max(len(self.exps), len(other.exps))
        target = tuple(max(a, b) for a, b in zip(self._padded(n), other._padded(n), strict=True))
        return KnownFraction(self._lift(target) + other._lift(target), target, self.den)

    __radd__ = __add__

    def __neg__(self) -> KnownFraction:
        return KnownFraction(-self.num, self.exps, self.den)

    def __sub__(self, other) -> KnownFraction:
        return self + (-self._coerce(other))

    def __rsub__(self, other) -> KnownFraction:
        return self._coerce(other) + (-self)

    def __mul__(self, other) -> KnownFraction:
        other = self._coerce(other)
        if not self.num or not other.num:
            return KnownFraction(self.den.ring.zero, (), self.den)
        n = max(len(self.exps), len(other.exps))
        exps = tuple(a + b for a, b in zip(self._padded(n), other._padded(n), strict=True))
        return KnownFraction(self.num * other.num, exps, self.den)

    __rmul__ = __mul__

    def is_zero(self) -> bool:
        return not self.num

    def denominator(self) -> PolyElement:
        out = self.den.ring.one
        for k, e in enumerate(self.exps):
            if e:
                out = out * self.den.factors[k] ** e
        return out


def constant(value: Fraction | int, den: Denominators) -> KnownFraction:
    value = Fraction(value)
    return KnownFraction(den.ring(QQ(value.numerator, value.denominator)), (), den)


def over_factor(numerators: Sequence[PolyElement], factor: PolyElement, den: Denominators):
    """Values numerator_i / factor for a new known factor (returns a list)."""
    k = den.register(factor)
    exps = (0,) * k + (1,)
    return [KnownFraction(n, exps, den) for n in numerators]
