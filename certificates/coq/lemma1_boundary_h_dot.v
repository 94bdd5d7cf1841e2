(** Exported from the derivation 'lemma1.boundary-h-dot' (verify.proof).
    Statement: on the boundary ḣ = k_s tr{sym(R_rl)(I - ξξᵀ)} ≥ k_s λmin(sym R_rl) tr(I - ξξᵀ) ≥ 0
    Paper: Lemma 1 proof, after eq. (15) *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_boundary_h_dot.

(** ξ: a unit vector *)
Variable xi : V3.
Hypothesis xi_unit : vdot xi xi = 1.

(** θ: an angle *)
Variable theta : R.

(** R_rl: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_rl : quat.
Hypothesis q_R_rl_nonzero : qn q_R_rl <> 0.
Local Notation R_rl := (rot q_R_rl).

(** k_s: a scalar *)
Variable k_s : R.
Hypothesis k_s_pos : 0 < k_s.

(** lambda_min(sym(R_rl)) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (sym R_rl) lam1.

(** side condition: boundary h = 0, i.e. cosθ = 0 *)
Hypothesis condition1 : (cos theta) = 0.

(** assumption: λmin(sym(R_rl)) > 0 (Assumption 1, item 2) *)
Hypothesis assumption1 : 0 < lam1.


(** Step 1: (1/2) k_s tr(R_rl - R_rlᵀ R̄_r R̄_r) = (1/4) k_s tr(R_rl + R_rlᵀ - R_rl (2ξξᵀ - I) - R_rlᵀ (2ξξᵀ - I))
    (algebra (R̄_r² = 2ξξᵀ - I is symmetric on the boundary)) *)
Theorem step1 : (((1/2) * k_s) * (tr (madd R_rl (mneg (mmul (mmul (mT R_rl) (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi))))) (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi))))))))) = (((1/4) * k_s) * (tr (madd (madd (madd R_rl (mT R_rl)) (mneg (mmul R_rl (madd (mscale 2 (outer xi xi)) (mneg I3))))) (mneg (mmul (mT R_rl) (madd (mscale 2 (outer xi xi)) (mneg I3))))))).
Proof using xi theta q_R_rl k_s lam1 xi_unit q_R_rl_nonzero k_s_pos lam1_spec condition1.
  generalize (rot q_R_rl) as G_R_rl; intro G_R_rl.
  apply (eq_by_sum _ _ ((((-1/2) * (v1 xi) ^ 2 * (cos theta) ^ 2 * (m22 G_R_rl) * k_s + (-1/2) * (v1 xi) ^ 2 * (cos theta) ^ 2 * (m33 G_R_rl) * k_s + (v1 xi) ^ 2 * (cos theta) * (m22 G_R_rl) * k_s + (v1 xi) ^ 2 * (cos theta) * (m33 G_R_rl) * k_s + (-1/2) * (v1 xi) ^ 2 * (m22 G_R_rl) * k_s + (-1/2) * (v1 xi) ^ 2 * (m33 G_R_rl) * k_s + (1/2) * (v1 xi) * (v2 xi) * (cos theta) ^ 2 * (m12 G_R_rl) * k_s + (1/2) * (v1 xi) * (v2 xi) * (cos theta) ^ 2 * (m21 G_R_rl) * k_s + (-1) * (v1 xi) * (v2 xi) * (cos theta) * (m12 G_R_rl) * k_s + (-1) * (v1 xi) * (v2 xi) * (cos theta) * (m21 G_R_rl) * k_s + (1/2) * (v1 xi) * (v2 xi) * (m12 G_R_rl) * k_s + (1/2) * (v1 xi) * (v2 xi) * (m21 G_R_rl) * k_s + (1/2) * (v1 xi) * (v3 xi) * (cos theta) ^ 2 * (m13 G_R_rl) * k_s + (1/2) * (v1 xi) * (v3 xi) * (cos theta) ^ 2 * (m31 G_R_rl) * k_s + (-1) * (v1 xi) * (v3 xi) * (cos theta) * (m13 G_R_rl) * k_s + (-1) * (v1 xi) * (v3 xi) * (cos theta) * (m31 G_R_rl) * k_s + (1/2) * (v1 xi) * (v3 xi) * (m13 G_R_rl) * k_s + (1/2) * (v1 xi) * (v3 xi) * (m31 G_R_rl) * k_s + (v1 xi) * (cos theta) * (sin theta) * (m23 G_R_rl) * k_s + (-1) * (v1 xi) * (cos theta) * (sin theta) * (m32 G_R_rl) * k_s + (-1) * (v1 xi) * (sin theta) * (m23 G_R_rl) * k_s + (v1 xi) * (sin theta) * (m32 G_R_rl) * k_s + (-1/2) * (v2 xi) ^ 2 * (cos theta) ^ 2 * (m11 G_R_rl) * k_s + (-1/2) * (v2 xi) ^ 2 * (cos theta) ^ 2 * (m33 G_R_rl) * k_s + (v2 xi) ^ 2 * (cos theta) * (m11 G_R_rl) * k_s + (v2 xi) ^ 2 * (cos theta) * (m33 G_R_rl) * k_s + (-1/2) * (v2 xi) ^ 2 * (m11 G_R_rl) * k_s + (-1/2) * (v2 xi) ^ 2 * (m33 G_R_rl) * k_s + (1/2) * (v2 xi) * (v3 xi) * (cos theta) ^ 2 * (m23 G_R_rl) * k_s + (1/2) * (v2 xi) * (v3 xi) * (cos theta) ^ 2 * (m32 G_R_rl) * k_s + (-1) * (v2 xi) * (v3 xi) * (cos theta) * (m23 G_R_rl) * k_s + (-1) * (v2 xi) * (v3 xi) * (cos theta) * (m32 G_R_rl) * k_s + (1/2) * (v2 xi) * (v3 xi) * (m23 G_R_rl) * k_s + (1/2) * (v2 xi) * (v3 xi) * (m32 G_R_rl) * k_s + (-1) * (v2 xi) * (cos theta) * (sin theta) * (m13 G_R_rl) * k_s + (v2 xi) * (cos theta) * (sin theta) * (m31 G_R_rl) * k_s + (v2 xi) * (sin theta) * (m13 G_R_rl) * k_s + (-1) * (v2 xi) * (sin theta) * (m31 G_R_rl) * k_s + (-1/2) * (v3 xi) ^ 2 * (cos theta) ^ 2 * (m11 G_R_rl) * k_s + (-1/2) * (v3 xi) ^ 2 * (cos theta) ^ 2 * (m22 G_R_rl) * k_s + (v3 xi) ^ 2 * (cos theta) * (m11 G_R_rl) * k_s + (v3 xi) ^ 2 * (cos theta) * (m22 G_R_rl) * k_s + (-1/2) * (v3 xi) ^ 2 * (m11 G_R_rl) * k_s + (-1/2) * (v3 xi) ^ 2 * (m22 G_R_rl) * k_s + (v3 xi) * (cos theta) * (sin theta) * (m12 G_R_rl) * k_s + (-1) * (v3 xi) * (cos theta) * (sin theta) * (m21 G_R_rl) * k_s + (-1) * (v3 xi) * (sin theta) * (m12 G_R_rl) * k_s + (v3 xi) * (sin theta) * (m21 G_R_rl) * k_s + (-1/2) * (cos theta) ^ 2 * (m22 G_R_rl) * k_s + (-1/2) * (cos theta) ^ 2 * (m33 G_R_rl) * k_s + (1/2) * (sin theta) ^ 2 * (m22 G_R_rl) * k_s + (1/2) * (sin theta) ^ 2 * (m33 G_R_rl) * k_s + (m11 G_R_rl) * k_s + (1/2) * (m22 G_R_rl) * k_s + (1/2) * (m33 G_R_rl) * k_s) * (1) / (1)) * (vdot xi xi - 1) + (((-1/2) * (v1 xi) * (v2 xi) * (m12 G_R_rl) * k_s + (-1/2) * (v1 xi) * (v2 xi) * (m21 G_R_rl) * k_s + (-1/2) * (v1 xi) * (v3 xi) * (m13 G_R_rl) * k_s + (-1/2) * (v1 xi) * (v3 xi) * (m31 G_R_rl) * k_s + (1/2) * (v2 xi) ^ 2 * (m11 G_R_rl) * k_s + (-1/2) * (v2 xi) ^ 2 * (m22 G_R_rl) * k_s + (-1/2) * (v2 xi) * (v3 xi) * (m23 G_R_rl) * k_s + (-1/2) * (v2 xi) * (v3 xi) * (m32 G_R_rl) * k_s + (1/2) * (v3 xi) ^ 2 * (m11 G_R_rl) * k_s + (-1/2) * (v3 xi) ^ 2 * (m33 G_R_rl) * k_s + (1/2) * (m22 G_R_rl) * k_s + (1/2) * (m33 G_R_rl) * k_s) * (1) / (1)) * (cos theta * cos theta + sin theta * sin theta - 1) + (((v1 xi) * (v2 xi) * (cos theta) * (m12 G_R_rl) * k_s + (v1 xi) * (v2 xi) * (cos theta) * (m21 G_R_rl) * k_s + (v1 xi) * (v3 xi) * (cos theta) * (m13 G_R_rl) * k_s + (v1 xi) * (v3 xi) * (cos theta) * (m31 G_R_rl) * k_s + (v1 xi) * (sin theta) * (m23 G_R_rl) * k_s + (-1) * (v1 xi) * (sin theta) * (m32 G_R_rl) * k_s + (-1) * (v2 xi) ^ 2 * (cos theta) * (m11 G_R_rl) * k_s + (v2 xi) ^ 2 * (cos theta) * (m22 G_R_rl) * k_s + (v2 xi) * (v3 xi) * (cos theta) * (m23 G_R_rl) * k_s + (v2 xi) * (v3 xi) * (cos theta) * (m32 G_R_rl) * k_s + (-1) * (v2 xi) * (sin theta) * (m13 G_R_rl) * k_s + (v2 xi) * (sin theta) * (m31 G_R_rl) * k_s + (-1) * (v3 xi) ^ 2 * (cos theta) * (m11 G_R_rl) * k_s + (v3 xi) ^ 2 * (cos theta) * (m33 G_R_rl) * k_s + (v3 xi) * (sin theta) * (m12 G_R_rl) * k_s + (-1) * (v3 xi) * (sin theta) * (m21 G_R_rl) * k_s + (-1) * (cos theta) * (m22 G_R_rl) * k_s + (-1) * (cos theta) * (m33 G_R_rl) * k_s) * (1) / (1)) * ((cos theta) - 0))); [rewrite (Rminus_diag_eq _ _ xi_unit), (circle theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
Qed.

(** Step 2: (1/4) k_s tr(R_rl + R_rlᵀ - R_rl (2ξξᵀ - I) - R_rlᵀ (2ξξᵀ - I)) = (1/2) k_s tr(sym(R_rl) (I - (2ξξᵀ - I)))
    (algebra (sym(A) = (A + Aᵀ)/2)) *)
Theorem step2 : (((1/4) * k_s) * (tr (madd (madd (madd R_rl (mT R_rl)) (mneg (mmul R_rl (madd (mscale 2 (outer xi xi)) (mneg I3))))) (mneg (mmul (mT R_rl) (madd (mscale 2 (outer xi xi)) (mneg I3))))))) = (((1/2) * k_s) * (tr (mmul (sym R_rl) (madd I3 (mneg (madd (mscale 2 (outer xi xi)) (mneg I3))))))).
Proof using xi theta q_R_rl k_s lam1 xi_unit q_R_rl_nonzero k_s_pos lam1_spec condition1.
  generalize (rot q_R_rl) as G_R_rl; intro G_R_rl.
  so3_poly.
Qed.

(** Step 3: (1/2) k_s tr(sym(R_rl) (I - (2ξξᵀ - I))) = k_s tr(sym(R_rl) (I - ξξᵀ))
    (algebra (I - (2ξξᵀ - I) = 2(I - ξξᵀ))) *)
Theorem step3 : (((1/2) * k_s) * (tr (mmul (sym R_rl) (madd I3 (mneg (madd (mscale 2 (outer xi xi)) (mneg I3))))))) = (k_s * (tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi)))))).
Proof using xi theta q_R_rl k_s lam1 xi_unit q_R_rl_nonzero k_s_pos lam1_spec condition1.
  generalize (rot q_R_rl) as G_R_rl; intro G_R_rl.
  so3_poly.
Qed.

(** Step 4: k_s tr(sym(R_rl) (I - ξξᵀ)) >= k_s λmin(sym(R_rl)) tr(I - ξξᵀ)
    (trace inequality; premise I - ξξᵀ = hat(ξ)ᵀhat(ξ) ⪰ 0: (k_s > 0 (declared)) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = sym(R_rl), B = I - ξξᵀ)) *)
Theorem step4 : (k_s * (tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi)))))) >= ((k_s * lam1) * (tr (madd I3 (mneg (outer xi xi))))).
Proof using xi theta q_R_rl k_s lam1 xi_unit q_R_rl_nonzero k_s_pos lam1_spec condition1.
  assert (T1 : 0 <= k_s) by exact (Rlt_le _ _ k_s_pos).
  assert (P1 : (mT (sym R_rl)) = (sym R_rl)).
  { generalize (rot q_R_rl) as G_R_rl; intro G_R_rl. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd I3 (mneg (outer xi xi)))) = (mscale 1 (mmul (mT (hat xi)) (hat xi)))).
  { so3_split. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_unfold; field; so3_nonzero]. }
  assert (T2 : 0 <= ((tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi))))) + (- (lam1 * (tr (madd I3 (mneg (outer xi xi)))))))) by exact (trace_lower_bound (sym R_rl) (madd I3 (mneg (outer xi xi))) (hat xi) 1 lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (T3 : 0 <= (k_s * ((tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi))))) + (- (lam1 * (tr (madd I3 (mneg (outer xi xi))))))))) by exact (Rmult_le_pos _ _ T1 T2).
  assert (E : ((k_s * (tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi)))))) + (- ((k_s * lam1) * (tr (madd I3 (mneg (outer xi xi))))))) = (k_s * ((tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi))))) + (- (lam1 * (tr (madd I3 (mneg (outer xi xi))))))))).
  { generalize (rot q_R_rl) as G_R_rl; intro G_R_rl. so3_poly. }
  exact (ge_by_slack _ _ _ E T3).
Qed.

(** Step 5: k_s λmin(sym(R_rl)) tr(I - ξξᵀ) >= 0
    (λmin(sym R_rl) > 0 and tr(I - ξξᵀ) = |hat ξ|²: ((k_s > 0 (declared)) * (assumed: λmin(sym(R_rl)) > 0)) * (square of hat(ξ))) *)
Theorem step5 : ((k_s * lam1) * (tr (madd I3 (mneg (outer xi xi))))) >= 0.
Proof using xi theta q_R_rl k_s lam1 xi_unit q_R_rl_nonzero k_s_pos lam1_spec condition1 assumption1.
  assert (T1 : 0 <= k_s) by exact (Rlt_le _ _ k_s_pos).
  assert (T2 : 0 <= lam1) by exact (Rlt_le _ _ assumption1).
  assert (T3 : 0 <= (k_s * lam1)) by exact (Rmult_le_pos _ _ T1 T2).
  assert (T4 : 0 <= (tr (mmul (mT (hat xi)) (hat xi)))) by exact (fro2_nonneg (hat xi)).
  assert (T5 : 0 <= ((k_s * lam1) * (tr (mmul (mT (hat xi)) (hat xi))))) by exact (Rmult_le_pos _ _ T3 T4).
  assert (E : (((k_s * lam1) * (tr (madd I3 (mneg (outer xi xi))))) + (- 0)) = ((k_s * lam1) * (tr (mmul (mT (hat xi)) (hat xi))))).
  { generalize (rot q_R_rl) as G_R_rl; intro G_R_rl. apply (eq_by_sum _ _ ((((-3) * k_s * lam1) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly]. }
  exact (ge_by_slack _ _ _ E T5).
Qed.

(** The derivation's claim: (1/2) k_s tr(R_rl - R_rlᵀ R̄_r R̄_r) >= 0 *)
Theorem claim : (((1/2) * k_s) * (tr (madd R_rl (mneg (mmul (mmul (mT R_rl) (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi))))) (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi))))))))) >= 0.
Proof using xi theta q_R_rl k_s lam1 xi_unit q_R_rl_nonzero k_s_pos lam1_spec condition1 assumption1.
  exact (Rge_trans _ _ _ (eq_ge_trans _ _ _ (eq_trans (eq_trans step1 step2) step3) step4) step5).
Qed.

End lemma1_boundary_h_dot.
