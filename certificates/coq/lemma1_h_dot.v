(** Exported from the derivation 'lemma1.h-dot' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: ḣ = (k_s/2) tr(R_rl - R_rlᵀ R̄_r²) along eq. (13)
    its place in the paper: Lemma 1 proof, eq. (15)
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_h_dot.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_r : quat.
Hypothesis q_v_1_R_r_nonzero : qn q_v_1_R_r <> 0.
Local Notation v_1_R_r := (rot q_v_1_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_Rbar : quat.
Hypothesis q_v_2_Rbar_nonzero : qn q_v_2_Rbar <> 0.
Local Notation v_2_Rbar := (rot q_v_2_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_R_l : quat.
Hypothesis q_v_3_R_l_nonzero : qn q_v_3_R_l <> 0.
Local Notation v_3_R_l := (rot q_v_3_R_l).

(** k_s: a scalar *)
Variable v_4_k_s : R.
Hypothesis v_4_k_s_pos : 0 < v_4_k_s.


(** Step 1: tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) = tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l))
    (algebra (h = tr(R̄_r) - 1, R_r constant)) *)
Theorem step1 : (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))) = (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 2: tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) = k_s tr(R_rᵀ R̄ sk(R̄ᵀ R_l))
    (algebra (eq. (13))) *)
Theorem step2 : (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))) = (v_4_k_s * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 3: k_s tr(R_rᵀ R̄ sk(R̄ᵀ R_l)) = k_s tr(R_rᵀ R̄ sk((R_rᵀ R̄)ᵀ R_rᵀ R_l))
    (algebra (R̄ᵀR_l = R̄_rᵀR_rl)) *)
Theorem step3 : (v_4_k_s * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))) = (v_4_k_s * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (sk (mmul (mT (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_3_R_l)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos.
  so3_norm.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 4: k_s tr(R_rᵀ R̄ sk((R_rᵀ R̄)ᵀ R_rᵀ R_l)) = (1/2) k_s tr(R_rᵀ R_l - (R_rᵀ R_l)ᵀ R_rᵀ R̄ R_rᵀ R̄)
    (algebra (cyclic trace)) *)
Theorem step4 : (v_4_k_s * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (sk (mmul (mT (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_3_R_l)))))) = (((1/2) * v_4_k_s) * (tr (madd (mmul (mT v_1_R_r) v_3_R_l) (mneg (mmul (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_2_Rbar)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos.
  so3_norm.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** The derivation's claim: tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) = (1/2) k_s tr(R_rᵀ R_l - (R_rᵀ R_l)ᵀ R_rᵀ R̄ R_rᵀ R̄) *)
Theorem claim : (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))) = (((1/2) * v_4_k_s) * (tr (madd (mmul (mT v_1_R_r) v_3_R_l) (mneg (mmul (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_2_Rbar)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos.
  exact (eq_trans (eq_trans (eq_trans step1 step2) step3) step4).
Qed.

End lemma1_h_dot.


From Coquelicot Require Import Hierarchy Derive.
From VerifyCoq Require Import Traj.

Section ddt_trajectories.

(** R_r: constant *)
Variable v_1_R_r : M3.
(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_2_Rbar : R -> M3.
(** R_l: its value at t *)
Variable v_3_R_l : M3.
(** k_s: constant *)
Variable v_4_k_s : R.
Variable t : R.

(** The first expression is the derivative: d/dt tr(R_rᵀ R̄) - 1 along the declared dynamics,
    at every t, is tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) *)
Theorem ddt : is_mderiv v_2_Rbar t (mmul (mscale v_4_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) v_3_R_l))) -> is_derive (fun s => ((tr (mmul (mT v_1_R_r) (v_2_Rbar s))) + (- 1))) t (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) v_3_R_l))))).
Proof.
  intros D1.
  eapply deriv_unique_eq; [ d_mirror | cbv beta; traj_same ].
Qed.

End ddt_trajectories.
