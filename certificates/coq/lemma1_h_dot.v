(** Exported from the derivation 'lemma1.h-dot' (verify.proof).
    Statement: ḣ = (k_s/2) tr(R_rl - R_rlᵀ R̄_r²) along eq. (13)
    Paper: Lemma 1 proof, eq. (15) *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

Section lemma1_h_dot.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_r : quat.
Hypothesis q_R_r_nonzero : qn q_R_r <> 0.
Local Notation R_r := (rot q_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_Rbar : quat.
Hypothesis q_Rbar_nonzero : qn q_Rbar <> 0.
Local Notation Rbar := (rot q_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_R_l : quat.
Hypothesis q_R_l_nonzero : qn q_R_l <> 0.
Local Notation R_l := (rot q_R_l).

(** k_s: a scalar *)
Variable k_s : R.
Hypothesis k_s_pos : 0 < k_s.


(** Step 1: ḣ = tr((d/dt R̄_r))
    (algebra (h = tr(R̄_r) - 1, R_r constant)) *)
Theorem step1 : (tr (mmul (mT R_r) (mmul (mscale k_s Rbar) (sk (mmul (mT Rbar) R_l))))) = (tr (mmul (mT R_r) (mmul (mscale k_s Rbar) (sk (mmul (mT Rbar) R_l))))).
Proof using q_R_r q_Rbar q_R_l k_s q_R_r_nonzero q_Rbar_nonzero q_R_l_nonzero k_s_pos.
  so3_norm.
  generalize (rot q_R_r) as G_R_r; intro G_R_r.
  generalize (rot q_Rbar) as G_Rbar; intro G_Rbar.
  generalize (rot q_R_l) as G_R_l; intro G_R_l.
  so3_poly.
Qed.

(** Step 2: tr((d/dt R̄_r)) = k_s tr(R_rᵀ R̄ sk(R̄ᵀ R_l))
    (algebra (eq. (13))) *)
Theorem step2 : (tr (mmul (mT R_r) (mmul (mscale k_s Rbar) (sk (mmul (mT Rbar) R_l))))) = (k_s * (tr (mmul (mmul (mT R_r) Rbar) (sk (mmul (mT Rbar) R_l))))).
Proof using q_R_r q_Rbar q_R_l k_s q_R_r_nonzero q_Rbar_nonzero q_R_l_nonzero k_s_pos.
  so3_norm.
  generalize (rot q_R_r) as G_R_r; intro G_R_r.
  generalize (rot q_Rbar) as G_Rbar; intro G_Rbar.
  generalize (rot q_R_l) as G_R_l; intro G_R_l.
  so3_poly.
Qed.

(** Step 3: k_s tr(R_rᵀ R̄ sk(R̄ᵀ R_l)) = k_s tr(R̄_r sk(R̄_rᵀ R_rl))
    (algebra (R̄ᵀR_l = R̄_rᵀR_rl)) *)
Theorem step3 : (k_s * (tr (mmul (mmul (mT R_r) Rbar) (sk (mmul (mT Rbar) R_l))))) = (k_s * (tr (mmul (mmul (mT R_r) Rbar) (sk (mmul (mT (mmul (mT R_r) Rbar)) (mmul (mT R_r) R_l)))))).
Proof using q_R_r q_Rbar q_R_l k_s q_R_r_nonzero q_Rbar_nonzero q_R_l_nonzero k_s_pos.
  so3_norm.
  generalize (rot q_R_r) as G_R_r; intro G_R_r.
  generalize (rot q_Rbar) as G_Rbar; intro G_Rbar.
  generalize (rot q_R_l) as G_R_l; intro G_R_l.
  so3_poly.
Qed.

(** Step 4: k_s tr(R̄_r sk(R̄_rᵀ R_rl)) = (1/2) k_s tr(R_rl - R_rlᵀ R̄_r R̄_r)
    (algebra (cyclic trace)) *)
Theorem step4 : (k_s * (tr (mmul (mmul (mT R_r) Rbar) (sk (mmul (mT (mmul (mT R_r) Rbar)) (mmul (mT R_r) R_l)))))) = (((1/2) * k_s) * (tr (madd (mmul (mT R_r) R_l) (mneg (mmul (mmul (mT (mmul (mT R_r) R_l)) (mmul (mT R_r) Rbar)) (mmul (mT R_r) Rbar)))))).
Proof using q_R_r q_Rbar q_R_l k_s q_R_r_nonzero q_Rbar_nonzero q_R_l_nonzero k_s_pos.
  so3_norm.
  generalize (rot q_R_r) as G_R_r; intro G_R_r.
  generalize (rot q_Rbar) as G_Rbar; intro G_Rbar.
  generalize (rot q_R_l) as G_R_l; intro G_R_l.
  so3_poly.
Qed.

(** The derivation's claim: ḣ = (1/2) k_s tr(R_rl - R_rlᵀ R̄_r R̄_r) *)
Theorem claim : (tr (mmul (mT R_r) (mmul (mscale k_s Rbar) (sk (mmul (mT Rbar) R_l))))) = (((1/2) * k_s) * (tr (madd (mmul (mT R_r) R_l) (mneg (mmul (mmul (mT (mmul (mT R_r) R_l)) (mmul (mT R_r) Rbar)) (mmul (mT R_r) Rbar)))))).
Proof using q_R_r q_Rbar q_R_l k_s q_R_r_nonzero q_Rbar_nonzero q_R_l_nonzero k_s_pos.
  exact (eq_trans (eq_trans (eq_trans step1 step2) step3) step4).
Qed.

End lemma1_h_dot.
