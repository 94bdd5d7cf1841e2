"""Exact-band certificates as Coq units: H(jw) + H(jw)^H >= 0 on a band (Section 4).

A ``verify-band-fd-certificate/1`` says, for the model H of the paper's Section 4 and a
band [w1, w2], that the Hermitian part of H(jw) is positive semidefinite at every w of
the band where H(jw) is defined (nu(w) >= 0 there; with a margin nu0, the stored model is
H - nu0 I). The unit written here states ``band_passive`` of the prelude ``BandCert.v``
from the model's matrices as data: Coq computes d(s) = det(sI - A) and Adj(s) by the
Faddeev-LeVerrier recursion, checks (sI - A) Adj(s) = d(s) I, forms
N(s) = C Adj(s) B + d(s) D, and the claim is Re z^H (H(jw) + H(jw)^H) z >= 0 with
H(jw) = N(jw) / d(jw) in complex arithmetic, for every w of the band with d(jw) != 0
and every complex z.

The proof: the Hermitian numerator Mt(w) = |d(jw)|^2 (H(jw) + H(jw)^H) has real
polynomial entries; for one port its entry, for two its trace and determinant, must be
>= 0 on the band (a 2 x 2 Hermitian matrix is >= 0 iff both are; lemma ``herm2``). For
each such polynomial the exporter proposes a witness (:mod:`verify.coq.interval_witness`)
that Coq re-checks: p = g^2 q and q in Bernstein form, with non-negative weights, on
pieces covering the band. The Python certificate's own data (Descartes breakpoints) is
not used by Coq: the exporter first re-checks the certificate with the exact checker
(:func:`verify.passivity.check.band_fd.check_band_fd_file`, binding included) and refuses
it when that fails, then Coq proves the claim on its own.

:func:`sign_polynomials` repeats Coq's computation of those polynomials (the same
rationals), so that the witnesses fit what Coq computes.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

from flint import fmpq, fmpq_mat, fmpq_poly

from verify.coq import interval_witness as iw
from verify.coq.kyp import CoqExportError, matrix_literal, module_name, q_literal
from verify.coq.unit import CoqUnit, comment_text
from verify.passivity.check.certificate import ExactModel

THEOREM = "passive_on_band"
SCHEMA = "verify-band-fd-certificate/1"


# what Coq computes, repeated --------------------------------------------------------------

def _mat(m, rows: int, cols: int) -> fmpq_mat:
    return fmpq_mat(rows, cols, [fmpq(int(x.numerator), int(x.denominator))
                                 for row in m for x in row])


def charpoly_adj(A: fmpq_mat) -> tuple[list[fmpq], list[fmpq_mat]]:
    """d's coefficients and Adj's coefficient matrices, lowest degree first, by the
    Faddeev-LeVerrier recursion (``charpoly_adj`` in ``BandCert.v``)."""
    n = A.nrows()
    eye = fmpq_mat(n, n, [fmpq(int(i == j)) for i in range(n) for j in range(n)])
    cs, Ms = [fmpq(1)], []
    Mk = eye
    for k in range(1, n + 1):
        AM = A * Mk
        c = -sum((AM[i, i] for i in range(n)), fmpq(0)) / k
        cs.insert(0, c)
        Ms.insert(0, Mk)
        Mk = AM + eye * c
    return cs, Ms


def jw_parts(p: fmpq_poly) -> tuple[fmpq_poly, fmpq_poly]:
    """Real and imaginary parts of p(jw) as real polynomials in w."""
    coeffs = p.coeffs()
    sign = (1, 1, -1, -1)
    re = [c * sign[k % 4] if k % 2 == 0 else 0 for k, c in enumerate(coeffs)]
    im = [c * sign[k % 4] if k % 2 == 1 else 0 for k, c in enumerate(coeffs)]
    return fmpq_poly(re), fmpq_poly(im)


def sign_polynomials(model: ExactModel) -> list[fmpq_poly]:
    """The polynomials whose non-negativity on the band Coq asks (``sign_polys``)."""
    n, m = model.n, model.m
    A = _mat(model.A, n, n)
    B, C, D = _mat(model.B, n, m), _mat(model.C, m, n), _mat(model.D, m, m)
    cs, Ms = charpoly_adj(A)
    coeff_mats = [C * M * B + D * c for c, M in zip(cs, Ms, strict=False)] + [D * cs[-1]]
    N = [[fmpq_poly([M[i, k] for M in coeff_mats]) for k in range(m)] for i in range(m)]
    dr, di = jw_parts(fmpq_poly(cs))
    parts = [[jw_parts(N[i][k]) for k in range(m)] for i in range(m)]

    def mt_re(i: int, k: int) -> fmpq_poly:
        return dr * (parts[i][k][0] + parts[k][i][0]) + di * (parts[i][k][1] + parts[k][i][1])

    def mt_im(i: int, k: int) -> fmpq_poly:
        return dr * (parts[i][k][1] - parts[k][i][1]) - di * (parts[i][k][0] - parts[k][i][0])

    if m == 1:
        return [mt_re(0, 0)]
    if m == 2:
        return [mt_re(0, 0) + mt_re(1, 1),
                mt_re(0, 0) * mt_re(1, 1) - (mt_re(0, 1) ** 2 + mt_im(0, 1) ** 2)]
    raise CoqExportError(f"{m} ports: the criterion on principal minors is proved in Coq "
                         "for one or two ports only")


# the unit ---------------------------------------------------------------------------------

def q_text(x: fmpq) -> str:
    return q_literal(Fraction(int(x.p), int(x.q)))


def poly_literal(p: fmpq_poly) -> str:
    return "[" + "; ".join(q_text(c) for c in p.coeffs()) + "]"


def witness_literal(w: iw.NonnegWitness) -> str:
    pieces = []
    for pc in w.pieces:
        terms = "; ".join(f"({q_text(c)}, {i}%nat, {j}%nat)" for c, i, j in pc.terms)
        pieces.append(f"({q_text(pc.u)}, {q_text(pc.v)},\n     [{terms}])")
    return (f"({poly_literal(w.g)},\n   {poly_literal(w.q)},\n   ["
            + ";\n    ".join(pieces) + "])")


def model_lines(model: ExactModel, margin: Fraction) -> list[str]:
    """The unit's preamble and the model's matrices (and nu0, D_shifted for a margin)."""
    n, m = model.n, model.m
    lines = [
        "From Coq Require Import QArith List.",
        "From VerifyCoq Require Import QCert BandCert.",
        "Import ListNotations.",
        "Local Open Scope Q_scope.",
        "",
        f"(** The model: {n} states, {m} port(s); x' = A x + B u, y = C x + D u. *)",
        f"Definition A : matQ :=\n  {matrix_literal(model.A)}.",
        f"Definition B : matQ :=\n  {matrix_literal(model.B)}.",
        f"Definition C : matQ :=\n  {matrix_literal(model.C)}.",
        f"Definition D : matQ :=\n  {matrix_literal(model.D)}.",
    ]
    if margin != 0:
        lines.append(f"(** H - nu0 I has the realisation (A, B, C, D - nu0 I). *)\n"
                     f"Definition nu0 : Q := {q_literal(margin)}.\n"
                     f"Definition D_shifted : matQ := msub D (scaled_identity {m} nu0).")
    return lines


def band_unit(name: str, *, model: ExactModel, band: tuple[Fraction, Fraction],
              margin: Fraction, label: str, source: str, fingerprint: str,
              origin: str) -> CoqUnit:
    """The unit proving ``band_passive`` for H - margin I (``model`` is H, unshifted).

    Raises CoqExportError when no witness is found (the claim may be false) or the model
    has more than two ports.
    """
    from verify.passivity.io.binding import shifted

    w1, w2 = (fmpq(int(x.numerator), int(x.denominator)) for x in band)
    if not w1 < w2:
        raise CoqExportError("the band is not w1 < w2")
    target = shifted(model, margin)
    witnesses = []
    for k, p in enumerate(sign_polynomials(target), start=1):
        found = iw.find(p, w1, w2)
        if found is None:
            raise CoqExportError(f"no witness that sign polynomial {k} is >= 0 on the band "
                                 "(it is negative somewhere inside, or the search budget "
                                 "was spent)")
        witnesses.append(found)
    n, m = model.n, model.m
    d_name = "D" if margin == 0 else "D_shifted"
    bound = "0" if margin == 0 else f"2 nu0 I, nu0 = {margin},"
    lines = [
        f"(** {comment_text(origin)}: exported by verify; checked by coqc.",
        f"    Model: {comment_text(label)}",
        f"    Source file: {comment_text(source)}",
        f"    Fingerprint (sha256 of the exact A, B, C, D): {fingerprint}",
        f"    Claim: H(jw) + H(jw)^H >= {bound} for {band[0]} <= w <= {band[1]} rad/s "
        "wherever H(jw) is",
        "    defined ([band_passive] in BandCert.v): Coq computes d(s) = det(sI - A) and "
        "Adj(s),",
        "    checks (sI - A) Adj(s) = d(s) I, and states Re z^H (H(jw) + H(jw)^H) z >= 0 for "
        "H(jw) =",
        "    N(jw) / d(jw), N(s) = C Adj(s) B + d(s) D.  Trusted, not proved here: that this "
        "H(jw) is",
        "    C (jwI - A)^-1 B + D (a matrix inverse from the checked identity).",
        "    The witnesses: for each sign polynomial p of the Hermitian numerator (BandCert.v"
        "),",
        "    p = g^2 q and q = sum c (x - u)^i (v - x)^j with c >= 0 on each piece [u, v] of "
        "the band. *)",
        "",
        *model_lines(model, margin),
    ]
    lines += [
        f"Definition w1 : Q := {q_literal(band[0])}.",
        f"Definition w2 : Q := {q_literal(band[1])}.",
        "",
        "(** Witnesses (data Coq re-checks), one per sign polynomial: (g, q, pieces). *)",
    ]
    for k, w in enumerate(witnesses, start=1):
        lines.append(f"Definition cert{k} : nonneg_cert :=\n  {witness_literal(w)}.")
    names = "; ".join(f"cert{k}" for k in range(1, len(witnesses) + 1))
    lines += [
        f"Definition certs : list nonneg_cert := [{names}].",
        "",
        f"Theorem {THEOREM} : band_passive {n} {m} A B C {d_name} w1 w2.",
        "Proof.",
        f"  apply (band_check_sound {n} {m} A B C {d_name} w1 w2 certs).",
        "  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)",
        "Qed.",
        "",
    ]
    return CoqUnit(name, "\n".join(lines), (THEOREM,), origin)


def read_checked_fd(path: Path, schema: str, kind: str, check) -> tuple[dict, ExactModel,
                                                                       Fraction]:
    """A stored frequency-domain certificate (exact-band or positive-real) read strictly,
    of ``schema``, and accepted by the Python exact checker ``check(data, path)`` with its
    binding: ``(data, H as given, margin)``; CoqExportError, one line, otherwise."""
    from verify.passivity.check.fd_certificate import model_from_json
    from verify.passivity.io.binding import shifted
    from verify.passivity.io.strict_json import CertificateFormatError, rational, read_strict

    try:
        data = read_strict(path)
        if data.get("schema") != schema:
            raise CoqExportError(f"{path.name}: not {kind} certificate "
                                 f"(schema {data.get('schema')!r})")
        result = check(data, path)
    except CertificateFormatError as exc:
        raise CoqExportError(f"{path.name}: {exc}") from None
    if not result.ok:
        raise CoqExportError(f"{path.name}: not exported: {result.reason}")
    margin = rational(data["meta"]["margin"], "meta.margin")
    return data, shifted(model_from_json(data), -margin), margin


def band_fd_unit_from_file(path: Path) -> CoqUnit:
    """The unit of a stored exact-band certificate, after the exact checker and the
    binding accept it (CoqExportError, one line, otherwise)."""
    from verify.passivity.check.band_fd import check_band_fd_file
    from verify.passivity.io.strict_json import rational

    path = Path(path)
    data, given, margin = read_checked_fd(path, SCHEMA, "an exact-band", check_band_fd_file)
    band = (rational(data["band"][0], "band"), rational(data["band"][1], "band"))
    try:
        return band_unit(module_name(path.name), model=given, band=band, margin=margin,
                         label=data["name"], source=data["source"],
                         fingerprint=data["fingerprint"],
                         origin=f"Exact-band certificate {path.name}")
    except CoqExportError as exc:
        raise CoqExportError(f"{path.name}: {exc}") from None
