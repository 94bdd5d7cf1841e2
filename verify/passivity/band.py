"""Passivity over a finite frequency band [w1, w2]: verdict, certificate or witness.

`verify gate MODEL --band W1:W2` asks whether nu(w) >= nu0 (paper, Section 4) for every w
in [w1, w2] where H(jw) is defined. Untrusted search, trusted check:

1. nu is minimised over the band by Hamiltonian level crossings
   (:mod:`verify.passivity.search.hamiltonian`); where it is negative, a rational w* inside the
   band and a rational vector v with v^H (H(jw*) + H(jw*)^H) v < 0 are checked exactly
   (:func:`verify.passivity.check.witness.frequency_witness_at`): not passive on the band.
2. Up to ``EXACT_BAND_LIMIT`` states, whatever is still open is decided completely and
   exactly (:mod:`verify.passivity.check.band_fd`): the principal-minor sums of the
   Hermitian part, cleared of a positive denominator, are >= 0 on [w1, w2] by exact root
   counting on the interval (a ``verify-band-fd-certificate/1`` with Descartes
   breakpoints), or one is negative at a rational w* of the band (exact vector witness).
   Tangencies inside or at the edges and poles anywhere on the band are decided too. No
   floating point enters this certificate, so its bytes are the same on every machine.
3. Small models (up to ``GKYP_STATES`` states) that step 2 leaves open, and models above
   ``EXACT_BAND_LIMIT`` states: the generalized KYP LMI (:mod:`verify.passivity.check.gkyp`)
   is solved with cvxpy + Clarabel for Hermitian P, Q with a margin
   (:mod:`verify.passivity.search.gkyp_sdp`), rounded to Gaussian rationals and checked
   exactly: passive on the band.
4. Above ``EXACT_BAND_LIMIT`` states a band the first and third steps do not settle is
   inconclusive.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

import numpy as np
from gmpy2 import mpq

from verify.errors import VerifyInputError
from verify.inputs.numbers import parse_number
from verify.passivity.check.band_fd import BandFdCertificate
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.gkyp import BandCertificate
from verify.passivity.check.realization import minimal_part
from verify.passivity.check.witness import Witness, frequency_witness_at
from verify.passivity.decision import (
    INCONCLUSIVE,
    NOT_PASSIVE,
    PASSIVE,
    GateVerdict,
    clearly_negative,
    decision_json,
    float_views,
    propose,
    realisation_note,
)
from verify.passivity.search.gkyp_sdp import band_certificate
from verify.passivity.search.hamiltonian import nu_minimum

if TYPE_CHECKING:
    from verify.passivity.model import LTIModel

#: states up to which a generalized KYP certificate is sought first (a small SDP)
GKYP_STATES = 20
#: states up to which a band is decided exactly and completely (never inconclusive); at
#: 120 states (2 ports) 1-27 s and under 200 MB (benchmarks/bench_passivity_complete.py)
EXACT_BAND_LIMIT = 120


def parse_band(text: str) -> tuple[Fraction, Fraction]:
    """'W1:W2' as exact rationals with 0 <= W1 < W2; one-line VerifyInputError otherwise."""
    parts = str(text).split(":")
    if len(parts) != 2:
        raise VerifyInputError(f"--band {text!r}: expected W1:W2, e.g. 0:1.5 (rad/s)")
    w1, w2 = (parse_number(part, f"--band {text!r}:", "--band 0:1.5") for part in parts)
    return check_band(w1, w2, f"--band {text!r}")


def check_band(w1: Fraction, w2: Fraction, where: str) -> tuple[Fraction, Fraction]:
    """(w1, w2) if 0 <= w1 < w2 <= 1e12 rad/s; one-line VerifyInputError naming ``where``."""
    if max(abs(w1), abs(w2)) > 10**12:
        raise VerifyInputError(f"{where}: band ends are at most 10^12 rad/s (the "
                               "exact band route's bound); above it, omit --band: the "
                               "full-axis gate covers every frequency")
    if w1 < 0:
        raise VerifyInputError(f"{where}: frequencies must be >= 0 rad/s")
    if w1 >= w2:
        raise VerifyInputError(f"{where}: need W1 < W2")
    return w1, w2


@dataclass
class BandDecision:
    """Verdict on nu(w) >= margin for w in ``band``; fields mirror :class:`Decision`."""

    model: LTIModel
    band: tuple[Fraction, Fraction]
    verdict: GateVerdict
    reason: str
    certificate: BandCertificate | BandFdCertificate | None = None
    witness: Witness | None = None
    nu_min: tuple[float, float] | None = None
    margin: Fraction = Fraction(0)
    seconds: float = 0.0
    note: str = ""  # what a verdict on a non-minimal realisation is about (in the reason)

    def to_json(self) -> dict:
        out = decision_json(self)
        return {**out, "band": [str(self.band[0]), str(self.band[1])]}


def _shifted(em: ExactModel, margin: Fraction) -> ExactModel:
    """H - margin I, exactly."""
    shift = mpq(margin)
    D = [[x - shift if i == j else x for j, x in enumerate(row)] for i, row in enumerate(em.D)]
    return ExactModel(em.A, em.B, em.C, D)


def band_witness(em: ExactModel, omega: float,
                 band: tuple[Fraction, Fraction]) -> Witness | None:
    """An exact frequency witness at a rational w* in [w1, w2] near omega."""
    for limit in (10, 1000, 10**6, 10**12):
        w = min(max(Fraction(omega).limit_denominator(limit), band[0]), band[1])
        found = frequency_witness_at(em, w)
        if found is not None:
            return found
    return None


def _poles_in_band(A: np.ndarray, band: tuple[Fraction, Fraction]) -> list[float]:
    """Frequencies w in the band with jw (numerically) an eigenvalue of A."""
    if A.shape[0] == 0:
        return []
    eig = np.linalg.eigvals(A)
    axis = eig[np.abs(eig.real) <= 1e-9 * np.maximum(1.0, np.abs(eig))]
    return sorted({round(float(abs(x.imag)), 12) for x in axis
                   if float(band[0]) <= abs(x.imag) <= float(band[1])})


def decide_band(model: LTIModel, band: tuple[Fraction, Fraction],
                margin: Fraction = Fraction(0), *, exact_first: bool = True) -> BandDecision:
    """Verdict for H(jw) + H(jw)^H >= 2 margin I on w1 <= w <= w2 (paper, Section 4).

    Parameters
    ----------
    model : LTIModel
        The human model, with its exact rational data.
    band : tuple of Fraction
        ``(w1, w2)`` in rad/s with 0 <= w1 < w2 (as from :func:`parse_band`).
    margin : Fraction, default 0
        nu0 in nu(w) >= nu0 on the band.
    exact_first : bool, default True
        Decide by the exact route (step 2 of the module docstring) before the generalized
        KYP SDP; False tries the SDP first (small models), as a second route to compare.

    Returns
    -------
    BandDecision
        :data:`PASSIVE` on the band with an exactly checked generalized KYP certificate,
        :data:`NOT_PASSIVE` with an exact witness at a rational frequency inside the band,
        or :data:`INCONCLUSIVE` with the reason.

    References
    ----------
    T. Iwasaki and S. Hara, "Generalized KYP lemma: unified frequency domain inequalities
    with design applications", IEEE Trans. Automatic Control 50(1), 2005.
    """
    start = time.perf_counter()
    part = minimal_part(model.exact)  # the exact model, never re-derived from floats
    em = _shifted(part.model, margin)
    A, B, C, D = float_views(em)
    where = f"[{band[0]}, {band[1]}] rad/s"

    def done(verdict, reason, **kw) -> BandDecision:
        note = realisation_note(part)
        return BandDecision(model, band, verdict, reason + note, margin=margin,
                            seconds=time.perf_counter() - start, note=note.lstrip("; "), **kw)

    low = propose(lambda: nu_minimum(A, B, C, D, band=(float(band[0]), float(band[1]))))
    nu_min = (low.omega, low.value) if low is not None and math.isfinite(low.value) else None
    exact_follows = em.n <= EXACT_BAND_LIMIT  # complete: float dips rounding explains skip
    if low is not None and low.value < 0 and (not exact_follows or propose(
            clearly_negative, A, B, C, D, low.omega, default=True)):
        # the minimiser first; then band points, in case it sits next to a pole (where nu
        # tends to -infinity and its rational neighbours hit the pole itself)
        lo, hi = float(band[0]), float(band[1])
        tries = [low.omega, hi, lo, (lo + hi) / 2, *np.geomspace(max(lo, hi * 1e-3), hi, 7)]
        for omega in tries:
            w = propose(band_witness, em, omega, band)
            if w is not None:
                return done(NOT_PASSIVE, f"not passive on {where}: {w.summary}", witness=w,
                            nu_min=nu_min)
    if exact_first and em.n <= EXACT_BAND_LIMIT:  # complete; its certificate is canonical
        decided = _exact(model, em, band, margin, where, nu_min, done)
        if decided.verdict != INCONCLUSIVE or em.n > GKYP_STATES:
            return decided
    found = None
    if em.n <= GKYP_STATES or em.n > EXACT_BAND_LIMIT:
        found = propose(band_certificate, em, A, B, C, D, band)
    if found is not None:
        P, Q, num_margin, label = found
        cert = BandCertificate(model.name, model.source, em, band, P, Q,
                               {"margin": str(margin), "numerical_margin": num_margin,
                                "rounding": label,
                                **{k: v for k, v in model.meta.items()
                                   if isinstance(v, str | int | float | bool)}})
        poles = propose(_poles_in_band, A, band, default=[])
        caveat = "" if not poles else (
            "; H has imaginary-axis poles at ω ≈ " + ", ".join(f"{p:.6g}" for p in poles)
            + " in the band, where H(jω) is undefined: the statement covers the other "
            "frequencies")
        return done(PASSIVE, f"passive on {where}: generalized KYP certificate checked "
                    f"exactly ({label} rounding){caveat}", certificate=cert, nu_min=nu_min)
    if em.n <= EXACT_BAND_LIMIT:
        return _exact(model, em, band, margin, where, nu_min, done)
    smallest = "" if nu_min is None else f"; smallest ν found {nu_min[1]:.3g} at ω = " \
        f"{nu_min[0]:.4g}"
    return done(INCONCLUSIVE, f"on {where}: no exactly checked band certificate (the "
                "rounded solver solution fails the exact check, or none was found) and no "
                f"exact witness{smallest}", nu_min=nu_min)


def _exact(model: LTIModel, em: ExactModel, band: tuple[Fraction, Fraction],
           margin: Fraction, where: str, nu_min, done) -> BandDecision:
    """The complete exact band decision (:mod:`verify.passivity.check.band_fd`)."""
    from verify.passivity.check.band_fd import analyse_band, band_witness, poles_in_band

    an = analyse_band(em, band)
    if not an.passive:
        k, fail = an.failure
        w = band_witness(em, an.polys, k, fail, an.band)
        return done(NOT_PASSIVE, f"not passive on {where}: {w.summary} (decided exactly: "
                    f"E_{k} of the Hermitian part is negative inside the band)", witness=w,
                    nu_min=nu_min)
    poles = poles_in_band(an.polys, an.band)
    caveat = "" if not poles else (
        "; H has imaginary-axis poles at ω ≈ " + ", ".join(
            f"{float((u + v) / 2):.6g}" for u, v in poles)
        + " in the band, where H(jω) is undefined: the statement covers the other "
        "frequencies")
    cert = BandFdCertificate(model.name, model.source, em, band, margin, an)
    return done(PASSIVE, f"passive on {where}: decided exactly by root counting on the band "
                f"(every principal-minor sum of the Hermitian part is >= 0 on it; "
                f"certificate with Descartes breakpoints){caveat}", certificate=cert,
                nu_min=nu_min)


__all__ = ["BandDecision", "band_witness", "check_band", "decide_band", "parse_band"]
