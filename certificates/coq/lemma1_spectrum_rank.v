(** Exported from the derivation 'lemma1.spectrum-rank' (verify.proof).
    Statement: rank of ξξᵀ is 1
    Paper: Lemma 1 proof *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_spectrum_rank.

(** ξ: a unit vector *)
Variable xi : V3.
Hypothesis xi_unit : vdot xi xi = 1.


(** Step 1: tr(ξξᵀ) = 1
    (algebra (|ξ| = 1)) *)
Theorem step1 : (tr (outer xi xi)) = 1.
Proof using xi xi_unit.
  apply (eq_by_sum _ _ (((1) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
Qed.

End lemma1_spectrum_rank.
