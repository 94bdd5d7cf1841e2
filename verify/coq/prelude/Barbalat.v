(** * Barbalat's lemma and the synchronisation of the leader and the average

    Theorem 1's proof ends with LaSalle's principle.  Its first half, that the leader
    and the quasi-average synchronise ([phi(R_l^T R-bar) -> 0]), follows from the energy
    inequality of [Thm1Energy.v] by Barbalat's lemma, proved here in the form used:
    if [W] is bounded below and [W' <= - g] with [g >= 0] Lipschitz, then [g -> 0].
    The premises of [phi_sync_converges] name what is not proved: the human's storage
    is non-negative, and [t -> phi(R_l^T R-bar(t))] is Lipschitz (which the paper's
    item 4, bounded human output, gives through the dynamics). *)

From Coq Require Import Reals Lra Psatz.
Local Set Warnings "-ambiguous-paths".
From Coquelicot Require Import Coquelicot.
From VerifyCoq Require Import SO3 RotSurj Traj Lemma1Inv Thm1Energy.
Open Scope R_scope.

(** A non-increasing function bounded below is eventually almost constant. *)
Lemma decr_settles (W : R -> R) (m : R) :
  (forall s t, 0 <= s -> s <= t -> W t <= W s) -> (forall t, 0 <= t -> m <= W t) ->
  forall eta, 0 < eta -> exists N, 0 <= N /\ forall t, N <= t -> W N - W t < eta.
Proof.
  intros D B eta He.
  set (E := fun y => exists t, 0 <= t /\ y = - W t).
  assert (Eb : bound E) by (exists (- m); intros y [t [Ht ->]]; specialize (B t Ht); lra).
  assert (E0 : exists y, E y) by (exists (- W 0); exists 0; split; [ lra | reflexivity ]).
  destruct (completeness E Eb E0) as [M [Sup Least]].
  assert (Ex : exists t, 0 <= t /\ M - eta < - W t).
  { destruct (Rle_or_lt 0 1) as [_ | ]; [ | lra ].
    apply Classical_Pred_Type.not_all_not_ex. intro H.
    assert (Up : is_upper_bound E (M - eta)).
    { intros y [t [Ht ->]]. specialize (H t).
      destruct (Rle_or_lt (- W t) (M - eta)) as [le | gt]; [ exact le | exfalso; apply H; split; assumption ]. }
    specialize (Least _ Up). lra. }
  destruct Ex as [N [HN Hlt]]. exists N. split; [ exact HN | ].
  intros t Ht. assert (Et : E (- W t)) by (exists t; split; [ lra | reflexivity ]).
  specialize (Sup _ Et). lra.
Qed.

(** Barbalat's lemma: [W] bounded below on [[0, oo)], [W' <= - g], [g >= 0] and
    [g] Lipschitz with constant [L]: then [g(t) -> 0]. *)
Theorem barbalat (W dW g : R -> R) (L m : R) :
  0 < L ->
  (forall t, 0 <= t -> is_derive W t (dW t)) ->
  (forall t, 0 <= t -> dW t <= - g t) ->
  (forall t, 0 <= t -> 0 <= g t) ->
  (forall s t, 0 <= s -> 0 <= t -> Rabs (g t - g s) <= L * Rabs (t - s)) ->
  (forall t, 0 <= t -> m <= W t) ->
  forall eps, 0 < eps -> exists N, 0 <= N /\ forall t, N <= t -> g t < eps.
Proof.
  intros HL D Hd Hg Lip B eps He.
  assert (Dec : forall s t, 0 <= s -> s <= t -> W t <= W s).
  { intros s t Hs Hst. apply (nonincreasing W dW t); try lra.
    - intros u Hu. apply D. lra.
    - intros u Hu. pose proof (Hd u ltac:(lra)). pose proof (Hg u ltac:(lra)). lra. }
  set (d := eps / (2 * L)).
  assert (Hdp : 0 < d) by (unfold d; apply Rdiv_lt_0_compat; lra).
  destruct (decr_settles W m Dec B (eps / 2 * d)) as [N [HN Hset]].
  { apply Rmult_lt_0_compat; lra. }
  exists N. split; [ exact HN | ]. intros t Ht.
  destruct (Rlt_le_dec (g t) eps) as [ok | big]; [ exact ok | exfalso ].
  (* on [t, t + d], g >= eps / 2 *)
  assert (Half : forall u, t <= u <= t + d -> eps / 2 <= g u).
  { intros u Hu. specialize (Lip t u ltac:(lra) ltac:(lra)).
    rewrite (Rabs_right (u - t)) in Lip by lra.
    assert (L * (u - t) <= L * d) by (apply Rmult_le_compat_l; lra).
    assert (Ld : L * d = eps / 2) by (unfold d; field; lra).
    pose proof (Rle_abs (g t - g u)). rewrite Rabs_minus_sym in Lip. lra. }
  destruct (MVT_cor2 W dW t (t + d) ltac:(lra)) as [c [E Hc]].
  { intros x Hx. apply is_derive_Reals, D. lra. }
  pose proof (Hd c ltac:(lra)). pose proof (Half c ltac:(lra)).
  assert (Drop : W (t + d) - W t <= - (eps / 2 * d)).
  { rewrite E. replace (t + d - t) with d by ring. nra. }
  pose proof (Dec N t HN Ht). specialize (Hset (t + d) ltac:(lra)). lra.
Qed.

(** ** The leader and the quasi-average synchronise *)
Section Convergence.
Variables (Rr : M3) (Rb Rl : R -> M3) (ws : R -> V3) (Sh dSh : R -> R) (ks lam Lp : R).
Hypothesis ks_pos : 0 < ks.
Hypothesis lam_pos : 0 < lam.
Hypothesis Rr_rot : is_rot Rr.
Hypothesis Rb_rot : forall t, 0 <= t -> is_rot (Rb t).
Hypothesis Rl_rot : forall t, 0 <= t -> is_rot (Rl t).
Hypothesis Rb_sol : forall t, 0 <= t ->
  is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t))))).
Hypothesis Rl_sol : forall t, 0 <= t ->
  is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                         (mvmul (mT (Rl t)) (ws t))))).
Hypothesis Sh_deriv : forall t, 0 <= t -> is_derive Sh t (dSh t).
Hypothesis Sh_supply : forall t, 0 <= t ->
  dSh t <= vdot (vee (sk (mmul (mT (Rl t)) Rr))) (mvmul (mT (Rl t)) (ws t)).
(** The human's storage is non-negative (Assumption 1, item 5: [beta >= 0]). *)
Hypothesis Sh_nonneg : forall t, 0 <= t -> 0 <= Sh t.
Hypothesis item2 : forall t, 0 <= t -> lam_min_spec (mmul (mT Rr) (Rl t)) lam.
Hypothesis init : 1 <= tr (mmul (mT Rr) (Rb 0)).
(** Not proved here: [t -> phi(R_l^T R-bar(t))] is Lipschitz with constant [Lp > 0]
    (a bounded rate; the paper's item 4 bounds the human's output, which bounds it). *)
Hypothesis Lp_pos : 0 < Lp.
Hypothesis phi_lipschitz : forall s t, 0 <= s -> 0 <= t ->
  Rabs (phi (mmul (mT (Rl t)) (Rb t)) - phi (mmul (mT (Rl s)) (Rb s))) <= Lp * Rabs (t - s).

Ltac from_forever :=
  first [ assumption
        | intros; match goal with H : forall t, 0 <= t -> _ |- _ => apply H; lra end ].

Lemma phi_sync_nonneg (t : R) : 0 <= t -> 0 <= phi (mmul (mT (Rl t)) (Rb t)).
Proof.
  intro Ht. exact (phi_rel_rot_nonneg _ _ (Rl_rot t Ht) (Rb_rot t Ht)).
Qed.

(** [phi(R_l^T R-bar(t)) -> 0] as [t -> oo]. *)
Theorem phi_sync_converges :
  forall eps, 0 < eps -> exists N, 0 <= N /\ forall t, N <= t -> phi (mmul (mT (Rl t)) (Rb t)) < eps.
Proof.
  intros eps He.
  assert (R : forall t, 0 <= t ->
            is_derive (V Rr Rb Rl Sh) t (dV Rr Rb Rl ws dSh ks t)
            /\ dV Rr Rb Rl ws dSh ks t <= - (ks * lam) * phi (mmul (mT (Rl t)) (Rb t))
            /\ dV Rr Rb Rl ws dSh ks t <= 0).
  { intros t Ht. apply (V_rate_bound Rr Rb Rl ws Sh dSh ks lam t); try from_forever. lra. }
  destruct (barbalat (V Rr Rb Rl Sh) (dV Rr Rb Rl ws dSh ks)
              (fun t => ks * lam * phi (mmul (mT (Rl t)) (Rb t))) (ks * lam * Lp) 0)
    with (eps := ks * lam * eps) as [N [HN HT]].
  - apply Rmult_lt_0_compat; [ apply Rmult_lt_0_compat | ]; assumption.
  - intros t Ht. apply (R t Ht).
  - intros t Ht. destruct (R t Ht) as [_ [B _]]. lra.
  - intros t Ht. pose proof (phi_sync_nonneg t Ht).
    apply Rmult_le_pos; [ apply Rmult_le_pos | ]; lra.
  - intros s t Hs Ht. rewrite <- Rmult_minus_distr_l, Rabs_mult, Rmult_assoc.
    rewrite (Rabs_right (ks * lam)) by (apply Rle_ge, Rmult_le_pos; lra).
    apply Rmult_le_compat_l; [ apply Rmult_le_pos; lra | apply phi_lipschitz; assumption ].
  - intros t Ht. unfold V. pose proof (phi_sync_nonneg t Ht). pose proof (Sh_nonneg t Ht).
    pose proof (phi_rel_rot_nonneg _ _ Rr_rot (Rb_rot t Ht)).
    pose proof (phi_rel_rot_nonneg _ _ Rr_rot (Rl_rot t Ht)).
    lra.
  - apply Rmult_lt_0_compat; [ apply Rmult_lt_0_compat | ]; assumption.
  - exists N. split; [ exact HN | ]. intros t Ht. specialize (HT t Ht).
    assert (Pk : 0 < ks * lam) by (apply Rmult_lt_0_compat; assumption).
    apply (Rmult_lt_reg_l (ks * lam)); [ exact Pk | ]. lra.
Qed.
End Convergence.
