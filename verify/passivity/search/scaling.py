"""Exact rescaling of badly scaled models by powers of two (frequency, gain and state).

Floating-point search (Riccati equations, Hamiltonian eigenvalues, SDPs) fails on a model
such as A = -1e150, B = C = 1e150 (every product overflows), or on subnormal entries,
although the exact question is as easy as for A = -1, B = C = 1. With

    H_s(s) = H(beta s) / alpha,   realised by   A/beta, B/(beta gamma), C gamma/alpha, D/alpha,

(beta, alpha, gamma powers of two, so every float scales without rounding) the verdict
does not change: H is positive real iff H_s is, and H - nu0 I is iff H_s - (nu0/alpha) I
is. Evidence maps back exactly:

- a KYP certificate P_s of the scaled realisation gives P = alpha / (beta gamma^2) P_s for
  the model as written (the congruence diag(gamma I, I) carries M(P) to alpha M_s(P_s));
  it is re-checked exactly against the model as written;
- a witness at frequency w_s or real point s_s of H_s is one at w = beta w_s (s = beta
  s_s) for H, with v^H (H + H^H) v = alpha times the scaled value.

The model is rescaled only when its entries are far from 1 (a frequency, gain or state
exponent beyond :data:`EXPONENT_LIMIT`), so well scaled models and their stored
certificates are untouched.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from fractions import Fraction
from typing import TYPE_CHECKING

from verify.inputs.number_text import exact_text
from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel

if TYPE_CHECKING:
    from verify.passivity.model import LTIModel

#: Rescale when a frequency, gain or state exponent exceeds this (|log2| of the scale).
EXPONENT_LIMIT = 60


@dataclass(frozen=True)
class Rescaling:
    """H_s(s) = H(2^freq s) / 2^gain, states scaled by 2^state (see the module doc)."""

    freq: int
    gain: int
    state: int
    model: LTIModel  # the rescaled model (exact: every entry times a power of two)

    @property
    def beta(self) -> Fraction:
        return Fraction(2) ** self.freq

    @property
    def alpha(self) -> Fraction:
        return Fraction(2) ** self.gain

    @property
    def p_factor(self) -> Fraction:
        """P = p_factor * P_s."""
        return Fraction(2) ** (self.gain - self.freq - 2 * self.state)

    def describe(self) -> str:
        return (f"decided on the exactly rescaled model H(βs)/α with β = 2^{self.freq}, "
                f"α = 2^{self.gain} (states scaled by 2^{self.state})")


def _exponents(m: ex.RationalMatrix) -> set[int]:
    """About log2 |x| (within one) of every nonzero entry (exact: bit lengths of the
    reduced numerator and denominator, as :func:`_fraction_exponent`)."""
    return {abs(x.numerator).bit_length() - x.denominator.bit_length() + 1
            for row in m for x in row if x}


def _scaled(m: ex.RationalMatrix, e: int) -> ex.RationalMatrix:
    """m * 2^e (exact: rationals scale by a power of two without rounding)."""
    f = ex.mpq(2) ** e
    return [[x * f for x in row] for row in m]


def _fraction_exponent(x: Fraction) -> int | None:
    """About log2 |x| (within one), for any size of x; None for 0."""
    if x == 0:
        return None
    return abs(x.numerator).bit_length() - x.denominator.bit_length() + 1


def rescale(em: ExactModel, margin: Fraction = Fraction(0)) -> Rescaling | None:
    """The exact rescaling of a badly scaled model (with the margin nu0 of H - nu0 I on the
    same gain scale); None when it is well scaled. ``em`` is the exact model as written
    (its minimal part), so the rescaled model is exactly H(beta s)/alpha of it."""
    from verify.passivity.model import LTIModel

    A, B, C, D = em.A, em.B, em.C, em.D
    spans = [_exponents(x) for x in (A, B, C, D)]
    eA, eB, eC, eD = (max(s) if s else None for s in spans)
    eM = _fraction_exponent(Fraction(margin))
    if eM is not None:
        eD = eM if eD is None else max(eD, eM)
    low = [min(s) for s in spans if s]
    tiny = bool(low) and min(low) < -900  # a subnormal-range entry
    freq = eA or 0
    gains = [e for e in (eD, None if eB is None or eC is None else eB + eC - freq)
             if e is not None]
    gain = max(gains) if gains else 0
    state = 0 if eB is None or eC is None else round((eB + gain - freq - eC) / 2)
    if max(abs(freq), abs(gain), abs(state)) <= EXPONENT_LIMIT and not tiny:
        return None
    if freq == gain == state == 0:  # nothing to gain (a second pass on a rescaled model)
        return None
    n, m = em.n, em.m
    scaled = ExactModel(_scaled(A, -freq) if n else [], _scaled(B, -freq - state) if n else [],
                        _scaled(C, state - gain) if n else [[] for _ in range(m)],
                        _scaled(D, -gain))
    return Rescaling(freq, gain, state, LTIModel("rescaled", exact=scaled))


_FREQUENCY_KEYS = ("omega", "s")
_GAIN_KEYS = ("value", "value_bound")


def map_witness(witness, r: Rescaling):
    """The witness of H_s restated for H (frequencies times beta, values times alpha)."""
    data = dict(witness.data)
    for key in _FREQUENCY_KEYS:
        if key in data:
            data[key] = exact_text(Fraction(data[key]) * r.beta)
    for key in _GAIN_KEYS:
        if key in data:
            data[key] = exact_text(Fraction(data[key]) * r.alpha)
    data["rescaled"] = {"frequency_exponent": r.freq, "gain_exponent": r.gain,
                        "state_exponent": r.state,
                        "note": "omega, s and value are for the model as written; other "
                                "fields (error-bound terms, pole intervals) are the scaled "
                                "model's"}
    return replace(witness, summary=f"{witness.summary} ({r.describe()}: the numbers "
                   "in this sentence are the scaled model's, the witness fields are for "
                   "the model as written)", data=data)


__all__ = ["EXPONENT_LIMIT", "Rescaling", "map_witness", "rescale"]
