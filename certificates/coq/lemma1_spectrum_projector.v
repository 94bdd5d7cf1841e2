(** Exported from the derivation 'lemma1.spectrum-projector' (verify.proof).
    Statement: ξξᵀ is an orthogonal projector of rank tr(ξξᵀ) = 1
    Paper: Lemma 1 proof, eigenvalues *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_spectrum_projector.

(** ξ: a unit vector *)
Variable xi : V3.
Hypothesis xi_unit : vdot xi xi = 1.


(** Step 1: ξξᵀ ξξᵀ = ξξᵀ
    (algebra (|ξ| = 1)) *)
Theorem step1 : (mmul (outer xi xi) (outer xi xi)) = (outer xi xi).
Proof using xi xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ ((((v1 xi) ^ 2) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 xi) * (v2 xi)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 xi) * (v3 xi)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 xi) * (v2 xi)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 xi) ^ 2) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 xi) * (v3 xi)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 xi) * (v3 xi)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 xi) * (v3 xi)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v3 xi) ^ 2) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
Qed.

End lemma1_spectrum_projector.
