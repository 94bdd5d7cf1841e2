(** Exported from the derivation 'thm1.S_rl-dot' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: Ṡ_rl ≤ -(k_s/2) λmin(R_rl + R_rlᵀ) φ(R_lᵀR̄) + k_s φ(R̄_r) - k_s φ(R_rl) + <sk(R_rl)^∨, ω_h^b>
    its place in the paper: Theorem 1 proof, Ṡ_rl chain
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_S_rl_dot.

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

(** ω_h^s: a vector *)
Variable v_5_omega_h_s : V3.

(** lambda_min(R_rᵀ R_l + (R_rᵀ R_l)ᵀ) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) lam1.


(** Step 1: (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) = (-1/2) tr(R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s'))
    (algebra (φ(R) = tr(I - R)/2)) *)
Theorem step1 : ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s)))))))) = ((-1/2) * (tr (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  so3_poly.
Qed.

(** Step 2: (-1/2) tr(R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) = (-1/2) tr(R_rᵀ R_l (k_s sk((R_rᵀ R_l)ᵀ R_rᵀ R̄) + hat(R_lᵀ 'ω_h^s')))
    (algebra (eq. (12b), R_lᵀR̄ = R_rlᵀR̄_r)) *)
Theorem step2 : ((-1/2) * (tr (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))) = ((-1/2) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (madd (mscale v_4_k_s (sk (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)))) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  so3_norm_hat.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  so3_poly.
Qed.

(** Step 3: (-1/2) tr(R_rᵀ R_l (k_s sk((R_rᵀ R_l)ᵀ R_rᵀ R̄) + hat(R_lᵀ 'ω_h^s'))) = (-1/2) k_s tr(R_rᵀ R_l sk((R_rᵀ R_l)ᵀ R_rᵀ R̄)) - (1/2) tr(R_rᵀ R_l hat(R_lᵀ 'ω_h^s'))
    (algebra (linearity)) *)
Theorem step3 : ((-1/2) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (madd (mscale v_4_k_s (sk (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)))) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s)))))) = ((((-1/2) * v_4_k_s) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (sk (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)))))) + (- ((1/2) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s))))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  so3_poly.
Qed.

(** Step 4: (-1/2) k_s tr(R_rᵀ R_l sk((R_rᵀ R_l)ᵀ R_rᵀ R̄)) - (1/2) tr(R_rᵀ R_l hat(R_lᵀ 'ω_h^s')) <= (-1/2) k_s λmin(R_rᵀ R_l + (R_rᵀ R_l)ᵀ) (1/2) tr(I - R_lᵀ R̄) + k_s (1/2) tr(I - R_rᵀ R̄) - k_s (1/2) tr(I - R_rᵀ R_l) + <vee(sk(R_rᵀ R_l)), R_lᵀ 'ω_h^s'>
    (as for Ṡ_r, and tr(R hat ω) = -2<sk(R)^∨, ω>: (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R_rl + R_rlᵀ), B = I - R_lᵀR̄)) *)
Theorem step4 : ((((-1/2) * v_4_k_s) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (sk (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)))))) + (- ((1/2) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s))))))) <= (((((((-1/2) * v_4_k_s) * lam1) * (phi (mmul (mT v_3_R_l) v_2_Rbar))) + (v_4_k_s * (phi (mmul (mT v_1_R_r) v_2_Rbar)))) + (- (v_4_k_s * (phi (mmul (mT v_1_R_r) v_3_R_l))))) + (vdot (vee (sk (mmul (mT v_1_R_r) v_3_R_l))) (mvmul (mT v_3_R_l) v_5_omega_h_s))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T2 : 0 <= ((1/4) * v_4_k_s)) by exact (Rmult_le_pos (1/4) v_4_k_s ltac:(lra) T1).
  assert (P1 : (mT (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l)))) = (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l)))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) = (mscale (1/2) (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))).
  { so3_norm. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (T3 : 0 <= ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))) by exact (trace_lower_bound (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))) (1/2) lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (T4 : 0 <= (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))))) by exact (Rmult_le_pos _ _ T2 T3).
  assert (E : ((((((((-1/2) * v_4_k_s) * lam1) * (phi (mmul (mT v_3_R_l) v_2_Rbar))) + (v_4_k_s * (phi (mmul (mT v_1_R_r) v_2_Rbar)))) + (- (v_4_k_s * (phi (mmul (mT v_1_R_r) v_3_R_l))))) + (vdot (vee (sk (mmul (mT v_1_R_r) v_3_R_l))) (mvmul (mT v_3_R_l) v_5_omega_h_s))) + (- ((((-1/2) * v_4_k_s) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (sk (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)))))) + (- ((1/2) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))) = (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))))).
  { so3_norm. generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. so3_poly. }
  exact (le_by_slack _ _ _ E T4).
Qed.

(** The derivation's claim: (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) <= (-1/2) k_s λmin(R_rᵀ R_l + (R_rᵀ R_l)ᵀ) (1/2) tr(I - R_lᵀ R̄) + k_s (1/2) tr(I - R_rᵀ R̄) - k_s (1/2) tr(I - R_rᵀ R_l) + <vee(sk(R_rᵀ R_l)), R_lᵀ 'ω_h^s'> *)
Theorem claim : ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s)))))))) <= (((((((-1/2) * v_4_k_s) * lam1) * (phi (mmul (mT v_3_R_l) v_2_Rbar))) + (v_4_k_s * (phi (mmul (mT v_1_R_r) v_2_Rbar)))) + (- (v_4_k_s * (phi (mmul (mT v_1_R_r) v_3_R_l))))) + (vdot (vee (sk (mmul (mT v_1_R_r) v_3_R_l))) (mvmul (mT v_3_R_l) v_5_omega_h_s))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  exact (eq_le_trans _ _ _ (eq_trans (eq_trans step1 step2) step3) step4).
Qed.

End thm1_S_rl_dot.


From Coquelicot Require Import Hierarchy Derive.
From VerifyCoq Require Import Traj.

Section ddt_trajectories.

(** R_r: constant *)
Variable v_1_R_r : M3.
(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_2_Rbar : R -> M3.
(** R_l: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_3_R_l : R -> M3.
(** k_s: constant *)
Variable v_4_k_s : R.
(** ω_h^s: its value at t *)
Variable v_5_omega_h_s : V3.
Variable t : R.

(** The first expression is the derivative: d/dt (1/2) tr(I - R_rᵀ R_l) along the declared dynamics,
    at every t, is (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) *)
Theorem ddt : is_mderiv v_3_R_l t (mmul (v_3_R_l t) (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT (v_3_R_l t)) (v_2_Rbar t))))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s)))) -> is_derive (fun s => (phi (mmul (mT v_1_R_r) (v_3_R_l s)))) t ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (v_3_R_l t) (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT (v_3_R_l t)) (v_2_Rbar t))))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s)))))))).
Proof.
  intros D1.
  eapply deriv_unique_eq; [ d_mirror | cbv beta; traj_same ].
Qed.

End ddt_trajectories.
