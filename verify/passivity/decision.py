"""The passivity verdict of a model: passive / not passive / inconclusive.

Everything is decided on the model's exact data (``LTIModel.exact``), reduced to its
exact minimal part (:func:`verify.passivity.check.realization.minimal_part`); a non-minimal
realisation is named in the reason, with what the verdict is then about. Floating-point
views only propose, and a proposal that fails numerically (overflow, subnormals, data
beyond the float range) yields nothing rather than an error.

Order of work: a witness at infinity (D + D^T not PSD) is cheapest; then a KYP
certificate is sought and checked exactly (passive); failing that, witnesses are sought:
a real point of the right half-plane where the Hermitian part of H is negative (cheap
for any n, see :func:`verify.passivity.check.witness.real_axis_witness`); frequencies where the
smallest eigenvalue nu(w) of (H(jw) + H(jw)^H)/2 is negative, the first candidate being
the minimiser of nu located by Hamiltonian level crossings
(:mod:`verify.passivity.search.hamiltonian`), which no grid spacing can step over, then a log
sweep with local refinement; and an exact RHP pole or a bad pole at 0 (symbolic, so
last); each confirmed exactly. Up to ``FREQUENCY_DOMAIN_LIMIT`` states whatever is
still open goes to the complete exact frequency-domain decision
(:mod:`verify.passivity.fd_decision`): positive real with a sum-of-squares certificate,
or not with an exact witness. Above it, anything else is inconclusive with the reason. A margin
nu0 asks for nu(w) >= nu0 everywhere, decided as passivity of H - nu0 I (exactly: nu0 is
rational).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from functools import partial
from typing import TYPE_CHECKING

import numpy as np
from gmpy2 import mpq

from verify.inputs.number_text import short_text
from verify.inputs.numbers import float_view
from verify.passivity.check.certificate import Certificate, ExactModel
from verify.passivity.check.realization import MinimalPart, minimal_part
from verify.passivity.check.witness import (
    Witness,
    frequency_witness,
    infinity_witness,
    pole_witness,
    real_axis_witness,
)
from verify.passivity.rescaled import restore
from verify.passivity.search.hamiltonian import nu_minimum, nu_rounding_bound, nu_values
from verify.passivity.search.kyp import SDP_STATE_LIMIT, find_certificate
from verify.passivity.search.scaling import rescale
from verify.passivity.verdicts import (
    INCONCLUSIVE,
    NOT_PASSIVE,
    PASSIVE,
    GateVerdict,
)
from verify.progress import silent

if TYPE_CHECKING:
    from verify.passivity.check.fd_certificate import PrCertificate
    from verify.passivity.model import LTIModel



# states up to which the exact frequency-domain decision (verify.passivity.fd_decision)
# runs when the KYP route and the floating-point witness search both fail: at 120 states
# (2 ports) about 20-70 s and under 350 MB peak RSS on a loaded 2-core machine
# (benchmarks/bench_passivity_complete.py)
FREQUENCY_DOMAIN_LIMIT = 120


@dataclass
class Decision:
    model: LTIModel
    verdict: GateVerdict
    reason: str
    certificate: Certificate | PrCertificate | None = None
    witness: Witness | None = None
    nu_min: tuple[float, float] | None = None  # (omega, nu) of the smallest nu found
    margin: Fraction = Fraction(0)
    seconds: float = 0.0
    note: str = ""  # what a verdict on a non-minimal realisation is about (in the reason)

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
    from scipy.optimize import minimize_scalar  # imported on use (start-up time)

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


def clearly_negative(A, B, C, D, omega: float, rel: float = 1e-9) -> bool:
    """nu(omega) < -rel ||H(j omega)||_2 in floating point: a dip that rounding cannot
    explain (a lossless H has nu = 0 up to rounding, and its exact checks would only fail).
    """
    n = A.shape[0]
    H = D + (C @ np.linalg.solve(1j * omega * np.eye(n) - A, B) if n else 0)
    value = float(np.linalg.eigvalsh((H + H.conj().T) / 2)[0])
    return bool(value < -rel * float(np.linalg.norm(H, 2)))


#: What a floating-point proposal may raise on extreme data (entries near the float
#: range, subnormals, overflow to inf); the proposal then yields nothing.
FLOAT_FAILURES = (ArithmeticError, ValueError, np.linalg.LinAlgError)


def nu_estimate_text(A, B, C, D, best: tuple[float, float] | None) -> str:
    """The smallest ν estimate for an inconclusive reason: its value only when it stands
    above the rounding error of its own evaluation (:func:`nu_rounding_bound`); a value
    inside it is rounding noise, and the reason says so instead of quoting it."""
    if best is None:
        return "no ν estimate"
    omega, value = best
    bound = propose(nu_rounding_bound, A, B, C, D, omega, default=math.inf)
    if abs(value) <= bound:
        return (f"the smallest ν found, at ω ≈ {omega:.4g}, is within the rounding error of "
                f"its floating-point evaluation (bound {bound:.1e}): no sign can be read "
                "from it")
    return f"smallest ν found {value:.3g} at ω = {omega:.4g}"


def propose(fn, *args, default=None):
    """fn(*args) from the untrusted float route, or ``default`` if it fails numerically."""
    try:
        with np.errstate(all="ignore"):
            return fn(*args)
    except FLOAT_FAILURES:
        return default


def shifted(em: ExactModel, margin: Fraction) -> ExactModel:
    """H - margin I, exactly."""
    if not margin:
        return em
    shift = mpq(margin)
    return ExactModel(em.A, em.B, em.C, [[x - shift if i == j else x for j, x in enumerate(row)]
                                         for i, row in enumerate(em.D)])


def float_views(em: ExactModel) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Float (A, B, C, D) of an exact model: nearest floats, +-inf beyond the range."""
    n, m = em.n, em.m
    return (float_view(em.A, n, n), float_view(em.B, n, m), float_view(em.C, m, n),
            float_view(em.D, m, m))


def realisation_note(part: MinimalPart) -> str:
    """What a verdict on a non-minimal realisation is about (empty when it is minimal).

    Passivity of the transfer function (positive realness) depends only on the minimal
    part; a KYP storage x^T P x / 2 with P > 0 on the given state needs A^T P + P A <= 0,
    hence no hidden mode in Re s > 0, so it is not what a certificate then proves.
    """
    if not part.hidden:
        return ""
    text = (f"; {part.summary()}; decided: positive realness of the transfer function "
            f"H(s), on its exact minimal realisation ({part.model.n} state(s)), where a "
            "certificate's storage lives")
    if part.hidden_rhp:
        text += ("; not on the given state: with a hidden mode in Re s > 0, no P > 0 on it "
                 "satisfies the KYP inequality")
    elif part.hidden_axis:
        text += "; a hidden mode lies on the imaginary axis"
    return text


def decide(model: LTIModel, margin: Fraction = Fraction(0), *,
           stage: Callable[[str], None] = silent) -> Decision:
    """Verdict for passivity of H (or of H - margin I when a margin is asked for).

    The exact model is ``model.exact`` reduced to its exact minimal part (the transfer
    function's realisation); floats are views of it and only propose.

    Parameters
    ----------
    model : LTIModel
        The human model H(s) = C (sI - A)^-1 B + D, with its exact rational data.
    margin : Fraction, default 0
        nu0 in nu(w) >= nu0 for every w, decided exactly as passivity of H - nu0 I.
    stage : callable, optional
        Told each route as it starts (progress lines of ``verify gate``).

    Returns
    -------
    Decision
        ``verdict`` is :data:`PASSIVE` with an exactly checked KYP or positive-real
        certificate, :data:`NOT_PASSIVE` with an exactly checked witness, or
        :data:`INCONCLUSIVE` with the reason; ``nu_min`` is the smallest nu(w) seen
        (floating point, informative only).

    References
    ----------
    The paper, Section 4 (nu(w) and passivity of the human model). KYP (positive real)
    lemma: B. D. O. Anderson and S. Vongpanitlerd, *Network Analysis and Synthesis*,
    Prentice-Hall 1973, Ch. 5; H. K. Khalil, *Nonlinear Systems*, 3rd ed., Lemma 6.2.
    """
    start = time.perf_counter()
    stage(f"{model.name}: exact minimal realisation")
    part = minimal_part(model.exact)
    note = realisation_note(part)
    em = shifted(part.model, margin)

    def done(verdict, reason, **kw) -> Decision:
        if margin and verdict == NOT_PASSIVE and not reason.startswith("H − νI"):
            reason = f"H − νI is not passive for ν = {short_text(margin)} (evidence for " \
                f"H − νI, whose feedthrough is D − νI): {reason}"
        return Decision(model, verdict, reason + note, margin=margin,
                        seconds=time.perf_counter() - start, note=note.lstrip("; "), **kw)

    w = infinity_witness(em, margin=margin)  # exact on the model as written, at any scale
    if w is not None:
        return done(NOT_PASSIVE, w.summary, witness=w)
    rescaled = rescale(part.model, margin)  # far from 1: decide H(beta s)/alpha instead
    if rescaled is not None:
        inner = decide(rescaled.model, margin / rescaled.alpha, stage=stage)
        out = restore(inner, rescaled, model, em, margin)
        out.reason += note if note not in out.reason else ""
        out.note = note.lstrip("; ")
        out.seconds = time.perf_counter() - start
        return out
    A, B, C, D = float_views(em)
    # between the SDP's limit and the complete route's, a frugal search (the exact route
    # follows): no costly exact check of a candidate that floating point already rejects
    frugal = SDP_STATE_LIMIT < em.n <= FREQUENCY_DOMAIN_LIMIT
    stage(f"{model.name}: searching a KYP certificate ({em.n} states)")
    search = propose(partial(find_certificate, frugal=True) if frugal else find_certificate,
                     em, A, B, C, D)
    if search is not None and search.P is not None:
        cert = Certificate(model.name, model.source, em, search.P,
                           {"margin": str(margin), "numerical_margin": search.margin,
                            **{k: v for k, v in model.meta.items()
                               if isinstance(v, str | int | float | bool)}})
        return done(PASSIVE, f"KYP certificate checked exactly: {search.reason}",
                    certificate=cert)
    search_reason = "the floating-point search failed on this data" if search is None \
        else search.reason
    stage(f"{model.name}: searching a witness (real axis, then frequencies)")
    w = propose(real_axis_witness, em)  # O(n^2) exact work
    if w is not None:
        return done(NOT_PASSIVE, w.summary, witness=w)
    candidates, best = propose(hamiltonian_candidates, A, B, C, D, default=([], None))
    swept, swept_best = propose(candidate_frequencies, A, B, C, D, default=([], None))
    candidates += [w for w in swept if w not in candidates]
    if best is None or (swept_best is not None and swept_best[1] < best[1]):
        best = swept_best
    if best is not None and not (np.isfinite(best[0]) and np.isfinite(best[1])):
        best = None
    if em.n <= FREQUENCY_DOMAIN_LIMIT:  # the exact route follows and is complete
        candidates = [w for w in candidates if propose(clearly_negative, A, B, C, D, w,
                                                        default=True)]
    for omega in candidates:
        w = propose(frequency_witness, em, omega)
        if w is not None:
            return done(NOT_PASSIVE, w.summary, witness=w, nu_min=best)
    if em.n <= FREQUENCY_DOMAIN_LIMIT:  # complete and exact: never inconclusive
        from verify.passivity.fd_decision import decide_positive_real

        stage(f"{model.name}: the complete exact frequency-domain decision (about a minute "
              "at 120 states)")
        verdict, reason, cert, w = decide_positive_real(
            em, model.name, model.source, {"margin": str(margin)})
        return done(verdict, reason, certificate=cert, witness=w, nu_min=best)
    # last: the symbolic transfer matrix can take minutes even at n = 8
    w = propose(pole_witness, em)
    if w is not None:
        return done(NOT_PASSIVE, w.summary, witness=w, nu_min=best)
    smallest = nu_estimate_text(A, B, C, D, best)
    return done(INCONCLUSIVE, f"no exactly checked certificate or witness ({search_reason}; "
                f"{smallest})", nu_min=best)
