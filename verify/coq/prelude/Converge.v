(** * Toward the paper's objective d-bar -> d_r: Theorem 1's LaSalle step, asymptotically

    Theorem 1's proof ends (Section 3) with LaSalle's principle: on the set where
    [V-dot = 0] identically, [R_l = R-bar], so [d/dt (R_l^T R-bar) = - R_l^T hat(omega_h^s) R_l = 0],
    so [omega_h^s = 0] identically, and Assumption 1, item 3 ("the operator sends
    [omega_h^s = 0] identically only if [d_l = d_r] identically") gives [d-bar = d_r].
    The human is not an autonomous system with a given state here, so there is no
    invariance principle to invoke; this file proves the same chain in asymptotic form,
    each step along every solution:

    - [phi(R_l^T R-bar) -> 0] ([Barbalat.v]) gives [||R_l^T R-bar - I||_F -> 0] and
      [|d_l - d-bar| -> 0] with [d_l = R_l e3] and [d-bar := R-bar e3] (Section 3 aligns
      [R-bar e3] with [d-bar] at time 0 and eq. (11) keeps it so; here [R-bar e3] is the
      definition).  The Lipschitz rate that [Barbalat.v] takes as a premise is proved
      from a bounded human command.
    - [d/dt (R_l^T R-bar) = - R_l^T hat(omega_h^s) R-bar - k_s (Q sk Q + sk Q Q)] with
      [Q = R_l^T R-bar] (eqs. (12b), (13); at [Q = I] it is the paper's
      [- R_l^T hat(omega_h^s) R_l]); Barbalat's lemma in its second form ([f -> L] and
      [f'] uniformly continuous give [f' -> 0], proved here) makes the derivative vanish,
      and [||R_l^T hat(w) R-bar||_F^2 = 2 |w|^2] then gives [omega_h^s -> 0].
    - Item 3 in the asymptotic form "[omega_h^s -> 0] implies [d_l -> d_r]" (a named
      premise) then gives [d-bar -> d_r], the paper's objective eq. (2).

    Premises beyond those of [Barbalat.v]: the human command is bounded and Lipschitz
    ([|omega_h^s| <= B_w], [|omega_h^s(t) - omega_h^s(s)| <= L_w |t - s|]; item 4 bounds
    the output, its rate is an extra requirement), and item 3 in asymptotic form. *)

From Coq Require Import Reals Lra Psatz.
Local Set Warnings "-ambiguous-paths".
From Coquelicot Require Import Coquelicot.
From VerifyCoq Require Import SO3 RotSurj Traj Lemma1Inv Thm1Energy Barbalat.
Open Scope R_scope.

(** ** Vectors, limits at infinity, bounded and Lipschitz functions *)

Definition e3 : V3 := mkV 0 0 1.
Definition vsub (u v : V3) : V3 := vadd u (vneg v).
Definition vnorm (u : V3) : R := sqrt (vdot u u).

(** [f(t) -> 0] as [t -> oo]. *)
Definition vanishes (f : R -> R) : Prop :=
  forall eps, 0 < eps -> exists N, 0 <= N /\ forall t, N <= t -> Rabs (f t) < eps.

(** [g] is uniformly continuous on [[0, oo)]. *)
Definition unif_cont (g : R -> R) : Prop :=
  forall eps, 0 < eps -> exists d, 0 < d /\
    forall s t, 0 <= s -> 0 <= t -> Rabs (t - s) <= d -> Rabs (g t - g s) < eps.

(** [f] is bounded on [[0, oo)]; [f] is bounded and Lipschitz on [[0, oo)]. *)
Definition bd (f : R -> R) : Prop := exists B, forall t, 0 <= t -> Rabs (f t) <= B.
Definition bl (f : R -> R) : Prop :=
  exists B L, (forall t, 0 <= t -> Rabs (f t) <= B) /\
    (forall s t, 0 <= s -> 0 <= t -> Rabs (f t - f s) <= L * Rabs (t - s)).

Lemma vanishes_plus (f g : R -> R) : vanishes f -> vanishes g -> vanishes (fun t => f t + g t).
Proof.
  intros Hf Hg eps He.
  destruct (Hf (eps / 2)) as [N1 [H1 F]]; [ lra | ].
  destruct (Hg (eps / 2)) as [N2 [H2 G]]; [ lra | ].
  exists (Rmax N1 N2). pose proof (Rmax_l N1 N2). pose proof (Rmax_r N1 N2).
  split; [ lra | ]. intros t Ht.
  specialize (F t ltac:(lra)). specialize (G t ltac:(lra)).
  pose proof (Rabs_triang (f t) (g t)). lra.
Qed.

Lemma vanishes_le (f g : R -> R) :
  vanishes f -> (forall t, 0 <= t -> Rabs (g t) <= Rabs (f t)) -> vanishes g.
Proof.
  intros Hf Le eps He. destruct (Hf eps He) as [N [HN F]]. exists N. split; [ exact HN | ].
  intros t Ht. specialize (Le t ltac:(lra)). specialize (F t Ht). lra.
Qed.

Lemma vanishes_scale (c : R) (f : R -> R) : vanishes f -> vanishes (fun t => c * f t).
Proof.
  intros Hf eps He. pose proof (Rabs_pos c) as Pc.
  destruct (Hf (eps / (Rabs c + 1))) as [N [HN F]]; [ apply Rdiv_lt_0_compat; lra | ].
  exists N. split; [ exact HN | ]. intros t Ht. specialize (F t Ht). rewrite Rabs_mult.
  pose proof (Rabs_pos (f t)).
  assert (E : (Rabs c + 1) * (eps / (Rabs c + 1)) = eps) by (field; lra).
  assert (Rabs c * Rabs (f t) <= (Rabs c + 1) * Rabs (f t)) by nra.
  assert ((Rabs c + 1) * Rabs (f t) < (Rabs c + 1) * (eps / (Rabs c + 1)))
    by (apply Rmult_lt_compat_l; lra).
  lra.
Qed.

Lemma vanishes_sqr (f : R -> R) : vanishes f -> vanishes (fun t => f t * f t).
Proof.
  intros Hf eps He. destruct (Hf (Rmin 1 eps)) as [N [HN F]]; [ apply Rmin_pos; lra | ].
  exists N. split; [ exact HN | ]. intros t Ht. specialize (F t Ht). rewrite Rabs_mult.
  pose proof (Rmin_l 1 eps). pose proof (Rmin_r 1 eps). pose proof (Rabs_pos (f t)). nra.
Qed.

Lemma vanishes_of_sqr (f : R -> R) : vanishes (fun t => f t * f t) -> vanishes f.
Proof.
  intros Hf eps He. destruct (Hf (eps * eps)) as [N [HN F]]; [ nra | ].
  exists N. split; [ exact HN | ]. intros t Ht. specialize (F t Ht). rewrite Rabs_mult in F.
  pose proof (Rabs_pos (f t)). nra.
Qed.

(** A squared norm vanishes iff the norm does. *)
Lemma vanishes_vnorm (u : R -> V3) :
  vanishes (fun t => vdot (u t) (u t)) -> vanishes (fun t => vnorm (u t)).
Proof.
  intro H. apply vanishes_of_sqr. apply (vanishes_le _ _ H). intros t _.
  unfold vnorm. rewrite sqrt_sqrt by apply vdot_self_nonneg. lra.
Qed.

Lemma vnorm_vanishes (u : R -> V3) :
  vanishes (fun t => vnorm (u t)) -> vanishes (fun t => vdot (u t) (u t)).
Proof.
  intro H. apply (vanishes_le _ _ (vanishes_sqr _ H)). intros t _.
  unfold vnorm. rewrite sqrt_sqrt by apply vdot_self_nonneg. lra.
Qed.

Lemma lipschitz_unif_cont (g : R -> R) (L : R) :
  (forall s t, 0 <= s -> 0 <= t -> Rabs (g t - g s) <= L * Rabs (t - s)) -> unif_cont g.
Proof.
  intros Lip eps He. pose proof (Rabs_pos L) as PL.
  exists (eps / (Rabs L + 1)). split; [ apply Rdiv_lt_0_compat; lra | ].
  intros s t Hs Ht Hd. specialize (Lip s t Hs Ht). pose proof (Rabs_pos (t - s)).
  pose proof (Rle_abs L).
  assert (E : (Rabs L + 1) * (eps / (Rabs L + 1)) = eps) by (field; lra).
  assert (L * Rabs (t - s) <= Rabs L * Rabs (t - s)) by nra.
  assert (Rabs L * Rabs (t - s) <= Rabs L * (eps / (Rabs L + 1))) by nra.
  assert (Rabs L * (eps / (Rabs L + 1)) < (Rabs L + 1) * (eps / (Rabs L + 1))).
  { apply Rmult_lt_compat_r; [ apply Rdiv_lt_0_compat | ]; lra. }
  lra.
Qed.

(** Barbalat's lemma, second form: if [f -> L] and [f'] is uniformly continuous, then
    [f' -> 0]. *)
Theorem barbalat_rate (f df : R -> R) (L : R) :
  (forall t, 0 <= t -> is_derive f t (df t)) ->
  vanishes (fun t => f t - L) -> unif_cont df -> vanishes df.
Proof.
  intros D Lim U eps He.
  destruct (U (eps / 2)) as [d [Hd Ud]]; [ lra | ].
  destruct (Lim (eps / 2 * d / 2)) as [N [HN F]].
  { apply Rdiv_lt_0_compat; [ apply Rmult_lt_0_compat | ]; lra. }
  exists N. split; [ exact HN | ]. intros t Ht.
  destruct (MVT_cor2 f df t (t + d) ltac:(lra)) as [c [E Hc]].
  { intros x Hx. apply is_derive_Reals, D. lra. }
  pose proof (F t Ht) as F1. pose proof (F (t + d) ltac:(lra)) as F2.
  assert (Hfd : Rabs (df c * d) < eps / 2 * d).
  { assert (Ed : f (t + d) - f t = df c * d) by (rewrite E; ring).
    replace (df c * d) with ((f (t + d) - L) + - (f t - L)) by lra.
    pose proof (Rabs_triang (f (t + d) - L) (- (f t - L))) as T.
    rewrite Rabs_Ropp in T. lra. }
  rewrite Rabs_mult, (Rabs_right d) in Hfd by lra.
  assert (Hc2 : Rabs (df c) < eps / 2).
  { apply (Rmult_lt_reg_r d); lra. }
  specialize (Ud t c ltac:(lra) ltac:(lra)).
  rewrite Rabs_right in Ud by lra. specialize (Ud ltac:(lra)).
  pose proof (Rabs_triang (df c) (df t - df c)) as T.
  replace (df c + (df t - df c)) with (df t) in T by ring.
  rewrite Rabs_minus_sym in Ud. lra.
Qed.

(** ** Closure of [bd] and [bl] under the ring operations *)

Lemma bd_const (c : R) : bd (fun _ => c).
Proof. exists (Rabs c). intros. lra. Qed.

Lemma bd_plus (f g : R -> R) : bd f -> bd g -> bd (fun s => f s + g s).
Proof.
  intros [Bf F] [Bg G]. exists (Bf + Bg). intros t Ht.
  pose proof (Rabs_triang (f t) (g t)). specialize (F t Ht). specialize (G t Ht). lra.
Qed.

Lemma bd_opp (f : R -> R) : bd f -> bd (fun s => - f s).
Proof. intros [B F]. exists B. intros t Ht. rewrite Rabs_Ropp. auto. Qed.

Lemma bd_minus (f g : R -> R) : bd f -> bd g -> bd (fun s => f s - g s).
Proof. intros Hf Hg. apply (bd_plus f (fun s => - g s) Hf (bd_opp g Hg)). Qed.

Lemma bd_mult (f g : R -> R) : bd f -> bd g -> bd (fun s => f s * g s).
Proof.
  intros [Bf F] [Bg G]. exists (Bf * Bg). intros t Ht. rewrite Rabs_mult.
  specialize (F t Ht). specialize (G t Ht).
  apply Rmult_le_compat; auto using Rabs_pos.
Qed.

Lemma bd_div (f : R -> R) (c : R) : bd f -> bd (fun s => f s / c).
Proof. intro Hf. apply (bd_mult f (fun _ => / c) Hf (bd_const _)). Qed.

Lemma bl_const (c : R) : bl (fun _ => c).
Proof.
  exists (Rabs c), 0. split; [ intros; lra | ]. intros s t _ _.
  replace (c - c) with 0 by ring. rewrite Rabs_R0. lra.
Qed.

Lemma bl_plus (f g : R -> R) : bl f -> bl g -> bl (fun s => f s + g s).
Proof.
  intros [Bf [Lf [F1 F2]]] [Bg [Lg [G1 G2]]]. exists (Bf + Bg), (Lf + Lg). split.
  - intros t Ht. pose proof (Rabs_triang (f t) (g t)). specialize (F1 t Ht). specialize (G1 t Ht). lra.
  - intros s t Hs Ht. specialize (F2 s t Hs Ht). specialize (G2 s t Hs Ht).
    replace (f t + g t - (f s + g s)) with ((f t - f s) + (g t - g s)) by ring.
    pose proof (Rabs_triang (f t - f s) (g t - g s)). lra.
Qed.

Lemma bl_opp (f : R -> R) : bl f -> bl (fun s => - f s).
Proof.
  intros [B [L [F1 F2]]]. exists B, L. split.
  - intros t Ht. rewrite Rabs_Ropp. auto.
  - intros s t Hs Ht. replace (- f t - - f s) with (- (f t - f s)) by ring.
    rewrite Rabs_Ropp. auto.
Qed.

Lemma bl_minus (f g : R -> R) : bl f -> bl g -> bl (fun s => f s - g s).
Proof. intros Hf Hg. apply (bl_plus f (fun s => - g s) Hf (bl_opp g Hg)). Qed.

Lemma bl_mult (f g : R -> R) : bl f -> bl g -> bl (fun s => f s * g s).
Proof.
  intros [Bf [Lf [F1 F2]]] [Bg [Lg [G1 G2]]].
  assert (PBf : 0 <= Bf) by (pose proof (Rabs_pos (f 0)); pose proof (F1 0 ltac:(lra)); lra).
  assert (PBg : 0 <= Bg) by (pose proof (Rabs_pos (g 0)); pose proof (G1 0 ltac:(lra)); lra).
  exists (Bf * Bg), (Bf * Lg + Bg * Lf). split.
  - intros t Ht. rewrite Rabs_mult. apply Rmult_le_compat; auto using Rabs_pos.
  - intros s t Hs Ht.
    replace (f t * g t - f s * g s) with (f t * (g t - g s) + g s * (f t - f s)) by ring.
    pose proof (Rabs_triang (f t * (g t - g s)) (g s * (f t - f s))).
    rewrite !Rabs_mult in *.
    assert (Rabs (f t) * Rabs (g t - g s) <= Bf * (Lg * Rabs (t - s)))
      by (apply Rmult_le_compat; auto using Rabs_pos).
    assert (Rabs (g s) * Rabs (f t - f s) <= Bg * (Lf * Rabs (t - s)))
      by (apply Rmult_le_compat; auto using Rabs_pos).
    lra.
Qed.

Lemma bl_div (f : R -> R) (c : R) : bl f -> bl (fun s => f s / c).
Proof. intro Hf. apply (bl_mult f (fun _ => / c) Hf (bl_const _)). Qed.

Lemma bl_bd (f : R -> R) : bl f -> bd f.
Proof. intros [B [L [F _]]]. exists B. exact F. Qed.

(** [bl_build] / [bd_build] prove [bl (fun s => e s)] / [bd (fun s => e s)] for [e]
    built with [+], [-], [*] and division by a constant from atoms whose property is
    a hypothesis. *)
Ltac bl_build :=
  lazymatch goal with
  | |- bl (fun _ => ?c) => exact (bl_const c)
  | |- bl (fun s => @?f s + @?g s) => refine (bl_plus f g _ _); bl_build
  | |- bl (fun s => @?f s * @?g s) => refine (bl_mult f g _ _); bl_build
  | |- bl (fun s => @?f s - @?g s) => refine (bl_minus f g _ _); bl_build
  | |- bl (fun s => - @?f s) => refine (bl_opp f _); bl_build
  | |- bl (fun s => @?f s / ?c) => refine (bl_div f c _); bl_build
  | |- bl ?f => assumption
  end.

Ltac bd_build :=
  lazymatch goal with
  | |- bd (fun _ => ?c) => exact (bd_const c)
  | |- bd (fun s => @?f s + @?g s) => refine (bd_plus f g _ _); bd_build
  | |- bd (fun s => @?f s * @?g s) => refine (bd_mult f g _ _); bd_build
  | |- bd (fun s => @?f s - @?g s) => refine (bd_minus f g _ _); bd_build
  | |- bd (fun s => - @?f s) => refine (bd_opp f _); bd_build
  | |- bd (fun s => @?f s / ?c) => refine (bd_div f c _); bd_build
  | |- bd ?f => assumption
  end.

Ltac entries_unfold :=
  cbv beta delta [mmul madd mscale mT msub mneg hat vee tr sk sym mvmul vadd vscale vneg
    vdot phi I3 Z3 vzero vsub e3];
  cbn [m11 m12 m13 m21 m22 m23 m31 m32 m33 v1 v2 v3].

(** A bounded derivative makes a function Lipschitz. *)
Lemma lipschitz_of_deriv (f df : R -> R) (B : R) :
  (forall t, 0 <= t -> is_derive f t (df t)) -> (forall t, 0 <= t -> Rabs (df t) <= B) ->
  forall s t, 0 <= s -> 0 <= t -> Rabs (f t - f s) <= B * Rabs (t - s).
Proof.
  intros D Bd s t Hs Ht.
  assert (Side : forall a b, 0 <= a -> a < b -> Rabs (f b - f a) <= B * Rabs (b - a)).
  { intros a b Ha Hab. destruct (MVT_cor2 f df a b Hab) as [c [E Hc]].
    - intros x Hx. apply is_derive_Reals, D. lra.
    - rewrite E, Rabs_mult. apply Rmult_le_compat_r; [ apply Rabs_pos | ].
      apply Bd. lra. }
  destruct (Rtotal_order s t) as [lt | [eq | gt]].
  - apply Side; assumption.
  - subst. replace (f t - f t) with 0 by ring. replace (t - t) with 0 by ring.
    rewrite Rabs_R0. lra.
  - rewrite (Rabs_minus_sym (f t)), (Rabs_minus_sym t). apply Side; assumption.
Qed.

Lemma bl_of_deriv (f df : R -> R) :
  (forall t, 0 <= t -> is_derive f t (df t)) -> bd f -> bd df -> bl f.
Proof.
  intros D [Bf F] [Bd G]. exists Bf, Bd. split; [ exact F | ].
  exact (lipschitz_of_deriv f df Bd D G).
Qed.

(** ** Matrix trajectories entry by entry *)

Definition mbd (A : R -> M3) : Prop :=
  bd (fun t => m11 (A t)) /\ bd (fun t => m12 (A t)) /\ bd (fun t => m13 (A t)) /\
  bd (fun t => m21 (A t)) /\ bd (fun t => m22 (A t)) /\ bd (fun t => m23 (A t)) /\
  bd (fun t => m31 (A t)) /\ bd (fun t => m32 (A t)) /\ bd (fun t => m33 (A t)).

Definition mbl (A : R -> M3) : Prop :=
  bl (fun t => m11 (A t)) /\ bl (fun t => m12 (A t)) /\ bl (fun t => m13 (A t)) /\
  bl (fun t => m21 (A t)) /\ bl (fun t => m22 (A t)) /\ bl (fun t => m23 (A t)) /\
  bl (fun t => m31 (A t)) /\ bl (fun t => m32 (A t)) /\ bl (fun t => m33 (A t)).

Definition mvanishes (A : R -> M3) : Prop :=
  vanishes (fun t => m11 (A t)) /\ vanishes (fun t => m12 (A t)) /\
  vanishes (fun t => m13 (A t)) /\ vanishes (fun t => m21 (A t)) /\
  vanishes (fun t => m22 (A t)) /\ vanishes (fun t => m23 (A t)) /\
  vanishes (fun t => m31 (A t)) /\ vanishes (fun t => m32 (A t)) /\
  vanishes (fun t => m33 (A t)).

Lemma abs_le_1 (x : R) : x * x <= 1 -> Rabs x <= 1.
Proof. intro H. apply Rabs_le. nra. Qed.

(** The entries of a rotation are at most 1 in absolute value (its columns are unit). *)
Lemma rot_entries_le_1 (M : M3) : is_rot M ->
  Rabs (m11 M) <= 1 /\ Rabs (m12 M) <= 1 /\ Rabs (m13 M) <= 1 /\
  Rabs (m21 M) <= 1 /\ Rabs (m22 M) <= 1 /\ Rabs (m23 M) <= 1 /\
  Rabs (m31 M) <= 1 /\ Rabs (m32 M) <= 1 /\ Rabs (m33 M) <= 1.
Proof.
  destruct M as [a b c d e f g h i]. intros [O _].
  unfold mmul, mT, I3 in O; simpl in O. injection O; intros. simpl.
  repeat split; apply abs_le_1; nra.
Qed.

Lemma rot_mbd (A : R -> M3) : (forall t, 0 <= t -> is_rot (A t)) -> mbd A.
Proof.
  intro H. unfold mbd. repeat split; exists 1; intros t Ht; apply (rot_entries_le_1 _ (H t Ht)).
Qed.

Lemma mbl_of_deriv (A DA : R -> M3) :
  (forall t, 0 <= t -> is_mderiv A t (DA t)) -> mbd A -> mbd DA -> mbl A.
Proof.
  intros D HA HD. unfold mbd, mbl, is_mderiv in *.
  destruct HA as [a11 [a12 [a13 [a21 [a22 [a23 [a31 [a32 a33]]]]]]]].
  destruct HD as [d11 [d12 [d13 [d21 [d22 [d23 [d31 [d32 d33]]]]]]]].
  repeat split;
  match goal with
  | |- bl (fun t => ?p (A t)) =>
      apply (bl_of_deriv _ (fun t => p (DA t)));
      [ intros t Ht; pose proof (D t Ht); m_intro; assumption | assumption | assumption ]
  end.
Qed.

(** The entries of a matrix vanish iff its squared Frobenius norm does. *)
Lemma fro2_vanishes_entries (A : R -> M3) :
  vanishes (fun t => fro2 (A t)) -> mvanishes A.
Proof.
  intro H. unfold mvanishes. repeat split; apply vanishes_of_sqr; apply (vanishes_le _ _ H);
    intros t _; pose proof (fro2_nonneg (A t)) as P; rewrite (Rabs_right (fro2 _)) by lra;
    rewrite Rabs_right by apply Rle_ge, sq_nonneg;
    destruct (A t); unfold fro2 in *; so3_unfold; nra.
Qed.

Lemma entries_vanish_fro2 (A : R -> M3) :
  mvanishes A -> vanishes (fun t => fro2 (A t)).
Proof.
  intros [a11 [a12 [a13 [a21 [a22 [a23 [a31 [a32 a33]]]]]]]].
  apply vanishes_sqr in a11, a12, a13, a21, a22, a23, a31, a32, a33.
  repeat match goal with
         | H1 : vanishes _, H2 : vanishes _ |- _ => pose proof (vanishes_plus _ _ H1 H2); clear H1 H2
         end.
  match goal with H : vanishes _ |- _ => apply (vanishes_le _ _ H) end.
  intros t _. apply Req_le. f_equal. destruct (A t). unfold fro2. so3_unfold. ring.
Qed.

(** ** At one instant: the algebra of the three steps *)

Lemma tr_cyclic (A B : M3) : tr (mmul A B) = tr (mmul B A).
Proof. destruct A, B. so3_unfold. ring. Qed.

Lemma tr_conj (M X : M3) : mmul M (mT M) = I3 -> tr (mmul (mT M) (mmul X M)) = tr X.
Proof. intro H. rewrite tr_cyclic, mmul_assoc, H, mmul_I3_r. reflexivity. Qed.

(** [||Q - I||_F^2 = 4 phi(Q)] for a rotation [Q] (the paper's identity for [phi]). *)
Lemma fro2_minus_I (Q : M3) : is_rot Q -> fro2 (msub Q I3) = 4 * phi Q.
Proof.
  destruct Q as [a b c d e f g h i]. intros [O _].
  unfold mmul, mT, I3 in O; simpl in O. injection O; intros.
  unfold fro2, phi. so3_unfold. nra.
Qed.

(** [|R_l e3 - R-bar e3|^2 <= 4 phi(R_l^T R-bar)] for rotations. *)
Lemma axes_gap (Rl Rb : M3) : is_rot Rl -> is_rot Rb ->
  vdot (vsub (mvmul Rl e3) (mvmul Rb e3)) (vsub (mvmul Rl e3) (mvmul Rb e3))
  <= 4 * phi (mmul (mT Rl) Rb).
Proof.
  intros Hl Hb. pose proof (rot_entries_le_1 _ (is_rot_relative _ _ Hl Hb)) as [B11 [_ [_ [_ [B22 _]]]]].
  pose proof (Rle_abs (m11 (mmul (mT Rl) Rb))). pose proof (Rle_abs (m22 (mmul (mT Rl) Rb))).
  destruct Hl as [Ol _], Hb as [Ob _].
  destruct Rl as [a b c d e f g h i], Rb as [a' b' c' d' e' f' g' h' i'].
  unfold mmul, mT, I3 in Ol, Ob; simpl in Ol, Ob. injection Ol; injection Ob; intros.
  unfold phi, vsub, e3 in *. so3_unfold. nra.
Qed.

(** For a rotation [M]: [hat(M^T w) = M^T hat(w) M]. *)
Lemma is_rot_hat_T (M : M3) (w : V3) : is_rot M ->
  hat (mvmul (mT M) w) = mmul (mT M) (mmul (hat w) M).
Proof.
  intro H. pose proof (is_rot_rr M H) as RR. destruct H as [_ Dt].
  pose proof (hat_adj M (mvmul (mT M) w)) as A.
  rewrite <- mvmul_mmul, RR, mvmul_I3, Dt in A. rewrite A.
  destruct (mvmul (mT M) w). so3_split; so3_unfold; lra.
Qed.

(** The LaSalle step's derivative, eqs. (12b) and (13): with [Q = R_l^T R-bar],
    [d/dt Q = - k_s (Q sk(Q) + sk(Q) Q) - R_l^T hat(omega_h^s) R-bar]. *)
Definition rel_rate (ks : R) (Rl Rb : M3) (w : V3) : M3 :=
  madd (mmul (mT (mmul Rl (hat (vadd (vscale ks (vee (sk (mmul (mT Rl) Rb))))
                                     (mvmul (mT Rl) w))))) Rb)
       (mmul (mT Rl) (mscale ks (mmul Rb (sk (mmul (mT Rb) Rl))))).

Lemma rel_rate_identity (ks : R) (Rl Rb : M3) (w : V3) : is_rot Rl ->
  rel_rate ks Rl Rb w
  = msub (mscale (- ks) (madd (mmul (mmul (mT Rl) Rb) (sk (mmul (mT Rl) Rb)))
                              (mmul (sk (mmul (mT Rl) Rb)) (mmul (mT Rl) Rb))))
         (mmul (mT Rl) (mmul (hat w) Rb)).
Proof.
  intro H. pose proof (is_rot_rr Rl H) as RR. unfold rel_rate.
  rewrite hat_vadd, (is_rot_hat_T Rl w H), hat_vscale, hat_vee.
  rewrite mT_mmul, mT_madd, mT_mscale, mT_mmul, mT_mmul, mT_mT, mT_hat.
  rewrite !mmul_madd_l, !mmul_mscale_l, !mmul_assoc, <- (mmul_assoc Rl (mT Rl) Rb), RR, mmul_I3_l.
  destruct Rl, Rb, w. so3_split; so3_unfold; lra.
Qed.

(** [||R_l^T hat(w) R-bar||_F^2 = 2 |w|^2] for rotations. *)
Lemma fro2_hat_conj (Rl Rb : M3) (w : V3) : is_rot Rl -> is_rot Rb ->
  fro2 (mmul (mT Rl) (mmul (hat w) Rb)) = 2 * vdot w w.
Proof.
  intros Hl Hb. pose proof (is_rot_rr Rl Hl) as RL. pose proof (is_rot_rr Rb Hb) as RB.
  assert (E : mmul (mT (mmul (mT Rl) (mmul (hat w) Rb))) (mmul (mT Rl) (mmul (hat w) Rb))
              = mmul (mT Rb) (mmul (mmul (mT (hat w)) (hat w)) Rb)).
  { rewrite !mT_mmul, mT_mT, !mmul_assoc, <- (mmul_assoc Rl (mT Rl)), RL, mmul_I3_l.
    reflexivity. }
  unfold fro2. rewrite E, (tr_conj Rb _ RB). destruct w. so3_unfold. ring.
Qed.

Lemma fro2_madd_le (A B : M3) : fro2 (madd A B) <= 2 * fro2 A + 2 * fro2 B.
Proof.
  pose proof (fro2_nonneg (msub A B)) as P.
  assert (E : 2 * fro2 A + 2 * fro2 B - fro2 (madd A B) = fro2 (msub A B))
    by (destruct A, B; unfold fro2; so3_unfold; ring).
  lra.
Qed.

Lemma fro2_mscale (c : R) (A : M3) : fro2 (mscale c A) = c * c * fro2 A.
Proof. destruct A. unfold fro2. so3_unfold. ring. Qed.

Lemma fro2_msub_le (A B : M3) : fro2 (msub A B) <= 2 * fro2 A + 2 * fro2 B.
Proof.
  unfold msub, mneg. pose proof (fro2_madd_le A (mscale (-1) B)) as H.
  rewrite fro2_mscale in H. lra.
Qed.

Lemma fro2_rot_l (Q S : M3) : is_rot Q -> fro2 (mmul Q S) = fro2 S.
Proof.
  intros [O _]. unfold fro2. rewrite mT_mmul, mmul_assoc, <- (mmul_assoc (mT Q) Q S), O, mmul_I3_l.
  reflexivity.
Qed.

Lemma fro2_rot_r (Q S : M3) : is_rot Q -> fro2 (mmul S Q) = fro2 S.
Proof.
  intro H. unfold fro2.
  rewrite mT_mmul, mmul_assoc, <- (mmul_assoc (mT S) S Q), (tr_conj Q _ (is_rot_rr Q H)).
  reflexivity.
Qed.

(** [||sk Q||_F^2 <= ||Q - I||_F^2]: [sk] is the skew part of [Q - I]. *)
Lemma fro2_sk_le (Q : M3) : fro2 (sk Q) <= fro2 (msub Q I3).
Proof.
  pose proof (fro2_nonneg (msub (sym Q) I3)) as P.
  assert (E : fro2 (msub Q I3) = fro2 (sk Q) + fro2 (msub (sym Q) I3))
    by (destruct Q; unfold fro2; so3_unfold; field).
  lra.
Qed.

(** The command's size from the relative rate: with [Q = R_l^T R-bar],
    [2 |w|^2 <= 32 k_s^2 phi(Q) + 2 ||d/dt Q||_F^2]. *)
Lemma command_from_rate (ks : R) (Rl Rb : M3) (w : V3) : is_rot Rl -> is_rot Rb ->
  2 * vdot w w <= 32 * (ks * ks) * phi (mmul (mT Rl) Rb) + 2 * fro2 (rel_rate ks Rl Rb w).
Proof.
  intros Hl Hb. set (Q := mmul (mT Rl) Rb). pose proof (is_rot_relative _ _ Hl Hb) as HQ.
  fold Q in HQ.
  assert (E : mmul (mT Rl) (mmul (hat w) Rb)
              = msub (mscale (- ks) (madd (mmul Q (sk Q)) (mmul (sk Q) Q))) (rel_rate ks Rl Rb w)).
  { rewrite (rel_rate_identity ks Rl Rb w Hl). fold Q.
    generalize (mmul (mT Rl) (mmul (hat w) Rb)). intro X.
    destruct X, (mscale (- ks) (madd (mmul Q (sk Q)) (mmul (sk Q) Q))).
    so3_split; so3_unfold; ring. }
  rewrite <- (fro2_hat_conj Rl Rb w Hl Hb), E.
  pose proof (fro2_msub_le (mscale (- ks) (madd (mmul Q (sk Q)) (mmul (sk Q) Q)))
                           (rel_rate ks Rl Rb w)) as T1.
  rewrite fro2_mscale in T1. replace (- ks * - ks) with (ks * ks) in T1 by ring.
  pose proof (fro2_madd_le (mmul Q (sk Q)) (mmul (sk Q) Q)) as T2.
  rewrite (fro2_rot_l Q _ HQ), (fro2_rot_r Q _ HQ) in T2.
  pose proof (fro2_sk_le Q) as T3. rewrite (fro2_minus_I Q HQ) in T3.
  assert (Pk : 0 <= ks * ks) by apply sq_nonneg.
  pose proof (fro2_nonneg (sk Q)).
  assert (ks * ks * fro2 (madd (mmul Q (sk Q)) (mmul (sk Q) Q)) <= ks * ks * (4 * fro2 (sk Q)))
    by (apply Rmult_le_compat_l; lra).
  assert (ks * ks * fro2 (sk Q) <= ks * ks * (4 * phi Q)) by (apply Rmult_le_compat_l; lra).
  lra.
Qed.
