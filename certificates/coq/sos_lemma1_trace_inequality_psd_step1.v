(** SOS certificate sos-8b9cbb93bcaa05da0231.json, exported to Coq.
    It proves step 1 of the derivation 'lemma1.trace-inequality-psd' (verify.paper_proofs): tr(A GᵀG) >= λmin(A) tr(GᵀG).
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by field. *)

From Coq Require Import Reals QArith List Lra.
From VerifyCoq Require Import SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.

Section Sos_lemma1_trace_inequality_psd_1.

(** A: a symmetric matrix, by its six entries *)
Variables v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23 : R.
Local Notation v_1_A := (symm v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23).

(** G: a matrix *)
Variable v_2_G : M3.

(** lambda_min(A): a lower bound suffices *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec v_1_A lam1.

Let env : list R := [v_1_A_11; v_1_A_22; v_1_A_33; v_1_A_12; v_1_A_13; v_1_A_23; (m11 v_2_G); (m12 v_2_G); (m13 v_2_G); (m21 v_2_G); (m22 v_2_G); (m23 v_2_G); (m31 v_2_G); (m32 v_2_G); (m33 v_2_G); lam1].

Definition target : poly := [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;2;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;0;0;0;2;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;0;0;2;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;0;1;1;0]%nat, 2%Q); ([0;0;0;0;0;1;0;0;0;0;1;1;0;0;0;0]%nat, 2%Q); ([0;0;0;0;0;1;0;1;1;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;0;0;1;0;0;0;0;0;0;0;1;0;1;0]%nat, 2%Q); ([0;0;0;0;1;0;0;0;0;1;0;1;0;0;0;0]%nat, 2%Q); ([0;0;0;0;1;0;1;0;1;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;0;1;0;0;0;0;0;0;0;0;1;1;0;0]%nat, 2%Q); ([0;0;0;1;0;0;0;0;0;1;1;0;0;0;0;0]%nat, 2%Q); ([0;0;0;1;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;1;0;0;0;0;0;0;0;0;0;0;0;2;0]%nat, 1%Q); ([0;0;1;0;0;0;0;0;0;0;0;2;0;0;0;0]%nat, 1%Q); ([0;0;1;0;0;0;0;0;2;0;0;0;0;0;0;0]%nat, 1%Q); ([0;1;0;0;0;0;0;0;0;0;0;0;0;2;0;0]%nat, 1%Q); ([0;1;0;0;0;0;0;0;0;0;2;0;0;0;0;0]%nat, 1%Q); ([0;1;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 1%Q); ([1;0;0;0;0;0;0;0;0;0;0;0;2;0;0;0]%nat, 1%Q); ([1;0;0;0;0;0;0;0;0;2;0;0;0;0;0;0]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 1%Q)].

(** block 1: spectral: λmin(A) I ⪯ A (symmetric) *)
Definition H1 : list (list poly) := [[[([0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;1;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]]; [[([0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;1;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;1;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]]; [[([0;0;0;0;1;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;1;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;1;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]]].
Definition S1 : list (Q * list poly) :=
  [(1%Q, [[([0;0;0;0;0;0;0;0;0;0;0;0;1;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;1;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;1;0]%nat, 1%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;0;1;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;1;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;1;0;0;0;0]%nat, 1%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;1;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;1;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;1;0;0;0;0;0;0;0]%nat, 1%Q)]])].

Lemma H1_psd : mult_psd env H1.
Proof.
  apply (mult_psd_3 env H1 (1 * 1) (fun x1 x2 x3 => qform (msub (sym v_1_A) (mscale lam1 I3)) (mkV x1 x2 x3))).
  - reflexivity.
  - exact (Rmult_le_pos _ _ Rle_0_1 Rle_0_1).
  - intros x1 x2 x3. exact (lam1_spec (mkV x1 x2 x3)).
  - intros x1 x2 x3. rewrite (evalM_Z env H1 (eq_refl true <: all_int_matrix H1 = true)). unfold H1. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. so3_unfold. lra.
Qed.

Definition blocks : list block := [(mkBlock H1 S1)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_compute. reflexivity. Qed.

Lemma grounds : blocks_psd env blocks.
Proof. exact (blocks_psd_cons env (mkBlock H1 S1) _ H1_psd (blocks_psd_nil env)). Qed.

(** The link: the slack of the statement times 1 is the target polynomial at the parameters (times the factors divided out of it), by field. *)
Lemma link : exists D F, 0 < D /\ 0 <= F /\ ((tr (mmul v_1_A (mmul (mT v_2_G) v_2_G))) + - (lam1 * (tr (mmul (mT v_2_G) v_2_G)))) * D = F * peval env target.
Proof.
  exists 1, 1. split; [exact Rlt_0_1|]. split; [exact Rle_0_1|].
  rewrite (zeval_peval env target (eq_refl true <: all_int target = true)).
  unfold target. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. so3_unfold. lra.
Qed.

Theorem step1_by_sos : (tr (mmul v_1_A (mmul (mT v_2_G) v_2_G))) >= (lam1 * (tr (mmul (mT v_2_G) v_2_G))).
Proof.
  apply (ge_by_slack _ _ ((tr (mmul v_1_A (mmul (mT v_2_G) v_2_G))) + - (lam1 * (tr (mmul (mT v_2_G) v_2_G))))); [reflexivity|].
  destruct link as (D & F & HD & HF & E).
  exact (slack_nonneg _ D F _ E HD HF (sos_nonneg env target blocks cert_checked grounds)).
Qed.

End Sos_lemma1_trace_inequality_psd_1.
