"""Witnesses of non-passivity (paper, Section 4: nu(w) < 0), each checked in exact arithmetic.

- at infinity: a rational v with v^T (D + D^T) v < 0, so H(jw) + H(jw)^H has a negative
  eigenvalue for all large w;
- at a frequency: a rational w* and a rational complex vector v = a + jb with
  v^H (H(jw*) + H(jw*)^H) v < 0, H(jw*) computed exactly over Q(j) from one real
  n x n integer system (A^2 + w*^2 I) Y = B solved by FLINT (see :func:`response_at`);
  w* is a short rational near the floating-point minimiser of nu, and v the rounded
  eigenvector of its smallest eigenvalue: no symbolic system is formed;
- at a real point s* > 0 of the right half-plane: a rational v in ker(D + D^T) with
  v^T (H(s*) + H(s*)^T) v < 0, where H(s*) v is not solved exactly but bounded: a rounded
  solution x of (s* I - A) x = B v leaves an exact residual r, and Gershgorin's theorem
  on the symmetric part of s* I - A gives mu > 0 with |(s* I - A)^-1| <= 1/mu, so
  |v^T C (s* I - A)^-1 B v - v^T C x| <= |C^T v| |r| / mu (O(n^2) exact work, for any n).
  It catches N^T C B N with a negative eigenvalue (N spans ker(D + D^T)): H(s) ~ D + C B/s
  at large s;
- a pole in the open right half-plane, or a pole of H at s = 0 that is not simple with a
  positive semidefinite residue: from the exact transfer matrix (sympy, small models),
  with the pole isolated by exact complex root isolation.

A positive-real H is analytic in Re s > 0, has H(s) + H(s)^H >= 0 there and
H(jw) + H(jw)^H >= 0 where defined, and only simple imaginary-axis poles with PSD
residues, so each witness refutes passivity. (For the right half-plane point directly:
a KYP certificate P gives u^H (H(s) + H(s)^H) u >= 2 Re(s) x^H P x >= 0 with
x = (sI - A)^-1 B u.)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TypeVar

import flint
import gmpy2
import numpy as np
from gmpy2 import mpq

from verify.inputs.number_text import approx_text, float_or_none, short_text
from verify.passivity.check import exact as ex
from verify.passivity.check import intmat
from verify.passivity.check.certificate import ExactModel


@dataclass
class Witness:
    kind: str  # "infinity", "rhp-point", "frequency", "unstable-pole", "pole-at-zero"
    summary: str
    data: dict = field(default_factory=dict)


def _quadratic(M: ex.RationalMatrix, v: list[mpq]) -> mpq:
    return sum((v[i] * M[i][j] * v[j] for i in range(len(v)) for j in range(len(v))), mpq(0))


def negative_direction(M: ex.RationalMatrix) -> tuple[list[mpq], mpq] | None:
    """A rational v with v^T M v < 0 (exact), from the float eigenvector; None if none found."""
    # a float copy of c M (c a power of two, same signs) proposes v, whatever the entries
    F = intmat.to_float(intmat.normalised(intmat.from_rational(M)))
    w, V = np.linalg.eigh((F + F.T) / 2)
    if w[0] >= 0:
        # the float eigenvalue may miss a tiny negative one; LDL decides below
        if ex.psd_ldl(M).ok:
            return None
    v = V[:, 0] / np.max(np.abs(V[:, 0]))
    for bits in (8, 16, 32, 53, 80):
        (q,) = ex.rationalize([v], bits)
        value = _quadratic(M, q)
        if value < 0:
            return q, value
    return None


def infinity_witness(model: ExactModel, *, margin: Fraction = Fraction(0)) -> Witness | None:
    """A rational v with vᵀ(D + Dᵀ)v < 0 for the model decided (paper, Section 4: H passive
    needs H(jω) + H(jω)ᴴ ⪰ 0 as ω → ∞, where H(jω) → D).

    With a margin ν the model decided is H − νI (``model`` is already shifted, its
    feedthrough is D − νI), and the message says so in terms of the model as given:
    D + Dᵀ − 2νI not PSD, i.e. ν(ω) < ν as ω → ∞.
    """
    S = ex.add(model.D, ex.transpose(model.D))
    found = negative_direction(S)
    if found is None:
        return None
    v, value = found
    exact = str(value)  # an exact rational: written as such when it is short
    shown = exact if len(exact) <= 24 else f"{gmpy2.mpfr(value):.3g} (rounded; exact in data)"
    shown_v = "(" + ", ".join(str(x) for x in v) + ")"  # a vector, not a Python list
    if margin:
        nu = short_text(margin)
        summary = (f"H − νI is not passive for ν = {nu}: D + Dᵀ − 2νI is not PSD, "
                   f"vᵀ(D + Dᵀ − 2νI)v = {shown} < 0 at v = {shown_v}, so "
                   "λmin(H(jω) + H(jω)ᴴ)/2 < ν as ω → ∞")
    else:
        summary = (f"D + Dᵀ is not PSD: vᵀ(D + Dᵀ)v = {shown} < 0 at v = {shown_v}, so "
                   "H(jω) + H(jω)ᴴ has a negative eigenvalue as ω → ∞")
    return Witness("infinity", summary, {"v": [str(x) for x in v], "value": exact})


def response_at(model: ExactModel, omega: Fraction) -> tuple[ex.RationalMatrix,
                                                             ex.RationalMatrix] | None:
    """(Re H(jw), Im H(jw)) exactly, for rational w; None when jw is a pole.

    (jw I - A)(-jw I - A) = A^2 + w^2 I, so (jw I - A)^-1 B = -(A + jw I) Y with
    (A^2 + w^2 I) Y = B: one real n x n system instead of the 2n x 2n real form of the
    complex one. Over a common denominator (A = Za/da, w = p/q) it is the integer system
    (q^2 Za^2 + p^2 da^2 I) Y' = Zb, solved exactly by FLINT (:mod:`verify.passivity.check.intmat`).
    A^2 + w^2 I is singular exactly when jw (or -jw, the same for real A) is an eigenvalue
    of A.
    """
    n, m = model.n, model.m
    w = Fraction(omega)
    if not n:
        return model.D, ex.zeros(m, m)
    a = intmat.from_rational(model.A)
    b = intmat.from_rational(model.B)
    Za, Zb = intmat.to_fmpz_mat(a), intmat.to_fmpz_mat(b)
    p, q, da, db = w.numerator, w.denominator, int(a.d), int(b.d)
    if p == 0:  # A Y = -B directly: a smaller system
        K, rhs_scale = Za, flint.fmpq(-da, db)  # Y = -(da/db) Za^-1 Zb
    else:
        K = Za * Za * (q * q)
        shift = p * p * da * da
        for i in range(n):
            K[i, i] += shift
        rhs_scale = flint.fmpq(q * q * da * da, db)  # Y = q^2 da^2 / db K^-1 Zb
    try:
        Y = K.solve(Zb) * rhs_scale
    except ZeroDivisionError:  # singular: jw is an eigenvalue of A
        return None
    C = intmat.rational_to_fmpq(model.C, n)
    if p == 0:  # X = Y, real
        Hr = C * Y
        return ex.add(intmat.fmpq_to_rational(Hr), model.D), ex.zeros(m, m)
    A = intmat.rational_to_fmpq(model.A, n)
    CY = C * Y
    Hr = -(C * (A * Y))
    Hi = CY * flint.fmpq(-p, q)
    return ex.add(intmat.fmpq_to_rational(Hr), model.D), intmat.fmpq_to_rational(Hi)


def hermitian_part_at(model: ExactModel, omega: Fraction) -> ex.RationalMatrix | None:
    """Real 2m x 2m form [[Re, -Im], [Im, Re]] of H(jw) + H(jw)^H, exactly; None at a pole."""
    response = response_at(model, omega)
    if response is None:
        return None
    Hr, Hi = response
    Pr = ex.add(Hr, ex.transpose(Hr))
    Pi = ex.add(Hi, ex.transpose(Hi), -1)
    return ex.block([[Pr, ex.scale(-1, Pi)], [Pi, Pr]])


#: above this many states a verified float solve is tried before the exact one
BOUND_FROM_STATES = 60


def _bounded_witness(model: ExactModel, w: Fraction) -> Witness | None:
    """The witness at w proved by :mod:`verify.passivity.check.witness_bound` (no exact solve)."""
    from verify.passivity.check.witness_bound import bounded_form, float_direction

    A, B, C, D = (intmat.to_float(intmat.from_rational(x))
                  for x in (model.A, model.B, model.C, model.D))
    if not all(np.all(np.isfinite(x)) for x in (A, B, C, D)):
        return None
    wf = float_or_none(w)
    if wf is None:  # beyond the float range: the exact route decides
        return None
    proposal = float_direction(A, B, C, D, wf)
    if proposal is None:
        return None
    a, b = proposal
    bound = bounded_form(model, w, a, b)
    if bound is None or bound >= 0:
        return None
    return Witness(
        "frequency",
        f"at ω* = {w} (≈ {approx_text(w)} rad/s), vᴴ(H(jω*) + H(jω*)ᴴ)v ≤ "
        f"{_rounded_up(bound)} (the exact bound rounded up) < 0 for an exact rational "
        "vector v = a + jb (exact bound of a verified floating-point solve)",
        {"omega": str(w), "a": [str(x) for x in a], "b": [str(x) for x in b],
         "value_bound": str(bound), "method": "verified solve (Neumann bound)"},
    )


def _rounded_up(x: object, digits: int = 3) -> str:
    """The exact rational ``x`` rounded up to ``digits`` significant digits, so that a
    written upper bound stays an upper bound (integers only: any size, no float)."""
    q = Fraction(str(x))
    if q == 0:
        return "0"
    num, den = abs(q.numerator), q.denominator
    e = len(str(num)) - len(str(den))  # within 1 of log10|q|
    while Fraction(num, den) >= Fraction(10) ** e:
        e += 1
    while Fraction(num, den) < Fraction(10) ** (e - 1):
        e -= 1
    step = Fraction(10) ** (e - digits)  # 10^(e-1) <= |q| < 10^e
    rounded = -((-q) // step) * step  # the ceiling of q on the grid of step
    return approx_text(rounded, digits + 1)


def frequency_witness_at(model: ExactModel, w: Fraction) -> Witness | None:
    """Exact check of a negative eigenvalue of H(jw) + H(jw)^H at the rational w itself.

    Above :data:`BOUND_FROM_STATES` states a bound from a verified float solve is tried
    first (O(n^3) integer work, :mod:`verify.passivity.check.witness_bound`); the exact H(jw)
    of :func:`response_at` decides when it does not apply.
    """
    if model.n > BOUND_FROM_STATES:
        found = _bounded_witness(model, w)
        if found is not None:
            return found
    M = hermitian_part_at(model, w)
    if M is None:
        return None
    found = negative_direction(M)
    if found is None:
        return None
    v, value = found
    return vector_witness(w, approx_text(w), f"{gmpy2.mpfr(value):.3g}", v, value, model.m)


def vector_witness(w: object, approx: str, shown_value: str, v: list, value: object,
                   m: int, note: str = "") -> Witness:
    """The frequency witness record: v = a + jb with vᴴ(H(jω*) + H(jω*)ᴴ)v = value < 0.

    ``w`` and ``value`` are exact rationals (printed as they print), ``approx`` and
    ``shown_value`` their readable forms (text, so that an ω* beyond the float range,
    such as 10^1500, is shown, never converted to a float); ``note`` says how ω* was
    found.
    """
    how = f" ({note})" if note else ""
    exact = str(value)  # an exact rational: written as such when it is short
    shown = exact if len(exact) <= 24 else f"{shown_value} (rounded; exact in the data)"
    return Witness(
        "frequency",
        f"at ω* = {w} (≈ {approx} rad/s), vᴴ(H(jω*) + H(jω*)ᴴ)v = "
        f"{shown} < 0 for an exact rational vector v = a + jb{how}",
        {"omega": str(w), "a": [str(x) for x in v[:m]],
         "b": [str(x) for x in v[m:]], "value": str(value)},
    )


T = TypeVar("T")

#: The canonical witness looks at most this far (relative) from the float frequency.
CANONICAL_REACH = Fraction(1, 10)
#: and makes at most this many exact checks before the plain rounding of omega.
CANONICAL_CHECKS = 48


def _continued_fraction(x: Fraction) -> list[int]:
    """The partial quotients of x >= 0 (finite: x is rational)."""
    terms = []
    p, q = x.numerator, x.denominator
    while q:
        a, r = divmod(p, q)
        terms.append(a)
        p, q = q, r
    return terms


def simplest_certified(x: Fraction, certify: Callable[[Fraction], T | None], *,
                       reach: Fraction, max_checks: int = CANONICAL_CHECKS) -> T | None:
    """The first rational on the Stern-Brocot path to ``x >= 0`` (within ``reach`` of it)
    that ``certify`` accepts, with what it returned; None after ``max_checks`` calls.

    The path is walked one run of semiconvergents (p' + j p)/(q' + j q), j = 1..a, per
    partial quotient a. Within a run the last node (a convergent) is tried first; when it
    is accepted, the first accepted node of the run is found by bisection over j (the
    accepted set is taken to be an interval around x). If J is an interval of accepted
    points around x, the simplest rational of J is a Stern-Brocot ancestor of every point
    of J, so the walk towards any x' in J (x plus float noise) stops at the same rational.
    """
    checks = 0

    def tried(r: Fraction) -> T | None:
        nonlocal checks
        if abs(r - x) > reach:
            return None
        checks += 1
        return certify(r)

    p2, q2, p1, q1 = 0, 1, 1, 0  # the two previous convergents
    for a in _continued_fraction(x):
        def node(j: int, p2=p2, q2=q2, p1=p1, q1=q1) -> Fraction:
            return Fraction(p2 + j * p1, q2 + j * q1)

        if a > 0:
            found = tried(node(a))
            if found is not None:
                lo, hi = 1, a  # node(hi) is accepted; find the first such j
                while lo < hi and checks < max_checks:
                    mid = (lo + hi) // 2
                    at_mid = tried(node(mid))
                    if at_mid is not None:
                        hi, found = mid, at_mid
                    else:
                        lo = mid + 1
                return found
        if checks >= max_checks:
            return None
        p2, q2, p1, q1 = p1, q1, p2 + a * p1, q2 + a * q1
    return None


def canonical_frequency_witness(model: ExactModel, omega: float) -> Witness | None:
    """The witness at the simplest rational on the way to ``omega`` that the exact check
    certifies, so that float noise in ``omega`` does not change it (paper, Section 4: the
    gate's *not passive* evidence is a rational frequency and vector).

    :func:`simplest_certified` walks the Stern-Brocot path to omega's exact binary value,
    keeping to :data:`CANONICAL_REACH` of omega; the exact check of
    :func:`frequency_witness_at` decides each node, nothing float is trusted. None after
    :data:`CANONICAL_CHECKS` checks without a witness.
    """
    x = abs(Fraction(omega))
    if x == 0:
        return frequency_witness_at(model, Fraction(0))
    return simplest_certified(x, lambda r: frequency_witness_at(model, r),
                              reach=CANONICAL_REACH * x)


def frequency_witness(model: ExactModel, omega: float) -> Witness | None:
    """Exact check of a negative eigenvalue of H(jw) + H(jw)^H at a rational w near omega:
    the canonical one (:func:`canonical_frequency_witness`), else a rounding of omega."""
    found = canonical_frequency_witness(model, omega)
    if found is not None:
        return found
    for limit in (10, 1000, 10**6, 10**12):
        w = Fraction(omega).limit_denominator(limit) if omega else Fraction(0)
        found = frequency_witness_at(model, w)
        if found is not None:
            return found
    return None


def _gershgorin_floor(M: ex.RationalMatrix) -> mpq:
    """A lower bound of the eigenvalues of the symmetric part of M (exact)."""
    n = len(M)
    out = None
    for i in range(n):
        radius = sum((abs(M[i][j] + M[j][i]) / 2 for j in range(n) if j != i), mpq(0))
        low = M[i][i] - radius
        out = low if out is None or low < out else out
    return out


def _norm2(v: list[mpq]) -> mpq:
    return sum((x * x for x in v), mpq(0))


def real_axis_witness(model: ExactModel, tries: int = 24) -> Witness | None:
    """A real s* > 0 where v^T (H(s*) + H(s*)^T) v < 0, bounded exactly (see module doc)."""
    n, m = model.n, model.m
    if n == 0:
        return None
    N = ex.kernel_basis(ex.add(model.D, ex.transpose(model.D)))
    if not N or not N[0]:
        return None
    CB = ex.matmul(model.C, model.B)
    G0 = ex.matmul(ex.matmul(ex.transpose(N), CB), N)
    found = negative_direction(ex.scale(mpq(1, 2), ex.add(G0, ex.transpose(G0))))
    if found is None:
        return None
    z, g = found  # z^T G0 z = g < 0
    v = [sum((N[i][a] * z[a] for a in range(len(z))), mpq(0)) for i in range(m)]
    Bv = [sum((model.B[i][j] * v[j] for j in range(m)), mpq(0)) for i in range(n)]
    Ctv = [sum((model.C[j][i] * v[j] for j in range(m)), mpq(0)) for i in range(n)]
    floor = _gershgorin_floor(ex.scale(-1, model.A))  # sym(s I - A) >= (s + floor) I
    Af = np.array([[float(x) for x in row] for row in model.A])
    second = abs(float(np.array([float(x) for x in Ctv]) @ Af @ np.array([float(x) for x in Bv])))
    sigma = max(1.0, -float(floor)) + 4 * second / abs(float(g))
    for _ in range(tries):
        s = mpq(Fraction(sigma).limit_denominator(1))
        if s < 1:
            s = mpq(1)
        mu = s + floor
        sigma *= 2
        if mu <= 0:
            continue
        x_f = np.linalg.solve(float(s) * np.eye(n) - Af, np.array([float(x) for x in Bv]))
        top = float(np.max(np.abs(x_f)))
        if not np.isfinite(top) or top == 0.0:
            continue
        (x,) = ex.rationalize([x_f], 60 - int(np.ceil(np.log2(top))))
        Ax = [sum((model.A[i][j] * x[j] for j in range(n)), mpq(0)) for i in range(n)]
        r = [Bv[i] - s * x[i] + Ax[i] for i in range(n)]
        main = 2 * sum((Ctv[i] * x[i] for i in range(n)), mpq(0))
        # |2 v^T C (sI - A)^-1 r| <= 2 |C^T v| |r| / mu, compared in squares
        if main < 0 and main * main * mu * mu > 4 * _norm2(Ctv) * _norm2(r):
            return Witness(
                "rhp-point",
                f"at the real point s* = {s} of the right half-plane, vᵀ(H(s*) + H(s*)ᵀ)v "
                f"≈ {approx_text(main, 3)} < 0 for a rational v in ker(D + Dᵀ) (exact bound "
                "on the error of a rounded solve; Nᵀ C B N has vᵀ C B v = "
                f"{approx_text(g, 3)} < 0); "
                "a passive H has H(s) + H(s)ᴴ ≥ 0 for Re s > 0",
                {"s": str(s), "v": [str(q) for q in v], "value_bound": str(main),
                 "mu": str(mu), "residual_norm2": str(_norm2(r))},
            )
    return None


EXACT_POLE_LIMIT = 12  # states; the exact transfer matrix is formed with sympy


def _transfer_matrix(model: ExactModel):
    """The exact strictly proper part C (sI - A)^-1 B, each entry cancelled.

    Faddeev-LeVerrier: with det(sI - A) = s^n + c_1 s^(n-1) + ... + c_n (exact, sympy's
    domain charpoly), adj(sI - A) = sum_k s^(n-1-k) B_k, B_0 = I, B_k = A B_(k-1) + c_k I.
    Only rational matrix products and polynomials over QQ: no symbolic matrix algebra,
    which took minutes at n = 8.
    """
    import sympy as sp  # only the pole route needs it: imported on use (start-up time)
    from sympy.polys.matrices import DomainMatrix

    s = sp.Symbol("s")
    n, m = model.n, model.m
    A_dm = DomainMatrix.from_Matrix(ex.to_sympy(model.A, n, n)).convert_to(sp.QQ)
    coeffs = [ex.mpq(int(c.numerator), int(c.denominator)) for c in A_dm.charpoly()]
    den = sp.Poly([sp.Rational(int(c.numerator), int(c.denominator)) for c in coeffs], s)
    # numerator terms C B_k B, k = 0 .. n-1 (exact rationals)
    Bk = [[ex.mpq(int(i == j)) for j in range(n)] for i in range(n)]
    terms = []
    for k in range(n):
        if k:
            Bk = ex.matmul(model.A, Bk)
            for i in range(n):
                Bk[i][i] += coeffs[k]
        terms.append(ex.matmul(ex.matmul(model.C, Bk), model.B))
    entries = []
    for i in range(m):
        row = []
        for j in range(m):
            num = sp.Poly([sp.Rational(int(t[i][j].numerator), int(t[i][j].denominator))
                           for t in terms], s)
            if num.is_zero:
                row.append(sp.Integer(0))
                continue
            p, q = num.cancel(den, include=True)
            row.append(p.as_expr() / q.as_expr())
        entries.append(row)
    return s, sp.Matrix(entries)


def _may_have_rhp_root(poly) -> bool:
    """False only when floating-point roots are all clearly in the left half-plane.

    Exact root isolation costs seconds per polynomial; skipping it can only miss a
    witness, never make one (the witness itself is isolated exactly).
    """
    try:
        with np.errstate(all="ignore"):
            roots = np.roots([float(c) for c in poly.all_coeffs()])
    except (np.linalg.LinAlgError, OverflowError, ValueError):
        return True
    if not np.all(np.isfinite(roots)):
        return True
    scale = max(1.0, float(np.max(np.abs(roots)))) if roots.size else 1.0
    return bool(roots.size == 0 or np.max(roots.real) > -1e-6 * scale)


def pole_witness(model: ExactModel) -> Witness | None:
    """An exact RHP pole, or a non-simple / non-PSD-residue pole at 0 (small models)."""
    if model.n == 0 or model.n > EXACT_POLE_LIMIT:
        return None
    import sympy as sp

    s, Hs = _transfer_matrix(model)
    m = model.m
    seen: set = set()
    for i in range(m):
        for j in range(m):
            poly = sp.Poly(sp.fraction(Hs[i, j])[1], s)
            if poly.degree() < 1 or poly in seen or not _may_have_rhp_root(poly):
                continue
            seen.add(poly)
            real, cplx = poly.intervals(all=True, eps=sp.Rational(1, 10**6))
            for (lo, hi), _ in real:
                if lo > 0:
                    return Witness(
                        "unstable-pole",
                        f"H[{i},{j}] has a real pole in ({lo}, {hi}], in the right half-plane",
                        {"entry": [i, j], "denominator": str(poly.as_expr()),
                         "interval": [str(lo), str(hi)]},
                    )
            for (c1, c2), _ in cplx:
                if sp.re(c1) > 0:
                    return Witness(
                        "unstable-pole",
                        f"H[{i},{j}] has a complex pole in the rectangle [{c1}, {c2}], in the "
                        "right half-plane",
                        {"entry": [i, j], "denominator": str(poly.as_expr()),
                         "rectangle": [str(c1), str(c2)]},
                    )
    # a pole at s = 0 must be simple with a Hermitian PSD residue
    multiplicity = 0
    for e in Hs:
        den = sp.Poly(sp.fraction(e)[1], s)
        k = 0
        while den.degree() > 0 and den.eval(0) == 0:
            den = sp.Poly(sp.quo(den.as_expr(), s), s)
            k += 1
        multiplicity = max(multiplicity, k)
    if multiplicity >= 2:
        return Witness("pole-at-zero", f"H has a pole of order {multiplicity} at s = 0",
                       {"order": multiplicity})
    if multiplicity == 1:
        residue = (Hs * s).applyfunc(lambda e: sp.cancel(e).subs(s, 0))
        if residue != residue.T or not ex.psd_ldl(ex.from_sympy(residue)).ok:
            return Witness(
                "pole-at-zero",
                f"the residue of H at s = 0 is {residue.tolist()}, not symmetric PSD",
                {"residue": [[str(x) for x in row] for row in residue.tolist()]},
            )
    return None
