(** Exported from the derivation 'sec3.rbar-dot-form' (verify.proof).
    Statement: with ω̃ = k_s R̄ sk(R̄ᵀR_l)^∨, hat(ω̃) R̄ = k_s R̄ sk(R̄ᵀR_l)
    Paper: eqs. (9), (12a), (13) *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section sec3_rbar_dot_form.

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_Rbar : quat.
Hypothesis q_Rbar_nonzero : qn q_Rbar <> 0.
Local Notation Rbar := (rot q_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_l : quat.
Hypothesis q_R_l_nonzero : qn q_R_l <> 0.
Local Notation R_l := (rot q_R_l).

(** k_s: a scalar *)
Variable k_s : R.
Hypothesis k_s_pos : 0 < k_s.


(** Step 1: hat(ω̃_h^s) R̄ = k_s R̄ sk(R̄ᵀ R_l)
    (algebra (hat(R v) = R hat(v) Rᵀ)) *)
Theorem step1 : (mmul (hat (mvmul (mscale k_s Rbar) (vee (sk (mmul (mT Rbar) R_l))))) Rbar) = (mmul (mscale k_s Rbar) (sk (mmul (mT Rbar) R_l))).
Proof using q_Rbar q_R_l k_s q_Rbar_nonzero q_R_l_nonzero k_s_pos.
  so3_norm_hat.
  generalize (rot q_Rbar) as G_Rbar; intro G_Rbar.
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

End sec3_rbar_dot_form.
