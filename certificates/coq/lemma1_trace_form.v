(** Exported from the derivation 'lemma1.trace-form' (verify.proof).
    Statement: tr(R̄_r) = 1 + 2cosθ, so R̄_r + R̄_rᵀ ⪰ 0 ⟺ cosθ ≥ 0 ⟺ tr(R̄_r) ≥ 1
    Paper: Lemma 1 proof, eq. (14) *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_trace_form.

(** ξ: a unit vector *)
Variable xi : V3.
Hypothesis xi_unit : vdot xi xi = 1.

(** θ: an angle *)
Variable theta : R.


(** Step 1: tr(R̄_r) = 1 + 2 cos(θ)
    (algebra (Rodrigues)) *)
Theorem step1 : (tr (madd (madd I3 (mscale (sin theta) (hat xi))) (mscale (1 + (- (cos theta))) (mmul (hat xi) (hat xi))))) = (1 + (2 * (cos theta))).
Proof using xi theta xi_unit.
  apply (eq_by_sum _ _ (((2 * (cos theta) + (-2)) * (1) / (1)) * (vdot xi xi - 1))); [rewrite (Rminus_diag_eq _ _ xi_unit); ring | so3_poly].
Qed.

End lemma1_trace_form.
