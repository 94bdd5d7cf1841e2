"""The paper's conclusions as Coq theorems along solutions (Section 3, Lemma 1, Theorem 1).

The proofs live in the prelude (``RotSurj.v``: every rotation matrix is ``rot q``;
``Traj.v``: derivatives of matrix trajectories; ``Lemma1Inv.v``: Lemma 1's invariance
by a last-exit argument). :func:`conclusion_units` writes one unit, fixed text with no
file-derived content, that restates each top theorem in full (so that a reader sees
the statement and its premises in one place, and ``All.v`` prints its assumptions) and
proves it by the prelude's lemma.
"""

from __future__ import annotations

from verify.coq.unit import CoqUnit

MODULE = "Conclusions"

#: Top theorems of the unit, with the premises a report names for each.
THEOREMS: dict[str, str] = {
    "every_rotation_is_rot_q": "M^T M = I and det M = 1",
    "lemma1_invariance_on_interval": (
        "k_s > 0; R_r a constant rotation; R̄(t) a rotation for t in [0, T]; R̄ "
        "differentiable on [0, T] with eq. (13); Assumption 1, item 2 along the solution "
        "(some λ > 0 below λmin(sym R_rl(t)) at every t)"),
    "lemma1_invariance_on_half_line": "the same premises for every t ≥ 0",
    "thm1_energy_nonincreasing": (
        "k_s > 0; R_r a constant rotation; R̄, R_l rotations on [0, T], differentiable "
        "with eq. (13) and eq. (12b) for any human command ω_h^s(t); the human passive "
        "with a differentiable storage S_h whose rate is at most <sk(R_lᵀR_r)^∨, ω_h^b> "
        "(Assumption 1, item 5, in differential form); a uniform λ > 0 below "
        "λmin(sym R_rl(t)) (item 2); tr(R_rᵀR̄(0)) ≥ 1"),
    "thm1_phi_sync_converges": (
        "the premises of thm1_energy_nonincreasing for every t ≥ 0; S_h ≥ 0; "
        "t ↦ φ(R_lᵀR̄(t)) Lipschitz (a bounded rate, which item 4 gives; not proved)"),
    # Theorem 1's LaSalle step in asymptotic form (prelude Converge.v)
    "barbalat_second_form": (
        "f differentiable on [0, ∞), f(t) → L, f′ uniformly continuous on [0, ∞)"),
    "thm1_lasalle_relative_rate": (
        "R_l(t) a rotation; R̄, R_l differentiable with eq. (13) and eq. (12b) for "
        "t ≥ 0"),
    "thm1_leader_average_axes": (
        "the premises of thm1_phi_sync_converges except its Lipschitz premise, "
        "which a bounded human command |ω_h^s(t)| ≤ B_w replaces (item 4)"),
    "thm1_human_command_vanishes": (
        "the premises of thm1_leader_average_axes; ω_h^s Lipschitz "
        "(|ω_h^s(t) − ω_h^s(s)| ≤ L_w |t − s|; not in Assumption 1)"),
    "thm1_dbar_converges_to_dr": (
        "the premises of thm1_human_command_vanishes; Assumption 1, item 3, in "
        "asymptotic form: ω_h^s(t) → 0 implies d_l(t) → d_r (not the paper's "
        "'identically' form); d̄ := R̄ e3, d_l = R_l e3, d_r = R_r e3"),
}

#: The closed loop of Theorem 1 on [0, oo) as premises (eqs. (12b), (13), Assumption 1,
#: items 2 and 5, Lemma 1's start), shared by the convergence theorems below.
_CLOSED_LOOP_ON_HALF_LINE = """\
  0 < ks -> 0 < lam ->
  is_rot Rr ->
  (forall t, 0 <= t -> is_rot (Rb t)) ->
  (forall t, 0 <= t -> is_rot (Rl t)) ->
  (forall t, 0 <= t ->
     is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))) ->
  (forall t, 0 <= t ->
     is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                            (mvmul (mT (Rl t)) (ws t)))))) ->
  (forall t, 0 <= t -> is_derive Sh t (dSh t)) ->
  (forall t, 0 <= t ->
     dSh t <= vdot (vee (sk (mmul (mT (Rl t)) Rr))) (mvmul (mT (Rl t)) (ws t))) ->
  (forall t, 0 <= t -> 0 <= Sh t) ->
  (forall t, 0 <= t -> lam_min_spec (mmul (mT Rr) (Rl t)) lam) ->
  1 <= tr (mmul (mT Rr) (Rb 0)) ->
"""

_TEXT_WITH_MARKERS = """\
(** The paper's conclusions along solutions: the statements in full, proved in the
    prelude ([RotSurj.v], [Traj.v], [Lemma1Inv.v]). *)
From Coq Require Import Reals.
From Coquelicot Require Import Coquelicot.
From VerifyCoq Require Import SO3 RotSurj Traj Lemma1Inv Thm1Energy Barbalat.
Open Scope R_scope.

(** Every rotation matrix is [rot q] for a quaternion [q] with [qn q <> 0]. *)
Theorem every_rotation_is_rot_q (M : M3) :
  mmul (mT M) M = I3 -> det M = 1 -> exists q : quat, qn q <> 0 /\\ rot q = M.
Proof. intros H1 H2. exact (rot_surjective M (conj H1 H2)). Qed.

(** Lemma 1 on [[0, T]]: for every solution of eq. (13) with R_r constant and
    Assumption 1, item 2 along it, tr(R_r^T R-bar(0)) >= 1 implies
    tr(R_r^T R-bar(t)) >= 1 for every t in [[0, T]]. *)
Theorem lemma1_invariance_on_interval (Rr : M3) (Rb Rl : R -> M3) (ks T : R) :
  0 < ks ->
  is_rot Rr ->
  (forall t, 0 <= t <= T -> is_rot (Rb t)) ->
  (forall t, 0 <= t <= T ->
     is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))) ->
  (forall t, 0 <= t <= T -> exists lam, 0 < lam /\\ lam_min_spec (mmul (mT Rr) (Rl t)) lam) ->
  1 <= tr (mmul (mT Rr) (Rb 0)) ->
  forall t, 0 <= t <= T -> 1 <= tr (mmul (mT Rr) (Rb t)).
Proof. exact (lemma1_invariance Rr Rb Rl ks T). Qed.

(** Lemma 1 on [[0, oo)]. *)
Theorem lemma1_invariance_on_half_line (Rr : M3) (Rb Rl : R -> M3) (ks : R) :
  0 < ks ->
  is_rot Rr ->
  (forall t, 0 <= t -> is_rot (Rb t)) ->
  (forall t, 0 <= t ->
     is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))) ->
  (forall t, 0 <= t -> exists lam, 0 < lam /\\ lam_min_spec (mmul (mT Rr) (Rl t)) lam) ->
  1 <= tr (mmul (mT Rr) (Rb 0)) ->
  forall t, 0 <= t -> 1 <= tr (mmul (mT Rr) (Rb t)).
Proof. exact (lemma1_invariance_forever Rr Rb Rl ks). Qed.

(** Theorem 1 on [[0, T]]: with the human passive with a differentiable storage [S_h]
    (its rate at most the supplied power), V = phi(R_r^T R-bar) + phi(R_r^T R_l) + S_h
    has [d/dt V <= - k_s lam phi(R_l^T R-bar) <= 0] and does not increase. *)
Theorem thm1_energy_nonincreasing (Rr : M3) (Rb Rl : R -> M3) (ws : R -> V3)
    (Sh dSh : R -> R) (ks lam T : R) :
  0 < ks -> 0 < lam ->
  is_rot Rr ->
  (forall t, 0 <= t <= T -> is_rot (Rb t)) ->
  (forall t, 0 <= t <= T -> is_rot (Rl t)) ->
  (forall t, 0 <= t <= T ->
     is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))) ->
  (forall t, 0 <= t <= T ->
     is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                            (mvmul (mT (Rl t)) (ws t)))))) ->
  (forall t, 0 <= t <= T -> is_derive Sh t (dSh t)) ->
  (forall t, 0 <= t <= T ->
     dSh t <= vdot (vee (sk (mmul (mT (Rl t)) Rr))) (mvmul (mT (Rl t)) (ws t))) ->
  (forall t, 0 <= t <= T -> lam_min_spec (mmul (mT Rr) (Rl t)) lam) ->
  1 <= tr (mmul (mT Rr) (Rb 0)) ->
  (forall t, 0 <= t <= T ->
     is_derive (V Rr Rb Rl Sh) t (dV Rr Rb Rl ws dSh ks t)
     /\\ dV Rr Rb Rl ws dSh ks t <= - (ks * lam) * phi (mmul (mT (Rl t)) (Rb t))) /\\
  (forall s t, 0 <= s -> s <= t -> t <= T -> V Rr Rb Rl Sh t <= V Rr Rb Rl Sh s).
Proof.
  intros. split.
  - intros t Ht. destruct (V_rate_bound Rr Rb Rl ws Sh dSh ks lam T) with (t := t)
      as [D [B _]]; auto.
  - exact (V_nonincreasing Rr Rb Rl ws Sh dSh ks lam T ltac:(assumption) ltac:(assumption)
             ltac:(assumption) ltac:(assumption) ltac:(assumption) ltac:(assumption)
             ltac:(assumption) ltac:(assumption) ltac:(assumption) ltac:(assumption)
             ltac:(assumption)).
Qed.

(** Theorem 1, synchronisation (Barbalat's lemma): under the same premises for every
    t >= 0, a non-negative human storage and a Lipschitz t -> phi(R_l^T R-bar(t)),
    phi(R_l^T R-bar(t)) -> 0: the leader and the quasi-average synchronise. *)
Theorem thm1_phi_sync_converges (Rr : M3) (Rb Rl : R -> M3) (ws : R -> V3)
    (Sh dSh : R -> R) (ks lam Lp : R) :
  @CLOSED_LOOP_ON_HALF_LINE@
  0 < Lp ->
  (forall s t, 0 <= s -> 0 <= t ->
     Rabs (phi (mmul (mT (Rl t)) (Rb t)) - phi (mmul (mT (Rl s)) (Rb s))) <= Lp * Rabs (t - s)) ->
  forall eps, 0 < eps ->
  exists N, 0 <= N /\\ forall t, N <= t -> phi (mmul (mT (Rl t)) (Rb t)) < eps.
Proof. exact (phi_sync_converges Rr Rb Rl ws Sh dSh ks lam Lp). Qed.

(** Theorem 1's LaSalle step in asymptotic form (prelude [Converge.v]).
    [vanishes f] reads [f(t) -> 0] as [t -> oo]:
    [forall eps, 0 < eps -> exists N, 0 <= N /\\ forall t, N <= t -> |f t| < eps];
    [vnorm u = sqrt(u . u)], [vsub u v = u - v], [e3 = (0, 0, 1)];
    [unif_cont g]: [g] uniformly continuous on [[0, oo)]. *)
From VerifyCoq Require Import Converge.

(** Barbalat's lemma, second form: [f -> L] and [f'] uniformly continuous give [f' -> 0]. *)
Theorem barbalat_second_form (f df : R -> R) (L : R) :
  (forall t, 0 <= t -> is_derive f t (df t)) ->
  vanishes (fun t => f t - L) -> unif_cont df -> vanishes df.
Proof. exact (barbalat_rate f df L). Qed.

(** The derivative behind the LaSalle step, along eqs. (12b), (13): with
    [Q = R_l^T R-bar], [d/dt Q = - k_s (Q sk(Q) + sk(Q) Q) - R_l^T hat(omega_h^s) R-bar]
    (at [Q = I] the paper's [- R_l^T hat(omega_h^s) R_l]). *)
Theorem thm1_lasalle_relative_rate (Rb Rl : R -> M3) (ws : R -> V3) (ks : R) :
  (forall t, 0 <= t -> is_rot (Rl t)) ->
  (forall t, 0 <= t ->
     is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))) ->
  (forall t, 0 <= t ->
     is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                            (mvmul (mT (Rl t)) (ws t)))))) ->
  forall t, 0 <= t ->
  is_mderiv (fun s => mmul (mT (Rl s)) (Rb s)) t
    (msub (mscale (- ks) (madd (mmul (mmul (mT (Rl t)) (Rb t)) (sk (mmul (mT (Rl t)) (Rb t))))
                               (mmul (sk (mmul (mT (Rl t)) (Rb t))) (mmul (mT (Rl t)) (Rb t)))))
          (mmul (mT (Rl t)) (mmul (hat (ws t)) (Rb t)))).
Proof. exact (rel_rate_along Rb Rl ws ks). Qed.

(** Theorem 1, synchronisation of the axes: with a bounded human command (which makes
    [t -> phi(R_l^T R-bar(t))] Lipschitz), [||R_l^T R-bar - I||_F^2 -> 0] and
    [|d_l - d-bar| -> 0] with [d_l = R_l e3] and [d-bar := R-bar e3]. *)
Theorem thm1_leader_average_axes (Rr : M3) (Rb Rl : R -> M3) (ws : R -> V3)
    (Sh dSh : R -> R) (ks lam Bw : R) :
  @CLOSED_LOOP_ON_HALF_LINE@
  (forall t, 0 <= t -> vnorm (ws t) <= Bw) ->
  vanishes (fun t => fro2 (msub (mmul (mT (Rl t)) (Rb t)) I3)) /\\
  vanishes (fun t => vnorm (vsub (mvmul (Rl t) e3) (mvmul (Rb t) e3))).
Proof. intros. apply (sync_axes Rr Rb Rl ws Sh dSh ks lam Bw); assumption. Qed.

(** Theorem 1's LaSalle step, asymptotically: [d/dt (R_l^T R-bar) -> 0] (Barbalat's
    second form) and so the human command dies out, [omega_h^s(t) -> 0]. *)
Theorem thm1_human_command_vanishes (Rr : M3) (Rb Rl : R -> M3) (ws : R -> V3)
    (Sh dSh : R -> R) (ks lam Bw Lw : R) :
  @CLOSED_LOOP_ON_HALF_LINE@
  (forall t, 0 <= t -> vnorm (ws t) <= Bw) ->
  (forall s t, 0 <= s -> 0 <= t -> vnorm (vsub (ws t) (ws s)) <= Lw * Rabs (t - s)) ->
  vanishes (fun t => vnorm (ws t)).
Proof. intros. apply (command_vanishes Rr Rb Rl ws Sh dSh ks lam Bw Lw); assumption. Qed.

(** Theorem 1's objective (Section 2): [|d-bar - d_r| -> 0], under Assumption 1,
    item 3, in asymptotic form (if the command dies out, [d_l -> d_r = R_r e3]), a premise. *)
Theorem thm1_dbar_converges_to_dr (Rr : M3) (Rb Rl : R -> M3) (ws : R -> V3)
    (Sh dSh : R -> R) (ks lam Bw Lw : R) :
  @CLOSED_LOOP_ON_HALF_LINE@
  (forall t, 0 <= t -> vnorm (ws t) <= Bw) ->
  (forall s t, 0 <= s -> 0 <= t -> vnorm (vsub (ws t) (ws s)) <= Lw * Rabs (t - s)) ->
  (vanishes (fun t => vnorm (ws t)) ->
   vanishes (fun t => vnorm (vsub (mvmul (Rl t) e3) (mvmul Rr e3)))) ->
  vanishes (fun t => vnorm (vsub (mvmul (Rb t) e3) (mvmul Rr e3))).
Proof. intros. apply (dbar_converges Rr Rb Rl ws Sh dSh ks lam Bw Lw); assumption. Qed.
"""


_TEXT = _TEXT_WITH_MARKERS.replace("  @CLOSED_LOOP_ON_HALF_LINE@\n",
                                   _CLOSED_LOOP_ON_HALF_LINE)


def conclusion_units() -> list[CoqUnit]:
    """The unit restating the conclusions' top theorems (fixed, deterministic text)."""
    return [CoqUnit(MODULE, _TEXT, tuple(THEOREMS),
                    source="Lemma 1 and Theorem 1 along solutions "
                           "(prelude Lemma1Inv.v, Thm1Energy.v, Converge.v)")]
