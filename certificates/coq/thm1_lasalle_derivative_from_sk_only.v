(** Exported from the derivation 'thm1.lasalle-derivative-from-sk-only' (verify.proof).
    Statement: with only sk(R_lᵀR̄) = 0 (R_lᵀR̄ = 2ξξᵀ - I, angle π) the formula changes
    Paper: Theorem 1 proof, 'which implies sk(R_lᵀR̄)^∨ = 0' *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_lasalle_derivative_from_sk_only.

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_l : quat.
Hypothesis q_R_l_nonzero : qn q_R_l <> 0.
Local Notation R_l := (rot q_R_l).

(** k_s: a scalar *)
Variable k_s : R.
Hypothesis k_s_pos : 0 < k_s.

(** ω_h^s: a vector *)
Variable omega_h_s : V3.

(** ξ: a unit vector *)
Variable xi : V3.
Hypothesis xi_unit : vdot xi xi = 1.


(** Step 1: d/dt(R_lᵀR̄) at R̄ = R_l(2ξξᵀ - I) = -R_lᵀ hat(ω_h^s) R_l (2ξξᵀ - I)
    (algebra (sk(2ξξᵀ - I) = 0)) *)
Theorem step1 : (madd (mmul (mT (mmul R_l (hat (vadd (vscale k_s (vee (sk (mmul (mT R_l) (mmul R_l (madd (mscale 2 (outer xi xi)) (mneg I3))))))) (mvmul (mT R_l) omega_h_s))))) (mmul R_l (madd (mscale 2 (outer xi xi)) (mneg I3)))) (mmul (mT R_l) (mmul (mscale k_s (mmul R_l (madd (mscale 2 (outer xi xi)) (mneg I3)))) (sk (mmul (mT (mmul R_l (madd (mscale 2 (outer xi xi)) (mneg I3)))) R_l))))) = (mneg (mmul (mmul (mmul (mT R_l) (hat omega_h_s)) R_l) (madd (mscale 2 (outer xi xi)) (mneg I3)))).
Proof using q_R_l k_s omega_h_s xi q_R_l_nonzero k_s_pos xi_unit.
  so3_norm_hat.
  generalize (rot q_R_l) as G_R_l; intro G_R_l.
  so3_split.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - so3_poly.
Qed.

End thm1_lasalle_derivative_from_sk_only.
