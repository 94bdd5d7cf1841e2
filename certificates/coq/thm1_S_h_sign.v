(** Exported from the derivation 'thm1.S_h-sign' (verify.proof).
    Statement: sk(R_lᵀR_r)^∨ = -sk(R_rl)^∨, so S_h ≥ 0 is eq. (16)
    Paper: eq. (16) and the definition of S_h *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_S_h_sign.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_r : quat.
Hypothesis q_R_r_nonzero : qn q_R_r <> 0.
Local Notation R_r := (rot q_R_r).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_l : quat.
Hypothesis q_R_l_nonzero : qn q_R_l <> 0.
Local Notation R_l := (rot q_R_l).


(** Step 1: vee(sk(R_lᵀ R_r)) = -vee(sk(R_rᵀ R_l))
    (algebra ((R_lᵀR_r) = R_rlᵀ)) *)
Theorem step1 : (vee (sk (mmul (mT R_l) R_r))) = (vneg (vee (sk (mmul (mT R_r) R_l)))).
Proof using q_R_r q_R_l q_R_r_nonzero q_R_l_nonzero.
  generalize (rot q_R_l) as G_R_l; intro G_R_l.
  generalize (rot q_R_r) as G_R_r; intro G_R_r.
  so3_split.
  - so3_poly.
  - so3_poly.
  - so3_poly.
Qed.

End thm1_S_h_sign.
