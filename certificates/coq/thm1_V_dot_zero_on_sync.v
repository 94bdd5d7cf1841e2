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


From Coquelicot Require Import Hierarchy Derive.
From VerifyCoq Require Import Traj.

Section ddt_trajectories.

(** R_r: constant *)
Variable v_1_R_r : M3.
(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_2_Rbar : R -> M3.
(** R_l: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_5_R_l : R -> M3.
(** k_s: constant *)
Variable v_3_k_s : R.
(** ω_h^s: its value at t *)
Variable v_4_omega_h_s : V3.
(** S_h: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_6_S_h : R -> R.
Variable t : R.

(** The first expression is the derivative: d/dt (1/2) tr(I - R_rᵀ R̄) + (1/2) tr(I - R_rᵀ R_l) + S_h along the declared dynamics and the substitution,
    at every t, is (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R̄)) + (1/2) tr(-R_rᵀ R̄ hat(k_s vee(sk(R̄ᵀ R̄)) + R̄ᵀ 'ω_h^s')) - <vee(R_rᵀ R̄), R̄ᵀ 'ω_h^s'> *)
Theorem ddt : is_mderiv v_2_Rbar t (mmul (mscale v_3_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) (v_5_R_l t)))) -> is_mderiv v_5_R_l t (mmul (v_5_R_l t) (hat (vadd (vscale v_3_k_s (vee (sk (mmul (mT (v_5_R_l t)) (v_2_Rbar t))))) (mvmul (mT (v_5_R_l t)) v_4_omega_h_s)))) -> is_derive v_6_S_h t (- (vdot (vee (mmul (mT v_1_R_r) (v_5_R_l t))) (mvmul (mT (v_5_R_l t)) v_4_omega_h_s))) -> (v_5_R_l t) = (v_2_Rbar t) -> is_derive (fun s => (((phi (mmul (mT v_1_R_r) (v_2_Rbar s))) + (phi (mmul (mT v_1_R_r) (v_5_R_l s)))) + (v_6_S_h s))) t ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_3_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) (v_2_Rbar t)))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (v_2_Rbar t) (hat (vadd (vscale v_3_k_s (vee (sk (mmul (mT (v_2_Rbar t)) (v_2_Rbar t))))) (mvmul (mT (v_2_Rbar t)) v_4_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) (v_2_Rbar t))) (mvmul (mT (v_2_Rbar t)) v_4_omega_h_s)))).
Proof.
  intros D1 D2 D3 E1.
  eapply deriv_unique_eq; [ d_mirror | cbv beta; try rewrite E1; traj_same ].
Qed.

End ddt_trajectories.
