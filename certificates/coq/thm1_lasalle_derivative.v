(** Exported from the derivation 'thm1.lasalle-derivative' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: on R_l = R̄: d/dt(R_lᵀR̄) = -R_lᵀ hat(ω_h^s) R_l = -hat(R_lᵀ ω_h^s)
    its place in the paper: Theorem 1 proof, LaSalle step
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_lasalle_derivative.

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_l : quat.
Hypothesis q_v_1_R_l_nonzero : qn q_v_1_R_l <> 0.
Local Notation v_1_R_l := (rot q_v_1_R_l).

(** k_s: a scalar *)
Variable v_2_k_s : R.
Hypothesis v_2_k_s_pos : 0 < v_2_k_s.

(** ω_h^s: a vector *)
Variable v_3_omega_h_s : V3.


(** Step 1: (R_l hat(k_s vee(sk(R_lᵀ R_l)) + R_lᵀ 'ω_h^s'))ᵀ R_l + R_lᵀ k_s R_l sk(R_lᵀ R_l) = -R_lᵀ hat('ω_h^s') R_l
    (algebra (sk(I) = 0)) *)
Theorem step1 : (madd (mmul (mT (mmul v_1_R_l (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT v_1_R_l) v_1_R_l)))) (mvmul (mT v_1_R_l) v_3_omega_h_s))))) v_1_R_l) (mmul (mT v_1_R_l) (mmul (mscale v_2_k_s v_1_R_l) (sk (mmul (mT v_1_R_l) v_1_R_l))))) = (mneg (mmul (mmul (mT v_1_R_l) (hat v_3_omega_h_s)) v_1_R_l)).
Proof using q_v_1_R_l v_2_k_s v_3_omega_h_s q_v_1_R_l_nonzero v_2_k_s_pos.
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

(** Step 2: -R_lᵀ hat('ω_h^s') R_l = -hat(R_lᵀ 'ω_h^s')
    (algebra (Rᵀ hat(ω) R = hat(Rᵀω))) *)
Theorem step2 : (mneg (mmul (mmul (mT v_1_R_l) (hat v_3_omega_h_s)) v_1_R_l)) = (mneg (hat (mvmul (mT v_1_R_l) v_3_omega_h_s))).
Proof using q_v_1_R_l v_2_k_s v_3_omega_h_s q_v_1_R_l_nonzero v_2_k_s_pos.
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

(** The derivation's claim: (R_l hat(k_s vee(sk(R_lᵀ R_l)) + R_lᵀ 'ω_h^s'))ᵀ R_l + R_lᵀ k_s R_l sk(R_lᵀ R_l) = -hat(R_lᵀ 'ω_h^s') *)
Theorem claim : (madd (mmul (mT (mmul v_1_R_l (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT v_1_R_l) v_1_R_l)))) (mvmul (mT v_1_R_l) v_3_omega_h_s))))) v_1_R_l) (mmul (mT v_1_R_l) (mmul (mscale v_2_k_s v_1_R_l) (sk (mmul (mT v_1_R_l) v_1_R_l))))) = (mneg (hat (mvmul (mT v_1_R_l) v_3_omega_h_s))).
Proof using q_v_1_R_l v_2_k_s v_3_omega_h_s q_v_1_R_l_nonzero v_2_k_s_pos.
  exact (eq_trans step1 step2).
Qed.

End thm1_lasalle_derivative.


From Coquelicot Require Import Hierarchy Derive.
From VerifyCoq Require Import Traj.

Section ddt_trajectories.

(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_4_Rbar : R -> M3.
(** R_l: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_1_R_l : R -> M3.
(** k_s: constant *)
Variable v_2_k_s : R.
(** ω_h^s: its value at t *)
Variable v_3_omega_h_s : V3.
Variable t : R.

(** The first expression is the derivative: d/dt R_lᵀ R̄ along the declared dynamics and the substitution,
    at every t, is (R_l hat(k_s vee(sk(R_lᵀ R_l)) + R_lᵀ 'ω_h^s'))ᵀ R_l + R_lᵀ k_s R_l sk(R_lᵀ R_l) *)
Theorem ddt : is_mderiv v_4_Rbar t (mmul (mscale v_2_k_s (v_4_Rbar t)) (sk (mmul (mT (v_4_Rbar t)) (v_1_R_l t)))) -> is_mderiv v_1_R_l t (mmul (v_1_R_l t) (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT (v_1_R_l t)) (v_4_Rbar t))))) (mvmul (mT (v_1_R_l t)) v_3_omega_h_s)))) -> (v_4_Rbar t) = (v_1_R_l t) -> is_mderiv (fun s => (mmul (mT (v_1_R_l s)) (v_4_Rbar s))) t (madd (mmul (mT (mmul (v_1_R_l t) (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT (v_1_R_l t)) (v_1_R_l t))))) (mvmul (mT (v_1_R_l t)) v_3_omega_h_s))))) (v_1_R_l t)) (mmul (mT (v_1_R_l t)) (mmul (mscale v_2_k_s (v_1_R_l t)) (sk (mmul (mT (v_1_R_l t)) (v_1_R_l t)))))).
Proof.
  intros D1 D2 E1.
  eapply mderiv_unique_eq; [ d_mirror | cbv beta; try rewrite E1; traj_same ].
Qed.

End ddt_trajectories.
