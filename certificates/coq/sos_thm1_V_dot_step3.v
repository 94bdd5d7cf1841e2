(** SOS certificate sos-3c0bd7455cbf7e25ea7e.json, exported to Coq.
    It proves step 3 of the derivation 'thm1.V-dot' (verify.paper_proofs): (-1/2) k_s (λmin((R̄_r + R̄_rᵀ)) + λmin((R_rl + R_rlᵀ))) φ(R_lᵀR̄) <= 0.
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by field. *)

From Coq Require Import Reals QArith List Lra.
From VerifyCoq Require Import SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.

Section Sos_thm1_V_dot_3.

(** k_s: a scalar *)
Variable v_1_k_s : R.
Hypothesis v_1_k_s_pos : 0 < v_1_k_s.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_R_r : quat.
Hypothesis q_v_2_R_r_nonzero : qn q_v_2_R_r <> 0.
Local Notation v_2_R_r := (rot q_v_2_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_Rbar : quat.
Hypothesis q_v_3_Rbar_nonzero : qn q_v_3_Rbar <> 0.
Local Notation v_3_Rbar := (rot q_v_3_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_4_R_l : quat.
Hypothesis q_v_4_R_l_nonzero : qn q_v_4_R_l <> 0.
Local Notation v_4_R_l := (rot q_v_4_R_l).

(** lambda_min((R̄_r + R̄_rᵀ)): a lower bound suffices *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (madd (mmul (mT v_2_R_r) v_3_Rbar) (mT (mmul (mT v_2_R_r) v_3_Rbar))) lam1.

(** lambda_min((R_rl + R_rlᵀ)): a lower bound suffices *)
Variable lam2 : R.
Hypothesis lam2_spec : lam_min_spec (madd (mmul (mT v_2_R_r) v_4_R_l) (mT (mmul (mT v_2_R_r) v_4_R_l))) lam2.

(** assumption: λmin(R̄_r + R̄_rᵀ) ≥ 0 (Lemma 1) *)
Hypothesis assumption1 : 0 <= lam1.

(** assumption: λmin(R_rl + R_rlᵀ) > 0 (Assumption 1, item 2) *)
Hypothesis assumption2 : 0 < lam2.

Let env : list R := [v_1_k_s; (qw q_v_2_R_r); (qx q_v_2_R_r); (qy q_v_2_R_r); (qz q_v_2_R_r); (qw q_v_3_Rbar); (qx q_v_3_Rbar); (qy q_v_3_Rbar); (qz q_v_3_Rbar); (qw q_v_4_R_l); (qx q_v_4_R_l); (qy q_v_4_R_l); (qz q_v_4_R_l); lam1; lam2].

Definition target : poly := [([1;0;0;0;0;0;0;0;2;0;0;2;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;0;2;0;0;2;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;0;0;2;0;2;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;0;2;0;2;0;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;0;0;2;2;0;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;0;2;2;0;0;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;0;1;1;0;0;1;1;0;1]%nat, (-2)%Q); ([1;0;0;0;0;0;0;1;1;0;0;1;1;1;0]%nat, (-2)%Q); ([1;0;0;0;0;0;0;2;0;0;0;0;2;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;2;0;0;0;0;2;1;0]%nat, 1%Q); ([1;0;0;0;0;0;0;2;0;0;2;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;2;0;0;2;0;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;0;2;0;2;0;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;2;0;2;0;0;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;1;0;1;0;1;0;1;0;1]%nat, (-2)%Q); ([1;0;0;0;0;0;1;0;1;0;1;0;1;1;0]%nat, (-2)%Q); ([1;0;0;0;0;0;1;1;0;0;1;1;0;0;1]%nat, (-2)%Q); ([1;0;0;0;0;0;1;1;0;0;1;1;0;1;0]%nat, (-2)%Q); ([1;0;0;0;0;0;2;0;0;0;0;0;2;0;1]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;0;0;0;2;1;0]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;0;0;2;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;0;0;2;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;2;0;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;2;0;0;0;1;0]%nat, 1%Q); ([1;0;0;0;0;1;0;0;1;1;0;0;1;0;1]%nat, (-2)%Q); ([1;0;0;0;0;1;0;0;1;1;0;0;1;1;0]%nat, (-2)%Q); ([1;0;0;0;0;1;0;1;0;1;0;1;0;0;1]%nat, (-2)%Q); ([1;0;0;0;0;1;0;1;0;1;0;1;0;1;0]%nat, (-2)%Q); ([1;0;0;0;0;1;1;0;0;1;1;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;0;1;1;0;0;1;1;0;0;1;0]%nat, (-2)%Q); ([1;0;0;0;0;2;0;0;0;0;0;0;2;0;1]%nat, 1%Q); ([1;0;0;0;0;2;0;0;0;0;0;0;2;1;0]%nat, 1%Q); ([1;0;0;0;0;2;0;0;0;0;0;2;0;0;1]%nat, 1%Q); ([1;0;0;0;0;2;0;0;0;0;0;2;0;1;0]%nat, 1%Q); ([1;0;0;0;0;2;0;0;0;0;2;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;2;0;0;0;0;2;0;0;1;0]%nat, 1%Q)].

(** block 1: k_s > 0 (declared) × assumed: λmin(R̄_r + R̄_rᵀ) ≥ 0 *)
Definition H1 : list (list poly) := [[[([1;0;0;0;0;0;0;0;0;0;0;0;0;1;0]%nat, 1%Q)]]].
Definition S1 : list (Q * list poly) :=
  [(1%Q, [[([0;0;0;0;0;0;0;0;1;0;0;1;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;1;0;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;1;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;1;0;0;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;1;0;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;1;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;0;1;0;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;1;0;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;1;0;0;0;0]%nat, (-1)%Q)]])].

Lemma H1_psd : mult_psd env H1.
Proof.
  unfold H1. apply mult_psd_scalar.
  rewrite zeval_peval by (vm_compute; reflexivity).
  match goal with |- 0 <= ?g => replace g with (v_1_k_s * lam1) by (cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]; so3_unfold; field; sos_nonzero) end.
  exact (Rmult_le_pos _ _ (Rlt_le _ _ v_1_k_s_pos) assumption1).
Qed.

(** block 2: k_s > 0 (declared) × assumed: λmin(R_rl + R_rlᵀ) > 0 *)
Definition H2 : list (list poly) := [[[([1;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, 1%Q)]]].
Definition S2 : list (Q * list poly) :=
  [(1%Q, [[([0;0;0;0;0;0;0;0;1;0;0;1;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;1;0;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;1;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;1;0;0;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;1;0;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;1;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;0;1;0;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;1;0;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;1;0;0;0;0]%nat, (-1)%Q)]])].

Lemma H2_psd : mult_psd env H2.
Proof.
  unfold H2. apply mult_psd_scalar.
  rewrite zeval_peval by (vm_compute; reflexivity).
  match goal with |- 0 <= ?g => replace g with (v_1_k_s * lam2) by (cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]; so3_unfold; field; sos_nonzero) end.
  exact (Rmult_le_pos _ _ (Rlt_le _ _ v_1_k_s_pos) (Rlt_le _ _ assumption2)).
Qed.

Definition blocks : list block := [(mkBlock H1 S1); (mkBlock H2 S2)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_compute. reflexivity. Qed.

Lemma grounds : blocks_psd env blocks.
Proof. exact (blocks_psd_cons env (mkBlock H1 S1) _ H1_psd (blocks_psd_cons env (mkBlock H2 S2) _ H2_psd (blocks_psd_nil env))). Qed.

(** The link, by computation: the statement's slack, unfolded and read as an expression (sos_reify), times a positive product of quaternion norms is the target polynomial at the parameters times a non-negative one. *)
Lemma link : exists D F, 0 < D /\ 0 <= F /\ (0 + - ((((-1/2) * v_1_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_4_R_l) v_3_Rbar)))) * D = F * peval env target.
Proof.
  assert (Hq : Forall (fun p => qnR env p <> 0) [1; 5; 9]%nat) by (apply Forall_cons; [exact q_v_2_R_r_nonzero|]; apply Forall_cons; [exact q_v_3_Rbar_nonzero|]; apply Forall_cons; [exact q_v_4_R_l_nonzero|]; apply Forall_nil).
  sos_link [v_1_k_s; (qw q_v_2_R_r); (qx q_v_2_R_r); (qy q_v_2_R_r); (qz q_v_2_R_r); (qw q_v_3_Rbar); (qx q_v_3_Rbar); (qy q_v_3_Rbar); (qz q_v_3_Rbar); (qw q_v_4_R_l); (qx q_v_4_R_l); (qy q_v_4_R_l); (qz q_v_4_R_l); lam1; lam2] [1; 5; 9]%nat Hq [0; 0; 0; 0; 0; 1; 0; 0; 0; 1]%nat.
Qed.

Theorem step3_by_sos : ((((-1/2) * v_1_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_4_R_l) v_3_Rbar))) <= 0.
Proof.
  apply (le_by_slack _ _ (0 + - ((((-1/2) * v_1_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_4_R_l) v_3_Rbar))))); [reflexivity|].
  destruct link as (D & F & HD & HF & E).
  exact (slack_nonneg _ D F _ E HD HF (sos_nonneg env target blocks cert_checked grounds)).
Qed.

End Sos_thm1_V_dot_3.
