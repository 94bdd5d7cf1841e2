(** Exported from the derivation 'lemma1.spectrum' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: R + Rᵀ = 2 ξξᵀ + 2cosθ (I - ξξᵀ): eigenvalue 2 on ξ, 2cosθ twice on ξ⊥
    its place in the paper: Lemma 1 proof, eigenvalues {2, 2cosθ, 2cosθ}
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_spectrum.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.

(** θ: an angle *)
Variable v_2_theta : R.


(** Step 1: I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ) + (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ))ᵀ = 2 ξ ξᵀ + 2 cos(θ) (I - ξ ξᵀ)
    (algebra (Rodrigues, |ξ| = 1)) *)
Theorem step1 : (madd (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi)))) (mT (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi)))))) = (madd (mscale 2 (outer v_1_xi v_1_xi)) (mscale (2 * (cos v_2_theta)) (madd I3 (mneg (outer v_1_xi v_1_xi))))).
Proof using v_1_xi v_2_theta v_1_xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ (((2 * (cos v_2_theta) + (-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ (((2 * (cos v_2_theta) + (-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ (((2 * (cos v_2_theta) + (-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

End lemma1_spectrum.
