(** SOS certificate sos-5616a1bb41d5db563c57.json, exported to Coq.
    It proves step 4 of the derivation 'lemma1.boundary-h-dot' (verify.paper_proofs): k_s tr(sym(R_rl) (I - ξξᵀ)) >= k_s λmin(sym(R_rl)) tr(I - ξξᵀ).
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by field.
    Charts: a unit vector is stated in its stereographic chart (all but the pole (0, 0, 1)) and an angle by tan(theta/2) (all but pi); the missed points are covered by the Python checker's continuity argument, not by this theorem. *)

From Coq Require Import Reals QArith List Lra.
From VerifyCoq Require Import SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.

Section Sos_lemma1_boundary_h_dot_4.

(** k_s: a scalar *)
Variable v_1_k_s : R.
Hypothesis v_1_k_s_pos : 0 < v_1_k_s.

(** R_rl: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_R_rl : quat.
Hypothesis q_v_2_R_rl_nonzero : qn q_v_2_R_rl <> 0.
Local Notation v_2_R_rl := (rot q_v_2_R_rl).

(** ξ: a unit vector in the stereographic chart (every unit vector but the pole (0, 0, 1)) *)
Variable v_3_xi : V3.
Variables a_v_3_xi b_v_3_xi : R.
Hypothesis v_3_xi_chart : v_3_xi = stereo a_v_3_xi b_v_3_xi.

(** θ: an angle with tan(θ/2) = t_v_4_theta (every angle but pi) *)
Variable v_4_theta : R.
Variable t_v_4_theta : R.
Hypothesis v_4_theta_cos : cos v_4_theta = (1 - t_v_4_theta * t_v_4_theta) / (1 + t_v_4_theta * t_v_4_theta).
Hypothesis v_4_theta_sin : sin v_4_theta = 2 * t_v_4_theta / (1 + t_v_4_theta * t_v_4_theta).

(** lambda_min(sym(R_rl)): a lower bound suffices *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (sym v_2_R_rl) lam1.

Let env : list R := [v_1_k_s; (qw q_v_2_R_rl); (qx q_v_2_R_rl); (qy q_v_2_R_rl); (qz q_v_2_R_rl); a_v_3_xi; b_v_3_xi; t_v_4_theta; lam1].

Definition target : poly := [([1;0;0;0;2;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;2;0;0]%nat, 4%Q); ([1;0;0;0;2;0;2;0;1]%nat, (-4)%Q); ([1;0;0;0;2;0;4;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;4;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;0]%nat, 4%Q); ([1;0;0;0;2;2;0;0;1]%nat, (-4)%Q); ([1;0;0;0;2;2;2;0;0]%nat, (-4)%Q); ([1;0;0;0;2;2;2;0;1]%nat, (-4)%Q); ([1;0;0;0;2;4;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;4;0;0;1]%nat, (-2)%Q); ([1;0;0;1;1;0;1;0;0]%nat, 8%Q); ([1;0;0;1;1;0;3;0;0]%nat, (-8)%Q); ([1;0;0;1;1;2;1;0;0]%nat, (-8)%Q); ([1;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;2;0;0]%nat, (-8)%Q); ([1;0;0;2;0;0;2;0;1]%nat, (-4)%Q); ([1;0;0;2;0;0;4;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;0;0;1]%nat, (-4)%Q); ([1;0;0;2;0;2;2;0;1]%nat, (-4)%Q); ([1;0;0;2;0;4;0;0;1]%nat, (-2)%Q); ([1;0;1;0;1;1;0;0;0]%nat, 8%Q); ([1;0;1;0;1;1;2;0;0]%nat, (-8)%Q); ([1;0;1;0;1;3;0;0;0]%nat, (-8)%Q); ([1;0;1;1;0;1;1;0;0]%nat, (-16)%Q); ([1;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;2;0;1]%nat, (-4)%Q); ([1;0;2;0;0;0;4;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;0;0;0]%nat, (-8)%Q); ([1;0;2;0;0;2;0;0;1]%nat, (-4)%Q); ([1;0;2;0;0;2;2;0;1]%nat, (-4)%Q); ([1;0;2;0;0;4;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;2;0;0]%nat, 4%Q); ([1;2;0;0;0;0;2;0;1]%nat, (-4)%Q); ([1;2;0;0;0;0;4;0;0]%nat, 2%Q); ([1;2;0;0;0;0;4;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;0;0;0]%nat, 4%Q); ([1;2;0;0;0;2;0;0;1]%nat, (-4)%Q); ([1;2;0;0;0;2;2;0;0]%nat, 4%Q); ([1;2;0;0;0;2;2;0;1]%nat, (-4)%Q); ([1;2;0;0;0;4;0;0;0]%nat, 2%Q); ([1;2;0;0;0;4;0;0;1]%nat, (-2)%Q)].

(** block 1: k_s > 0 (declared) *)
Definition H1 : list (list poly) := [[[([1;0;0;0;0;0;0;0;0]%nat, 1%Q)]]].
Definition S1 : list (Q * list poly) :=
  [].

Lemma H1_psd : mult_psd env H1.
Proof.
  unfold H1. apply mult_psd_scalar.
  rewrite zeval_peval by (vm_compute; reflexivity).
  match goal with |- 0 <= ?g => replace g with v_1_k_s by (cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]; rewrite ?v_3_xi_chart; unfold stereo; rewrite ?v_4_theta_cos, ?v_4_theta_sin; so3_unfold; field; sos_nonzero) end.
  exact (Rlt_le _ _ v_1_k_s_pos).
Qed.

(** block 2: k_s > 0 (declared) × spectral: λmin(sym(R_rl)) I ⪯ sym(R_rl) (symmetric) *)
Definition H2 : list (list poly) := [[[([1;0;0;0;2;0;0;0;0]%nat, (-1)%Q); ([1;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;0]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;0;0]%nat, 1%Q); ([1;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;0;0]%nat, 1%Q); ([1;2;0;0;0;0;0;0;1]%nat, (-1)%Q)]; [([1;0;1;1;0;0;0;0;0]%nat, 2%Q)]; [([1;0;1;0;1;0;0;0;0]%nat, 2%Q)]]; [[([1;0;1;1;0;0;0;0;0]%nat, 2%Q)]; [([1;0;0;0;2;0;0;0;0]%nat, (-1)%Q); ([1;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;0]%nat, 1%Q); ([1;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;0;0]%nat, (-1)%Q); ([1;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;0;0]%nat, 1%Q); ([1;2;0;0;0;0;0;0;1]%nat, (-1)%Q)]; [([1;0;0;1;1;0;0;0;0]%nat, 2%Q)]]; [[([1;0;1;0;1;0;0;0;0]%nat, 2%Q)]; [([1;0;0;1;1;0;0;0;0]%nat, 2%Q)]; [([1;0;0;0;2;0;0;0;0]%nat, 1%Q); ([1;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;0]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;0;0]%nat, (-1)%Q); ([1;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;0;0]%nat, 1%Q); ([1;2;0;0;0;0;0;0;1]%nat, (-1)%Q)]]].
Definition S2 : list (Q * list poly) :=
  [(1%Q, [[([0;0;0;0;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;2;0;0;0]%nat, (-1)%Q)]; [([0;0;0;0;0;1;1;0;0]%nat, (-1)%Q)]; [([0;0;0;0;0;1;0;0;0]%nat, 2%Q)]]);
   (1%Q, [[([0;0;0;0;0;1;1;0;0]%nat, (-1)%Q)]; [([0;0;0;0;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;2;0;0]%nat, (-1)%Q)]; [([0;0;0;0;0;0;1;0;0]%nat, 2%Q)]]);
   (2%Q, [[([0;0;0;0;0;0;1;0;0]%nat, 1%Q)]; [([0;0;0;0;0;1;0;0;0]%nat, (-1)%Q)]; []]);
   (1%Q, [[([0;0;0;0;0;0;2;0;0]%nat, 1%Q)]; [([0;0;0;0;0;1;1;0;0]%nat, (-1)%Q)]; []]);
   (1%Q, [[([0;0;0;0;0;1;1;0;0]%nat, 1%Q)]; [([0;0;0;0;0;2;0;0;0]%nat, (-1)%Q)]; []])].

Lemma H2_psd : mult_psd env H2.
Proof.
  apply (mult_psd_3 env H2 (v_1_k_s * (qn q_v_2_R_rl) ^ 1) (fun x1 x2 x3 => qform (msub (sym (sym v_2_R_rl)) (mscale lam1 I3)) (mkV x1 x2 x3))).
  - reflexivity.
  - exact (Rmult_le_pos _ _ (Rlt_le _ _ v_1_k_s_pos) (Rlt_le _ _ (pow_lt _ 1 (qn_pos q_v_2_R_rl q_v_2_R_rl_nonzero)))).
  - intros x1 x2 x3. exact (lam1_spec (mkV x1 x2 x3)).
  - intros x1 x2 x3. rewrite (evalM_Z env H2 (eq_refl true <: all_int_matrix H2 = true)). unfold H2. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. rewrite ?v_3_xi_chart; unfold stereo; rewrite ?v_4_theta_cos, ?v_4_theta_sin; so3_unfold. field; sos_nonzero.
Qed.

Definition blocks : list block := [(mkBlock H1 S1); (mkBlock H2 S2)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_compute. reflexivity. Qed.

Lemma grounds : blocks_psd env blocks.
Proof. exact (blocks_psd_cons env (mkBlock H1 S1) _ H1_psd (blocks_psd_cons env (mkBlock H2 S2) _ H2_psd (blocks_psd_nil env))). Qed.

(** The link: the slack of the statement times ((1 + a_v_3_xi * a_v_3_xi + b_v_3_xi * b_v_3_xi) ^ 2 * (qn q_v_2_R_rl) ^ 1) is the target polynomial at the parameters (times the factors divided out of it), by field. *)
Lemma link : exists D F, 0 < D /\ 0 <= F /\ ((v_1_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_3_xi v_3_xi)))))) + - ((v_1_k_s * lam1) * (tr (madd I3 (mneg (outer v_3_xi v_3_xi)))))) * D = F * peval env target.
Proof.
  exists ((1 + a_v_3_xi * a_v_3_xi + b_v_3_xi * b_v_3_xi) ^ 2 * (qn q_v_2_R_rl) ^ 1), 1. split; [exact (Rmult_lt_0_compat _ _ (pow_lt _ 2 (chart_den_pos a_v_3_xi b_v_3_xi)) (pow_lt _ 1 (qn_pos q_v_2_R_rl q_v_2_R_rl_nonzero)))|]. split; [exact Rle_0_1|].
  rewrite (zeval_peval env target (eq_refl true <: all_int target = true)).
  unfold target. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. rewrite ?v_3_xi_chart; unfold stereo; rewrite ?v_4_theta_cos, ?v_4_theta_sin; so3_unfold. field; sos_nonzero.
Qed.

Theorem step4_by_sos : (v_1_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_3_xi v_3_xi)))))) >= ((v_1_k_s * lam1) * (tr (madd I3 (mneg (outer v_3_xi v_3_xi))))).
Proof.
  apply (ge_by_slack _ _ ((v_1_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_3_xi v_3_xi)))))) + - ((v_1_k_s * lam1) * (tr (madd I3 (mneg (outer v_3_xi v_3_xi))))))); [reflexivity|].
  destruct link as (D & F & HD & HF & E).
  exact (slack_nonneg _ D F _ E HD HF (sos_nonneg env target blocks cert_checked grounds)).
Qed.

End Sos_lemma1_boundary_h_dot_4.
