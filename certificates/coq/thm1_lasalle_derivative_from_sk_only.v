(** Exported from the derivation 'thm1.lasalle-derivative-from-sk-only' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: with only sk(R_lᵀR̄) = 0 (R_lᵀR̄ = 2ξξᵀ - I, angle π) the formula changes
    its place in the paper: Theorem 1 proof, 'which implies sk(R_lᵀR̄)^∨ = 0'
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_lasalle_derivative_from_sk_only.

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_l : quat.
Hypothesis q_v_1_R_l_nonzero : qn q_v_1_R_l <> 0.
Local Notation v_1_R_l := (rot q_v_1_R_l).

(** k_s: a scalar *)
Variable v_2_k_s : R.
Hypothesis v_2_k_s_pos : 0 < v_2_k_s.

(** ω_h^s: a vector *)
Variable v_3_omega_h_s : V3.

(** ξ: a unit vector *)
Variable v_4_xi : V3.
Hypothesis v_4_xi_unit : vdot v_4_xi v_4_xi = 1.


(** Step 1: (R_l hat(k_s vee(sk(R_lᵀ R_l (2 ξ ξᵀ - I))) + R_lᵀ 'ω_h^s'))ᵀ R_l (2 ξ ξᵀ - I) + R_lᵀ k_s R_l (2 ξ ξᵀ - I) sk((R_l (2 ξ ξᵀ - I))ᵀ R_l) = -R_lᵀ hat('ω_h^s') R_l (2 ξ ξᵀ - I)
    (algebra (sk(2ξξᵀ - I) = 0)) *)
Theorem step1 : (madd (mmul (mT (mmul v_1_R_l (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT v_1_R_l) (mmul v_1_R_l (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3))))))) (mvmul (mT v_1_R_l) v_3_omega_h_s))))) (mmul v_1_R_l (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) (mmul (mT v_1_R_l) (mmul (mscale v_2_k_s (mmul v_1_R_l (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) (sk (mmul (mT (mmul v_1_R_l (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) v_1_R_l))))) = (mneg (mmul (mmul (mmul (mT v_1_R_l) (hat v_3_omega_h_s)) v_1_R_l) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))).
Proof using q_v_1_R_l v_2_k_s v_3_omega_h_s v_4_xi q_v_1_R_l_nonzero v_2_k_s_pos v_4_xi_unit.
  so3_norm_hat.
  generalize (rot q_v_1_R_l) as G_v_1_R_l; intro G_v_1_R_l.
  so3_split.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
Qed.

End thm1_lasalle_derivative_from_sk_only.


From Coquelicot Require Import Hierarchy Derive.
From VerifyCoq Require Import Traj.

Section ddt_trajectories.

(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_5_Rbar : R -> M3.
(** R_l: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_1_R_l : R -> M3.
(** k_s: constant *)
Variable v_2_k_s : R.
(** ω_h^s: its value at t *)
Variable v_3_omega_h_s : V3.
(** ξ: its value at t *)
Variable v_4_xi : V3.
Variable t : R.

(** The first expression is the derivative: d/dt R_lᵀ R̄ along the declared dynamics and the substitution,
    at every t, is (R_l hat(k_s vee(sk(R_lᵀ R_l (2 ξ ξᵀ - I))) + R_lᵀ 'ω_h^s'))ᵀ R_l (2 ξ ξᵀ - I) + R_lᵀ k_s R_l (2 ξ ξᵀ - I) sk((R_l (2 ξ ξᵀ - I))ᵀ R_l) *)
Theorem ddt : is_mderiv v_5_Rbar t (mmul (mscale v_2_k_s (v_5_Rbar t)) (sk (mmul (mT (v_5_Rbar t)) (v_1_R_l t)))) -> is_mderiv v_1_R_l t (mmul (v_1_R_l t) (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT (v_1_R_l t)) (v_5_Rbar t))))) (mvmul (mT (v_1_R_l t)) v_3_omega_h_s)))) -> (v_5_Rbar t) = (mmul (v_1_R_l t) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3))) -> is_mderiv (fun s => (mmul (mT (v_1_R_l s)) (v_5_Rbar s))) t (madd (mmul (mT (mmul (v_1_R_l t) (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT (v_1_R_l t)) (mmul (v_1_R_l t) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3))))))) (mvmul (mT (v_1_R_l t)) v_3_omega_h_s))))) (mmul (v_1_R_l t) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) (mmul (mT (v_1_R_l t)) (mmul (mscale v_2_k_s (mmul (v_1_R_l t) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) (sk (mmul (mT (mmul (v_1_R_l t) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) (v_1_R_l t)))))).
Proof.
  intros D1 D2 E1.
  eapply mderiv_unique_eq; [ d_mirror | cbv beta; try rewrite E1; traj_same ].
Qed.

End ddt_trajectories.
