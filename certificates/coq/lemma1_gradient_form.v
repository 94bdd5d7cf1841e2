(** Exported from the derivation 'lemma1.gradient-form' (verify.proof).
    Statement: d/ds h(R̄_r exp(s ω^)) at s = 0 equals <-2 sk(R̄_r)^∨, ω>: the gradient of h on SO(3) is -2 sk(R̄_r)^∨
    Paper: Lemma 1 proof, Nagumo premise *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_gradient_form.

(** R̄_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_Rbar_r : quat.
Hypothesis q_Rbar_r_nonzero : qn q_Rbar_r <> 0.
Local Notation Rbar_r := (rot q_Rbar_r).

(** ω: a vector *)
Variable omega : V3.


(** Step 1: tr(R̄_r hat(ω)) = <grad h, ω>
    (algebra (tr(A hat ω) = -2 <sk(A)^∨, ω>)) *)
Theorem step1 : (tr (mmul Rbar_r (hat omega))) = (vdot (vscale (-2) (vee Rbar_r)) omega).
Proof using q_Rbar_r omega q_Rbar_r_nonzero.
  generalize (rot q_Rbar_r) as G_Rbar_r; intro G_Rbar_r.
  so3_poly.
Qed.

End lemma1_gradient_form.
