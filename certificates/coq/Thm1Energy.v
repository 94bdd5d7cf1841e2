(** * Theorem 1 along every solution: the energy V = S_r + S_rl + S_h does not increase

    The closed loop of Section 3: [R_r] constant, eq. (13) for [R-bar], the leader's law
    (eq. (12b)) [d/dt R_l = R_l hat(omega_l)] with
    [omega_l = k_s sk(R_l^T R-bar)^vee + R_l^T omega_h^s], and any human command
    [omega_h^s(t)].  The human is passive with a storage function of its own state:
    [S_h(t)] differentiable, [S_h >= 0] and [d/dt S_h <= <u, omega_h^b>] with the human's
    input [u = sk(R_l^T R_r)^vee] and output [omega_h^b = R_l^T omega_h^s] (the
    paper's Assumption 1, item 5, in differential form; for an LTI human with a KYP
    certificate [P] it is [x^T P x / 2]).  Then along every solution on [[0, T]]
    (premises: the hypotheses of section [Theorem1]), with Lemma 1 (proved in
    [Lemma1Inv.v]) giving [R-bar_r + R-bar_r^T >= 0]:
    [d/dt V <= - k_s lam phi(R_l^T R-bar) <= 0] for a uniform [lam > 0] below
    [lambda_min(sym R_rl)] (Assumption 1, item 2), and [V] is non-increasing. *)

From Coq Require Import Reals Lra Psatz.
Local Set Warnings "-ambiguous-paths".
From Coquelicot Require Import Coquelicot.
From VerifyCoq Require Import SO3 RotSurj Traj Lemma1Inv.
Open Scope R_scope.

(** ** At one instant *)

(** [tr(R) >= 1] makes [R + R^T] positive semidefinite (eq. (14), one direction). *)
Lemma rot_trace_psd (w x y z : R) :
  qn (mkQ w x y z) <> 0 -> 1 <= tr (rot (mkQ w x y z)) ->
  lam_min_spec (madd (rot (mkQ w x y z)) (mT (rot (mkQ w x y z)))) 0.
Proof.
  intros Hn Ht v. destruct v as [a b c]. unfold qn in Hn; simpl in Hn.
  assert (Hp : 0 < w * w + x * x + y * y + z * z).
  { destruct (Rle_lt_dec (w * w + x * x + y * y + z * z) 0); [ | assumption ].
    exfalso. apply Hn. nra. }
  assert (H2 : (w * w + x * x + y * y + z * z) * (tr (rot (mkQ w x y z)) - 1)
               = 2 * (w * w - (x * x + y * y + z * z))) by (so3_unfold; field; exact Hn).
  assert (Hw : 0 <= w * w - (x * x + y * y + z * z)).
  { assert (T1 : 0 <= tr (rot (mkQ w x y z)) - 1) by lra.
    pose proof (Rmult_le_pos _ _ (Rlt_le _ _ Hp) T1). lra. }
  assert (E : qform (msub (sym (madd (rot (mkQ w x y z)) (mT (rot (mkQ w x y z))))) (mscale 0 I3))
                (mkV a b c)
              = 2 * ((a * a + b * b + c * c) * (w * w - (x * x + y * y + z * z))
                     + 2 * (x * a + y * b + z * c) * (x * a + y * b + z * c))
                / (w * w + x * x + y * y + z * z)).
  { (* with s = 2/|q|^2 both sides are polynomials in s; their difference is
       -|v|^2 (s |q|^2 - 2), checked by lra (cheaper than field on the entries) *)
    pose proof (rot_scale_norm (mkQ w x y z)) as Hs.
    replace (2 * ((a * a + b * b + c * c) * (w * w - (x * x + y * y + z * z))
                  + 2 * (x * a + y * b + z * c) * (x * a + y * b + z * c))
             / (w * w + x * x + y * y + z * z))
      with (((a * a + b * b + c * c) * (w * w - (x * x + y * y + z * z))
             + 2 * (x * a + y * b + z * c) * (x * a + y * b + z * c)) * (2 / qn (mkQ w x y z)))
      by (unfold qn; simpl; field; exact Hn).
    unfold qform, rot. revert Hs. generalize (2 / qn (mkQ w x y z)); intros s Hs.
    specialize (Hs Hn). so3_unfold.
    apply (eq_by_cofactors_1 _ _ (- (a * a + b * b + c * c))
                             (s * (w * w + x * x + y * y + z * z) - 2)); lra. }
  rewrite E. unfold Rdiv. apply Rmult_le_pos; [ | apply Rlt_le, Rinv_0_lt_compat; exact Hp ].
  pose proof (Rmult_le_pos _ _ (vdot_self_nonneg (mkV a b c)) Hw) as P1.
  pose proof (sq_nonneg (x * a + y * b + z * c)) as P2. unfold vdot in P1; simpl in P1. lra.
Qed.

Lemma is_rot_trace_psd (M : M3) : is_rot M -> 1 <= tr M -> lam_min_spec (madd M (mT M)) 0.
Proof.
  intros H Ht. destruct (rot_surjective M H) as [[w x y z] [Hq E]]. subst M.
  apply rot_trace_psd; assumption.
Qed.

Section Instant.
Variables qr qb ql : quat.
Hypothesis qr_nz : qn qr <> 0.
Hypothesis qb_nz : qn qb <> 0.
Hypothesis ql_nz : qn ql <> 0.
Variables (ks : R) (ws : V3).

(** eq. (17), first line: the rates of S_r and S_rl plus the supplied power. *)
Lemma v_rate_identity :
  - tr (mmul (mT (rot qr)) (mscale ks (mmul (rot qb) (sk (mmul (mT (rot qb)) (rot ql)))))) / 2
  - tr (mmul (mT (rot qr)) (mmul (rot ql) (hat (vadd (vscale ks (vee (sk (mmul (mT (rot ql)) (rot qb)))))
                                                    (mvmul (mT (rot ql)) ws))))) / 2
  + vdot (vee (sk (mmul (mT (rot ql)) (rot qr)))) (mvmul (mT (rot ql)) ws)
  = (-1/4) * ks * (tr (mmul (madd (mmul (mT (rot qr)) (rot qb)) (mT (mmul (mT (rot qr)) (rot qb))))
                            (msub I3 (mmul (mT (rot qb)) (rot ql))))
                   + tr (mmul (madd (mmul (mT (rot qr)) (rot ql)) (mT (mmul (mT (rot qr)) (rot ql))))
                            (msub I3 (mmul (mT (rot ql)) (rot qb))))).
Proof.
  so3_norm.
  generalize (rot qr) as Gr; intro Gr. generalize (rot qb) as Gb; intro Gb.
  generalize (rot ql) as Gl; intro Gl.
  destruct ws. so3_poly.
Qed.
End Instant.

Lemma sym_one_minus_rot (q : quat) : qn q <> 0 ->
  sym (msub I3 (rot q)) = mscale (1/2) (mmul (mT (msub I3 (rot q))) (msub I3 (rot q))).
Proof.
  intro H. so3_norm. generalize (rot q) as G; intro G. so3_split; so3_poly.
Qed.

Lemma lam_min_double (A : M3) (lam : R) :
  lam_min_spec A lam -> lam_min_spec (madd A (mT A)) (2 * lam).
Proof.
  intros H v. specialize (H v).
  assert (E : qform (msub (sym (madd A (mT A))) (mscale (2 * lam) I3)) v
              = 2 * qform (msub (sym A) (mscale lam I3)) v)
    by (destruct A, v; unfold qform; so3_unfold; ring).
  rewrite E. lra.
Qed.

Lemma mT_sum_self (A : M3) : mT (madd A (mT A)) = madd A (mT A).
Proof. destruct A. so3_split; so3_unfold; lra. Qed.

(** eq. (17) with its bound, for any three rotations: Lemma 1's [tr(R_r^T R-bar) >= 1]
    and [lam] below [lambda_min(sym R_rl)]. *)
Lemma v_rate_bound (Rr Rb Rl : M3) (ks lam : R) (ws : V3) :
  is_rot Rr -> is_rot Rb -> is_rot Rl -> 0 <= ks ->
  1 <= tr (mmul (mT Rr) Rb) -> lam_min_spec (mmul (mT Rr) Rl) lam ->
  - tr (mmul (mT Rr) (mscale ks (mmul Rb (sk (mmul (mT Rb) Rl))))) / 2
  - tr (mmul (mT Rr) (mmul Rl (hat (vadd (vscale ks (vee (sk (mmul (mT Rl) Rb))))
                                        (mvmul (mT Rl) ws))))) / 2
  + vdot (vee (sk (mmul (mT Rl) Rr))) (mvmul (mT Rl) ws)
  <= - (ks * lam) * phi (mmul (mT Rl) Rb).
Proof.
  intros HRr HRb HRl Hks Htr Hlam.
  pose proof (is_rot_trace_psd _ (is_rot_relative Rr Rb HRr HRb) Htr) as Hpsd.
  pose proof (lam_min_double _ _ Hlam) as Hlam2.
  destruct (rot_surjective _ (is_rot_relative Rb Rl HRb HRl)) as [q1 [Hq1 E1]].
  destruct (rot_surjective _ (is_rot_relative Rl Rb HRl HRb)) as [q2 [Hq2 E2]].
  pose proof (trace_lower_bound _ _ _ (1/2) 0 (mT_sum_self _)
                (eq_ind _ (fun Q => sym (msub I3 Q) = mscale (1/2) (mmul (mT (msub I3 Q)) (msub I3 Q)))
                   (sym_one_minus_rot q1 Hq1) _ E1) ltac:(lra) Hpsd) as T1.
  pose proof (trace_lower_bound _ _ _ (1/2) (2 * lam) (mT_sum_self _)
                (eq_ind _ (fun Q => sym (msub I3 Q) = mscale (1/2) (mmul (mT (msub I3 Q)) (msub I3 Q)))
                   (sym_one_minus_rot q2 Hq2) _ E2) ltac:(lra) Hlam2) as T2.
  destruct (rot_surjective _ HRr) as [qr [Hr Er]].
  destruct (rot_surjective _ HRb) as [qb [Hb Eb]].
  destruct (rot_surjective _ HRl) as [ql [Hl El]].
  subst Rr Rb Rl.
  rewrite v_rate_identity by assumption.
  unfold phi. pose proof (Rmult_le_pos _ _ Hks T1). pose proof (Rmult_le_pos _ _ Hks T2). lra.
Qed.

(** [phi(R) >= 0] for a rotation (Theorem 1's energy function). *)
Lemma phi_rot_nonneg (q : quat) : qn q <> 0 -> 0 <= phi (rot q).
Proof.
  intro H. destruct q as [w x y z]. unfold qn in H; simpl in H.
  assert (Hp : 0 < w * w + x * x + y * y + z * z).
  { destruct (Rle_lt_dec (w * w + x * x + y * y + z * z) 0); [ | assumption ].
    exfalso. apply H. nra. }
  assert (E : phi (rot (mkQ w x y z)) = 2 * (x * x + y * y + z * z) / (w * w + x * x + y * y + z * z))
    by (so3_unfold; field; exact H).
  rewrite E. unfold Rdiv. apply Rmult_le_pos; [ nra | apply Rlt_le, Rinv_0_lt_compat; exact Hp ].
Qed.

(** [phi(A^T B) >= 0] for two rotations: the relative rotation is a rotation.  Shared by
    [Barbalat.v], [Converge.v] and [Thm1LTI.v]. *)
Lemma phi_rel_rot_nonneg (A B : M3) : is_rot A -> is_rot B -> 0 <= phi (mmul (mT A) B).
Proof.
  intros HA HB. destruct (rot_surjective _ (is_rot_relative _ _ HA HB)) as [q [Hq E]].
  rewrite <- E. apply phi_rot_nonneg. exact Hq.
Qed.

(** ** Along solutions *)

(** A function whose derivative is [<= 0] on [[0, T]] does not increase there. *)
Lemma nonincreasing (f df : R -> R) (T : R) :
  (forall t, 0 <= t <= T -> is_derive f t (df t)) -> (forall t, 0 <= t <= T -> df t <= 0) ->
  forall s t, 0 <= s -> s <= t -> t <= T -> f t <= f s.
Proof.
  intros D N s t Hs Hst HT.
  destruct (Rle_lt_or_eq_dec s t Hst) as [lt | eq]; [ | subst; lra ].
  destruct (MVT_cor2 f df s t lt) as [c [E Hc]].
  - intros x Hx. apply is_derive_Reals, D. lra.
  - pose proof (N c ltac:(lra)). nra.
Qed.

Section Theorem1.
Variables (Rr : M3) (Rb Rl : R -> M3) (ws : R -> V3) (Sh dSh : R -> R) (ks lam T : R).
(** [k_s > 0]; [lam > 0] is a uniform lower bound of [lambda_min(sym R_rl)]. *)
Hypothesis ks_pos : 0 < ks.
Hypothesis lam_pos : 0 < lam.
(** [R_r] is a constant rotation; [R-bar] and [R_l] stay on SO(3) on [[0, T]]. *)
Hypothesis Rr_rot : is_rot Rr.
Hypothesis Rb_rot : forall t, 0 <= t <= T -> is_rot (Rb t).
Hypothesis Rl_rot : forall t, 0 <= t <= T -> is_rot (Rl t).
(** The solution exists and is differentiable on [[0, T]]: eq. (13) and eq. (12b). *)
Hypothesis Rb_sol : forall t, 0 <= t <= T ->
  is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t))))).
Hypothesis Rl_sol : forall t, 0 <= t <= T ->
  is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                         (mvmul (mT (Rl t)) (ws t))))).
(** The human is passive with a differentiable storage [S_h] (Assumption 1, item 5,
    in differential form): its rate is at most the supplied power [<u, omega_h^b>]. *)
Hypothesis Sh_deriv : forall t, 0 <= t <= T -> is_derive Sh t (dSh t).
Hypothesis Sh_supply : forall t, 0 <= t <= T ->
  dSh t <= vdot (vee (sk (mmul (mT (Rl t)) Rr))) (mvmul (mT (Rl t)) (ws t)).
(** Assumption 1, item 2, uniformly along the solution. *)
Hypothesis item2 : forall t, 0 <= t <= T -> lam_min_spec (mmul (mT Rr) (Rl t)) lam.
(** Lemma 1's premise at time 0. *)
Hypothesis init : 1 <= tr (mmul (mT Rr) (Rb 0)).

(** The energy of Theorem 1's proof. *)
Definition V (t : R) : R := phi (mmul (mT Rr) (Rb t)) + phi (mmul (mT Rr) (Rl t)) + Sh t.

Definition dV (t : R) : R :=
  - tr (mmul (mT Rr) (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))) / 2
  - tr (mmul (mT Rr) (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                             (mvmul (mT (Rl t)) (ws t)))))) / 2
  + dSh t.

Lemma V_derivative (t : R) : 0 <= t <= T -> is_derive V t (dV t).
Proof.
  intro Ht. unfold V, dV.
  pose proof (deriv_phi _ t _ (mderiv_mmul (fun _ => mT Rr) Rb t Z3 _ (mderiv_const (mT Rr) t) (Rb_sol t Ht))) as D1.
  pose proof (deriv_phi _ t _ (mderiv_mmul (fun _ => mT Rr) Rl t Z3 _ (mderiv_const (mT Rr) t) (Rl_sol t Ht))) as D2.
  eapply deriv_unique_eq.
  - exact (d_plus _ _ t _ _ (d_plus _ _ t _ _ D1 D2) (Sh_deriv t Ht)).
  - destruct Rr, (Rb t), (Rl t), (ws t). so3_poly.
Qed.

(** eq. (17) along the solution: [d/dt V <= - k_s lam phi(R_l^T R-bar) <= 0]. *)
Theorem V_rate_bound (t : R) : 0 <= t <= T ->
  is_derive V t (dV t) /\ dV t <= - (ks * lam) * phi (mmul (mT (Rl t)) (Rb t)) /\ dV t <= 0.
Proof.
  intro Ht. split; [ exact (V_derivative t Ht) | ].
  assert (L1 : 1 <= tr (mmul (mT Rr) (Rb t))).
  { apply (lemma1_invariance Rr Rb Rl ks T ks_pos Rr_rot Rb_rot Rb_sol); [ | exact init | exact Ht ].
    intros s Hs. exists lam. split; [ exact lam_pos | exact (item2 s Hs) ]. }
  pose proof (v_rate_bound Rr (Rb t) (Rl t) ks lam (ws t) Rr_rot (Rb_rot t Ht) (Rl_rot t Ht)
                (Rlt_le _ _ ks_pos) L1 (item2 t Ht)) as B.
  pose proof (Sh_supply t Ht) as S.
  assert (P : 0 <= phi (mmul (mT (Rl t)) (Rb t))).
  { destruct (rot_surjective _ (is_rot_relative _ _ (Rl_rot t Ht) (Rb_rot t Ht))) as [q [Hq E]].
    rewrite <- E. apply phi_rot_nonneg. exact Hq. }
  unfold dV. split; [ lra | ].
  pose proof (Rmult_le_pos _ _ (Rmult_le_pos _ _ (Rlt_le _ _ ks_pos) (Rlt_le _ _ lam_pos)) P). lra.
Qed.

(** [V] does not increase on [[0, T]]. *)
Theorem V_nonincreasing : forall s t, 0 <= s -> s <= t -> t <= T -> V t <= V s.
Proof.
  apply (nonincreasing V dV T).
  - exact V_derivative.
  - intros t Ht. apply (V_rate_bound t Ht).
Qed.

End Theorem1.
