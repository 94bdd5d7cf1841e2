(** * Theorem 1 with a certified LTI human in the loop

    The closed loop of Section 3 with the human of Section 4 in it: an LTI model with
    [n] states and [m] ports (2 or 3), x' = A x + B u_h, y = C x + D u_h, whose input is
    the paper's item 5 signal [u = sk(R_l^T R_r)^vee] and whose output is the body
    command [omega_h^b]; the leader's law (eq. (12b)) receives [omega_h^s = R_l omega_h^b].
    The embedding of the m-port model into the three-vector loop is the simulator's
    ([verify/sim/humans.py]): the model reads the first [m] components of [u]
    ([u_h = E u], [port]) and its output fills the first [m] components of
    [omega_h^b], the others zero ([omega_h^b = E^T y], [pad]); so
    [u . omega_h^b = u_h . y] ([supply_embedding]).

    With a KYP certificate of (A, B, C, D) ([QCert.kyp_certified]) the human's storage
    is the state function [S_h = x^T P x / 2] ([LTIHuman.v]), which replaces the
    paper's integral storage, and along every solution on [[0, T]]:
    [V = phi(R_r^T R-bar) + phi(R_r^T R_l) + x^T P x / 2] does not increase, its rate
    is at most [- k_s lam phi(R_l^T R-bar)], and
    [V(t) + int_0^t k_s lam phi(R_l^T R-bar) <= V(0)] ([thm1_lti_energy]); the state
    stays in the sublevel set [x^T P x <= 2 V(0)], hence bounded:
    [c |x(t)|^2 <= 2 V(0)] for a [c > 0] that [P > 0] gives (Assumption 1, item 4, for
    the human's state, proved rather than assumed); on [[0, oo)] with a Lipschitz
    [t -> phi(R_l^T R-bar(t))], [phi(R_l^T R-bar) -> 0] ([thm1_lti_sync]). *)

From Coq Require Import Reals Lra Lia Psatz.
Local Set Warnings "-ambiguous-paths -notation-overridden".
From Coquelicot Require Import Coquelicot.
From VerifyCoq Require Import SO3 RotSurj Traj Lemma1Inv Thm1Energy Barbalat.
From VerifyCoq Require QCert LTIHuman.
Open Scope R_scope.

(** ** The m-port human in the three-vector loop *)

(** [E u]: the first [m] components of a three-vector, as the model's input. *)
Definition port (w : V3) (k : nat) : R :=
  match k with 0 => v1 w | 1 => v2 w | 2 => v3 w | _ => 0 end.

(** [E^T y]: the model's [m] outputs as a three-vector, the others zero. *)
Definition pad (m : nat) (y : nat -> R) : V3 :=
  mkV (if Nat.ltb 0 m then y 0%nat else 0) (if Nat.ltb 1 m then y 1%nat else 0)
      (if Nat.ltb 2 m then y 2%nat else 0).

(** The supply of the loop is the model's: [u . E^T y = (E u) . y]. *)
Lemma supply_embedding (m : nat) (w : V3) (y : nat -> R) :
  (m <= 3)%nat -> vdot w (pad m y) = LTIHuman.vdotn m (port w) y.
Proof.
  intros H. destruct w as [a b c].
  destruct m as [|[|[|[|m]]]]; try lia; unfold vdot, pad, LTIHuman.vdotn; simpl; ring.
Qed.

Lemma rot_cancel (M : M3) (w : V3) : is_rot M -> mvmul (mT M) (mvmul M w) = w.
Proof.
  intros [H _]. transitivity (mvmul (mmul (mT M) M) w).
  - destruct M, w. unfold mvmul, mmul, mT; simpl. f_equal; ring.
  - rewrite H. destruct w. unfold mvmul, I3; simpl. f_equal; ring.
Qed.

(** ** The dissipation inequality in integral form *)

(** [f' <= - g] on [[0, T]] with [g] continuous there: [f(t) + int_0^t g <= f(0)]. *)
Lemma integral_dissipation (f df g : R -> R) (T : R) :
  (forall t, 0 <= t <= T -> is_derive f t (df t)) ->
  (forall t, 0 <= t <= T -> continuous g t) ->
  (forall t, 0 <= t <= T -> df t <= - g t) ->
  forall t, 0 <= t <= T -> ex_RInt g 0 t /\ f t + RInt g 0 t <= f 0.
Proof.
  intros D Cg B t Ht.
  destruct (C0_extension_le g 0 T Cg) as [h [Ch Eh]].
  assert (Ih : forall a b, ex_RInt h a b) by (intros; apply (ex_RInt_continuous (V := R_CompleteNormedModule)); intros; apply Ch).
  assert (Eq : forall s, 0 <= s <= T -> RInt g 0 s = RInt h 0 s).
  { intros s Hs. apply RInt_ext. intros z Hz.
    rewrite Rmin_left, Rmax_right in Hz by lra. symmetry. apply Eh. lra. }
  set (W := fun s => f s + RInt h 0 s).
  assert (DW : forall s, 0 <= s <= T -> is_derive W s (df s + h s)).
  { intros s Hs. apply (is_derive_plus f (fun s => RInt h 0 s)); [ apply D, Hs | ].
    apply (is_derive_RInt h (fun s => RInt h 0 s) 0 s).
    - apply filter_forall. intros y. apply (RInt_correct (V := R_CompleteNormedModule)), Ih.
    - apply Ch. }
  split.
  - apply (ex_RInt_continuous (V := R_CompleteNormedModule)). intros z Hz. rewrite Rmin_left, Rmax_right in Hz by lra.
    apply Cg. lra.
  - pose proof (nonincreasing W (fun s => df s + h s) T DW) as N.
    assert (Hn : forall s, 0 <= s <= T -> df s + h s <= 0).
    { intros s Hs. rewrite Eh by exact Hs. pose proof (B s Hs). lra. }
    specialize (N Hn 0 t ltac:(lra) ltac:(lra) ltac:(lra)).
    unfold W in N. rewrite RInt_point in N. rewrite Eq by exact Ht.
    change (zero : R) with 0 in N. lra.
Qed.

(** ** The closed loop with the LTI human, on [[0, T]] *)

Section LTILoop.
(** The human: a realisation with [n] states and [m] ports and a KYP certificate [P]. *)
Variables (n m : nat) (A B C D P : QCert.matQ).
Hypothesis n_pos : (0 < n)%nat.
Hypothesis m_pos : (0 < m)%nat.
Hypothesis m_le : (m <= 3)%nat.
Hypothesis cert : QCert.kyp_certified n m A B C D P.
(** The loop: reference, quasi-average, leader, the human's state; gain, item 2's bound. *)
Variables (Rr : M3) (Rb Rl : R -> M3) (x : R -> nat -> R) (ks lam T : R).

(** The human's input [E sk(R_l^T R_r)^vee] (item 5), output [omega_h^b = E^T y], and the
    spatial command [omega_h^s = R_l omega_h^b] of eq. (12b). *)
Definition u_h (t : R) : nat -> R := port (vee (sk (mmul (mT (Rl t)) Rr))).
Definition w_b (t : R) : V3 := pad m (LTIHuman.lti_out n m C D x u_h t).
Definition w_s (t : R) : V3 := mvmul (Rl t) (w_b t).
(** The human's storage from the certificate. *)
Definition S_h (t : R) : R := LTIHuman.storage n P x t.
Definition dS_h (t : R) : R := LTIHuman.storage_rate n m A B P x u_h t.

Hypothesis ks_pos : 0 < ks.
Hypothesis lam_pos : 0 < lam.
Hypothesis Rr_rot : is_rot Rr.
Hypothesis Rb_rot : forall t, 0 <= t <= T -> is_rot (Rb t).
Hypothesis Rl_rot : forall t, 0 <= t <= T -> is_rot (Rl t).
(** eq. (13), eq. (12b) with the human's command, and the human's state equation. *)
Hypothesis Rb_sol : forall t, 0 <= t <= T ->
  is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t))))).
Hypothesis Rl_sol : forall t, 0 <= t <= T ->
  is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                         (mvmul (mT (Rl t)) (w_s t))))).
Hypothesis x_sol : forall t, 0 <= t <= T -> forall i, (i < n)%nat ->
  is_derive (fun s => x s i) t (LTIHuman.lti_rate n m A B x u_h t i).
Hypothesis item2 : forall t, 0 <= t <= T -> lam_min_spec (mmul (mT Rr) (Rl t)) lam.
Hypothesis init : 1 <= tr (mmul (mT Rr) (Rb 0)).

Lemma S_h_supply (t : R) : 0 <= t <= T ->
  dS_h t <= vdot (vee (sk (mmul (mT (Rl t)) Rr))) (mvmul (mT (Rl t)) (w_s t)).
Proof.
  intros Ht. unfold w_s. rewrite rot_cancel by exact (Rl_rot t Ht).
  unfold w_b. rewrite supply_embedding by exact m_le.
  exact (LTIHuman.storage_dissipation n m A B C D P n_pos m_pos cert x u_h t).
Qed.

Lemma S_h_derive (t : R) : 0 <= t <= T -> is_derive S_h t (dS_h t).
Proof. intros Ht. apply (LTIHuman.storage_derive n m A B C D P cert). exact (x_sol t Ht). Qed.

Lemma sync_continuous (t : R) : 0 <= t <= T ->
  continuous (fun s => ks * lam * phi (mmul (mT (Rl s)) (Rb s))) t.
Proof.
  intros Ht. apply (ex_derive_continuous (K := R_AbsRing) (V := R_NormedModule)).
  pose proof (deriv_phi _ t _ (mderiv_mmul (fun s => mT (Rl s)) Rb t _ _
                 (mderiv_mT Rl t _ (Rl_sol t Ht)) (Rb_sol t Ht))) as H.
  eexists. apply (d_mult (fun _ => ks * lam) _ t 0 _ (d_const (ks * lam) t) H).
Qed.

(** Theorem 1's energy with the certified human, along the solution on [[0, T]]. *)
Theorem thm1_lti_energy :
  (forall t, 0 <= t <= T ->
     is_derive (V Rr Rb Rl S_h) t (dV Rr Rb Rl w_s dS_h ks t)
     /\ dV Rr Rb Rl w_s dS_h ks t <= - (ks * lam) * phi (mmul (mT (Rl t)) (Rb t))) /\
  (forall s t, 0 <= s -> s <= t -> t <= T -> V Rr Rb Rl S_h t <= V Rr Rb Rl S_h s) /\
  (forall t, 0 <= t <= T ->
     ex_RInt (fun s => ks * lam * phi (mmul (mT (Rl s)) (Rb s))) 0 t /\
     V Rr Rb Rl S_h t + RInt (fun s => ks * lam * phi (mmul (mT (Rl s)) (Rb s))) 0 t
       <= V Rr Rb Rl S_h 0) /\
  (forall t, 0 <= t <= T -> 0 <= S_h t /\ QCert.qform n P (x t) <= 2 * V Rr Rb Rl S_h 0) /\
  (exists c, 0 < c /\
     forall t, 0 <= t <= T -> c * LTIHuman.normsq n (x t) <= 2 * V Rr Rb Rl S_h 0).
Proof.
  assert (R : forall t, 0 <= t <= T ->
            is_derive (V Rr Rb Rl S_h) t (dV Rr Rb Rl w_s dS_h ks t)
            /\ dV Rr Rb Rl w_s dS_h ks t <= - (ks * lam) * phi (mmul (mT (Rl t)) (Rb t))
            /\ dV Rr Rb Rl w_s dS_h ks t <= 0).
  { intros t Ht. apply (V_rate_bound Rr Rb Rl w_s S_h dS_h ks lam T); auto.
    - exact S_h_derive.
    - exact S_h_supply. }
  assert (Dec : forall s t, 0 <= s -> s <= t -> t <= T -> V Rr Rb Rl S_h t <= V Rr Rb Rl S_h s).
  { apply (V_nonincreasing Rr Rb Rl w_s S_h dS_h ks lam T); auto.
    - exact S_h_derive.
    - exact S_h_supply. }
  split; [ intros t Ht; destruct (R t Ht) as [Dv [Bv _]]; split; assumption | ].
  split; [ exact Dec | ]. split.
  - apply (integral_dissipation (V Rr Rb Rl S_h) (dV Rr Rb Rl w_s dS_h ks)).
    + intros t Ht. apply (R t Ht).
    + exact sync_continuous.
    + intros t Ht. destruct (R t Ht) as [_ [Bv _]]. lra.
  - assert (Sub : forall t, 0 <= t <= T ->
              0 <= S_h t /\ QCert.qform n P (x t) <= 2 * V Rr Rb Rl S_h 0).
    { intros t Ht. pose proof (LTIHuman.storage_nonneg n m A B C D P cert x t) as Hs.
      split; [ exact Hs | ].
      pose proof (Dec 0 t ltac:(lra) ltac:(lra) ltac:(lra)) as Hd.
      pose proof (phi_rel_rot_nonneg _ _ Rr_rot (Rb_rot t Ht)) as P1.
      pose proof (phi_rel_rot_nonneg _ _ Rr_rot (Rl_rot t Ht)) as P2.
      unfold V, S_h, LTIHuman.storage in *. lra. }
    split; [ exact Sub | ].
    destruct (LTIHuman.storage_coercive n m A B C D P cert x) as [c [Hc Low]].
    exists c. split; [ exact Hc | ]. intros t Ht. pose proof (Low t) as L.
    destruct (Sub t Ht) as [_ Q]. unfold S_h, LTIHuman.storage in *. lra.
Qed.

End LTILoop.

(** ** On [[0, oo)]: the leader and the quasi-average synchronise *)

Section LTISync.
Variables (n m : nat) (A B C D P : QCert.matQ).
Hypothesis n_pos : (0 < n)%nat.
Hypothesis m_pos : (0 < m)%nat.
Hypothesis m_le : (m <= 3)%nat.
Hypothesis cert : QCert.kyp_certified n m A B C D P.
Variables (Rr : M3) (Rb Rl : R -> M3) (x : R -> nat -> R) (ks lam Lp : R).
Hypothesis ks_pos : 0 < ks.
Hypothesis lam_pos : 0 < lam.
Hypothesis Rr_rot : is_rot Rr.
Hypothesis Rb_rot : forall t, 0 <= t -> is_rot (Rb t).
Hypothesis Rl_rot : forall t, 0 <= t -> is_rot (Rl t).
Hypothesis Rb_sol : forall t, 0 <= t ->
  is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t))))).
Hypothesis Rl_sol : forall t, 0 <= t ->
  is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                         (mvmul (mT (Rl t)) (w_s n m C D Rr Rl x t))))).
Hypothesis x_sol : forall t, 0 <= t -> forall i, (i < n)%nat ->
  is_derive (fun s => x s i) t (LTIHuman.lti_rate n m A B x (u_h Rr Rl) t i).
Hypothesis item2 : forall t, 0 <= t -> lam_min_spec (mmul (mT Rr) (Rl t)) lam.
Hypothesis init : 1 <= tr (mmul (mT Rr) (Rb 0)).
(** Not proved here: [t -> phi(R_l^T R-bar(t))] is Lipschitz (a bounded rate). *)
Hypothesis Lp_pos : 0 < Lp.
Hypothesis phi_lipschitz : forall s t, 0 <= s -> 0 <= t ->
  Rabs (phi (mmul (mT (Rl t)) (Rb t)) - phi (mmul (mT (Rl s)) (Rb s))) <= Lp * Rabs (t - s).

Theorem thm1_lti_sync :
  forall eps, 0 < eps -> exists N, 0 <= N /\ forall t, N <= t -> phi (mmul (mT (Rl t)) (Rb t)) < eps.
Proof.
  apply (phi_sync_converges Rr Rb Rl (w_s n m C D Rr Rl x) (S_h n P x)
           (dS_h n m A B P Rr Rl x) ks lam Lp); auto.
  - intros t Ht. apply (LTIHuman.storage_derive n m A B C D P cert). exact (x_sol t Ht).
  - intros t Ht. apply (S_h_supply n m A B C D P n_pos m_pos m_le cert Rr Rl x t);
      [ intros s Hs; apply Rl_rot; lra | lra ].
  - intros t _. exact (LTIHuman.storage_nonneg n m A B C D P cert x t).
Qed.

End LTISync.
