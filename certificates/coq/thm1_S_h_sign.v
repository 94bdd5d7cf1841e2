(** Exported from the derivation 'thm1.S_h-sign' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: sk(R_lᵀR_r)^∨ = -sk(R_rl)^∨, so S_h ≥ 0 is eq. (16)
    its place in the paper: eq. (16) and the definition of S_h
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_S_h_sign.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_r : quat.
Hypothesis q_v_1_R_r_nonzero : qn q_v_1_R_r <> 0.
Local Notation v_1_R_r := (rot q_v_1_R_r).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_R_l : quat.
Hypothesis q_v_2_R_l_nonzero : qn q_v_2_R_l <> 0.
Local Notation v_2_R_l := (rot q_v_2_R_l).


(** Step 1: vee(sk(R_lᵀ R_r)) = -vee(sk(R_rᵀ R_l))
    (algebra ((R_lᵀR_r) = R_rlᵀ)) *)
Theorem step1 : (vee (sk (mmul (mT v_2_R_l) v_1_R_r))) = (vneg (vee (sk (mmul (mT v_1_R_r) v_2_R_l)))).
Proof using q_v_1_R_r q_v_2_R_l q_v_1_R_r_nonzero q_v_2_R_l_nonzero.
  generalize (rot q_v_2_R_l) as G_v_2_R_l; intro G_v_2_R_l.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  so3_split.
  - so3_poly.
  - so3_poly.
  - so3_poly.
Qed.

End thm1_S_h_sign.
