(** Theorem 1 with the human of KYP certificate reconstructed-k_s-3.0-99babda880e6.json: exported by verify; checked by coqc.
    Model: reconstructed k_s = 3.0 (4 states, 2 ports).
    The human's realisation (A, B, C, D) and storage x^T P x / 2 are those of the
    certificate unit Cert_reconstructed_k_s_3_0_99babda880e6 (its theorem passive: kyp_certified); the loop
    and the embedding of the model's ports are those of the prelude Thm1LTI.v. *)

From Coq Require Import Reals Lia.
From Coquelicot Require Import Coquelicot.
From VerifyCoq Require Import SO3 RotSurj Traj Lemma1Inv Thm1Energy Barbalat Thm1LTI.
From VerifyCoq Require QCert LTIHuman Cert_reconstructed_k_s_3_0_99babda880e6.
Open Scope R_scope.

(** The human's realisation and the certificate's P: the certificate unit's data. *)
Definition A : QCert.matQ := Cert_reconstructed_k_s_3_0_99babda880e6.A.
Definition B : QCert.matQ := Cert_reconstructed_k_s_3_0_99babda880e6.B.
Definition C : QCert.matQ := Cert_reconstructed_k_s_3_0_99babda880e6.C.
Definition D : QCert.matQ := Cert_reconstructed_k_s_3_0_99babda880e6.D.
Definition P : QCert.matQ := Cert_reconstructed_k_s_3_0_99babda880e6.P.

(** Along every solution on [0, T]: V does not increase, its rate is at most
    - k_s lam phi(R_l^T R-bar), the dissipation inequality in integral form, and the
    human's state stays in the sublevel set x^T P x <= 2 V(0), so it is bounded:
    c |x|^2 <= 2 V(0) for some c > 0 (P > 0). *)
Theorem thm1_energy :
  forall (Rr : M3) (Rb Rl : R -> M3) (x : R -> nat -> R) (ks lam T : R),
  0 < ks -> 0 < lam ->
  is_rot Rr ->
  (forall t, 0 <= t <= T -> is_rot (Rb t)) ->
  (forall t, 0 <= t <= T -> is_rot (Rl t)) ->
  (forall t, 0 <= t <= T ->
     is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))) ->
  (forall t, 0 <= t <= T ->
     is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                            (mvmul (mT (Rl t)) (w_s 4 2 C D Rr Rl x t)))))) ->
  (forall t, 0 <= t <= T -> forall i, (i < 4)%nat ->
     is_derive (fun s => x s i) t (LTIHuman.lti_rate 4 2 A B x (u_h Rr Rl) t i)) ->
  (forall t, 0 <= t <= T -> lam_min_spec (mmul (mT Rr) (Rl t)) lam) ->
  1 <= tr (mmul (mT Rr) (Rb 0)) ->
  (forall t, 0 <= t <= T ->
     is_derive (V Rr Rb Rl (S_h 4 P x)) t
       (dV Rr Rb Rl (w_s 4 2 C D Rr Rl x) (dS_h 4 2 A B P Rr Rl x) ks t)
     /\ dV Rr Rb Rl (w_s 4 2 C D Rr Rl x) (dS_h 4 2 A B P Rr Rl x) ks t
        <= - (ks * lam) * phi (mmul (mT (Rl t)) (Rb t))) /\
  (forall s t, 0 <= s -> s <= t -> t <= T ->
     V Rr Rb Rl (S_h 4 P x) t <= V Rr Rb Rl (S_h 4 P x) s) /\
  (forall t, 0 <= t <= T ->
     ex_RInt (fun s => ks * lam * phi (mmul (mT (Rl s)) (Rb s))) 0 t /\
     V Rr Rb Rl (S_h 4 P x) t + RInt (fun s => ks * lam * phi (mmul (mT (Rl s)) (Rb s))) 0 t
       <= V Rr Rb Rl (S_h 4 P x) 0) /\
  (forall t, 0 <= t <= T ->
     0 <= S_h 4 P x t /\ QCert.qform 4 P (x t) <= 2 * V Rr Rb Rl (S_h 4 P x) 0) /\
  (exists c, 0 < c /\
     forall t, 0 <= t <= T -> c * LTIHuman.normsq 4 (x t) <= 2 * V Rr Rb Rl (S_h 4 P x) 0).
Proof.
  intros Rr Rb Rl x ks lam T.
  exact (thm1_lti_energy 4 2 A B C D P ltac:(lia) ltac:(lia) ltac:(lia)
           Cert_reconstructed_k_s_3_0_99babda880e6.passive Rr Rb Rl x ks lam T).
Qed.

(** On [0, oo), with t -> phi(R_l^T R-bar(t)) Lipschitz: the leader and the
    quasi-average synchronise. *)
Theorem thm1_sync :
  forall (Rr : M3) (Rb Rl : R -> M3) (x : R -> nat -> R) (ks lam Lp : R),
  0 < ks -> 0 < lam ->
  is_rot Rr ->
  (forall t, 0 <= t -> is_rot (Rb t)) ->
  (forall t, 0 <= t -> is_rot (Rl t)) ->
  (forall t, 0 <= t ->
     is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))) ->
  (forall t, 0 <= t ->
     is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                            (mvmul (mT (Rl t)) (w_s 4 2 C D Rr Rl x t)))))) ->
  (forall t, 0 <= t -> forall i, (i < 4)%nat ->
     is_derive (fun s => x s i) t (LTIHuman.lti_rate 4 2 A B x (u_h Rr Rl) t i)) ->
  (forall t, 0 <= t -> lam_min_spec (mmul (mT Rr) (Rl t)) lam) ->
  1 <= tr (mmul (mT Rr) (Rb 0)) ->
  0 < Lp ->
  (forall s t, 0 <= s -> 0 <= t ->
     Rabs (phi (mmul (mT (Rl t)) (Rb t)) - phi (mmul (mT (Rl s)) (Rb s))) <= Lp * Rabs (t - s)) ->
  forall eps, 0 < eps ->
  exists N, 0 <= N /\ forall t, N <= t -> phi (mmul (mT (Rl t)) (Rb t)) < eps.
Proof.
  intros Rr Rb Rl x ks lam Lp.
  exact (thm1_lti_sync 4 2 A B C D P ltac:(lia) ltac:(lia) ltac:(lia)
           Cert_reconstructed_k_s_3_0_99babda880e6.passive Rr Rb Rl x ks lam Lp).
Qed.
