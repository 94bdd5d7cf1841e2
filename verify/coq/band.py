"""Band (generalized KYP) certificates as Coq units: passivity on a frequency band.

A ``verify-gkyp-certificate`` proves, for the model H of the paper's Section 4 and a band
[w1, w2], that H(jw) + H(jw)^H >= 2 nu0 I there, from Hermitian P = Pr + j Pi and
Q = Qr + j Qi with Q >= 0 and L(P, Q) <= 0 (the generalized KYP lemma; see
:mod:`verify.passivity.check.gkyp`). The unit states ``gkyp_certified`` of ``QCert.v``:
the shapes, 0 <= w1 < w2, P and Q Hermitian, the real form of Q >= 0 and the real form
of L(P, Q) <= 0 as real quadratic forms, with L computed by Coq from A, B, C, D (shifted
by nu0), P, Q, w1, w2. Witnesses are data Coq re-checks, as for KYP units.
"""

from __future__ import annotations

from pathlib import Path

from verify.coq.kyp import (
    CoqExportError,
    matrix_literal,
    module_name,
    q_literal,
    read_bound_certificate,
    terms_literal,
)
from verify.coq.unit import CoqUnit, comment_text
from verify.coq.witness import psd_witness
from verify.passivity.check import exact as ex
from verify.passivity.check.gkyp import embed, gkyp_matrix, is_hermitian
from verify.passivity.io import certificate_files as cf
from verify.passivity.io.binding import shifted

THEOREM = "passive_on_band"


def gkyp_unit_from_file(path: Path) -> CoqUnit:
    """The unit of a stored band (GKYP) certificate, after its binding is checked."""
    path = Path(path)
    cert = read_bound_certificate(path, (cf.BAND_V1, cf.BAND_V2), cf.parse_band, "band")
    assert cert.claim.band is not None and cert.Q is not None
    model, (w1, w2), margin = cert.model, cert.claim.band, cert.claim.margin
    n, m = model.n, model.m
    if n == 0:
        raise CoqExportError(f"{path.name}: a static gain has no band certificate to export")
    P, Q = cert.P, cert.Q
    if not (is_hermitian(P) and is_hermitian(Q)):  # type: ignore[arg-type]
        raise CoqExportError(f"{path.name}: P and Q must be Hermitian")
    wQ = psd_witness(embed(Q))
    Lr, Li = gkyp_matrix(shifted(model, margin), P, Q, (w1, w2))  # type: ignore[arg-type]
    wL = psd_witness(ex.scale(-1, embed((Lr, Li))))
    if wQ is None or wL is None:
        raise CoqExportError(f"{path.name}: no witness that Q >= 0 and L(P, Q) <= 0")
    d_name = "D" if margin == 0 else "D_shifted"
    lines = [
        f"(** Band certificate {comment_text(path.name)}: exported by verify; checked by "
        "coqc.",
        f"    Model: {comment_text(cert.name)}",
        f"    Source file: {comment_text(cert.source)}",
        f"    Fingerprint (sha256 of the exact A, B, C, D): {cert.fingerprint}",
        f"    Claim: H(jw) + H(jw)^H >= {'0' if margin == 0 else f'2 nu0 I, nu0 = {margin},'}"
        f" for {w1} <= w <= {w2} rad/s wherever H(jw) is defined, by the generalized KYP",
        "    lemma: P, Q Hermitian, Q >= 0 and L(P, Q) <= 0 ([gkyp_certified] in QCert.v).",
        "    Each matrix is written over one common denominator. *)",
        "",
        "From Coq Require Import QArith List.",
        "From VerifyCoq Require Import QCert.",
        "Import ListNotations.",
        "Local Open Scope Q_scope.",
        "",
        f"Definition A : matQ :=\n  {matrix_literal(model.A)}.",
        f"Definition B : matQ :=\n  {matrix_literal(model.B)}.",
        f"Definition C : matQ :=\n  {matrix_literal(model.C)}.",
        f"Definition D : matQ :=\n  {matrix_literal(model.D)}.",
    ]
    if margin != 0:
        lines.append(f"Definition nu0 : Q := {q_literal(margin)}.\n"
                     f"Definition D_shifted : matQ := msub D (scaled_identity {m} nu0).")
    lines += [
        f"Definition w1 : Q := {q_literal(w1)}.",
        f"Definition w2 : Q := {q_literal(w2)}.",
        "",
        "(** The certificate: P = Pr + j Pi, Q = Qr + j Qi. *)",
        f"Definition Pr : matQ :=\n  {matrix_literal(P[0])}.",
        f"Definition Pi : matQ :=\n  {matrix_literal(P[1])}.",
        f"Definition Qr : matQ :=\n  {matrix_literal(Q[0])}.",
        f"Definition Qi : matQ :=\n  {matrix_literal(Q[1])}.",
        "",
        f"(** Witnesses (data Coq re-checks): {wQ.method}; {wL.method}. *)",
        f"Definition eQ : Q := {q_literal(wQ.eps)}.",
        f"Definition wQ : list term :=\n  {terms_literal(wQ)}.",
        f"Definition eL : Q := {q_literal(wL.eps)}.",
        f"Definition wL : list term :=\n  {terms_literal(wL)}.",
        "",
        f"Theorem {THEOREM} : gkyp_certified {n} {m} A B C {d_name} Pr Pi Qr Qi w1 w2.",
        "Proof.",
        f"  apply (gkyp_check_sound {n} {m} A B C {d_name} Pr Pi Qr Qi w1 w2 eQ wQ eL wL).",
        "  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)",
        "Qed.",
        "",
    ]
    return CoqUnit(module_name(path.name), "\n".join(lines), (THEOREM,),
                   f"band certificate {path.name}")
