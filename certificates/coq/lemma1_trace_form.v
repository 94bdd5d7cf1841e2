(** Exported from the derivation 'lemma1.trace-form' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: tr(R̄_r) = 1 + 2cosθ, so R̄_r + R̄_rᵀ ⪰ 0 ⟺ cosθ ≥ 0 ⟺ tr(R̄_r) ≥ 1
    its place in the paper: Lemma 1 proof, eq. (14)
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_trace_form.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.

(** θ: an angle *)
Variable v_2_theta : R.


(** Step 1: tr(I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) = 1 + 2 cos(θ)
    (algebra (Rodrigues)) *)
Theorem step1 : (tr (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))) = (1 + (2 * (cos v_2_theta))).
Proof using v_1_xi v_2_theta v_1_xi_unit.
  apply (eq_by_sum _ _ (((2 * (cos v_2_theta) + (-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

End lemma1_trace_form.
