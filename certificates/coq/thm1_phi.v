(** Exported from the derivation 'thm1.phi' (verify.proof).
    Statement: φ(R) = tr(I - R)/2 = ‖I - R‖_F²/4
    Paper: Theorem 1 proof, definition of φ *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_phi.

(** R: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_v : quat.
Hypothesis q_R_v_nonzero : qn q_R_v <> 0.
Local Notation R_v := (rot q_R_v).


(** Step 1: φ(R) = (1/4) tr((I - R)ᵀ (I - R))
    (algebra (RᵀR = I)) *)
Theorem step1 : (phi R_v) = ((1/4) * (tr (mmul (mT (madd I3 (mneg R_v))) (madd I3 (mneg R_v))))).
Proof using q_R_v q_R_v_nonzero.
  so3_norm.
  generalize (rot q_R_v) as G_R_v; intro G_R_v.
  so3_poly.
Qed.

End thm1_phi.
