(** Exported from the derivation 'lemma1.spectrum-rank' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: rank of ξξᵀ is 1
    its place in the paper: Lemma 1 proof
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_spectrum_rank.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.


(** Step 1: tr(ξ ξᵀ) = 1
    (algebra (|ξ| = 1)) *)
Theorem step1 : (tr (outer v_1_xi v_1_xi)) = 1.
Proof using v_1_xi v_1_xi_unit.
  apply (eq_by_sum _ _ (((1) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

End lemma1_spectrum_rank.
