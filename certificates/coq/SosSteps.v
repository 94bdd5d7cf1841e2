(** 8 units in one file, each a module of its own name: sos_lemma1_boundary_h_dot_step4,
    sos_lemma1_boundary_h_dot_step5, sos_lemma1_boundary_sign_direct_step1,
    sos_lemma1_trace_inequality_psd_step1, sos_lemma1_trace_inequality_sym_psd_step1,
    sos_thm1_S_r_dot_step7, sos_thm1_S_rl_dot_step4, sos_thm1_V_dot_step3. The libraries
    are loaded once, below; each module imports those its unit uses. *)

From Coq Require Reals QArith List Lra.
From VerifyCoq Require SO3 SOSCert.

Module sos_lemma1_boundary_h_dot_step4.

(** SOS certificate sos-5616a1bb41d5db563c57.json, exported to Coq.
    It proves step 4 of the derivation 'lemma1.boundary-h-dot' (verify.paper_proofs): k_s tr(sym(R_rl) (I - ξξᵀ)) >= k_s λmin(sym(R_rl)) tr(I - ξξᵀ).
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by field.
    Charts: a unit vector is stated in its stereographic chart (all but the pole (0, 0, 1)) and an angle by tan(theta/2) (all but pi); the missed points are covered by the Python checker's continuity argument, not by this theorem. *)

Import Reals QArith List Lra SO3 SOSCert.
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
  apply (mult_psd_3 env H2 (v_1_k_s * ((qn q_v_2_R_rl) ^ 1)) (fun x1 x2 x3 => qform (msub (sym (sym v_2_R_rl)) (mscale lam1 I3)) (mkV x1 x2 x3))).
  - reflexivity.
  - exact (Rmult_le_pos _ _ (Rlt_le _ _ v_1_k_s_pos) (Rlt_le _ _ (pow_lt _ 1 (qn_pos q_v_2_R_rl q_v_2_R_rl_nonzero)))).
  - intros x1 x2 x3. exact (lam1_spec (mkV x1 x2 x3)).
  - intros x1 x2 x3. rewrite (evalM_Z env H2 (eq_refl true <: all_int_matrix H2 = true)). unfold H2. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. rewrite ?v_3_xi_chart; unfold stereo; rewrite ?v_4_theta_cos, ?v_4_theta_sin; so3_unfold. field; sos_nonzero.
Qed.

Definition blocks : list block := [(mkBlock H1 S1); (mkBlock H2 S2)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_cast_no_check (eq_refl true). Qed.

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

End sos_lemma1_boundary_h_dot_step4.

Module sos_lemma1_boundary_h_dot_step5.

(** SOS certificate sos-ca4209e02297c7d04166.json, exported to Coq.
    It proves step 5 of the derivation 'lemma1.boundary-h-dot' (verify.paper_proofs): k_s λmin(sym(R_rl)) tr(I - ξξᵀ) >= 0.
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by field.
    Charts: a unit vector is stated in its stereographic chart (all but the pole (0, 0, 1)) and an angle by tan(theta/2) (all but pi); the missed points are covered by the Python checker's continuity argument, not by this theorem. *)

Import Reals QArith List Lra SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.

Section Sos_lemma1_boundary_h_dot_5.

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

(** assumption: λmin(sym(R_rl)) > 0 (Assumption 1, item 2) *)
Hypothesis assumption1 : 0 < lam1.

Let env : list R := [v_1_k_s; (qw q_v_2_R_rl); (qx q_v_2_R_rl); (qy q_v_2_R_rl); (qz q_v_2_R_rl); a_v_3_xi; b_v_3_xi; t_v_4_theta; lam1].

Definition target : poly := [([1;0;0;0;0;0;0;0;1]%nat, 2%Q)].

(** block 1: k_s > 0 (declared) × assumed: λmin(sym(R_rl)) > 0 *)
Definition H1 : list (list poly) := [[[([1;0;0;0;0;0;0;0;1]%nat, 1%Q)]]].
Definition S1 : list (Q * list poly) :=
  [(2%Q, [[([0;0;0;0;0;0;0;0;0]%nat, 1%Q)]])].

Lemma H1_psd : mult_psd env H1.
Proof.
  unfold H1. apply mult_psd_scalar.
  rewrite zeval_peval by (vm_compute; reflexivity).
  match goal with |- 0 <= ?g => replace g with (v_1_k_s * lam1) by (cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]; rewrite ?v_3_xi_chart; unfold stereo; rewrite ?v_4_theta_cos, ?v_4_theta_sin; so3_unfold; field; sos_nonzero) end.
  exact (Rmult_le_pos _ _ (Rlt_le _ _ v_1_k_s_pos) (Rlt_le _ _ assumption1)).
Qed.

Definition blocks : list block := [(mkBlock H1 S1)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_cast_no_check (eq_refl true). Qed.

Lemma grounds : blocks_psd env blocks.
Proof. exact (blocks_psd_cons env (mkBlock H1 S1) _ H1_psd (blocks_psd_nil env)). Qed.

(** The link: the slack of the statement times 1 is the target polynomial at the parameters (times the factors divided out of it), by field. *)
Lemma link : exists D F, 0 < D /\ 0 <= F /\ (((v_1_k_s * lam1) * (tr (madd I3 (mneg (outer v_3_xi v_3_xi))))) + - 0) * D = F * peval env target.
Proof.
  exists 1, 1. split; [exact Rlt_0_1|]. split; [exact Rle_0_1|].
  rewrite (zeval_peval env target (eq_refl true <: all_int target = true)).
  unfold target. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. rewrite ?v_3_xi_chart; unfold stereo; rewrite ?v_4_theta_cos, ?v_4_theta_sin; so3_unfold. field; sos_nonzero.
Qed.

Theorem step5_by_sos : ((v_1_k_s * lam1) * (tr (madd I3 (mneg (outer v_3_xi v_3_xi))))) >= 0.
Proof.
  apply (ge_by_slack _ _ (((v_1_k_s * lam1) * (tr (madd I3 (mneg (outer v_3_xi v_3_xi))))) + - 0)); [reflexivity|].
  destruct link as (D & F & HD & HF & E).
  exact (slack_nonneg _ D F _ E HD HF (sos_nonneg env target blocks cert_checked grounds)).
Qed.

End Sos_lemma1_boundary_h_dot_5.

End sos_lemma1_boundary_h_dot_step5.

Module sos_lemma1_boundary_sign_direct_step1.

(** SOS certificate sos-0d7a67545a4e02ce9d38.json, exported to Coq.
    It proves step 1 of the derivation 'lemma1.boundary-sign-direct' (verify.paper_proofs): k_s tr(sym(R_rl) (I - ξξᵀ)) >= 0.
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by field.
    Charts: a unit vector is stated in its stereographic chart (all but the pole (0, 0, 1)) and an angle by tan(theta/2) (all but pi); the missed points are covered by the Python checker's continuity argument, not by this theorem. *)

Import Reals QArith List Lra SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.

Section Sos_lemma1_boundary_sign_direct_1.

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

(** assumption: sym(R_rl) ≻ 0 (Assumption 1, item 2) *)
Hypothesis assumption1 : pd v_2_R_rl.

Let env : list R := [v_1_k_s; (qw q_v_2_R_rl); (qx q_v_2_R_rl); (qy q_v_2_R_rl); (qz q_v_2_R_rl); a_v_3_xi; b_v_3_xi].

Definition target : poly := [([1;0;0;0;2;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;2]%nat, 4%Q); ([1;0;0;0;2;0;4]%nat, (-2)%Q); ([1;0;0;0;2;2;0]%nat, 4%Q); ([1;0;0;0;2;2;2]%nat, (-4)%Q); ([1;0;0;0;2;4;0]%nat, (-2)%Q); ([1;0;0;1;1;0;1]%nat, 8%Q); ([1;0;0;1;1;0;3]%nat, (-8)%Q); ([1;0;0;1;1;2;1]%nat, (-8)%Q); ([1;0;0;2;0;0;2]%nat, (-8)%Q); ([1;0;1;0;1;1;0]%nat, 8%Q); ([1;0;1;0;1;1;2]%nat, (-8)%Q); ([1;0;1;0;1;3;0]%nat, (-8)%Q); ([1;0;1;1;0;1;1]%nat, (-16)%Q); ([1;0;2;0;0;2;0]%nat, (-8)%Q); ([1;2;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;0;2]%nat, 4%Q); ([1;2;0;0;0;0;4]%nat, 2%Q); ([1;2;0;0;0;2;0]%nat, 4%Q); ([1;2;0;0;0;2;2]%nat, 4%Q); ([1;2;0;0;0;4;0]%nat, 2%Q)].

(** block 1: k_s > 0 (declared) × assumed: sym(R_rl) ≻ 0 *)
Definition H1 : list (list poly) := [[[([1;0;0;0;2;0;0]%nat, (-1)%Q); ([1;0;0;2;0;0;0]%nat, (-1)%Q); ([1;0;2;0;0;0;0]%nat, 1%Q); ([1;2;0;0;0;0;0]%nat, 1%Q)]; [([1;0;1;1;0;0;0]%nat, 2%Q)]; [([1;0;1;0;1;0;0]%nat, 2%Q)]]; [[([1;0;1;1;0;0;0]%nat, 2%Q)]; [([1;0;0;0;2;0;0]%nat, (-1)%Q); ([1;0;0;2;0;0;0]%nat, 1%Q); ([1;0;2;0;0;0;0]%nat, (-1)%Q); ([1;2;0;0;0;0;0]%nat, 1%Q)]; [([1;0;0;1;1;0;0]%nat, 2%Q)]]; [[([1;0;1;0;1;0;0]%nat, 2%Q)]; [([1;0;0;1;1;0;0]%nat, 2%Q)]; [([1;0;0;0;2;0;0]%nat, 1%Q); ([1;0;0;2;0;0;0]%nat, (-1)%Q); ([1;0;2;0;0;0;0]%nat, (-1)%Q); ([1;2;0;0;0;0;0]%nat, 1%Q)]]].
Definition S1 : list (Q * list poly) :=
  [(1%Q, [[([0;0;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;2]%nat, (-2#7)%Q); ([0;0;0;0;0;2;0]%nat, (-1)%Q)]; [([0;0;0;0;0;1;1]%nat, (-5#7)%Q)]; [([0;0;0;0;0;1;0]%nat, 2%Q)]]);
   (1%Q, [[([0;0;0;0;0;1;1]%nat, (-5#7)%Q)]; [([0;0;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;2]%nat, (-1)%Q); ([0;0;0;0;0;2;0]%nat, (-2#7)%Q)]; [([0;0;0;0;0;0;1]%nat, 2%Q)]]);
   ((18#7)%Q, [[([0;0;0;0;0;0;1]%nat, 1%Q)]; [([0;0;0;0;0;1;0]%nat, (-1)%Q)]; []]);
   ((45#49)%Q, [[([0;0;0;0;0;0;2]%nat, 1%Q)]; [([0;0;0;0;0;1;1]%nat, (-1)%Q)]; []]);
   ((45#49)%Q, [[([0;0;0;0;0;1;1]%nat, 1%Q)]; [([0;0;0;0;0;2;0]%nat, (-1)%Q)]; []])].

Lemma H1_psd : mult_psd env H1.
Proof.
  apply (mult_psd_3 env H1 (v_1_k_s * ((qn q_v_2_R_rl) ^ 1)) (fun x1 x2 x3 => qform (sym v_2_R_rl) (mkV x1 x2 x3))).
  - reflexivity.
  - exact (Rmult_le_pos _ _ (Rlt_le _ _ v_1_k_s_pos) (Rlt_le _ _ (pow_lt _ 1 (qn_pos q_v_2_R_rl q_v_2_R_rl_nonzero)))).
  - intros x1 x2 x3. exact ((pd_psd _ assumption1) (mkV x1 x2 x3)).
  - intros x1 x2 x3. rewrite (evalM_Z env H1 (eq_refl true <: all_int_matrix H1 = true)). unfold H1. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. rewrite ?v_3_xi_chart; unfold stereo; so3_unfold. field; sos_nonzero.
Qed.

Definition blocks : list block := [(mkBlock H1 S1)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_cast_no_check (eq_refl true). Qed.

Lemma grounds : blocks_psd env blocks.
Proof. exact (blocks_psd_cons env (mkBlock H1 S1) _ H1_psd (blocks_psd_nil env)). Qed.

(** The link: the slack of the statement times ((1 + a_v_3_xi * a_v_3_xi + b_v_3_xi * b_v_3_xi) ^ 2 * (qn q_v_2_R_rl) ^ 1) is the target polynomial at the parameters (times the factors divided out of it), by field. *)
Lemma link : exists D F, 0 < D /\ 0 <= F /\ ((v_1_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_3_xi v_3_xi)))))) + - 0) * D = F * peval env target.
Proof.
  exists ((1 + a_v_3_xi * a_v_3_xi + b_v_3_xi * b_v_3_xi) ^ 2 * (qn q_v_2_R_rl) ^ 1), 1. split; [exact (Rmult_lt_0_compat _ _ (pow_lt _ 2 (chart_den_pos a_v_3_xi b_v_3_xi)) (pow_lt _ 1 (qn_pos q_v_2_R_rl q_v_2_R_rl_nonzero)))|]. split; [exact Rle_0_1|].
  rewrite (zeval_peval env target (eq_refl true <: all_int target = true)).
  unfold target. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. rewrite ?v_3_xi_chart; unfold stereo; so3_unfold. field; sos_nonzero.
Qed.

Theorem step1_by_sos : (v_1_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_3_xi v_3_xi)))))) >= 0.
Proof.
  apply (ge_by_slack _ _ ((v_1_k_s * (tr (mmul (sym v_2_R_rl) (madd I3 (mneg (outer v_3_xi v_3_xi)))))) + - 0)); [reflexivity|].
  destruct link as (D & F & HD & HF & E).
  exact (slack_nonneg _ D F _ E HD HF (sos_nonneg env target blocks cert_checked grounds)).
Qed.

End Sos_lemma1_boundary_sign_direct_1.

End sos_lemma1_boundary_sign_direct_step1.

Module sos_lemma1_trace_inequality_psd_step1.

(** SOS certificate sos-8b9cbb93bcaa05da0231.json, exported to Coq.
    It proves step 1 of the derivation 'lemma1.trace-inequality-psd' (verify.paper_proofs): tr(A GᵀG) >= λmin(A) tr(GᵀG).
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by field. *)

Import Reals QArith List Lra SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.

Section Sos_lemma1_trace_inequality_psd_1.

(** A: a symmetric matrix, by its six entries *)
Variables v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23 : R.
Local Notation v_1_A := (symm v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23).

(** G: a matrix *)
Variable v_2_G : M3.

(** lambda_min(A): a lower bound suffices *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec v_1_A lam1.

Let env : list R := [v_1_A_11; v_1_A_22; v_1_A_33; v_1_A_12; v_1_A_13; v_1_A_23; (m11 v_2_G); (m12 v_2_G); (m13 v_2_G); (m21 v_2_G); (m22 v_2_G); (m23 v_2_G); (m31 v_2_G); (m32 v_2_G); (m33 v_2_G); lam1].

Definition target : poly := [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;2;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;0;0;0;2;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;0;0;2;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;0;1;1;0]%nat, 2%Q); ([0;0;0;0;0;1;0;0;0;0;1;1;0;0;0;0]%nat, 2%Q); ([0;0;0;0;0;1;0;1;1;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;0;0;1;0;0;0;0;0;0;0;1;0;1;0]%nat, 2%Q); ([0;0;0;0;1;0;0;0;0;1;0;1;0;0;0;0]%nat, 2%Q); ([0;0;0;0;1;0;1;0;1;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;0;1;0;0;0;0;0;0;0;0;1;1;0;0]%nat, 2%Q); ([0;0;0;1;0;0;0;0;0;1;1;0;0;0;0;0]%nat, 2%Q); ([0;0;0;1;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;1;0;0;0;0;0;0;0;0;0;0;0;2;0]%nat, 1%Q); ([0;0;1;0;0;0;0;0;0;0;0;2;0;0;0;0]%nat, 1%Q); ([0;0;1;0;0;0;0;0;2;0;0;0;0;0;0;0]%nat, 1%Q); ([0;1;0;0;0;0;0;0;0;0;0;0;0;2;0;0]%nat, 1%Q); ([0;1;0;0;0;0;0;0;0;0;2;0;0;0;0;0]%nat, 1%Q); ([0;1;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 1%Q); ([1;0;0;0;0;0;0;0;0;0;0;0;2;0;0;0]%nat, 1%Q); ([1;0;0;0;0;0;0;0;0;2;0;0;0;0;0;0]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 1%Q)].

(** block 1: spectral: λmin(A) I ⪯ A (symmetric) *)
Definition H1 : list (list poly) := [[[([0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;1;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]]; [[([0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;1;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;1;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]]; [[([0;0;0;0;1;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;1;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;1;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]]].
Definition S1 : list (Q * list poly) :=
  [(1%Q, [[([0;0;0;0;0;0;0;0;0;0;0;0;1;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;1;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;1;0]%nat, 1%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;0;1;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;1;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;1;0;0;0;0]%nat, 1%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;1;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;1;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;1;0;0;0;0;0;0;0]%nat, 1%Q)]])].

Lemma H1_psd : mult_psd env H1.
Proof.
  apply (mult_psd_3 env H1 (1 * 1) (fun x1 x2 x3 => qform (msub (sym v_1_A) (mscale lam1 I3)) (mkV x1 x2 x3))).
  - reflexivity.
  - exact (Rmult_le_pos _ _ Rle_0_1 Rle_0_1).
  - intros x1 x2 x3. exact (lam1_spec (mkV x1 x2 x3)).
  - intros x1 x2 x3. rewrite (evalM_Z env H1 (eq_refl true <: all_int_matrix H1 = true)). unfold H1. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. so3_unfold. lra.
Qed.

Definition blocks : list block := [(mkBlock H1 S1)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_cast_no_check (eq_refl true). Qed.

Lemma grounds : blocks_psd env blocks.
Proof. exact (blocks_psd_cons env (mkBlock H1 S1) _ H1_psd (blocks_psd_nil env)). Qed.

(** The link: the slack of the statement times 1 is the target polynomial at the parameters (times the factors divided out of it), by field. *)
Lemma link : exists D F, 0 < D /\ 0 <= F /\ ((tr (mmul v_1_A (mmul (mT v_2_G) v_2_G))) + - (lam1 * (tr (mmul (mT v_2_G) v_2_G)))) * D = F * peval env target.
Proof.
  exists 1, 1. split; [exact Rlt_0_1|]. split; [exact Rle_0_1|].
  rewrite (zeval_peval env target (eq_refl true <: all_int target = true)).
  unfold target. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. so3_unfold. lra.
Qed.

Theorem step1_by_sos : (tr (mmul v_1_A (mmul (mT v_2_G) v_2_G))) >= (lam1 * (tr (mmul (mT v_2_G) v_2_G))).
Proof.
  apply (ge_by_slack _ _ ((tr (mmul v_1_A (mmul (mT v_2_G) v_2_G))) + - (lam1 * (tr (mmul (mT v_2_G) v_2_G))))); [reflexivity|].
  destruct link as (D & F & HD & HF & E).
  exact (slack_nonneg _ D F _ E HD HF (sos_nonneg env target blocks cert_checked grounds)).
Qed.

End Sos_lemma1_trace_inequality_psd_1.

End sos_lemma1_trace_inequality_psd_step1.

Module sos_lemma1_trace_inequality_sym_psd_step1.

(** SOS certificate sos-c8496f0d25f1949d1f31.json, exported to Coq.
    It proves step 1 of the derivation 'lemma1.trace-inequality-sym-psd' (verify.paper_proofs): tr(A (GᵀG + hat v)) >= λmin(A) tr((GᵀG + hat v)).
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by field. *)

Import Reals QArith List Lra SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.

Section Sos_lemma1_trace_inequality_sym_psd_1.

(** A: a symmetric matrix, by its six entries *)
Variables v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23 : R.
Local Notation v_1_A := (symm v_1_A_11 v_1_A_22 v_1_A_33 v_1_A_12 v_1_A_13 v_1_A_23).

(** G: a matrix *)
Variable v_2_G : M3.

(** v: a vector *)
Variable v_3_v : V3.

(** lambda_min(A): a lower bound suffices *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec v_1_A lam1.

Let env : list R := [v_1_A_11; v_1_A_22; v_1_A_33; v_1_A_12; v_1_A_13; v_1_A_23; (m11 v_2_G); (m12 v_2_G); (m13 v_2_G); (m21 v_2_G); (m22 v_2_G); (m23 v_2_G); (m31 v_2_G); (m32 v_2_G); (m33 v_2_G); (v1 v_3_v); (v2 v_3_v); (v3 v_3_v); lam1].

Definition target : poly := [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;0;1;1;0;0;0;0]%nat, 2%Q); ([0;0;0;0;0;1;0;0;0;0;1;1;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;0;0;0;1;0;1;1;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;0;0;1;0;0;0;0;0;0;0;1;0;1;0;0;0;0]%nat, 2%Q); ([0;0;0;0;1;0;0;0;0;1;0;1;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;0;0;1;0;1;0;1;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;0;1;0;0;0;0;0;0;0;0;1;1;0;0;0;0;0]%nat, 2%Q); ([0;0;0;1;0;0;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;0;1;0;0;1;1;0;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([0;0;1;0;0;0;0;0;0;0;0;0;0;0;2;0;0;0;0]%nat, 1%Q); ([0;0;1;0;0;0;0;0;0;0;0;2;0;0;0;0;0;0;0]%nat, 1%Q); ([0;0;1;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q); ([0;1;0;0;0;0;0;0;0;0;0;0;0;2;0;0;0;0;0]%nat, 1%Q); ([0;1;0;0;0;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 1%Q); ([0;1;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q); ([1;0;0;0;0;0;0;0;0;0;0;0;2;0;0;0;0;0;0]%nat, 1%Q); ([1;0;0;0;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)].

(** block 1: spectral: λmin(A) I ⪯ A (symmetric) *)
Definition H1 : list (list poly) := [[[([0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]]; [[([0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;1;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]]; [[([0;0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([0;0;1;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]]].
Definition S1 : list (Q * list poly) :=
  [(1%Q, [[([0;0;0;0;0;0;0;0;0;0;0;0;1;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;1;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;0;0;0;1;0;0;0;0]%nat, 1%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;0;1;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;1;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;0;0;0;1;0;0;0;0;0;0;0]%nat, 1%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;1;0;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;1;0;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;1;0;0;0;0;0;0;0;0;0;0]%nat, 1%Q)]])].

Lemma H1_psd : mult_psd env H1.
Proof.
  apply (mult_psd_3 env H1 (1 * 1) (fun x1 x2 x3 => qform (msub (sym v_1_A) (mscale lam1 I3)) (mkV x1 x2 x3))).
  - reflexivity.
  - exact (Rmult_le_pos _ _ Rle_0_1 Rle_0_1).
  - intros x1 x2 x3. exact (lam1_spec (mkV x1 x2 x3)).
  - intros x1 x2 x3. rewrite (evalM_Z env H1 (eq_refl true <: all_int_matrix H1 = true)). unfold H1. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. so3_unfold. lra.
Qed.

Definition blocks : list block := [(mkBlock H1 S1)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_cast_no_check (eq_refl true). Qed.

Lemma grounds : blocks_psd env blocks.
Proof. exact (blocks_psd_cons env (mkBlock H1 S1) _ H1_psd (blocks_psd_nil env)). Qed.

(** The link: the slack of the statement times 1 is the target polynomial at the parameters (times the factors divided out of it), by field. *)
Lemma link : exists D F, 0 < D /\ 0 <= F /\ ((tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) + - (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v))))) * D = F * peval env target.
Proof.
  exists 1, 1. split; [exact Rlt_0_1|]. split; [exact Rle_0_1|].
  rewrite (zeval_peval env target (eq_refl true <: all_int target = true)).
  unfold target. cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]. so3_unfold. lra.
Qed.

Theorem step1_by_sos : (tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) >= (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))).
Proof.
  apply (ge_by_slack _ _ ((tr (mmul v_1_A (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))) + - (lam1 * (tr (madd (mmul (mT v_2_G) v_2_G) (hat v_3_v)))))); [reflexivity|].
  destruct link as (D & F & HD & HF & E).
  exact (slack_nonneg _ D F _ E HD HF (sos_nonneg env target blocks cert_checked grounds)).
Qed.

End Sos_lemma1_trace_inequality_sym_psd_1.

End sos_lemma1_trace_inequality_sym_psd_step1.

Module sos_thm1_S_r_dot_step7.

(** SOS certificate sos-217401dc738227942628.json, exported to Coq.
    It proves step 7 of the derivation 'thm1.S_r-dot' (verify.paper_proofs): (-1/4) k_s tr((R̄_r + R̄_rᵀ) (I - R̄ᵀ R_l)) - (1/2) k_s tr(I - R̄_r) + (1/2) k_s tr(I - R_rl) <= (-1/2) k_s λmin((R̄_r + R̄_rᵀ)) φ(R̄ᵀ R_l) - k_s φ(R̄_r) + k_s φ(R_rl).
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by computation (SOSCert.mult_psd_9r, SOSCert.link_ok). *)

Import Reals QArith List Lra SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.

Section Sos_thm1_S_r_dot_7.

(** k_s: a scalar *)
Variable v_1_k_s : R.
Hypothesis v_1_k_s_pos : 0 < v_1_k_s.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_R_r : quat.
Hypothesis q_v_2_R_r_nonzero : qn q_v_2_R_r <> 0.
Local Notation v_2_R_r := (rot q_v_2_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_Rbar : quat.
Hypothesis q_v_3_Rbar_nonzero : qn q_v_3_Rbar <> 0.
Local Notation v_3_Rbar := (rot q_v_3_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_4_R_l : quat.
Hypothesis q_v_4_R_l_nonzero : qn q_v_4_R_l <> 0.
Local Notation v_4_R_l := (rot q_v_4_R_l).

(** lambda_min((R̄_r + R̄_rᵀ)): a lower bound suffices *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (madd (mmul (mT v_2_R_r) v_3_Rbar) (mT (mmul (mT v_2_R_r) v_3_Rbar))) lam1.

Let env : list R := [v_1_k_s; (qw q_v_2_R_r); (qx q_v_2_R_r); (qy q_v_2_R_r); (qz q_v_2_R_r); (qw q_v_3_Rbar); (qx q_v_3_Rbar); (qy q_v_3_Rbar); (qz q_v_3_Rbar); (qw q_v_4_R_l); (qx q_v_4_R_l); (qy q_v_4_R_l); (qz q_v_4_R_l); lam1].

Definition target : poly := [([1;0;0;0;2;0;0;0;4;0;0;2;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;4;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;0;4;0;2;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;4;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;0;4;2;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;4;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;1;3;0;0;1;1;0]%nat, (-4)%Q); ([1;0;0;0;2;0;0;1;3;0;0;1;1;1]%nat, 2%Q); ([1;0;0;0;2;0;0;2;2;0;0;0;2;0]%nat, 2%Q); ([1;0;0;0;2;0;0;2;2;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;2;2;0;0;2;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;0;2;2;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;2;2;0;2;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;2;2;0;2;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;0;2;2;2;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;2;2;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;0;3;1;0;0;1;1;0]%nat, 4%Q); ([1;0;0;0;2;0;0;3;1;0;0;1;1;1]%nat, 2%Q); ([1;0;0;0;2;0;0;4;0;0;0;0;2;0]%nat, (-2)%Q); ([1;0;0;0;2;0;0;4;0;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;4;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;4;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;1;0;3;0;1;0;1;0]%nat, (-4)%Q); ([1;0;0;0;2;0;1;0;3;0;1;0;1;1]%nat, 2%Q); ([1;0;0;0;2;0;1;1;2;0;1;1;0;0]%nat, (-8)%Q); ([1;0;0;0;2;0;1;1;2;0;1;1;0;1]%nat, 2%Q); ([1;0;0;0;2;0;1;2;1;0;1;0;1;0]%nat, 4%Q); ([1;0;0;0;2;0;1;2;1;0;1;0;1;1]%nat, 2%Q); ([1;0;0;0;2;0;1;3;0;0;1;1;0;1]%nat, 2%Q); ([1;0;0;0;2;0;2;0;2;0;0;0;2;0]%nat, 2%Q); ([1;0;0;0;2;0;2;0;2;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;0;2;0;0;2;0;0]%nat, 2%Q); ([1;0;0;0;2;0;2;0;2;0;0;2;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;2;0;2;0;2;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;2;0;2;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;0;2;2;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;2;0;2;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;2;1;1;0;0;1;1;0]%nat, 4%Q); ([1;0;0;0;2;0;2;1;1;0;0;1;1;1]%nat, 2%Q); ([1;0;0;0;2;0;2;2;0;0;0;0;2;0]%nat, (-4)%Q); ([1;0;0;0;2;0;2;2;0;0;0;0;2;1]%nat, (-2)%Q); ([1;0;0;0;2;0;2;2;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;2;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;2;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;3;0;1;0;1;0;1;0]%nat, 4%Q); ([1;0;0;0;2;0;3;0;1;0;1;0;1;1]%nat, 2%Q); ([1;0;0;0;2;0;3;1;0;0;1;1;0;1]%nat, 2%Q); ([1;0;0;0;2;0;4;0;0;0;0;0;2;0]%nat, (-2)%Q); ([1;0;0;0;2;0;4;0;0;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;0;2;0;4;0;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;4;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;1;0;0;3;1;0;0;1;0]%nat, (-4)%Q); ([1;0;0;0;2;1;0;0;3;1;0;0;1;1]%nat, 2%Q); ([1;0;0;0;2;1;0;1;2;1;0;1;0;0]%nat, (-8)%Q); ([1;0;0;0;2;1;0;1;2;1;0;1;0;1]%nat, 2%Q); ([1;0;0;0;2;1;0;2;1;1;0;0;1;0]%nat, 4%Q); ([1;0;0;0;2;1;0;2;1;1;0;0;1;1]%nat, 2%Q); ([1;0;0;0;2;1;0;3;0;1;0;1;0;1]%nat, 2%Q); ([1;0;0;0;2;1;1;0;2;1;1;0;0;0]%nat, (-8)%Q); ([1;0;0;0;2;1;1;0;2;1;1;0;0;1]%nat, 2%Q); ([1;0;0;0;2;1;1;2;0;1;1;0;0;1]%nat, 2%Q); ([1;0;0;0;2;1;2;0;1;1;0;0;1;0]%nat, 4%Q); ([1;0;0;0;2;1;2;0;1;1;0;0;1;1]%nat, 2%Q); ([1;0;0;0;2;1;2;1;0;1;0;1;0;1]%nat, 2%Q); ([1;0;0;0;2;1;3;0;0;1;1;0;0;1]%nat, 2%Q); ([1;0;0;0;2;2;0;0;2;0;0;0;2;0]%nat, 2%Q); ([1;0;0;0;2;2;0;0;2;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;0;2;0;0;2;0;0]%nat, 2%Q); ([1;0;0;0;2;2;0;0;2;0;0;2;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;2;0;2;0;0;0]%nat, 2%Q); ([1;0;0;0;2;2;0;0;2;0;2;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;2;2;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;2;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;1;1;0;0;1;1;0]%nat, 4%Q); ([1;0;0;0;2;2;0;1;1;0;0;1;1;1]%nat, 2%Q); ([1;0;0;0;2;2;0;2;0;0;0;0;2;0]%nat, (-4)%Q); ([1;0;0;0;2;2;0;2;0;0;0;0;2;1]%nat, (-2)%Q); ([1;0;0;0;2;2;0;2;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;2;0;0;2;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;0;2;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;1;0;1;0;1;0;1;0]%nat, 4%Q); ([1;0;0;0;2;2;1;0;1;0;1;0;1;1]%nat, 2%Q); ([1;0;0;0;2;2;1;1;0;0;1;1;0;1]%nat, 2%Q); ([1;0;0;0;2;2;2;0;0;0;0;0;2;0]%nat, (-4)%Q); ([1;0;0;0;2;2;2;0;0;0;0;0;2;1]%nat, (-2)%Q); ([1;0;0;0;2;2;2;0;0;0;0;2;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;2;0;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;2;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;3;0;0;1;1;0;0;1;0]%nat, 4%Q); ([1;0;0;0;2;3;0;0;1;1;0;0;1;1]%nat, 2%Q); ([1;0;0;0;2;3;0;1;0;1;0;1;0;1]%nat, 2%Q); ([1;0;0;0;2;3;1;0;0;1;1;0;0;1]%nat, 2%Q); ([1;0;0;0;2;4;0;0;0;0;0;0;2;0]%nat, (-2)%Q); ([1;0;0;0;2;4;0;0;0;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;0;2;4;0;0;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;0;2;4;0;0;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;1;1;0;0;1;3;0;0;2;0;0]%nat, 8%Q); ([1;0;0;1;1;0;0;1;3;0;2;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;0;1;3;2;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;0;2;2;0;0;1;1;0]%nat, (-16)%Q); ([1;0;0;1;1;0;0;3;1;0;0;0;2;0]%nat, 8%Q); ([1;0;0;1;1;0;0;3;1;0;2;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;0;3;1;2;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;1;0;3;0;1;1;0;0]%nat, 4%Q); ([1;0;0;1;1;0;1;1;2;0;1;0;1;0]%nat, (-12)%Q); ([1;0;0;1;1;0;1;2;1;0;1;1;0;0]%nat, (-12)%Q); ([1;0;0;1;1;0;1;3;0;0;1;0;1;0]%nat, 4%Q); ([1;0;0;1;1;0;2;0;2;0;0;1;1;0]%nat, (-4)%Q); ([1;0;0;1;1;0;2;1;1;0;0;0;2;0]%nat, 8%Q); ([1;0;0;1;1;0;2;1;1;0;0;2;0;0]%nat, 8%Q); ([1;0;0;1;1;0;2;1;1;0;2;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;2;1;1;2;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;2;2;0;0;0;1;1;0]%nat, (-4)%Q); ([1;0;0;1;1;0;3;0;1;0;1;1;0;0]%nat, 4%Q); ([1;0;0;1;1;0;3;1;0;0;1;0;1;0]%nat, 4%Q); ([1;0;0;1;1;0;4;0;0;0;0;1;1;0]%nat, (-4)%Q); ([1;0;0;1;1;1;0;0;3;1;0;1;0;0]%nat, 4%Q); ([1;0;0;1;1;1;0;1;2;1;0;0;1;0]%nat, (-12)%Q); ([1;0;0;1;1;1;0;2;1;1;0;1;0;0]%nat, (-12)%Q); ([1;0;0;1;1;1;0;3;0;1;0;0;1;0]%nat, 4%Q); ([1;0;0;1;1;1;1;1;1;1;1;0;0;0]%nat, (-16)%Q); ([1;0;0;1;1;1;2;0;1;1;0;1;0;0]%nat, 4%Q); ([1;0;0;1;1;1;2;1;0;1;0;0;1;0]%nat, 4%Q); ([1;0;0;1;1;2;0;0;2;0;0;1;1;0]%nat, (-4)%Q); ([1;0;0;1;1;2;0;1;1;0;0;0;2;0]%nat, 8%Q); ([1;0;0;1;1;2;0;1;1;0;0;2;0;0]%nat, 8%Q); ([1;0;0;1;1;2;0;1;1;0;2;0;0;0]%nat, 4%Q); ([1;0;0;1;1;2;0;1;1;2;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;2;0;2;0;0;0;1;1;0]%nat, (-4)%Q); ([1;0;0;1;1;2;1;0;1;0;1;1;0;0]%nat, 4%Q); ([1;0;0;1;1;2;1;1;0;0;1;0;1;0]%nat, 4%Q); ([1;0;0;1;1;2;2;0;0;0;0;1;1;0]%nat, (-8)%Q); ([1;0;0;1;1;3;0;0;1;1;0;1;0;0]%nat, 4%Q); ([1;0;0;1;1;3;0;1;0;1;0;0;1;0]%nat, 4%Q); ([1;0;0;1;1;4;0;0;0;0;0;1;1;0]%nat, (-4)%Q); ([1;0;0;2;0;0;0;0;4;0;0;2;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;0;0;4;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;4;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;4;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;1;3;0;0;1;1;0]%nat, 4%Q); ([1;0;0;2;0;0;0;1;3;0;0;1;1;1]%nat, 2%Q); ([1;0;0;2;0;0;0;2;2;0;0;0;2;0]%nat, (-2)%Q); ([1;0;0;2;0;0;0;2;2;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;2;2;0;0;2;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;2;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;2;2;0;2;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;2;0;2;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;0;2;2;2;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;2;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;0;3;1;0;0;1;1;0]%nat, (-4)%Q); ([1;0;0;2;0;0;0;3;1;0;0;1;1;1]%nat, 2%Q); ([1;0;0;2;0;0;0;4;0;0;0;0;2;0]%nat, 2%Q); ([1;0;0;2;0;0;0;4;0;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;4;0;0;2;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;4;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;4;0;2;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;4;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;1;0;3;0;1;0;1;1]%nat, 2%Q); ([1;0;0;2;0;0;1;1;2;0;1;1;0;0]%nat, 4%Q); ([1;0;0;2;0;0;1;1;2;0;1;1;0;1]%nat, 2%Q); ([1;0;0;2;0;0;1;2;1;0;1;0;1;0]%nat, (-8)%Q); ([1;0;0;2;0;0;1;2;1;0;1;0;1;1]%nat, 2%Q); ([1;0;0;2;0;0;1;3;0;0;1;1;0;0]%nat, (-4)%Q); ([1;0;0;2;0;0;1;3;0;0;1;1;0;1]%nat, 2%Q); ([1;0;0;2;0;0;2;0;2;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;0;2;0;0;2;0;0]%nat, (-4)%Q); ([1;0;0;2;0;0;2;0;2;0;0;2;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;2;0;2;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;0;2;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;2;1;1;0;0;1;1;0]%nat, 4%Q); ([1;0;0;2;0;0;2;1;1;0;0;1;1;1]%nat, 2%Q); ([1;0;0;2;0;0;2;2;0;0;0;0;2;0]%nat, 2%Q); ([1;0;0;2;0;0;2;2;0;0;0;0;2;1]%nat, (-2)%Q); ([1;0;0;2;0;0;2;2;0;0;0;2;0;0]%nat, 2%Q); ([1;0;0;2;0;0;2;2;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;2;0;0;2;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;2;2;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;2;0;2;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;2;2;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;3;0;1;0;1;0;1;1]%nat, 2%Q); ([1;0;0;2;0;0;3;1;0;0;1;1;0;0]%nat, 4%Q); ([1;0;0;2;0;0;3;1;0;0;1;1;0;1]%nat, 2%Q); ([1;0;0;2;0;0;4;0;0;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;2;0;0;4;0;0;0;0;2;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;4;0;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;4;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;1;0;0;3;1;0;0;1;1]%nat, 2%Q); ([1;0;0;2;0;1;0;1;2;1;0;1;0;0]%nat, 4%Q); ([1;0;0;2;0;1;0;1;2;1;0;1;0;1]%nat, 2%Q); ([1;0;0;2;0;1;0;2;1;1;0;0;1;0]%nat, (-8)%Q); ([1;0;0;2;0;1;0;2;1;1;0;0;1;1]%nat, 2%Q); ([1;0;0;2;0;1;0;3;0;1;0;1;0;0]%nat, (-4)%Q); ([1;0;0;2;0;1;0;3;0;1;0;1;0;1]%nat, 2%Q); ([1;0;0;2;0;1;1;0;2;1;1;0;0;1]%nat, 2%Q); ([1;0;0;2;0;1;1;2;0;1;1;0;0;0]%nat, (-8)%Q); ([1;0;0;2;0;1;1;2;0;1;1;0;0;1]%nat, 2%Q); ([1;0;0;2;0;1;2;0;1;1;0;0;1;1]%nat, 2%Q); ([1;0;0;2;0;1;2;1;0;1;0;1;0;0]%nat, 4%Q); ([1;0;0;2;0;1;2;1;0;1;0;1;0;1]%nat, 2%Q); ([1;0;0;2;0;1;3;0;0;1;1;0;0;1]%nat, 2%Q); ([1;0;0;2;0;2;0;0;2;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;0;2;0;0;2;0;0]%nat, (-4)%Q); ([1;0;0;2;0;2;0;0;2;0;0;2;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;0;0;2;0;2;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;0;0;2;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;1;1;0;0;1;1;0]%nat, 4%Q); ([1;0;0;2;0;2;0;1;1;0;0;1;1;1]%nat, 2%Q); ([1;0;0;2;0;2;0;2;0;0;0;0;2;0]%nat, 2%Q); ([1;0;0;2;0;2;0;2;0;0;0;0;2;1]%nat, (-2)%Q); ([1;0;0;2;0;2;0;2;0;0;0;2;0;0]%nat, 2%Q); ([1;0;0;2;0;2;0;2;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;2;0;0;2;0;0;0]%nat, 2%Q); ([1;0;0;2;0;2;0;2;0;0;2;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;0;2;0;2;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;2;0;2;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;1;0;1;0;1;0;1;1]%nat, 2%Q); ([1;0;0;2;0;2;1;1;0;0;1;1;0;0]%nat, 4%Q); ([1;0;0;2;0;2;1;1;0;0;1;1;0;1]%nat, 2%Q); ([1;0;0;2;0;2;2;0;0;0;0;0;2;1]%nat, (-2)%Q); ([1;0;0;2;0;2;2;0;0;0;0;2;0;0]%nat, (-4)%Q); ([1;0;0;2;0;2;2;0;0;0;0;2;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;2;0;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;2;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;3;0;0;1;1;0;0;1;1]%nat, 2%Q); ([1;0;0;2;0;3;0;1;0;1;0;1;0;0]%nat, 4%Q); ([1;0;0;2;0;3;0;1;0;1;0;1;0;1]%nat, 2%Q); ([1;0;0;2;0;3;1;0;0;1;1;0;0;1]%nat, 2%Q); ([1;0;0;2;0;4;0;0;0;0;0;0;2;1]%nat, (-1)%Q); ([1;0;0;2;0;4;0;0;0;0;0;2;0;0]%nat, (-2)%Q); ([1;0;0;2;0;4;0;0;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;0;2;0;4;0;0;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;1;0;1;0;0;1;3;0;1;1;0;0]%nat, 4%Q); ([1;0;1;0;1;0;0;2;2;0;1;0;1;0]%nat, (-4)%Q); ([1;0;1;0;1;0;0;3;1;0;1;1;0;0]%nat, 4%Q); ([1;0;1;0;1;0;0;4;0;0;1;0;1;0]%nat, (-4)%Q); ([1;0;1;0;1;0;1;0;3;0;0;2;0;0]%nat, 4%Q); ([1;0;1;0;1;0;1;0;3;0;2;0;0;0]%nat, 8%Q); ([1;0;1;0;1;0;1;0;3;2;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;1;1;2;0;0;1;1;0]%nat, (-12)%Q); ([1;0;1;0;1;0;1;2;1;0;0;0;2;0]%nat, 8%Q); ([1;0;1;0;1;0;1;2;1;0;0;2;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;1;2;1;0;2;0;0;0]%nat, 8%Q); ([1;0;1;0;1;0;1;2;1;2;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;1;3;0;0;0;1;1;0]%nat, 4%Q); ([1;0;1;0;1;0;2;0;2;0;1;0;1;0]%nat, (-16)%Q); ([1;0;1;0;1;0;2;1;1;0;1;1;0;0]%nat, (-12)%Q); ([1;0;1;0;1;0;2;2;0;0;1;0;1;0]%nat, (-4)%Q); ([1;0;1;0;1;0;3;0;1;0;0;0;2;0]%nat, 8%Q); ([1;0;1;0;1;0;3;0;1;0;0;2;0;0]%nat, 4%Q); ([1;0;1;0;1;0;3;0;1;2;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;3;1;0;0;0;1;1;0]%nat, 4%Q); ([1;0;1;0;1;1;0;0;3;1;1;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;0;2;1;1;1;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;1;0;2;1;0;0;1;0]%nat, (-12)%Q); ([1;0;1;0;1;1;1;1;1;1;0;1;0;0]%nat, (-16)%Q); ([1;0;1;0;1;1;1;2;0;1;0;0;1;0]%nat, 4%Q); ([1;0;1;0;1;1;2;0;1;1;1;0;0;0]%nat, (-12)%Q); ([1;0;1;0;1;1;3;0;0;1;0;0;1;0]%nat, 4%Q); ([1;0;1;0;1;2;0;0;2;0;1;0;1;0]%nat, (-4)%Q); ([1;0;1;0;1;2;0;1;1;0;1;1;0;0]%nat, 4%Q); ([1;0;1;0;1;2;0;2;0;0;1;0;1;0]%nat, (-8)%Q); ([1;0;1;0;1;2;1;0;1;0;0;0;2;0]%nat, 8%Q); ([1;0;1;0;1;2;1;0;1;0;0;2;0;0]%nat, 4%Q); ([1;0;1;0;1;2;1;0;1;0;2;0;0;0]%nat, 8%Q); ([1;0;1;0;1;2;1;0;1;2;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;2;1;1;0;0;0;1;1;0]%nat, 4%Q); ([1;0;1;0;1;2;2;0;0;0;1;0;1;0]%nat, (-4)%Q); ([1;0;1;0;1;3;0;0;1;1;1;0;0;0]%nat, 4%Q); ([1;0;1;0;1;3;1;0;0;1;0;0;1;0]%nat, 4%Q); ([1;0;1;0;1;4;0;0;0;0;1;0;1;0]%nat, (-4)%Q); ([1;0;1;1;0;0;0;0;4;0;1;1;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;0;1;3;0;1;0;1;0]%nat, 4%Q); ([1;0;1;1;0;0;0;2;2;0;1;1;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;0;3;1;0;1;0;1;0]%nat, 4%Q); ([1;0;1;1;0;0;1;0;3;0;0;1;1;0]%nat, 4%Q); ([1;0;1;1;0;0;1;1;2;0;0;0;2;0]%nat, (-4)%Q); ([1;0;1;1;0;0;1;1;2;0;0;2;0;0]%nat, 8%Q); ([1;0;1;1;0;0;1;1;2;0;2;0;0;0]%nat, 8%Q); ([1;0;1;1;0;0;1;1;2;2;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;1;2;1;0;0;1;1;0]%nat, (-12)%Q); ([1;0;1;1;0;0;1;3;0;0;0;0;2;0]%nat, 4%Q); ([1;0;1;1;0;0;1;3;0;0;2;0;0;0]%nat, 8%Q); ([1;0;1;1;0;0;1;3;0;2;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;2;0;2;0;1;1;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;2;1;1;0;1;0;1;0]%nat, (-12)%Q); ([1;0;1;1;0;0;2;2;0;0;1;1;0;0]%nat, (-16)%Q); ([1;0;1;1;0;0;3;0;1;0;0;1;1;0]%nat, 4%Q); ([1;0;1;1;0;0;3;1;0;0;0;0;2;0]%nat, 4%Q); ([1;0;1;1;0;0;3;1;0;0;0;2;0;0]%nat, 8%Q); ([1;0;1;1;0;0;3;1;0;2;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;0;1;2;1;1;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;0;3;0;1;1;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;1;0;2;1;0;1;0;0]%nat, 4%Q); ([1;0;1;1;0;1;1;1;1;1;0;0;1;0]%nat, (-16)%Q); ([1;0;1;1;0;1;1;2;0;1;0;1;0;0]%nat, (-12)%Q); ([1;0;1;1;0;1;2;1;0;1;1;0;0;0]%nat, (-12)%Q); ([1;0;1;1;0;1;3;0;0;1;0;1;0;0]%nat, 4%Q); ([1;0;1;1;0;2;0;0;2;0;1;1;0;0]%nat, (-8)%Q); ([1;0;1;1;0;2;0;1;1;0;1;0;1;0]%nat, 4%Q); ([1;0;1;1;0;2;0;2;0;0;1;1;0;0]%nat, (-4)%Q); ([1;0;1;1;0;2;1;0;1;0;0;1;1;0]%nat, 4%Q); ([1;0;1;1;0;2;1;1;0;0;0;0;2;0]%nat, 4%Q); ([1;0;1;1;0;2;1;1;0;0;0;2;0;0]%nat, 8%Q); ([1;0;1;1;0;2;1;1;0;0;2;0;0;0]%nat, 8%Q); ([1;0;1;1;0;2;1;1;0;2;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;2;2;0;0;0;1;1;0;0]%nat, (-4)%Q); ([1;0;1;1;0;3;0;1;0;1;1;0;0;0]%nat, 4%Q); ([1;0;1;1;0;3;1;0;0;1;0;1;0;0]%nat, 4%Q); ([1;0;1;1;0;4;0;0;0;0;1;1;0;0]%nat, (-4)%Q); ([1;0;2;0;0;0;0;0;4;0;0;2;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;0;4;0;2;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;0;4;0;2;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;0;4;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;1;3;0;0;1;1;1]%nat, 2%Q); ([1;0;2;0;0;0;0;2;2;0;0;0;2;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;2;2;0;0;2;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;2;2;0;2;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;0;0;2;2;0;2;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;0;2;2;2;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;0;3;1;0;0;1;1;1]%nat, 2%Q); ([1;0;2;0;0;0;0;4;0;0;0;0;2;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;4;0;0;2;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;4;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;4;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;1;0;3;0;1;0;1;0]%nat, 4%Q); ([1;0;2;0;0;0;1;0;3;0;1;0;1;1]%nat, 2%Q); ([1;0;2;0;0;0;1;1;2;0;1;1;0;0]%nat, 4%Q); ([1;0;2;0;0;0;1;1;2;0;1;1;0;1]%nat, 2%Q); ([1;0;2;0;0;0;1;2;1;0;1;0;1;0]%nat, 4%Q); ([1;0;2;0;0;0;1;2;1;0;1;0;1;1]%nat, 2%Q); ([1;0;2;0;0;0;1;3;0;0;1;1;0;0]%nat, 4%Q); ([1;0;2;0;0;0;1;3;0;0;1;1;0;1]%nat, 2%Q); ([1;0;2;0;0;0;2;0;2;0;0;0;2;0]%nat, (-2)%Q); ([1;0;2;0;0;0;2;0;2;0;0;0;2;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;0;2;0;0;2;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;2;0;0;2;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;2;0;2;0;2;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;2;0;2;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;0;2;2;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;2;2;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;2;1;1;0;0;1;1;0]%nat, (-8)%Q); ([1;0;2;0;0;0;2;1;1;0;0;1;1;1]%nat, 2%Q); ([1;0;2;0;0;0;2;2;0;0;0;0;2;0]%nat, 2%Q); ([1;0;2;0;0;0;2;2;0;0;0;0;2;1]%nat, (-2)%Q); ([1;0;2;0;0;0;2;2;0;0;0;2;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;2;2;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;2;0;0;2;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;2;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;2;0;2;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;2;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;3;0;1;0;1;0;1;0]%nat, (-4)%Q); ([1;0;2;0;0;0;3;0;1;0;1;0;1;1]%nat, 2%Q); ([1;0;2;0;0;0;3;1;0;0;1;1;0;0]%nat, (-4)%Q); ([1;0;2;0;0;0;3;1;0;0;1;1;0;1]%nat, 2%Q); ([1;0;2;0;0;0;4;0;0;0;0;0;2;0]%nat, 2%Q); ([1;0;2;0;0;0;4;0;0;0;0;0;2;1]%nat, (-1)%Q); ([1;0;2;0;0;0;4;0;0;0;0;2;0;0]%nat, 2%Q); ([1;0;2;0;0;0;4;0;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;4;0;0;2;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;4;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;1;0;0;3;1;0;0;1;1]%nat, 2%Q); ([1;0;2;0;0;1;0;1;2;1;0;1;0;1]%nat, 2%Q); ([1;0;2;0;0;1;0;2;1;1;0;0;1;1]%nat, 2%Q); ([1;0;2;0;0;1;0;3;0;1;0;1;0;1]%nat, 2%Q); ([1;0;2;0;0;1;1;0;2;1;1;0;0;0]%nat, 4%Q); ([1;0;2;0;0;1;1;0;2;1;1;0;0;1]%nat, 2%Q); ([1;0;2;0;0;1;1;2;0;1;1;0;0;0]%nat, 4%Q); ([1;0;2;0;0;1;1;2;0;1;1;0;0;1]%nat, 2%Q); ([1;0;2;0;0;1;2;0;1;1;0;0;1;0]%nat, (-8)%Q); ([1;0;2;0;0;1;2;0;1;1;0;0;1;1]%nat, 2%Q); ([1;0;2;0;0;1;2;1;0;1;0;1;0;0]%nat, (-8)%Q); ([1;0;2;0;0;1;2;1;0;1;0;1;0;1]%nat, 2%Q); ([1;0;2;0;0;1;3;0;0;1;1;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;1;3;0;0;1;1;0;0;1]%nat, 2%Q); ([1;0;2;0;0;2;0;0;2;0;0;0;2;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;0;2;0;0;2;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;0;0;2;0;2;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;2;0;0;2;0;2;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;0;0;2;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;1;1;0;0;1;1;1]%nat, 2%Q); ([1;0;2;0;0;2;0;2;0;0;0;0;2;1]%nat, (-2)%Q); ([1;0;2;0;0;2;0;2;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;2;0;0;2;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;2;0;2;0;0;2;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;0;2;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;1;0;1;0;1;0;1;0]%nat, 4%Q); ([1;0;2;0;0;2;1;0;1;0;1;0;1;1]%nat, 2%Q); ([1;0;2;0;0;2;1;1;0;0;1;1;0;0]%nat, 4%Q); ([1;0;2;0;0;2;1;1;0;0;1;1;0;1]%nat, 2%Q); ([1;0;2;0;0;2;2;0;0;0;0;0;2;0]%nat, 2%Q); ([1;0;2;0;0;2;2;0;0;0;0;0;2;1]%nat, (-2)%Q); ([1;0;2;0;0;2;2;0;0;0;0;2;0;0]%nat, 2%Q); ([1;0;2;0;0;2;2;0;0;0;0;2;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;2;0;0;0;2;0;0;0]%nat, 2%Q); ([1;0;2;0;0;2;2;0;0;0;2;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;2;0;0;2;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;2;2;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;3;0;0;1;1;0;0;1;1]%nat, 2%Q); ([1;0;2;0;0;3;0;1;0;1;0;1;0;1]%nat, 2%Q); ([1;0;2;0;0;3;1;0;0;1;1;0;0;0]%nat, 4%Q); ([1;0;2;0;0;3;1;0;0;1;1;0;0;1]%nat, 2%Q); ([1;0;2;0;0;4;0;0;0;0;0;0;2;1]%nat, (-1)%Q); ([1;0;2;0;0;4;0;0;0;0;0;2;0;1]%nat, (-1)%Q); ([1;0;2;0;0;4;0;0;0;0;2;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;4;0;0;0;0;2;0;0;1]%nat, (-1)%Q); ([1;1;0;0;1;0;0;1;3;1;0;1;0;0]%nat, 4%Q); ([1;1;0;0;1;0;0;2;2;1;0;0;1;0]%nat, (-4)%Q); ([1;1;0;0;1;0;0;3;1;1;0;1;0;0]%nat, 4%Q); ([1;1;0;0;1;0;0;4;0;1;0;0;1;0]%nat, (-4)%Q); ([1;1;0;0;1;0;1;0;3;1;1;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;1;2;1;1;1;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;2;0;2;1;0;0;1;0]%nat, (-4)%Q); ([1;1;0;0;1;0;2;1;1;1;0;1;0;0]%nat, 4%Q); ([1;1;0;0;1;0;2;2;0;1;0;0;1;0]%nat, (-8)%Q); ([1;1;0;0;1;0;3;0;1;1;1;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;4;0;0;1;0;0;1;0]%nat, (-4)%Q); ([1;1;0;0;1;1;0;0;3;0;0;2;0;0]%nat, 4%Q); ([1;1;0;0;1;1;0;0;3;0;2;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;0;0;3;2;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;1;0;1;2;0;0;1;1;0]%nat, (-12)%Q); ([1;1;0;0;1;1;0;2;1;0;0;0;2;0]%nat, 8%Q); ([1;1;0;0;1;1;0;2;1;0;0;2;0;0]%nat, (-4)%Q); ([1;1;0;0;1;1;0;2;1;0;2;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;0;2;1;2;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;1;0;3;0;0;0;1;1;0]%nat, 4%Q); ([1;1;0;0;1;1;1;0;2;0;1;0;1;0]%nat, (-12)%Q); ([1;1;0;0;1;1;1;1;1;0;1;1;0;0]%nat, (-16)%Q); ([1;1;0;0;1;1;1;2;0;0;1;0;1;0]%nat, 4%Q); ([1;1;0;0;1;1;2;0;1;0;0;0;2;0]%nat, 8%Q); ([1;1;0;0;1;1;2;0;1;0;0;2;0;0]%nat, 4%Q); ([1;1;0;0;1;1;2;0;1;0;2;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;1;2;0;1;2;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;1;2;1;0;0;0;1;1;0]%nat, 4%Q); ([1;1;0;0;1;1;3;0;0;0;1;0;1;0]%nat, 4%Q); ([1;1;0;0;1;2;0;0;2;1;0;0;1;0]%nat, (-16)%Q); ([1;1;0;0;1;2;0;1;1;1;0;1;0;0]%nat, (-12)%Q); ([1;1;0;0;1;2;0;2;0;1;0;0;1;0]%nat, (-4)%Q); ([1;1;0;0;1;2;1;0;1;1;1;0;0;0]%nat, (-12)%Q); ([1;1;0;0;1;2;2;0;0;1;0;0;1;0]%nat, (-4)%Q); ([1;1;0;0;1;3;0;0;1;0;0;0;2;0]%nat, 8%Q); ([1;1;0;0;1;3;0;0;1;0;0;2;0;0]%nat, 4%Q); ([1;1;0;0;1;3;0;0;1;0;2;0;0;0]%nat, 4%Q); ([1;1;0;0;1;3;0;1;0;0;0;1;1;0]%nat, 4%Q); ([1;1;0;0;1;3;1;0;0;0;1;0;1;0]%nat, 4%Q); ([1;1;0;1;0;0;0;0;4;1;0;1;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;1;3;1;0;0;1;0]%nat, 4%Q); ([1;1;0;1;0;0;0;2;2;1;0;1;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;3;1;1;0;0;1;0]%nat, 4%Q); ([1;1;0;1;0;0;1;1;2;1;1;0;0;0]%nat, 4%Q); ([1;1;0;1;0;0;1;3;0;1;1;0;0;0]%nat, 4%Q); ([1;1;0;1;0;0;2;0;2;1;0;1;0;0]%nat, (-8)%Q); ([1;1;0;1;0;0;2;1;1;1;0;0;1;0]%nat, 4%Q); ([1;1;0;1;0;0;2;2;0;1;0;1;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;3;1;0;1;1;0;0;0]%nat, 4%Q); ([1;1;0;1;0;0;4;0;0;1;0;1;0;0]%nat, (-4)%Q); ([1;1;0;1;0;1;0;0;3;0;0;1;1;0]%nat, 4%Q); ([1;1;0;1;0;1;0;1;2;0;0;0;2;0]%nat, (-4)%Q); ([1;1;0;1;0;1;0;1;2;0;0;2;0;0]%nat, 8%Q); ([1;1;0;1;0;1;0;1;2;0;2;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;0;1;2;2;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;1;0;2;1;0;0;1;1;0]%nat, (-12)%Q); ([1;1;0;1;0;1;0;3;0;0;0;0;2;0]%nat, 4%Q); ([1;1;0;1;0;1;0;3;0;0;2;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;0;3;0;2;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;1;1;0;2;0;1;1;0;0]%nat, 4%Q); ([1;1;0;1;0;1;1;1;1;0;1;0;1;0]%nat, (-16)%Q); ([1;1;0;1;0;1;1;2;0;0;1;1;0;0]%nat, (-12)%Q); ([1;1;0;1;0;1;2;0;1;0;0;1;1;0]%nat, 4%Q); ([1;1;0;1;0;1;2;1;0;0;0;0;2;0]%nat, 4%Q); ([1;1;0;1;0;1;2;1;0;0;0;2;0;0]%nat, 8%Q); ([1;1;0;1;0;1;2;1;0;0;2;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;1;2;1;0;2;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;1;3;0;0;0;1;1;0;0]%nat, 4%Q); ([1;1;0;1;0;2;0;0;2;1;0;1;0;0]%nat, (-4)%Q); ([1;1;0;1;0;2;0;1;1;1;0;0;1;0]%nat, (-12)%Q); ([1;1;0;1;0;2;0;2;0;1;0;1;0;0]%nat, (-16)%Q); ([1;1;0;1;0;2;1;1;0;1;1;0;0;0]%nat, (-12)%Q); ([1;1;0;1;0;2;2;0;0;1;0;1;0;0]%nat, (-4)%Q); ([1;1;0;1;0;3;0;0;1;0;0;1;1;0]%nat, 4%Q); ([1;1;0;1;0;3;0;1;0;0;0;0;2;0]%nat, 4%Q); ([1;1;0;1;0;3;0;1;0;0;0;2;0;0]%nat, 8%Q); ([1;1;0;1;0;3;0;1;0;0;2;0;0;0]%nat, 4%Q); ([1;1;0;1;0;3;1;0;0;0;1;1;0;0]%nat, 4%Q); ([1;1;1;0;0;0;0;0;4;1;1;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;0;2;2;1;1;0;0;0]%nat, (-8)%Q); ([1;1;1;0;0;0;0;4;0;1;1;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;1;0;3;1;0;0;1;0]%nat, 4%Q); ([1;1;1;0;0;0;1;1;2;1;0;1;0;0]%nat, 4%Q); ([1;1;1;0;0;0;1;2;1;1;0;0;1;0]%nat, 4%Q); ([1;1;1;0;0;0;1;3;0;1;0;1;0;0]%nat, 4%Q); ([1;1;1;0;0;0;2;0;2;1;1;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;2;2;0;1;1;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;3;0;1;1;0;0;1;0]%nat, 4%Q); ([1;1;1;0;0;0;3;1;0;1;0;1;0;0]%nat, 4%Q); ([1;1;1;0;0;1;0;0;3;0;1;0;1;0]%nat, 4%Q); ([1;1;1;0;0;1;0;1;2;0;1;1;0;0]%nat, 4%Q); ([1;1;1;0;0;1;0;2;1;0;1;0;1;0]%nat, 4%Q); ([1;1;1;0;0;1;0;3;0;0;1;1;0;0]%nat, 4%Q); ([1;1;1;0;0;1;1;0;2;0;0;0;2;0]%nat, (-4)%Q); ([1;1;1;0;0;1;1;0;2;0;0;2;0;0]%nat, 4%Q); ([1;1;1;0;0;1;1;0;2;0;2;0;0;0]%nat, 8%Q); ([1;1;1;0;0;1;1;0;2;2;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;1;1;1;1;0;0;1;1;0]%nat, (-16)%Q); ([1;1;1;0;0;1;1;2;0;0;0;0;2;0]%nat, 4%Q); ([1;1;1;0;0;1;1;2;0;0;0;2;0;0]%nat, (-4)%Q); ([1;1;1;0;0;1;1;2;0;0;2;0;0;0]%nat, 8%Q); ([1;1;1;0;0;1;1;2;0;2;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;1;2;0;1;0;1;0;1;0]%nat, (-12)%Q); ([1;1;1;0;0;1;2;1;0;0;1;1;0;0]%nat, (-12)%Q); ([1;1;1;0;0;1;3;0;0;0;0;0;2;0]%nat, 4%Q); ([1;1;1;0;0;1;3;0;0;0;0;2;0;0]%nat, 4%Q); ([1;1;1;0;0;1;3;0;0;2;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;2;0;0;2;1;1;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;2;0;2;0;1;1;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;2;1;0;1;1;0;0;1;0]%nat, (-12)%Q); ([1;1;1;0;0;2;1;1;0;1;0;1;0;0]%nat, (-12)%Q); ([1;1;1;0;0;2;2;0;0;1;1;0;0;0]%nat, (-16)%Q); ([1;1;1;0;0;3;0;0;1;0;1;0;1;0]%nat, 4%Q); ([1;1;1;0;0;3;0;1;0;0;1;1;0;0]%nat, 4%Q); ([1;1;1;0;0;3;1;0;0;0;0;0;2;0]%nat, 4%Q); ([1;1;1;0;0;3;1;0;0;0;0;2;0;0]%nat, 4%Q); ([1;1;1;0;0;3;1;0;0;0;2;0;0;0]%nat, 8%Q); ([1;2;0;0;0;0;0;0;4;0;0;2;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;0;4;0;2;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;0;4;2;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;0;4;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;1;3;0;0;1;1;1]%nat, 2%Q); ([1;2;0;0;0;0;0;2;2;0;0;0;2;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;2;2;0;0;2;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;2;2;0;2;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;0;2;2;2;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;0;2;2;2;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;0;3;1;0;0;1;1;1]%nat, 2%Q); ([1;2;0;0;0;0;0;4;0;0;0;0;2;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;4;0;0;2;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;4;0;2;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;4;0;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;1;0;3;0;1;0;1;1]%nat, 2%Q); ([1;2;0;0;0;0;1;1;2;0;1;1;0;1]%nat, 2%Q); ([1;2;0;0;0;0;1;2;1;0;1;0;1;1]%nat, 2%Q); ([1;2;0;0;0;0;1;3;0;0;1;1;0;1]%nat, 2%Q); ([1;2;0;0;0;0;2;0;2;0;0;0;2;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;0;2;0;0;2;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;2;0;2;0;2;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;0;2;2;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;2;0;2;2;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;2;1;1;0;0;1;1;1]%nat, 2%Q); ([1;2;0;0;0;0;2;2;0;0;0;0;2;1]%nat, (-2)%Q); ([1;2;0;0;0;0;2;2;0;0;0;2;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;2;0;0;2;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;2;0;2;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;2;2;0;2;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;3;0;1;0;1;0;1;1]%nat, 2%Q); ([1;2;0;0;0;0;3;1;0;0;1;1;0;1]%nat, 2%Q); ([1;2;0;0;0;0;4;0;0;0;0;0;2;1]%nat, (-1)%Q); ([1;2;0;0;0;0;4;0;0;0;0;2;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;4;0;0;2;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;4;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;1;0;0;3;1;0;0;1;0]%nat, 4%Q); ([1;2;0;0;0;1;0;0;3;1;0;0;1;1]%nat, 2%Q); ([1;2;0;0;0;1;0;1;2;1;0;1;0;0]%nat, 4%Q); ([1;2;0;0;0;1;0;1;2;1;0;1;0;1]%nat, 2%Q); ([1;2;0;0;0;1;0;2;1;1;0;0;1;0]%nat, 4%Q); ([1;2;0;0;0;1;0;2;1;1;0;0;1;1]%nat, 2%Q); ([1;2;0;0;0;1;0;3;0;1;0;1;0;0]%nat, 4%Q); ([1;2;0;0;0;1;0;3;0;1;0;1;0;1]%nat, 2%Q); ([1;2;0;0;0;1;1;0;2;1;1;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;1;0;2;1;1;0;0;1]%nat, 2%Q); ([1;2;0;0;0;1;1;2;0;1;1;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;1;2;0;1;1;0;0;1]%nat, 2%Q); ([1;2;0;0;0;1;2;0;1;1;0;0;1;0]%nat, 4%Q); ([1;2;0;0;0;1;2;0;1;1;0;0;1;1]%nat, 2%Q); ([1;2;0;0;0;1;2;1;0;1;0;1;0;0]%nat, 4%Q); ([1;2;0;0;0;1;2;1;0;1;0;1;0;1]%nat, 2%Q); ([1;2;0;0;0;1;3;0;0;1;1;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;3;0;0;1;1;0;0;1]%nat, 2%Q); ([1;2;0;0;0;2;0;0;2;0;0;0;2;0]%nat, (-2)%Q); ([1;2;0;0;0;2;0;0;2;0;0;0;2;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;0;2;0;0;2;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;2;0;0;2;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;0;0;2;0;2;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;2;0;2;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;0;0;2;2;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;2;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;1;1;0;0;1;1;0]%nat, (-8)%Q); ([1;2;0;0;0;2;0;1;1;0;0;1;1;1]%nat, 2%Q); ([1;2;0;0;0;2;0;2;0;0;0;0;2;0]%nat, 2%Q); ([1;2;0;0;0;2;0;2;0;0;0;0;2;1]%nat, (-2)%Q); ([1;2;0;0;0;2;0;2;0;0;0;2;0;0]%nat, (-2)%Q); ([1;2;0;0;0;2;0;2;0;0;0;2;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;2;0;0;2;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;2;0;0;2;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;0;2;0;2;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;2;0;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;1;0;1;0;1;0;1;0]%nat, (-8)%Q); ([1;2;0;0;0;2;1;0;1;0;1;0;1;1]%nat, 2%Q); ([1;2;0;0;0;2;1;1;0;0;1;1;0;0]%nat, (-8)%Q); ([1;2;0;0;0;2;1;1;0;0;1;1;0;1]%nat, 2%Q); ([1;2;0;0;0;2;2;0;0;0;0;0;2;0]%nat, 2%Q); ([1;2;0;0;0;2;2;0;0;0;0;0;2;1]%nat, (-2)%Q); ([1;2;0;0;0;2;2;0;0;0;0;2;0;0]%nat, 2%Q); ([1;2;0;0;0;2;2;0;0;0;0;2;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;2;0;0;0;2;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;2;2;0;0;0;2;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;2;0;0;2;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;2;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;3;0;0;1;1;0;0;1;0]%nat, (-4)%Q); ([1;2;0;0;0;3;0;0;1;1;0;0;1;1]%nat, 2%Q); ([1;2;0;0;0;3;0;1;0;1;0;1;0;0]%nat, (-4)%Q); ([1;2;0;0;0;3;0;1;0;1;0;1;0;1]%nat, 2%Q); ([1;2;0;0;0;3;1;0;0;1;1;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;3;1;0;0;1;1;0;0;1]%nat, 2%Q); ([1;2;0;0;0;4;0;0;0;0;0;0;2;0]%nat, 2%Q); ([1;2;0;0;0;4;0;0;0;0;0;0;2;1]%nat, (-1)%Q); ([1;2;0;0;0;4;0;0;0;0;0;2;0;0]%nat, 2%Q); ([1;2;0;0;0;4;0;0;0;0;0;2;0;1]%nat, (-1)%Q); ([1;2;0;0;0;4;0;0;0;0;2;0;0;0]%nat, 2%Q); ([1;2;0;0;0;4;0;0;0;0;2;0;0;1]%nat, (-1)%Q)].

(** block 1: k_s > 0 (declared) × spectral: λmin((R̄_r + R̄_rᵀ)) I ⪯ (R̄_r + R̄_rᵀ) (symmetric) *)
Definition H1 : list (list poly) := [[[([1;0;0;0;2;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;1;0;1;0;1;0;1;0;0;0;0;0]%nat, 8%Q); ([1;0;1;0;1;1;0;1;0;0;0;0;0;0]%nat, (-8)%Q); ([1;0;1;1;0;0;1;1;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;1;0;1;0;0;1;0;0;0;0;0]%nat, 8%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;1;0;0;1;0;1;1;0;0;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;1;0;0;1;0;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;0;1;0;1;0;0;0;0;0]%nat, (-8)%Q); ([1;1;0;1;0;1;0;1;0;0;0;0;0;0]%nat, 8%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q)]; [([1;0;0;0;2;0;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;0;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;1;0;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;1;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;0;0;2;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;2;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;1;0;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;2;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;1;1;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;0;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;1;1;0;0;0;0;0;0]%nat, 4%Q)]; [([1;0;0;0;2;1;0;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;0;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;0;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;0;2;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;2;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;1;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;1;0;1;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;1;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;0;2;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;1;0;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;1;0;1;0;0;0;0;0]%nat, 4%Q)]]; [[([1;0;0;0;2;0;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;0;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;1;0;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;1;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;0;0;2;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;2;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;1;0;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;2;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;1;1;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;0;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;1;1;0;0;0;0;0;0]%nat, 4%Q)]; [([1;0;0;0;2;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;1;1;0;0;1;1;0;0;0;0;0]%nat, 8%Q); ([1;0;0;1;1;1;1;0;0;0;0;0;0;0]%nat, 8%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;1;1;0;0;1;1;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;1;0;1;0;0;1;0;0;0;0;0]%nat, (-8)%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;1;0;0;1;0;1;1;0;0;0;0;0;0]%nat, (-8)%Q); ([1;1;0;0;1;1;0;0;1;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;0;0;1;1;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;1;1;0;0;0;0;0;0;0]%nat, 8%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q)]; [([1;0;0;0;2;1;1;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;2;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;2;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;1;1;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;0;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;0;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;0;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;1;0;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;0;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;0;2;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;0;1;1;0;0;0;0;0]%nat, 4%Q)]]; [[([1;0;0;0;2;1;0;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;0;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;0;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;0;2;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;2;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;1;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;1;0;1;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;1;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;0;2;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;1;0;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;1;0;1;0;0;0;0;0]%nat, 4%Q)]; [([1;0;0;0;2;1;1;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;2;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;2;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;1;1;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;0;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;0;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;0;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;1;0;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;0;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;0;2;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;0;1;1;0;0;0;0;0]%nat, 4%Q)]; [([1;0;0;0;2;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;1;1;0;0;1;1;0;0;0;0;0]%nat, 8%Q); ([1;0;0;1;1;1;1;0;0;0;0;0;0;0]%nat, (-8)%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;1;0;1;0;1;0;1;0;0;0;0;0]%nat, 8%Q); ([1;0;1;0;1;1;0;1;0;0;0;0;0;0]%nat, 8%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;1;0;1;0;0;1;0;1;0;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;1;0;1;0;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;0;0;1;1;0;0;0;0;0]%nat, (-8)%Q); ([1;1;1;0;0;1;1;0;0;0;0;0;0;0]%nat, 8%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q)]]].
Definition S1 : list (Q * list poly) :=
  [((1#2)%Q, [[([0;0;0;0;0;0;0;0;1;0;1;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;0;1;0]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;0;1;0;0]%nat, (-1)%Q)]; [([0;0;0;0;0;0;0;0;1;0;0;1;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;0;0;0;1;0]%nat, (-1)%Q); ([0;0;0;0;0;0;1;0;0;1;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;1;0;0;0]%nat, 1%Q)]; []]);
   ((1#2)%Q, [[([0;0;0;0;0;0;0;0;1;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;0;1;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;0;1;0;0;0;0;1;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;1;0]%nat, (-1)%Q)]; []; [([0;0;0;0;0;0;0;0;1;0;0;1;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;0;0;0;1;0]%nat, (-1)%Q); ([0;0;0;0;0;0;1;0;0;1;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;1;0;0;0]%nat, 1%Q)]]);
   ((1#2)%Q, [[]; [([0;0;0;0;0;0;0;0;1;1;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;0;0;1;0;0;1;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;1;0;0]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;1;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;1;0;1;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;0;1;0]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;0;1;0;0]%nat, (-1)%Q)]])].

Lemma H1_psd : mult_psd env H1.
Proof.
  unfold H1. sos_psd9 [v_1_k_s; (qw q_v_2_R_r); (qx q_v_2_R_r); (qy q_v_2_R_r); (qz q_v_2_R_r); (qw q_v_3_Rbar); (qx q_v_3_Rbar); (qy q_v_3_Rbar); (qz q_v_3_Rbar); (qw q_v_4_R_l); (qx q_v_4_R_l); (qy q_v_4_R_l); (qz q_v_4_R_l); lam1] (v_1_k_s) (msub (sym (madd (mmul (mT v_2_R_r) v_3_Rbar) (mT (mmul (mT v_2_R_r) v_3_Rbar)))) (mscale lam1 I3)) [0; 1; 0; 0; 0; 1; 0; 0; 0; 0; 0; 0; 0; 0]%nat.
  - exact (Rlt_le _ _ v_1_k_s_pos).
  - exact lam1_spec.
Qed.

Definition blocks : list block := [(mkBlock H1 S1)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_cast_no_check (eq_refl true). Qed.

Lemma grounds : blocks_psd env blocks.
Proof. exact (blocks_psd_cons env (mkBlock H1 S1) _ H1_psd (blocks_psd_nil env)). Qed.

(** The link, by computation: the statement's slack, read as an expression of the prelude's operations (sos_reify), times a positive product of quaternion norms is the target polynomial at the parameters times a non-negative one. *)
Lemma link : exists D F, 0 < D /\ 0 <= F /\ (((((((-1/2) * v_1_k_s) * lam1) * (phi (mmul (mT v_3_Rbar) v_4_R_l))) + (- (v_1_k_s * (phi (mmul (mT v_2_R_r) v_3_Rbar))))) + (v_1_k_s * (phi (mmul (mT v_2_R_r) v_4_R_l)))) + - (((((-1/4) * v_1_k_s) * (tr (mmul (madd (mmul (mT v_2_R_r) v_3_Rbar) (mT (mmul (mT v_2_R_r) v_3_Rbar))) (madd I3 (mneg (mmul (mT v_3_Rbar) v_4_R_l)))))) + (- (((1/2) * v_1_k_s) * (tr (madd I3 (mneg (mmul (mT v_2_R_r) v_3_Rbar))))))) + (((1/2) * v_1_k_s) * (tr (madd I3 (mneg (mmul (mT v_2_R_r) v_4_R_l))))))) * D = F * peval env target.
Proof.
  assert (Hq : Forall (fun p => qnR env p <> 0) [1; 5; 9]%nat) by (apply Forall_cons; [exact q_v_2_R_r_nonzero|]; apply Forall_cons; [exact q_v_3_Rbar_nonzero|]; apply Forall_cons; [exact q_v_4_R_l_nonzero|]; apply Forall_nil).
  sos_link [v_1_k_s; (qw q_v_2_R_r); (qx q_v_2_R_r); (qy q_v_2_R_r); (qz q_v_2_R_r); (qw q_v_3_Rbar); (qx q_v_3_Rbar); (qy q_v_3_Rbar); (qz q_v_3_Rbar); (qw q_v_4_R_l); (qx q_v_4_R_l); (qy q_v_4_R_l); (qz q_v_4_R_l); lam1] [1; 5; 9]%nat Hq [0; 1; 0; 0; 0; 2; 0; 0; 0; 1]%nat.
Qed.

Theorem step7_by_sos : (((((-1/4) * v_1_k_s) * (tr (mmul (madd (mmul (mT v_2_R_r) v_3_Rbar) (mT (mmul (mT v_2_R_r) v_3_Rbar))) (madd I3 (mneg (mmul (mT v_3_Rbar) v_4_R_l)))))) + (- (((1/2) * v_1_k_s) * (tr (madd I3 (mneg (mmul (mT v_2_R_r) v_3_Rbar))))))) + (((1/2) * v_1_k_s) * (tr (madd I3 (mneg (mmul (mT v_2_R_r) v_4_R_l)))))) <= ((((((-1/2) * v_1_k_s) * lam1) * (phi (mmul (mT v_3_Rbar) v_4_R_l))) + (- (v_1_k_s * (phi (mmul (mT v_2_R_r) v_3_Rbar))))) + (v_1_k_s * (phi (mmul (mT v_2_R_r) v_4_R_l)))).
Proof.
  apply (le_by_slack _ _ (((((((-1/2) * v_1_k_s) * lam1) * (phi (mmul (mT v_3_Rbar) v_4_R_l))) + (- (v_1_k_s * (phi (mmul (mT v_2_R_r) v_3_Rbar))))) + (v_1_k_s * (phi (mmul (mT v_2_R_r) v_4_R_l)))) + - (((((-1/4) * v_1_k_s) * (tr (mmul (madd (mmul (mT v_2_R_r) v_3_Rbar) (mT (mmul (mT v_2_R_r) v_3_Rbar))) (madd I3 (mneg (mmul (mT v_3_Rbar) v_4_R_l)))))) + (- (((1/2) * v_1_k_s) * (tr (madd I3 (mneg (mmul (mT v_2_R_r) v_3_Rbar))))))) + (((1/2) * v_1_k_s) * (tr (madd I3 (mneg (mmul (mT v_2_R_r) v_4_R_l)))))))); [reflexivity|].
  destruct link as (D & F & HD & HF & E).
  exact (slack_nonneg _ D F _ E HD HF (sos_nonneg env target blocks cert_checked grounds)).
Qed.

End Sos_thm1_S_r_dot_7.

End sos_thm1_S_r_dot_step7.

Module sos_thm1_S_rl_dot_step4.

(** SOS certificate sos-0723deceb163521b67e4.json, exported to Coq.
    It proves step 4 of the derivation 'thm1.S_rl-dot' (verify.paper_proofs): (-1/2) k_s tr(R_rl sk(R_rlᵀ R̄_r)) - (1/2) tr(R_rl hat(ω_h^b)) <= (-1/2) k_s λmin((R_rl + R_rlᵀ)) φ(R_lᵀR̄) + k_s φ(R̄_r) - k_s φ(R_rl) + <vee(sk(R_rl)), ω_h^b>.
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by computation (SOSCert.mult_psd_9r, SOSCert.link_ok). *)

Import Reals QArith List Lra SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.

Section Sos_thm1_S_rl_dot_4.

(** k_s: a scalar *)
Variable v_1_k_s : R.
Hypothesis v_1_k_s_pos : 0 < v_1_k_s.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_R_r : quat.
Hypothesis q_v_2_R_r_nonzero : qn q_v_2_R_r <> 0.
Local Notation v_2_R_r := (rot q_v_2_R_r).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_R_l : quat.
Hypothesis q_v_3_R_l_nonzero : qn q_v_3_R_l <> 0.
Local Notation v_3_R_l := (rot q_v_3_R_l).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_4_Rbar : quat.
Hypothesis q_v_4_Rbar_nonzero : qn q_v_4_Rbar <> 0.
Local Notation v_4_Rbar := (rot q_v_4_Rbar).

(** ω_h^s: a vector *)
Variable v_5_omega_h_s : V3.

(** lambda_min((R_rl + R_rlᵀ)): a lower bound suffices *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (madd (mmul (mT v_2_R_r) v_3_R_l) (mT (mmul (mT v_2_R_r) v_3_R_l))) lam1.

Let env : list R := [v_1_k_s; (qw q_v_2_R_r); (qx q_v_2_R_r); (qy q_v_2_R_r); (qz q_v_2_R_r); (qw q_v_3_R_l); (qx q_v_3_R_l); (qy q_v_3_R_l); (qz q_v_3_R_l); (qw q_v_4_Rbar); (qx q_v_4_Rbar); (qy q_v_4_Rbar); (qz q_v_4_Rbar); (v1 v_5_omega_h_s); (v2 v_5_omega_h_s); (v3 v_5_omega_h_s); lam1].

Definition target : poly := [([1;0;0;0;2;0;0;0;4;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;4;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;0;4;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;4;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;0;4;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;4;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;1;3;0;0;1;1;0;0;0;0]%nat, (-4)%Q); ([1;0;0;0;2;0;0;1;3;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;0;0;2;2;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;2;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;2;2;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;0;2;2;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;2;2;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;2;2;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;0;2;2;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;2;2;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;0;3;1;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;0;0;2;0;0;3;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;0;0;4;0;0;0;0;2;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;0;4;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;4;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;4;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;1;0;3;0;1;0;1;0;0;0;0]%nat, (-4)%Q); ([1;0;0;0;2;0;1;0;3;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;0;1;1;2;0;1;1;0;0;0;0;0]%nat, (-8)%Q); ([1;0;0;0;2;0;1;1;2;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;0;1;2;1;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;0;2;0;1;2;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;0;1;3;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;0;2;0;2;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;2;0;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;0;2;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;2;0;2;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;2;0;2;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;2;0;2;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;0;2;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;2;0;2;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;2;1;1;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;0;0;2;0;2;1;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;0;2;2;0;0;0;0;2;0;0;0;0]%nat, (-4)%Q); ([1;0;0;0;2;0;2;2;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;2;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;2;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;2;0;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;0;3;0;1;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;0;2;0;3;0;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;0;3;1;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;0;4;0;0;0;0;0;2;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;4;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;4;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;4;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;1;0;0;3;1;0;0;1;0;0;0;0]%nat, (-4)%Q); ([1;0;0;0;2;1;0;0;3;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;1;0;1;2;1;0;1;0;0;0;0;0]%nat, (-8)%Q); ([1;0;0;0;2;1;0;1;2;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;1;0;2;1;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;0;2;1;0;2;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;1;0;3;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;1;1;0;2;1;1;0;0;0;0;0;0]%nat, (-8)%Q); ([1;0;0;0;2;1;1;0;2;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;1;1;2;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;1;2;0;1;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;0;2;1;2;0;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;1;2;1;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;1;3;0;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;2;0;0;2;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;2;0;0;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;0;2;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;2;0;0;2;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;2;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;2;0;0;2;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;2;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;2;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;1;1;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;0;0;2;2;0;1;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;2;0;2;0;0;0;0;2;0;0;0;0]%nat, (-4)%Q); ([1;0;0;0;2;2;0;2;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;0;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;2;0;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;0;2;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;1;0;1;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;0;2;2;1;0;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;2;1;1;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;2;2;0;0;0;0;0;2;0;0;0;0]%nat, (-4)%Q); ([1;0;0;0;2;2;2;0;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;2;0;0;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;2;2;2;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;2;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;3;0;0;1;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;0;2;3;0;0;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;3;0;1;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;3;1;0;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;0;0;2;4;0;0;0;0;0;0;2;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;4;0;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;4;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;4;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;1;1;0;0;1;3;0;0;2;0;0;0;0;0]%nat, 8%Q); ([1;0;0;1;1;0;0;1;3;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;0;1;3;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;0;2;2;0;0;1;1;0;0;0;0]%nat, (-16)%Q); ([1;0;0;1;1;0;0;3;1;0;0;0;2;0;0;0;0]%nat, 8%Q); ([1;0;0;1;1;0;0;3;1;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;0;3;1;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;1;0;3;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;1;1;2;0;1;0;1;0;0;0;0]%nat, (-12)%Q); ([1;0;0;1;1;0;1;2;1;0;1;1;0;0;0;0;0]%nat, (-12)%Q); ([1;0;0;1;1;0;1;3;0;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;2;0;2;0;0;1;1;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;2;1;1;0;0;0;2;0;0;0;0]%nat, 8%Q); ([1;0;0;1;1;0;2;1;1;0;0;2;0;0;0;0;0]%nat, 8%Q); ([1;0;0;1;1;0;2;1;1;0;2;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;2;1;1;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;2;2;0;0;0;1;1;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;3;0;1;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;3;1;0;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;4;0;0;0;0;1;1;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;1;0;0;3;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;0;1;2;1;0;0;1;0;0;0;0]%nat, (-12)%Q); ([1;0;0;1;1;1;0;2;1;1;0;1;0;0;0;0;0]%nat, (-12)%Q); ([1;0;0;1;1;1;0;3;0;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;1;1;1;1;1;0;0;0;0;0;0]%nat, (-16)%Q); ([1;0;0;1;1;1;2;0;1;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;2;1;0;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;2;0;0;2;0;0;1;1;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;2;0;1;1;0;0;0;2;0;0;0;0]%nat, 8%Q); ([1;0;0;1;1;2;0;1;1;0;0;2;0;0;0;0;0]%nat, 8%Q); ([1;0;0;1;1;2;0;1;1;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;2;0;1;1;2;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;2;0;2;0;0;0;1;1;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;2;1;0;1;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;2;1;1;0;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;2;2;0;0;0;0;1;1;0;0;0;0]%nat, (-8)%Q); ([1;0;0;1;1;3;0;0;1;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;3;0;1;0;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;4;0;0;0;0;0;1;1;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;0;0;0;4;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;0;0;4;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;4;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;4;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;1;3;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;0;0;1;3;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;0;0;2;2;0;0;0;2;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;0;2;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;2;2;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;2;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;2;2;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;2;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;0;2;2;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;2;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;0;3;1;0;0;1;1;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;0;0;3;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;0;0;4;0;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;4;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;4;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;4;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;4;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;4;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;1;0;3;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;0;1;1;2;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;0;1;1;2;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;0;1;2;1;0;1;0;1;0;0;0;0]%nat, (-8)%Q); ([1;0;0;2;0;0;1;2;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;0;1;3;0;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;0;1;3;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;0;2;0;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;0;2;0;0;2;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;0;2;0;2;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;2;0;2;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;0;2;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;2;1;1;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;0;2;1;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;0;2;2;0;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;2;2;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;2;2;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;2;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;2;0;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;2;2;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;2;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;2;2;0;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;0;3;0;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;0;3;1;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;0;3;1;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;0;4;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;4;0;0;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;4;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;4;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;1;0;0;3;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;1;0;1;2;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;1;0;1;2;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;1;0;2;1;1;0;0;1;0;0;0;0]%nat, (-8)%Q); ([1;0;0;2;0;1;0;2;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;1;0;3;0;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;1;0;3;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;1;1;0;2;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;1;1;2;0;1;1;0;0;0;0;0;0]%nat, (-8)%Q); ([1;0;0;2;0;1;1;2;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;1;2;0;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;1;2;1;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;1;2;1;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;1;3;0;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;2;0;0;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;0;2;0;0;2;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;2;0;0;2;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;0;0;2;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;0;0;2;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;1;1;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;2;0;1;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;2;0;2;0;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;2;0;2;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;0;2;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;2;0;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;2;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;2;0;2;0;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;0;2;0;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;2;0;2;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;1;0;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;2;1;1;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;2;1;1;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;2;2;0;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;2;0;0;0;0;2;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;2;2;0;0;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;0;0;2;0;2;2;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;2;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;3;0;0;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;3;0;1;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;3;0;1;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;3;1;0;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;0;2;0;4;0;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;4;0;0;0;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;4;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;4;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;1;0;1;0;0;1;3;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;0;2;2;0;1;0;1;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;0;3;1;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;0;4;0;0;1;0;1;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;1;0;3;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;1;0;3;0;2;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;0;1;0;1;0;3;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;1;1;2;0;0;1;1;0;0;0;0]%nat, (-12)%Q); ([1;0;1;0;1;0;1;2;1;0;0;0;2;0;0;0;0]%nat, 8%Q); ([1;0;1;0;1;0;1;2;1;0;0;2;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;1;2;1;0;2;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;0;1;0;1;2;1;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;1;3;0;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;2;0;2;0;1;0;1;0;0;0;0]%nat, (-16)%Q); ([1;0;1;0;1;0;2;1;1;0;1;1;0;0;0;0;0]%nat, (-12)%Q); ([1;0;1;0;1;0;2;2;0;0;1;0;1;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;3;0;1;0;0;0;2;0;0;0;0]%nat, 8%Q); ([1;0;1;0;1;0;3;0;1;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;3;0;1;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;3;1;0;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;0;0;3;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;0;2;1;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;1;0;2;1;0;0;1;0;0;0;0]%nat, (-12)%Q); ([1;0;1;0;1;1;1;1;1;1;0;1;0;0;0;0;0]%nat, (-16)%Q); ([1;0;1;0;1;1;1;2;0;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;2;0;1;1;1;0;0;0;0;0;0]%nat, (-12)%Q); ([1;0;1;0;1;1;3;0;0;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;2;0;0;2;0;1;0;1;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;2;0;1;1;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;2;0;2;0;0;1;0;1;0;0;0;0]%nat, (-8)%Q); ([1;0;1;0;1;2;1;0;1;0;0;0;2;0;0;0;0]%nat, 8%Q); ([1;0;1;0;1;2;1;0;1;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;2;1;0;1;0;2;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;0;1;2;1;0;1;2;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;2;1;1;0;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;2;2;0;0;0;1;0;1;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;3;0;0;1;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;3;1;0;0;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;4;0;0;0;0;1;0;1;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;0;0;4;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;0;1;3;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;0;2;2;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;0;3;1;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;1;0;3;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;1;1;2;0;0;0;2;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;1;1;2;0;0;2;0;0;0;0;0]%nat, 8%Q); ([1;0;1;1;0;0;1;1;2;0;2;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;1;0;0;1;1;2;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;1;2;1;0;0;1;1;0;0;0;0]%nat, (-12)%Q); ([1;0;1;1;0;0;1;3;0;0;0;0;2;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;1;3;0;0;2;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;1;0;0;1;3;0;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;2;0;2;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;2;1;1;0;1;0;1;0;0;0;0]%nat, (-12)%Q); ([1;0;1;1;0;0;2;2;0;0;1;1;0;0;0;0;0]%nat, (-16)%Q); ([1;0;1;1;0;0;3;0;1;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;3;1;0;0;0;0;2;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;3;1;0;0;0;2;0;0;0;0;0]%nat, 8%Q); ([1;0;1;1;0;0;3;1;0;2;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;0;1;2;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;0;3;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;1;0;2;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;1;1;1;1;0;0;1;0;0;0;0]%nat, (-16)%Q); ([1;0;1;1;0;1;1;2;0;1;0;1;0;0;0;0;0]%nat, (-12)%Q); ([1;0;1;1;0;1;2;1;0;1;1;0;0;0;0;0;0]%nat, (-12)%Q); ([1;0;1;1;0;1;3;0;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;2;0;0;2;0;1;1;0;0;0;0;0]%nat, (-8)%Q); ([1;0;1;1;0;2;0;1;1;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;2;0;2;0;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;2;1;0;1;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;2;1;1;0;0;0;0;2;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;2;1;1;0;0;0;2;0;0;0;0;0]%nat, 8%Q); ([1;0;1;1;0;2;1;1;0;0;2;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;1;0;2;1;1;0;2;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;2;2;0;0;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;3;0;1;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;3;1;0;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;4;0;0;0;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;0;0;0;4;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;0;4;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;0;4;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;0;4;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;1;3;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;0;0;2;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;2;2;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;2;2;0;2;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;0;0;2;2;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;0;2;2;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;0;3;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;0;0;4;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;4;0;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;4;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;4;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;1;0;3;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;0;1;0;3;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;0;1;1;2;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;0;1;1;2;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;0;1;2;1;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;0;1;2;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;0;1;3;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;0;1;3;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;0;2;0;2;0;0;0;2;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;2;0;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;0;2;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;2;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;2;0;2;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;2;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;0;2;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;2;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;2;1;1;0;0;1;1;0;0;0;0]%nat, (-8)%Q); ([1;0;2;0;0;0;2;1;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;0;2;2;0;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;2;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;2;2;0;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;2;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;2;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;2;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;2;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;2;0;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;0;3;0;1;0;1;0;1;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;0;3;0;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;0;3;1;0;0;1;1;0;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;0;3;1;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;0;4;0;0;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;4;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;4;0;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;4;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;4;0;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;4;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;1;0;0;3;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;1;0;1;2;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;1;0;2;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;1;0;3;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;1;1;0;2;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;1;1;0;2;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;1;1;2;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;1;1;2;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;1;2;0;1;1;0;0;1;0;0;0;0]%nat, (-8)%Q); ([1;0;2;0;0;1;2;0;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;1;2;1;0;1;0;1;0;0;0;0;0]%nat, (-8)%Q); ([1;0;2;0;0;1;2;1;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;1;3;0;0;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;1;3;0;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;2;0;0;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;0;2;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;0;0;2;0;2;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;2;0;0;2;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;0;0;2;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;1;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;2;0;2;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;0;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;2;0;0;2;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;2;0;2;0;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;0;2;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;1;0;1;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;2;1;0;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;2;1;1;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;2;1;1;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;2;2;0;0;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;2;2;0;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;2;0;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;2;2;0;0;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;0;2;0;0;2;2;0;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;2;2;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;2;0;0;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;2;2;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;3;0;0;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;3;0;1;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;3;1;0;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;3;1;0;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;0;2;0;0;4;0;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;4;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;4;0;0;0;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;4;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;1;0;0;1;0;0;1;3;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;0;2;2;1;0;0;1;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;0;3;1;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;0;4;0;1;0;0;1;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;1;0;3;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;1;2;1;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;2;0;2;1;0;0;1;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;2;1;1;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;2;2;0;1;0;0;1;0;0;0;0]%nat, (-8)%Q); ([1;1;0;0;1;0;3;0;1;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;4;0;0;1;0;0;1;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;1;0;0;3;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;0;0;3;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;0;0;3;2;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;1;0;1;2;0;0;1;1;0;0;0;0]%nat, (-12)%Q); ([1;1;0;0;1;1;0;2;1;0;0;0;2;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;1;0;2;1;0;0;2;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;1;0;2;1;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;0;2;1;2;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;1;0;3;0;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;1;0;2;0;1;0;1;0;0;0;0]%nat, (-12)%Q); ([1;1;0;0;1;1;1;1;1;0;1;1;0;0;0;0;0]%nat, (-16)%Q); ([1;1;0;0;1;1;1;2;0;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;2;0;1;0;0;0;2;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;1;2;0;1;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;2;0;1;0;2;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;1;2;0;1;2;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;1;2;1;0;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;3;0;0;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;2;0;0;2;1;0;0;1;0;0;0;0]%nat, (-16)%Q); ([1;1;0;0;1;2;0;1;1;1;0;1;0;0;0;0;0]%nat, (-12)%Q); ([1;1;0;0;1;2;0;2;0;1;0;0;1;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;2;1;0;1;1;1;0;0;0;0;0;0]%nat, (-12)%Q); ([1;1;0;0;1;2;2;0;0;1;0;0;1;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;3;0;0;1;0;0;0;2;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;3;0;0;1;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;3;0;0;1;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;3;0;1;0;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;3;1;0;0;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;0;0;0;4;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;1;3;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;0;0;2;2;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;3;1;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;0;1;1;2;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;0;1;3;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;0;2;0;2;1;0;1;0;0;0;0;0]%nat, (-8)%Q); ([1;1;0;1;0;0;2;1;1;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;0;2;2;0;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;3;1;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;0;4;0;0;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;1;0;0;3;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;0;1;2;0;0;0;2;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;1;0;1;2;0;0;2;0;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;1;0;1;2;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;0;1;2;2;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;1;0;2;1;0;0;1;1;0;0;0;0]%nat, (-12)%Q); ([1;1;0;1;0;1;0;3;0;0;0;0;2;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;0;3;0;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;0;3;0;2;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;1;1;0;2;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;1;1;1;0;1;0;1;0;0;0;0]%nat, (-16)%Q); ([1;1;0;1;0;1;1;2;0;0;1;1;0;0;0;0;0]%nat, (-12)%Q); ([1;1;0;1;0;1;2;0;1;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;2;1;0;0;0;0;2;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;2;1;0;0;0;2;0;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;1;2;1;0;0;2;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;1;2;1;0;2;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;1;3;0;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;2;0;0;2;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;2;0;1;1;1;0;0;1;0;0;0;0]%nat, (-12)%Q); ([1;1;0;1;0;2;0;2;0;1;0;1;0;0;0;0;0]%nat, (-16)%Q); ([1;1;0;1;0;2;1;1;0;1;1;0;0;0;0;0;0]%nat, (-12)%Q); ([1;1;0;1;0;2;2;0;0;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;3;0;0;1;0;0;1;1;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;3;0;1;0;0;0;0;2;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;3;0;1;0;0;0;2;0;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;3;0;1;0;0;2;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;3;1;0;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;0;0;4;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;0;2;2;1;1;0;0;0;0;0;0]%nat, (-8)%Q); ([1;1;1;0;0;0;0;4;0;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;1;0;3;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;1;1;2;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;1;2;1;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;1;3;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;2;0;2;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;2;2;0;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;3;0;1;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;3;1;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;0;0;3;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;0;1;2;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;0;2;1;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;0;3;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;1;0;2;0;0;0;2;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;1;1;0;2;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;1;0;2;0;2;0;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;1;1;0;2;2;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;1;1;1;1;0;0;1;1;0;0;0;0]%nat, (-16)%Q); ([1;1;1;0;0;1;1;2;0;0;0;0;2;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;1;2;0;0;0;2;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;1;1;2;0;0;2;0;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;1;1;2;0;2;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;1;2;0;1;0;1;0;1;0;0;0;0]%nat, (-12)%Q); ([1;1;1;0;0;1;2;1;0;0;1;1;0;0;0;0;0]%nat, (-12)%Q); ([1;1;1;0;0;1;3;0;0;0;0;0;2;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;3;0;0;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;3;0;0;2;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;2;0;0;2;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;2;0;2;0;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;2;1;0;1;1;0;0;1;0;0;0;0]%nat, (-12)%Q); ([1;1;1;0;0;2;1;1;0;1;0;1;0;0;0;0;0]%nat, (-12)%Q); ([1;1;1;0;0;2;2;0;0;1;1;0;0;0;0;0;0]%nat, (-16)%Q); ([1;1;1;0;0;3;0;0;1;0;1;0;1;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;3;0;1;0;0;1;1;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;3;1;0;0;0;0;0;2;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;3;1;0;0;0;0;2;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;3;1;0;0;0;2;0;0;0;0;0;0]%nat, 8%Q); ([1;2;0;0;0;0;0;0;4;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;0;4;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;0;4;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;0;4;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;1;3;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;0;0;2;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;2;2;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;2;2;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;0;2;2;2;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;0;2;2;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;0;3;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;0;0;4;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;4;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;4;0;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;4;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;1;0;3;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;0;1;1;2;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;0;1;2;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;0;1;3;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;0;2;0;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;0;2;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;2;0;2;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;0;2;2;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;2;0;2;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;2;1;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;0;2;2;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;2;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;2;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;2;0;2;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;2;2;0;2;0;0;0;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;0;3;0;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;0;3;1;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;0;4;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;4;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;4;0;0;2;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;4;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;1;0;0;3;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;0;0;3;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;1;0;1;2;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;0;1;2;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;1;0;2;1;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;0;2;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;1;0;3;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;0;3;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;1;1;0;2;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;1;0;2;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;1;1;2;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;1;2;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;1;2;0;1;1;0;0;1;0;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;2;0;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;1;2;1;0;1;0;1;0;0;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;2;1;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;1;3;0;0;1;1;0;0;0;0;0;0]%nat, 4%Q); ([1;2;0;0;0;1;3;0;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;2;0;0;2;0;0;0;2;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;2;0;0;2;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;0;2;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;2;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;0;0;2;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;2;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;0;0;2;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;2;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;1;1;0;0;1;1;0;0;0;0]%nat, (-8)%Q); ([1;2;0;0;0;2;0;1;1;0;0;1;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;2;0;2;0;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;2;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;0;2;0;0;0;2;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;2;0;2;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;2;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;2;0;0;2;0;0;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;0;2;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;2;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;1;0;1;0;1;0;1;0;0;0;0]%nat, (-8)%Q); ([1;2;0;0;0;2;1;0;1;0;1;0;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;2;1;1;0;0;1;1;0;0;0;0;0]%nat, (-8)%Q); ([1;2;0;0;0;2;1;1;0;0;1;1;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;2;2;0;0;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;2;0;0;0;0;0;2;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;2;0;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;2;0;0;0;0;2;0;0;0;0;1]%nat, (-2)%Q); ([1;2;0;0;0;2;2;0;0;0;2;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;2;2;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;2;0;0;2;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;2;0;0;2;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;3;0;0;1;1;0;0;1;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;3;0;0;1;1;0;0;1;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;3;0;1;0;1;0;1;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;3;0;1;0;1;0;1;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;3;1;0;0;1;1;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;3;1;0;0;1;1;0;0;0;0;0;1]%nat, 2%Q); ([1;2;0;0;0;4;0;0;0;0;0;0;2;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;4;0;0;0;0;0;0;2;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;4;0;0;0;0;0;2;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;4;0;0;0;0;0;2;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;4;0;0;0;0;2;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;4;0;0;0;0;2;0;0;0;0;0;1]%nat, (-1)%Q)].

(** block 1: k_s > 0 (declared) × spectral: λmin((R_rl + R_rlᵀ)) I ⪯ (R_rl + R_rlᵀ) (symmetric) *)
Definition H1 : list (list poly) := [[[([1;0;0;0;2;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;1;0;1;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;0;1;1;0;1;0;0;0;0;0;0;0;0;0]%nat, (-8)%Q); ([1;0;1;1;0;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;1;0;1;0;0;1;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;1;0;0;1;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;0;0;1;1;0;0;1;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;0;1;0;1;0;0;0;0;0;0;0;0]%nat, (-8)%Q); ([1;1;0;1;0;1;0;1;0;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q)]; [([1;0;0;0;2;0;1;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;0;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;1;0;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;1;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;1;0;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;2;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;1;1;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;0;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q)]; [([1;0;0;0;2;1;0;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;0;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;0;1;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;0;2;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;1;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;1;0;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;1;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;1;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;1;0;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q)]]; [[([1;0;0;0;2;0;1;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;0;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;2;0;1;0;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;1;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;1;0;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;2;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;1;1;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;1;0;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q)]; [([1;0;0;0;2;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;1;1;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;0;0;1;1;1;1;0;0;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;1;1;0;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;1;0;1;0;0;1;0;0;0;0;0;0;0;0]%nat, (-8)%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;1;0;0;1;0;1;1;0;0;0;0;0;0;0;0;0]%nat, (-8)%Q); ([1;1;0;0;1;1;0;0;1;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;1;1;0;0;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q)]; [([1;0;0;0;2;1;1;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;2;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;1;1;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;0;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;0;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;1;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;1;0;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;0;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 4%Q)]]; [[([1;0;0;0;2;1;0;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;1;0;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;0;1;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;0;2;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;1;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;2;0;0;1;0;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;0;1;1;1;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;1;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;1;0;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q)]; [([1;0;0;0;2;1;1;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;1;1;0;2;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;0;1;1;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;0;2;0;1;1;0;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;0;1;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;0;1;1;0;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;0;1;1;0;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;1;1;0;1;0;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;0;2;0;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;0;1;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;0;1;1;0;1;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;0;1;0;0;1;1;0;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;0;1;0;1;0;0;1;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;1;1;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 4%Q); ([1;1;1;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, (-4)%Q); ([1;2;0;0;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 4%Q)]; [([1;0;0;0;2;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;0;2;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;0;2;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;1;1;0;0;1;1;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;0;0;1;1;1;1;0;0;0;0;0;0;0;0;0;0]%nat, (-8)%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;0;2;0;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;0;2;0;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;1;0;1;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;0;1;0;1;1;0;1;0;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;0;2;0;0;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;0;2;0;0;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;1;0;1;0;0;1;0;1;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;0;1;0;1;0;1;0;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;1;1;0;0;0;0;1;1;0;0;0;0;0;0;0;0]%nat, (-8)%Q); ([1;1;1;0;0;1;1;0;0;0;0;0;0;0;0;0;0]%nat, 8%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;0;0;0;2;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;0;2;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;0;0;0;0]%nat, (-2)%Q); ([1;2;0;0;0;0;2;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;0;0;0;0]%nat, 2%Q); ([1;2;0;0;0;2;0;0;0;0;0;0;0;0;0;0;1]%nat, (-1)%Q)]]].
Definition S1 : list (Q * list poly) :=
  [((1#2)%Q, [[([0;0;0;0;0;0;0;0;1;0;1;0;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;1;0;0;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;0;1;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;0;1;0;0;0;0;0]%nat, (-1)%Q)]; [([0;0;0;0;0;0;0;0;1;0;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;0;0;0;1;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;0;1;0;0;1;0;0;0;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;1;0;0;0;0;0;0]%nat, 1%Q)]; []]);
   ((1#2)%Q, [[([0;0;0;0;0;0;0;0;1;1;0;0;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;0;1;0;0;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;0;1;0;0;0;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;1;0;0;0;0]%nat, (-1)%Q)]; []; [([0;0;0;0;0;0;0;0;1;0;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;0;0;0;1;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;0;1;0;0;1;0;0;0;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;1;0;0;0;0;0;0]%nat, 1%Q)]]);
   ((1#2)%Q, [[]; [([0;0;0;0;0;0;0;0;1;1;0;0;0;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;0;0;1;0;0;1;0;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;1;0;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;1;0;0;0;0]%nat, 1%Q)]; [([0;0;0;0;0;0;0;0;1;0;1;0;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;1;0;0;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;0;1;0;0;0;0]%nat, (-1)%Q); ([0;0;0;0;0;1;0;0;0;0;0;1;0;0;0;0;0]%nat, (-1)%Q)]])].

Lemma H1_psd : mult_psd env H1.
Proof.
  unfold H1. sos_psd9 [v_1_k_s; (qw q_v_2_R_r); (qx q_v_2_R_r); (qy q_v_2_R_r); (qz q_v_2_R_r); (qw q_v_3_R_l); (qx q_v_3_R_l); (qy q_v_3_R_l); (qz q_v_3_R_l); (qw q_v_4_Rbar); (qx q_v_4_Rbar); (qy q_v_4_Rbar); (qz q_v_4_Rbar); (v1 v_5_omega_h_s); (v2 v_5_omega_h_s); (v3 v_5_omega_h_s); lam1] (v_1_k_s) (msub (sym (madd (mmul (mT v_2_R_r) v_3_R_l) (mT (mmul (mT v_2_R_r) v_3_R_l)))) (mscale lam1 I3)) [0; 1; 0; 0; 0; 1; 0; 0; 0; 0; 0; 0; 0; 0; 0; 0; 0]%nat.
  - exact (Rlt_le _ _ v_1_k_s_pos).
  - exact lam1_spec.
Qed.

Definition blocks : list block := [(mkBlock H1 S1)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_cast_no_check (eq_refl true). Qed.

Lemma grounds : blocks_psd env blocks.
Proof. exact (blocks_psd_cons env (mkBlock H1 S1) _ H1_psd (blocks_psd_nil env)). Qed.

(** The link, by computation: the statement's slack, read as an expression of the prelude's operations (sos_reify), times a positive product of quaternion norms is the target polynomial at the parameters times a non-negative one. *)
Lemma link : exists D F, 0 < D /\ 0 <= F /\ ((((((((-1/2) * v_1_k_s) * lam1) * (phi (mmul (mT v_3_R_l) v_4_Rbar))) + (v_1_k_s * (phi (mmul (mT v_2_R_r) v_4_Rbar)))) + (- (v_1_k_s * (phi (mmul (mT v_2_R_r) v_3_R_l))))) + (vdot (vee (sk (mmul (mT v_2_R_r) v_3_R_l))) (mvmul (mT v_3_R_l) v_5_omega_h_s))) + - ((((-1/2) * v_1_k_s) * (tr (mmul (mmul (mT v_2_R_r) v_3_R_l) (sk (mmul (mT (mmul (mT v_2_R_r) v_3_R_l)) (mmul (mT v_2_R_r) v_4_Rbar)))))) + (- ((1/2) * (tr (mmul (mmul (mT v_2_R_r) v_3_R_l) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s)))))))) * D = F * peval env target.
Proof.
  assert (Hq : Forall (fun p => qnR env p <> 0) [1; 5; 9]%nat) by (apply Forall_cons; [exact q_v_2_R_r_nonzero|]; apply Forall_cons; [exact q_v_3_R_l_nonzero|]; apply Forall_cons; [exact q_v_4_Rbar_nonzero|]; apply Forall_nil).
  sos_link [v_1_k_s; (qw q_v_2_R_r); (qx q_v_2_R_r); (qy q_v_2_R_r); (qz q_v_2_R_r); (qw q_v_3_R_l); (qx q_v_3_R_l); (qy q_v_3_R_l); (qz q_v_3_R_l); (qw q_v_4_Rbar); (qx q_v_4_Rbar); (qy q_v_4_Rbar); (qz q_v_4_Rbar); (v1 v_5_omega_h_s); (v2 v_5_omega_h_s); (v3 v_5_omega_h_s); lam1] [1; 5; 9]%nat Hq [0; 1; 0; 0; 0; 2; 0; 0; 0; 1]%nat.
Qed.

Theorem step4_by_sos : ((((-1/2) * v_1_k_s) * (tr (mmul (mmul (mT v_2_R_r) v_3_R_l) (sk (mmul (mT (mmul (mT v_2_R_r) v_3_R_l)) (mmul (mT v_2_R_r) v_4_Rbar)))))) + (- ((1/2) * (tr (mmul (mmul (mT v_2_R_r) v_3_R_l) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s))))))) <= (((((((-1/2) * v_1_k_s) * lam1) * (phi (mmul (mT v_3_R_l) v_4_Rbar))) + (v_1_k_s * (phi (mmul (mT v_2_R_r) v_4_Rbar)))) + (- (v_1_k_s * (phi (mmul (mT v_2_R_r) v_3_R_l))))) + (vdot (vee (sk (mmul (mT v_2_R_r) v_3_R_l))) (mvmul (mT v_3_R_l) v_5_omega_h_s))).
Proof.
  apply (le_by_slack _ _ ((((((((-1/2) * v_1_k_s) * lam1) * (phi (mmul (mT v_3_R_l) v_4_Rbar))) + (v_1_k_s * (phi (mmul (mT v_2_R_r) v_4_Rbar)))) + (- (v_1_k_s * (phi (mmul (mT v_2_R_r) v_3_R_l))))) + (vdot (vee (sk (mmul (mT v_2_R_r) v_3_R_l))) (mvmul (mT v_3_R_l) v_5_omega_h_s))) + - ((((-1/2) * v_1_k_s) * (tr (mmul (mmul (mT v_2_R_r) v_3_R_l) (sk (mmul (mT (mmul (mT v_2_R_r) v_3_R_l)) (mmul (mT v_2_R_r) v_4_Rbar)))))) + (- ((1/2) * (tr (mmul (mmul (mT v_2_R_r) v_3_R_l) (hat (mvmul (mT v_3_R_l) v_5_omega_h_s))))))))); [reflexivity|].
  destruct link as (D & F & HD & HF & E).
  exact (slack_nonneg _ D F _ E HD HF (sos_nonneg env target blocks cert_checked grounds)).
Qed.

End Sos_thm1_S_rl_dot_4.

End sos_thm1_S_rl_dot_step4.

Module sos_thm1_V_dot_step3.

(** SOS certificate sos-3c0bd7455cbf7e25ea7e.json, exported to Coq.
    It proves step 3 of the derivation 'thm1.V-dot' (verify.paper_proofs): (-1/2) k_s (λmin((R̄_r + R̄_rᵀ)) + λmin((R_rl + R_rlᵀ))) φ(R_lᵀR̄) <= 0.
    The certificate's data (target polynomial, multipliers, LDL^T squares) is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and the link from the statement to the target polynomial are proved by computation (SOSCert.mult_psd_9r, SOSCert.link_ok). *)

Import Reals QArith List Lra SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.

Section Sos_thm1_V_dot_3.

(** k_s: a scalar *)
Variable v_1_k_s : R.
Hypothesis v_1_k_s_pos : 0 < v_1_k_s.

(** R_r: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_2_R_r : quat.
Hypothesis q_v_2_R_r_nonzero : qn q_v_2_R_r <> 0.
Local Notation v_2_R_r := (rot q_v_2_R_r).

(** R̄: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_3_Rbar : quat.
Hypothesis q_v_3_Rbar_nonzero : qn q_v_3_Rbar <> 0.
Local Notation v_3_Rbar := (rot q_v_3_Rbar).

(** R_l: a rotation, rot q with |q|^2 <> 0 *)
Variable q_v_4_R_l : quat.
Hypothesis q_v_4_R_l_nonzero : qn q_v_4_R_l <> 0.
Local Notation v_4_R_l := (rot q_v_4_R_l).

(** lambda_min((R̄_r + R̄_rᵀ)): a lower bound suffices *)
Variable lam1 : R.
Hypothesis lam1_spec : lam_min_spec (madd (mmul (mT v_2_R_r) v_3_Rbar) (mT (mmul (mT v_2_R_r) v_3_Rbar))) lam1.

(** lambda_min((R_rl + R_rlᵀ)): a lower bound suffices *)
Variable lam2 : R.
Hypothesis lam2_spec : lam_min_spec (madd (mmul (mT v_2_R_r) v_4_R_l) (mT (mmul (mT v_2_R_r) v_4_R_l))) lam2.

(** assumption: λmin(R̄_r + R̄_rᵀ) ≥ 0 (Lemma 1) *)
Hypothesis assumption1 : 0 <= lam1.

(** assumption: λmin(R_rl + R_rlᵀ) > 0 (Assumption 1, item 2) *)
Hypothesis assumption2 : 0 < lam2.

Let env : list R := [v_1_k_s; (qw q_v_2_R_r); (qx q_v_2_R_r); (qy q_v_2_R_r); (qz q_v_2_R_r); (qw q_v_3_Rbar); (qx q_v_3_Rbar); (qy q_v_3_Rbar); (qz q_v_3_Rbar); (qw q_v_4_R_l); (qx q_v_4_R_l); (qy q_v_4_R_l); (qz q_v_4_R_l); lam1; lam2].

Definition target : poly := [([1;0;0;0;0;0;0;0;2;0;0;2;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;0;2;0;0;2;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;0;0;2;0;2;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;0;2;0;2;0;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;0;0;2;2;0;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;0;2;2;0;0;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;0;1;1;0;0;1;1;0;1]%nat, (-2)%Q); ([1;0;0;0;0;0;0;1;1;0;0;1;1;1;0]%nat, (-2)%Q); ([1;0;0;0;0;0;0;2;0;0;0;0;2;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;2;0;0;0;0;2;1;0]%nat, 1%Q); ([1;0;0;0;0;0;0;2;0;0;2;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;2;0;0;2;0;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;0;2;0;2;0;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;0;2;0;2;0;0;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;1;0;1;0;1;0;1;0;1]%nat, (-2)%Q); ([1;0;0;0;0;0;1;0;1;0;1;0;1;1;0]%nat, (-2)%Q); ([1;0;0;0;0;0;1;1;0;0;1;1;0;0;1]%nat, (-2)%Q); ([1;0;0;0;0;0;1;1;0;0;1;1;0;1;0]%nat, (-2)%Q); ([1;0;0;0;0;0;2;0;0;0;0;0;2;0;1]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;0;0;0;2;1;0]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;0;0;2;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;0;0;2;0;1;0]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;2;0;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;0;2;0;0;2;0;0;0;1;0]%nat, 1%Q); ([1;0;0;0;0;1;0;0;1;1;0;0;1;0;1]%nat, (-2)%Q); ([1;0;0;0;0;1;0;0;1;1;0;0;1;1;0]%nat, (-2)%Q); ([1;0;0;0;0;1;0;1;0;1;0;1;0;0;1]%nat, (-2)%Q); ([1;0;0;0;0;1;0;1;0;1;0;1;0;1;0]%nat, (-2)%Q); ([1;0;0;0;0;1;1;0;0;1;1;0;0;0;1]%nat, (-2)%Q); ([1;0;0;0;0;1;1;0;0;1;1;0;0;1;0]%nat, (-2)%Q); ([1;0;0;0;0;2;0;0;0;0;0;0;2;0;1]%nat, 1%Q); ([1;0;0;0;0;2;0;0;0;0;0;0;2;1;0]%nat, 1%Q); ([1;0;0;0;0;2;0;0;0;0;0;2;0;0;1]%nat, 1%Q); ([1;0;0;0;0;2;0;0;0;0;0;2;0;1;0]%nat, 1%Q); ([1;0;0;0;0;2;0;0;0;0;2;0;0;0;1]%nat, 1%Q); ([1;0;0;0;0;2;0;0;0;0;2;0;0;1;0]%nat, 1%Q)].

(** block 1: k_s > 0 (declared) × assumed: λmin(R̄_r + R̄_rᵀ) ≥ 0 *)
Definition H1 : list (list poly) := [[[([1;0;0;0;0;0;0;0;0;0;0;0;0;1;0]%nat, 1%Q)]]].
Definition S1 : list (Q * list poly) :=
  [(1%Q, [[([0;0;0;0;0;0;0;0;1;0;0;1;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;1;0;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;1;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;1;0;0;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;1;0;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;1;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;0;1;0;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;1;0;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;1;0;0;0;0]%nat, (-1)%Q)]])].

Lemma H1_psd : mult_psd env H1.
Proof.
  unfold H1. apply mult_psd_scalar.
  rewrite zeval_peval by (vm_compute; reflexivity).
  match goal with |- 0 <= ?g => replace g with (v_1_k_s * lam1) by (cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]; so3_unfold; field; sos_nonzero) end.
  exact (Rmult_le_pos _ _ (Rlt_le _ _ v_1_k_s_pos) assumption1).
Qed.

(** block 2: k_s > 0 (declared) × assumed: λmin(R_rl + R_rlᵀ) > 0 *)
Definition H2 : list (list poly) := [[[([1;0;0;0;0;0;0;0;0;0;0;0;0;0;1]%nat, 1%Q)]]].
Definition S2 : list (Q * list poly) :=
  [(1%Q, [[([0;0;0;0;0;0;0;0;1;0;0;1;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;0;1;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;1;0;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;0;1;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;0;0;1;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;1;0;0;1;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;0;1;0;0;0;0;1;0;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;0;1;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;0;1;0;0;0]%nat, (-1)%Q)]]);
   (1%Q, [[([0;0;0;0;0;0;1;0;0;1;0;0;0;0;0]%nat, 1%Q); ([0;0;0;0;0;1;0;0;0;0;1;0;0;0;0]%nat, (-1)%Q)]])].

Lemma H2_psd : mult_psd env H2.
Proof.
  unfold H2. apply mult_psd_scalar.
  rewrite zeval_peval by (vm_compute; reflexivity).
  match goal with |- 0 <= ?g => replace g with (v_1_k_s * lam2) by (cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]; so3_unfold; field; sos_nonzero) end.
  exact (Rmult_le_pos _ _ (Rlt_le _ _ v_1_k_s_pos) (Rlt_le _ _ assumption2)).
Qed.

Definition blocks : list block := [(mkBlock H1 S1); (mkBlock H2 S2)].

Lemma cert_checked : cert_ok target blocks = true.
Proof. vm_cast_no_check (eq_refl true). Qed.

Lemma grounds : blocks_psd env blocks.
Proof. exact (blocks_psd_cons env (mkBlock H1 S1) _ H1_psd (blocks_psd_cons env (mkBlock H2 S2) _ H2_psd (blocks_psd_nil env))). Qed.

(** The link, by computation: the statement's slack, read as an expression of the prelude's operations (sos_reify), times a positive product of quaternion norms is the target polynomial at the parameters times a non-negative one. *)
Lemma link : exists D F, 0 < D /\ 0 <= F /\ (0 + - ((((-1/2) * v_1_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_4_R_l) v_3_Rbar)))) * D = F * peval env target.
Proof.
  assert (Hq : Forall (fun p => qnR env p <> 0) [1; 5; 9]%nat) by (apply Forall_cons; [exact q_v_2_R_r_nonzero|]; apply Forall_cons; [exact q_v_3_Rbar_nonzero|]; apply Forall_cons; [exact q_v_4_R_l_nonzero|]; apply Forall_nil).
  sos_link [v_1_k_s; (qw q_v_2_R_r); (qx q_v_2_R_r); (qy q_v_2_R_r); (qz q_v_2_R_r); (qw q_v_3_Rbar); (qx q_v_3_Rbar); (qy q_v_3_Rbar); (qz q_v_3_Rbar); (qw q_v_4_R_l); (qx q_v_4_R_l); (qy q_v_4_R_l); (qz q_v_4_R_l); lam1; lam2] [1; 5; 9]%nat Hq [0; 0; 0; 0; 0; 1; 0; 0; 0; 1]%nat.
Qed.

Theorem step3_by_sos : ((((-1/2) * v_1_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_4_R_l) v_3_Rbar))) <= 0.
Proof.
  apply (le_by_slack _ _ (0 + - ((((-1/2) * v_1_k_s) * (lam1 + lam2)) * (phi (mmul (mT v_4_R_l) v_3_Rbar))))); [reflexivity|].
  destruct link as (D & F & HD & HF & E).
  exact (slack_nonneg _ D F _ E HD HF (sos_nonneg env target blocks cert_checked grounds)).
Qed.

End Sos_thm1_V_dot_3.

End sos_thm1_V_dot_step3.
