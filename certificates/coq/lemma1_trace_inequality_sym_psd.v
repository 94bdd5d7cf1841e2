(** Exported from the derivation 'lemma1.trace-inequality-sym-psd' (verify.proof).
    Statement: B need not be symmetric: sym(B) ⪰ 0 suffices (tr(A hat v) = 0)
    Paper: repair of the quoted inequality *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_trace_inequality_sym_psd.

(** A: a symmetric matrix, by its six entries *)
Variables A_11 A_22 A_33 A_12 A_13 A_23 : R.
Local Notation A := (symm A_11 A_22 A_33 A_12 A_13 A_23).

(** G: a matrix *)
Variable G : M3.

(** v: a vector *)
Variable v : V3.

(** lambda_min(A) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec A lam1.


(** Step 1: tr(A (GᵀG + hat v)) >= λmin(A) tr((GᵀG + hat v))
    (trace inequality tr(AB) >= lambda_min(A) tr(B), A = A, B = (GᵀG + hat v)) *)
Theorem step1 : (tr (mmul A (madd (mmul (mT G) G) (hat v)))) >= (lam1 * (tr (madd (mmul (mT G) G) (hat v)))).
Proof using A_11 A_22 A_33 A_12 A_13 A_23 G v lam1 lam1_spec.
  assert (P1 : (mT A) = A).
  { so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd (mmul (mT G) G) (hat v))) = (mscale 1 (mmul (mT G) G))).
  { so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (T1 : 0 <= ((tr (mmul A (madd (mmul (mT G) G) (hat v)))) + (- (lam1 * (tr (madd (mmul (mT G) G) (hat v))))))) by exact (trace_lower_bound A (madd (mmul (mT G) G) (hat v)) G 1 lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (E : ((tr (mmul A (madd (mmul (mT G) G) (hat v)))) + (- (lam1 * (tr (madd (mmul (mT G) G) (hat v)))))) = ((tr (mmul A (madd (mmul (mT G) G) (hat v)))) + (- (lam1 * (tr (madd (mmul (mT G) G) (hat v))))))).
  { so3_poly. }
  exact (ge_by_slack _ _ _ E T1).
Qed.

End lemma1_trace_inequality_sym_psd.
