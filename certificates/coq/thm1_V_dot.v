(** Exported from the derivation 'thm1.V-dot' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: V̇ = -(k_s/4)[tr{(R̄_r+R̄_rᵀ)(I - R̄ᵀR_l)} + tr{(R_rl+R_rlᵀ)(I - R_lᵀR̄)}] ≤ -(k_s/2)(λ1 + λ2) φ(R_lᵀR̄) ≤ 0
    its place in the paper: Theorem 1 proof, eq. (17)
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_V_dot.

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

(** assumption: λmin(R̄_r + R̄_rᵀ) ≥ 0 (Lemma 1) *)
Hypothesis assumption1 : 0 <= lam1.

(** assumption: λmin(R_rl + R_rlᵀ) > 0 (Assumption 1, item 2) *)
Hypothesis assumption2 : 0 < lam2.


(** Step 1: (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) + (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) - <vee(R_rᵀ R_l), R_lᵀ 'ω_h^s'> = (-1/4) k_s (tr((R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) (I - R̄ᵀ R_l)) + tr((R_rᵀ R_l + (R_rᵀ R_l)ᵀ) (I - R_lᵀ R̄)))
    (algebra (Ṡ_r + Ṡ_rl + Ṡ_h; the human terms cancel)) *)
Theorem step1 : ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) v_3_R_l)) (mvmul (mT v_3_R_l) v_5_omega_h_s)))) = (((-1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 lam2 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec lam2_spec.
  so3_norm.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 2: (-1/4) k_s (tr((R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) (I - R̄ᵀ R_l)) + tr((R_rᵀ R_l + (R_rᵀ R_l)ᵀ) (I - R_lᵀ R̄))) <= (-1/2) k_s (λmin(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) + λmin(R_rᵀ R_l + (R_rᵀ R_l)ᵀ)) (1/2) tr(I - R_lᵀ R̄)
    (trace inequality twice: (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R̄_r + R̄_rᵀ), B = I - R̄ᵀ R_l); (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R_rl + R_rlᵀ), B = I - R_lᵀR̄)) *)
Theorem step2 : (((-1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))) <= ((((-1/2) * v_4_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_3_R_l) v_2_Rbar))).
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
  assert (E : (((((-1/2) * v_4_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_3_R_l) v_2_Rbar))) + (- (((-1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))))) = ((((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))))) + (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam2 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_poly. }
  exact (le_by_slack _ _ _ E (Rplus_le_le_0_compat _ _ T4 T8)).
Qed.

(** Step 3: (-1/2) k_s (λmin(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) + λmin(R_rᵀ R_l + (R_rᵀ R_l)ᵀ)) (1/2) tr(I - R_lᵀ R̄) <= 0
    (λ1 ≥ 0 (Lemma 1), λ2 > 0 (Assumption 1.2), φ(Q) = ‖I - Q‖²/4: ((1/2 * (k_s > 0 (declared))) * ((assumed: λmin(R̄_r + R̄_rᵀ) ≥ 0) + (assumed: λmin(R_rl + R_rlᵀ) > 0))) * (1/4 * (square of I - R_lᵀR̄))) *)
Theorem step3 : ((((-1/2) * v_4_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_3_R_l) v_2_Rbar))) <= 0.
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 lam2 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec lam2_spec assumption1 assumption2.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T2 : 0 <= ((1/2) * v_4_k_s)) by exact (Rmult_le_pos (1/2) v_4_k_s ltac:(lra) T1).
  assert (T3 : 0 <= lam1) by exact assumption1.
  assert (T4 : 0 <= lam2) by exact (Rlt_le _ _ assumption2).
  assert (T5 : 0 <= (lam1 + lam2)) by exact (Rplus_le_le_0_compat _ _ T3 T4).
  assert (T6 : 0 <= (((1/2) * v_4_k_s) * (lam1 + lam2))) by exact (Rmult_le_pos _ _ T2 T5).
  assert (T7 : 0 <= (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))) by exact (fro2_nonneg (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))).
  assert (T8 : 0 <= ((1/4) * (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))) by exact (Rmult_le_pos (1/4) (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) ltac:(lra) T7).
  assert (T9 : 0 <= ((((1/2) * v_4_k_s) * (lam1 + lam2)) * ((1/4) * (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))) by exact (Rmult_le_pos _ _ T6 T8).
  assert (E : (0 + (- ((((-1/2) * v_4_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_3_R_l) v_2_Rbar))))) = ((((1/2) * v_4_k_s) * (lam1 + lam2)) * ((1/4) * (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))).
  { so3_norm. generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_poly. }
  exact (le_by_slack _ _ _ E T9).
Qed.

(** The derivation's claim: (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) + (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) - <vee(R_rᵀ R_l), R_lᵀ 'ω_h^s'> <= 0 *)
Theorem claim : ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) v_3_R_l)) (mvmul (mT v_3_R_l) v_5_omega_h_s)))) <= 0.
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 lam2 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec lam2_spec assumption1 assumption2.
  exact (Rle_trans _ _ _ (eq_le_trans _ _ _ step1 step2) step3).
Qed.

End thm1_V_dot.


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
(** S_h: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_6_S_h : R -> R.
Variable t : R.

(** The first expression is the derivative: d/dt (1/2) tr(I - R_rᵀ R̄) + (1/2) tr(I - R_rᵀ R_l) + S_h along the declared dynamics,
    at every t, is (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) + (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) - <vee(R_rᵀ R_l), R_lᵀ 'ω_h^s'> *)
Theorem ddt : is_mderiv v_2_Rbar t (mmul (mscale v_4_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) (v_3_R_l t)))) -> is_mderiv v_3_R_l t (mmul (v_3_R_l t) (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT (v_3_R_l t)) (v_2_Rbar t))))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s)))) -> is_derive v_6_S_h t (- (vdot (vee (mmul (mT v_1_R_r) (v_3_R_l t))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s))) -> is_derive (fun s => (((phi (mmul (mT v_1_R_r) (v_2_Rbar s))) + (phi (mmul (mT v_1_R_r) (v_3_R_l s)))) + (v_6_S_h s))) t ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) (v_3_R_l t)))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (v_3_R_l t) (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT (v_3_R_l t)) (v_2_Rbar t))))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) (v_3_R_l t))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s)))).
Proof.
  intros D1 D2 D3.
  eapply deriv_unique_eq; [ d_mirror | cbv beta; traj_same ].
Qed.

End ddt_trajectories.
