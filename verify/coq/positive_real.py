"""Positive-real certificates as Coq units: their frequency-domain inequality (Section 4).

A ``verify-pr-certificate/1`` says that H(s) = C (sI - A)^-1 B + D is positive real: no
pole in Re s > 0, simple imaginary-axis poles with Hermitian positive semidefinite
residues, and H(jw) + H(jw)^H >= 0 for every real w (the paper's nu(w) >= 0 for all w).
The unit written here proves the last part, ``fdi_holds`` of ``BandCert.v``: the
Hermitian part of H(jw) is >= 0 at every w >= 0 where d(jw) != 0 (w < 0 is the complex
conjugate), from the same sign polynomials as an exact-band unit
(:mod:`verify.coq.band_fd`) and half-line witnesses
(:func:`verify.coq.interval_witness.find_ray`). The pole conditions are the unit's second
theorem when A is Hurwitz (``stable``, :mod:`verify.coq.lyapunov`: a Lyapunov witness,
no pole with Re s >= 0, so no residue condition to check); otherwise (an imaginary-axis
pole) they are not stated in Coq and :data:`NOT_KERNEL_CHECKED` says so, in the unit and
in the development's list.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

from flint import fmpq

from verify.coq import interval_witness as iw
from verify.coq.band_fd import (
    model_lines,
    poly_literal,
    q_text,
    read_checked_fd,
    sign_polynomials,
    witness_literal,
)
from verify.coq.kyp import CoqExportError, module_name
from verify.coq.lyapunov import THEOREM as POLES_THEOREM
from verify.coq.lyapunov import lyapunov_lines
from verify.coq.unit import CoqUnit, comment_text
from verify.passivity.check.certificate import ExactModel

THEOREM = "frequency_inequality"
SCHEMA = "verify-pr-certificate/1"

#: What the unit of a positive-real certificate leaves to the Python exact checker.
NOT_KERNEL_CHECKED = (
    "the pole conditions of positive realness (no pole in Re s > 0 by the Routh table; "
    "simple imaginary-axis poles with Hermitian positive semidefinite residues) are not "
    "stated in Coq: the unit proves the frequency-domain inequality H(jw) + H(jw)^H >= 0 "
    "for every w >= 0 ([fdi_holds]); the rest is checked by the Python exact checker only")


def _ray_literal(w: iw.RayWitness) -> str:
    bounded = witness_literal(iw.NonnegWitness(w.g, w.q, w.pieces)) if w.pieces else \
        f"({poly_literal(w.g)},\n   {poly_literal(w.q)},\n   [])"
    terms = "; ".join(f"({q_text(c)}, {i}%nat)" for c, i in w.ray)
    return f"({bounded},\n   ({q_text(w.u)}, [{terms}]))"


def pr_unit(name: str, *, model: ExactModel, margin: Fraction, label: str, source: str,
            fingerprint: str, origin: str) -> CoqUnit:
    """The unit proving ``fdi_holds`` for H - margin I (``model`` is H, unshifted).

    Raises CoqExportError when no witness is found or the model has more than two ports.
    """
    from verify.passivity.io.binding import shifted

    witnesses = []
    for k, p in enumerate(sign_polynomials(shifted(model, margin)), start=1):
        found = iw.find_ray(p, fmpq(0))
        if found is None:
            raise CoqExportError(f"no witness that sign polynomial {k} is >= 0 on [0, oo)")
        witnesses.append(found)
    n, m = model.n, model.m
    d_name = "D" if margin == 0 else "D_shifted"
    bound = "0" if margin == 0 else f"2 nu0 I, nu0 = {margin},"
    poles = lyapunov_lines(model.A, n)
    if poles is None:
        missing = "    matrix inverse behind it trusted).  Not kernel-checked: " \
            + comment_text(NOT_KERNEL_CHECKED.split(" are not stated in Coq")[0]) + "."
    else:
        missing = ("    matrix inverse behind it trusted).  The pole conditions: theorem "
                   "[stable], every eigenvalue\n    of A has Re < 0 ([hurwitz] in "
                   "PoleCert.v), so H has no pole with Re s >= 0.")
    preamble = model_lines(model, margin)
    if poles is not None:
        preamble[1] = "From VerifyCoq Require Import QCert BandCert PoleCert."
    lines = [
        f"(** {comment_text(origin)}: exported by verify; checked by coqc.",
        f"    Model: {comment_text(label)}",
        f"    Source file: {comment_text(source)}",
        f"    Fingerprint (sha256 of the exact A, B, C, D): {fingerprint}",
        f"    Claim: H(jw) + H(jw)^H >= {bound} for every w >= 0 wherever H(jw) is defined",
        "    ([fdi_holds] in BandCert.v; H(jw) = N(jw) / d(jw) as in BandCert.v's header, "
        "the",
        missing,
        "    The witnesses: for each sign polynomial p, p = g^2 q, q in Bernstein form on "
        "pieces",
        "    of [0, u] and q = sum c (x - u)^i with c >= 0 on [u, oo). *)",
        "",
        *preamble,
        "",
        "(** Witnesses (data Coq re-checks), one per sign polynomial: (g, q, pieces, ray). *)",
    ]
    for k, w in enumerate(witnesses, start=1):
        lines.append(f"Definition cert{k} : ray_cert :=\n  {_ray_literal(w)}.")
    names = "; ".join(f"cert{k}" for k in range(1, len(witnesses) + 1))
    lines += [
        f"Definition certs : list ray_cert := [{names}].",
        "",
        f"Theorem {THEOREM} : fdi_holds {n} {m} A B C {d_name}.",
        "Proof.",
        f"  apply (fdi_check_sound {n} {m} A B C {d_name} certs).",
        "  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)",
        "Qed.",
        *(poles or []),
        "",
    ]
    theorems = (THEOREM,) if poles is None else (THEOREM, POLES_THEOREM)
    return CoqUnit(name, "\n".join(lines), theorems, origin)


def pr_unit_from_file(path: Path) -> CoqUnit:
    """The unit of a stored positive-real certificate, after the exact checker and the
    binding accept it (CoqExportError, one line, otherwise)."""
    from verify.passivity.check.fd_certificate import check_pr_file

    path = Path(path)
    data, given, margin = read_checked_fd(path, SCHEMA, "a positive-real", check_pr_file)
    try:
        return pr_unit(module_name(path.name), model=given, margin=margin,
                       label=data["name"], source=data["source"],
                       fingerprint=data["fingerprint"],
                       origin=f"Positive-real certificate {path.name}")
    except CoqExportError as exc:
        raise CoqExportError(f"{path.name}: {exc}") from None
