"""Theorem 1 with a certified LTI human: the unit written next to a KYP certificate's unit.

A KYP certificate unit (:mod:`verify.coq.kyp`) proves ``kyp_certified n m A B C D P`` for
the human's model H (Section 4). The unit written here (``Thm1_<certificate>``)
``Require``s it and states Theorem 1 of Section 3 for that human in the loop, from the
prelude's ``LTIHuman.v`` (the storage xᵀPx/2 and its dissipation inequality) and
``Thm1LTI.v`` (the closed loop): along every solution of eq. (13), eq. (12b) with
ω_h^s = R_l ω_h^b and the human's state equation, with item 2 along it,

- ``thm1_energy``: V = φ(R_rᵀR̄) + φ(R_rᵀR_l) + xᵀPx/2 has V̇ ≤ -k_s λ φ(R_lᵀR̄), does
  not increase, V(t) + ∫₀ᵗ k_s λ φ(R_lᵀR̄) ≤ V(0), xᵀPx ≤ 2 V(0), and c |x|² ≤ 2 V(0) for
  some c > 0 (the human's state is bounded: Assumption 1, item 4, proved for it);
- ``thm1_sync``: on [0, ∞), with t ↦ φ(R_lᵀR̄(t)) Lipschitz (a named premise),
  φ(R_lᵀR̄(t)) → 0.

The matrices A, B, C, D, P are the certificate unit's definitions (no number is written
here) and the KYP premise is discharged by its theorem ``passive``. The text is a fixed
template: the only file-derived parts are the certificate's module name (made by
:func:`verify.coq.kyp.module_name`, letters, digits and underscores), the dimensions
(integers) and comments made inert (:func:`verify.coq.text.inert_comment`); the
statements are recorded for the audit's round trip.
"""

from __future__ import annotations

import re

from verify.coq.unit import CoqExportError, CoqUnit, comment_text

#: Top theorems of a Theorem 1 unit, with the premises a report names for each.
THEOREMS: dict[str, str] = {
    "thm1_energy": (
        "k_s > 0; R_r a constant rotation; R̄, R_l rotations on [0, T], differentiable with "
        "eq. (13) and eq. (12b) with ω_h^s = R_l ω_h^b; the human's state x differentiable "
        "with x' = A x + B E sk(R_lᵀR_r)^∨ and ω_h^b = Eᵀ(C x + D E sk(R_lᵀR_r)^∨) "
        "(A, B, C, D, P from the KYP certificate unit, whose theorem passive discharges the "
        "passivity premise); a uniform λ > 0 below λmin(sym R_rl(t)) (item 2); "
        "tr(R_rᵀR̄(0)) ≥ 1"),
    "thm1_sync": (
        "the premises of thm1_energy for every t ≥ 0; t ↦ φ(R_lᵀR̄(t)) Lipschitz "
        "(a bounded rate; not proved)"),
}

#: Prefix of the unit's module name (the certificate unit's is ``Cert_``).
PREFIX = "Thm1_"
_CERT_MODULE = re.compile(r"Cert_[A-Za-z0-9_]+\Z")

_LOOP = """\
  0 < ks -> 0 < lam ->
  is_rot Rr ->
  (forall t, {dom} -> is_rot (Rb t)) ->
  (forall t, {dom} -> is_rot (Rl t)) ->
  (forall t, {dom} ->
     is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))) ->
  (forall t, {dom} ->
     is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                            (mvmul (mT (Rl t)) (w_s {n} {m} C D Rr Rl x t)))))) ->
  (forall t, {dom} -> forall i, (i < {n})%nat ->
     is_derive (fun s => x s i) t (LTIHuman.lti_rate {n} {m} A B x (u_h Rr Rl) t i)) ->
  (forall t, {dom} -> lam_min_spec (mmul (mT Rr) (Rl t)) lam) ->
  1 <= tr (mmul (mT Rr) (Rb 0)) ->"""

_ENERGY = """\
forall (Rr : M3) (Rb Rl : R -> M3) (x : R -> nat -> R) (ks lam T : R),
{loop}
  (forall t, 0 <= t <= T ->
     is_derive (V Rr Rb Rl (S_h {n} P x)) t
       (dV Rr Rb Rl (w_s {n} {m} C D Rr Rl x) (dS_h {n} {m} A B P Rr Rl x) ks t)
     /\\ dV Rr Rb Rl (w_s {n} {m} C D Rr Rl x) (dS_h {n} {m} A B P Rr Rl x) ks t
        <= - (ks * lam) * phi (mmul (mT (Rl t)) (Rb t))) /\\
  (forall s t, 0 <= s -> s <= t -> t <= T ->
     V Rr Rb Rl (S_h {n} P x) t <= V Rr Rb Rl (S_h {n} P x) s) /\\
  (forall t, 0 <= t <= T ->
     ex_RInt (fun s => ks * lam * phi (mmul (mT (Rl s)) (Rb s))) 0 t /\\
     V Rr Rb Rl (S_h {n} P x) t + RInt (fun s => ks * lam * phi (mmul (mT (Rl s)) (Rb s))) 0 t
       <= V Rr Rb Rl (S_h {n} P x) 0) /\\
  (forall t, 0 <= t <= T ->
     0 <= S_h {n} P x t /\\ QCert.qform {n} P (x t) <= 2 * V Rr Rb Rl (S_h {n} P x) 0) /\\
  (exists c, 0 < c /\\
     forall t, 0 <= t <= T -> c * LTIHuman.normsq {n} (x t) <= 2 * V Rr Rb Rl (S_h {n} P x) 0)"""

_SYNC = """\
forall (Rr : M3) (Rb Rl : R -> M3) (x : R -> nat -> R) (ks lam Lp : R),
{loop}
  0 < Lp ->
  (forall s t, 0 <= s -> 0 <= t ->
     Rabs (phi (mmul (mT (Rl t)) (Rb t)) - phi (mmul (mT (Rl s)) (Rb s))) <= Lp * Rabs (t - s)) ->
  forall eps, 0 < eps ->
  exists N, 0 <= N /\\ forall t, N <= t -> phi (mmul (mT (Rl t)) (Rb t)) < eps"""


def unit_name(cert_module: str) -> str:
    """The Theorem 1 unit's module name for a certificate unit ``Cert_<stem>``."""
    if not _CERT_MODULE.match(cert_module):
        raise ValueError(f"not a certificate unit's name: {cert_module!r}")
    return PREFIX + cert_module.removeprefix("Cert_")


def statements(n: int, m: int) -> dict[str, str]:
    """Theorem name -> statement (the text after ``Theorem name``), as the unit writes it."""
    energy_loop = _LOOP.format(dom="0 <= t <= T", n=n, m=m)
    sync_loop = _LOOP.format(dom="0 <= t", n=n, m=m)
    return {"thm1_energy": _ENERGY.format(loop=energy_loop, n=n, m=m),
            "thm1_sync": _SYNC.format(loop=sync_loop)}


def thm1_unit(cert_module: str, n: int, m: int, *, label: str, origin: str) -> CoqUnit:
    """The Theorem 1 unit for the human of the certificate unit ``cert_module``, with
    ``n`` states and ``m`` ports; CoqExportError when the model does not fit the loop
    (no state, or not 1 to 3 ports)."""
    if not (isinstance(n, int) and isinstance(m, int)) or n < 1:
        raise CoqExportError("Theorem 1 needs a human model with at least one state")
    if not 1 <= m <= 3:
        raise CoqExportError(f"Theorem 1's loop has three-vector signals; a model with {m} "
                             "ports does not fit it")
    name = unit_name(cert_module)
    mats = "A B C D P"
    stated = statements(n, m)
    lines = [
        f"(** Theorem 1 with the human of {comment_text(origin)}: exported by verify; "
        "checked by coqc.",
        f"    Model: {comment_text(label)} ({n} states, {m} ports).",
        "    The human's realisation (A, B, C, D) and storage x^T P x / 2 are those of the",
        f"    certificate unit {cert_module} (its theorem passive: kyp_certified); the loop",
        "    and the embedding of the model's ports are those of the prelude Thm1LTI.v. *)",
        "",
        "From Coq Require Import Reals Lia.",
        "From Coquelicot Require Import Coquelicot.",
        "From VerifyCoq Require Import SO3 RotSurj Traj Lemma1Inv Thm1Energy Barbalat Thm1LTI.",
        f"From VerifyCoq Require QCert LTIHuman {cert_module}.",
        "Open Scope R_scope.",
        "",
        "(** The human's realisation and the certificate's P: the certificate unit's data. *)",
        *(f"Definition {k} : QCert.matQ := {cert_module}.{k}." for k in "ABCDP"),
        "",
        "(** Along every solution on [0, T]: V does not increase, its rate is at most",
        "    - k_s lam phi(R_l^T R-bar), the dissipation inequality in integral form, and the",
        "    human's state stays in the sublevel set x^T P x <= 2 V(0), so it is bounded:",
        "    c |x|^2 <= 2 V(0) for some c > 0 (P > 0). *)",
        f"Theorem thm1_energy :\n  {stated['thm1_energy']}.",
        "Proof.",
        "  intros Rr Rb Rl x ks lam T.",
        f"  exact (thm1_lti_energy {n} {m} {mats} ltac:(lia) ltac:(lia) ltac:(lia)",
        f"           {cert_module}.passive Rr Rb Rl x ks lam T).",
        "Qed.",
        "",
        "(** On [0, oo), with t -> phi(R_l^T R-bar(t)) Lipschitz: the leader and the",
        "    quasi-average synchronise. *)",
        f"Theorem thm1_sync :\n  {stated['thm1_sync']}.",
        "Proof.",
        "  intros Rr Rb Rl x ks lam Lp.",
        f"  exact (thm1_lti_sync {n} {m} {mats} ltac:(lia) ltac:(lia) ltac:(lia)",
        f"           {cert_module}.passive Rr Rb Rl x ks lam Lp).",
        "Qed.",
        "",
    ]
    return CoqUnit(name, "\n".join(lines), tuple(THEOREMS),
                   source=f"Theorem 1 with the human of {origin}",
                   statements=tuple((k, v) for k, v in stated.items()),
                   # it rests on the certificate unit's theorem, checked on machine words
                   machine_words=True)
