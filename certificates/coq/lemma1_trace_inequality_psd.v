(** Exported from the derivation 'lemma1.trace-inequality-psd' (verify.proof).
    Statement: tr(AB) ≥ λmin(A) tr(B) for A symmetric and B = GᵀG ⪰ 0
    Paper: repair of the quoted inequality *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_trace_inequality_psd.

(** A: a symmetric matrix, by its six entries *)
Variables A_11 A_22 A_33 A_12 A_13 A_23 : R.
Local Notation A := (symm A_11 A_22 A_33 A_12 A_13 A_23).

(** G: a matrix *)
Variable G : M3.

(** lambda_min(A) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec A lam1.


(** Step 1: tr(A GᵀG) >= λmin(A) tr(GᵀG)
    (trace inequality tr(AB) >= lambda_min(A) tr(B), A = A, B = GᵀG) *)
Theorem step1 : (tr (mmul A (mmul (mT G) G))) >= (lam1 * (tr (mmul (mT G) G))).
Proof using A_11 A_22 A_33 A_12 A_13 A_23 G lam1 lam1_spec.
  assert (P1 : (mT A) = A).
  { so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (mmul (mT G) G)) = (mscale 1 (mmul (mT G) G))).
  { so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (T1 : 0 <= ((tr (mmul A (mmul (mT G) G))) + (- (lam1 * (tr (mmul (mT G) G)))))) by exact (trace_lower_bound A (mmul (mT G) G) G 1 lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (E : ((tr (mmul A (mmul (mT G) G))) + (- (lam1 * (tr (mmul (mT G) G))))) = ((tr (mmul A (mmul (mT G) G))) + (- (lam1 * (tr (mmul (mT G) G)))))).
  { so3_poly. }
  exact (ge_by_slack _ _ _ E T1).
Qed.

End lemma1_trace_inequality_psd.
