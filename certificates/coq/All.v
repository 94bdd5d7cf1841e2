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
From VerifyCoq Require Cert_reconstructed_k_s_2_5_band_0_1_5_f0739b7ae628.
From VerifyCoq Require Cert_reconstructed_k_s_3_0_99babda880e6.
Print Assumptions lemma1_spectrum.step1.
Print Assumptions lemma1_spectrum_projector.step1.
Print Assumptions lemma1_spectrum_rank.step1.
Print Assumptions lemma1_trace_form.step1.
Print Assumptions sec3_rbar_dot_form.step1.
Print Assumptions lemma1_h_dot.step1.
Print Assumptions lemma1_h_dot.step2.
Print Assumptions lemma1_h_dot.step3.
Print Assumptions lemma1_h_dot.step4.
Print Assumptions lemma1_h_dot.claim.
Print Assumptions lemma1_boundary_square.step1.
Print Assumptions lemma1_boundary_square.step2.
Print Assumptions lemma1_boundary_square.step3.
Print Assumptions lemma1_boundary_square.claim.
Print Assumptions lemma1_boundary_h_dot.step1.
Print Assumptions lemma1_boundary_h_dot.step2.
Print Assumptions lemma1_boundary_h_dot.step3.
Print Assumptions lemma1_boundary_h_dot.step4.
Print Assumptions lemma1_boundary_h_dot.step5.
Print Assumptions lemma1_boundary_h_dot.claim.
Print Assumptions lemma1_boundary_sign_direct.step1.
Print Assumptions lemma1_gradient_form.step1.
Print Assumptions lemma1_gradient_nonzero.step1.
Print Assumptions lemma1_gradient_nonzero.step2.
Print Assumptions lemma1_gradient_nonzero.claim.
Print Assumptions lemma1_gradient_vanishes_at_pi.step1.
Print Assumptions lemma1_gradient_vanishes_at_pi.step2.
Print Assumptions lemma1_gradient_vanishes_at_pi.claim.
Print Assumptions lemma1_trace_inequality_psd.step1.
Print Assumptions lemma1_trace_inequality_sym_psd.step1.
Print Assumptions thm1_phi.step1.
Print Assumptions thm1_S_r_dot.step1.
Print Assumptions thm1_S_r_dot.step2.
Print Assumptions thm1_S_r_dot.step3.
Print Assumptions thm1_S_r_dot.step4.
Print Assumptions thm1_S_r_dot.step5.
Print Assumptions thm1_S_r_dot.step6.
Print Assumptions thm1_S_r_dot.step7.
Print Assumptions thm1_S_r_dot.claim.
Print Assumptions thm1_S_rl_dot.step1.
Print Assumptions thm1_S_rl_dot.step2.
Print Assumptions thm1_S_rl_dot.step3.
Print Assumptions thm1_S_rl_dot.step4.
Print Assumptions thm1_S_rl_dot.claim.
Print Assumptions thm1_S_h_sign.step1.
Print Assumptions thm1_V_dot.step1.
Print Assumptions thm1_V_dot.step2.
Print Assumptions thm1_V_dot.step3.
Print Assumptions thm1_V_dot.claim.
Print Assumptions thm1_V_dot_zero_implies_sync.step1.
Print Assumptions thm1_V_dot_zero_on_sync.step1.
Print Assumptions thm1_lasalle_derivative.step1.
Print Assumptions thm1_lasalle_derivative.step2.
Print Assumptions thm1_lasalle_derivative.claim.
Print Assumptions thm1_lasalle_derivative_from_sk_only.step1.
Print Assumptions Cert_reconstructed_k_s_2_5_band_0_1_5_f0739b7ae628.passive_on_band.
Print Assumptions Cert_reconstructed_k_s_3_0_99babda880e6.passive.
