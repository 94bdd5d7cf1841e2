(** * Lemma 1 along every solution: tr(R_r^T R-bar) >= 1 is forward invariant

    The paper (Section 3, Lemma 1) invokes Nagumo's theorem with "h-dot >= 0 on the
    boundary h = 0", where [h = tr(R_r^T R-bar) - 1].  A non-strict boundary bound
    does not give invariance by itself ([h(t) = -t^3] is a counterexample), but
    Assumption 1, item 2 gives a strict one: on the boundary
    [h-dot = k_s tr(sym(R_rl)(I - xi xi^T)) >= 2 k_s lam > 0] for any [lam > 0] below
    [lambda_min(sym R_rl)].  A strict boundary bound is enough for a last-exit
    argument ([barrier]), so no general Nagumo theorem (tangent cones, uniqueness of
    solutions) is needed.  The derivative of [h] along a solution of eq. (13) is taken
    by the rules of [Traj.v]; the boundary bound is an identity in quaternion
    coordinates ([boundary_identity]) made to hold for every rotation by
    [rot_surjective].  The premises are the hypotheses of section [Lemma1]. *)

From Coq Require Import Reals Lra Psatz.
Local Set Warnings "-ambiguous-paths".
From Coquelicot Require Import Coquelicot.
From VerifyCoq Require Import SO3 RotSurj Traj.
Open Scope R_scope.

(** Near a point where [h] is negative, [h] stays negative. *)
Lemma neg_near (h : R -> R) (s l : R) :
  derivable_pt_lim h s l -> h s < 0 ->
  exists d, 0 < d /\ forall k, Rabs k < d -> h (s + k) < 0.
Proof.
  intros D Hs. destruct (D 1 Rlt_0_1) as [d Hd].
  set (m := Rmin d (- h s / (Rabs l + 1))).
  assert (Hl : 0 < Rabs l + 1) by (pose proof (Rabs_pos l); lra).
  assert (Hm : 0 < m).
  { unfold m. apply Rmin_pos; [ apply cond_pos | apply Rdiv_lt_0_compat; lra ]. }
  exists m. split; [ exact Hm | ]. intros k Hk.
  destruct (Req_dec k 0) as [E | Nk].
  { subst k. rewrite Rplus_0_r. exact Hs. }
  assert (Hkd : Rabs k < d) by (apply Rlt_le_trans with m; [ exact Hk | apply Rmin_l ]).
  assert (Hkm : Rabs k * (Rabs l + 1) < - h s).
  { assert (Rabs k < - h s / (Rabs l + 1)) by (apply Rlt_le_trans with m; [ exact Hk | apply Rmin_r ]).
    apply (Rmult_lt_compat_r (Rabs l + 1)) in H; [ | exact Hl ].
    unfold Rdiv in H. rewrite Rmult_assoc, Rinv_l, Rmult_1_r in H; lra. }
  specialize (Hd k Nk Hkd).
  assert (E : h (s + k) - h s = ((h (s + k) - h s) / k - l) * k + l * k) by (field; exact Nk).
  assert (B : Rabs (h (s + k) - h s) <= Rabs ((h (s + k) - h s) / k - l) * Rabs k + Rabs l * Rabs k).
  { rewrite E at 1. rewrite <- !Rabs_mult. apply Rabs_triang. }
  assert (C : Rabs ((h (s + k) - h s) / k - l) * Rabs k <= 1 * Rabs k).
  { apply Rmult_le_compat_r; [ apply Rabs_pos | lra ]. }
  pose proof (Rle_abs (h (s + k) - h s)). nra.
Qed.

(** Right of a point where [h] is positive, or zero with a positive derivative,
    [h] is positive. *)
Lemma pos_right (h : R -> R) (s l : R) :
  derivable_pt_lim h s l -> (0 < h s \/ (h s = 0 /\ 0 < l)) ->
  exists d, 0 < d /\ forall k, 0 < k < d -> 0 < h (s + k).
Proof.
  intros D [Hs | [Hs Hl]].
  - destruct (neg_near (fun u => - h u) s (- l)) as [d [Hd H]].
    + apply derivable_pt_lim_opp. exact D.
    + lra.
    + exists d. split; [ exact Hd | ]. intros k Hk. specialize (H k).
      assert (Rabs k < d) by (rewrite Rabs_right; lra). apply H in H0. lra.
  - destruct (D l Hl) as [d Hd]. exists d. split; [ apply cond_pos | ]. intros k Hk.
    assert (Nk : k <> 0) by lra.
    assert (Ak : Rabs k < d) by (rewrite Rabs_right; lra).
    specialize (Hd k Nk Ak). rewrite Hs in Hd.
    assert (Q : 0 < (h (s + k) - 0) / k).
    { apply Rabs_def2 in Hd. lra. }
    assert (E : h (s + k) = (h (s + k) - 0) / k * k) by (field; exact Nk).
    rewrite E. apply Rmult_lt_0_compat; lra.
Qed.

(** The last-exit argument (Lemma 1's invariance without Nagumo's general theorem):
    a differentiable [h] on [[0, T]] with [h 0 >= 0] whose derivative is positive
    wherever [h] vanishes stays non-negative on [[0, T]]. *)
Theorem barrier (h dh : R -> R) (T : R) :
  (forall t, 0 <= t <= T -> is_derive h t (dh t)) ->
  (forall t, 0 <= t <= T -> h t = 0 -> 0 < dh t) ->
  0 <= h 0 -> forall t, 0 <= t <= T -> 0 <= h t.
Proof.
  intros Dh Bd H0 t1 Ht1.
  destruct (Rle_or_lt 0 (h t1)) as [ok | neg]; [ exact ok | exfalso ].
  assert (D : forall t, 0 <= t <= T -> derivable_pt_lim h t (dh t))
    by (intros t Ht; apply is_derive_Reals, Dh, Ht).
  set (E := fun u => 0 <= u <= t1 /\ 0 <= h u).
  assert (Eb : bound E) by (exists t1; intros u [Hu _]; lra).
  assert (E0 : exists u, E u) by (exists 0; split; [ lra | exact H0 ]).
  destruct (completeness E Eb E0) as [s [Sup Least]].
  assert (Hs0 : 0 <= s) by (apply Sup; split; [ lra | exact H0 ]).
  assert (Hs1 : s <= t1) by (apply Least; intros u [Hu _]; lra).
  (* h s >= 0: otherwise h < 0 near s, and points of E come arbitrarily close to s *)
  assert (Hhs : 0 <= h s).
  { destruct (Rle_or_lt 0 (h s)) as [ok | ns]; [ exact ok | exfalso ].
    destruct (neg_near h s (dh s) (D s ltac:(lra)) ns) as [d [Hd Hn]].
    assert (Up : is_upper_bound E (s - d / 2)).
    { intros u [Hu Hhu]. destruct (Rle_or_lt u (s - d / 2)) as [le | gt]; [ exact le | ].
      assert (u <= s) by (apply Sup; split; assumption).
      specialize (Hn (u - s)). replace (s + (u - s)) with u in Hn by ring.
      assert (h u < 0) by (apply Hn; rewrite Rabs_left1; lra). lra. }
    specialize (Least _ Up). lra. }
  assert (Hst : s < t1) by (destruct (Req_dec s t1); [ subst; lra | lra ]).
  (* right of s, up to t1, h is negative *)
  assert (Right : forall u, s < u <= t1 -> h u < 0).
  { intros u Hu. destruct (Rle_or_lt 0 (h u)) as [nn | ng]; [ | exact ng ].
    assert (u <= s) by (apply Sup; split; [ lra | exact nn ]). lra. }
  assert (Pos : 0 < h s \/ (h s = 0 /\ 0 < dh s)).
  { destruct (Rle_lt_or_eq_dec 0 (h s) Hhs) as [p | z]; [ left; exact p | right ].
    split; [ symmetry; exact z | apply Bd; [ lra | symmetry; exact z ] ]. }
  destruct (pos_right h s (dh s) (D s ltac:(lra)) Pos) as [d [Hd Hp]].
  set (k := Rmin (d / 2) (t1 - s)).
  assert (Hk : 0 < k <= d / 2) by (unfold k; split; [ apply Rmin_pos; lra | apply Rmin_l ]).
  assert (Hk2 : k <= t1 - s) by apply Rmin_r.
  specialize (Hp k ltac:(lra)). specialize (Right (s + k) ltac:(lra)). lra.
Qed.

Lemma det_mmul (A B : M3) : det (mmul A B) = det A * det B.
Proof. destruct A, B. so3_unfold. lra. Qed.

Lemma det_mT (A : M3) : det (mT A) = det A.
Proof. destruct A. so3_unfold. lra. Qed.

Lemma is_rot_rr (M : M3) : is_rot M -> mmul M (mT M) = I3.
Proof.
  intro H. destruct (rot_surjective M H) as [q [Hq <-]]. apply rot_orthogonal_r. exact Hq.
Qed.

Lemma is_rot_relative (A B : M3) : is_rot A -> is_rot B -> is_rot (mmul (mT A) B).
Proof.
  intros HA HB. pose proof (is_rot_rr A HA) as RA. destruct HA as [OA DA], HB as [OB DB].
  split.
  - rewrite mT_mmul, mT_mT, !mmul_assoc, <- (mmul_assoc A (mT A) B), RA, mmul_I3_l. exact OB.
  - rewrite det_mmul, det_mT, DA, DB. ring.
Qed.

(** [tr(R_r^T (k_s B sk(B^T L)))] in terms of [P = R_r^T B] and [A = R_r^T L]. *)
Lemma h_rate_relative (Rr B L : M3) (ks : R) :
  mmul Rr (mT Rr) = I3 ->
  tr (mmul (mT Rr) (mscale ks (mmul B (sk (mmul (mT B) L)))))
  = ks * tr (mmul (mmul (mT Rr) B) (sk (mmul (mT (mmul (mT Rr) B)) (mmul (mT Rr) L)))).
Proof.
  intro H. rewrite mT_mmul, mT_mT, !mmul_assoc, <- (mmul_assoc Rr (mT Rr) L), H, mmul_I3_l.
  destruct Rr, B, L. so3_unfold. lra.
Qed.

Lemma boundary_quat (w x y z : R) : qn (mkQ w x y z) <> 0 -> tr (rot (mkQ w x y z)) = 1 ->
  w * w = x * x + y * y + z * z.
Proof.
  intros Hn Ht. unfold qn in Hn; simpl in Hn.
  assert (H2 : (w * w + x * x + y * y + z * z) * (tr (rot (mkQ w x y z)) - 1)
               = 2 * (w * w - (x * x + y * y + z * z))) by (so3_unfold; field; exact Hn).
  rewrite Ht in H2. lra.
Qed.

Lemma boundary_identity (w x y z lam : R) (A : M3) :
  w * w = x * x + y * y + z * z -> x * x + y * y + z * z <> 0 ->
  tr (mmul (rot (mkQ w x y z)) (sk (mmul (mT (rot (mkQ w x y z))) A))) - 2 * lam
  = (qform (msub (sym A) (mscale lam I3)) (mkV 0 (- z) y)
     + qform (msub (sym A) (mscale lam I3)) (mkV z 0 (- x))
     + qform (msub (sym A) (mscale lam I3)) (mkV (- y) x 0)) / (x * x + y * y + z * z).
Proof.
  (* With t = 1/|v|^2 (= 2/|q|^2 on the boundary), both sides are polynomials in t;
     their difference is a combination of t |v|^2 - 1 and w^2 - |v|^2, checked by lra
     (cheaper than field_simplify on the rational entries). *)
  intros Hb Hs.
  assert (Ht : 2 / qn (mkQ w x y z) = / (x * x + y * y + z * z))
    by (unfold qn; simpl; rewrite Hb; field; split; [exact Hs | intro E; apply Hs; lra]).
  assert (Hi : / (x * x + y * y + z * z) * (x * x + y * y + z * z) = 1) by (field; exact Hs).
  unfold rot. rewrite Ht. unfold Rdiv. revert Hi.
  generalize (/ (x * x + y * y + z * z)); intros t Hi.
  destruct A as [a11 a12 a13 a21 a22 a23 a31 a32 a33]. unfold qform. so3_unfold.
  apply (eq_by_cofactors_2 _ _
    (a11 * t * y * y + a11 * t * z * z - a12 * t * w * z - a12 * t * x * y + a13 * t * w * y
     - a13 * t * x * z + a21 * t * w * z - a21 * t * x * y + a22 * t * w * w - a22 * t * y * y
     - a23 * t * w * x - a23 * t * y * z - a31 * t * w * y - a31 * t * x * z + a32 * t * w * x
     - a32 * t * y * z + a33 * t * w * w - a33 * t * z * z + 2 * lam)
    (t * (x * x + y * y + z * z) - 1)
    (- t * (- a11 * t * y * y - a11 * t * z * z + a12 * t * x * y + a13 * t * x * z
            + a21 * t * x * y + a22 * t * y * y - a22 + a23 * t * y * z + a31 * t * x * z
            + a32 * t * y * z + a33 * t * z * z - a33))
    (w * w - (x * x + y * y + z * z))); lra.
Qed.

Lemma boundary_rate (w x y z : R) (A : M3) (lam : R) :
  qn (mkQ w x y z) <> 0 -> tr (rot (mkQ w x y z)) = 1 -> lam_min_spec A lam ->
  2 * lam <= tr (mmul (rot (mkQ w x y z)) (sk (mmul (mT (rot (mkQ w x y z))) A))).
Proof.
  intros Hn Ht Hl. pose proof (boundary_quat w x y z Hn Ht) as Hb.
  assert (Hs : 0 < x * x + y * y + z * z).
  { unfold qn in Hn; simpl in Hn. destruct (Req_dec (x * x + y * y + z * z) 0) as [z0 | nz].
    - exfalso. apply Hn. nra.
    - nra. }
  pose proof (Hl (mkV 0 (- z) y)) as L1. pose proof (Hl (mkV z 0 (- x))) as L2.
  pose proof (Hl (mkV (- y) x 0)) as L3.
  pose proof (boundary_identity w x y z lam A Hb ltac:(lra)) as E.
  assert (0 <= (qform (msub (sym A) (mscale lam I3)) (mkV 0 (- z) y)
     + qform (msub (sym A) (mscale lam I3)) (mkV z 0 (- x))
     + qform (msub (sym A) (mscale lam I3)) (mkV (- y) x 0)) / (x * x + y * y + z * z))
    by (unfold Rdiv; apply Rmult_le_pos; [ lra | apply Rlt_le, Rinv_0_lt_compat; lra ]).
  lra.
Qed.

(** The boundary bound at one instant: on [tr(R_r^T R-bar) = 1], with [lam <= lambda_min(sym R_rl)],
    the rate of [h] is at least [2 k_s lam]. *)
Lemma h_rate_on_boundary (Rr B L : M3) (ks lam : R) :
  is_rot Rr -> is_rot B -> 0 <= ks -> tr (mmul (mT Rr) B) = 1 ->
  lam_min_spec (mmul (mT Rr) L) lam ->
  2 * ks * lam <= tr (mmul (mT Rr) (mscale ks (mmul B (sk (mmul (mT B) L))))).
Proof.
  intros HRr HB Hks Htr Hlam.
  rewrite (h_rate_relative Rr B L ks (is_rot_rr Rr HRr)).
  destruct (rot_surjective _ (is_rot_relative Rr B HRr HB)) as [[w x y z] [Hq E]].
  rewrite <- E in *.
  pose proof (boundary_rate w x y z _ lam Hq Htr Hlam). nra.
Qed.

(** ** Lemma 1 along every solution

    The paper's setting (Section 3): [R_r] constant, [R-bar] a solution of eq. (13),
    [d/dt R-bar = k_s R-bar sk(R-bar^T R_l)], for a leader attitude [R_l] that the
    human and the leader's law move in any way at all, as long as Assumption 1, item 2
    holds along it (stated with a positive lower bound of [lambda_min(sym R_rl)] at
    every instant).  Premises, each a hypothesis of the section: *)
Section Lemma1.
Variables (Rr : M3) (Rb Rl : R -> M3) (ks T : R).
(** [k_s > 0]. *)
Hypothesis ks_pos : 0 < ks.
(** [R_r] is a rotation (constant: it is a matrix, not a function of time). *)
Hypothesis Rr_rot : is_rot Rr.
(** The solution stays on SO(3) on [[0, T]]. *)
Hypothesis Rb_rot : forall t, 0 <= t <= T -> is_rot (Rb t).
(** The solution exists and is differentiable on [[0, T]], with eq. (13). *)
Hypothesis Rb_sol : forall t, 0 <= t <= T ->
  is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t))))).
(** Assumption 1, item 2, along the solution: [sym(R_rl(t))] is positive definite,
    i.e. some [lam > 0] is at most its least eigenvalue. *)
Hypothesis item2 : forall t, 0 <= t <= T ->
  exists lam, 0 < lam /\ lam_min_spec (mmul (mT Rr) (Rl t)) lam.

Definition h_of (t : R) : R := tr (mmul (mT Rr) (Rb t)) - 1.

Lemma h_derivative (t : R) : 0 <= t <= T ->
  is_derive h_of t (tr (mmul (mT Rr) (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t))))))).
Proof.
  intro Ht. unfold h_of.
  pose proof (mderiv_mmul (fun _ => mT Rr) Rb t Z3 _ (mderiv_const (mT Rr) t) (Rb_sol t Ht)) as D.
  apply deriv_tr in D.
  eapply deriv_unique_eq.
  - apply (d_minus _ _ t _ 0 D (d_const 1 t)).
  - destruct Rr, (Rb t). so3_unfold. lra.
Qed.

(** Lemma 1 on [[0, T]]: [tr(R_r^T R-bar) >= 1] (i.e. [R-bar_r + R-bar_r^T] positive
    semidefinite, eq. (14)) at time 0 implies it at every time of [[0, T]]. *)
Theorem lemma1_invariance :
  1 <= tr (mmul (mT Rr) (Rb 0)) -> forall t, 0 <= t <= T -> 1 <= tr (mmul (mT Rr) (Rb t)).
Proof.
  intros H0 t Ht.
  assert (B : 0 <= h_of t).
  { apply (barrier h_of
      (fun s => tr (mmul (mT Rr) (mscale ks (mmul (Rb s) (sk (mmul (mT (Rb s)) (Rl s))))))) T).
    - exact h_derivative.
    - intros s Hs Hz. destruct (item2 s Hs) as [lam Hlam]. decompose [and] Hlam.
      assert (Htr : tr (mmul (mT Rr) (Rb s)) = 1) by (unfold h_of in Hz; lra).
      assert (Hrate : 2 * ks * lam
                      <= tr (mmul (mT Rr) (mscale ks (mmul (Rb s) (sk (mmul (mT (Rb s)) (Rl s)))))))
        by (apply h_rate_on_boundary; auto; lra).
      nra.
    - unfold h_of. lra.
    - exact Ht. }
  unfold h_of in B. lra.
Qed.

End Lemma1.

(** Lemma 1 on [[0, oo)]: the premises at every [t >= 0]. *)
Theorem lemma1_invariance_forever (Rr : M3) (Rb Rl : R -> M3) (ks : R) :
  0 < ks -> is_rot Rr -> (forall t, 0 <= t -> is_rot (Rb t)) ->
  (forall t, 0 <= t ->
     is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))) ->
  (forall t, 0 <= t -> exists lam, 0 < lam /\ lam_min_spec (mmul (mT Rr) (Rl t)) lam) ->
  1 <= tr (mmul (mT Rr) (Rb 0)) -> forall t, 0 <= t -> 1 <= tr (mmul (mT Rr) (Rb t)).
Proof.
  intros Hks HRr HRb Hsol H2 H0 t Ht.
  apply (lemma1_invariance Rr Rb Rl ks t); try assumption; try (intros; apply HRb || apply Hsol || apply H2; lra).
  lra.
Qed.
