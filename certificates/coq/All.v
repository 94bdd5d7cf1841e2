From VerifyCoq Require lemma1_spectrum.
From VerifyCoq Require lemma1_spectrum_projector.
From VerifyCoq Require lemma1_spectrum_rank.
From VerifyCoq Require lemma1_trace_form.
From VerifyCoq Require sec3_rbar_dot_form.
From VerifyCoq Require lemma1_h_dot.
From VerifyCoq Require lemma1_boundary_square.
From VerifyCoq Require lemma1_boundary_h_dot.
From VerifyCoq Require lemma1_boundary_sign_direct.
From VerifyCoq Require lemma1_gradient_form.
From VerifyCoq Require lemma1_gradient_nonzero.
From VerifyCoq Require lemma1_gradient_vanishes_at_pi.
From VerifyCoq Require lemma1_trace_inequality_psd.
From VerifyCoq Require lemma1_trace_inequality_sym_psd.
From VerifyCoq Require thm1_phi.
From VerifyCoq Require thm1_S_r_dot.
From VerifyCoq Require thm1_S_rl_dot.
From VerifyCoq Require thm1_S_h_sign.
From VerifyCoq Require thm1_V_dot.
From VerifyCoq Require thm1_V_dot_zero_implies_sync.
From VerifyCoq Require thm1_V_dot_zero_on_sync.
From VerifyCoq Require thm1_lasalle_derivative.
From VerifyCoq Require thm1_lasalle_derivative_from_sk_only.
From VerifyCoq Require sos_lemma1_boundary_h_dot_step4.
From VerifyCoq Require sos_lemma1_boundary_h_dot_step5.
From VerifyCoq Require sos_lemma1_boundary_sign_direct_step1.
From VerifyCoq Require sos_lemma1_trace_inequality_psd_step1.
From VerifyCoq Require sos_lemma1_trace_inequality_sym_psd_step1.
From VerifyCoq Require sos_thm1_S_r_dot_step7.
From VerifyCoq Require sos_thm1_S_rl_dot_step4.
From VerifyCoq Require sos_thm1_V_dot_step3.
From VerifyCoq Require Cert_nonpassive_human_identified_robust_band_0_1_46_e70cf8beb9e5.
From VerifyCoq Require Cert_nonpassive_human_identified_robust_refuted_at_2_88945_ca067ce3563c.
From VerifyCoq Require Cert_passive_human_identified_robust_band_0_7_97_3da104e65018.
From VerifyCoq Require Cert_reconstructed_k_s_2_5_band_0_1_5_f0739b7ae628.
From VerifyCoq Require Cert_reconstructed_k_s_3_0_99babda880e6.
From VerifyCoq Require Thm1_reconstructed_k_s_3_0_99babda880e6.
From VerifyCoq Require Conclusions.

(** Every top theorem of the development. *)
Definition top_theorems :=
  (lemma1_spectrum.step1,
   lemma1_spectrum_projector.step1,
   lemma1_spectrum_rank.step1,
   lemma1_trace_form.step1,
   sec3_rbar_dot_form.step1,
   lemma1_h_dot.step1,
   lemma1_h_dot.step2,
   lemma1_h_dot.step3,
   lemma1_h_dot.step4,
   lemma1_h_dot.claim,
   lemma1_h_dot.ddt,
   lemma1_boundary_square.step1,
   lemma1_boundary_square.step2,
   lemma1_boundary_square.step3,
   lemma1_boundary_square.claim,
   lemma1_boundary_h_dot.step1,
   lemma1_boundary_h_dot.step2,
   lemma1_boundary_h_dot.step3,
   lemma1_boundary_h_dot.step4,
   lemma1_boundary_h_dot.step5,
   lemma1_boundary_h_dot.claim,
   lemma1_boundary_sign_direct.step1,
   lemma1_gradient_form.step1,
   lemma1_gradient_nonzero.step1,
   lemma1_gradient_nonzero.step2,
   lemma1_gradient_nonzero.claim,
   lemma1_gradient_vanishes_at_pi.step1,
   lemma1_gradient_vanishes_at_pi.step2,
   lemma1_gradient_vanishes_at_pi.claim,
   lemma1_trace_inequality_psd.step1,
   lemma1_trace_inequality_sym_psd.step1,
   thm1_phi.step1,
   thm1_S_r_dot.step1,
   thm1_S_r_dot.step2,
   thm1_S_r_dot.step3,
   thm1_S_r_dot.step4,
   thm1_S_r_dot.step5,
   thm1_S_r_dot.step6,
   thm1_S_r_dot.step7,
   thm1_S_r_dot.claim,
   thm1_S_r_dot.ddt,
   thm1_S_rl_dot.step1,
   thm1_S_rl_dot.step2,
   thm1_S_rl_dot.step3,
   thm1_S_rl_dot.step4,
   thm1_S_rl_dot.claim,
   thm1_S_rl_dot.ddt,
   thm1_S_h_sign.step1,
   thm1_V_dot.step1,
   thm1_V_dot.step2,
   thm1_V_dot.step3,
   thm1_V_dot.claim,
   thm1_V_dot.ddt,
   thm1_V_dot_zero_implies_sync.step1,
   thm1_V_dot_zero_on_sync.step1,
   thm1_V_dot_zero_on_sync.ddt,
   thm1_lasalle_derivative.step1,
   thm1_lasalle_derivative.step2,
   thm1_lasalle_derivative.claim,
   thm1_lasalle_derivative.ddt,
   thm1_lasalle_derivative_from_sk_only.step1,
   thm1_lasalle_derivative_from_sk_only.ddt,
   sos_lemma1_boundary_h_dot_step4.step4_by_sos,
   sos_lemma1_boundary_h_dot_step5.step5_by_sos,
   sos_lemma1_boundary_sign_direct_step1.step1_by_sos,
   sos_lemma1_trace_inequality_psd_step1.step1_by_sos,
   sos_lemma1_trace_inequality_sym_psd_step1.step1_by_sos,
   sos_thm1_S_r_dot_step7.step7_by_sos,
   sos_thm1_S_rl_dot_step4.step4_by_sos,
   sos_thm1_V_dot_step3.step3_by_sos,
   Cert_nonpassive_human_identified_robust_band_0_1_46_e70cf8beb9e5.sigma_inverse,
   Cert_nonpassive_human_identified_robust_band_0_1_46_e70cf8beb9e5.robust_passive,
   Cert_nonpassive_human_identified_robust_refuted_at_2_88945_ca067ce3563c.sigma_inverse,
   Cert_nonpassive_human_identified_robust_refuted_at_2_88945_ca067ce3563c.robust_not_passive,
   Cert_passive_human_identified_robust_band_0_7_97_3da104e65018.sigma_inverse,
   Cert_passive_human_identified_robust_band_0_7_97_3da104e65018.robust_passive,
   Cert_reconstructed_k_s_2_5_band_0_1_5_f0739b7ae628.passive_on_band,
   Conclusions.every_rotation_is_rot_q,
   Conclusions.lemma1_invariance_on_interval,
   Conclusions.lemma1_invariance_on_half_line,
   Conclusions.thm1_energy_nonincreasing,
   Conclusions.thm1_phi_sync_converges,
   Conclusions.barbalat_second_form,
   Conclusions.thm1_lasalle_relative_rate,
   Conclusions.thm1_leader_average_axes,
   Conclusions.thm1_human_command_vanishes,
   Conclusions.thm1_dbar_converges_to_dr).
Print Assumptions top_theorems.

(** The top theorems checked on machine integers. *)
Definition word_theorems :=
  (Cert_reconstructed_k_s_3_0_99babda880e6.passive,
   Thm1_reconstructed_k_s_3_0_99babda880e6.thm1_energy,
   Thm1_reconstructed_k_s_3_0_99babda880e6.thm1_sync).
Print Assumptions word_theorems.
