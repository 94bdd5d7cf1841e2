(** Exported from the derivation 'lemma1.gradient-form' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: d/ds h(R̄_r exp(s ω^)) at s = 0 equals <-2 sk(R̄_r)^∨, ω>: the gradient of h on SO(3) is -2 sk(R̄_r)^∨
    its place in the paper: Lemma 1 proof, Nagumo premise
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_gradient_form.

(** R̄_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_Rbar_r : quat.
Hypothesis q_v_1_Rbar_r_nonzero : qn q_v_1_Rbar_r <> 0.
Local Notation v_1_Rbar_r := (rot q_v_1_Rbar_r).

(** ω: a vector *)
Variable v_2_omega : V3.


(** Step 1: tr(R̄_r hat(ω)) = <(-2) vee(R̄_r), ω>
    (algebra (tr(A hat ω) = -2 <sk(A)^∨, ω>)) *)
Theorem step1 : (tr (mmul v_1_Rbar_r (hat v_2_omega))) = (vdot (vscale (-2) (vee v_1_Rbar_r)) v_2_omega).
Proof using q_v_1_Rbar_r v_2_omega q_v_1_Rbar_r_nonzero.
  generalize (rot q_v_1_Rbar_r) as G_v_1_Rbar_r; intro G_v_1_Rbar_r.
  so3_poly.
Qed.

End lemma1_gradient_form.
