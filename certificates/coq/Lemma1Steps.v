(** 14 units in one file, each a module of its own name: lemma1_spectrum,
    lemma1_spectrum_projector, lemma1_spectrum_rank, lemma1_trace_form,
    sec3_rbar_dot_form, lemma1_h_dot, lemma1_boundary_square, lemma1_boundary_h_dot,
    lemma1_boundary_sign_direct, lemma1_gradient_form, lemma1_gradient_nonzero,
    lemma1_gradient_vanishes_at_pi, lemma1_trace_inequality_psd,
    lemma1_trace_inequality_sym_psd. The libraries are loaded once, below; each module
    imports those its unit uses. *)

From Coq Require Reals Lra.
From VerifyCoq Require SO3 SOSCert Traj.
From Coquelicot Require Hierarchy Derive.

Module lemma1_spectrum.

(** Exported from the derivation 'lemma1.spectrum' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: R + Rᵀ = 2 ξξᵀ + 2cosθ (I - ξξᵀ): eigenvalue 2 on ξ, 2cosθ twice on ξ⊥
    its place in the paper: Lemma 1 proof, eigenvalues {2, 2cosθ, 2cosθ}
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section lemma1_spectrum.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.

(** θ: an angle *)
Variable v_2_theta : R.


(** Step 1: I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ) + (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ))ᵀ = 2 ξ ξᵀ + 2 cos(θ) (I - ξ ξᵀ)
    (algebra (Rodrigues, |ξ| = 1)) *)
Theorem step1 : (madd (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi)))) (mT (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi)))))) = (madd (mscale 2 (outer v_1_xi v_1_xi)) (mscale (2 * (cos v_2_theta)) (madd I3 (mneg (outer v_1_xi v_1_xi))))).
Proof using v_1_xi v_2_theta v_1_xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ (((2 * (cos v_2_theta) + (-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ (((2 * (cos v_2_theta) + (-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ (((2 * (cos v_2_theta) + (-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

End lemma1_spectrum.

End lemma1_spectrum.

Module lemma1_spectrum_projector.

(** Exported from the derivation 'lemma1.spectrum-projector' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: ξξᵀ is an orthogonal projector of rank tr(ξξᵀ) = 1
    its place in the paper: Lemma 1 proof, eigenvalues
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section lemma1_spectrum_projector.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.


(** Step 1: ξ ξᵀ ξ ξᵀ = ξ ξᵀ
    (algebra (|ξ| = 1)) *)
Theorem step1 : (mmul (outer v_1_xi v_1_xi) (outer v_1_xi v_1_xi)) = (outer v_1_xi v_1_xi).
Proof using v_1_xi v_1_xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v2 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v2 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v3 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

End lemma1_spectrum_projector.

End lemma1_spectrum_projector.

Module lemma1_spectrum_rank.

(** Exported from the derivation 'lemma1.spectrum-rank' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: rank of ξξᵀ is 1
    its place in the paper: Lemma 1 proof
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section lemma1_spectrum_rank.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.


(** Step 1: tr(ξ ξᵀ) = 1
    (algebra (|ξ| = 1)) *)
Theorem step1 : (tr (outer v_1_xi v_1_xi)) = 1.
Proof using v_1_xi v_1_xi_unit.
  apply (eq_by_sum _ _ (((1) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

End lemma1_spectrum_rank.

End lemma1_spectrum_rank.

Module lemma1_trace_form.

(** Exported from the derivation 'lemma1.trace-form' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: tr(R̄_r) = 1 + 2cosθ, so R̄_r + R̄_rᵀ ⪰ 0 ⟺ cosθ ≥ 0 ⟺ tr(R̄_r) ≥ 1
    its place in the paper: Lemma 1 proof, eq. (14)
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section lemma1_trace_form.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.

(** θ: an angle *)
Variable v_2_theta : R.


(** Step 1: tr(I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) = 1 + 2 cos(θ)
    (algebra (Rodrigues)) *)
Theorem step1 : (tr (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))) = (1 + (2 * (cos v_2_theta))).
Proof using v_1_xi v_2_theta v_1_xi_unit.
  apply (eq_by_sum _ _ (((2 * (cos v_2_theta) + (-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

End lemma1_trace_form.

End lemma1_trace_form.

Module sec3_rbar_dot_form.

(** Exported from the derivation 'sec3.rbar-dot-form' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: with ω̃ = k_s R̄ sk(R̄ᵀR_l)^∨, hat(ω̃) R̄ = k_s R̄ sk(R̄ᵀR_l)
    its place in the paper: eqs. (9), (12a), (13)
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section sec3_rbar_dot_form.

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_Rbar : quat.
Hypothesis q_v_1_Rbar_nonzero : qn q_v_1_Rbar <> 0.
Local Notation v_1_Rbar := (rot q_v_1_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_R_l : quat.
Hypothesis q_v_2_R_l_nonzero : qn q_v_2_R_l <> 0.
Local Notation v_2_R_l := (rot q_v_2_R_l).

(** k_s: a scalar *)
Variable v_3_k_s : R.
Hypothesis v_3_k_s_pos : 0 < v_3_k_s.


(** Step 1: hat(k_s R̄ vee(sk(R̄ᵀ R_l))) R̄ = k_s R̄ sk(R̄ᵀ R_l)
    (algebra (hat(R v) = R hat(v) Rᵀ)) *)
Theorem step1 : (mmul (hat (mvmul (mscale v_3_k_s v_1_Rbar) (vee (sk (mmul (mT v_1_Rbar) v_2_R_l))))) v_1_Rbar) = (mmul (mscale v_3_k_s v_1_Rbar) (sk (mmul (mT v_1_Rbar) v_2_R_l))).
Proof using q_v_1_Rbar q_v_2_R_l v_3_k_s q_v_1_Rbar_nonzero q_v_2_R_l_nonzero v_3_k_s_pos.
  first [ SOSCert.sos_eq ((qw q_v_1_Rbar) :: (qx q_v_1_Rbar) :: (qy q_v_1_Rbar) :: (qz q_v_1_Rbar) :: (qw q_v_2_R_l) :: (qx q_v_2_R_l) :: (qy q_v_2_R_l) :: (qz q_v_2_R_l) :: v_3_k_s :: nil)%list (0%nat :: 4%nat :: nil)%list | so3_norm_hat; generalize (rot q_v_1_Rbar) as G_v_1_Rbar; intro G_v_1_Rbar; generalize (rot q_v_2_R_l) as G_v_2_R_l; intro G_v_2_R_l; so3_split; so3_poly ].
Qed.

End sec3_rbar_dot_form.

End sec3_rbar_dot_form.

Module lemma1_h_dot.

(** Exported from the derivation 'lemma1.h-dot' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: ḣ = (k_s/2) tr(R_rl - R_rlᵀ R̄_r²) along eq. (13)
    its place in the paper: Lemma 1 proof, eq. (15)
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3 Hierarchy Derive Traj.
Open Scope R_scope.

Section lemma1_h_dot.

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


(** Step 1: tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) = tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l))
    (algebra (h = tr(R̄_r) - 1, R_r constant)) *)
Theorem step1 : (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))) = (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 2: tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) = k_s tr(R_rᵀ R̄ sk(R̄ᵀ R_l))
    (algebra (eq. (13))) *)
Theorem step2 : (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))) = (v_4_k_s * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 3: k_s tr(R_rᵀ R̄ sk(R̄ᵀ R_l)) = k_s tr(R_rᵀ R̄ sk((R_rᵀ R̄)ᵀ R_rᵀ R_l))
    (algebra (R̄ᵀR_l = R̄_rᵀR_rl)) *)
Theorem step3 : (v_4_k_s * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))) = (v_4_k_s * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (sk (mmul (mT (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_3_R_l)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos.
  so3_norm.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** Step 4: k_s tr(R_rᵀ R̄ sk((R_rᵀ R̄)ᵀ R_rᵀ R_l)) = (1/2) k_s tr(R_rᵀ R_l - (R_rᵀ R_l)ᵀ R_rᵀ R̄ R_rᵀ R̄)
    (algebra (cyclic trace)) *)
Theorem step4 : (v_4_k_s * (tr (mmul (mmul (mT v_1_R_r) v_2_Rbar) (sk (mmul (mT (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_3_R_l)))))) = (((1/2) * v_4_k_s) * (tr (madd (mmul (mT v_1_R_r) v_3_R_l) (mneg (mmul (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_2_Rbar)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos.
  so3_norm.
  generalize (rot q_v_1_R_r) as G_v_1_R_r; intro G_v_1_R_r.
  generalize (rot q_v_2_Rbar) as G_v_2_Rbar; intro G_v_2_Rbar.
  generalize (rot q_v_3_R_l) as G_v_3_R_l; intro G_v_3_R_l.
  so3_poly.
Qed.

(** The derivation's claim: tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) = (1/2) k_s tr(R_rᵀ R_l - (R_rᵀ R_l)ᵀ R_rᵀ R̄ R_rᵀ R̄) *)
Theorem claim : (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s v_2_Rbar) (sk (mmul (mT v_2_Rbar) v_3_R_l))))) = (((1/2) * v_4_k_s) * (tr (madd (mmul (mT v_1_R_r) v_3_R_l) (mneg (mmul (mmul (mT (mmul (mT v_1_R_r) v_3_R_l)) (mmul (mT v_1_R_r) v_2_Rbar)) (mmul (mT v_1_R_r) v_2_Rbar)))))).
Proof using q_v_1_R_r q_v_2_Rbar q_v_3_R_l v_4_k_s q_v_1_R_r_nonzero q_v_2_Rbar_nonzero q_v_3_R_l_nonzero v_4_k_s_pos.
  exact (eq_trans (eq_trans (eq_trans step1 step2) step3) step4).
Qed.

End lemma1_h_dot.



Section ddt_trajectories.

(** R_r: constant *)
Variable v_1_R_r : M3.
(** R̄: a trajectory (its derivative at t is a premise when it is differentiated) *)
Variable v_2_Rbar : R -> M3.
(** R_l: its value at t *)
Variable v_3_R_l : M3.
(** k_s: constant *)
Variable v_4_k_s : R.
Variable t : R.

(** The first expression is the derivative: d/dt tr(R_rᵀ R̄) - 1 along the declared dynamics,
    at every t, is tr(R_rᵀ k_s R̄ sk(R̄ᵀ R_l)) *)
Theorem ddt : is_mderiv v_2_Rbar t (mmul (mscale v_4_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) v_3_R_l))) -> is_derive (fun s => ((tr (mmul (mT v_1_R_r) (v_2_Rbar s))) + (- 1))) t (tr (mmul (mT v_1_R_r) (mmul (mscale v_4_k_s (v_2_Rbar t)) (sk (mmul (mT (v_2_Rbar t)) v_3_R_l))))).
Proof.
  intros D1.
  eapply deriv_unique_eq; [ d_mirror | cbv beta; traj_same ].
Qed.

End ddt_trajectories.

End lemma1_h_dot.

Module lemma1_boundary_square.

(** Exported from the derivation 'lemma1.boundary-square' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: on the boundary, R̄_r² = 2ξξᵀ - I
    its place in the paper: Lemma 1 proof, boundary
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section lemma1_boundary_square.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.

(** θ: an angle *)
Variable v_2_theta : R.

(** side condition: boundary h = 0, i.e. cosθ = 0 *)
Hypothesis condition1 : (cos v_2_theta) = 0.


(** Step 1: (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) = I + 2 sin(θ) cos(θ) hat(ξ) + (1 - (cos(θ) cos(θ) - sin(θ) sin(θ))) hat(ξ) hat(ξ)
    (algebra (R̄_r² = exp(2θ ξ^), double-angle formulas)) *)
Theorem step1 : (mmul (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi)))) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))) = (madd (madd I3 (mscale ((2 * (sin v_2_theta)) * (cos v_2_theta)) (hat v_1_xi))) (mscale (1 + (- (((cos v_2_theta) * (cos v_2_theta)) + (- ((sin v_2_theta) * (sin v_2_theta)))))) (mmul (hat v_1_xi) (hat v_1_xi)))).
Proof using v_1_xi v_2_theta v_1_xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) + (v2 v_1_xi) ^ 2 + (v3 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) + (v3 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) + (-1) * (v1 v_1_xi) * (v2 v_1_xi) + (-2) * (v3 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + 2 * (v3 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + (-1) * (v1 v_1_xi) * (v3 v_1_xi) + 2 * (v2 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + (-2) * (v2 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) + (-1) * (v1 v_1_xi) * (v2 v_1_xi) + 2 * (v3 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + (-2) * (v3 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v1 v_1_xi) ^ 2 * (cos v_2_theta) + (v1 v_1_xi) ^ 2 + (v3 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) + (v3 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-2) * (v1 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + 2 * (v1 v_1_xi) * (sin v_2_theta) + (-1) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + (-1) * (v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((-1) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + (-1) * (v1 v_1_xi) * (v3 v_1_xi) + (-2) * (v2 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + 2 * (v2 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ (((2 * (v1 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) + (-2) * (v1 v_1_xi) * (sin v_2_theta) + (-1) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 + 2 * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + (-1) * (v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v1 v_1_xi) ^ 2 * (cos v_2_theta) + (v1 v_1_xi) ^ 2 + (v2 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 + (-2) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) + (v2 v_1_xi) ^ 2) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

(** Step 2: I + 2 sin(θ) cos(θ) hat(ξ) + (1 - (cos(θ) cos(θ) - sin(θ) sin(θ))) hat(ξ) hat(ξ) = I + 2 hat(ξ) hat(ξ)
    (algebra (cosθ = 0)) *)
Theorem step2 : (madd (madd I3 (mscale ((2 * (sin v_2_theta)) * (cos v_2_theta)) (hat v_1_xi))) (mscale (1 + (- (((cos v_2_theta) * (cos v_2_theta)) + (- ((sin v_2_theta) * (sin v_2_theta)))))) (mmul (hat v_1_xi) (hat v_1_xi)))) = (madd I3 (mscale 2 (mmul (hat v_1_xi) (hat v_1_xi)))).
Proof using v_1_xi v_2_theta v_1_xi_unit condition1.
  so3_split.
  - apply (eq_by_sum _ _ ((((-1) * (v2 v_1_xi) ^ 2 + (-1) * (v3 v_1_xi) ^ 2) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + ((2 * (v2 v_1_xi) ^ 2 * (cos v_2_theta) + 2 * (v3 v_1_xi) ^ 2 * (cos v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v2 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) + (-2) * (v3 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + 2 * (v2 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v2 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) + 2 * (v3 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((cos v_2_theta) ^ 2 + (-1) * (sin v_2_theta) ^ 2 + 1) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1) + (((v2 v_1_xi) ^ 2 + (-1)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) + 2 * (cos v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit), (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v1 v_1_xi) * (sin v_2_theta) + (-2) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v1 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) + (-2) * (v2 v_1_xi) * (sin v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((v2 v_1_xi) * (v3 v_1_xi)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + ((2 * (v1 v_1_xi) * (sin v_2_theta) + (-2) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
  - apply (eq_by_sum _ _ ((((cos v_2_theta) ^ 2 + (-1) * (sin v_2_theta) ^ 2 + 1) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1) + (((v3 v_1_xi) ^ 2 + (-1)) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((-2) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) + 2 * (cos v_2_theta)) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit), (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
Qed.

(** Step 3: I + 2 hat(ξ) hat(ξ) = 2 ξ ξᵀ - I
    (algebra (ξ^² = ξξᵀ - I for |ξ| = 1)) *)
Theorem step3 : (madd I3 (mscale 2 (mmul (hat v_1_xi) (hat v_1_xi)))) = (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3)).
Proof using v_1_xi v_2_theta v_1_xi_unit.
  so3_split.
  - apply (eq_by_sum _ _ ((((-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ ((((-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
  - so3_poly.
  - so3_poly.
  - so3_poly.
  - apply (eq_by_sum _ _ ((((-2)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly].
Qed.

(** The derivation's claim: (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) = 2 ξ ξᵀ - I *)
Theorem claim : (mmul (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi)))) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))) = (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3)).
Proof using v_1_xi v_2_theta v_1_xi_unit condition1.
  exact (eq_trans (eq_trans step1 step2) step3).
Qed.

End lemma1_boundary_square.

End lemma1_boundary_square.

Module lemma1_boundary_h_dot.

(** Exported from the derivation 'lemma1.boundary-h-dot' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: on the boundary ḣ = k_s tr{sym(R_rl)(I - ξξᵀ)} ≥ k_s λmin(sym R_rl) tr(I - ξξᵀ) ≥ 0
    its place in the paper: Lemma 1 proof, after eq. (15)
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section lemma1_boundary_h_dot.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.

(** θ: an angle *)
Variable v_2_theta : R.

(** R_rl: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_R_rl : quat.
Hypothesis q_v_3_R_rl_nonzero : qn q_v_3_R_rl <> 0.
Local Notation v_3_R_rl := (rot q_v_3_R_rl).

(** k_s: a scalar *)
Variable v_4_k_s : R.
Hypothesis v_4_k_s_pos : 0 < v_4_k_s.

(** lambda_min(sym(R_rl)) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (sym v_3_R_rl) lam1.

(** side condition: boundary h = 0, i.e. cosθ = 0 *)
Hypothesis condition1 : (cos v_2_theta) = 0.

(** assumption: λmin(sym(R_rl)) > 0 (Assumption 1, item 2) *)
Hypothesis assumption1 : 0 < lam1.


(** Step 1: (1/2) k_s tr(R_rl - R_rlᵀ (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ))) = (1/4) k_s tr(R_rl + R_rlᵀ - R_rl (2 ξ ξᵀ - I) - R_rlᵀ (2 ξ ξᵀ - I))
    (algebra (R̄_r² = 2ξξᵀ - I is symmetric on the boundary)) *)
Theorem step1 : (((1/2) * v_4_k_s) * (tr (madd v_3_R_rl (mneg (mmul (mmul (mT v_3_R_rl) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))))))) = (((1/4) * v_4_k_s) * (tr (madd (madd (madd v_3_R_rl (mT v_3_R_rl)) (mneg (mmul v_3_R_rl (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))) (mneg (mmul (mT v_3_R_rl) (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))))).
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1.
  generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl.
  apply (eq_by_sum _ _ ((((-1/2) * (v1 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) ^ 2 * (cos v_2_theta) * (m22 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) ^ 2 * (cos v_2_theta) * (m33 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) ^ 2 * (m12 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) ^ 2 * (m21 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) * (m12 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) * (m21 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (m12 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (m21 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 * (m13 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 * (m31 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m13 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m31 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (m13 G_v_3_R_rl) * v_4_k_s + (1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (m31 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m23 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m32 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (sin v_2_theta) * (m23 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (sin v_2_theta) * (m32 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) ^ 2 * (cos v_2_theta) * (m11 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) ^ 2 * (cos v_2_theta) * (m33 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 * (m23 G_v_3_R_rl) * v_4_k_s + (1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) ^ 2 * (m32 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m23 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m32 G_v_3_R_rl) * v_4_k_s + (1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (m23 G_v_3_R_rl) * v_4_k_s + (1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (m32 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m13 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m31 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) * (sin v_2_theta) * (m13 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) * (sin v_2_theta) * (m31 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) ^ 2 * (cos v_2_theta) * (m11 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) ^ 2 * (cos v_2_theta) * (m22 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v3 v_1_xi) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v3 v_1_xi) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m12 G_v_3_R_rl) * v_4_k_s + (-1) * (v3 v_1_xi) * (cos v_2_theta) * (sin v_2_theta) * (m21 G_v_3_R_rl) * v_4_k_s + (-1) * (v3 v_1_xi) * (sin v_2_theta) * (m12 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) * (sin v_2_theta) * (m21 G_v_3_R_rl) * v_4_k_s + (-1/2) * (cos v_2_theta) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (-1/2) * (cos v_2_theta) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (1/2) * (sin v_2_theta) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (1/2) * (sin v_2_theta) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (m11 G_v_3_R_rl) * v_4_k_s + (1/2) * (m22 G_v_3_R_rl) * v_4_k_s + (1/2) * (m33 G_v_3_R_rl) * v_4_k_s) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1) + (((-1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (m12 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) * (v2 v_1_xi) * (m21 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (m13 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v1 v_1_xi) * (v3 v_1_xi) * (m31 G_v_3_R_rl) * v_4_k_s + (1/2) * (v2 v_1_xi) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) ^ 2 * (m22 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (m23 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v2 v_1_xi) * (v3 v_1_xi) * (m32 G_v_3_R_rl) * v_4_k_s + (1/2) * (v3 v_1_xi) ^ 2 * (m11 G_v_3_R_rl) * v_4_k_s + (-1/2) * (v3 v_1_xi) ^ 2 * (m33 G_v_3_R_rl) * v_4_k_s + (1/2) * (m22 G_v_3_R_rl) * v_4_k_s + (1/2) * (m33 G_v_3_R_rl) * v_4_k_s) * (1) / (1)) * (cos v_2_theta * cos v_2_theta + sin v_2_theta * sin v_2_theta - 1) + (((v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) * (m12 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (v2 v_1_xi) * (cos v_2_theta) * (m21 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m13 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m31 G_v_3_R_rl) * v_4_k_s + (v1 v_1_xi) * (sin v_2_theta) * (m23 G_v_3_R_rl) * v_4_k_s + (-1) * (v1 v_1_xi) * (sin v_2_theta) * (m32 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) ^ 2 * (cos v_2_theta) * (m11 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) ^ 2 * (cos v_2_theta) * (m22 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m23 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) * (v3 v_1_xi) * (cos v_2_theta) * (m32 G_v_3_R_rl) * v_4_k_s + (-1) * (v2 v_1_xi) * (sin v_2_theta) * (m13 G_v_3_R_rl) * v_4_k_s + (v2 v_1_xi) * (sin v_2_theta) * (m31 G_v_3_R_rl) * v_4_k_s + (-1) * (v3 v_1_xi) ^ 2 * (cos v_2_theta) * (m11 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) ^ 2 * (cos v_2_theta) * (m33 G_v_3_R_rl) * v_4_k_s + (v3 v_1_xi) * (sin v_2_theta) * (m12 G_v_3_R_rl) * v_4_k_s + (-1) * (v3 v_1_xi) * (sin v_2_theta) * (m21 G_v_3_R_rl) * v_4_k_s + (-1) * (cos v_2_theta) * (m22 G_v_3_R_rl) * v_4_k_s + (-1) * (cos v_2_theta) * (m33 G_v_3_R_rl) * v_4_k_s) * (1) / (1)) * ((cos v_2_theta) - 0))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit), (circle v_2_theta), (Rminus_diag_eq _ _ condition1); ring | so3_poly].
Qed.

(** Step 2: (1/4) k_s tr(R_rl + R_rlᵀ - R_rl (2 ξ ξᵀ - I) - R_rlᵀ (2 ξ ξᵀ - I)) = (1/2) k_s tr(sym(R_rl) (I - (2 ξ ξᵀ - I)))
    (algebra (sym(A) = (A + Aᵀ)/2)) *)
Theorem step2 : (((1/4) * v_4_k_s) * (tr (madd (madd (madd v_3_R_rl (mT v_3_R_rl)) (mneg (mmul v_3_R_rl (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))) (mneg (mmul (mT v_3_R_rl) (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))))) = (((1/2) * v_4_k_s) * (tr (mmul (sym v_3_R_rl) (madd I3 (mneg (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))))).
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1.
  generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl.
  so3_poly.
Qed.

(** Step 3: (1/2) k_s tr(sym(R_rl) (I - (2 ξ ξᵀ - I))) = k_s tr(sym(R_rl) (I - ξ ξᵀ))
    (algebra (I - (2ξξᵀ - I) = 2(I - ξξᵀ))) *)
Theorem step3 : (((1/2) * v_4_k_s) * (tr (mmul (sym v_3_R_rl) (madd I3 (mneg (madd (mscale 2 (outer v_1_xi v_1_xi)) (mneg I3))))))) = (v_4_k_s * (tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))).
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1.
  generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl.
  so3_poly.
Qed.

(** Step 4: k_s tr(sym(R_rl) (I - ξ ξᵀ)) >= k_s λmin(sym(R_rl)) tr(I - ξ ξᵀ)
    (trace inequality; premise I - ξξᵀ = hat(ξ)ᵀhat(ξ) ⪰ 0: (k_s > 0 (declared)) * (trace inequality tr(AB) >= lambda_min(A) tr(B), A = sym(R_rl), B = I - ξξᵀ)) *)
Theorem step4 : (v_4_k_s * (tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))) >= ((v_4_k_s * lam1) * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))).
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (P1 : (mT (sym v_3_R_rl)) = (sym v_3_R_rl)).
  { generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd I3 (mneg (outer v_1_xi v_1_xi)))) = (mscale 1 (mmul (mT (hat v_1_xi)) (hat v_1_xi)))).
  { so3_split. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. }
  assert (T2 : 0 <= ((tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))))) + (- (lam1 * (tr (madd I3 (mneg (outer v_1_xi v_1_xi)))))))) by exact (trace_lower_bound (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))) (hat v_1_xi) 1 lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (T3 : 0 <= (v_4_k_s * ((tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))))) + (- (lam1 * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))))))) by exact (Rmult_le_pos _ _ T1 T2).
  assert (E : ((v_4_k_s * (tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))) + (- ((v_4_k_s * lam1) * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))))) = (v_4_k_s * ((tr (mmul (sym v_3_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))))) + (- (lam1 * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))))))).
  { generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl. so3_poly. }
  exact (ge_by_slack _ _ _ E T3).
Qed.

(** Step 5: k_s λmin(sym(R_rl)) tr(I - ξ ξᵀ) >= 0
    (λmin(sym R_rl) > 0 and tr(I - ξξᵀ) = |hat ξ|²: ((k_s > 0 (declared)) * (assumed: λmin(sym(R_rl)) > 0)) * (square of hat(ξ))) *)
Theorem step5 : ((v_4_k_s * lam1) * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))) >= 0.
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1 assumption1.
  assert (T1 : 0 <= v_4_k_s) by exact (Rlt_le _ _ v_4_k_s_pos).
  assert (T2 : 0 <= lam1) by exact (Rlt_le _ _ assumption1).
  assert (T3 : 0 <= (v_4_k_s * lam1)) by exact (Rmult_le_pos _ _ T1 T2).
  assert (T4 : 0 <= (tr (mmul (mT (hat v_1_xi)) (hat v_1_xi)))) by exact (fro2_nonneg (hat v_1_xi)).
  assert (T5 : 0 <= ((v_4_k_s * lam1) * (tr (mmul (mT (hat v_1_xi)) (hat v_1_xi))))) by exact (Rmult_le_pos _ _ T3 T4).
  assert (E : (((v_4_k_s * lam1) * (tr (madd I3 (mneg (outer v_1_xi v_1_xi))))) + (- 0)) = ((v_4_k_s * lam1) * (tr (mmul (mT (hat v_1_xi)) (hat v_1_xi))))).
  { generalize (rot q_v_3_R_rl) as G_v_3_R_rl; intro G_v_3_R_rl. apply (eq_by_sum _ _ ((((-3) * v_4_k_s * lam1) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_poly]. }
  exact (ge_by_slack _ _ _ E T5).
Qed.

(** The derivation's claim: (1/2) k_s tr(R_rl - R_rlᵀ (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ)) (I + sin(θ) hat(ξ) + (1 - cos(θ)) hat(ξ) hat(ξ))) >= 0 *)
Theorem claim : (((1/2) * v_4_k_s) * (tr (madd v_3_R_rl (mneg (mmul (mmul (mT v_3_R_rl) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))) (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi))) (mscale (1 + (- (cos v_2_theta))) (mmul (hat v_1_xi) (hat v_1_xi))))))))) >= 0.
Proof using v_1_xi v_2_theta q_v_3_R_rl v_4_k_s lam1 v_1_xi_unit q_v_3_R_rl_nonzero v_4_k_s_pos lam1_spec condition1 assumption1.
  exact (Rge_trans _ _ _ (eq_ge_trans _ _ _ (eq_trans (eq_trans step1 step2) step3) step4) step5).
Qed.

End lemma1_boundary_h_dot.

End lemma1_boundary_h_dot.

Module lemma1_boundary_sign_direct.

(** Exported from the derivation 'lemma1.boundary-sign-direct' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: the paper's closing argument: sym(R_rl) ≻ 0 and I - ξξᵀ ⪰ 0 give ḣ ≥ 0
    its place in the paper: Lemma 1 proof, last paragraph
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section lemma1_boundary_sign_direct.

(** ξ: a unit vector *)
Variable v_1_xi : V3.
Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1.

(** R_rl: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_R_rl : quat.
Hypothesis q_v_2_R_rl_nonzero : qn q_v_2_R_rl <> 0.
Local Notation v_2_R_rl := (rot q_v_2_R_rl).

(** k_s: a scalar *)
Variable v_3_k_s : R.
Hypothesis v_3_k_s_pos : 0 < v_3_k_s.

(** assumption: sym(R_rl) ≻ 0 (Assumption 1, item 2) *)
Hypothesis assumption1 : pd v_2_R_rl.


(** Step 1: k_s tr(sym(R_rl) (I - ξ ξᵀ)) >= 0
    (tr of a product of PSD matrices: (k_s > 0 (declared)) * (trace of a product of PSD matrices, A = sym(R_rl), B = I - ξξᵀ)) *)
Theorem step1 : (v_3_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))) >= 0.
Proof using v_1_xi q_v_2_R_rl v_3_k_s v_1_xi_unit q_v_2_R_rl_nonzero v_3_k_s_pos assumption1.
  assert (T1 : 0 <= v_3_k_s) by exact (Rlt_le _ _ v_3_k_s_pos).
  assert (P1 : (mT (sym v_2_R_rl)) = (sym v_2_R_rl)).
  { generalize (rot q_v_2_R_rl) as G_v_2_R_rl; intro G_v_2_R_rl. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym v_2_R_rl) = (sym v_2_R_rl)).
  { generalize (rot q_v_2_R_rl) as G_v_2_R_rl; intro G_v_2_R_rl. so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P3 : (sym (madd I3 (mneg (outer v_1_xi v_1_xi)))) = (mscale 1 (mmul (mT (hat v_1_xi)) (hat v_1_xi)))).
  { so3_split. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - so3_unfold; field; so3_nonzero. - apply (eq_by_sum _ _ ((((-1)) * (1) / (1)) * (vdot v_1_xi v_1_xi - 1))); [rewrite (Rminus_diag_eq _ _ v_1_xi_unit); ring | so3_unfold; field; so3_nonzero]. }
  assert (T2 : 0 <= (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))) by exact (trace_pd_product (sym v_2_R_rl) v_2_R_rl (madd I3 (mneg (outer v_1_xi v_1_xi))) (hat v_1_xi) 1 P1 P2 assumption1 P3 ltac:(lra)).
  assert (T3 : 0 <= (v_3_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))))))) by exact (Rmult_le_pos _ _ T1 T2).
  assert (E : ((v_3_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi)))))) + (- 0)) = (v_3_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_1_xi v_1_xi))))))).
  { generalize (rot q_v_2_R_rl) as G_v_2_R_rl; intro G_v_2_R_rl. so3_poly. }
  exact (ge_by_slack _ _ _ E T3).
Qed.

End lemma1_boundary_sign_direct.

End lemma1_boundary_sign_direct.

Module lemma1_gradient_form.

(** Exported from the derivation 'lemma1.gradient-form' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: d/ds h(R̄_r exp(s ω^)) at s = 0 equals <-2 sk(R̄_r)^∨, ω>: the gradient of h on SO(3) is -2 sk(R̄_r)^∨
    its place in the paper: Lemma 1 proof, Nagumo premise
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
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

End lemma1_gradient_form.

Module lemma1_gradient_nonzero.

(** Exported from the derivation 'lemma1.gradient-nonzero' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: |grad h|² = (3 - tr R̄_r)(1 + tr R̄_r) = 4 on the boundary (non-zero)
    its place in the paper: Lemma 1 proof, Nagumo premise
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
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

End lemma1_gradient_nonzero.

Module lemma1_gradient_vanishes_at_pi.

(** Exported from the derivation 'lemma1.gradient-vanishes-at-pi' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: at rotation angle π the gradient on SO(3) is 0 although ∂h/∂R = I there
    its place in the paper: Lemma 1 proof: '∂h/∂R̄_r = I globally' is the ambient gradient
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section lemma1_gradient_vanishes_at_pi.

(** R̄_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_1_Rbar_r : quat.
Hypothesis q_v_1_Rbar_r_nonzero : qn q_v_1_Rbar_r <> 0.
Local Notation v_1_Rbar_r := (rot q_v_1_Rbar_r).

(** side condition: rotation angle π, tr(R̄_r) = -1 *)
Hypothesis condition1 : (tr v_1_Rbar_r) = (-1).


(** Step 1: <(-2) vee(R̄_r), (-2) vee(R̄_r)> = (3 - tr(R̄_r)) (1 + tr(R̄_r))
    (algebra (|sk(R)^∨|² = sin²θ)) *)
Theorem step1 : (vdot (vscale (-2) (vee v_1_Rbar_r)) (vscale (-2) (vee v_1_Rbar_r))) = ((3 + (- (tr v_1_Rbar_r))) * (1 + (tr v_1_Rbar_r))).
Proof using q_v_1_Rbar_r q_v_1_Rbar_r_nonzero.
  so3_unfold; field; so3_nonzero.
Qed.

(** Step 2: (3 - tr(R̄_r)) (1 + tr(R̄_r)) = 0
    (algebra (tr R̄_r = -1)) *)
Theorem step2 : ((3 + (- (tr v_1_Rbar_r))) * (1 + (tr v_1_Rbar_r))) = 0.
Proof using q_v_1_Rbar_r q_v_1_Rbar_r_nonzero condition1.
  apply (eq_by_sum _ _ (((4 * (qx q_v_1_Rbar_r) ^ 2 + 4 * (qy q_v_1_Rbar_r) ^ 2 + 4 * (qz q_v_1_Rbar_r) ^ 2) * ((qn q_v_1_Rbar_r)) / ((qn q_v_1_Rbar_r) ^ 2)) * ((tr v_1_Rbar_r) - (-1)))); [rewrite (Rminus_diag_eq _ _ condition1); ring | so3_unfold; field; so3_nonzero].
Qed.

(** The derivation's claim: <(-2) vee(R̄_r), (-2) vee(R̄_r)> = 0 *)
Theorem claim : (vdot (vscale (-2) (vee v_1_Rbar_r)) (vscale (-2) (vee v_1_Rbar_r))) = 0.
Proof using q_v_1_Rbar_r q_v_1_Rbar_r_nonzero condition1.
  exact (eq_trans step1 step2).
Qed.

End lemma1_gradient_vanishes_at_pi.

End lemma1_gradient_vanishes_at_pi.

Module lemma1_trace_inequality_psd.

(** Exported from the derivation 'lemma1.trace-inequality-psd' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: tr(AB) ≥ λmin(A) tr(B) for A symmetric and B = GᵀG ⪰ 0
    its place in the paper: repair of the quoted inequality
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section lemma1_trace_inequality_psd.

(** A: a symmetric matrix, by its six entries *)
Variables v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23 : R.
Local Notation v_1_A := (symm v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23).

(** G: a matrix *)
Variable v_2_G : M3.

(** lambda_min(A) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec v_1_A lam1.


(** Step 1: tr(A Gᵀ G) >= λmin(A) tr(Gᵀ G)
    (trace inequality tr(AB) >= lambda_min(A) tr(B), A = A, B = GᵀG) *)
Theorem step1 : (tr (mmul v_1_A (mmul (mT v_2_G) v_2_G))) >= (lam1 * (tr (mmul (mT v_2_G) v_2_G))).
Proof using v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23 v_2_G lam1 lam1_spec.
  assert (P1 : (mT v_1_A) = v_1_A).
  { so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (mmul (mT v_2_G) v_2_G)) = (mscale 1 (mmul (mT v_2_G) v_2_G))).
  { so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (T1 : 0 <= ((tr (mmul v_1_A (mmul (mT v_2_G) v_2_G))) + (- (lam1 * (tr (mmul (mT v_2_G) v_2_G)))))) by exact (trace_lower_bound v_1_A (mmul (mT v_2_G) v_2_G) v_2_G 1 lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (E : ((tr (mmul v_1_A (mmul (mT v_2_G) v_2_G))) + (- (lam1 * (tr (mmul (mT v_2_G) v_2_G))))) = ((tr (mmul v_1_A (mmul (mT v_2_G) v_2_G))) + (- (lam1 * (tr (mmul (mT v_2_G) v_2_G)))))).
  { so3_poly. }
  exact (ge_by_slack _ _ _ E T1).
Qed.

End lemma1_trace_inequality_psd.

End lemma1_trace_inequality_psd.

Module lemma1_trace_inequality_sym_psd.

(** Exported from the derivation 'lemma1.trace-inequality-sym-psd' (verify.proof).
    Context only, not theorems of this file:
    the derivation's summary: B need not be symmetric: sym(B) ⪰ 0 suffices (tr(A hat v) = 0)
    its place in the paper: repair of the quoted inequality
    Each theorem below is one step, exactly as the comment above it writes it,
    under the hypotheses its Proof using line names. *)

Import Reals Lra SO3.
Open Scope R_scope.

Section lemma1_trace_inequality_sym_psd.

(** A: a symmetric matrix, by its six entries *)
Variables v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23 : R.
Local Notation v_1_A := (symm v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23).

(** G: a matrix *)
Variable v_2_G : M3.

(** v: a vector *)
Variable v_3_v : V3.

(** lambda_min(A) *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec v_1_A lam1.


(** Step 1: tr(A (Gᵀ G + hat(v))) >= λmin(A) tr(Gᵀ G + hat(v))
    (trace inequality tr(AB) >= lambda_min(A) tr(B), A = A, B = (GᵀG + hat v)) *)
Theorem step1 : (tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) >= (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))).
Proof using v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23 v_2_G v_3_v lam1 lam1_spec.
  assert (P1 : (mT v_1_A) = v_1_A).
  { so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (P2 : (sym (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v))) = (mscale 1 (mmul (mT v_2_G) v_2_G))).
  { so3_split. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. - so3_poly. }
  assert (T1 : 0 <= ((tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) + (- (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v))))))) by exact (trace_lower_bound v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)) v_2_G 1 lam1 P1 P2 ltac:(lra) lam1_spec).
  assert (E : ((tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) + (- (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))))) = ((tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) + (- (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v))))))).
  { so3_poly. }
  exact (ge_by_slack _ _ _ E T1).
Qed.

End lemma1_trace_inequality_sym_psd.

End lemma1_trace_inequality_sym_psd.
