(** Exported from the derivation 'thm1.V-dot-zero-implies-sync' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: (k_s/8)(λ1 + λ2)‖I - R_lᵀR̄‖² ≤ -V̇: with λ1 + λ2 > 0, V̇ = 0 forces R_l = R̄
    its place in the paper: Theorem 1 proof, 'V̇ = 0 iff R_l = R̄'
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_V_dot_zero_implies_sync.

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

(** lambda_min(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) lam1.

(** lambda_min(R_rᵀ R_l + (R_rᵀ R_l)ᵀ) *)
Variable lam2 : R.
Hypothesis lam2_spec : lam_min_spec (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) lam2.


(** Step 1: (1/8) k_s (λmin(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) + λmin(R_rᵀ R_l + (R_rᵀ R_l)ᵀ)) tr((I - R_lᵀ R̄)ᵀ (I - R_lᵀ R̄)) <= -((1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) + (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) - <vee(R_rᵀ R_l), R_lᵀ 'ω_h^s'>)
    (the bound of eq. (17) with φ(Q) = ‖I - Q‖²/4: (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R̄_r + R̄_rᵀ), B = I - R̄ᵀ R_l); (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R_rl + R_rlᵀ), B = I - R_lᵀR̄)) *)
Theorem step1 : ((((1/8) * v_4_k_s) * (lam1 + lam2)) * (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))) <= (- ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) v_3_R_l)) (mvmul (mT v_3_R_l) v_5_omega_h_s))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 lam2 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec lam2_spec.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T2 : 0 <= ((1/4) * v_4_k_s)) by exact (Rmult_le_pos (1/4) v_4_k_s ltac:(lra) T1).
  assert (P1 : (mT (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar)))) = (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar)))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))) = (mscale (1/2) (mmul (mT (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))).
  { so3_norm. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (T3 : 0 <= ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))))) by exact (trace_lower_bound (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))) (1/2) lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (T4 : 0 <= (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))))))) by exact (Rmult_le_pos _ _ T2 T3).
  assert (T5 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T6 : 0 <= ((1/4) * v_4_k_s)) by exact (Rmult_le_pos (1/4) v_4_k_s ltac:(lra) T5).
  assert (P3 : (mT (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l)))) = (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l)))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P4 : (sym (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) = (mscale (1/2) (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))).
  { so3_norm. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (T7 : 0 <= ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam2 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))) by exact (trace_lower_bound (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))) (1/2) lam2 P3 P4 ltac:(lra) lam2_spec).
  assert (T8 : 0 <= (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam2 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))))) by exact (Rmult_le_pos _ _ T6 T7).
  assert (E : ((- ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) v_3_R_l)) (mvmul (mT v_3_R_l) v_5_omega_h_s))))) + (- ((((1/8) * v_4_k_s) * (lam1 + lam2)) * (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))) = ((((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))))) + (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam2 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))))).
  { so3_norm. generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_poly. }
  exact (le_by_slack _ _ _ E (Rplus_le_le_0_compat _ _ T4 T8)).
Qed.

End thm1_V_dot_zero_implies_sync.
