(** 9 units in one file, each a module of its own name: thm1_phi, thm1_S_r_dot,
    thm1_S_rl_dot, thm1_S_h_sign, thm1_V_dot, thm1_V_dot_zero_implies_sync,
    thm1_V_dot_zero_on_sync, thm1_lasalle_derivative,
    thm1_lasalle_derivative_from_sk_only. The libraries are loaded once, below; each
    module imports those its unit uses. *)

From Coq Require Reals Lra.
From VerifyCoq Require SO3 SOSCert Traj.
From Coquelicot Require Hierarchy Derive.

Module thm1_phi.

(** Exported from the derivation 'thm1.phi' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: φ(R) = tr(I - R)/2 = ‖I - R‖_F²/4
    its place in the paper: Theorem 1 proof, definition of φ
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
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
  first [ SOSCert.sos_eq ((qw q_v_1_R) :: (qx q_v_1_R) :: (qy q_v_1_R) :: (qz q_v_1_R) :: nil)%list (0%nat :: nil)%list | so3_norm; generalize (rot q_v_1_R) as G_v_1_R; intro G_v_1_R; so3_poly ].
Qed.

End thm1_phi.

End thm1_phi.

Module thm1_S_r_dot.

(** Exported from the derivation 'thm1.S_r-dot' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: Ṡ_r ≤ -(k_s/2) λmin(R̄_r + R̄_rᵀ) φ(R̄ᵀR_l) - k_s φ(R̄_r) + k_s φ(R_rl)
    its place in the paper: Theorem 1 proof, Ṡ_r chain
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3 Hierarchy Derive Traj.
Open Scope R_scope.

Section thm1_S_r_dot.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_r : quat.
Hypothesis q_v_1_R_r_nonzero : qn q_v_1_R_r <> 0.
Local Notation v_1_R_r := (rot q_v_1_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_Rbar : quat.
Hypothesis q_v_2_Rbar_nonzero : qn q_v_2_Rbar <> 0.
Local Notation v_2_Rbar := (rot q_v_2_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_R_l : quat.
Hypothesis q_v_3_R_l_nonzero : qn q_v_3_R_l <> 0.
Local Notation v_3_R_l := (rot q_v_3_R_l).

(** k_s: a scalar *)
Variable v_4_k_s : R.
Hypothesis v_4_k_s_pos : 0 < v_4_k_s.

(** lambda_min(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) lam1.


(** Step 1: (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) = (-1/2) tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l))
    (algebra (φ(R) = tr(I - R)/2)) *)
Theorem step1 : ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))))) = ((-1/2) * (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 2: (-1/2) tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) = (-1/2) k_s tr(R_rᵀ R̄ sk((R_rᵀ R̄)ᵀ R_rᵀ R_l))
    (algebra (eq. (13))) *)
Theorem step2 : ((-1/2) * (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l)))))) = (((-1/2) * v_4_k_s) * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (sk (mmul (mT (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_3_R_l)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  so3_norm.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 3: (-1/2) k_s tr(R_rᵀ R̄ sk((R_rᵀ R̄)ᵀ R_rᵀ R_l)) = (-1/4) k_s tr(R_rᵀ R̄ ((R_rᵀ R̄)ᵀ R_rᵀ R_l - (R_rᵀ R_l)ᵀ R_rᵀ R̄))
    (algebra (sk definition)) *)
Theorem step3 : (((-1/2) * v_4_k_s) * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (sk (mmul (mT (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_3_R_l)))))) = (((-1/4) * v_4_k_s) * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (madd (mmul (mT (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_3_R_l)) (mneg (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar))))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 4: (-1/4) k_s tr(R_rᵀ R̄ ((R_rᵀ R̄)ᵀ R_rᵀ R_l - (R_rᵀ R_l)ᵀ R_rᵀ R̄)) = (-1/4) k_s tr(R_rᵀ R_l - R_rᵀ R̄ (R_rᵀ R_l)ᵀ R_rᵀ R̄)
    (algebra (R̄_r R̄_rᵀ = I)) *)
Theorem step4 : (((-1/4) * v_4_k_s) * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (madd (mmul (mT (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_3_R_l)) (mneg (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar))))))) = (((-1/4) * v_4_k_s) * (tr (madd (mmul (mT v_1_R_r) v_3_R_l) (mneg (mmul (mmul (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_3_R_l))) (mmul (mT v_1_R_r) v_2_Rbar)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  so3_norm.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 5: (-1/4) k_s tr(R_rᵀ R_l - R_rᵀ R̄ (R_rᵀ R_l)ᵀ R_rᵀ R̄) = (-1/4) k_s tr((R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) (I - (R_rᵀ R̄)ᵀ R_rᵀ R_l)) + (1/2) k_s tr(R_rᵀ R̄) - (1/2) k_s tr(R_rᵀ R_l)
    (algebra (add and subtract)) *)
Theorem step5 : (((-1/4) * v_4_k_s) * (tr (madd (mmul (mT v_1_R_r) v_3_R_l) (mneg (mmul (mmul (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_3_R_l))) (mmul (mT v_1_R_r) v_2_Rbar)))))) = (((((-1/4) * v_4_k_s) * (tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_3_R_l))))))) + (((1/2) * v_4_k_s) * (tr (mmul (mT v_1_R_r) v_2_Rbar)))) + (- (((1/2) * v_4_k_s) * (tr (mmul (mT v_1_R_r) v_3_R_l))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  so3_norm.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  so3_poly.
Qed.

(** Step 6: (-1/4) k_s tr((R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) (I - (R_rᵀ R̄)ᵀ R_rᵀ R_l)) + (1/2) k_s tr(R_rᵀ R̄) - (1/2) k_s tr(R_rᵀ R_l) = (-1/4) k_s tr((R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) (I - R̄ᵀ R_l)) - (1/2) k_s tr(I - R_rᵀ R̄) + (1/2) k_s tr(I - R_rᵀ R_l)
    (algebra (R̄_rᵀR_rl = R̄ᵀR_l)) *)
Theorem step6 : (((((-1/4) * v_4_k_s) * (tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_3_R_l))))))) + (((1/2) * v_4_k_s) * (tr (mmul (mT v_1_R_r) v_2_Rbar)))) + (- (((1/2) * v_4_k_s) * (tr (mmul (mT v_1_R_r) v_3_R_l))))) = (((((-1/4) * v_4_k_s) * (tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))) + (- (((1/2) * v_4_k_s) * (tr (madd I3 (mneg (mmul (mT v_1_R_r) v_2_Rbar))))))) + (((1/2) * v_4_k_s) * (tr (madd I3 (mneg (mmul (mT v_1_R_r) v_3_R_l)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  so3_norm.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 7: (-1/4) k_s tr((R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) (I - R̄ᵀ R_l)) - (1/2) k_s tr(I - R_rᵀ R̄) + (1/2) k_s tr(I - R_rᵀ R_l) <= (-1/2) k_s λmin(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) (1/2) tr(I - R̄ᵀ R_l) - k_s (1/2) tr(I - R_rᵀ R̄) + k_s (1/2) tr(I - R_rᵀ R_l)
    (trace inequality, sym(I - R̄ᵀR_l) = ½(I - R̄ᵀR_l)ᵀ(I - R̄ᵀR_l) ⪰ 0: (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R̄_r + R̄_rᵀ), B = I - R̄ᵀ R_l)) *)
Theorem step7 : (((((-1/4) * v_4_k_s) * (tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))) + (- (((1/2) * v_4_k_s) * (tr (madd I3 (mneg (mmul (mT v_1_R_r) v_2_Rbar))))))) + (((1/2) * v_4_k_s) * (tr (madd I3 (mneg (mmul (mT v_1_R_r) v_3_R_l)))))) <= ((((((-1/2) * v_4_k_s) * lam1) * (phi (mmul (mT v_2_Rbar) v_3_R_l))) + (- (v_4_k_s * (phi (mmul (mT v_1_R_r) v_2_Rbar))))) + (v_4_k_s * (phi (mmul (mT v_1_R_r) v_3_R_l)))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T2 : 0 <= ((1/4) * v_4_k_s)) by exact (Rmult_le_pos (1/4) v_4_k_s ltac:(lra) T1).
  assert (P1 : (mT (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar)))) = (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar)))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))) = (mscale (1/2) (mmul (mT (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))).
  { first [ SOSCert.sos_eq ((qw q_v_1_R_r) :: (qx q_v_1_R_r) :: (qy q_v_1_R_r) :: (qz q_v_1_R_r) :: (qw q_v_2_Rbar) :: (qx q_v_2_Rbar) :: (qy q_v_2_Rbar) :: (qz q_v_2_Rbar) :: (qw q_v_3_R_l) :: (qx q_v_3_R_l) :: (qy q_v_3_R_l) :: (qz q_v_3_R_l) :: v_4_k_s :: lam1 :: nil)%list (0%nat :: 4%nat :: 8%nat :: nil)%list | so3_norm; generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar; generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l; so3_split; so3_poly ]. }
  assert (T3 : 0 <= ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))))) by exact (trace_lower_bound (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))) (1/2) lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (T4 : 0 <= (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))))))) by exact (Rmult_le_pos _ _ T2 T3).
  assert (E : (((((((-1/2) * v_4_k_s) * lam1) * (phi (mmul (mT v_2_Rbar) v_3_R_l))) + (- (v_4_k_s * (phi (mmul (mT v_1_R_r) v_2_Rbar))))) + (v_4_k_s * (phi (mmul (mT v_1_R_r) v_3_R_l)))) + (- (((((-1/4) * v_4_k_s) * (tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))) + (- (((1/2) * v_4_k_s) * (tr (madd I3 (mneg (mmul (mT v_1_R_r) v_2_Rbar))))))) + (((1/2) * v_4_k_s) * (tr (madd I3 (mneg (mmul (mT v_1_R_r) v_3_R_l)))))))) = (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))))))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_poly. }
  exact (le_by_slack _ _ _ E T4).
Qed.

(** The derivation's claim: (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) <= (-1/2) k_s λmin(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) (1/2) tr(I - R̄ᵀ R_l) - k_s (1/2) tr(I - R_rᵀ R̄) + k_s (1/2) tr(I - R_rᵀ R_l) *)
Theorem claim : ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))))) <= ((((((-1/2) * v_4_k_s) * lam1) * (phi (mmul (mT v_2_Rbar) v_3_R_l))) + (- (v_4_k_s * (phi (mmul (mT v_1_R_r) v_2_Rbar))))) + (v_4_k_s * (phi (mmul (mT v_1_R_r) v_3_R_l)))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  exact (eq_le_trans _ _ _ (eq_trans (eq_trans (eq_trans (eq_trans (eq_trans step1 step2) step3) step4) step5) step6) step7).
Qed.

End thm1_S_r_dot.



Section ddt_trajectories.

(** R_r: constant *)
Variable v_1_R_r : M3.
(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_2_Rbar : R -> M3.
(** R_l: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_3_R_l : R -> M3.
(** k_s: constant *)
Variable v_4_k_s : R.
Variable t : R.

(** The first expression is the derivative: d/dt (1/2) tr(I - R_rᵀ R̄) along the declared dynamics,
    at every t, is (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) *)
Theorem ddt : is_mderiv v_2_Rbar t (mmul (mscale v_4_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) (v_3_R_l t)))) -> is_derive (fun s => (phi (mmul (mT v_1_R_r) (v_2_Rbar s)))) t ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) (v_3_R_l t)))))))).
Proof.
  intros D1.
  eapply deriv_unique_eq; [ d_mirror | cbv beta; traj_same ].
Qed.

End ddt_trajectories.

End thm1_S_r_dot.

Module thm1_S_rl_dot.

(** Exported from the derivation 'thm1.S_rl-dot' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: Ṡ_rl ≤ -(k_s/2) λmin(R_rl + R_rlᵀ) φ(R_lᵀR̄) + k_s φ(R̄_r) - k_s φ(R_rl) + <sk(R_rl)^∨, ω_h^b>
    its place in the paper: Theorem 1 proof, Ṡ_rl chain
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3 Hierarchy Derive Traj.
Open Scope R_scope.

Section thm1_S_rl_dot.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_r : quat.
Hypothesis q_v_1_R_r_nonzero : qn q_v_1_R_r <> 0.
Local Notation v_1_R_r := (rot q_v_1_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_Rbar : quat.
Hypothesis q_v_2_Rbar_nonzero : qn q_v_2_Rbar <> 0.
Local Notation v_2_Rbar := (rot q_v_2_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_R_l : quat.
Hypothesis q_v_3_R_l_nonzero : qn q_v_3_R_l <> 0.
Local Notation v_3_R_l := (rot q_v_3_R_l).

(** k_s: a scalar *)
Variable v_4_k_s : R.
Hypothesis v_4_k_s_pos : 0 < v_4_k_s.

(** ω_h^s: a vector *)
Variable v_5_omega_h_s : V3.

(** lambda_min(R_rᵀ R_l + (R_rᵀ R_l)ᵀ) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) lam1.


(** Step 1: (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) = (-1/2) tr(R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s'))
    (algebra (φ(R) = tr(I - R)/2)) *)
Theorem step1 : ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s)))))))) = ((-1/2) * (tr (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  so3_poly.
Qed.

(** Step 2: (-1/2) tr(R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) = (-1/2) tr(R_rᵀ R_l (k_s sk((R_rᵀ R_l)ᵀ R_rᵀ R̄) + hat(R_lᵀ 'ω_h^s')))
    (algebra (eq. (12b), R_lᵀR̄ = R_rlᵀR̄_r)) *)
Theorem step2 : ((-1/2) * (tr (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))) = ((-1/2) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (madd (mscale v_4_k_s (sk (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)))) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  so3_norm_hat.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  so3_poly.
Qed.

(** Step 3: (-1/2) tr(R_rᵀ R_l (k_s sk((R_rᵀ R_l)ᵀ R_rᵀ R̄) + hat(R_lᵀ 'ω_h^s'))) = (-1/2) k_s tr(R_rᵀ R_l sk((R_rᵀ R_l)ᵀ R_rᵀ R̄)) - (1/2) tr(R_rᵀ R_l hat(R_lᵀ 'ω_h^s'))
    (algebra (linearity)) *)
Theorem step3 : ((-1/2) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (madd (mscale v_4_k_s (sk (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)))) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s)))))) = ((((-1/2) * v_4_k_s) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (sk (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)))))) + (- ((1/2) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s))))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  so3_poly.
Qed.

(** Step 4: (-1/2) k_s tr(R_rᵀ R_l sk((R_rᵀ R_l)ᵀ R_rᵀ R̄)) - (1/2) tr(R_rᵀ R_l hat(R_lᵀ 'ω_h^s')) <= (-1/2) k_s λmin(R_rᵀ R_l + (R_rᵀ R_l)ᵀ) (1/2) tr(I - R_lᵀ R̄) + k_s (1/2) tr(I - R_rᵀ R̄) - k_s (1/2) tr(I - R_rᵀ R_l) + <vee(sk(R_rᵀ R_l)), R_lᵀ 'ω_h^s'>
    (as for Ṡ_r, and tr(R hat ω) = -2<sk(R)^∨, ω>: (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R_rl + R_rlᵀ), B = I - R_lᵀR̄)) *)
Theorem step4 : ((((-1/2) * v_4_k_s) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (sk (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)))))) + (- ((1/2) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s))))))) <= (((((((-1/2) * v_4_k_s) * lam1) * (phi (mmul (mT v_3_R_l) v_2_Rbar))) + (v_4_k_s * (phi (mmul (mT v_1_R_r) v_2_Rbar)))) + (- (v_4_k_s * (phi (mmul (mT v_1_R_r) v_3_R_l))))) + (vdot (vee (sk (mmul (mT v_1_R_r) v_3_R_l))) (mvmul (mT v_3_R_l) v_5_omega_h_s))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T2 : 0 <= ((1/4) * v_4_k_s)) by exact (Rmult_le_pos (1/4) v_4_k_s ltac:(lra) T1).
  assert (P1 : (mT (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l)))) = (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l)))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) = (mscale (1/2) (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))).
  { first [ SOSCert.sos_eq ((qw q_v_1_R_r) :: (qx q_v_1_R_r) :: (qy q_v_1_R_r) :: (qz q_v_1_R_r) :: (qw q_v_2_Rbar) :: (qx q_v_2_Rbar) :: (qy q_v_2_Rbar) :: (qz q_v_2_Rbar) :: (qw q_v_3_R_l) :: (qx q_v_3_R_l) :: (qy q_v_3_R_l) :: (qz q_v_3_R_l) :: v_4_k_s :: (v1 v_5_omega_h_s) :: (v2 v_5_omega_h_s) :: (v3 v_5_omega_h_s) :: lam1 :: nil)%list (0%nat :: 4%nat :: 8%nat :: nil)%list | so3_norm; generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l; generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar; so3_split; so3_poly ]. }
  assert (T3 : 0 <= ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))) by exact (trace_lower_bound (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))) (1/2) lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (T4 : 0 <= (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))))) by exact (Rmult_le_pos _ _ T2 T3).
  assert (E : ((((((((-1/2) * v_4_k_s) * lam1) * (phi (mmul (mT v_3_R_l) v_2_Rbar))) + (v_4_k_s * (phi (mmul (mT v_1_R_r) v_2_Rbar)))) + (- (v_4_k_s * (phi (mmul (mT v_1_R_r) v_3_R_l))))) + (vdot (vee (sk (mmul (mT v_1_R_r) v_3_R_l))) (mvmul (mT v_3_R_l) v_5_omega_h_s))) + (- ((((-1/2) * v_4_k_s) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (sk (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)))))) + (- ((1/2) * (tr (mmul (mmul (mT v_1_R_r) v_3_R_l) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))) = (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))))).
  { so3_norm. generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. so3_poly. }
  exact (le_by_slack _ _ _ E T4).
Qed.

(** The derivation's claim: (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) <= (-1/2) k_s λmin(R_rᵀ R_l + (R_rᵀ R_l)ᵀ) (1/2) tr(I - R_lᵀ R̄) + k_s (1/2) tr(I - R_rᵀ R̄) - k_s (1/2) tr(I - R_rᵀ R_l) + <vee(sk(R_rᵀ R_l)), R_lᵀ 'ω_h^s'> *)
Theorem claim : ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s)))))))) <= (((((((-1/2) * v_4_k_s) * lam1) * (phi (mmul (mT v_3_R_l) v_2_Rbar))) + (v_4_k_s * (phi (mmul (mT v_1_R_r) v_2_Rbar)))) + (- (v_4_k_s * (phi (mmul (mT v_1_R_r) v_3_R_l))))) + (vdot (vee (sk (mmul (mT v_1_R_r) v_3_R_l))) (mvmul (mT v_3_R_l) v_5_omega_h_s))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec.
  exact (eq_le_trans _ _ _ (eq_trans (eq_trans step1 step2) step3) step4).
Qed.

End thm1_S_rl_dot.



Section ddt_trajectories.

(** R_r: constant *)
Variable v_1_R_r : M3.
(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_2_Rbar : R -> M3.
(** R_l: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_3_R_l : R -> M3.
(** k_s: constant *)
Variable v_4_k_s : R.
(** ω_h^s: its value at t *)
Variable v_5_omega_h_s : V3.
Variable t : R.

(** The first expression is the derivative: d/dt (1/2) tr(I - R_rᵀ R_l) along the declared dynamics,
    at every t, is (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) *)
Theorem ddt : is_mderiv v_3_R_l t (mmul (v_3_R_l t) (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT (v_3_R_l t)) (v_2_Rbar t))))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s)))) -> is_derive (fun s => (phi (mmul (mT v_1_R_r) (v_3_R_l s)))) t ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (v_3_R_l t) (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT (v_3_R_l t)) (v_2_Rbar t))))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s)))))))).
Proof.
  intros D1.
  eapply deriv_unique_eq; [ d_mirror | cbv beta; traj_same ].
Qed.

End ddt_trajectories.

End thm1_S_rl_dot.

Module thm1_S_h_sign.

(** Exported from the derivation 'thm1.S_h-sign' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: sk(R_lᵀR_r)^∨ = -sk(R_rl)^∨, so S_h ≥ 0 is eq. (16)
    its place in the paper: eq. (16) and the definition of S_h
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
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

End thm1_S_h_sign.

Module thm1_V_dot.

(** Exported from the derivation 'thm1.V-dot' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: V̇ = -(k_s/4)[tr{(R̄_r+R̄_rᵀ)(I - R̄ᵀR_l)} + tr{(R_rl+R_rlᵀ)(I - R_lᵀR̄)}] ≤ -(k_s/2)(λ1 + λ2) φ(R_lᵀR̄) ≤ 0
    its place in the paper: Theorem 1 proof, eq. (17)
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3 Hierarchy Derive Traj.
Open Scope R_scope.

Section thm1_V_dot.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_r : quat.
Hypothesis q_v_1_R_r_nonzero : qn q_v_1_R_r <> 0.
Local Notation v_1_R_r := (rot q_v_1_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_Rbar : quat.
Hypothesis q_v_2_Rbar_nonzero : qn q_v_2_Rbar <> 0.
Local Notation v_2_Rbar := (rot q_v_2_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_R_l : quat.
Hypothesis q_v_3_R_l_nonzero : qn q_v_3_R_l <> 0.
Local Notation v_3_R_l := (rot q_v_3_R_l).

(** k_s: a scalar *)
Variable v_4_k_s : R.
Hypothesis v_4_k_s_pos : 0 < v_4_k_s.

(** ω_h^s: a vector *)
Variable v_5_omega_h_s : V3.

(** lambda_min(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) lam1.

(** lambda_min(R_rᵀ R_l + (R_rᵀ R_l)ᵀ) *)
Variable lam2 : R.
Hypothesis lam2_spec : lam_min_spec (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) lam2.

(** assumption: λmin(R̄_r + R̄_rᵀ) ≥ 0 (Lemma 1) *)
Hypothesis assumption1 : 0 <= lam1.

(** assumption: λmin(R_rl + R_rlᵀ) > 0 (Assumption 1, item 2) *)
Hypothesis assumption2 : 0 < lam2.


(** Step 1: (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) + (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) - <vee(R_rᵀ R_l), R_lᵀ 'ω_h^s'> = (-1/4) k_s (tr((R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) (I - R̄ᵀ R_l)) + tr((R_rᵀ R_l + (R_rᵀ R_l)ᵀ) (I - R_lᵀ R̄)))
    (algebra (Ṡ_r + Ṡ_rl + Ṡ_h; the human terms cancel)) *)
Theorem step1 : ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) v_3_R_l)) (mvmul (mT v_3_R_l) v_5_omega_h_s)))) = (((-1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 lam2 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec lam2_spec.
  so3_norm.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 2: (-1/4) k_s (tr((R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) (I - R̄ᵀ R_l)) + tr((R_rᵀ R_l + (R_rᵀ R_l)ᵀ) (I - R_lᵀ R̄))) <= (-1/2) k_s (λmin(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) + λmin(R_rᵀ R_l + (R_rᵀ R_l)ᵀ)) (1/2) tr(I - R_lᵀ R̄)
    (trace inequality twice: (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R̄_r + R̄_rᵀ), B = I - R̄ᵀ R_l); (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R_rl + R_rlᵀ), B = I - R_lᵀR̄)) *)
Theorem step2 : (((-1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))) <= ((((-1/2) * v_4_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_3_R_l) v_2_Rbar))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 lam2 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec lam2_spec.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T2 : 0 <= ((1/4) * v_4_k_s)) by exact (Rmult_le_pos (1/4) v_4_k_s ltac:(lra) T1).
  assert (P1 : (mT (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar)))) = (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar)))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))) = (mscale (1/2) (mmul (mT (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))).
  { first [ SOSCert.sos_eq ((qw q_v_1_R_r) :: (qx q_v_1_R_r) :: (qy q_v_1_R_r) :: (qz q_v_1_R_r) :: (qw q_v_2_Rbar) :: (qx q_v_2_Rbar) :: (qy q_v_2_Rbar) :: (qz q_v_2_Rbar) :: (qw q_v_3_R_l) :: (qx q_v_3_R_l) :: (qy q_v_3_R_l) :: (qz q_v_3_R_l) :: v_4_k_s :: (v1 v_5_omega_h_s) :: (v2 v_5_omega_h_s) :: (v3 v_5_omega_h_s) :: lam1 :: lam2 :: nil)%list (0%nat :: 4%nat :: 8%nat :: nil)%list | so3_norm; generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar; generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l; so3_split; so3_poly ]. }
  assert (T3 : 0 <= ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))))) by exact (trace_lower_bound (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))) (1/2) lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (T4 : 0 <= (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))))))) by exact (Rmult_le_pos _ _ T2 T3).
  assert (T5 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T6 : 0 <= ((1/4) * v_4_k_s)) by exact (Rmult_le_pos (1/4) v_4_k_s ltac:(lra) T5).
  assert (P3 : (mT (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l)))) = (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l)))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P4 : (sym (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) = (mscale (1/2) (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))).
  { first [ SOSCert.sos_eq ((qw q_v_1_R_r) :: (qx q_v_1_R_r) :: (qy q_v_1_R_r) :: (qz q_v_1_R_r) :: (qw q_v_2_Rbar) :: (qx q_v_2_Rbar) :: (qy q_v_2_Rbar) :: (qz q_v_2_Rbar) :: (qw q_v_3_R_l) :: (qx q_v_3_R_l) :: (qy q_v_3_R_l) :: (qz q_v_3_R_l) :: v_4_k_s :: (v1 v_5_omega_h_s) :: (v2 v_5_omega_h_s) :: (v3 v_5_omega_h_s) :: lam1 :: lam2 :: nil)%list (0%nat :: 4%nat :: 8%nat :: nil)%list | so3_norm; generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l; generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar; so3_split; so3_poly ]. }
  assert (T7 : 0 <= ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam2 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))) by exact (trace_lower_bound (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))) (1/2) lam2 P3 P4 ltac:(lra) lam2_spec).
  assert (T8 : 0 <= (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam2 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))))) by exact (Rmult_le_pos _ _ T6 T7).
  assert (E : (((((-1/2) * v_4_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_3_R_l) v_2_Rbar))) + (- (((-1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))))) = ((((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))))) + (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam2 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_poly. }
  exact (le_by_slack _ _ _ E (Rplus_le_le_0_compat _ _ T4 T8)).
Qed.

(** Step 3: (-1/2) k_s (λmin(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) + λmin(R_rᵀ R_l + (R_rᵀ R_l)ᵀ)) (1/2) tr(I - R_lᵀ R̄) <= 0
    (λ1 ≥ 0 (Lemma 1), λ2 > 0 (Assumption 1.2), φ(Q) = ‖I - Q‖²/4: ((1/2 * (k_s > 0 (declared))) * ((assumed: λmin(R̄_r + R̄_rᵀ) ≥ 0) + (assumed: λmin(R_rl + R_rlᵀ) > 0))) * (1/4 * (square of I - R_lᵀR̄))) *)
Theorem step3 : ((((-1/2) * v_4_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_3_R_l) v_2_Rbar))) <= 0.
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 lam2 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec lam2_spec assumption1 assumption2.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T2 : 0 <= ((1/2) * v_4_k_s)) by exact (Rmult_le_pos (1/2) v_4_k_s ltac:(lra) T1).
  assert (T3 : 0 <= lam1) by exact assumption1.
  assert (T4 : 0 <= lam2) by exact (Rlt_le _ _ assumption2).
  assert (T5 : 0 <= (lam1 + lam2)) by exact (Rplus_le_le_0_compat _ _ T3 T4).
  assert (T6 : 0 <= (((1/2) * v_4_k_s) * (lam1 + lam2))) by exact (Rmult_le_pos _ _ T2 T5).
  assert (T7 : 0 <= (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))) by exact (fro2_nonneg (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))).
  assert (T8 : 0 <= ((1/4) * (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))) by exact (Rmult_le_pos (1/4) (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) ltac:(lra) T7).
  assert (T9 : 0 <= ((((1/2) * v_4_k_s) * (lam1 + lam2)) * ((1/4) * (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))) by exact (Rmult_le_pos _ _ T6 T8).
  assert (E : (0 + (- ((((-1/2) * v_4_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_3_R_l) v_2_Rbar))))) = ((((1/2) * v_4_k_s) * (lam1 + lam2)) * ((1/4) * (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))).
  { so3_norm. generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_poly. }
  exact (le_by_slack _ _ _ E T9).
Qed.

(** The derivation's claim: (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) + (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) - <vee(R_rᵀ R_l), R_lᵀ 'ω_h^s'> <= 0 *)
Theorem claim : ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) v_3_R_l)) (mvmul (mT v_3_R_l) v_5_omega_h_s)))) <= 0.
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 lam2 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec lam2_spec assumption1 assumption2.
  exact (Rle_trans _ _ _ (eq_le_trans _ _ _ step1 step2) step3).
Qed.

End thm1_V_dot.



Section ddt_trajectories.

(** R_r: constant *)
Variable v_1_R_r : M3.
(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_2_Rbar : R -> M3.
(** R_l: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_3_R_l : R -> M3.
(** k_s: constant *)
Variable v_4_k_s : R.
(** ω_h^s: its value at t *)
Variable v_5_omega_h_s : V3.
(** S_h: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_6_S_h : R -> R.
Variable t : R.

(** The first expression is the derivative: d/dt (1/2) tr(I - R_rᵀ R̄) + (1/2) tr(I - R_rᵀ R_l) + S_h along the declared dynamics,
    at every t, is (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) + (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) - <vee(R_rᵀ R_l), R_lᵀ 'ω_h^s'> *)
Theorem ddt : is_mderiv v_2_Rbar t (mmul (mscale v_4_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) (v_3_R_l t)))) -> is_mderiv v_3_R_l t (mmul (v_3_R_l t) (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT (v_3_R_l t)) (v_2_Rbar t))))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s)))) -> is_derive v_6_S_h t (- (vdot (vee (mmul (mT v_1_R_r) (v_3_R_l t))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s))) -> is_derive (fun s => (((phi (mmul (mT v_1_R_r) (v_2_Rbar s))) + (phi (mmul (mT v_1_R_r) (v_3_R_l s)))) + (v_6_S_h s))) t ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) (v_3_R_l t)))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (v_3_R_l t) (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT (v_3_R_l t)) (v_2_Rbar t))))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) (v_3_R_l t))) (mvmul (mT (v_3_R_l t)) v_5_omega_h_s)))).
Proof.
  intros D1 D2 D3.
  eapply deriv_unique_eq; [ d_mirror | cbv beta; traj_same ].
Qed.

End ddt_trajectories.

End thm1_V_dot.

Module thm1_V_dot_zero_implies_sync.

(** Exported from the derivation 'thm1.V-dot-zero-implies-sync' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: (k_s/8)(λ1 + λ2)‖I - R_lᵀR̄‖² ≤ -V̇: with λ1 + λ2 > 0, V̇ = 0 forces R_l = R̄
    its place in the paper: Theorem 1 proof, 'V̇ = 0 iff R_l = R̄'
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section thm1_V_dot_zero_implies_sync.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_r : quat.
Hypothesis q_v_1_R_r_nonzero : qn q_v_1_R_r <> 0.
Local Notation v_1_R_r := (rot q_v_1_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_Rbar : quat.
Hypothesis q_v_2_Rbar_nonzero : qn q_v_2_Rbar <> 0.
Local Notation v_2_Rbar := (rot q_v_2_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_R_l : quat.
Hypothesis q_v_3_R_l_nonzero : qn q_v_3_R_l <> 0.
Local Notation v_3_R_l := (rot q_v_3_R_l).

(** k_s: a scalar *)
Variable v_4_k_s : R.
Hypothesis v_4_k_s_pos : 0 < v_4_k_s.

(** ω_h^s: a vector *)
Variable v_5_omega_h_s : V3.

(** lambda_min(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) lam1.

(** lambda_min(R_rᵀ R_l + (R_rᵀ R_l)ᵀ) *)
Variable lam2 : R.
Hypothesis lam2_spec : lam_min_spec (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) lam2.


(** Step 1: (1/8) k_s (λmin(R_rᵀ R̄ + (R_rᵀ R̄)ᵀ) + λmin(R_rᵀ R_l + (R_rᵀ R_l)ᵀ)) tr((I - R_lᵀ R̄)ᵀ (I - R_lᵀ R̄)) <= -((1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) + (1/2) tr(-R_rᵀ R_l hat(k_s vee(sk(R_lᵀ R̄)) + R_lᵀ 'ω_h^s')) - <vee(R_rᵀ R_l), R_lᵀ 'ω_h^s'>)
    (the bound of eq. (17) with φ(Q) = ‖I - Q‖²/4: (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R̄_r + R̄_rᵀ), B = I - R̄ᵀ R_l); (1/4 * (k_s > 0 (declared))) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = (R_rl + R_rlᵀ), B = I - R_lᵀR̄)) *)
Theorem step1 : ((((1/8) * v_4_k_s) * (lam1 + lam2)) * (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))) <= (- ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) v_3_R_l)) (mvmul (mT v_3_R_l) v_5_omega_h_s))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s v_5_omega_h_s lam1 lam2 q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos lam1_spec lam2_spec.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T2 : 0 <= ((1/4) * v_4_k_s)) by exact (Rmult_le_pos (1/4) v_4_k_s ltac:(lra) T1).
  assert (P1 : (mT (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar)))) = (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar)))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))) = (mscale (1/2) (mmul (mT (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))).
  { first [ SOSCert.sos_eq ((qw q_v_1_R_r) :: (qx q_v_1_R_r) :: (qy q_v_1_R_r) :: (qz q_v_1_R_r) :: (qw q_v_2_Rbar) :: (qx q_v_2_Rbar) :: (qy q_v_2_Rbar) :: (qz q_v_2_Rbar) :: (qw q_v_3_R_l) :: (qx q_v_3_R_l) :: (qy q_v_3_R_l) :: (qz q_v_3_R_l) :: v_4_k_s :: (v1 v_5_omega_h_s) :: (v2 v_5_omega_h_s) :: (v3 v_5_omega_h_s) :: lam1 :: lam2 :: nil)%list (0%nat :: 4%nat :: 8%nat :: nil)%list | so3_norm; generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar; generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l; so3_split; so3_poly ]. }
  assert (T3 : 0 <= ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))))) by exact (trace_lower_bound (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))) (1/2) lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (T4 : 0 <= (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))))))) by exact (Rmult_le_pos _ _ T2 T3).
  assert (T5 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T6 : 0 <= ((1/4) * v_4_k_s)) by exact (Rmult_le_pos (1/4) v_4_k_s ltac:(lra) T5).
  assert (P3 : (mT (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l)))) = (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l)))).
  { generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P4 : (sym (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) = (mscale (1/2) (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))).
  { first [ SOSCert.sos_eq ((qw q_v_1_R_r) :: (qx q_v_1_R_r) :: (qy q_v_1_R_r) :: (qz q_v_1_R_r) :: (qw q_v_2_Rbar) :: (qx q_v_2_Rbar) :: (qy q_v_2_Rbar) :: (qz q_v_2_Rbar) :: (qw q_v_3_R_l) :: (qx q_v_3_R_l) :: (qy q_v_3_R_l) :: (qz q_v_3_R_l) :: v_4_k_s :: (v1 v_5_omega_h_s) :: (v2 v_5_omega_h_s) :: (v3 v_5_omega_h_s) :: lam1 :: lam2 :: nil)%list (0%nat :: 4%nat :: 8%nat :: nil)%list | so3_norm; generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l; generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar; so3_split; so3_poly ]. }
  assert (T7 : 0 <= ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam2 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))) by exact (trace_lower_bound (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))) (1/2) lam2 P3 P4 ltac:(lra) lam2_spec).
  assert (T8 : 0 <= (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam2 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))))))) by exact (Rmult_le_pos _ _ T6 T7).
  assert (E : ((- ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_3_R_l (hat (vadd (vscale v_4_k_s (vee (sk (mmul (mT v_3_R_l) v_2_Rbar)))) (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) v_3_R_l)) (mvmul (mT v_3_R_l) v_5_omega_h_s))))) + (- ((((1/8) * v_4_k_s) * (lam1 + lam2)) * (tr (mmul (mT (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))) = ((((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_2_Rbar) (mT (mmul (mT v_1_R_r) v_2_Rbar))) (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l))))) + (- (lam1 * (tr (madd I3 (mneg (mmul (mT v_2_Rbar) v_3_R_l)))))))) + (((1/4) * v_4_k_s) * ((tr (mmul (madd (mmul (mT v_1_R_r) v_3_R_l) (mT (mmul (mT v_1_R_r) v_3_R_l))) (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar))))) + (- (lam2 * (tr (madd I3 (mneg (mmul (mT v_3_R_l) v_2_Rbar)))))))))).
  { so3_norm. generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r. generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar. generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l. so3_poly. }
  exact (le_by_slack _ _ _ E (Rplus_le_le_0_compat _ _ T4 T8)).
Qed.

End thm1_V_dot_zero_implies_sync.

End thm1_V_dot_zero_implies_sync.

Module thm1_V_dot_zero_on_sync.

(** Exported from the derivation 'thm1.V-dot-zero-on-sync' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: V̇ = 0 when R_l = R̄, whatever the human commands
    its place in the paper: Theorem 1 proof, 'V̇ = 0 iff R_l = R̄'
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3 Hierarchy Derive Traj.
Open Scope R_scope.

Section thm1_V_dot_zero_on_sync.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_r : quat.
Hypothesis q_v_1_R_r_nonzero : qn q_v_1_R_r <> 0.
Local Notation v_1_R_r := (rot q_v_1_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_Rbar : quat.
Hypothesis q_v_2_Rbar_nonzero : qn q_v_2_Rbar <> 0.
Local Notation v_2_Rbar := (rot q_v_2_Rbar).

(** k_s: a scalar *)
Variable v_3_k_s : R.
Hypothesis v_3_k_s_pos : 0 < v_3_k_s.

(** ω_h^s: a vector *)
Variable v_4_omega_h_s : V3.


(** Step 1: (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R̄)) + (1/2) tr(-R_rᵀ R̄ hat(k_s vee(sk(R̄ᵀ R̄)) + R̄ᵀ 'ω_h^s')) - <vee(R_rᵀ R̄), R̄ᵀ 'ω_h^s'> = 0
    (algebra (R_l = R̄)) *)
Theorem step1 : ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_3_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_2_Rbar))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul v_2_Rbar (hat (vadd (vscale v_3_k_s (vee (sk (mmul (mT v_2_Rbar) v_2_Rbar)))) (mvmul (mT v_2_Rbar) v_4_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) v_2_Rbar)) (mvmul (mT v_2_Rbar) v_4_omega_h_s)))) = 0.
Proof using q_v_1_R_r q_v_2_Rbar v_3_k_s v_4_omega_h_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero v_3_k_s_pos.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  so3_poly.
Qed.

End thm1_V_dot_zero_on_sync.



Section ddt_trajectories.

(** R_r: constant *)
Variable v_1_R_r : M3.
(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_2_Rbar : R -> M3.
(** R_l: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_5_R_l : R -> M3.
(** k_s: constant *)
Variable v_3_k_s : R.
(** ω_h^s: its value at t *)
Variable v_4_omega_h_s : V3.
(** S_h: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_6_S_h : R -> R.
Variable t : R.

(** The first expression is the derivative: d/dt (1/2) tr(I - R_rᵀ R̄) + (1/2) tr(I - R_rᵀ R_l) + S_h along the declared dynamics and the substitution,
    at every t, is (1/2) tr(-R_rᵀ k_s R̄ sk(R̄ᵀ R̄)) + (1/2) tr(-R_rᵀ R̄ hat(k_s vee(sk(R̄ᵀ R̄)) + R̄ᵀ 'ω_h^s')) - <vee(R_rᵀ R̄), R̄ᵀ 'ω_h^s'> *)
Theorem ddt : is_mderiv v_2_Rbar t (mmul (mscale v_3_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) (v_5_R_l t)))) -> is_mderiv v_5_R_l t (mmul (v_5_R_l t) (hat (vadd (vscale v_3_k_s (vee (sk (mmul (mT (v_5_R_l t)) (v_2_Rbar t))))) (mvmul (mT (v_5_R_l t)) v_4_omega_h_s)))) -> is_derive v_6_S_h t (- (vdot (vee (mmul (mT v_1_R_r) (v_5_R_l t))) (mvmul (mT (v_5_R_l t)) v_4_omega_h_s))) -> (v_5_R_l t) = (v_2_Rbar t) -> is_derive (fun s => (((phi (mmul (mT v_1_R_r) (v_2_Rbar s))) + (phi (mmul (mT v_1_R_r) (v_5_R_l s)))) + (v_6_S_h s))) t ((((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (mscale v_3_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) (v_2_Rbar t)))))))) + ((1/2) * (tr (mneg (mmul (mT v_1_R_r) (mmul (v_2_Rbar t) (hat (vadd (vscale v_3_k_s (vee (sk (mmul (mT (v_2_Rbar t)) (v_2_Rbar t))))) (mvmul (mT (v_2_Rbar t)) v_4_omega_h_s))))))))) + (- (vdot (vee (mmul (mT v_1_R_r) (v_2_Rbar t))) (mvmul (mT (v_2_Rbar t)) v_4_omega_h_s)))).
Proof.
  intros D1 D2 D3 E1.
  eapply deriv_unique_eq; [ d_mirror | cbv beta; try rewrite E1; traj_same ].
Qed.

End ddt_trajectories.

End thm1_V_dot_zero_on_sync.

Module thm1_lasalle_derivative.

(** Exported from the derivation 'thm1.lasalle-derivative' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: on R_l = R̄: d/dt(R_lᵀR̄) = -R_lᵀ hat(ω_h^s) R_l = -hat(R_lᵀ ω_h^s)
    its place in the paper: Theorem 1 proof, LaSalle step
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3 Hierarchy Derive Traj.
Open Scope R_scope.

Section thm1_lasalle_derivative.

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_l : quat.
Hypothesis q_v_1_R_l_nonzero : qn q_v_1_R_l <> 0.
Local Notation v_1_R_l := (rot q_v_1_R_l).

(** k_s: a scalar *)
Variable v_2_k_s : R.
Hypothesis v_2_k_s_pos : 0 < v_2_k_s.

(** ω_h^s: a vector *)
Variable v_3_omega_h_s : V3.


(** Step 1: (R_l hat(k_s vee(sk(R_lᵀ R_l)) + R_lᵀ 'ω_h^s'))ᵀ R_l + R_lᵀ k_s R_l sk(R_lᵀ R_l) = -R_lᵀ hat('ω_h^s') R_l
    (algebra (sk(I) = 0)) *)
Theorem step1 : (madd (mmul (mT (mmul v_1_R_l (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT v_1_R_l) v_1_R_l)))) (mvmul (mT v_1_R_l) v_3_omega_h_s))))) v_1_R_l) (mmul (mT v_1_R_l) (mmul (mscale v_2_k_s v_1_R_l) (sk (mmul (mT v_1_R_l) v_1_R_l))))) = (mneg (mmul (mmul (mT v_1_R_l) (hat v_3_omega_h_s)) v_1_R_l)).
Proof using q_v_1_R_l v_2_k_s v_3_omega_h_s q_v_1_R_l_nonzero v_2_k_s_pos.
  first [ SOSCert.sos_eq ((qw q_v_1_R_l) :: (qx q_v_1_R_l) :: (qy q_v_1_R_l) :: (qz q_v_1_R_l) :: v_2_k_s :: (v1 v_3_omega_h_s) :: (v2 v_3_omega_h_s) :: (v3 v_3_omega_h_s) :: nil)%list (0%nat :: nil)%list | so3_norm_hat; generalize (rot q_v_1_R_l) as G_v_1_R_l; intro G_v_1_R_l; so3_split; so3_poly ].
Qed.

(** Step 2: -R_lᵀ hat('ω_h^s') R_l = -hat(R_lᵀ 'ω_h^s')
    (algebra (Rᵀ hat(ω) R = hat(Rᵀω))) *)
Theorem step2 : (mneg (mmul (mmul (mT v_1_R_l) (hat v_3_omega_h_s)) v_1_R_l)) = (mneg (hat (mvmul (mT v_1_R_l) v_3_omega_h_s))).
Proof using q_v_1_R_l v_2_k_s v_3_omega_h_s q_v_1_R_l_nonzero v_2_k_s_pos.
  first [ SOSCert.sos_eq ((qw q_v_1_R_l) :: (qx q_v_1_R_l) :: (qy q_v_1_R_l) :: (qz q_v_1_R_l) :: v_2_k_s :: (v1 v_3_omega_h_s) :: (v2 v_3_omega_h_s) :: (v3 v_3_omega_h_s) :: nil)%list (0%nat :: nil)%list | so3_norm_hat; generalize (rot q_v_1_R_l) as G_v_1_R_l; intro G_v_1_R_l; so3_split; so3_poly ].
Qed.

(** The derivation's claim: (R_l hat(k_s vee(sk(R_lᵀ R_l)) + R_lᵀ 'ω_h^s'))ᵀ R_l + R_lᵀ k_s R_l sk(R_lᵀ R_l) = -hat(R_lᵀ 'ω_h^s') *)
Theorem claim : (madd (mmul (mT (mmul v_1_R_l (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT v_1_R_l) v_1_R_l)))) (mvmul (mT v_1_R_l) v_3_omega_h_s))))) v_1_R_l) (mmul (mT v_1_R_l) (mmul (mscale v_2_k_s v_1_R_l) (sk (mmul (mT v_1_R_l) v_1_R_l))))) = (mneg (hat (mvmul (mT v_1_R_l) v_3_omega_h_s))).
Proof using q_v_1_R_l v_2_k_s v_3_omega_h_s q_v_1_R_l_nonzero v_2_k_s_pos.
  exact (eq_trans step1 step2).
Qed.

End thm1_lasalle_derivative.



Section ddt_trajectories.

(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_4_Rbar : R -> M3.
(** R_l: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_1_R_l : R -> M3.
(** k_s: constant *)
Variable v_2_k_s : R.
(** ω_h^s: its value at t *)
Variable v_3_omega_h_s : V3.
Variable t : R.

(** The first expression is the derivative: d/dt R_lᵀ R̄ along the declared dynamics and the substitution,
    at every t, is (R_l hat(k_s vee(sk(R_lᵀ R_l)) + R_lᵀ 'ω_h^s'))ᵀ R_l + R_lᵀ k_s R_l sk(R_lᵀ R_l) *)
Theorem ddt : is_mderiv v_4_Rbar t (mmul (mscale v_2_k_s (v_4_Rbar t)) (sk (mmul (mT (v_4_Rbar t)) (v_1_R_l t)))) -> is_mderiv v_1_R_l t (mmul (v_1_R_l t) (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT (v_1_R_l t)) (v_4_Rbar t))))) (mvmul (mT (v_1_R_l t)) v_3_omega_h_s)))) -> (v_4_Rbar t) = (v_1_R_l t) -> is_mderiv (fun s => (mmul (mT (v_1_R_l s)) (v_4_Rbar s))) t (madd (mmul (mT (mmul (v_1_R_l t) (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT (v_1_R_l t)) (v_1_R_l t))))) (mvmul (mT (v_1_R_l t)) v_3_omega_h_s))))) (v_1_R_l t)) (mmul (mT (v_1_R_l t)) (mmul (mscale v_2_k_s (v_1_R_l t)) (sk (mmul (mT (v_1_R_l t)) (v_1_R_l t)))))).
Proof.
  intros D1 D2 E1.
  eapply mderiv_unique_eq; [ d_mirror | cbv beta; try rewrite E1; traj_same ].
Qed.

End ddt_trajectories.

End thm1_lasalle_derivative.

Module thm1_lasalle_derivative_from_sk_only.

(** Exported from the derivation 'thm1.lasalle-derivative-from-sk-only' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: with only sk(R_lᵀR̄) = 0 (R_lᵀR̄ = 2ξξᵀ - I, angle π) the formula changes
    its place in the paper: Theorem 1 proof, 'which implies sk(R_lᵀR̄)^∨ = 0'
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3 Hierarchy Derive Traj.
Open Scope R_scope.

Section thm1_lasalle_derivative_from_sk_only.

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_R_l : quat.
Hypothesis q_v_1_R_l_nonzero : qn q_v_1_R_l <> 0.
Local Notation v_1_R_l := (rot q_v_1_R_l).

(** k_s: a scalar *)
Variable v_2_k_s : R.
Hypothesis v_2_k_s_pos : 0 < v_2_k_s.

(** ω_h^s: a vector *)
Variable v_3_omega_h_s : V3.

(** ξ: a unit vector *)
Variable v_4_xi : V3.
Hypothesis v_4_xi_unit : vdot v_4_xi v_4_xi = 1.


(** Step 1: (R_l hat(k_s vee(sk(R_lᵀ R_l (2 ξ ξᵀ - I))) + R_lᵀ 'ω_h^s'))ᵀ R_l (2 ξ ξᵀ - I) + R_lᵀ k_s R_l (2 ξ ξᵀ - I) sk((R_l (2 ξ ξᵀ - I))ᵀ R_l) = -R_lᵀ hat('ω_h^s') R_l (2 ξ ξᵀ - I)
    (algebra (sk(2ξξᵀ - I) = 0)) *)
Theorem step1 : (madd (mmul (mT (mmul v_1_R_l (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT v_1_R_l) (mmul v_1_R_l (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3))))))) (mvmul (mT v_1_R_l) v_3_omega_h_s))))) (mmul v_1_R_l (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) (mmul (mT v_1_R_l) (mmul (mscale v_2_k_s (mmul v_1_R_l (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) (sk (mmul (mT (mmul v_1_R_l (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) v_1_R_l))))) = (mneg (mmul (mmul (mmul (mT v_1_R_l) (hat v_3_omega_h_s)) v_1_R_l) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))).
Proof using q_v_1_R_l v_2_k_s v_3_omega_h_s v_4_xi q_v_1_R_l_nonzero v_2_k_s_pos v_4_xi_unit.
  first [ SOSCert.sos_eq ((qw q_v_1_R_l) :: (qx q_v_1_R_l) :: (qy q_v_1_R_l) :: (qz q_v_1_R_l) :: v_2_k_s :: (v1 v_3_omega_h_s) :: (v2 v_3_omega_h_s) :: (v3 v_3_omega_h_s) :: (v1 v_4_xi) :: (v2 v_4_xi) :: (v3 v_4_xi) :: nil)%list (0%nat :: nil)%list | so3_norm_hat; generalize (rot q_v_1_R_l) as G_v_1_R_l; intro G_v_1_R_l; so3_split; so3_poly ].
Qed.

End thm1_lasalle_derivative_from_sk_only.



Section ddt_trajectories.

(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_5_Rbar : R -> M3.
(** R_l: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_1_R_l : R -> M3.
(** k_s: constant *)
Variable v_2_k_s : R.
(** ω_h^s: its value at t *)
Variable v_3_omega_h_s : V3.
(** ξ: its value at t *)
Variable v_4_xi : V3.
Variable t : R.

(** The first expression is the derivative: d/dt R_lᵀ R̄ along the declared dynamics and the substitution,
    at every t, is (R_l hat(k_s vee(sk(R_lᵀ R_l (2 ξ ξᵀ - I))) + R_lᵀ 'ω_h^s'))ᵀ R_l (2 ξ ξᵀ - I) + R_lᵀ k_s R_l (2 ξ ξᵀ - I) sk((R_l (2 ξ ξᵀ - I))ᵀ R_l) *)
Theorem ddt : is_mderiv v_5_Rbar t (mmul (mscale v_2_k_s (v_5_Rbar t)) (sk (mmul (mT (v_5_Rbar t)) (v_1_R_l t)))) -> is_mderiv v_1_R_l t (mmul (v_1_R_l t) (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT (v_1_R_l t)) (v_5_Rbar t))))) (mvmul (mT (v_1_R_l t)) v_3_omega_h_s)))) -> (v_5_Rbar t) = (mmul (v_1_R_l t) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3))) -> is_mderiv (fun s => (mmul (mT (v_1_R_l s)) (v_5_Rbar s))) t (madd (mmul (mT (mmul (v_1_R_l t) (hat (vadd (vscale v_2_k_s (vee (sk (mmul (mT (v_1_R_l t)) (mmul (v_1_R_l t) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3))))))) (mvmul (mT (v_1_R_l t)) v_3_omega_h_s))))) (mmul (v_1_R_l t) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) (mmul (mT (v_1_R_l t)) (mmul (mscale v_2_k_s (mmul (v_1_R_l t) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) (sk (mmul (mT (mmul (v_1_R_l t) (madd (mscale 2 (outer v_4_xi v_4_xi)) (mneg I3)))) (v_1_R_l t)))))).
Proof.
  intros D1 D2 E1.
  eapply mderiv_unique_eq; [ d_mirror | cbv beta; try rewrite E1; traj_same ].
Qed.

End ddt_trajectories.

End thm1_lasalle_derivative_from_sk_only.
