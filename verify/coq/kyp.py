"""KYP certificates as Coq units: passivity in the LMI form of the positive-real lemma.

The paper's Section 4 asks that the human's model H be passive, and Theorem 1's storage
function of the human is then x^T P x / 2 for a KYP certificate P. A certificate file
(``verify-kyp-certificate/1`` or ``/2``) stores the model H as exact matrices
(A, B, C, D), a margin nu0 and the matrix P. The unit written here states,
from the definitions of the prelude ``QCert.v``,

    kyp_certified n m A B C (D - nu0 I) P :
      the shapes match, P = P^T, P > 0 and
      M(P) = [[A^T P + P A, P B - C^T], [B^T P - C, -(D + D^T - 2 nu0 I)]] <= 0,

with P > 0 and M(P) <= 0 meaning x^T P x > 0 for every real x != 0 and
x^T M(P) x <= 0 for every real x. Coq computes M(P) from the data itself; the
witnesses (:mod:`verify.coq.witness`) are data that Coq re-checks by computation, and
the lemma turning the check into the statement is proved once in the prelude. A comment
names the model (its file and sha256 fingerprint), so a reader can compare.

The exporter refuses (``CoqExportError``) a certificate that is not bound to its claim
(fingerprint, file name, statement: :func:`verify.passivity.io.certificate_files.check_binding`)
or for which no witness is found; it never writes a unit that states something else.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from functools import reduce
from math import gcd, lcm
from pathlib import Path
from typing import Any

from gmpy2 import mpq

from verify.coq.unit import CoqExportError, CoqUnit, comment_text
from verify.coq.witness import Witness, psd_witness
from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel, kyp_matrix
from verify.passivity.io import certificate_files as cf
from verify.passivity.io.binding import shifted

#: The theorem every KYP unit proves.
THEOREM = "passive"


def q_literal(x: mpq | Fraction | int, den: int | None = None) -> str:
    """A rational as a Coq ``Q`` literal ``(p # q)``; over ``den`` (a multiple of its
    denominator) when given: the same rational, written unreduced."""
    x = mpq(x)
    if den is None:
        return f"({int(x.numerator)} # {int(x.denominator)})"
    return f"({int(x * den)} # {den})"


def common_denominator(values) -> int:
    """The least common denominator of the values (1 for none)."""
    return int(reduce(lcm, (int(mpq(x).denominator) for x in values), 1))


#: A matrix is written over two denominators (one for its dyadic entries, one for the
#: rest) when one common denominator would lengthen its dyadic entries by more bits.
SPLIT_BITS = 64


def _is_dyadic(x: mpq) -> bool:
    d = int(mpq(x).denominator)
    return d & (d - 1) == 0


def entry_denominators(values) -> list[int]:
    """The denominator each entry is written over: one common denominator, or, when that
    would lengthen the dyadic entries (0 and integers included) by more than
    ``SPLIT_BITS`` bits, the common denominator of the dyadic entries for them and that
    of the others for the rest. ``QCert.dot`` sums a product of such matrices in one bin
    of numerators per pair of denominators."""
    values = [mpq(x) for x in values]
    whole = common_denominator(values)
    dyadic = common_denominator(x for x in values if _is_dyadic(x))
    if whole.bit_length() - dyadic.bit_length() <= SPLIT_BITS:
        return [whole] * len(values)
    rest = common_denominator(x for x in values if not _is_dyadic(x))
    return [dyadic if _is_dyadic(x) else rest for x in values]


def matrix_literal(m: ex.RationalMatrix, indent: str = "  ") -> str:
    """A matrix as a Coq ``list (list Q)``, one row a line, its entries over one common
    denominator (``QCert.qadd`` then adds them by their numerators), or over two
    (:func:`entry_denominators`)."""
    if not m:
        return "[]"
    dens = iter(entry_denominators(x for row in m for x in row))
    rows = [f"[{'; '.join(q_literal(x, next(dens)) for x in row)}]" for row in m]
    return "[" + (";\n" + indent + " ").join(rows) + "]"


def terms_literal(w: Witness) -> str:
    """The terms of a witness as a Coq ``list term`` (the weights over one denominator,
    the vectors' entries over another)."""
    if not w.terms:
        return "[]"
    dd = common_denominator(d for d, _ in w.terms)
    dl = common_denominator(x for _, vec in w.terms for x in vec)
    items = [f"({q_literal(d, dd)}, [{'; '.join(q_literal(x, dl) for x in vec)}])"
             for d, vec in w.terms]
    return "[" + ";\n   ".join(items) + "]"


def module_name(file_name: str) -> str:
    """A Coq module name for a certificate file name (letters, digits, underscores)."""
    stem = file_name[:-5] if file_name.endswith(".json") else file_name
    return "Cert_" + re.sub(r"[^A-Za-z0-9]+", "_", stem).strip("_")


#: Limbs of the integers written on machine words (``QCert.wnum``): base 2^62.
LIMB_BITS = 62


def word_literal(x: int, second: bool = False) -> str:
    """An integer as a Coq ``QCert.wnum`` literal: ``(Wp w)``, ``(Wn w)`` for one limb over
    the first denominator, else ``(Wl neg second [w0; w1; ...])`` (limbs of 62 bits, least
    significant first)."""
    x = int(x)
    mag = abs(x)
    if not second and mag < 1 << LIMB_BITS:
        return f"(Wp {mag})" if x >= 0 else f"(Wn {mag})"
    limbs = []
    while mag:
        limbs.append(mag & ((1 << LIMB_BITS) - 1))
        mag >>= LIMB_BITS
    flag = "true" if x < 0 else "false"
    return f"(Wl {flag} {'true' if second else 'false'} [{'; '.join(map(str, limbs))}])"


def _words_rows(rows) -> str:
    return "[" + ";\n   ".join("[" + "; ".join(row) + "]" for row in rows) + "]"


@dataclass(frozen=True)
class WordMatrix:
    """A rational matrix as ``QCert.wmat`` data: two denominators d1, d2 and each entry's
    numerator over one of them; ``scaled`` is the integer matrix d1 d2 X that Coq's
    ``zmatw`` computes from it."""

    d1: int
    d2: int
    text: str
    scaled: list[list[int]]

    @property
    def scale(self) -> int:
        return self.d1 * self.d2


def word_matrix(m: ex.RationalMatrix) -> WordMatrix:
    """The data of a rational matrix on machine words (:func:`entry_denominators`)."""
    values = [mpq(x) for row in m for x in row]
    dens = entry_denominators(values)
    d1 = dens[0] if values else 1
    d2 = next((d for d in dens if d != d1), 1)
    it = iter(dens)
    rows, scaled = [], []
    for row in m:
        lits, ints = [], []
        for x in row:
            d = next(it)
            second = d != d1
            num = int(mpq(x) * d)
            lits.append(word_literal(num, second))
            ints.append(num * (d1 if second else d2))
        rows.append(lits)
        scaled.append(ints)
    return WordMatrix(d1, d2, _words_rows(rows), scaled)


def word_witness(w: Witness, scale: int) -> str:
    """A witness for a matrix M as a ``QCert.wwit`` for the integer matrix ``scale M``:
    (e, den, c, weights, vectors) with ``den scale M - e I - c sum_k w_k u_k u_k^T``
    equal to ``den scale`` times the rational residual (so dominant exactly when it is);
    c is the weights' greatest common divisor."""
    terms = list(w.terms)
    vectors, weights = [], []
    for d, vec in terms:
        q = common_denominator(vec)
        vectors.append([int(mpq(x) * q) for x in vec])
        weights.append(mpq(d) * scale / (q * q))
    eps = mpq(w.eps) * scale
    den = common_denominator([eps, *weights])
    e = int(eps * den)
    ints = [int(x * den) for x in weights]
    c = reduce(gcd, ints, 0) or 1  # the common factor, applied after the sum
    ws = "; ".join(word_literal(x // c) for x in ints)
    vs = _words_rows([[word_literal(v) for v in vec] for vec in vectors])
    return (f"({word_literal(e)}, {word_literal(den)}, {word_literal(c)},\n   [{ws}],\n"
            f"   {vs})")


def kyp_unit(name: str, *, model: ExactModel, P: ex.RationalMatrix, margin: Fraction,
             label: str, source: str, fingerprint: str, origin: str) -> CoqUnit:
    """The Coq unit proving ``kyp_certified`` for (A, B, C, D - margin I) and P.

    The data of A, B, C and P are written on machine words and checked on integers
    (``QCert.kyp_wcheck``): Coq computes the integer matrices s P and L M(P) from them
    and checks the witnesses there. Raises CoqExportError when P is not a KYP
    certificate of that model (no witness).
    """
    n, m = model.n, model.m
    if n == 0:
        raise CoqExportError("a model without states (a static gain) has no KYP matrix P "
                             "to export")
    if m == 0:
        raise CoqExportError("a model without ports has no KYP matrix to export")
    target = shifted(model, margin)
    wP = psd_witness(P, strict=True)
    if wP is None:
        raise CoqExportError("no witness that P > 0 (P is not positive definite, or "
                             "too close to singular for the rounded factor)")
    negM = ex.scale(-1, kyp_matrix(target, P))
    wM = psd_witness(negM)
    if wM is None:
        raise CoqExportError("no witness that M(P) <= 0 (the KYP matrix is not negative "
                             "semidefinite, or has no room for the rounded factor)")
    wA, wB, wC, wPm = (word_matrix(x) for x in (model.A, model.B, model.C, P))
    dD = common_denominator(x for row in target.D for x in row)
    WD = _words_rows([[word_literal(int(mpq(x) * dD)) for x in row] for row in target.D])
    L = wA.scale * wPm.scale * wB.scale * wC.scale * dD
    if not wP.terms:
        wP = Witness(wP.eps, ((mpq(0), (mpq(0),) * n),), wP.method)
    if not wM.terms:
        wM = Witness(wM.eps, ((mpq(0), (mpq(0),) * (n + m)),), wM.method)
    d_name = "D"
    lines = [
        f"(** {comment_text(origin)}: exported by verify; checked by coqc.",
        f"    Model: {comment_text(label)}",
        f"    Source file: {comment_text(source)}",
        f"    Fingerprint (sha256 of the exact A, B, C, D): {fingerprint}",
        "    Claim: H"
        + ("" if margin == 0 else f" - nu0 I, nu0 = {margin},")
        + " is passive, in the LMI form of the KYP lemma: P = P^T, P > 0 and",
        "    M(P) = [[A^T P + P A, P B - C^T], [B^T P - C, -(D + D^T"
        + ("" if margin == 0 else " - 2 nu0 I") + ")]] <= 0,",
        "    both as real quadratic forms ([kyp_certified] in QCert.v). *)",
        "",
        "From Coq Require Import QArith List.",
        "From VerifyCoq Require Import QCert.",
        "Import ListNotations.",
        "Import Uint63.",
        "Local Open Scope Q_scope.",
        "Local Open Scope uint63_scope.",
        "",
        f"(** The model: {n} states, {m} ports; x' = A x + B u, y = C x + D u.",
        "    A, B, C (and P below) are data on machine words ([qmatw] in QCert.v): two",
        "    denominators, then each entry's numerator, (Wp k) = k, (Wn k) = -k, and",
        "    (Wl neg second [k0; k1; ...]) = +-(k0 + 2^62 k1 + ...) over the second",
        "    denominator when second = true, else over the first. *)",
    ]
    for nm, wm in (("A", wA), ("B", wB), ("C", wC)):
        lines.append(f"Definition W{nm} : wmat :=\n  ({wm.d1}%positive, {wm.d2}%positive,\n"
                     f"   {wm.text}).\nDefinition {nm} : matQ := qmatw W{nm}.")
    lines.append(f"Definition D : matQ :=\n  {matrix_literal(model.D)}.")
    if margin != 0:
        d_name = "D_shifted"
        lines.append(f"(** H - nu0 I has the realisation (A, B, C, D - nu0 I). *)\n"
                     f"Definition nu0 : Q := {q_literal(margin)}.\n"
                     f"Definition D_shifted : matQ := msub D (scaled_identity {m} nu0).")
    lines += [
        f"(** {d_name} times dD, as integers (Coq checks that they are). *)",
        f"Definition dD : positive := {dD}%positive.",
        f"Definition WD : list (list wnum) :=\n  {WD}.",
        "",
        "(** The certificate. *)",
        f"Definition WP : wmat :=\n  ({wPm.d1}%positive, {wPm.d2}%positive,\n   {wPm.text}).",
        "Definition P : matQ := qmatw WP.",
        "",
        "(** Witnesses (data Coq re-checks) on the integer matrices s P and L M(P), where",
        "    Coq computes both from the data: (e, den, [w_k], [u_k]) such that",
        "    den X - e I - sum_k w_k u_k u_k^T is diagonally dominant",
        f"    (P: {wP.method}; -M(P): {wM.method}). *)",
        f"Definition wP : wwit :=\n  {word_witness(wP, wPm.scale)}.",
        f"Definition wM : wwit :=\n  {word_witness(wM, L)}.",
        "",
        f"Theorem {THEOREM} : kyp_certified {n} {m} A B C {d_name} P.",
        "Proof.",
        f"  apply (kyp_wcheck_sound {n} {m} WA WB WC {d_name} dD WD WP wP wM).",
        "  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)",
        "Qed.",
        "",
    ]
    return CoqUnit(name, "\n".join(lines), (THEOREM,), origin, machine_words=True)


def read_bound_certificate(path: Path, schemas: tuple[str, ...],
                           parse: Callable[[dict], Any], kind: str) -> Any:
    """A stored certificate of one of ``schemas``, parsed strictly and bound to its model
    file (fingerprint, file name, statement re-derived); one-line CoqExportError if not."""
    from verify.passivity.io.strict_json import CertificateFormatError, read_strict

    path = Path(path)
    try:
        data = read_strict(path)
        if data.get("schema") not in schemas:
            raise CoqExportError(f"{path.name}: not a {kind} certificate "
                                 f"(schema {data.get('schema')!r})")
        cert = parse(data)
    except CertificateFormatError as exc:
        raise CoqExportError(f"{path.name}: {exc}") from None
    error, _note = cf.check_binding(cert, path)
    if error is not None:
        raise CoqExportError(f"{path.name}: not exported: {error}")
    return cert


def kyp_unit_from_file(path: Path) -> CoqUnit:
    """The unit of a stored KYP certificate file, after its binding is checked."""
    return kyp_units_from_file(path)[0]


def kyp_units_from_file(path: Path) -> list[CoqUnit]:
    """The unit of a stored KYP certificate file (after its binding is checked), then,
    when the certificate is for H itself (no margin) with 1 to 3 ports, the unit of
    Theorem 1 with that human in the loop (:mod:`verify.coq.thm1_lti`)."""
    from verify.coq.thm1_lti import thm1_unit

    path = Path(path)
    cert = read_bound_certificate(path, (cf.KYP_V1, cf.KYP_V2), cf.parse_kyp, "KYP")
    origin = f"KYP certificate {path.name}"
    try:
        unit = kyp_unit(module_name(path.name), model=cert.model, P=cert.P,  # type: ignore[arg-type]
                        margin=cert.claim.margin, label=cert.name, source=cert.source,
                        fingerprint=cert.fingerprint, origin=origin)
    except CoqExportError as exc:
        raise CoqExportError(f"{path.name}: {exc}") from None
    if cert.claim.margin != 0 or not 1 <= cert.model.m <= 3:
        return [unit]
    return [unit, thm1_unit(unit.name, cert.model.n, cert.model.m, label=cert.name,
                            origin=origin)]
