(** Exported from the derivation 'lemma1.trace-inequality-sym-psd' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: B need not be symmetric: sym(B) ⪰ 0 suffices (tr(A hat v) = 0)
    its place in the paper: repair of the quoted inequality
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_trace_inequality_sym_psd.

(** A: a symmetric matrix, by its six entries *)
Variables v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23 : R.
Local Notation v_1_A := (symm v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23).

(** G: a matrix *)
Variable v_2_G : M3.

(** v: a vector *)
Variable v_3_v : V3.

(** lambda_min(A) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec v_1_A lam1.


(** Step 1: tr(A (Gᵀ G + hat(v))) >= λmin(A) tr(Gᵀ G + hat(v))
    (trace inequality tr(AB) >= lambda_min(A) tr(B), A = A, B = (GᵀG + hat v)) *)
Theorem step1 : (tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) >= (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))).
Proof using v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23 v_2_G v_3_v lam1 lam1_spec.
  assert (P1 : (mT v_1_A) = v_1_A).
  { so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v))) = (mscale 1 (mmul (mT v_2_G) v_2_G))).
  { so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (T1 : 0 <= ((tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) + (- (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v))))))) by exact (trace_lower_bound v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)) v_2_G 1 lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (E : ((tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) + (- (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))))) = ((tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) + (- (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v))))))).
  { so3_poly. }
  exact (ge_by_slack _ _ _ E T1).
Qed.

End lemma1_trace_inequality_sym_psd.
