(** Exported from the derivation 'lemma1.boundary-sign-direct' (verify.proof).
    Statement: the paper's closing argument: sym(R_rl) ≻ 0 and I - ξξᵀ ⪰ 0 give ḣ ≥ 0
    Paper: Lemma 1 proof, last paragraph *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_boundary_sign_direct.

(** ξ: a unit vector *)
Variable xi : V3.
Hypothesis xi_unit : vdot xi xi = 1.

(** R_rl: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_rl : quat.
Hypothesis q_R_rl_nonzero : qn q_R_rl <> 0.
Local Notation R_rl := (rot q_R_rl).

(** k_s: a scalar *)
Variable k_s : R.
Hypothesis k_s_pos : 0 < k_s.

(** assumption: sym(R_rl) ≻ 0 (Assumption 1, item 2) *)
Hypothesis assumption1 : pd R_rl.


(** Step 1: k_s tr(sym(R_rl) (I - ξξᵀ)) >= 0
    (tr of a product of PSD matrices: (k_s > 0 (declared)) * (trace of a product of PSD matrices, A = sym(R_rl), B = I - ξξᵀ)) *)
Theorem step1 : (k_s * (tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi)))))) >= 0.
Proof using xi q_R_rl k_s xi_unit q_R_rl_nonzero k_s_pos assumption1.
  assert (T1 : 0 <= k_s) by exact (Rlt_le _ _ k_s_pos).
  assert (P1 : (mT (sym R_rl)) = (sym R_rl)).
  { generalize (rot q_R_rl) as G_R_rl; intro G_R_rl. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym R_rl) = (sym R_rl)).
  { generalize (rot q_R_rl) as G_R_rl; intro G_R_rl. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P3 : (sym (madd I3 (mneg (outer xi xi)))) = (mscale 1 (mmul (mT (hat xi)) (hat xi)))).
  { so3_split. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_unfold; field; so3_nonzero]. }
  assert (T2 : 0 <= (tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi)))))) by exact (trace_pd_product (sym R_rl) R_rl (madd I3 (mneg (outer xi xi))) (hat xi) 1 P1 P2 assumption1 P3 ltac:(lra)).
  assert (T3 : 0 <= (k_s * (tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi))))))) by exact (Rmult_le_pos _ _ T1 T2).
  assert (E : ((k_s * (tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi)))))) + (- 0)) = (k_s * (tr (mmul (sym R_rl) (madd I3 (mneg (outer xi xi))))))).
  { generalize (rot q_R_rl) as G_R_rl; intro G_R_rl. so3_poly. }
  exact (ge_by_slack _ _ _ E T3).
Qed.

End lemma1_boundary_sign_direct.
