(** Exported from the derivation 'thm1.phi' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: φ(R) = tr(I - R)/2 = ‖I - R‖_F²/4
    its place in the paper: Theorem 1 proof, definition of φ
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section thm1_phi.

(** R: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R : quat.
Hypothesis q_v_1_R_nonzero : qn q_v_1_R <> 0.
Local Notation v_1_R := (rot q_v_1_R).


(** Step 1: (1/2) tr(I - R) = (1/4) tr((I - R)ᵀ (I - R))
    (algebra (RᵀR = I)) *)
Theorem step1 : (phi v_1_R) = ((1/4) * (tr (mmul (mT (madd I3 (mneg v_1_R))) (madd I3 (mneg v_1_R))))).
Proof using q_v_1_R q_v_1_R_nonzero.
  so3_norm.
  generalize (rot q_v_1_R) as G_v_1_R; intro G_v_1_R.
  so3_poly.
Qed.

End thm1_phi.
