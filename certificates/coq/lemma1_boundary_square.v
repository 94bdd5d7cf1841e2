(** Exported from the derivation 'lemma1.boundary-square' (verify.proof).
    Statement: on the boundary, R̄_r² = 2ξξᵀ - I
    Paper: Lemma 1 proof, boundary *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_boundary_square.

(** ξ: a unit vector *)
Variable xi : V3.
Hypothesis xi_unit : vdot xi xi = 1.

(** θ: an angle *)
Variable theta : R.

(** side condition: boundary h = 0, i.e. cosθ = 0 *)
Hypothesis condition1 : (cos theta) = 0.


(** Step 1: R̄_r R̄_r = I + 2 sin(θ) cos(θ) hat(ξ) + (1 - (cos(θ) cos(θ) - sin(θ) sin(θ))) hat(ξ) hat(ξ)
    (algebra (R̄_r² = exp(2θ ξ^), double-angle formulas)) *)
Theorem step1 : (mmul (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi)))) (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi))))) = (madd (madd I3 (mscale ((2 * (sin theta)) * (cos theta)) (hat xi))) (mscale (1 + (- (((cos theta) * (cos theta)) + (- ((sin theta) * (sin theta)))))) (mmul (hat xi) (hat xi)))).
Proof using xi theta xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ ((((v2 xi) ^ 2 * (cos theta) ^ 2 + (-2) * (v2 xi) ^ 2 * (cos theta) + (v2 xi) ^ 2 + (v3 xi) ^ 2 * (cos theta) ^ 2 + (-2) * (v3 xi) ^ 2 * (cos theta) + (v3 xi) ^ 2) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 xi) * (v2 xi) * (cos theta) ^ 2 + 2 * (v1 xi) * (v2 xi) * (cos theta) + (-1) * (v1 xi) * (v2 xi) + (-2) * (v3 xi) * (cos theta) * (sin theta) + 2 * (v3 xi) * (sin theta)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 xi) * (v3 xi) * (cos theta) ^ 2 + 2 * (v1 xi) * (v3 xi) * (cos theta) + (-1) * (v1 xi) * (v3 xi) + 2 * (v2 xi) * (cos theta) * (sin theta) + (-2) * (v2 xi) * (sin theta)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 xi) * (v2 xi) * (cos theta) ^ 2 + 2 * (v1 xi) * (v2 xi) * (cos theta) + (-1) * (v1 xi) * (v2 xi) + 2 * (v3 xi) * (cos theta) * (sin theta) + (-2) * (v3 xi) * (sin theta)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 xi) ^ 2 * (cos theta) ^ 2 + (-2) * (v1 xi) ^ 2 * (cos theta) + (v1 xi) ^ 2 + (v3 xi) ^ 2 * (cos theta) ^ 2 + (-2) * (v3 xi) ^ 2 * (cos theta) + (v3 xi) ^ 2) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-2) * (v1 xi) * (cos theta) * (sin theta) + 2 * (v1 xi) * (sin theta) + (-1) * (v2 xi) * (v3 xi) * (cos theta) ^ 2 + 2 * (v2 xi) * (v3 xi) * (cos theta) + (-1) * (v2 xi) * (v3 xi)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 xi) * (v3 xi) * (cos theta) ^ 2 + 2 * (v1 xi) * (v3 xi) * (cos theta) + (-1) * (v1 xi) * (v3 xi) + (-2) * (v2 xi) * (cos theta) * (sin theta) + 2 * (v2 xi) * (sin theta)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ (((2 * (v1 xi) * (cos theta) * (sin theta) + (-2) * (v1 xi) * (sin theta) + (-1) * (v2 xi) * (v3 xi) * (cos theta) ^ 2 + 2 * (v2 xi) * (v3 xi) * (cos theta) + (-1) * (v2 xi) * (v3 xi)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 xi) ^ 2 * (cos theta) ^ 2 + (-2) * (v1 xi) ^ 2 * (cos theta) + (v1 xi) ^ 2 + (v2 xi) ^ 2 * (cos theta) ^ 2 + (-2) * (v2 xi) ^ 2 * (cos theta) + (v2 xi) ^ 2) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
Qed.

(** Step 2: I + 2 sin(θ) cos(θ) hat(ξ) + (1 - (cos(θ) cos(θ) - sin(θ) sin(θ))) hat(ξ) hat(ξ) = I + 2 hat(ξ) hat(ξ)
    (algebra (cosθ = 0)) *)
Theorem step2 : (madd (madd I3 (mscale ((2 * (sin theta)) * (cos theta)) (hat xi))) (mscale (1 + (- (((cos theta) * (cos theta)) + (- ((sin theta) * (sin theta)))))) (mmul (hat xi) (hat xi)))) = (madd I3 (mscale 2 (mmul (hat xi) (hat xi)))).
Proof using xi theta xi_unit condition1.
  so3_split.
  - apply (eq_by_sum _ _ ((((-1) * (v2 xi) ^ 2 + (-1) * (v3 xi) ^ 2) * (1) / (1)) * (cos theta * cos theta + sin theta * sin theta - 1) + ((2 * (v2 xi) ^ 2 * (cos theta) + 2 * (v3 xi) ^ 2 * (cos theta)) * (1) / (1)) * ((cos theta) - 0))); [rewrite (circle theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 xi) * (v2 xi)) * (1) / (1)) * (cos theta * cos theta + sin theta * sin theta - 1) + (((-2) * (v1 xi) * (v2 xi) * (cos theta) + (-2) * (v3 xi) * (sin theta)) * (1) / (1)) * ((cos theta) - 0))); [rewrite (circle theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 xi) * (v3 xi)) * (1) / (1)) * (cos theta * cos theta + sin theta * sin theta - 1) + (((-2) * (v1 xi) * (v3 xi) * (cos theta) + 2 * (v2 xi) * (sin theta)) * (1) / (1)) * ((cos theta) - 0))); [rewrite (circle theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 xi) * (v2 xi)) * (1) / (1)) * (cos theta * cos theta + sin theta * sin theta - 1) + (((-2) * (v1 xi) * (v2 xi) * (cos theta) + 2 * (v3 xi) * (sin theta)) * (1) / (1)) * ((cos theta) - 0))); [rewrite (circle theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((cos theta) ^ 2 + (-1) * (sin theta) ^ 2 + 1) * (1) / (1)) * (vdot xi xi - 1) + (((v2 xi) ^ 2 + (-1)) * (1) / (1)) * (cos theta * cos theta + sin theta * sin theta - 1) + (((-2) * (v2 xi) ^ 2 * (cos theta) + 2 * (cos theta)) * (1) / (1)) * ((cos theta) - 0))); [rewrite (Rminus_diag_eq _ _ xi_unit), (circle theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 xi) * (v3 xi)) * (1) / (1)) * (cos theta * cos theta + sin theta * sin theta - 1) + (((-2) * (v1 xi) * (sin theta) + (-2) * (v2 xi) * (v3 xi) * (cos theta)) * (1) / (1)) * ((cos theta) - 0))); [rewrite (circle theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 xi) * (v3 xi)) * (1) / (1)) * (cos theta * cos theta + sin theta * sin theta - 1) + (((-2) * (v1 xi) * (v3 xi) * (cos theta) + (-2) * (v2 xi) * (sin theta)) * (1) / (1)) * ((cos theta) - 0))); [rewrite (circle theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 xi) * (v3 xi)) * (1) / (1)) * (cos theta * cos theta + sin theta * sin theta - 1) + ((2 * (v1 xi) * (sin theta) + (-2) * (v2 xi) * (v3 xi) * (cos theta)) * (1) / (1)) * ((cos theta) - 0))); [rewrite (circle theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((cos theta) ^ 2 + (-1) * (sin theta) ^ 2 + 1) * (1) / (1)) * (vdot xi xi - 1) + (((v3 xi) ^ 2 + (-1)) * (1) / (1)) * (cos theta * cos theta + sin theta * sin theta - 1) + (((-2) * (v3 xi) ^ 2 * (cos theta) + 2 * (cos theta)) * (1) / (1)) * ((cos theta) - 0))); [rewrite (Rminus_diag_eq _ _ xi_unit), (circle theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
Qed.

(** Step 3: I + 2 hat(ξ) hat(ξ) = 2 ξξᵀ - I
    (algebra (ξ^² = ξξᵀ - I for |ξ| = 1)) *)
Theorem step3 : (madd I3 (mscale 2 (mmul (hat xi) (hat xi)))) = (madd (mscale 2 (outer xi xi)) (mneg I3)).
Proof using xi theta xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ ((((-2)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ ((((-2)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ ((((-2)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
Qed.

(** The derivation's claim: R̄_r R̄_r = 2 ξξᵀ - I *)
Theorem claim : (mmul (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi)))) (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi))))) = (madd (mscale 2 (outer xi xi)) (mneg I3)).
Proof using xi theta xi_unit condition1.
  exact (eq_trans (eq_trans step1 step2) step3).
Qed.

End lemma1_boundary_square.
