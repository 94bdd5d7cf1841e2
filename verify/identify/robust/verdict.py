"""The robust verdict: passivity of every model in the identification's confidence region.

For the structures with diagonal rational elements and constant off-diagonal elements
(the paper's Section 4 class and its P:Z generalisation), passivity on a band is a set of
polynomial inequalities in (θ, w^2) (:mod:`verify.passivity.check.robust_band`). The
verdict, for every θ in the region (:mod:`verify.identify.model.region`):

* **passive** (proved): a branch-and-bound tree over a rational box enclosing the
  region's image times the frequency piece(s), proposed in floating point
  (:mod:`verify.identify.robust.proof_search`) and checked leaf by leaf in exact arithmetic
  (:func:`verify.identify.robust.band_check.check_leaves`); the certificate is written;
* **not passive** (refuted, for the whole region): one rational frequency w of the band
  and one real direction v with v^T (H_θ(jw) + H_θ(jw)^H) v < 0 for every θ of the
  region, by an interval branch and bound proposed in floating point
  (:mod:`verify.identify.robust.refutation_search`) and checked leaf by leaf in exact arithmetic
  (:mod:`verify.identify.robust.refutation_certificate`); that certificate is written. One
  failing model of the region is never enough: the region may hold passive models too;
* **inconclusive** otherwise: the data cannot decide on that band. The reason names the
  evidence on each side when there is some, both exact: a model of the region that is not
  passive (a rational θ whose membership in the ellipsoid is checked exactly, with the
  gate's exact witness at a rational w: :func:`verify.passivity.band.band_witness`,
  :func:`verify.passivity.check.witness.frequency_witness`) and a passive one (the
  region's centre, with the gate's exact certificate); the largest band on which the
  whole region is proved passive is :func:`largest_band`'s.

All frequencies: for the paper's class the off-diagonal sum c12 + c21 of an identified
model is never exactly 0, while Re h_i(jw) -> 0 as w -> infinity, so
det(H(jw) + H(jw)^H) ~ -(c12 + c21)^2 < 0 at high frequency: almost every identified
model of that class is not passive over all frequencies, and what can hold is passivity
on a band [w1, w_max]. :func:`largest_band` finds the largest w_max the prover proves
(bisection on w_max).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np
from gmpy2 import mpq

from verify.identify.estimate.structure import Structure
from verify.identify.model.model_writer import structure_text
from verify.identify.model.region import Region, half_widths
from verify.identify.robust import band_certificate as rc
from verify.identify.robust import band_check
from verify.identify.robust import refutation_certificate as rfc
from verify.identify.robust.proof_search import Ellipsoid, search, short
from verify.identify.robust.refutation_search import refute_region
from verify.passivity.check import robust_band as rb
from verify.passivity.decision import INCONCLUSIVE, NOT_PASSIVE, PASSIVE, GateVerdict

#: Default number of boxes the search may visit per frequency piece.
MAX_BOXES = 40_000
#: Boxes the region-wide refutation may visit per candidate frequency.
REFUTE_BOXES = 6_000
#: Largest certificate (leaves) the band search keeps.
MAX_BAND_LEAVES = 2_000


@dataclass
class RobustResult:
    """The robust verdict on ``band`` (None: all frequencies), with its evidence."""

    verdict: GateVerdict
    band: tuple[Fraction, Fraction] | None
    reason: str
    certificate: dict[str, Any] | None = None  # robust passivity of the whole region
    theta: list[mpq] | None = None  # a non-passive parameter vector (exact, in the region)
    distance: mpq | None = None  # its (θ - θc)^T Σ^-1 (θ - θc), exactly
    witness: Any = None  # the gate's Witness at θ
    seconds: float = 0.0
    refutation: dict[str, Any] | None = None  # no model of the region is passive
    passive_theta: list[mpq] | None = None  # a passive model of a straddling region
    withdrawn: bool = False  # an answer for the class the larger model contradicts

    @property
    def passed(self) -> bool:
        return self.verdict == PASSIVE

    def where(self) -> str:
        return "at all frequencies" if self.band is None else \
            f"on [{self.band[0]}, {self.band[1]}] rad/s"

    def to_json(self) -> dict[str, Any]:
        return {"verdict": str(self.verdict), "band": None if self.band is None else
                [str(self.band[0]), str(self.band[1])], "reason": self.reason,
                "leaves": None if self.certificate is None else self.certificate["leaves"],
                "theta": None if self.theta is None else [str(x) for x in self.theta],
                "distance": None if self.distance is None else str(self.distance),
                "witness": None if self.witness is None else {
                    "kind": self.witness.kind, "summary": self.witness.summary,
                    **self.witness.data},
                "refutation": None if self.refutation is None else {
                    "frequency": self.refutation["frequency"],
                    "direction": self.refutation["direction"],
                    "leaves": self.refutation["leaves"]},
                "straddles": self.straddles, "withdrawn": self.withdrawn,
                "passive_theta": None if self.passive_theta is None else
                [str(x) for x in self.passive_theta],
                "seconds": round(self.seconds, 4)}

    def headline(self) -> str:
        """The answer in a few words: which of the three, and on what evidence."""
        if self.verdict == PASSIVE:
            return "passive: every model of the region is passive (exact certificate)"
        if self.verdict == NOT_PASSIVE:
            return ("not passive: no model of the region is passive (exact region-wide "
                    "refutation certificate)")
        if self.withdrawn:
            return ("inconclusive: the answer for the fitted class's region is withdrawn "
                    "(the data reject the class, and the larger model contradicts it)")
        if self.straddles:
            return ("inconclusive: the region holds a passive and a non-passive model "
                    "(both exact); the data cannot decide")
        return "inconclusive: neither proved nor refuted for the whole region"

    def files(self, out: Path) -> dict[Path, str]:
        """The region-wide refutation certificate to write into ``out`` (none if absent);
        the proof certificate is written by the caller as before."""
        if self.refutation is None:
            return {}
        return {out / self.refutation_name(): rfc.dumps(self.refutation)}

    def refutation_name(self) -> str | None:
        if self.refutation is None:
            return None
        return rfc.file_name(self.refutation["name"], Fraction(self.refutation["frequency"]),
                             self.refutation["fingerprint"])

    @property
    def straddles(self) -> bool:
        """An inconclusive verdict with a passive and a non-passive model of the region,
        both exact."""
        return self.verdict == INCONCLUSIVE and self.theta is not None \
            and self.passive_theta is not None


def supported(structure: Structure) -> str | None:
    """None if the prover handles the structure, else why not."""
    if not structure.diagonal_with_constant_coupling:
        return (f"structure {structure_text(structure)} not supported: the robust prover "
                "handles diagonal rational elements with constant off-diagonal elements "
                "(paper, P:Z)")
    if structure.poles > 12:
        return "structure not supported: more than 12 poles per element"
    return None


def _shape(structure: Structure) -> rb.Shape:
    return rb.Shape(structure.zeros, structure.poles)


# ------------------------------------------------------------------ proof


def prove(region: Region, structure: Structure, band: tuple[Fraction, Fraction] | None,
          *, name: str, source: str, max_boxes: int = MAX_BOXES,
          hints: list | None = None, max_leaves: int | None = None
          ) -> tuple[dict[str, Any] | None, str]:
    """A checked certificate of robust passivity on ``band``, or (None, why not).

    ``hints``, when given, receives the search's undecided box centres (φ, t) inside the
    region where a condition is negative in floating point (refutation candidates)."""
    shape = _shape(structure)
    phi, cov_phi = rb.reduce_region(region.center, region.covariance)
    r = half_widths(cov_phi, region.chi2)
    S = rb.inverse(cov_phi)
    ellipsoid = Ellipsoid(np.array([float(x) for x in phi]),
                          np.array([[float(x) for x in row] for row in S]), float(region.chi2),
                          np.array([[float(x) for x in row] for row in cov_phi]))
    trees = []
    for variable, t1, t2 in rc.pieces_for(band):
        root = [(c - h, c + h) for c, h in zip(phi, r, strict=True)] + [(t1, t2)]
        found = search(root, variable, shape, ellipsoid, stability=band is None,
                       max_boxes=max_boxes, exact=(cov_phi, phi, region.chi2))
        if found.tree is None:
            if hints is not None:
                hints += [(point, variable) for point, _ in found.candidates]
            what = "w^2" if variable == "x" else "1/w^2"
            return None, f"{found.reason} ({what} in [{t1}, {t2}]){_width_note(phi, r)}"
        trees.append(found.tree)
    data = rc.certificate_json(name, source, structure_text(structure), region, band, r,
                               trees)
    if max_leaves is not None and data["leaves"] > max_leaves:
        return None, f"a proof with {data['leaves']} leaves (more than {max_leaves} asked)"
    refusal = band_check.check_leaves(data, shape, region, band)
    if refusal is not None:
        return None, f"the proposed tree fails the exact check ({refusal})"
    return data, f"{data['leaves']} leaves checked exactly"


def _width_note(phi, r) -> str:
    """Say how wide the enclosing box is when it is wide (the usual cause of a failed
    proof: interval bounds over a large box are coarse)."""
    rel = max((float(h) / abs(float(c)) for c, h in zip(phi, r, strict=True) if c != 0),
              default=0.0)
    if rel < 0.25:
        return ""
    return (f"; the box enclosing the region is coarse: half-widths up to {rel:.0%} of the "
            "parameter values (a wide region: more data or fewer parameters)")


# ------------------------------------------------------------------ refutation


def float_nu(structure: Structure, theta: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """Float nu(w) = lambda_min(H(jw) + H(jw)^H)/2 of the model at θ."""
    per = structure.zeros + 1 + structure.poles
    s = 1j * omega
    re = []
    for i in range(2):
        block = theta[i * per:(i + 1) * per]
        num, den = block[: structure.zeros + 1], np.r_[1.0, block[structure.zeros + 1:]]
        with np.errstate(all="ignore"):
            re.append((np.polyval(num, s) / np.polyval(den, s)).real)
    c = theta[-2] + theta[-1]
    a, d = re
    return (a + d) / 2 - np.sqrt(((a - d) / 2) ** 2 + (c / 2) ** 2)


def _grid(band: tuple[Fraction, Fraction] | None) -> np.ndarray:
    if band is None:
        return np.geomspace(1e-3, 1e5, 600)
    lo, hi = float(band[0]), float(band[1])
    return np.unique(np.r_[np.linspace(lo, hi, 200), np.geomspace(max(lo, hi * 1e-3), hi, 200)])


def candidates(region: Region, structure: Structure,
               band: tuple[Fraction, Fraction] | None, iterations: int = 8
               ) -> list[tuple[np.ndarray, float]]:
    """Float (θ, w) with nu < 0, θ near the ellipsoid's boundary (Frank-Wolfe vertices of
    the linearised nu; untrusted proposals), best first."""
    c = region.float_center()
    cov = region.float_covariance()
    chi2 = float(region.chi2)
    grid = _grid(band)
    theta = c.copy()
    found: list[tuple[np.ndarray, float, float]] = []
    for _ in range(iterations):
        values = float_nu(structure, theta, grid)
        if not np.any(np.isfinite(values)):
            break
        k = int(np.nanargmin(values))
        w, v = float(grid[k]), float(values[k])
        if v < 0:
            found.append((theta.copy(), w, v))
        g = np.zeros_like(theta)
        for j in range(len(theta)):
            h = 1e-6 * max(1.0, abs(theta[j]))
            e = np.zeros_like(theta)
            e[j] = h
            g[j] = (float_nu(structure, theta + e, np.array([w]))[0]
                    - float_nu(structure, theta - e, np.array([w]))[0]) / (2 * h)
        norm = math.sqrt(max(float(g @ cov @ g), 0.0))
        if not math.isfinite(norm) or norm == 0:
            break
        theta = c - 0.999 * math.sqrt(chi2) * (cov @ g) / norm
    found.sort(key=lambda f: f[2])
    return [(t, w) for t, w, _ in found]


def _exact_at(structure: Structure, theta: list[mpq]):
    from verify.passivity.check.realization import minimal_part
    from verify.passivity.model import from_transfer_function

    num, den = structure.transfer_matrix(theta)
    return minimal_part(from_transfer_function(num, den, name="θ").exact).model


def lift(region: Region, point: np.ndarray, variable: str) -> tuple[np.ndarray, float]:
    """(θ, w) from a point (φ, t) of the search: c12 + c21 = φ_c split so that θ is
    nearest the centre in the region's metric (a float proposal)."""
    c = region.float_center()
    S = np.linalg.inv(region.float_covariance())
    theta = np.r_[point[:-2], 0.0, 0.0]
    total = point[-2]
    # q(c12) with c21 = total - c12 is quadratic; its minimiser in closed form
    e = np.zeros_like(c)
    e[-2], e[-1] = 1.0, -1.0
    base = theta.copy()
    base[-1] = total
    d = base - c
    c12 = -float(e @ S @ d) / float(e @ S @ e)
    theta = base + c12 * e
    t = float(point[-1])
    omega = math.sqrt(t) if variable == "x" else (1 / math.sqrt(t) if t > 0 else 1e6)
    return theta, omega


def refute(region: Region, structure: Structure, band: tuple[Fraction, Fraction] | None,
           hints: list | None = None) -> tuple[list[mpq], mpq, Any] | None:
    """(θ, its exact distance, the gate's exact witness) for a non-passive model of the
    region, or None when the search finds none. ``hints`` are (φ, t) points of the
    branch and bound (:func:`prove`), tried after the Frank-Wolfe candidates."""
    from verify.errors import VerifyInputError
    from verify.passivity.band import band_witness
    from verify.passivity.check.witness import frequency_witness, pole_witness

    S = rb.inverse(region.covariance)
    tries = candidates(region, structure, band)
    tries += [lift(region, np.asarray(p, dtype=float), v) for p, v in hints or ()]
    for theta_f, omega in tries:
        theta = [short(float(x)) for x in theta_f]
        q = rb.quadratic_form(S, region.center, theta)
        if q > region.chi2:
            continue
        try:
            em = _exact_at(structure, theta)
        except VerifyInputError:
            continue
        w = band_witness(em, omega, band) if band is not None else \
            frequency_witness(em, omega) or pole_witness(em)
        if w is not None:
            return theta, q, w
    return None


# ------------------------------------------------------------------ verdicts


def robust_verdict(region: Region, structure: Structure,
                   band: tuple[Fraction, Fraction] | None, *, name: str, source: str,
                   nominal: Any = None, max_boxes: int = MAX_BOXES,
                   refute_boxes: int = REFUTE_BOXES) -> RobustResult:
    """The robust verdict on ``band`` (None: all frequencies; module docstring).

    ``nominal`` is the gate's decision on the written model (θ = θc): a not-passive one
    shows at once that no proof of the whole region exists (θc lies in the region), a
    passive one is the passive side of a straddling region. One failing model never
    makes the verdict *not passive*: that needs the region-wide refutation.
    """
    start = time.perf_counter()

    def done(verdict, reason, **kw) -> RobustResult:
        return RobustResult(verdict, band, reason, seconds=time.perf_counter() - start, **kw)

    why = supported(structure)
    if why is not None:
        return done(INCONCLUSIVE, why)
    failing: tuple | None = None
    if nominal is not None and nominal.verdict == NOT_PASSIVE and nominal.witness is not None:
        failing = (list(region.center), mpq(0), nominal.witness)
    else:
        failing = refute(region, structure, band)  # cheap: a float search, one witness
    no_proof = "a model of the region is not passive, so no proof of the whole region exists"
    if failing is None:
        hints: list = []
        cert, no_proof = prove(region, structure, band, name=name, source=source,
                               max_boxes=max_boxes, hints=hints)
        if cert is not None:
            return done(PASSIVE, f"every model of the region is passive {_where(band)}: "
                        f"{no_proof}", certificate=cert)
        failing = refute(region, structure, band, hints) if hints else None
    found = refute_region(region, structure_text(structure), band, name=name,
                          source=source, max_boxes=refute_boxes)
    theta, q, w = failing if failing is not None else (None, None, None)
    if found.certificate is not None:
        return done(NOT_PASSIVE, f"no model of the region is passive {_where(band)}: "
                    f"{found.reason}", refutation=found.certificate, theta=theta,
                    distance=q, witness=w)
    passing = _passing(region, structure, band, nominal)
    sides = []
    if failing is not None:
        sides.append(f"a model inside the region ((θ-θc)ᵀΣ⁻¹(θ-θc) = {float(q):.4g} <= "
                     f"chi2 = {float(region.chi2):.4g}, exact) is not passive: {w.summary}")
    if passing is not None:
        sides.append(passing[1])
    if len(sides) == 2:
        straddle = "the region straddles: " + "; ".join(sides) + ". "
    else:
        straddle = ("; ".join(sides) + ". ") if sides else ""
    return done(INCONCLUSIVE, f"the data cannot decide {_where(band)}: {straddle}"
                f"No proof for the whole region ({no_proof}); no refutation of the whole "
                f"region ({found.reason})", theta=theta, distance=q, witness=w,
                passive_theta=None if passing is None else passing[0])


def _gate_at(structure: Structure, theta: list[mpq], band) -> Any:
    """The gate's exact decision on the model at θ (None if θ gives no model)."""
    from verify.errors import VerifyInputError
    from verify.passivity.band import decide_band
    from verify.passivity.decision import decide
    from verify.passivity.model import from_transfer_function

    num, den = structure.transfer_matrix(list(theta))
    try:
        model = from_transfer_function(num, den, name="θ")
    except VerifyInputError:
        return None
    return decide(model) if band is None else decide_band(model, band)


def _skew_point(region: Region) -> list[mpq]:
    """The point of c12 + c21 = 0 nearest the centre in the region's metric (closed form:
    θc - Σe (eᵀθc)/(eᵀΣe), e summing the couplings; short rationals)."""
    c, cov = region.float_center(), region.float_covariance()
    e = np.zeros_like(c)
    e[-2:] = 1.0
    theta = c - cov @ e * float(e @ c) / float(e @ cov @ e)
    out = [short(float(x)) for x in theta]
    out[-1] = -out[-2]  # exactly skew
    return out


def _passing(region: Region, structure: Structure, band: tuple[Fraction, Fraction] | None,
             nominal: Any) -> tuple[list[mpq], str] | None:
    """A passive model of the region with its exact evidence (the gate's certificate):
    the centre (``nominal`` is the gate's decision on it, made here when not given), else
    the nearest model with c12 = -c21 (for the paper's class the couplings can keep a
    model from passivity only through their sum), when it lies in the region (exactly)."""
    if nominal is None:
        nominal = _gate_at(structure, list(region.center), band)
    if nominal is not None and nominal.verdict == PASSIVE:
        return list(region.center), (f"the region's centre (the written model) is passive "
                                     f"{_where(band)} (the gate's exact certificate: "
                                     f"{nominal.reason})")
    theta = _skew_point(region)
    if not region.contains(theta):
        return None
    decision = _gate_at(structure, theta, band)
    if decision is None or decision.verdict != PASSIVE:
        return None
    q = rb.quadratic_form(rb.inverse(region.covariance), region.center, theta)
    return theta, (f"a model inside the region with c12 = -c21 ((θ-θc)ᵀΣ⁻¹(θ-θc) = "
                   f"{float(q):.4g}, exact) is passive {_where(band)} (the gate's exact "
                   f"certificate: {decision.reason})")


def _where(band) -> str:
    return "at all frequencies" if band is None else f"on [{band[0]}, {band[1]}] rad/s"


def _three_digits(x: float) -> Fraction:
    e = math.floor(math.log10(x)) - 2
    return Fraction(math.floor(x / 10.0**e)) * Fraction(10) ** e


def nominal_crossing(region: Region, structure: Structure, w1: float, cap: float
                     ) -> float:
    """The first frequency above w1 where the nominal nu is negative (float), or cap."""
    grid = np.geomspace(max(w1, cap * 1e-4), cap, 2000)
    values = float_nu(structure, region.float_center(), grid)
    bad = np.nonzero(values < 0)[0]
    return float(grid[bad[0]]) if bad.size else cap


@dataclass
class BandSearch:
    """The largest proved band [w1, w_max] and its certificate (or None)."""

    w1: Fraction
    w_max: Fraction | None
    certificate: dict[str, Any] | None
    tried: list[tuple[str, bool]] = field(default_factory=list)

    def to_json(self) -> dict[str, Any]:
        return {"w1": str(self.w1), "w_max": None if self.w_max is None else str(self.w_max),
                "tried": [{"w_max": w, "proved": ok} for w, ok in self.tried]}


def largest_band(region: Region, structure: Structure, w1: Fraction, cap: float, *,
                 name: str, source: str, steps: int = 7, max_boxes: int = MAX_BOXES,
                 max_leaves: int | None = MAX_BAND_LEAVES) -> BandSearch:
    """Bisection (in log w) for the largest w_max <= cap with robust passivity proved on
    [w1, w_max] by a certificate of at most ``max_leaves`` leaves (near the limit the
    trees grow fast; a slightly smaller band keeps the file small); w_max is rounded down
    to 3 significant digits."""
    out = BandSearch(w1, None, None)
    if supported(structure) is not None:
        return out
    high = min(cap, nominal_crossing(region, structure, float(w1), cap))
    low = max(float(w1), high * 1e-3)
    for k in range(steps + 1):
        trial = high if k == 0 else math.sqrt(low * high)
        w = _three_digits(trial)
        if w <= w1 or (out.w_max is not None and w <= out.w_max):
            break
        cert, _ = prove(region, structure, (w1, w), name=name, source=source,
                        max_boxes=max_boxes, max_leaves=max_leaves)
        out.tried.append((str(w), cert is not None))
        if cert is not None:
            out.w_max, out.certificate = w, cert
            if k == 0:
                break
            low = float(w)
        else:
            high = float(w)
        if high / low < 1.02:
            break
    return out


__all__ = [
    "MAX_BAND_LEAVES",
    "MAX_BOXES",
    "REFUTE_BOXES",
    "BandSearch",
    "RobustResult",
    "candidates",
    "float_nu",
    "largest_band",
    "lift",
    "nominal_crossing",
    "prove",
    "refute",
    "robust_verdict",
    "supported",
]
