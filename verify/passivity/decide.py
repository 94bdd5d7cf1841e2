"""The passivity verdict of a model: passive / not passive / inconclusive (issue 4, item 2).

Order of work: a witness at infinity (D + D^T not PSD) is cheapest; then a KYP
certificate is sought and checked exactly (passive); failing that, witnesses are sought:
a real point of the right half-plane where the Hermitian part of H is negative (cheap
for any n, see :func:`verify.passivity.witness.real_axis_witness`); frequencies where the
smallest eigenvalue nu(w) of (H(jw) + H(jw)^H)/2 is negative, the first candidate being
the minimiser of nu located by Hamiltonian level crossings
(:mod:`verify.passivity.hamiltonian`), which no grid spacing can step over, then a log
sweep with local refinement; and an exact RHP pole or a bad pole at 0 (symbolic, so
last); each confirmed exactly. Up to ``FREQUENCY_DOMAIN_LIMIT`` states whatever is
still open goes to the complete exact frequency-domain decision
(:mod:`verify.passivity.fd_decision`): positive real with a sum-of-squares certificate,
or not with an exact witness. Above it, anything else is inconclusive with the reason. A margin
nu0 asks for nu(w) >= nu0 everywhere, decided as passivity of H - nu0 I (exactly: nu0 is
rational).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

import numpy as np
from gmpy2 import mpq
from scipy.optimize import minimize_scalar

from verify.passivity.certificate import Certificate, ExactModel, exact_model
from verify.passivity.hamiltonian import nu_minimum, nu_values
from verify.passivity.kyp import find_certificate
from verify.passivity.witness import (
    Witness,
    frequency_witness,
    infinity_witness,
    pole_witness,
    real_axis_witness,
)

if TYPE_CHECKING:
    from verify.passivity.fd_certificate import PrCertificate
    from verify.passivity.model import LTIModel

PASSIVE, NOT_PASSIVE, INCONCLUSIVE = "passive", "not passive", "inconclusive"
# states up to which the exact frequency-domain decision (verify.passivity.fd_decision)
# runs when the KYP route and the floating-point witness search both fail
FREQUENCY_DOMAIN_LIMIT = 60


@dataclass
class Decision:
    model: LTIModel
    verdict: str
    reason: str
    certificate: Certificate | PrCertificate | None = None
    witness: Witness | None = None
    nu_min: tuple[float, float] | None = None  # (omega, nu) of the smallest nu found
    margin: Fraction = Fraction(0)
    seconds: float = 0.0

    def to_json(self) -> dict:
        return decision_json(self)



def decision_json(d) -> dict:
    """JSON fields shared by a verdict over all frequencies and over a band (gate output)."""
    return {
        "name": d.model.name,
        "source": d.model.source,
        "verdict": d.verdict,
        "reason": d.reason,
        "margin": str(d.margin),
        "states": d.model.n,
        "ports": d.model.m,
        "witness": None if d.witness is None else {
            "kind": d.witness.kind, "summary": d.witness.summary, **d.witness.data},
        "nu_min": None if d.nu_min is None else {"omega": d.nu_min[0], "nu": d.nu_min[1]},
        "seconds": round(d.seconds, 4),
    }

def nu(model_A, B, C, D, omega: np.ndarray) -> np.ndarray:
    """nu(w) = lambda_min(H(jw) + H(jw)^H)/2 at each frequency (floating point)."""
    return nu_values(model_A, B, C, D, np.asarray(omega, dtype=float))


def candidate_frequencies(A, B, C, D, count: int = 400) -> tuple[list[float], tuple]:
    """Frequencies where nu is smallest: a log sweep around the poles, then refinement."""
    eig = np.abs(np.linalg.eigvals(A)) if A.shape[0] else np.array([1.0])
    eig = eig[eig > 0] if np.any(eig > 0) else np.array([1.0])
    lo, hi = np.log10(eig.min()) - 4, np.log10(eig.max()) + 6
    grid = np.concatenate([[0.0], np.logspace(lo, hi, count)])
    with np.errstate(all="ignore"):
        values = nu(A, B, C, D, grid)
    values = np.where(np.isfinite(values), values, np.inf)
    order = np.argsort(values)[:5]
    found = []
    for k in order:
        w0 = grid[k]
        if w0 > 0:
            res = minimize_scalar(
                lambda x: nu(A, B, C, D, np.array([10.0**x]))[0],
                bounds=(np.log10(w0) - 0.1, np.log10(w0) + 0.1),
                method="bounded",
                options={"xatol": 1e-10},
            )
            if np.isfinite(res.fun) and res.fun < values[k]:
                found.append((float(10.0**res.x), float(res.fun)))
                continue
        found.append((float(w0), float(values[k])))
    found.sort(key=lambda p: p[1])
    # only frequencies where nu is negative in floating point are worth an exact check
    return [w for w, v in found if v < 0], found[0]


def hamiltonian_candidates(A: np.ndarray, B: np.ndarray, C: np.ndarray, D: np.ndarray
                           ) -> tuple[list[float], tuple[float, float] | None]:
    """The minimiser of nu by level crossings, if nu is negative there (floating point)."""
    try:
        with np.errstate(all="ignore"):
            found = nu_minimum(A, B, C, D)
    except (np.linalg.LinAlgError, ValueError):
        return [], None
    if not np.isfinite(found.value) or np.isinf(found.omega):
        return [], None
    return ([found.omega] if found.value < 0 else []), (found.omega, found.value)


def decide(model: LTIModel, margin: Fraction = Fraction(0)) -> Decision:
    """Verdict for passivity of H (or of H - margin I when a margin is asked for)."""
    start = time.perf_counter()
    A, B, C, D = model.A, model.B, model.C, model.D
    em = exact_model(A, B, C, D)
    if margin:  # H - margin I, exactly
        shift = mpq(margin)
        em = ExactModel(em.A, em.B, em.C, [[x - shift if i == j else x for j, x in enumerate(row)]
                                           for i, row in enumerate(em.D)])
        D = D - float(margin) * np.eye(model.m)

    def done(verdict, reason, **kw) -> Decision:
        return Decision(model, verdict, reason, margin=margin,
                        seconds=time.perf_counter() - start, **kw)

    w = infinity_witness(em)
    if w is not None:
        return done(NOT_PASSIVE, w.summary, witness=w)
    search = find_certificate(em, A, B, C, D)
    if search.P is not None:
        cert = Certificate(model.name, model.source, em, search.P,
                           {"margin": str(margin), "numerical_margin": search.margin,
                            **{k: v for k, v in model.meta.items()
                               if isinstance(v, str | int | float | bool)}})
        return done(PASSIVE, f"KYP certificate checked exactly: {search.reason}",
                    certificate=cert)
    w = real_axis_witness(em)  # O(n^2) exact work
    if w is not None:
        return done(NOT_PASSIVE, w.summary, witness=w)
    candidates, best = hamiltonian_candidates(A, B, C, D)
    swept, swept_best = candidate_frequencies(A, B, C, D)
    candidates += [w for w in swept if w not in candidates]
    best = best if best is not None and best[1] <= swept_best[1] else swept_best
    for omega in candidates:
        w = frequency_witness(em, omega)
        if w is not None:
            return done(NOT_PASSIVE, w.summary, witness=w, nu_min=best)
    if model.n <= FREQUENCY_DOMAIN_LIMIT:  # complete and exact: never inconclusive
        from verify.passivity.fd_decision import decide_positive_real

        verdict, reason, cert, w = decide_positive_real(
            em, model.name, model.source, {"margin": str(margin)})
        return done(verdict, reason, certificate=cert, witness=w, nu_min=best)
    # last: the symbolic transfer matrix can take minutes even at n = 8
    w = pole_witness(em)
    if w is not None:
        return done(NOT_PASSIVE, w.summary, witness=w, nu_min=best)
    return done(INCONCLUSIVE, f"no exactly checked certificate or witness ({search.reason}; "
                f"smallest ν found {best[1]:.3g} at ω = {best[0]:.4g})", nu_min=best)
