"""Complete exact decision of positive realness of H(s) = C (sI - A)^-1 B + D over Q.

The paper's Section 4 gates a human model on "nu(w) >= 0 for all w"; with poles in mind,
the decided notion is positive realness of the transfer matrix (e.g. Brogliato, Lozano,
Maschke and Egeland, *Dissipative Systems Analysis and Control*, 3rd ed., Theorem 2.48):

(a) no pole in Re s > 0;
(b) every pole on the imaginary axis (s = 0 included) is simple, with a Hermitian
    positive semidefinite residue K = lim (s - jw0) H(s);
(c) H(jw) + H(jw)^H >= 0 for every real w that is not a pole.

Every step is exact (python-flint polynomials over Q, :mod:`verify.passivity.check.qpoly`):

1. H exactly by Faddeev-LeVerrier (characteristic polynomial chi of A by FLINT, then
   C adj(sI - A) B), each entry reduced by its gcd with chi; a pole of H is a pole of an
   entry, so d = lcm of the reduced entry denominators carries every pole with its
   largest order, and H = N / d with N a polynomial matrix.
2. (a) per entry: with q the squarefree part of its denominator, a = gcd(q(s), q(-s))
   holds the roots symmetric about the imaginary axis and b = q / a none, so b is
   Hurwitz (Routh table) or has a root in Re s > 0; a = s^e alpha(s^2) has all roots on
   the axis iff rho(w) = a(jw) / j^e has deg a real roots (exact count), else a root and its
   mirror lie off the axis, one in Re s > 0.
3. (b) simplicity: a is coprime to den / a in every entry. With d = a c and
   Mt(w) = (-j)^e N(jw) conj(c(jw)) + j^e N(jw)^H c(jw), one has
   H(jw) + H(jw)^H = Mt(w) / (rho(w) |c(jw)|^2); near a root w0 of rho it behaves like
   -j (K - K^H) / (w - w0), so every residue is Hermitian iff rho divides Mt exactly.
   PSD residues: K |d'(jw0)|^2 = T(w0) with T(w) = N(jw) conj(d'(jw)); T(w0) >= 0 iff every
   coefficient E_k of det(lambda I + T_h(w0)) is >= 0 (T_h the Hermitian part), decided as
   the sign of a polynomial at a real algebraic w0, isolated by Descartes bisection (or
   by D sign changes at rational points when all D roots are real) and signed by an exact
   Taylor expansion with a bound on its remainder (no Sturm sequence, whose coefficients
   grow quadratically with the degree).
4. (c) Mh = Mt / rho is a Hermitian polynomial matrix with H(jw) + H(jw)^H = Mh / |c|^2
   and |c(jw)|^2 > 0 on R, so (c) holds iff Mh(w) >= 0 for all real w iff every E_k(w)
   (sum of the k x k principal minors of Mh) is >= 0 on R. E_k is divided by the largest
   power |c|^(2j), j < k, that divides it exactly; the quotient's squarefree
   decomposition decides the sign: >= 0 iff the content is positive and no
   odd-multiplicity factor has a real root, certified by an exact sum of squares
   (:mod:`verify.passivity.check.univariate_sos`).

Negative verdicts carry exact evidence: an entry with a pole in Re s > 0 (the Routh
column or the real-root count, and a certified root enclosure), an entry with a repeated
imaginary-axis pole, a residue whose Hermitian form has E_k(w0) < 0, or a rational
frequency w* with an exact vector v, v^H (H(jw*) + H(jw*)^H) v < 0.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from flint import fmpq, fmpq_mat, fmpq_poly

from verify.inputs.number_text import approx_text
from verify.passivity.check import qpoly as qp
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.univariate_sos import Nonnegativity, nonnegativity_certificate

PASSIVE, NOT_PASSIVE = "passive", "not passive"


# 1. the transfer matrix ----------------------------------------------------------------

@dataclass(frozen=True)
class TransferMatrix:
    """H = N / d exactly: entries reduced, d the lcm of their denominators (monic)."""

    charpoly: fmpq_poly
    nums: list[list[fmpq_poly]]  # reduced numerators (D included)
    dens: list[list[fmpq_poly]]  # reduced monic denominators
    d: fmpq_poly
    N: list[list[fmpq_poly]]  # common-denominator numerators, H = N / d


def _mat(rows, r: int, c: int) -> fmpq_mat:
    return fmpq_mat(r, c, [qp.q(x) for row in rows for x in row])


def transfer_matrix(model: ExactModel) -> TransferMatrix:
    """Exact H(s): adj(sI - A) = sum_k s^(n-1-k) B_k, B_0 = I, B_k = A B_(k-1) + c_k I
    (Faddeev-LeVerrier), so C adj(sI - A) B needs only the products X_k = B_k B."""
    n, m = model.n, model.m
    D = [[qp.q(x) for x in row] for row in model.D]
    if n == 0:
        chi = qp.ONE
        raw = [[qp.ZERO] * m for _ in range(m)]
    else:
        A, B, C = _mat(model.A, n, n), _mat(model.B, n, m), _mat(model.C, m, n)
        chi = A.charpoly()
        c = chi.coeffs()[::-1]  # c[0] = 1, c[k] the coefficient of s^(n-k)
        X = B
        terms = [C * X]
        for k in range(1, n):
            X = A * X + c[k] * B
            terms.append(C * X)
        raw = [[fmpq_poly([terms[n - 1 - p][i, j] for p in range(n)]) for j in range(m)]
               for i in range(m)]
    nums, dens = [], []
    for i in range(m):
        nrow, drow = [], []
        for j in range(m):
            num = raw[i][j] + D[i][j] * chi
            if num.is_zero():
                nrow.append(qp.ZERO)
                drow.append(qp.ONE)
                continue
            g = num.gcd(chi)
            den = chi / g
            lead = den.leading_coefficient()
            nrow.append((num / g) / lead)
            drow.append(den / lead)
        nums.append(nrow)
        dens.append(drow)
    d = qp.ONE
    for row in dens:
        for den in row:
            d = d * den / d.gcd(den)
    d = qp.monic(d)
    N = [[nums[i][j] * (d / dens[i][j]) for j in range(m)] for i in range(m)]
    return TransferMatrix(chi, nums, dens, d, N)


# 2. poles ----------------------------------------------------------------------------

@dataclass(frozen=True)
class AxisSplit:
    """q = squarefree part of p = a * b: a holds the roots symmetric about the imaginary
    axis (a = s^e alpha(s^2)), b the others; rho(w) = a(jw) / j^e is real."""

    a: fmpq_poly
    b: fmpq_poly
    e: int
    rho: fmpq_poly


def axis_split(p: fmpq_poly) -> AxisSplit:
    q = qp.squarefree_part(p)
    a = qp.monic(q.gcd(qp.mirror(q)))
    b = q / a
    e = 1 if a(0) == 0 else 0
    re, im = qp.at_jw(a)
    return AxisSplit(a, b, e, im if e else re)


@dataclass(frozen=True)
class PoleFact:
    """Why an entry's denominator has (or has not) a pole in Re s > 0 or a bad axis pole."""

    entry: tuple[int, int]
    den: fmpq_poly
    routh: list[fmpq]  # first column of the Routh table of b
    axis_real_roots: int  # real roots of rho (all on the axis iff = deg a), exact count
    axis_degree: int
    repeated_axis: fmpq_poly  # gcd(a, den / a): non-constant iff a repeated axis pole

    @property
    def hurwitz_rest(self) -> bool:
        return all(x > 0 for x in self.routh) and len(self.routh) == self.rest_degree + 1

    rest_degree: int = 0

    @property
    def rhp(self) -> bool:
        return not self.hurwitz_rest or self.axis_real_roots != self.axis_degree

    @property
    def repeated(self) -> bool:
        return self.repeated_axis.degree() >= 1


def pole_fact(entry: tuple[int, int], den: fmpq_poly) -> PoleFact:
    sp = axis_split(den)
    repeated = qp.monic(sp.a.gcd(den / sp.a)) if sp.a.degree() >= 1 else qp.ONE
    return PoleFact(entry, den, qp.routh_first_column(sp.b), qp.count_real_roots(sp.rho),
                    sp.a.degree(), repeated, sp.b.degree())


def rhp_root_enclosure(den: fmpq_poly) -> str:
    """A certified enclosure (arb ball) of a root of den in Re s > 0, for the report."""
    q = qp.squarefree_part(den)
    for prec in (64, 256, 1024, 4096):
        for r in qp.approximate_roots(q, prec):
            if r.real > 0:
                return str(r)
    return "(enclosure not separated from the axis at 4096 bits)"


# 3. residues and 4. the Hermitian part ---------------------------------------------------

def _cpoly_matrix(P: list[list[fmpq_poly]]) -> list[list[qp.CPoly]]:
    return [[qp.at_jw(x) for x in row] for row in P]


def hermitian_numerator(tm: TransferMatrix, sp: AxisSplit) -> list[list[qp.CPoly]]:
    """Mt(w) = (-j)^e N(jw) conj(c(jw)) + j^e N(jw)^H c(jw), d = a c."""
    c = qp.at_jw(tm.d / sp.a)
    Nj = _cpoly_matrix(tm.N)
    m = len(Nj)
    out = []
    for i in range(m):
        row = []
        for k in range(m):
            left = qp.times_j_power(qp.cmul(Nj[i][k], qp.conj(c)), -sp.e)
            right = qp.times_j_power(qp.cmul(qp.conj(Nj[k][i]), c), sp.e)
            row.append(qp.cadd(left, right))
        out.append(row)
    return out


def divide_by(Mt: list[list[qp.CPoly]], rho: fmpq_poly) -> list[list[qp.CPoly]] | None:
    """Mt / rho entrywise if exact, else None."""
    out = []
    for row in Mt:
        new = []
        for re, im in row:
            (qr, rr), (qi, ri) = divmod(re, rho), divmod(im, rho)
            if not rr.is_zero() or not ri.is_zero():
                return None
            new.append((qr, qi))
        out.append(new)
    return out


def principal_minor_sums(M: list[list[qp.CPoly]]) -> list[fmpq_poly]:
    """[E_1, ..., E_m]: det(lambda I + M) = sum_k E_k lambda^(m-k), for Hermitian M(w).

    Faddeev-LeVerrier over Q(j)[w]: M_1 = I, c_(m-k) = -tr(M M_k) / k,
    M_(k+1) = M M_k + c_(m-k) I; E_k = (-1)^k c_(m-k), real for Hermitian M.
    """
    m = len(M)
    zero = (qp.ZERO, qp.ZERO)
    Mk = [[(qp.ONE, qp.ZERO) if i == j else zero for j in range(m)] for i in range(m)]
    E = []
    for k in range(1, m + 1):
        AM = [[zero for _ in range(m)] for _ in range(m)]
        for i in range(m):
            for j in range(m):
                acc = zero
                for t in range(m):
                    acc = qp.cadd(acc, qp.cmul(M[i][t], Mk[t][j]))
                AM[i][j] = acc
        tr = zero
        for i in range(m):
            tr = qp.cadd(tr, AM[i][i])
        ck = (-tr[0] / k, -tr[1] / k)
        if not ck[1].is_zero():
            raise ArithmeticError("the matrix is not Hermitian")
        E.append(ck[0] if k % 2 == 0 else -ck[0])
        Mk = [[qp.cadd(AM[i][j], ck) if i == j else AM[i][j] for j in range(m)]
              for i in range(m)]
    return E


def reduce_by_square(E: fmpq_poly, gamma: fmpq_poly, most: int) -> tuple[fmpq_poly, int]:
    """E = gamma^j Q with the largest j <= most (gamma = |c(jw)|^2 > 0 on R)."""
    j = 0
    if gamma.degree() < 1 or E.is_zero():
        return E, 0
    while j < most:
        quo, rem = divmod(E, gamma)
        if not rem.is_zero():
            break
        E, j = quo, j + 1
    return E, j


def residue_forms(tm: TransferMatrix, sp: AxisSplit) -> list[fmpq_poly]:
    """[E_k(T_h)]: T(w) = N(jw) conj(d'(jw)) equals K |d'(jw0)|^2 at a pole jw0."""
    dp = qp.at_jw(tm.d.derivative())
    Nj = _cpoly_matrix(tm.N)
    m = len(Nj)
    T = [[qp.cmul(Nj[i][k], qp.conj(dp)) for k in range(m)] for i in range(m)]
    half = fmpq(1, 2)
    Th = [[((T[i][k][0] + T[k][i][0]) * half, (T[i][k][1] - T[k][i][1]) * half)
           for k in range(m)] for i in range(m)]
    return principal_minor_sums(Th)


@dataclass(frozen=True)
class AxisPole:
    """A pole jw0, w0 >= 0 the one root of rho in (lo, hi]; signs of E_k(T_h)(w0)."""

    lo: fmpq
    hi: fmpq
    signs: list[int]


def axis_poles(sp: AxisSplit, forms: list[fmpq_poly]) -> list[AxisPole]:
    """The roots w0 >= 0 of rho with the signs of the residue forms there (exact; root
    isolation by Descartes bisection and sign changes, no Sturm sequence)."""
    out = []
    rho = sp.rho
    reduced = [qp.reduce_mod(g, rho) for g in forms]  # once per form, not per root
    for lo, hi in qp.isolate_real_roots(rho):  # (lo, hi) open with a sign change, or lo == hi
        if hi < 0 or (lo < hi and hi <= 0):
            continue
        if lo < 0 < hi:  # split at 0: the root is 0 itself, negative, or in (0, hi)
            at0 = rho(0)
            if at0 == 0:
                lo = hi = fmpq(0)
            elif qp.sign(at0) == qp.sign(rho(hi)):
                continue
            else:
                lo = fmpq(0)
        if hi > 0:  # a readable enclosure of w0: relative width about 2^-24
            lo, hi = qp.refine_root(rho, (lo, hi), (1 + hi) / 2**24)
        out.append(AxisPole(lo, hi, [qp.sign_at_root(g, rho, (lo, hi), red)
                                     for g, red in zip(forms, reduced, strict=True)]))
    return out


# the decision ----------------------------------------------------------------------------

@dataclass
class Analysis:
    """Every derived exact fact, and the verdict they imply."""

    tm: TransferMatrix
    verdict: str = PASSIVE
    reason: str = ""
    failure: dict = field(default_factory=dict)  # what failed, when not passive
    pole_facts: list[PoleFact] = field(default_factory=list)
    split: AxisSplit | None = None
    residue_forms: list[fmpq_poly] = field(default_factory=list)
    poles_on_axis: list[AxisPole] = field(default_factory=list)
    gamma: fmpq_poly | None = None
    E: list[fmpq_poly] = field(default_factory=list)
    powers: list[int] = field(default_factory=list)
    quotients: list[fmpq_poly] = field(default_factory=list)
    certificates: list[Nonnegativity | None] = field(default_factory=list)


def analyse(model: ExactModel, *, certify: bool = True) -> Analysis:
    """The exact decision (``certify``: also build the SOS certificates)."""
    tm = transfer_matrix(model)
    an = Analysis(tm)
    m = model.m
    seen: dict = {}
    for i in range(m):
        for j in range(m):
            den = tm.dens[i][j]
            if den.degree() < 1:
                continue
            key = tuple(str(c) for c in den.coeffs())
            if key in seen:
                continue
            fact = pole_fact((i, j), den)
            seen[key] = fact
            an.pole_facts.append(fact)
    for fact in an.pole_facts:
        if fact.rhp:
            i, j = fact.entry
            an.verdict, an.failure = NOT_PASSIVE, {"kind": "unstable-pole", "fact": fact}
            an.reason = (f"H[{i},{j}] has a pole in the open right half-plane, near "
                         f"{rhp_root_enclosure(fact.den)} (exact: "
                         + ("the Routh column of its off-axis part is not all positive"
                            if not fact.hurwitz_rest else
                            "its roots symmetric about the axis are not all on it") + ")")
            return an
    for fact in an.pole_facts:
        if fact.repeated:
            i, j = fact.entry
            an.verdict, an.failure = NOT_PASSIVE, {"kind": "repeated-axis-pole", "fact": fact}
            an.reason = (f"H[{i},{j}] has a repeated pole on the imaginary axis at the roots "
                         f"of {fact.repeated_axis.str(var='s')} (positive realness needs "
                         "simple poles there)")
            return an
    sp = axis_split(tm.d)
    an.split = sp
    Mt = hermitian_numerator(tm, sp)
    Mh = divide_by(Mt, sp.rho)
    if Mh is None:
        an.verdict, an.failure = NOT_PASSIVE, {"kind": "residue-not-hermitian"}
        an.reason = ("a residue of H at an imaginary-axis pole is not Hermitian (exact: "
                     "rho(w) does not divide the Hermitian numerator)")
        return an
    if sp.a.degree() >= 1:
        an.residue_forms = residue_forms(tm, sp)
        an.poles_on_axis = axis_poles(sp, an.residue_forms)
        for pole in an.poles_on_axis:
            bad = [k + 1 for k, s in enumerate(pole.signs) if s < 0]
            if bad:
                an.verdict = NOT_PASSIVE
                an.failure = {"kind": "residue-not-psd", "pole": pole, "k": bad[0]}
                where = "0" if pole.hi == 0 else f"j·w0, w0 in ({pole.lo}, {pole.hi}]"
                an.reason = (f"the residue of H at the imaginary-axis pole s = {where} "
                             f"(w0 ≈ {approx_text((pole.lo + pole.hi) / 2)}) is not positive "
                             "semidefinite "
                             f"(exact: E_{bad[0]} of its Hermitian form is negative)")
                return an
    c = qp.at_jw(tm.d / sp.a)
    an.gamma = c[0] * c[0] + c[1] * c[1]
    an.E = principal_minor_sums(Mh)
    for k, Ek in enumerate(an.E, start=1):
        quotient, j = reduce_by_square(Ek, an.gamma, k - 1)
        an.powers.append(j)
        an.quotients.append(quotient)
        cert = nonnegativity_certificate(quotient) if certify else _sign_only(quotient)
        an.certificates.append(cert)
        if cert is None:
            an.verdict = NOT_PASSIVE
            an.failure = {"kind": "frequency", "k": k, "quotient": quotient}
            an.reason = (f"H(jω) + H(jω)ᴴ is not positive semidefinite at some real ω "
                         f"(E_{k}, the sum of its {k} x {k} principal minors, is negative "
                         "somewhere)")
            return an
    an.reason = _passive_reason(model, an)
    return an


def _sign_only(f: fmpq_poly):
    from verify.passivity.check.univariate_sos import has_real_root

    if f.is_zero():
        return Nonnegativity(fmpq(0), [])
    content, factors = f.factor_squarefree()
    if content < 0 or any(e % 2 and has_real_root(g) for g, e in factors):
        return None
    return Nonnegativity(fmpq(content), [(g, int(e), None) for g, e in factors])


def _passive_reason(model: ExactModel, an: Analysis) -> str:
    deg = an.tm.d.degree()
    axis = len(an.poles_on_axis)
    if deg == model.n:
        minimal = "the realisation is minimal (pole polynomial of degree n)"
    elif model.m == 1:
        minimal = (f"the realisation is not minimal (H has {deg} poles, the model "
                   f"{model.n} states): this is passivity of H(s), not a storage function "
                   "on the given state")
    else:
        minimal = (f"the lcm of the entry denominators has degree {deg} < n = {model.n}; "
                   "this is passivity of H(s), not a storage function on the given state")
    return (f"H(s) is positive real, decided exactly in the frequency domain: no pole in "
            f"Re s > 0, {axis} simple imaginary-axis pole pair(s) with Hermitian PSD "
            "residues, and every principal-minor sum of H(jω) + H(jω)ᴴ is an exact sum of "
            f"squares on ℝ; {minimal}")
