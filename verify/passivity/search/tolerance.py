"""Passive within a tolerance: a certified passive model at a stated relative distance.

A model written with rounded numbers can miss passivity by a rounding error although the
model it stands for is passive: a port-Hamiltonian model with C = G^T Q computed in
floating point (C B is not exactly symmetric, so H(jw) + H(jw)^H dips below zero near
w ~ 1e16), or a lossless model whose imaginary-axis poles came out at +1e-16 +- 1.414j.
The exact gate calls both *not passive*, rightly. ``verify gate --tolerance EPS`` asks
instead whether a model within relative distance EPS is certified passive.

The perturbation family. With a, d >= 0,

    H_eps(s) = H(s + a) + d I,   realised by   (A - a I, B, C, D + d I).

It is a natural one: if H is positive real so is H(s + a) (the right half-plane maps into
itself) and adding d I >= 0 keeps it so; the shift moves every pole a to the left (a pole
at +1e-16 +- 1.414j becomes stable), and d > 0 makes D + D^T > 0, which removes the
equality constraint P B = C^T that a non-symmetric C B violates (so no projection of C B
is needed). Only A's diagonal and D's diagonal move; B and C are untouched.

Size. The perturbation is measured in the induced infinity norm (largest absolute row
sum), computed exactly: ||dA|| relative to ||A|| (a frequency scale) and ||dD|| relative
to the gain scale g = max(||D||, ||C|| ||B|| / ||A||); the relative size is the larger of
the two ratios. The model is exact (``LTIModel.exact``) and so is the perturbation: the
moved entries are exactly A - a I and D + d I, and ||dA|| = a, ||dD|| = d. Candidates a, d
are powers of two, from 2^-30 of the budget up to the budget, smallest first; the first
whose perturbed model the exact gate certifies
(:func:`verify.passivity.decision.decide`, its KYP certificate re-checked exactly) is
reported. A model for which none is certified keeps its exact verdict.

References: the shift s -> s + a is the usual passage between positive-real and strictly
positive-real functions (Brogliato, Lozano, Maschke, Egeland, *Dissipative Systems
Analysis and Control*, 3rd ed., Section 2.9).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from verify.inputs.number_text import approx_text, float_or_none
from verify.inputs.numbers import fraction
from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import Certificate, ExactModel, check_kyp
from verify.passivity.decision import Decision, decide, decision_json
from verify.passivity.model import LTIModel
from verify.passivity.search.kyp import KypSearch
from verify.passivity.search.kyp import _balance as kyp_balance
from verify.passivity.search.kyp import reduced_search as kyp_reduced_search
from verify.passivity.verdicts import PASSIVE, PASSIVE_WITHIN

#: fractions of the budget tried, smallest first (powers of two)
_LADDER = (-30, -20, -12, -6, -2, 0)


def _inf_norm(M: ex.RationalMatrix) -> Fraction:
    """Largest absolute row sum, exactly."""
    sums = [sum((abs(fraction(x)) for x in row),
                Fraction(0)) for row in M]
    return max(sums, default=Fraction(0))


@dataclass(frozen=True)
class Perturbation:
    """What moved and by how much (exact rationals); see the module doc."""

    shift: Fraction  # a: A -> A - a I (as applied after rounding: its largest entry)
    feedthrough: Fraction  # d: D -> D + d I (likewise)
    moved_a: Fraction  # ||fl(A - a I) - A||, induced infinity norm
    moved_d: Fraction  # ||fl(D + d I) - D||
    norm_a: Fraction  # ||A||
    gain: Fraction  # g = max(||D||, ||C|| ||B|| / ||A||)
    tolerance: Fraction

    @property
    def relative(self) -> Fraction:
        ra = self.moved_a / self.norm_a if self.norm_a else Fraction(0)
        rd = self.moved_d / self.gain if self.gain else Fraction(0)
        return max(ra, rd)

    def summary(self) -> str:
        moved = " and ".join(
            f"{name} by {approx_text(size, 3)}" for name, size in
            (("A's diagonal", self.moved_a), ("D's diagonal", self.moved_d)) if size)
        size, bound = approx_text(self.relative, 3), approx_text(self.tolerance, 3)
        return (f"H(s + a) + d I ({moved or 'nothing'}): relative size {size} <= {bound} "
                "(induced ∞-norm, relative to ‖A‖ and to the gain scale)")

    def to_json(self) -> dict:
        return {
            "family": "H(s + a) + d I: A -> A - a I, D -> D + d I (B, C unchanged)",
            "moved": ["A (diagonal)", "D (diagonal)"],
            "a": str(self.shift), "d": str(self.feedthrough),
            "norm": "induced infinity norm (largest absolute row sum), exact",
            "delta_A": str(self.moved_a), "delta_D": str(self.moved_d),
            "relative_to": {"A": f"||A|| = {self.norm_a}",
                            "D": f"g = max(||D||, ||C|| ||B|| / ||A||) = {self.gain}"},
            "relative_size": str(self.relative),
            "relative_size_float": float_or_none(self.relative),
            "tolerance": str(self.tolerance),
        }


@dataclass
class ToleranceDecision(Decision):
    """A verdict *passive within tolerance*: ``certificate`` is the perturbed model's."""

    perturbation: Perturbation | None = None
    exact: Decision | None = None  # the verdict on the model as written
    perturbed_model: LTIModel | None = None

    def to_json(self) -> dict:
        out = decision_json(self)
        out["tolerance"] = {
            "perturbation": None if self.perturbation is None else self.perturbation.to_json(),
            "exact_verdict": None if self.exact is None else self.exact.verdict,
            "exact_reason": None if self.exact is None else self.exact.reason,
            "perturbed_certificate": None if self.certificate is None
            else self.certificate.to_json() if hasattr(self.certificate, "to_json")
            else {"model": self.certificate.model.to_json(),
                  "P": ex.to_strings(self.certificate.P)},
        }
        return out


def _power_of_two_below(x: Fraction) -> Fraction:
    """The largest 2^k <= x (x > 0)."""
    k = math.floor(math.log2(x.numerator) - math.log2(x.denominator))
    p = Fraction(2) ** k
    while p > x:
        p /= 2
    while p * 2 <= x:
        p *= 2
    return p


def scales(model: LTIModel) -> tuple[Fraction, Fraction]:
    """(||A||, g) of the module doc, exactly."""
    em = model.exact
    nA, nB, nC, nD = (_inf_norm(x) for x in (em.A, em.B, em.C, em.D))
    gain = max(nD, nC * nB / nA if nA else Fraction(0))
    return nA, gain


def _perturbed(model: LTIModel, a: Fraction, d: Fraction) -> tuple[LTIModel, Fraction,
                                                                   Fraction]:
    """The perturbed model (A - a I, B, C, D + d I), exactly, and the norms of what moved."""
    em = model.exact
    n = em.n
    qa, qd = ex.mpq(a), ex.mpq(d)
    A = [[x - qa if i == j else x for j, x in enumerate(row)] for i, row in enumerate(em.A)]
    D = [[x + qd if i == j else x for j, x in enumerate(row)] for i, row in enumerate(em.D)]
    out = LTIModel(f"{model.name} (perturbed)", source=model.source, meta=model.meta,
                   exact=ExactModel(A, em.B, em.C, D))
    return out, (a if n else Fraction(0)), d


def _symmetrised_output(em: ExactModel) -> ex.RationalMatrix | None:
    """C + dC with N^T (C + dC) B N symmetric (N spans ker(D + D^T)), exactly; None when
    D + D^T > 0 or B N is rank deficient.

    dC = N (N^T N)^-1 X with X = -K (G^T G)^-1 G^T, G = B N and K the skew part of
    N^T C B N: then N^T dC B N = X G = -K. It is the least-squares correction, of the
    size of the rounding that broke the symmetry.
    """
    S = ex.add(em.D, ex.transpose(em.D))
    N = ex.kernel_basis(S)
    if not N or not N[0] or em.n == 0:
        return None
    G = ex.matmul(em.B, N)
    K0 = ex.matmul(ex.matmul(ex.transpose(N), em.C), G)
    K = ex.scale(ex.mpq(1, 2), ex.add(K0, ex.transpose(K0), -1))
    if not any(x for row in K for x in row):
        return em.C
    GtG = ex.to_sympy(ex.matmul(ex.transpose(G), G))
    NtN = ex.to_sympy(ex.matmul(ex.transpose(N), N))
    if GtG.det() == 0:
        return None
    X = ex.scale(-1, ex.matmul(ex.matmul(K, ex.from_sympy(GtG.inv())), ex.transpose(G)))
    dC = ex.matmul(ex.matmul(N, ex.from_sympy(NtN.inv())), X)
    return ex.add(em.C, dC)


def _boundary_certificate(model: LTIModel, perturbed: LTIModel,
                          margin: Fraction) -> Decision | None:
    """A KYP certificate of the perturbed model proposed by its boundary neighbour.

    When d is tiny the perturbed model's KYP problem is nearly singular and floating-point
    Riccati equations fail on it. Its neighbour (A - a I, B, C + dC, D) with the original
    D and C B made symmetric on ker(D + D^T) (see :func:`_symmetrised_output`) is exactly
    the singular problem that :mod:`verify.passivity.search.reduce` parametrises; its certificate
    P meets P B N = (C + dC)^T N exactly, and the remaining mismatch dC is absorbed by the
    d I added to D. P is then checked exactly against the perturbed model itself.
    """
    if margin or model.n == 0:
        return None
    start = time.perf_counter()
    em_p = perturbed.exact
    em_0 = ExactModel(em_p.A, em_p.B, em_p.C, model.exact.D)
    C_sym = _symmetrised_output(em_0)
    if C_sym is None:
        return None
    neighbour = ExactModel(em_0.A, em_0.B, C_sym, em_0.D)
    try:
        found = kyp_reduced_search(neighbour, kyp_balance(perturbed.A))
    except (np.linalg.LinAlgError, ValueError, OverflowError):
        return None
    if not isinstance(found, KypSearch) or found.P is None:
        return None
    check = check_kyp(em_p, found.P)
    if not check.ok:
        return None
    cert = Certificate(perturbed.name, perturbed.source, em_p, found.P,
                       {"margin": "0", "numerical_margin": found.margin})
    return Decision(perturbed, PASSIVE, f"KYP certificate checked exactly: {check.reason} "
                    "(proposed by the boundary neighbour with C B symmetrised on "
                    "ker(D + Dᵀ))", certificate=cert,
                    seconds=time.perf_counter() - start)


def within_tolerance(model: LTIModel, tolerance: Fraction, margin: Fraction,
                     exact: Decision) -> Decision:
    """``exact`` if it is passive or no perturbation within ``tolerance`` is certified,
    else a :class:`ToleranceDecision` (verdict *passive within tolerance*)."""
    if exact.verdict == PASSIVE or tolerance <= 0:
        return exact
    norm_a, gain = scales(model)
    if gain == 0 and norm_a == 0:
        return exact
    for k in _LADDER:
        part = tolerance * Fraction(2) ** k
        a = _power_of_two_below(part * norm_a) if norm_a and model.n else Fraction(0)
        d = _power_of_two_below(part * gain) if gain else Fraction(0)
        try:
            perturbed, dA, dD = _perturbed(model, a, d)
        except OverflowError:
            continue
        p = Perturbation(a, d, dA, dD, norm_a, gain, tolerance)
        if p.relative > tolerance:
            continue
        inner = _boundary_certificate(model, perturbed, margin) or decide(perturbed, margin)
        if inner.verdict == PASSIVE and inner.certificate is not None:
            inner.certificate.meta["perturbation_of"] = {
                "name": model.name, "source": model.source, **p.to_json()}
            return ToleranceDecision(
                model, PASSIVE_WITHIN,
                f"as written the model is {exact.verdict} ({exact.reason}); the perturbed "
                f"model {p.summary()} is passive: {inner.reason}",
                certificate=inner.certificate, witness=exact.witness, nu_min=exact.nu_min,
                margin=margin, seconds=exact.seconds + inner.seconds, perturbation=p,
                exact=exact, perturbed_model=perturbed)
    exact.reason = (f"{exact.reason}; no model H(s + a) + d I within relative distance "
                    f"{approx_text(tolerance, 3)} was certified passive")
    return exact


__all__ = ["PASSIVE_WITHIN", "Perturbation", "ToleranceDecision", "scales",
           "within_tolerance"]
