(** Exported from the derivation 'thm1.V-dot-zero-on-sync' (verify.proof).
    Statement: V̇ = 0 when R_l = R̄, whatever the human commands
    Paper: Theorem 1 proof, 'V̇ = 0 iff R_l = R̄' *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_V_dot_zero_on_sync.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_r : quat.
Hypothesis q_R_r_nonzero : qn q_R_r <> 0.
Local Notation R_r := (rot q_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_Rbar : quat.
Hypothesis q_Rbar_nonzero : qn q_Rbar <> 0.
Local Notation Rbar := (rot q_Rbar).

(** k_s: a scalar *)
Variable k_s : R.
Hypothesis k_s_pos : 0 < k_s.

(** ω_h^s: a vector *)
Variable omega_h_s : V3.


(** Step 1: V̇ at R_l = R̄ = 0
    (algebra (R_l = R̄)) *)
Theorem step1 : ((((1/2) * (tr (mneg (mmul (mT R_r) (mmul (mscale k_s Rbar) (sk (mmul (mT Rbar) Rbar))))))) + ((1/2) * (tr (mneg (mmul (mT R_r) (mmul Rbar (hat (vadd (vscale k_s (vee (sk (mmul (mT Rbar) Rbar)))) (mvmul (mT Rbar) omega_h_s))))))))) + (- (vdot (vee (mmul (mT R_r) Rbar)) (mvmul (mT Rbar) omega_h_s)))) = 0.
Proof using q_R_r q_Rbar k_s omega_h_s q_R_r_nonzero q_Rbar_nonzero k_s_pos.
  generalize (rot q_R_r) as G_R_r; intro G_R_r.
  generalize (rot q_Rbar) as G_Rbar; intro G_Rbar.
  so3_poly.
Qed.

End thm1_V_dot_zero_on_sync.
