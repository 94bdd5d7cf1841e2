(** Exported from the derivation 'thm1.lasalle-derivative' (verify.proof).
    Statement: on R_l = R̄: d/dt(R_lᵀR̄) = -R_lᵀ hat(ω_h^s) R_l = -hat(R_lᵀ ω_h^s)
    Paper: Theorem 1 proof, LaSalle step *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_lasalle_derivative.

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_l : quat.
Hypothesis q_R_l_nonzero : qn q_R_l <> 0.
Local Notation R_l := (rot q_R_l).

(** k_s: a scalar *)
Variable k_s : R.
Hypothesis k_s_pos : 0 < k_s.

(** ω_h^s: a vector *)
Variable omega_h_s : V3.


(** Step 1: d/dt(R_lᵀR̄) at R̄ = R_l = -R_lᵀ hat(ω_h^s) R_l
    (algebra (sk(I) = 0)) *)
Theorem step1 : (madd (mmul (mT (mmul R_l (hat (vadd (vscale k_s (vee (sk (mmul (mT R_l) R_l)))) (mvmul (mT R_l) omega_h_s))))) R_l) (mmul (mT R_l) (mmul (mscale k_s R_l) (sk (mmul (mT R_l) R_l))))) = (mneg (mmul (mmul (mT R_l) (hat omega_h_s)) R_l)).
Proof using q_R_l k_s omega_h_s q_R_l_nonzero k_s_pos.
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

(** Step 2: -R_lᵀ hat(ω_h^s) R_l = -hat(R_lᵀ ω_h^s)
    (algebra (Rᵀ hat(ω) R = hat(Rᵀω))) *)
Theorem step2 : (mneg (mmul (mmul (mT R_l) (hat omega_h_s)) R_l)) = (mneg (hat (mvmul (mT R_l) omega_h_s))).
Proof using q_R_l k_s omega_h_s q_R_l_nonzero k_s_pos.
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

(** The derivation's claim: d/dt(R_lᵀR̄) at R̄ = R_l = -hat(R_lᵀ ω_h^s) *)
Theorem claim : (madd (mmul (mT (mmul R_l (hat (vadd (vscale k_s (vee (sk (mmul (mT R_l) R_l)))) (mvmul (mT R_l) omega_h_s))))) R_l) (mmul (mT R_l) (mmul (mscale k_s R_l) (sk (mmul (mT R_l) R_l))))) = (mneg (hat (mvmul (mT R_l) omega_h_s))).
Proof using q_R_l k_s omega_h_s q_R_l_nonzero k_s_pos.
  exact (eq_trans step1 step2).
Qed.

End thm1_lasalle_derivative.
