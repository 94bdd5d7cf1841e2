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
from fractions import Fraction
from functools import reduce
from math import lcm
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


def kyp_unit(name: str, *, model: ExactModel, P: ex.RationalMatrix, margin: Fraction,
             label: str, source: str, fingerprint: str, origin: str) -> CoqUnit:
    """The Coq unit proving ``kyp_certified`` for (A, B, C, D - margin I) and P.

    Raises CoqExportError when P is not a KYP certificate of that model (no witness).
    """
    n, m = model.n, model.m
    if n == 0:
        raise CoqExportError("a model without states (a static gain) has no KYP matrix P "
                             "to export")
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
        "Local Open Scope Q_scope.",
        "",
        f"(** The model: {n} states, {m} ports; x' = A x + B u, y = C x + D u.",
        "    Each matrix is written over one common denominator ((2 # 2) is 1, (0 # 2) is 0).",
        "    *)",
        f"Definition A : matQ :=\n  {matrix_literal(model.A)}.",
        f"Definition B : matQ :=\n  {matrix_literal(model.B)}.",
        f"Definition C : matQ :=\n  {matrix_literal(model.C)}.",
        f"Definition D : matQ :=\n  {matrix_literal(model.D)}.",
    ]
    if margin != 0:
        d_name = "D_shifted"
        lines.append(f"(** H - nu0 I has the realisation (A, B, C, D - nu0 I). *)\n"
                     f"Definition nu0 : Q := {q_literal(margin)}.\n"
                     f"Definition D_shifted : matQ := msub D (scaled_identity {m} nu0).")
    lines += [
        "",
        "(** The certificate. *)",
        f"Definition P : matQ :=\n  {matrix_literal(P)}.",
        "",
        f"(** Witnesses (data Coq re-checks): P - eP I = sum of wP terms + a dominant "
        f"residual ({wP.method});",
        f"    -M(P) - eM I likewise ({wM.method}). *)",
        f"Definition eP : Q := {q_literal(wP.eps)}.",
        f"Definition wP : list term :=\n  {terms_literal(wP)}.",
        f"Definition eM : Q := {q_literal(wM.eps)}.",
        f"Definition wM : list term :=\n  {terms_literal(wM)}.",
        "",
        f"Theorem {THEOREM} : kyp_certified {n} {m} A B C {d_name} P.",
        "Proof.",
        f"  apply (kyp_check_sound {n} {m} A B C {d_name} P eP wP eM wM).",
        "  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)",
        "Qed.",
        "",
    ]
    return CoqUnit(name, "\n".join(lines), (THEOREM,), origin)


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
