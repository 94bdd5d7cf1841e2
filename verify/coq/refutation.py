"""Negative verdicts as Coq units: a model that is not positive real (Section 4).

The gate's *not passive* verdict rests on an exact witness
(:mod:`verify.passivity.check.witness`). The unit written here proves, from the model's
matrices as data, ``model_ok /\\ ~ positive_real`` of the prelude ``WitnessCert.v``:
the realisation describes a model and its transfer matrix is not positive real (no
passive storage exists). The witness Coq re-checks is one of

- a frequency witness (w, z): Coq computes d(jw) and N(jw) over the complex rationals
  and checks d(jw) != 0 and Re z^H Mt(w) z < 0, Mt(w) = |d(jw)|^2 (H(jw) + H(jw)^H)
  (``fdi_witness_check``). The gate's frequency witness is used as it is; a witness at
  infinity (v^T (D + D^T) v < 0) becomes a frequency witness at a finite w (a power of
  two) where the same real vector works, found here;
- an unstable witness [s1, s2] ⊂ (0, oo): d(s1) d(s2) <= 0 for d(s) = det(sI - A)
  (``unstable_witness_check``), from an isolated positive real root of d.

The model stated is the exact minimal realisation the gate decided (shifted by the
margin), so that the refutation is about the transfer matrix, as the verdict is.
Nothing here is trusted: :func:`form_at` repeats Coq's computation exactly so that the
exporter proposes only a witness that Coq will accept, and Coq recomputes everything.
A frequency witness is first made short (:func:`short_witness`: the simplest w near the
gate's and z rounded to a few bits, each re-checked exactly), since the kernel's work
grows with their digits.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from flint import fmpq, fmpq_mat, fmpq_poly

from verify.coq.band_fd import _mat, charpoly_adj, jw_parts, model_lines, q_text
from verify.coq.kyp import CoqExportError
from verify.coq.unit import CoqUnit, comment_text
from verify.passivity.check.certificate import ExactModel

THEOREM = "not_passive"

#: Largest exponent k tried for the finite frequency w = 2^k of a witness at infinity.
INFINITY_MAX_EXPONENT = 400


@dataclass(frozen=True)
class FrequencyWitness:
    """w >= 0 and z = a + jb (m entries each) with Re z^H Mt(w) z < 0."""

    omega: Fraction
    a: tuple[Fraction, ...]
    b: tuple[Fraction, ...]
    value: Fraction  # Re z^H Mt(w) z, as Coq computes it (< 0)


@dataclass(frozen=True)
class UnstableWitness:
    """0 < s1 <= s2 with d(s1) d(s2) <= 0, d = det(sI - A)."""

    s1: Fraction
    s2: Fraction


def _fq(x) -> fmpq:
    x = Fraction(x)
    return fmpq(x.numerator, x.denominator)


def _fr(x: fmpq) -> Fraction:
    return Fraction(int(x.p), int(x.q))


def _polys(model: ExactModel) -> tuple[fmpq_poly, list[list[fmpq_poly]]]:
    """d(s) = det(sI - A) and N(s) = C Adj(s) B + d(s) D, as Coq computes them."""
    n, m = model.n, model.m
    A = _mat(model.A, n, n)
    B, C, D = _mat(model.B, n, m), _mat(model.C, m, n), _mat(model.D, m, m)
    cs, Ms = charpoly_adj(A)
    coeff_mats: list[fmpq_mat] = [C * M * B + D * c for c, M in zip(cs, Ms, strict=False)]
    coeff_mats.append(D * cs[-1])
    N = [[fmpq_poly([M[i, k] for M in coeff_mats]) for k in range(m)] for i in range(m)]
    return fmpq_poly(cs), N


class _Form:
    """Re z^H Mt(w) z as a function of (w, z), the polynomials computed once."""

    def __init__(self, model: ExactModel) -> None:
        d, N = _polys(model)
        self.m = model.m
        self.d_parts = jw_parts(d)
        self.n_parts = [[jw_parts(N[i][k]) for k in range(self.m)] for i in range(self.m)]

    def __call__(self, omega: Fraction, a, b) -> Fraction | None:
        return _form_value(self, omega, a, b)


def form_at(model: ExactModel, omega: Fraction, a, b) -> Fraction | None:
    """Re z^H Mt(w) z for z = a + jb, exactly as ``fdi_witness_check`` computes it;
    None when d(jw) = 0 (the check then fails)."""
    return _Form(model)(omega, a, b)


def _form_value(form: _Form, omega: Fraction, a, b) -> Fraction | None:
    w = _fq(omega)
    dr, di = form.d_parts[0](w), form.d_parts[1](w)
    if dr * dr + di * di == 0:
        return None
    m = form.m
    vals = [[tuple(p(w) for p in form.n_parts[i][k]) for k in range(m)] for i in range(m)]
    z = [(_fq(a[i]), _fq(b[i])) for i in range(m)]
    total = fmpq(0)
    for i in range(m):
        for k in range(m):
            nik, nki = vals[i][k], vals[k][i]
            mr = dr * (nik[0] + nki[0]) + di * (nik[1] + nki[1])
            mi = dr * (nik[1] - nki[1]) - di * (nik[0] - nki[0])
            # Re conj(z_i) (M z_k)
            pr, pi = mr * z[k][0] - mi * z[k][1], mr * z[k][1] + mi * z[k][0]
            total += z[i][0] * pr + z[i][1] * pi
    return _fr(total)


def simplest_between(lo: Fraction, hi: Fraction) -> Fraction:
    """The simplest rational in [lo, hi] (0 <= lo <= hi): the least denominator, and the
    least numerator for it (the first one met going down the Stern-Brocot tree), by
    continued fractions."""
    lo, hi = Fraction(lo), Fraction(hi)
    if lo < 0 or hi < lo:
        raise ValueError("need 0 <= lo <= hi")
    whole = lo.numerator // lo.denominator
    if whole == lo or whole + 1 <= hi:
        return Fraction(whole if whole == lo else whole + 1)
    # lo and hi in (whole, whole + 1): the simplest of their reciprocals' interval
    return whole + 1 / simplest_between(1 / (hi - whole), 1 / (lo - whole))


#: Bits tried for the entries of a shortened direction z (largest entry scaled to 1).
SHORT_BITS = (2, 4, 8, 16, 32, 64)
#: Relative half-widths tried for a shortened frequency: 2^-1, 2^-2, ..., 2^-64.
SHORT_WIDTHS = tuple(Fraction(1, 2 ** k) for k in range(1, 65))


def _rounded(x: Fraction, bits: int) -> Fraction:
    return Fraction(round(x * 2 ** bits), 2 ** bits)


def short_witness(model: ExactModel, found: FrequencyWitness,
                  band: tuple[Fraction, Fraction] | None = None) -> FrequencyWitness:
    """A witness with short numbers for the same model: z scaled so its largest entry
    is 1 and rounded to a few bits, then w the simplest rational within a relative
    2^-k of the witness's (inside the band, if any), each re-checked exactly
    (:func:`form_at`: the value stays < 0); ``found`` itself where nothing shorter
    passes. The kernel's work grows with the digits of w and z (Mt(w) has degree 2n)."""
    form = _Form(model)
    top = max((abs(x) for x in (*found.a, *found.b)), default=Fraction(0))
    a, b, value = found.a, found.b, found.value
    if top > 0:
        for bits in SHORT_BITS:
            ra = tuple(_rounded(x / top, bits) for x in found.a)
            rb = tuple(_rounded(x / top, bits) for x in found.b)
            v = form(found.omega, ra, rb)
            if v is not None and v < 0:
                a, b, value = ra, rb, v
                break
    omega = found.omega
    if omega > 0:
        for width in SHORT_WIDTHS:
            lo, hi = omega * (1 - width), omega * (1 + width)
            if band is not None:
                lo, hi = max(lo, band[0]), min(hi, band[1])
            w = simplest_between(max(lo, Fraction(0)), hi)
            v = form(w, a, b)
            if v is not None and v < 0:
                return FrequencyWitness(w, a, b, v)
    return FrequencyWitness(omega, a, b, value)


def frequency_from_data(model: ExactModel, data: dict) -> FrequencyWitness | None:
    """The gate's frequency witness (``omega``, ``a``, ``b``), if Coq's check accepts it."""
    try:
        omega = Fraction(data["omega"])
        a = tuple(Fraction(x) for x in data["a"])
        b = tuple(Fraction(x) for x in data["b"])
    except (KeyError, TypeError, ValueError, ZeroDivisionError):
        return None
    if omega < 0 or len(a) != model.m or len(b) != model.m:
        return None
    value = form_at(model, omega, a, b)
    return None if value is None or value >= 0 else FrequencyWitness(omega, a, b, value)


def frequency_from_infinity(model: ExactModel, v) -> FrequencyWitness | None:
    """A frequency w = 2^k where the real vector v of a witness at infinity works."""
    a = tuple(Fraction(x) for x in v)
    b = tuple(Fraction(0) for _ in a)
    if len(a) != model.m:
        return None
    if model.n == 0:
        value = form_at(model, Fraction(0), a, b)
        return None if value is None or value >= 0 else \
            FrequencyWitness(Fraction(0), a, b, value)
    k = 0
    while k <= INFINITY_MAX_EXPONENT:
        omega = Fraction(2) ** k
        value = form_at(model, omega, a, b)
        if value is not None and value < 0:
            return FrequencyWitness(omega, a, b, value)
        k = 2 * k + 1 if k else 1
    return None


def unstable_witness(model: ExactModel) -> UnstableWitness | None:
    """An interval [s1, s2] ⊂ (0, oo) on whose ends d changes sign (or a positive
    rational root, s1 = s2), from exact real root isolation of d's odd-multiplicity
    factors (:mod:`verify.passivity.check.interval_roots`)."""
    from verify.passivity.check.interval_roots import refine, roots_inside

    d, _ = _polys(model)
    if d.degree() < 1:
        return None
    coeffs = d.coeffs()
    bound = 1 + max(abs(c / coeffs[-1]) for c in coeffs[:-1])
    _, factors = d.factor()
    for factor, mult in factors:
        if mult % 2 == 0:
            continue
        for interval in roots_inside(factor, fmpq(0), bound):
            u, v = refine(factor, interval, fmpq(1, 1024))
            if u > 0 and d(u) * d(v) <= 0:
                return UnstableWitness(_fr(u), _fr(v))
    return None


def _vector_literal(a, b) -> str:
    pairs = zip(a, b, strict=True)
    return "[" + "; ".join(f"({q_text(_fq(x))}, {q_text(_fq(y))})" for x, y in pairs) + "]"


def refutation_unit(name: str, *, model: ExactModel, margin: Fraction,
                    witness: FrequencyWitness | UnstableWitness, label: str, source: str,
                    fingerprint: str, origin: str,
                    band: tuple[Fraction, Fraction] | None = None) -> CoqUnit:
    """The unit proving ``model_ok /\\ ~ positive_real`` for (A, B, C, D - margin I),
    ``model`` unshifted; with ``band`` (a frequency witness inside it),
    ``model_ok /\\ ~ band_passive`` on that band."""
    n, m = model.n, model.m
    d_name = "D" if margin == 0 else "D_shifted"
    if band is not None:
        if not isinstance(witness, FrequencyWitness) or \
                not band[0] <= witness.omega <= band[1]:
            raise CoqExportError("a band refutation needs a frequency witness in the band")
        return _band_unit(name, model, margin, witness, band, label, source, fingerprint,
                          origin)
    if isinstance(witness, FrequencyWitness):
        how = (f"a frequency witness: at w = {witness.omega}, Re z^H Mt(w) z = "
               f"{witness.value} < 0 with Mt(w) = |d(jw)|^2 (H(jw) + H(jw)^H)")
        data = [f"Definition w_star : Q := {q_text(_fq(witness.omega))}.",
                f"Definition z_star : list cQ :=\n  {_vector_literal(witness.a, witness.b)}."]
        proof = [f"  apply (not_positive_real_of_fdi {n} {m} A B C {d_name} w_star z_star)."]
    else:
        how = (f"an unstable witness: det(sI - A) changes sign on [{witness.s1}, "
               f"{witness.s2}], in Re s > 0")
        data = [f"Definition s1 : Q := {q_text(_fq(witness.s1))}.",
                f"Definition s2 : Q := {q_text(_fq(witness.s2))}."]
        proof = [f"  apply (not_positive_real_of_unstable {n} {m} A B C {d_name} s1 s2)."]
    preamble = model_lines(model, margin)
    preamble[1] = "From VerifyCoq Require Import QCert BandCert WitnessCert."
    bound = "" if margin == 0 else f" (the model decided is H - nu0 I, nu0 = {margin})"
    lines = [
        f"(** {comment_text(origin)}: exported by verify; checked by coqc.",
        f"    Model: {comment_text(label)}",
        f"    Source file: {comment_text(source)}",
        f"    Fingerprint (sha256 of the exact A, B, C, D): {fingerprint}",
        f"    Claim: the transfer matrix is not positive real{comment_text(bound)}, so the "
        "model is not passive",
        "    ([positive_real] in WitnessCert.v), by " + comment_text(how) + ". *)",
        "",
        *preamble,
        "",
        "(** The witness (data Coq re-checks). *)",
        *data,
        "",
        f"Theorem {THEOREM} : model_ok {n} {m} A B C {d_name} "
        f"/\\ ~ positive_real {n} {m} A B C {d_name}.",
        "Proof.",
        *proof,
        "  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)",
        "Qed.",
        "",
    ]
    return CoqUnit(name, "\n".join(lines), (THEOREM,), origin)


def _band_unit(name: str, model: ExactModel, margin: Fraction, witness: FrequencyWitness,
               band: tuple[Fraction, Fraction], label: str, source: str, fingerprint: str,
               origin: str) -> CoqUnit:
    n, m = model.n, model.m
    d_name = "D" if margin == 0 else "D_shifted"
    preamble = model_lines(model, margin)
    preamble[1] = "From VerifyCoq Require Import QCert BandCert WitnessCert."
    lines = [
        f"(** {comment_text(origin)}: exported by verify; checked by coqc.",
        f"    Model: {comment_text(label)}",
        f"    Source file: {comment_text(source)}",
        f"    Fingerprint (sha256 of the exact A, B, C, D): {fingerprint}",
        f"    Claim: not passive on the band [{band[0]}, {band[1]}] rad/s ([band_passive] in "
        "BandCert.v),",
        f"    by a frequency witness: at w = {witness.omega}, Re z^H Mt(w) z = "
        f"{witness.value} < 0. *)",
        "",
        *preamble,
        "",
        f"Definition w1 : Q := {q_text(_fq(band[0]))}.",
        f"Definition w2 : Q := {q_text(_fq(band[1]))}.",
        "(** The witness (data Coq re-checks). *)",
        f"Definition w_star : Q := {q_text(_fq(witness.omega))}.",
        f"Definition z_star : list cQ :=\n  {_vector_literal(witness.a, witness.b)}.",
        "",
        f"Theorem {THEOREM} : model_ok {n} {m} A B C {d_name} "
        f"/\\ ~ band_passive {n} {m} A B C {d_name} w1 w2.",
        "Proof.",
        f"  apply (not_band_passive_of_fdi {n} {m} A B C {d_name} w1 w2 w_star z_star).",
        "  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)",
        "Qed.",
        "",
    ]
    return CoqUnit(name, "\n".join(lines), (THEOREM,), origin)


def _search_frequency(em: ExactModel, hints: list[float],
                      band: tuple[Fraction, Fraction] | None = None
                      ) -> FrequencyWitness | None:
    """A frequency witness of the exact checker near the hinted frequencies, then near
    the minimisers of nu found in floating point (untrusted proposals, re-checked)."""
    from verify.passivity.check.witness import frequency_witness
    from verify.passivity.decision import (
        candidate_frequencies,
        float_views,
        hamiltonian_candidates,
        propose,
    )

    A, B, C, D = float_views(em)
    found, _ = propose(hamiltonian_candidates, A, B, C, D, default=([], None))
    swept, _ = propose(candidate_frequencies, A, B, C, D, default=([], None))
    for omega in [*hints, *found, *swept]:
        if band is not None and not band[0] <= Fraction(omega) <= band[1]:
            continue
        w = propose(frequency_witness, em, omega)
        if w is not None and w.kind == "frequency":
            fw = frequency_from_data(em, w.data)
            if fw is not None and (band is None or band[0] <= fw.omega <= band[1]):
                return fw
    return None


def decision_witness(decision) -> tuple[ExactModel, FrequencyWitness | UnstableWitness]:
    """The model the gate decided (its exact minimal realisation, unshifted) and a witness
    Coq's check accepts for it shifted by the margin; CoqExportError (the reason) when
    none is found."""
    from verify.passivity.check.realization import minimal_part
    from verify.passivity.io.binding import shifted

    base = minimal_part(decision.model.exact).model
    em = shifted(base, Fraction(decision.margin))
    witness = decision.witness
    kind = None if witness is None else witness.kind
    band = getattr(decision, "band", None)
    found: FrequencyWitness | UnstableWitness | None = None
    if kind == "frequency":
        found = frequency_from_data(em, witness.data)
        if found is not None and band is not None and \
                not band[0] <= found.omega <= band[1]:
            found = None
    elif kind == "infinity" and band is None:
        found = frequency_from_infinity(em, witness.data.get("v", ()))
    if found is None and band is None:
        found = unstable_witness(em)
    if found is None:
        hints = [] if decision.nu_min is None else [decision.nu_min[0]]
        if band is not None:
            hints += [float(band[0] + (band[1] - band[0]) * k / 16) for k in range(17)]
        found = _search_frequency(em, hints, band)
    if isinstance(found, FrequencyWitness):
        found = short_witness(em, found, band)
    if found is None:
        raise CoqExportError(
            f"no witness Coq's check accepts was found for the {kind or 'gate'} witness (a "
            "non-real pole in Re s > 0 or a pole on the imaginary axis is not stated as a "
            "Coq witness)")
    return base, found


def decision_unit(decision, name: str) -> CoqUnit:
    """The refutation unit of a gate's *not passive* decision (module ``name``)."""
    base, found = decision_witness(decision)
    model = decision.model
    return refutation_unit(
        name, model=base, margin=Fraction(decision.margin), witness=found,
        label=model.name, source=str(model.source), fingerprint=base.fingerprint(),
        origin=f"Refutation of passivity ({name})", band=getattr(decision, "band", None))
