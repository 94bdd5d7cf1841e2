(** Exported from the derivation 'sec3.rbar-dot-form' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: with ω̃ = k_s R̄ sk(R̄ᵀR_l)^∨, hat(ω̃) R̄ = k_s R̄ sk(R̄ᵀR_l)
    its place in the paper: eqs. (9), (12a), (13)
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section sec3_rbar_dot_form.

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_Rbar : quat.
Hypothesis q_v_1_Rbar_nonzero : qn q_v_1_Rbar <> 0.
Local Notation v_1_Rbar := (rot q_v_1_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_R_l : quat.
Hypothesis q_v_2_R_l_nonzero : qn q_v_2_R_l <> 0.
Local Notation v_2_R_l := (rot q_v_2_R_l).

(** k_s: a scalar *)
Variable v_3_k_s : R.
Hypothesis v_3_k_s_pos : 0 < v_3_k_s.


(** Step 1: hat(k_s R̄ vee(sk(R̄ᵀ R_l))) R̄ = k_s R̄ sk(R̄ᵀ R_l)
    (algebra (hat(R v) = R hat(v) Rᵀ)) *)
Theorem step1 : (mmul (hat (mvmul (mscale v_3_k_s v_1_Rbar) (vee (sk (mmul (mT v_1_Rbar) v_2_R_l))))) v_1_Rbar) = (mmul (mscale v_3_k_s v_1_Rbar) (sk (mmul (mT v_1_Rbar) v_2_R_l))).
Proof using q_v_1_Rbar q_v_2_R_l v_3_k_s q_v_1_Rbar_nonzero q_v_2_R_l_nonzero v_3_k_s_pos.
  so3_norm_hat.
  generalize (rot q_v_1_Rbar) as G_v_1_Rbar; intro G_v_1_Rbar.
  generalize (rot q_v_2_R_l) as G_v_2_R_l; intro G_v_2_R_l.
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
