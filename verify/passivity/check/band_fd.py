"""Exact finite-band decision: H(jw) + H(jw)^H >= 0 for w1 <= w <= w2, with a certificate.

The paper's Section 4 gate asks for nu(w) >= 0; on a band [w1, w2] only (``verify gate
--band``) the question is pointwise: the Hermitian part of H(jw) is positive semidefinite
at every w of the band where H(jw) is defined. No stability is implied or needed.

With H = N / d exactly (:func:`verify.passivity.check.frequency_domain.transfer_matrix`),
d = a c split as in :func:`~verify.passivity.check.frequency_domain.axis_split` and Mt the
Hermitian numerator, H(jw) + H(jw)^H = Mt(w) / (rho(w) |c(jw)|^2) at every non-pole w.
When rho divides Mt (Hermitian residues), Mh = Mt / rho and the principal-minor sums
E_k(Mh) decide; otherwise sign(E_k(Mt / rho)) = sign(rho^k E_k(Mt)) and rho^(k mod 2)
E_k(Mt) decides. Either way each sum is divided by the largest power of
gamma = |c(jw)|^2 that divides it (gamma > 0 off the poles), giving F_1, ..., F_m with

    H(jw) + H(jw)^H >= 0 at w  <=>  F_k(w) >= 0 for every k   (w not a pole).

Because the poles in the band are finitely many and the F_k are continuous, "F_k >= 0 on
[w1, w2] minus the poles" is "F_k >= 0 on [w1, w2]": poles inside the band or at its
edges need no special case, and a pole's own frequency is simply not covered by the
statement (H(jw) is not defined there).

F >= 0 on [w1, w2] is decided exactly from F = content * prod g_i^e_i (squarefree
decomposition): the odd-exponent factors must have no root in the open interval
(w1, w2) (proved by Descartes breakpoints, :mod:`verify.passivity.check.interval_roots`)
and content * prod g_i must be positive at one inner rational point. Roots of any factor
at w1 or w2 (a tangency or a sign change at the band's edge) are allowed. When F_k < 0
somewhere inside, a rational w* with F_k(w*) < 0 off the poles is found and an exact vector
v with v^H (H(jw*) + H(jw*)^H) v < 0 is the witness.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any

from flint import fmpq, fmpq_poly

from verify.inputs.numbers import fraction
from verify.passivity.check import qpoly as qp
from verify.passivity.check.certificate import ExactModel, KypCheck
from verify.passivity.check.fd_witness import frequency_vector_witness
from verify.passivity.check.frequency_domain import (
    TransferMatrix,
    axis_split,
    divide_by,
    hermitian_numerator,
    principal_minor_sums,
    reduce_by_square,
    transfer_matrix,
)
from verify.passivity.check.interval_roots import check_no_root, first_root_inside, refine
from verify.passivity.check.witness import Witness

SCHEMA = "verify-band-fd-certificate/1"
_KEYS = {"schema", "name", "source", "fingerprint", "statement", "band", "model", "route",
         "minor_sums", "meta"}


# the polynomials ---------------------------------------------------------------------

@dataclass(frozen=True)
class BandPolynomials:
    """F_1..F_m with sign(F_k(w)) = sign(E_k(H(jw) + H(jw)^H)) off the poles."""

    tm: TransferMatrix
    rho: fmpq_poly  # real polynomial whose roots are the imaginary-axis poles w0
    route: str  # "hermitian": rho divides Mt; "numerator": it does not
    F: list[fmpq_poly]

    def is_pole(self, w: fmpq) -> bool:
        re, im = qp.at_jw(self.tm.d)
        return re(w) == 0 and im(w) == 0


def band_polynomials(model: ExactModel) -> BandPolynomials:
    """The sign polynomials F_k of the Hermitian part of H(jw), exactly (module docstring)."""
    tm = transfer_matrix(model)
    sp = axis_split(tm.d)
    Mt = hermitian_numerator(tm, sp)
    Mh = divide_by(Mt, sp.rho)
    c = qp.at_jw(tm.d / sp.a)
    gamma = c[0] * c[0] + c[1] * c[1]
    route = "hermitian" if Mh is not None else "numerator"
    E = principal_minor_sums(Mh if Mh is not None else Mt)
    F = []
    for k, Ek in enumerate(E, start=1):
        quotient, _ = reduce_by_square(Ek, gamma, k if Mh is None else k - 1)
        F.append(quotient * sp.rho if Mh is None and k % 2 else quotient)
    return BandPolynomials(tm, sp.rho, route, F)


# the sign decision on an interval -------------------------------------------------------

@dataclass(frozen=True)
class IntervalNonnegativity:
    """F = content * prod g^e on [w1, w2]; each odd-exponent g has Descartes breakpoints
    proving it has no root in (w1, w2)."""

    content: fmpq
    factors: list[tuple[fmpq_poly, int, list[fmpq] | None]]

    def to_json(self) -> dict[str, Any]:
        return {"content": str(self.content),
                "factors": [{"poly": qp.coeff_strings(g), "exponent": e,
                             "breakpoints": None if pts is None else [str(t) for t in pts]}
                            for g, e, pts in self.factors]}


@dataclass(frozen=True)
class IntervalFailure:
    """F < 0 somewhere in (w1, w2): ``root`` is an isolating interval (or rational point)
    of a sign change of F inside, or None when F < 0 at every inner non-root."""

    factor: fmpq_poly | None
    root: tuple[fmpq, fmpq] | None


def inner_point(points: list[fmpq]) -> fmpq:
    """The point where a factor's sign is read: the midpoint of its first piece."""
    return (points[0] + points[1]) / 2


def _sign(x) -> int:
    return (x > 0) - (x < 0)


def nonnegative_on(F: fmpq_poly, w1: fmpq, w2: fmpq
                   ) -> IntervalNonnegativity | IntervalFailure:
    """Exactly: F >= 0 on [w1, w2] (with its certificate), or where it fails."""
    if F.is_zero():
        return IntervalNonnegativity(fmpq(0), [])
    content, factors = F.factor_squarefree()
    content = qp.q(content)
    out: list[tuple[fmpq_poly, int, list[fmpq] | None]] = []
    sign = _sign(content)
    for g, e in factors:
        e = int(e)
        if e % 2 == 0:
            out.append((g, e, None))
            continue
        found = first_root_inside(g, w1, w2)
        if found.root is not None:
            return IntervalFailure(g, found.root)
        sign *= _sign(g(inner_point(found.breakpoints)))
        out.append((g, e, found.breakpoints))
    if sign < 0:
        return IntervalFailure(None, None)
    return IntervalNonnegativity(content, out)


def check_interval_nonnegativity(F: fmpq_poly, w1: fmpq, w2: fmpq,
                                 cert: IntervalNonnegativity) -> str | None:
    """None when ``cert`` proves F >= 0 on [w1, w2] exactly, else the reason."""
    if F.is_zero():
        return None if cert.content == 0 and not cert.factors else "F is zero"
    if cert.content == 0:
        return "the content is zero"
    product = fmpq_poly([cert.content])
    sign = _sign(cert.content)
    for g, e, points in cert.factors:
        if e < 1:
            return "a factor has exponent < 1"
        if g.degree() < 1:
            return "a factor is constant"
        if e % 2:
            if points is None:
                return "an odd-exponent factor has no breakpoints"
            problem = check_no_root(g, w1, w2, points)
            if problem is not None:
                return problem
            sign *= _sign(g(inner_point(points)))
        product *= g ** e
    if product != F:
        return "the factorisation does not multiply out to the polynomial"
    if sign <= 0:
        return "the polynomial is negative inside the band"
    return None


# witnesses ------------------------------------------------------------------------------

def negative_points(F: fmpq_poly, fail: IntervalFailure, w1: fmpq, w2: fmpq, is_pole):
    """Rational w in [w1, w2] with F(w) < 0 and not a pole, nearest the failure first."""
    def good(w) -> bool:
        return w1 <= w <= w2 and F(w) < 0 and not is_pole(w)

    if fail.root is None:  # negative at every inner point but finitely many
        for k in range(1, 64):
            for i in range(1, 2 ** k, 2):
                w = w1 + (w2 - w1) * fmpq(i, 2 ** k)
                if good(w):
                    yield w
                    return
        return
    u, v = fail.root
    g = fail.factor
    if u == v:  # a rational root of g: F changes sign there
        for i in range(1, 400):
            delta = (w2 - w1) / fmpq(2) ** i
            for w in (u + delta, u - delta):
                if good(w):
                    yield w
                    return
        return
    for _ in range(400):  # the interval holds one simple root of g: F changes sign in it
        for w in (u, v, (u + v) / 2):
            if good(w):
                yield w
                return
        u, v = refine(g, (u, v), (v - u) / 4)
        if u == v:
            yield from negative_points(F, IntervalFailure(g, (u, u)), w1, w2, is_pole)
            return


def band_witness(model: ExactModel, polys: BandPolynomials, k: int, fail: IntervalFailure,
                 band: tuple[fmpq, fmpq]) -> Witness:
    """The exact vector witness at a rational w* in the band, or the sign fact alone."""
    F = polys.F[k - 1]
    for w in negative_points(F, fail, band[0], band[1], polys.is_pole):
        found = frequency_vector_witness(
            model, w, f"E_{k}(ω*) < 0: the sum of the {k} x {k} principal minors", polys.tm)
        if found is not None:
            return found
    where = "" if fail.root is None else f" (a sign change in [{fail.root[0]}, {fail.root[1]}])"
    return Witness("negative-minor-sum", f"F_{k} < 0 somewhere in the band{where}",
                   {"k": k, "F": qp.coeff_strings(F)})


# the decision ---------------------------------------------------------------------------

@dataclass
class BandAnalysis:
    """The exact band verdict: certificates per k, or the first failing k with a witness."""

    polys: BandPolynomials
    band: tuple[fmpq, fmpq]
    certificates: list[IntervalNonnegativity]
    failure: tuple[int, IntervalFailure] | None = None

    @property
    def passive(self) -> bool:
        return self.failure is None


def analyse_band(model: ExactModel, band: tuple[Fraction, Fraction]) -> BandAnalysis:
    """Every F_k >= 0 on the band (certified), or the first k where it fails."""
    w1, w2 = qp.q(band[0]), qp.q(band[1])
    polys = band_polynomials(model)
    certs = []
    for k, F in enumerate(polys.F, start=1):
        result = nonnegative_on(F, w1, w2)
        if isinstance(result, IntervalFailure):
            return BandAnalysis(polys, (w1, w2), certs, (k, result))
        certs.append(result)
    return BandAnalysis(polys, (w1, w2), certs)


def poles_in_band(polys: BandPolynomials, band: tuple[fmpq, fmpq]) -> list[tuple[fmpq, fmpq]]:
    """Enclosures (u, v) (u == v: exact) of the imaginary-axis poles w0 in [w1, w2]."""
    from verify.passivity.check.interval_roots import roots_inside

    rho = qp.squarefree_part(polys.rho)
    if rho.degree() < 1:
        return []
    w1, w2 = band
    out = [(w, w) for w in (w1,) if rho(w) == 0]
    for u, v in roots_inside(rho, w1, w2):
        out.append(refine(rho, (u, v), (1 + abs(v)) / 2**24) if u != v else (u, v))
    if rho(w2) == 0:
        out.append((w2, w2))
    return out


# the certificate ------------------------------------------------------------------------

def statement(band: tuple[Fraction, Fraction], margin: Fraction) -> str:
    """What a certificate of this schema proves (a function of the claim alone)."""
    bound = "0" if margin == 0 else f"2 nu0 I, nu0 = {margin},"
    return (f"H(jw) + H(jw)^H >= {bound} for {band[0]} <= w <= {band[1]} rad/s wherever "
            "H(jw) is defined, H the given model (the stored model is H - nu0 I): each "
            "principal-minor sum of its Hermitian part, cleared of a denominator positive "
            "off the poles, is >= 0 on the band (odd-multiplicity factors without a root "
            "inside by Descartes' rule on rational breakpoints)")


@dataclass(frozen=True)
class BandFdCertificate:
    """A passive-on-band verdict's exact certificate (``.model`` is H - nu0 I)."""

    name: str
    source: str
    model: ExactModel
    band: tuple[Fraction, Fraction]
    margin: Fraction
    analysis: BandAnalysis

    def to_json(self) -> dict[str, Any]:
        return {"schema": SCHEMA, "name": self.name, "source": self.source,
                "fingerprint": self.model.fingerprint(),
                "statement": statement(self.band, self.margin),
                "band": [str(self.band[0]), str(self.band[1])],
                "model": self.model.to_json(), "route": self.analysis.polys.route,
                "minor_sums": [c.to_json() for c in self.analysis.certificates],
                "meta": {"margin": str(self.margin)}}


def _from_json(item: Any) -> IntervalNonnegativity:
    if not isinstance(item, dict) or set(item) != {"content", "factors"}:
        raise ValueError("malformed minor-sum certificate")
    if not isinstance(item["content"], str) or not isinstance(item["factors"], list):
        raise ValueError("malformed minor-sum certificate")
    factors = []
    for f in item["factors"]:
        if not isinstance(f, dict) or set(f) != {"poly", "exponent", "breakpoints"}:
            raise ValueError("malformed factor")
        e = f["exponent"]
        if not isinstance(e, int) or isinstance(e, bool):
            raise ValueError("a factor exponent is not an integer")
        pts = f["breakpoints"]
        if pts is not None:
            if not isinstance(pts, list) or not all(isinstance(t, str) for t in pts):
                raise ValueError("breakpoints are a list of 'p/q' strings")
            pts = [_rational(t, "breakpoint") for t in pts]
        factors.append((_poly(f["poly"]), e, pts))
    return IntervalNonnegativity(_rational(item["content"], "content"), factors)


def _rational(text: Any, where: str) -> fmpq:
    """A canonical 'p' or 'p/q' (no exponents: bounded work on a hostile file)."""
    from verify.passivity.io.strict_json import rational

    return qp.q(rational(text, where))


def _poly(texts: Any) -> fmpq_poly:
    if not isinstance(texts, list):
        raise ValueError("a polynomial is a list of 'p/q' strings")
    return fmpq_poly([_rational(t, "coefficient") for t in texts])


def check_band_fd_data(data: Any) -> tuple[KypCheck, ExactModel | None, tuple | None]:
    """Exact re-check of a parsed certificate: (result, stored model, band).

    ValueError (one line) when malformed. Everything is re-derived from the stored model:
    the F_k, their factorisations, the Descartes breakpoints, the inner signs.
    """
    from verify.passivity.check.fd_certificate import model_from_json
    from verify.passivity.io.strict_json import fields

    if not isinstance(data, dict) or data.get("schema") != SCHEMA:
        raise ValueError(f"schema is not {SCHEMA}")
    fields(data, required=_KEYS)
    try:
        model = model_from_json(data)
        band_text = data["band"]
        if not isinstance(band_text, list) or len(band_text) != 2 \
                or not all(isinstance(t, str) for t in band_text):
            raise ValueError("band is two 'p/q' strings")
        band = (fraction(_rational(band_text[0], "band")),
                fraction(_rational(band_text[1], "band")))
        meta = data["meta"]
        if not isinstance(meta, dict) or set(meta) != {"margin"} \
                or not isinstance(meta["margin"], str):
            raise ValueError("meta must hold exactly the margin nu0")
        margin = fraction(_rational(meta["margin"], "meta.margin"))
        if not isinstance(data["minor_sums"], list):
            raise ValueError("minor_sums is a list")
        certs = [_from_json(item) for item in data["minor_sums"]]
    except (KeyError, TypeError, ValueError, ZeroDivisionError) as exc:
        raise ValueError(f"malformed certificate ({exc})") from None
    if not 0 <= band[0] < band[1]:
        return KypCheck(False, "the band is not 0 <= w1 < w2"), None, None
    if data["fingerprint"] != model.fingerprint():
        return KypCheck(False, "fingerprint does not match the model data"), None, None
    if data["statement"] != statement(band, margin):
        return KypCheck(False, "statement edited: the statement is not the one this "
                               "certificate proves"), \
            None, None
    polys = band_polynomials(model)
    if data["route"] != polys.route:
        return KypCheck(False, "the stored route differs from the re-derived one"), None, None
    if len(certs) != len(polys.F):
        return KypCheck(False, f"expected {len(polys.F)} minor-sum certificates"), None, None
    w1, w2 = qp.q(band[0]), qp.q(band[1])
    for k, (F, cert) in enumerate(zip(polys.F, certs, strict=True), start=1):
        problem = check_interval_nonnegativity(F, w1, w2, cert)
        if problem is not None:
            return KypCheck(False, f"E_{k}: {problem}"), None, None
    return KypCheck(True, "principal-minor sums re-derived from the stored model; every "
                    "factorisation, Descartes breakpoint list and inner sign re-checked "
                    "exactly"), model, band


def check_band_fd_file(data: dict[str, Any], path: Path) -> KypCheck:
    """Checker of this schema for ``verify certificates check``: the exact facts, then the
    file name and the source binding (:mod:`verify.passivity.io.binding`)."""
    from verify.passivity.io.binding import Claim, bind_source, file_name, shifted
    from verify.passivity.io.strict_json import CertificateFormatError

    try:
        result, model, band = check_band_fd_data(data)
        if not isinstance(data["name"], str) or not isinstance(data["source"], str):
            raise ValueError("name and source must be strings")
    except ValueError as exc:
        raise CertificateFormatError(str(exc)) from None
    if not result.ok:
        return result
    margin = fraction(_rational(data["meta"]["margin"], "meta.margin"))
    given = shifted(model, -margin)
    expected = file_name(data["name"], Claim(margin, band), given.fingerprint())
    if Path(path).name != expected:
        return KypCheck(False, f"file name does not match the content (expected {expected})")
    bound = bind_source(data["name"], data["source"], given, {}, path)
    if bound.error is not None:
        return KypCheck(False, bound.error)
    what = "passive" if margin == 0 else f"ν ≥ {margin}"
    return KypCheck(True, f"{what} on [{band[0]}, {band[1]}] rad/s: {result.reason}; "
                    f"{bound.note}")
