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
  pose proof (rot_orthogonal q_R_v q_R_v_nonzero) as OL_R_v.
  pose proof (rot_orthogonal_r q_R_v q_R_v_nonzero) as OR_R_v.
  pose proof (rot_det q_R_v q_R_v_nonzero) as D_R_v.
  revert OL_R_v OR_R_v D_R_v; generalize (rot q_R_v) as G_R_v; intros G_R_v OL_R_v OR_R_v D_R_v.
  apply (eq_by_sum _ _ ((((-1/4)) * (1) / (1)) * (m11 (mmul (mT G_R_v) G_R_v) - m11 I3) + (((-1/4)) * (1) / (1)) * (m22 (mmul (mT G_R_v) G_R_v) - m22 I3) + (((-1/4)) * (1) / (1)) * (m33 (mmul (mT G_R_v) G_R_v) - m33 I3))); [rewrite (Rminus_diag_eq _ _ (f_equal m11 OL_R_v)), (Rminus_diag_eq _ _ (f_equal m22 OL_R_v)), (Rminus_diag_eq _ _ (f_equal m33 OL_R_v)); ring | so3_unfold; field; so3_nonzero].
Qed.

End thm1_phi.
