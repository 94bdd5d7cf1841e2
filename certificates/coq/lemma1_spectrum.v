(** Exported from the derivation 'lemma1.spectrum' (verify.proof).
    Statement: R + Rᵀ = 2 ξξᵀ + 2cosθ (I - ξξᵀ): eigenvalue 2 on ξ, 2cosθ twice on ξ⊥
    Paper: Lemma 1 proof, eigenvalues {2, 2cosθ, 2cosθ} *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_spectrum.

(** ξ: a unit vector *)
Variable xi : V3.
Hypothesis xi_unit : vdot xi xi = 1.

(** θ: an angle *)
Variable theta : R.


(** Step 1: R̄_r + R̄_rᵀ = 2 ξξᵀ + 2 cos(θ) (I - ξξᵀ)
    (algebra (Rodrigues, |ξ| = 1)) *)
Theorem step1 : (madd (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi)))) (mT (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi)))))) = (madd (mscale 2 (outer xi xi)) (mscale (2 * (cos theta)) (madd I3 (mneg (outer xi xi))))).
Proof using xi theta xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ (((2 * (cos theta) + (-2)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ (((2 * (cos theta) + (-2)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ (((2 * (cos theta) + (-2)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
Qed.

End lemma1_spectrum.
