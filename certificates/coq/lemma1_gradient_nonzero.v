(** Exported from the derivation 'lemma1.gradient-nonzero' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: |grad h|² = (3 - tr R̄_r)(1 + tr R̄_r) = 4 on the boundary (non-zero)
    its place in the paper: Lemma 1 proof, Nagumo premise
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_gradient_nonzero.

(** R̄_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_Rbar_r : quat.
Hypothesis q_v_1_Rbar_r_nonzero : qn q_v_1_Rbar_r <> 0.
Local Notation v_1_Rbar_r := (rot q_v_1_Rbar_r).

(** side condition: boundary tr(R̄_r) = 1 *)
Hypothesis condition1 : (tr v_1_Rbar_r) = 1.


(** Step 1: <(-2) vee(R̄_r), (-2) vee(R̄_r)> = (3 - tr(R̄_r)) (1 + tr(R̄_r))
    (algebra (|sk(R)^∨|² = sin²θ)) *)
Theorem step1 : (vdot (vscale (-2) (vee v_1_Rbar_r)) (vscale (-2) (vee v_1_Rbar_r))) = ((3 + (- (tr v_1_Rbar_r))) * (1 + (tr v_1_Rbar_r))).
Proof using q_v_1_Rbar_r q_v_1_Rbar_r_nonzero.
  so3_unfold; field; so3_nonzero.
Qed.

(** Step 2: (3 - tr(R̄_r)) (1 + tr(R̄_r)) = 4
    (algebra (tr R̄_r = 1)) *)
Theorem step2 : ((3 + (- (tr v_1_Rbar_r))) * (1 + (tr v_1_Rbar_r))) = 4.
Proof using q_v_1_Rbar_r q_v_1_Rbar_r_nonzero condition1.
  apply (eq_by_sum _ _ ((((-2) * (qw q_v_1_Rbar_r) ^ 2 + 2 * (qx q_v_1_Rbar_r) ^ 2 + 2 * (qy q_v_1_Rbar_r) ^ 2 + 2 * (qz q_v_1_Rbar_r) ^ 2) * ((qn q_v_1_Rbar_r)) / ((qn q_v_1_Rbar_r) ^ 2)) * ((tr v_1_Rbar_r) - 1))); [rewrite (Rminus_diag_eq _ _ condition1); ring | so3_unfold; field; so3_nonzero].
Qed.

(** The derivation's claim: <(-2) vee(R̄_r), (-2) vee(R̄_r)> = 4 *)
Theorem claim : (vdot (vscale (-2) (vee v_1_Rbar_r)) (vscale (-2) (vee v_1_Rbar_r))) = 4.
Proof using q_v_1_Rbar_r q_v_1_Rbar_r_nonzero condition1.
  exact (eq_trans step1 step2).
Qed.

End lemma1_gradient_nonzero.
