"""Passivity indices of a human model: IFP nu and OFP rho, with exact bounds (Khalil, Def. 6.3).

Section 4 of the paper uses nu(w) = lambda_min(H(jw) + H(jw)^H)/2 frequency by frequency.
The two classical indices summarise it (Khalil, Nonlinear Systems, Def. 6.3; both
defined here through the KYP LMI with a storage V = x^T P x / 2, P > 0):

* input-feedforward index nu_IFP: the largest nu with u^T y >= nu |u|^2 + dV/dt, i.e.
  H - nu I passive, i.e. P > 0 with M(P) + 2 nu [[0, 0], [0, I]] <= 0;
* output-feedback index rho_OFP: the largest rho with u^T y >= rho |y|^2 + dV/dt, i.e.
  P > 0 with M(P) + 2 rho [C D]^T [C D] <= 0,

where M(P) = [[A^T P + P A, P B - C^T], [B^T P - C, -(D + D^T)]]. For a stable minimal
model nu_IFP = inf_w nu(w) including w -> infinity.

What is exact and what is not:

* ``estimate``: floating point. nu_IFP from the Hamiltonian minimum of nu
  (:mod:`verify.passivity.search.hamiltonian`); rho_OFP from an SDP (cvxpy + Clarabel).
* ``lower``: a rational bound with an exactly checked certificate P. For IFP it is a KYP
  certificate of H - nu_lo I. For OFP, the loop transformation u = u~ + rho y turns
  OFP(rho) of H into passivity of H~ = (I - rho H)^-1 H, realised exactly
  (A + rho B E C, B E', E C, E D), E = (I - rho D)^-1, E' = I + rho D E; the P found
  for H~ is then re-checked exactly in the original LMI above.
* ``upper``: a rational bound with an exact witness: at a rational w* (or w -> infinity)
  and a rational complex z, the LMI gives z^H (H + H^H) z >= 2 nu |z|^2 and
  z^H (H + H^H) z >= 2 rho |H z|^2 (substitute x = (jw I - A)^-1 B z; any P works), so
  the exact Rayleigh quotients bound nu_IFP and rho_OFP from above.

When lower == upper the index is known exactly.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TYPE_CHECKING

import cvxpy as cp
import numpy as np
from gmpy2 import mpq
from scipy.optimize import minimize_scalar

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel, kyp_matrix
from verify.passivity.check.realization import minimal_part
from verify.passivity.check.witness import hermitian_part_at, response_at, simplest_certified
from verify.passivity.decision import float_views, propose
from verify.passivity.search.canonical import coarse_kyp
from verify.passivity.search.hamiltonian import nu_minimum
from verify.passivity.search.kyp import find_certificate

if TYPE_CHECKING:
    from verify.passivity.model import LTIModel


@dataclass(frozen=True)
class IndexBounds:
    """Numerical estimate and exact rational bounds of one index (see module docstring)."""

    kind: str  # "IFP" or "OFP"
    estimate: float | None
    estimate_at: float | None  # frequency of the estimate's minimiser (inf: w -> infinity)
    lower: Fraction | None = None
    upper: Fraction | None = None
    upper_at: str | None = None  # what witnesses the upper bound (a rational w*, ...)
    certificate: ex.RationalMatrix | None = None  # P proving the lower bound
    notes: tuple[str, ...] = field(default_factory=tuple)
    #: the lowest value the search tried, when the upper bound is that value: then the
    #: index is at most it, and nothing below it was looked at
    search_floor: Fraction | None = None

    @property
    def exact(self) -> bool:
        return self.lower is not None and self.lower == self.upper

    @property
    def symbol(self) -> str:
        return "ν_IFP" if self.kind == "IFP" else "ρ_OFP"

    def summary(self) -> str:
        """What is known of the index, in one line: exact facts first, then the estimate.

        A search limit is never shown as a bound: when the only upper bound is the
        lowest value the search tried, the line says the index is at most that value
        and that nothing lower was tried.
        """
        name = self.symbol
        var = "ν" if self.kind == "IFP" else "ρ"
        if self.exact:
            return (f"{name} = {self.lower} exactly (KYP certificate for {self.lower}; "
                    f"exact witness: {self.upper_at})" + self._notes())
        if self.estimate is None:
            est = "no numerical estimate"
        else:
            where = ("ω → ∞" if self.estimate_at is not None and math.isinf(self.estimate_at)
                     else "" if self.estimate_at is None else f"ω ≈ {self.estimate_at:.4g}")
            est = f"≈ {self.estimate:.6g} (numerical{', at ' + where if where else ''})"
        if self.lower is not None and self.upper is not None:
            known = (f"exactly {self.lower} ≤ {name} ≤ {self.upper} (lower: KYP "
                     f"certificate; upper: exact witness, {self.upper_at})")
        elif self.lower is not None:
            known = f"{name} ≥ {self.lower} exactly (KYP certificate); no upper bound found"
        elif self.upper is not None and self.search_floor is not None:
            known = (f"exactly, {self.symbol} ≤ {self.upper} ({self.upper_at}); the search "
                     f"tried no {var} below {self.search_floor}, so {name} may be lower "
                     f"still, or no {var} may work at all")
        elif self.upper is not None:
            known = (f"{name} ≤ {self.upper} exactly (exact witness: {self.upper_at}); "
                     "no certified lower bound")
        else:
            known = "no exact bound found"
        head = f"{name} {est}" if self.estimate is not None else f"{name}: {est}"
        return f"{head}; {known}" + self._notes()

    def _notes(self) -> str:
        return "".join(f"; {note}" for note in self.notes)

    def to_json(self) -> dict:
        return {
            "kind": self.kind,
            "estimate": written_estimate(self.estimate),
            "estimate_at": written_estimate(self.estimate_at),
            "exact": self.exact,
            "lower": None if self.lower is None else str(self.lower),
            "upper": None if self.upper is None else str(self.upper),
            "upper_at": self.upper_at,
            "certificate_P": None if self.certificate is None else ex.to_strings(
                self.certificate),
            "notes": list(self.notes),
            "search_floor": None if self.search_floor is None else str(self.search_floor),
        }


# --------------------------------------------------------------------------- shared pieces


#: Significant digits of the floating-point estimates written to artefacts: far above
#: what a float search resolves reproducibly across BLAS builds, far below its noise.
ESTIMATE_DIGITS = 6


def written_estimate(x: float | None) -> float | None:
    """A float estimate as written: ``ESTIMATE_DIGITS`` significant digits of max(1, |x|),
    so an estimate of 0 that the search found as 3e-10 on one machine and -2e-10 on
    another is written 0.0 on both."""
    if x is None or not math.isfinite(x):
        return x
    if abs(x) < 1:
        return float(f"{x:.{ESTIMATE_DIGITS}f}") + 0.0  # + 0.0: no negative zero
    return float(f"{x:.{ESTIMATE_DIGITS}g}")


def _coarse_ofp(em: ExactModel, loop: ExactModel, P: ex.RationalMatrix,
                rho: Fraction) -> ex.RationalMatrix:
    """The coarsest rounding of an OFP certificate that the OFP check still accepts."""
    candidate = coarse_kyp(loop, P)
    return candidate if check_ofp(em, candidate, rho) else P


def _lower_candidates(estimate: float) -> list[Fraction]:
    """Rationals to certify, best first: a short one at the estimate, then a little below."""
    scale = max(1.0, abs(estimate))
    out = []
    nice = Fraction(estimate).limit_denominator(1000)
    if nice <= Fraction(estimate) + Fraction(1e-6 * scale):  # the exact check decides
        out.append(nice)
    for gap in (1e-6, 1e-4, 1e-2):
        target = Fraction(estimate - gap * scale)
        q = target.limit_denominator(10**6)
        out.append(q if q <= target else target.limit_denominator(10**9))
    return list(dict.fromkeys(out))


def round_up(x: Fraction) -> Fraction:
    """A short rational q >= x within a relative 1e-6 of x (upper bounds stay valid)."""
    tol = Fraction(1, 10**6) * max(1, abs(x))
    for k in (1000, 10**6, 10**9, 10**12):
        for q in (x.limit_denominator(k), Fraction(math.ceil(x * k), k)):
            if x <= q <= x + tol:
                return q
    return x


def _rational_vector(v: np.ndarray, bits: int = 30) -> list[mpq]:
    v = v / np.max(np.abs(v))
    return ex.rationalize([np.concatenate([v.real, v.imag])], bits)[0]


def _frequencies(omega: float) -> list[Fraction | None]:
    """Rational approximations of omega and of two neighbours (for a minimiser next to a
    pole, where H(jw) itself is undefined); None stands for w -> infinity."""
    if math.isinf(omega):
        return [None]
    near = [omega, omega * (1 - 1e-6), omega * (1 + 1e-6)] if omega > 0 else [omega, 1e-6]
    return list(dict.fromkeys(Fraction(w).limit_denominator(k) for w in near
                              for k in (1000, 10**6)))


def _canonical_point(model: LTIModel, em: ExactModel, best: Fraction | None,
                     upper: Fraction | None, rayleigh) -> str | None:
    """Where the upper bound is witnessed, canonical: the simplest rational on the
    Stern-Brocot path to the best point found whose exact Rayleigh quotient is still at
    most the (rounded-up) bound, so float noise in the search does not change the text."""
    if upper is None:
        return None
    if best is None:
        return "ω → ∞"

    def certify(r: Fraction) -> Fraction | None:
        bound = propose(rayleigh, model, em, r)
        return r if bound is not None and bound <= upper else None

    w = abs(best)
    found = simplest_certified(w, certify, reach=w / 10) if w else None
    return f"ω = {found if found is not None else best}"


def _response(em: ExactModel, w: Fraction | None):
    if w is None:
        return em.D, ex.zeros(em.m, em.m)
    return response_at(em, w)


def _herm(em: ExactModel, w: Fraction | None) -> ex.RationalMatrix | None:
    if w is None:
        S = ex.add(em.D, ex.transpose(em.D))
        return ex.block([[S, ex.zeros(em.m, em.m)], [ex.zeros(em.m, em.m), S]])
    return hermitian_part_at(em, w)


def _quadratic(M: ex.RationalMatrix, v: list[mpq]) -> mpq:
    return sum((v[i] * M[i][j] * v[j] for i in range(len(v)) for j in range(len(v))), mpq(0))


def _float_response(model: LTIModel, w: float) -> np.ndarray:
    if math.isinf(w) or model.n == 0:
        return model.D.astype(complex)
    return model.frequency_response(np.array([w]))[0]


# --------------------------------------------------------------------------- IFP


def _shift(em: ExactModel, nu: Fraction) -> ExactModel:
    s = mpq(nu)
    return ExactModel(em.A, em.B, em.C, [[x - s if i == j else x for j, x in enumerate(row)]
                                         for i, row in enumerate(em.D)])


def ifp_index(model: LTIModel) -> IndexBounds:
    """nu_IFP: Hamiltonian estimate, certified lower bound, witnessed upper bound."""
    em = minimal_part(model.exact).model  # the exact model, never re-derived from floats
    A, B, C, D = float_views(em)
    notes = []
    found = propose(nu_minimum, A, B, C, D)  # floats only propose; failure proposes nothing
    estimate = found.value if found is not None and math.isfinite(found.value) else None
    lower, P = None, None
    if estimate is not None:
        for nu in _lower_candidates(estimate):
            search = propose(find_certificate, _shift(em, nu), A, B, C,
                             D - float(nu) * np.eye(model.m))
            if search is not None and search.P is not None:
                lower, P = nu, coarse_kyp(_shift(em, nu), search.P)
                break
        else:
            notes.append("no KYP certificate for H - ν I below the estimate (unstable or "
                         "non-minimal realisation?)")
    upper, best = None, None
    points = [math.inf] + ([found.omega] if estimate is not None and math.isfinite(
        found.omega) else [])
    for omega in points:
        for w in _frequencies(omega):
            bound = propose(_ifp_rayleigh, model, em, w)
            if bound is not None and (upper is None or bound < upper):
                upper, best = bound, w
    upper = None if upper is None else round_up(upper)
    upper_at = _canonical_point(model, em, best, upper, _ifp_rayleigh)
    return IndexBounds("IFP", estimate, found.omega if estimate is not None else None,
                       lower, upper, upper_at, P, tuple(notes))


def _ifp_rayleigh(model: LTIModel, em: ExactModel, w: Fraction | None) -> Fraction | None:
    """z^H (H + H^H) z / (2 |z|^2) at rational w for a rational z near the eigenvector."""
    M = _herm(em, w)
    if M is None:
        return None
    H = _float_response(model, math.inf if w is None else float(w))
    _, V = np.linalg.eigh(H + H.conj().T)
    v = _rational_vector(V[:, 0])
    return Fraction(_quadratic(M, v) / (2 * sum((x * x for x in v), mpq(0))))


# --------------------------------------------------------------------------- OFP


def ofp_matrix(em: ExactModel, P: ex.RationalMatrix, rho: Fraction) -> ex.RationalMatrix:
    """M(P) + 2 rho [C D]^T [C D], exactly."""
    CD = ex.block([[em.C, em.D]]) if em.n else em.D
    return ex.add(kyp_matrix(em, P), ex.scale(2 * mpq(rho), ex.matmul(ex.transpose(CD), CD)))


def check_ofp(em: ExactModel, P: ex.RationalMatrix, rho: Fraction) -> bool:
    """Exact decision of P > 0 and M(P) + 2 rho [C D]^T [C D] <= 0."""
    if em.n and not (ex.is_symmetric(P) and ex.pd_ldl(P).ok):
        return False
    return ex.psd_ldl(ex.scale(-1, ofp_matrix(em, P, rho))).ok


def loop_transform(em: ExactModel, rho: Fraction) -> ExactModel | None:
    """Exact realisation of (I - rho H)^-1 H (module docstring); None if I - rho D is singular."""
    m = em.m
    r = mpq(rho)
    eye = [[mpq(int(i == j)) for j in range(m)] for i in range(m)]
    IrD = ex.to_sympy(ex.add(eye, ex.scale(-r, em.D)), m, m)
    if IrD.det() == 0:
        return None
    E = ex.from_sympy(IrD.inv())
    E2 = ex.add(eye, ex.scale(r, ex.matmul(em.D, E)))
    if not em.n:
        return ExactModel([], [], [[] for _ in range(m)], ex.matmul(E, em.D))
    A = ex.add(em.A, ex.scale(r, ex.matmul(ex.matmul(em.B, E), em.C)))
    return ExactModel(A, ex.matmul(em.B, E2), ex.matmul(E, em.C), ex.matmul(E, em.D))


#: The SDP's range for rho, [-OFP_RANGE, OFP_RANGE]: an estimate at its top end is the
#: range's end, not an estimate of rho_OFP (which may be larger, up to +infinity).
OFP_RANGE = 1e6


def ofp_estimate(A: np.ndarray, B: np.ndarray, C: np.ndarray, D: np.ndarray) -> float | None:
    """max rho with P >= 0 and M(P) + 2 rho [C D]^T [C D] <= 0 (cvxpy + Clarabel); untrusted."""
    n = A.shape[0]
    rho = cp.Variable()
    CD = np.hstack([C, D])
    if n:
        P = cp.Variable((n, n), symmetric=True)
        M = cp.bmat([[A.T @ P + P @ A, P @ B - C.T], [B.T @ P - C, -(D + D.T)]])
        cons = [P >> 0]
    else:
        M, cons = -(D + D.T), []
    lhs = M + 2 * rho * (CD.T @ CD)
    cons += [(lhs + lhs.T) / 2 << 0, rho <= OFP_RANGE, rho >= -OFP_RANGE]
    prob = cp.Problem(cp.Maximize(rho), cons)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            prob.solve(solver=cp.CLARABEL)
    except (cp.error.SolverError, ValueError):
        return None
    if rho.value is None or prob.status != "optimal":
        return None
    return float(rho.value)


def _ofp_ratio(model: LTIModel, w: float) -> tuple[float, np.ndarray] | None:
    """min over z of z^H (H + H^H) z / (2 |H z|^2) at w, with its minimiser (floating point)."""
    try:
        H = _float_response(model, w)
    except ValueError:
        return None
    G = 2 * H.conj().T @ H
    if np.linalg.eigvalsh(G)[0] <= 1e-12 * max(1.0, np.linalg.norm(G)):
        return None
    import scipy.linalg as sla

    vals, vecs = sla.eigh(H + H.conj().T, G)
    return float(vals[0]), vecs[:, 0]


def _ofp_witness_frequency(model: LTIModel) -> float:
    """A frequency where the OFP ratio is smallest (log sweep + refinement; only for the
    upper bound, which is valid at any frequency)."""
    poles = np.abs(np.linalg.eigvals(model.A)) if model.n else np.array([1.0])
    poles = poles[poles > 0] if np.any(poles > 0) else np.array([1.0])
    grid = np.concatenate([[0.0], np.logspace(np.log10(poles.min()) - 3,
                                              np.log10(poles.max()) + 3, 300), [math.inf]])
    values = []
    for w in grid:
        r = _ofp_ratio(model, w)
        values.append(math.inf if r is None else r[0])
    k = int(np.argmin(values))
    w0 = float(grid[k])
    if 0 < w0 < math.inf:
        res = minimize_scalar(lambda x: (_ofp_ratio(model, 10.0**x) or (math.inf,))[0],
                              bounds=(math.log10(w0) - 0.05, math.log10(w0) + 0.05),
                              method="bounded", options={"xatol": 1e-10})
        if math.isfinite(res.fun) and res.fun < values[k]:
            return float(10.0**res.x)
    return w0


def _ofp_rayleigh(model: LTIModel, em: ExactModel, w: Fraction | None) -> Fraction | None:
    """z^H (H + H^H) z / (2 |H z|^2) exactly at rational w for a rational z."""
    r = _ofp_ratio(model, math.inf if w is None else float(w))
    response = _response(em, w)
    if r is None or response is None:
        return None
    v = _rational_vector(r[1])
    m = em.m
    a, b = v[:m], v[m:]
    Hr, Hi = response
    re = [sum((Hr[i][j] * a[j] - Hi[i][j] * b[j] for j in range(m)), mpq(0)) for i in range(m)]
    im = [sum((Hi[i][j] * a[j] + Hr[i][j] * b[j] for j in range(m)), mpq(0)) for i in range(m)]
    gain = sum((x * x for x in re + im), mpq(0))
    if gain == 0:
        return None
    M = _herm(em, w)
    return None if M is None else Fraction(_quadratic(M, v) / (2 * gain))


#: Loop gains tried for an instability witness, most negative first.
LOOP_GAINS = (-10**6, -10**4, -10**3, -10**2, -10, -1)


def unstable_loop(em: ExactModel, upper: Fraction | None) -> tuple[Fraction, str] | None:
    """The most negative rho0 in LOOP_GAINS (below ``upper``) whose loop u = rho0 y has an
    exact right-half-plane pole, with its description; None if there is none.

    OFP(rho) with a storage P > 0 makes the loop u = rho y Lyapunov stable (dV/dt <= 0
    when u~ = 0), and OFP(rho) implies OFP(rho') for rho' < rho; so an unstable loop at
    rho0 refutes OFP(rho) for every rho >= rho0: rho_OFP < rho0. (Small models only: the
    pole is isolated exactly on the loop's transfer matrix.)
    """
    from verify.passivity.check.witness import pole_witness

    for rho0 in LOOP_GAINS:
        if upper is not None and rho0 >= upper:
            break
        loop = loop_transform(em, Fraction(rho0))
        found = None if loop is None else pole_witness(loop)
        if found is not None and found.kind == "unstable-pole":
            return Fraction(rho0), f"the loop u = {rho0}·y has a pole in Re s > 0 (exact " \
                f"root isolation), so OFP(ρ) fails for every ρ ≥ {rho0}"
    return None


def ofp_index(model: LTIModel) -> IndexBounds:
    """rho_OFP: SDP estimate, certified lower bound, witnessed upper bound."""
    em = minimal_part(model.exact).model  # the exact model, never re-derived from floats
    A, B, C, D = float_views(em)
    notes = []
    estimate = propose(ofp_estimate, A, B, C, D)
    lower, P = None, None
    if estimate is not None:
        for rho in _lower_candidates(estimate):
            loop = loop_transform(em, rho)
            if loop is None:
                continue
            search = propose(find_certificate, loop, *float_views(loop))
            if search is not None and search.P is not None and check_ofp(em, search.P, rho):
                lower, P = rho, _coarse_ofp(em, loop, search.P, rho)
                break
        else:
            notes.append("no certificate for OFP(ρ) below the estimate")
        if estimate >= OFP_RANGE * (1 - 1e-6):  # the SDP stopped at its range's end
            notes.append("the SDP reached the top of its range (ρ = 10⁶), so ρ_OFP may be "
                         "larger, up to +∞")
            estimate = None
    else:
        notes.append("the SDP found no feasible ρ in its range [-1000000, 1000000] (with a "
                     "storage P > 0, OFP(ρ) needs the loop u = ρ y to be stable)")
    omega = propose(_ofp_witness_frequency, model, default=math.inf)
    upper, best = None, None
    for w in [None, *_frequencies(omega)]:
        bound = propose(_ofp_rayleigh, model, em, w)
        if bound is not None and (upper is None or bound < upper):
            upper, best = bound, w
    upper = None if upper is None else round_up(upper)
    upper_at = _canonical_point(model, em, best, upper, _ofp_rayleigh)
    floor = None
    if lower is None:
        unstable = propose(unstable_loop, em, upper)
        if unstable is not None:
            upper, upper_at = unstable
            floor = upper if upper == min(LOOP_GAINS) else None
    if estimate is not None and upper is not None and estimate > float(upper) + 1e-6 * max(
            1.0, abs(estimate)):
        notes.append(f"the SDP value {estimate:.6g} exceeds the exact upper bound: discarded "
                     "as inaccurate")
        estimate = None
    return IndexBounds("OFP", estimate, omega if estimate is not None else None, lower,
                       upper, upper_at, P, tuple(notes), floor)


def indices(model: LTIModel) -> tuple[IndexBounds, IndexBounds]:
    """(nu_IFP, rho_OFP) of a model, each with estimate and exact bounds."""
    return ifp_index(model), ofp_index(model)


__all__ = ["IndexBounds", "check_ofp", "ifp_index", "indices", "loop_transform", "ofp_estimate",
           "ofp_index", "ofp_matrix", "round_up", "written_estimate"]
