(** Exported from the derivation 'lemma1.spectrum-projector' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: ξξᵀ is an orthogonal projector of rank tr(ξξᵀ) = 1
    its place in the paper: Lemma 1 proof, eigenvalues
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_spectrum_projector.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.


(** Step 1: ξ ξᵀ ξ ξᵀ = ξ ξᵀ
    (algebra (|ξ| = 1)) *)
Theorem step1 : (mmul (outer v_1_xi v_1_xi) (outer v_1_xi v_1_xi)) = (outer v_1_xi v_1_xi).
Proof using v_1_xi v_1_xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v2 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v2 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v3 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

End lemma1_spectrum_projector.
