(** Exported from the derivation 'lemma1.boundary-h-dot' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: on the boundary ḣ = k_s tr{sym(R_rl)(I - ξξᵀ)} ≥ k_s λmin(sym R_rl) tr(I - ξξᵀ) ≥ 0
    its place in the paper: Lemma 1 proof, after eq. (15)
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_boundary_h_dot.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.

(** θ: an angle *)
Variable v_2_theta : R.

(** R_rl: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_R_rl : quat.
Hypothesis q_v_3_R_rl_nonzero : qn q_v_3_R_rl <> 0.
Local Notation v_3_R_rl := (rot q_v_3_R_rl).

(** k_s: a scalar *)
Variable v_4_k_s : R.
Hypothesis v_4_k_s_pos : 0 < v_4_k_s.

(** lambda_min(sym(R_rl)) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (sym v_3_R_rl) lam1.

(** side condition: boundary h = 0, i.e. cosθ = 0 *)
Hypothesis condition1 : (cos v_2_theta) = 0.

(** assumption: λmin(sym(R_rl)) > 0 (Assumption 1, item 2) *)
Hypothesis assumption1 : 0 < lam1.


(** Step 1: (1/2) k_s tr(R_rl - R_rlᵀ (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ))) = (1/4) k_s tr(R_rl + R_rlᵀ - R_rl (2 ξ ξᵀ - I) - R_rlᵀ (2 ξ ξᵀ - I))
    (algebra (R̄_r² = 2ξξᵀ - I is symmetric on the boundary)) *)
Theorem step1 : (((1/2) * v_4_k_s) * (tr (madd v_3_R_rl (mneg (mmul (mmul (mT v_3_R_rl) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))))))) = (((1/4) * v_4_k_s) * (tr (madd (madd (madd v_3_R_rl (mT v_3_R_rl)) (mneg (mmul v_3_R_rl (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))) (mneg (mmul (mT v_3_R_rl) (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))))).
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1.
  generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl.
  apply (eq_by_sum _ _ ((((-1/2) * (v1 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) ^ 2 * (cos v_2_theta) * (m22 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) ^ 2 * (cos v_2_theta) * (m33 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) ^ 2 * (m12 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) ^ 2 * (m21 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) * (m12 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) * (m21 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (m12 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (m21 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 * (m13 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 * (m31 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m13 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m31 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (m13 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (m31 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m23 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m32 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (sin v_2_theta) * (m23 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (sin v_2_theta) * (m32 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) ^ 2 * (cos v_2_theta) * (m11 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) ^ 2 * (cos v_2_theta) * (m33 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 * (m23 G_v_3_R_rl) * v_4_k_s + (1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 * (m32 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m23 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m32 G_v_3_R_rl) * v_4_k_s + (1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (m23 G_v_3_R_rl) * v_4_k_s + (1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (m32 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m13 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m31 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) * (sin v_2_theta) * (m13 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) * (sin v_2_theta) * (m31 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) ^ 2 * (cos v_2_theta) * (m11 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) ^ 2 * (cos v_2_theta) * (m22 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v3 v_1_xi) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v3 v_1_xi) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m12 G_v_3_R_rl) * v_4_k_s + (-1) * (v3 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m21 G_v_3_R_rl) * v_4_k_s + (-1) * (v3 v_1_xi) * (sin v_2_theta) * (m12 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) * (sin v_2_theta) * (m21 G_v_3_R_rl) * v_4_k_s + (-1/2) * (cos v_2_theta) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (-1/2) * (cos v_2_theta) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (1/2) * (sin v_2_theta) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (1/2) * (sin v_2_theta) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (m11 G_v_3_R_rl) * v_4_k_s + (1/2) * (m22 G_v_3_R_rl) * v_4_k_s + (1/2) * (m33 G_v_3_R_rl) * v_4_k_s) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1) + (((-1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (m12 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (m21 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (m13 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (m31 G_v_3_R_rl) * v_4_k_s + (1/2) * (v2 v_1_xi) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (m23 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (m32 G_v_3_R_rl) * v_4_k_s + (1/2) * (v3 v_1_xi) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v3 v_1_xi) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (1/2) * (m22 G_v_3_R_rl) * v_4_k_s + (1/2) * (m33 G_v_3_R_rl) * v_4_k_s) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) * (m12 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) * (m21 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m13 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m31 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (sin v_2_theta) * (m23 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (sin v_2_theta) * (m32 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) * (m11 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) ^ 2 * (cos v_2_theta) * (m22 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m23 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m32 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) * (sin v_2_theta) * (m13 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) * (sin v_2_theta) * (m31 G_v_3_R_rl) * v_4_k_s + (-1) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) * (m11 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) ^ 2 * (cos v_2_theta) * (m33 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) * (sin v_2_theta) * (m12 G_v_3_R_rl) * v_4_k_s + (-1) * (v3 v_1_xi) * (sin v_2_theta) * (m21 G_v_3_R_rl) * v_4_k_s + (-1) * (cos v_2_theta) * (m22 G_v_3_R_rl) * v_4_k_s + (-1) * (cos v_2_theta) * (m33 G_v_3_R_rl) * v_4_k_s) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit), (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
Qed.

(** Step 2: (1/4) k_s tr(R_rl + R_rlᵀ - R_rl (2 ξ ξᵀ - I) - R_rlᵀ (2 ξ ξᵀ - I)) = (1/2) k_s tr(sym(R_rl) (I - (2 ξ ξᵀ - I)))
    (algebra (sym(A) = (A + Aᵀ)/2)) *)
Theorem step2 : (((1/4) * v_4_k_s) * (tr (madd (madd (madd v_3_R_rl (mT v_3_R_rl)) (mneg (mmul v_3_R_rl (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))) (mneg (mmul (mT v_3_R_rl) (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))))) = (((1/2) * v_4_k_s) * (tr (mmul (sym v_3_R_rl) (madd I3 (mneg (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))))).
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1.
  generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl.
  so3_poly.
Qed.

(** Step 3: (1/2) k_s tr(sym(R_rl) (I - (2 ξ ξᵀ - I))) = k_s tr(sym(R_rl) (I - ξ ξᵀ))
    (algebra (I - (2ξξᵀ - I) = 2(I - ξξᵀ))) *)
Theorem step3 : (((1/2) * v_4_k_s) * (tr (mmul (sym v_3_R_rl) (madd I3 (mneg (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))))) = (v_4_k_s * (tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))).
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1.
  generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl.
  so3_poly.
Qed.

(** Step 4: k_s tr(sym(R_rl) (I - ξ ξᵀ)) >= k_s λmin(sym(R_rl)) tr(I - ξ ξᵀ)
    (trace inequality; premise I - ξξᵀ = hat(ξ)ᵀhat(ξ) ⪰ 0: (k_s > 0 (declared)) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = sym(R_rl), B = I - ξξᵀ)) *)
Theorem step4 : (v_4_k_s * (tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))) >= ((v_4_k_s * lam1) * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))).
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (P1 : (mT (sym v_3_R_rl)) = (sym v_3_R_rl)).
  { generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd I3 (mneg (outer v_1_xi v_1_xi)))) = (mscale 1 (mmul (mT (hat v_1_xi)) (hat v_1_xi)))).
  { so3_split. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. }
  assert (T2 : 0 <= ((tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))))) + (- (lam1 * (tr (madd I3 (mneg (outer v_1_xi v_1_xi)))))))) by exact (trace_lower_bound (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))) (hat v_1_xi) 1 lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (T3 : 0 <= (v_4_k_s * ((tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))))) + (- (lam1 * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))))))) by exact (Rmult_le_pos _ _ T1 T2).
  assert (E : ((v_4_k_s * (tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))) + (- ((v_4_k_s * lam1) * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))))) = (v_4_k_s * ((tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))))) + (- (lam1 * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))))))).
  { generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl. so3_poly. }
  exact (ge_by_slack _ _ _ E T3).
Qed.

(** Step 5: k_s λmin(sym(R_rl)) tr(I - ξ ξᵀ) >= 0
    (λmin(sym R_rl) > 0 and tr(I - ξξᵀ) = |hat ξ|²: ((k_s > 0 (declared)) * (assumed: λmin(sym(R_rl)) > 0)) * (square of hat(ξ))) *)
Theorem step5 : ((v_4_k_s * lam1) * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))) >= 0.
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1 assumption1.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T2 : 0 <= lam1) by exact (Rlt_le _ _ assumption1).
  assert (T3 : 0 <= (v_4_k_s * lam1)) by exact (Rmult_le_pos _ _ T1 T2).
  assert (T4 : 0 <= (tr (mmul (mT (hat v_1_xi)) (hat v_1_xi)))) by exact (fro2_nonneg (hat v_1_xi)).
  assert (T5 : 0 <= ((v_4_k_s * lam1) * (tr (mmul (mT (hat v_1_xi)) (hat v_1_xi))))) by exact (Rmult_le_pos _ _ T3 T4).
  assert (E : (((v_4_k_s * lam1) * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))) + (- 0)) = ((v_4_k_s * lam1) * (tr (mmul (mT (hat v_1_xi)) (hat v_1_xi))))).
  { generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl. apply (eq_by_sum _ _ ((((-3) * v_4_k_s * lam1) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly]. }
  exact (ge_by_slack _ _ _ E T5).
Qed.

(** The derivation's claim: (1/2) k_s tr(R_rl - R_rlᵀ (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ))) >= 0 *)
Theorem claim : (((1/2) * v_4_k_s) * (tr (madd v_3_R_rl (mneg (mmul (mmul (mT v_3_R_rl) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))))))) >= 0.
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1 assumption1.
  exact (Rge_trans _ _ _ (eq_ge_trans _ _ _ (eq_trans (eq_trans step1 step2) step3) step4) step5).
Qed.

End lemma1_boundary_h_dot.
