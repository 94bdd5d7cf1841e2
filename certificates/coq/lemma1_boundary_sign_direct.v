(** Exported from the derivation 'lemma1.boundary-sign-direct' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: the paper's closing argument: sym(R_rl) ≻ 0 and I - ξξᵀ ⪰ 0 give ḣ ≥ 0
    its place in the paper: Lemma 1 proof, last paragraph
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_boundary_sign_direct.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.

(** R_rl: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_R_rl : quat.
Hypothesis q_v_2_R_rl_nonzero : qn q_v_2_R_rl <> 0.
Local Notation v_2_R_rl := (rot q_v_2_R_rl).

(** k_s: a scalar *)
Variable v_3_k_s : R.
Hypothesis v_3_k_s_pos : 0 < v_3_k_s.

(** assumption: sym(R_rl) ≻ 0 (Assumption 1, item 2) *)
Hypothesis assumption1 : pd v_2_R_rl.


(** Step 1: k_s tr(sym(R_rl) (I - ξ ξᵀ)) >= 0
    (tr of a product of PSD matrices: (k_s > 0 (declared)) * (trace of a product of PSD matrices, A = sym(R_rl), B = I - ξξᵀ)) *)
Theorem step1 : (v_3_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))) >= 0.
Proof using v_1_xi q_v_2_R_rl v_3_k_s v_1_xi_unit q_v_2_R_rl_nonzero v_3_k_s_pos assumption1.
  assert (T1 : 0 <= v_3_k_s) by exact (Rlt_le _ _ v_3_k_s_pos).
  assert (P1 : (mT (sym v_2_R_rl)) = (sym v_2_R_rl)).
  { generalize (rot q_v_2_R_rl) as G_v_2_R_rl; intro G_v_2_R_rl. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym v_2_R_rl) = (sym v_2_R_rl)).
  { generalize (rot q_v_2_R_rl) as G_v_2_R_rl; intro G_v_2_R_rl. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P3 : (sym (madd I3 (mneg (outer v_1_xi v_1_xi)))) = (mscale 1 (mmul (mT (hat v_1_xi)) (hat v_1_xi)))).
  { so3_split. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. }
  assert (T2 : 0 <= (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))) by exact (trace_pd_product (sym v_2_R_rl) v_2_R_rl (madd I3 (mneg (outer v_1_xi v_1_xi))) (hat v_1_xi) 1 P1 P2 assumption1 P3 ltac:(lra)).
  assert (T3 : 0 <= (v_3_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))))))) by exact (Rmult_le_pos _ _ T1 T2).
  assert (E : ((v_3_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))) + (- 0)) = (v_3_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))))))).
  { generalize (rot q_v_2_R_rl) as G_v_2_R_rl; intro G_v_2_R_rl. so3_poly. }
  exact (ge_by_slack _ _ _ E T3).
Qed.

End lemma1_boundary_sign_direct.
