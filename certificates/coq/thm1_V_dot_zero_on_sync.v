(** Exported from the derivation 'thm1.V-dot-zero-on-sync' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: V̇ = 0 when R_l = R̄, whatever the human commands
    its place in the paper: Theorem 1 proof, 'V̇ = 0 iff R_l = R̄'
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_V_dot_zero_on_sync.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_r : quat.
Hypothesis q_v_1_R_r_nonzero : qn q_v_1_R_r <> 0.
Local Notation v_1_R_r := (rot q_v_1_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_Rbar : quat.
Hypothesis q_v_2_Rbar_nonzero : qn q_v_2_Rbar <> 0.
Local Notation v_2_Rbar := (rot q_v_2_Rbar).

(** k_s: a scalar *)
Variable v_3_k_s : R.
Hypothesis v_3_k_s_pos : 0 < v_3_k_s.

(** ω_h^s: a vector *)
Variable v_4_omega_h_s : V3.


(** Step 1: (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R̄)) + (1/2) tr(-R_rᵀ R̄ hat(k_s vee(sk(R̄ᵀ R̄)) + R̄ᵀ 'ω_h^s')) - <vee(R_rᵀ R̄), R̄ᵀ 'ω_h^s'> = 0
    (algebra (R_l = R̄)) *)
Theorem step1 : ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_3_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_2_Rbar))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_2_Rbar (hat (vadd (vscale v_3_k_s (vee (sk (mmul (mT v_2_Rbar) v_2_Rbar)))) (mvmul (mT v_2_Rbar) v_4_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) v_2_Rbar)) (mvmul (mT v_2_Rbar) v_4_omega_h_s)))) = 0.
Proof using q_v_1_R_r q_v_2_Rbar v_3_k_s v_4_omega_h_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero v_3_k_s_pos.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  so3_poly.
Qed.

End thm1_V_dot_zero_on_sync.
