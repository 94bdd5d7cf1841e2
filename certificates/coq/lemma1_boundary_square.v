(** Exported from the derivation 'lemma1.boundary-square' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: on the boundary, R̄_r² = 2ξξᵀ - I
    its place in the paper: Lemma 1 proof, boundary
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_boundary_square.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.

(** θ: an angle *)
Variable v_2_theta : R.

(** side condition: boundary h = 0, i.e. cosθ = 0 *)
Hypothesis condition1 : (cos v_2_theta) = 0.


(** Step 1: (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) = I + 2 sin(θ) cos(θ) hat(ξ) + (1 - (cos(θ) cos(θ) - sin(θ) sin(θ))) hat(ξ) hat(ξ)
    (algebra (R̄_r² = exp(2θ ξ^), double-angle formulas)) *)
Theorem step1 : (mmul (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi)))) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))) = (madd (madd I3 (mscale ((2 * (sin v_2_theta)) * (cos v_2_theta)) (hat v_1_xi))) (mscale (1 + (- (((cos v_2_theta) * (cos v_2_theta)) + (- ((sin v_2_theta) * (sin v_2_theta)))))) (mmul (hat v_1_xi) (hat v_1_xi)))).
Proof using v_1_xi v_2_theta v_1_xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) + (v2 v_1_xi) ^ 2 + (v3 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) + (v3 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) + (-1) * (v1 v_1_xi) * (v2 v_1_xi) + (-2) * (v3 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + 2 * (v3 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + (-1) * (v1 v_1_xi) * (v3 v_1_xi) + 2 * (v2 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + (-2) * (v2 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) + (-1) * (v1 v_1_xi) * (v2 v_1_xi) + 2 * (v3 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + (-2) * (v3 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v1 v_1_xi) ^ 2 * (cos v_2_theta) + (v1 v_1_xi) ^ 2 + (v3 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) + (v3 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-2) * (v1 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + 2 * (v1 v_1_xi) * (sin v_2_theta) + (-1) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + (-1) * (v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + (-1) * (v1 v_1_xi) * (v3 v_1_xi) + (-2) * (v2 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + 2 * (v2 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ (((2 * (v1 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + (-2) * (v1 v_1_xi) * (sin v_2_theta) + (-1) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + (-1) * (v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v1 v_1_xi) ^ 2 * (cos v_2_theta) + (v1 v_1_xi) ^ 2 + (v2 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) + (v2 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

(** Step 2: I + 2 sin(θ) cos(θ) hat(ξ) + (1 - (cos(θ) cos(θ) - sin(θ) sin(θ))) hat(ξ) hat(ξ) = I + 2 hat(ξ) hat(ξ)
    (algebra (cosθ = 0)) *)
Theorem step2 : (madd (madd I3 (mscale ((2 * (sin v_2_theta)) * (cos v_2_theta)) (hat v_1_xi))) (mscale (1 + (- (((cos v_2_theta) * (cos v_2_theta)) + (- ((sin v_2_theta) * (sin v_2_theta)))))) (mmul (hat v_1_xi) (hat v_1_xi)))) = (madd I3 (mscale 2 (mmul (hat v_1_xi) (hat v_1_xi)))).
Proof using v_1_xi v_2_theta v_1_xi_unit condition1.
  so3_split.
  - apply (eq_by_sum _ _ ((((-1) * (v2 v_1_xi) ^ 2 + (-1) * (v3 v_1_xi) ^ 2) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + ((2 * (v2 v_1_xi) ^ 2 * (cos v_2_theta) + 2 * (v3 v_1_xi) ^ 2 * (cos v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v2 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) + (-2) * (v3 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + 2 * (v2 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v2 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) + 2 * (v3 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((cos v_2_theta) ^ 2 + (-1) * (sin v_2_theta) ^ 2 + 1) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1) + (((v2 v_1_xi) ^ 2 + (-1)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) + 2 * (cos v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit), (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v1 v_1_xi) * (sin v_2_theta) + (-2) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + (-2) * (v2 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + ((2 * (v1 v_1_xi) * (sin v_2_theta) + (-2) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((cos v_2_theta) ^ 2 + (-1) * (sin v_2_theta) ^ 2 + 1) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1) + (((v3 v_1_xi) ^ 2 + (-1)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) + 2 * (cos v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit), (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
Qed.

(** Step 3: I + 2 hat(ξ) hat(ξ) = 2 ξ ξᵀ - I
    (algebra (ξ^² = ξξᵀ - I for |ξ| = 1)) *)
Theorem step3 : (madd I3 (mscale 2 (mmul (hat v_1_xi) (hat v_1_xi)))) = (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3)).
Proof using v_1_xi v_2_theta v_1_xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ ((((-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ ((((-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ ((((-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

(** The derivation's claim: (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) = 2 ξ ξᵀ - I *)
Theorem claim : (mmul (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi)))) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))) = (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3)).
Proof using v_1_xi v_2_theta v_1_xi_unit condition1.
  exact (eq_trans (eq_trans step1 step2) step3).
Qed.

End lemma1_boundary_square.
