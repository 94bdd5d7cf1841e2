"""Exact rational sums of squares for univariate polynomials that are >= 0 on R.

A polynomial f with rational coefficients and f(w) >= 0 for all real w is written as

    f = c * g^2 * prod_i f_i        (squarefree decomposition; odd-multiplicity factors f_i)

and each f_i, positive on R, as a weighted sum of squares sum_l c_l p_l(w)^2 with
rational c_l >= 0 and rational polynomials p_l. The search follows the "univsos2"
perturbation-and-absorption algorithm of Magron, Safey El Din and Schweighofer,
"Algorithms for weighted sum of squares decomposition of non-negative univariate
polynomials", J. Symbolic Comput. 93 (2019), Algorithm 2:

1. pick a rational eps > 0 with p - eps * t > 0, t = sum_{i<=d} w^(2i) (deg p = 2d);
2. approximate the roots z_k (Im z_k > 0) of p - eps t and round s = prod (w - z_k) to
   s1 + j s2 with rational coefficients, so p - eps t ~ lc (s1^2 + s2^2);
3. the exact remainder u = p - eps t - lc (s1^2 + s2^2) is absorbed by eps t:
   u_(2i+1) w^(2i+1) = |u_(2i+1)|/2 [(w^(i+1) + sgn w^i)^2 - w^(2i+2) - w^(2i)], and each
   w^(2i) keeps the weight eps + u_(2i) - (|u_(2i+1)| + |u_(2i-1)|)/2, which must be >= 0
   (else the precision is doubled).

Only step 3's identity is trusted: :func:`check_sos` re-expands the squares exactly.
Roots are approximated by arb balls (deterministic at a given precision), so the same
polynomial always yields the same certificate bytes.
"""

from __future__ import annotations

from dataclasses import dataclass

from flint import acb_poly, fmpq, fmpq_poly

from verify.passivity.check import qpoly as qp

Sos = list[tuple[fmpq, fmpq_poly]]  # sum of weight * poly^2, weights >= 0


class SosNotFoundError(RuntimeError):
    """The search gave up (the polynomial may have a real root)."""


def has_real_root(p: fmpq_poly) -> bool:
    """Whether p has a real root: arb's certified root isolation (a real root comes
    with an exactly zero imaginary part), at increasing precision. The answer only
    steers the search: a "no" is confirmed by an exact SOS identity, a "yes" by an
    exact point where a polynomial is negative."""
    return qp.has_real_root(p)


def _positive(p: fmpq_poly) -> bool:
    return p.leading_coefficient() > 0 and not has_real_root(p)


def _round_poly(coeffs, bits: int) -> fmpq_poly:
    out = []
    scale = fmpq(2) ** bits if bits >= 0 else fmpq(1, 2 ** -bits)
    for x in coeffs:
        m = qp.dyadic(x)
        out.append(fmpq(int((m * scale).p // (m * scale).q)) / scale if m != 0 else fmpq(0))
    return fmpq_poly(out)


def sos_positive(p: fmpq_poly, max_rounds: int = 12) -> Sos:
    """A weighted SOS of p > 0 on R (even degree, positive leading coefficient)."""
    d2 = p.degree()
    if d2 < 0 or d2 % 2 or p.leading_coefficient() <= 0:
        raise SosNotFoundError("not a polynomial of even degree with positive leading coefficient")
    if d2 == 0:
        return [(p.leading_coefficient(), qp.ONE)]
    d = d2 // 2
    t = fmpq_poly([1 if k % 2 == 0 else 0 for k in range(d2 + 1)])
    lc = p.leading_coefficient()
    eps = min(lc, abs(p(0)) if p(0) else lc) / 2
    for _ in range(200):
        if _positive(p - eps * t):
            break
        eps /= 4
    else:
        raise SosNotFoundError("no perturbation keeps the polynomial positive")
    pe = p - eps * t
    lce = pe.leading_coefficient()
    bits = 64
    for _ in range(max_rounds):
        roots = qp.approximate_roots(pe, prec=bits + 32)
        upper = [r for r in roots if r.imag > 0]
        if len(upper) != d:
            bits *= 2
            continue
        with qp.precision(bits + 32):
            s = acb_poly.from_roots(upper)
        top = max(int(abs(c).mid().man_exp()[1]) + abs(c).mid().man_exp()[0].bit_length()
                  for c in s.coeffs())  # about log2 of the largest coefficient
        keep = bits - top  # fractional bits: ``bits`` significant bits overall
        s1 = _round_poly([c.real for c in s.coeffs()], keep)
        s2 = _round_poly([c.imag for c in s.coeffs()], keep)
        u = p - eps * t - lce * (s1 * s1 + s2 * s2)
        uc = u.coeffs() + [fmpq(0)] * (d2 + 2 - len(u.coeffs()))
        weights = []
        for i in range(d + 1):
            below = abs(uc[2 * i - 1]) if i > 0 else fmpq(0)
            weights.append(eps + uc[2 * i] - (abs(uc[2 * i + 1]) + below) / 2)
        if all(x >= 0 for x in weights):
            sos: Sos = [(lce, s1), (lce, s2)]
            for i in range(d):
                c = uc[2 * i + 1]
                if c != 0:
                    sgn = 1 if c > 0 else -1
                    sos.append((abs(c) / 2, fmpq_poly([0] * i + [sgn, 1])))
            for i, wt in enumerate(weights):
                if wt != 0:
                    sos.append((wt, fmpq_poly([0] * i + [1])))
            sos = [(w, f) for w, f in sos if w != 0 and not f.is_zero()]
            if not check_sos(p, sos):  # cannot happen; kept as a guard on this module
                raise SosNotFoundError("internal: SOS identity failed")
            return sos
        bits *= 2
    raise SosNotFoundError("precision budget exhausted")


def sos_value(sos: Sos) -> fmpq_poly:
    out = qp.ZERO
    for w, f in sos:
        out += w * f * f
    return out


def check_sos(p: fmpq_poly, sos: Sos) -> bool:
    """Exact: every weight >= 0 and sum w_l p_l^2 == p."""
    return all(w >= 0 for w, _ in sos) and sos_value(sos) == p


@dataclass(frozen=True)
class SturmCount:
    """Positivity of a factor without an SOS: it has no real root and a positive leading
    coefficient, both re-decided exactly by the checker (JSON: ``"sturm"``, the historical
    name; the root count is an exact real-root count,
    :func:`verify.passivity.check.qpoly.count_real_roots`)."""

    def to_json(self) -> str:
        return "sturm"


@dataclass(frozen=True)
class Nonnegativity:
    """f = content * prod factor^exponent, with an SOS (or a Sturm count) for each
    odd-exponent factor."""

    content: fmpq
    factors: list[tuple[fmpq_poly, int, Sos | SturmCount | None]]

    def to_json(self) -> dict:
        return {
            "content": str(self.content),
            "factors": [{"poly": qp.coeff_strings(f), "exponent": e,
                         "sos": None if s is None else s.to_json()
                         if isinstance(s, SturmCount) else [
                             {"weight": str(w), "poly": qp.coeff_strings(g)} for w, g in s]}
                        for f, e, s in self.factors],
        }


def nonnegativity_certificate(f: fmpq_poly) -> Nonnegativity | None:
    """The decomposition of f >= 0 on R, or None when f < 0 somewhere (decided exactly)."""
    if f.is_zero():
        return Nonnegativity(fmpq(0), [])
    content, factors = f.factor_squarefree()
    content = fmpq(content) if not isinstance(content, fmpq) else content
    odd = [g for g, e in factors if e % 2]
    if any(g.leading_coefficient() < 0 for g in odd):  # flint gives monic factors
        odd_sign = -1
    else:
        odd_sign = 1
    if content * odd_sign < 0 or any(has_real_root(g) for g in odd):
        return None
    out = []
    for g, e in factors:
        out.append((g, int(e), _positivity(g) if e % 2 else None))
    return Nonnegativity(content, out)


SOS_DEGREE_LIMIT = 400  # above it, exact root counts (root approximation gets slow)


def _positivity(g: fmpq_poly) -> Sos | SturmCount:
    """An SOS of g > 0, or a :class:`SturmCount` (no real root by an exact count,
    re-counted by the checker) when the SOS search gives up or g is of high degree."""
    if g.degree() <= SOS_DEGREE_LIMIT:
        try:
            return sos_positive(g, max_rounds=6)
        except SosNotFoundError:
            pass
    return SturmCount()


def check_nonnegativity(f: fmpq_poly, cert: Nonnegativity) -> str | None:
    """None when the certificate proves f >= 0 on R exactly, else the reason it fails."""
    if f.is_zero():
        return None if not cert.factors and cert.content == 0 else "f is zero"
    if cert.content <= 0:
        return "the content is not positive"
    product = fmpq_poly([cert.content])
    for g, e, s in cert.factors:
        if e < 1:
            return "a factor has exponent < 1"
        if e % 2:
            if isinstance(s, SturmCount):
                if g.leading_coefficient() <= 0 or qp.count_real_roots(g) != 0:
                    return "an odd-exponent factor is not positive (exact root count)"
            elif s is None or not check_sos(g, s):
                return "an odd-exponent factor lacks a valid sum of squares"
        product *= g ** e
    if product != f:
        return "the factorisation does not multiply out to the polynomial"
    return None


#: Bound on the degree a certificate may ask for: each polynomial, and the product
#: of the factors with their exponents (checked before any power is taken).
MAX_CERTIFICATE_DEGREE = 10_000


def _strict_poly(texts, where: str) -> fmpq_poly:
    """A polynomial of strict rationals (:func:`verify.inputs.numbers.strict_rational`)."""
    from verify.inputs.numbers import strict_rational

    if not isinstance(texts, list):
        raise ValueError(f"{where}: a polynomial is a list of 'p/q' coefficient strings")
    if len(texts) > MAX_CERTIFICATE_DEGREE + 1:
        raise ValueError(f"{where}: degree {len(texts) - 1} above the limit "
                         f"{MAX_CERTIFICATE_DEGREE}")
    return fmpq_poly([qp.q(strict_rational(t, f"{where}[{i}]")) for i, t in enumerate(texts)])


def nonnegativity_from_json(data: dict) -> Nonnegativity:
    """Parse :meth:`Nonnegativity.to_json` (ValueError on malformed data).

    Numbers are strict rationals; exponents are integers >= 1, and the degree of the
    product of the factors is at most ``MAX_CERTIFICATE_DEGREE``, checked here, before
    the checker raises anything to a power.
    """
    from verify.inputs.numbers import strict_rational

    if not isinstance(data, dict) or set(data) != {"content", "factors"}:
        raise ValueError("malformed nonnegativity certificate")
    if not isinstance(data["factors"], list):
        raise ValueError("malformed factors")
    factors = []
    total = 0
    for k, item in enumerate(data["factors"]):
        if not isinstance(item, dict) or set(item) != {"poly", "exponent", "sos"}:
            raise ValueError("malformed factor")
        e = item["exponent"]
        if not isinstance(e, int) or isinstance(e, bool):
            raise ValueError("a factor exponent is not an integer")
        if not 1 <= e <= MAX_CERTIFICATE_DEGREE:
            raise ValueError(f"factors[{k}]: exponent {_brief_int(e)} outside 1.."
                             f"{MAX_CERTIFICATE_DEGREE}")
        poly = _strict_poly(item["poly"], f"factors[{k}].poly")
        total += e * max(poly.degree(), 1)
        if total > MAX_CERTIFICATE_DEGREE:
            raise ValueError(f"factors[{k}]: the product of the factors has degree above "
                             f"the limit {MAX_CERTIFICATE_DEGREE}")
        sos = None
        if item["sos"] == "sturm":
            sos = SturmCount()
        elif item["sos"] is not None:
            if not isinstance(item["sos"], list):
                raise ValueError("malformed sum of squares")
            sos = []
            for term in item["sos"]:
                if not isinstance(term, dict) or set(term) != {"weight", "poly"}:
                    raise ValueError("malformed sum-of-squares term")
                where = f"factors[{k}].sos[{len(sos)}]"
                sos.append((qp.q(strict_rational(term["weight"], f"{where}.weight")),
                            _strict_poly(term["poly"], f"{where}.poly")))
        factors.append((poly, e, sos))
    return Nonnegativity(qp.q(strict_rational(data["content"], "content")), factors)


def _brief_int(e: int) -> str:
    return str(e) if e.bit_length() < 64 else f"of {e.bit_length()} bits"
