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
      [R-bar e3] with [d-bar] at time 0 and the stealthy control keeps it so; here
      [R-bar e3] is the definition).  The Lipschitz rate that [Barbalat.v] takes as a premise is proved
      from a bounded human command.
    - [d/dt (R_l^T R-bar) = - R_l^T hat(omega_h^s) R-bar - k_s (Q sk Q + sk Q Q)] with
      [Q = R_l^T R-bar] (eqs. (12b), (13); at [Q = I] it is the paper's
      [- R_l^T hat(omega_h^s) R_l]); Barbalat's lemma in its second form ([f -> L] and
      [f'] uniformly continuous give [f' -> 0], proved here) makes the derivative vanish,
      and [||R_l^T hat(w) R-bar||_F^2 = 2 |w|^2] then gives [omega_h^s -> 0].
    - Item 3 in the asymptotic form "[omega_h^s -> 0] implies [d_l -> d_r]" (a named
      premise) then gives [d-bar -> d_r], the control objective of Section 2.

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

(** A property of scalar functions closed under the ring operations ([bd], [bl]),
    lifted to matrix and vector trajectories entry by entry; the closure under the
    paper's operations ([mmul], [mT], [sk], [hat], [vee], ...) is proved once, so that a
    long expression such as [d/dt (R_l^T R-bar)] is handled operation by operation. *)
Definition closed (P : (R -> R) -> Prop) : Prop :=
  (forall c, P (fun _ => c)) /\ (forall f g, P f -> P g -> P (fun s => f s + g s)) /\
  (forall f g, P f -> P g -> P (fun s => f s * g s)) /\ (forall f, P f -> P (fun s => - f s)).

Definition mP (P : (R -> R) -> Prop) (A : R -> M3) : Prop :=
  P (fun t => m11 (A t)) /\ P (fun t => m12 (A t)) /\ P (fun t => m13 (A t)) /\
  P (fun t => m21 (A t)) /\ P (fun t => m22 (A t)) /\ P (fun t => m23 (A t)) /\
  P (fun t => m31 (A t)) /\ P (fun t => m32 (A t)) /\ P (fun t => m33 (A t)).

Definition vP (P : (R -> R) -> Prop) (u : R -> V3) : Prop :=
  P (fun t => v1 (u t)) /\ P (fun t => v2 (u t)) /\ P (fun t => v3 (u t)).

Notation mbd := (mP bd).
Notation mbl := (mP bl).

Lemma bd_closed : closed bd.
Proof. split; [ exact bd_const | split; [ exact bd_plus | split; [ exact bd_mult | exact bd_opp ] ] ]. Qed.

Lemma bl_closed : closed bl.
Proof. split; [ exact bl_const | split; [ exact bl_plus | split; [ exact bl_mult | exact bl_opp ] ] ]. Qed.

Ltac ent_unfold := cbv beta iota zeta delta [mmul madd mscale mT msub mneg hat vee
    tr sk sym mvmul vadd vscale vneg vdot phi I3 Z3 vzero vsub e3
    m11 m12 m13 m21 m22 m23 m31 m32 m33 v1 v2 v3].

Ltac split_all := repeat match goal with H : _ /\ _ |- _ => destruct H end.

(** [p_build] proves [P (fun s => e s)] for [e] built with [+], [-], [*] and division
    by a constant from atoms whose property is a hypothesis. *)
Ltac p_build Pc Pp Pm Po :=
  lazymatch goal with
  | |- ?P (fun _ => ?c) => exact (Pc c)
  | |- ?P (fun s => @?f s + @?g s) => refine (Pp f g _ _); p_build Pc Pp Pm Po
  | |- ?P (fun s => @?f s * @?g s) => refine (Pm f g _ _); p_build Pc Pp Pm Po
  | |- ?P (fun s => @?f s - @?g s) =>
      refine (Pp f (fun s => - g s) _ (Po g _)); p_build Pc Pp Pm Po
  | |- ?P (fun s => - @?f s) => refine (Po f _); p_build Pc Pp Pm Po
  | |- ?P (fun s => @?f s / ?c) => refine (Pm f (fun _ => / c) _ (Pc _)); p_build Pc Pp Pm Po
  | |- _ => assumption
  end.

Ltac closure_entries HP :=
  let Pc := fresh "Pc" in let Pp := fresh "Pp" in let Pm := fresh "Pm" in let Po := fresh "Po" in
  destruct HP as [Pc [Pp [Pm Po]]]; unfold mP, vP in *; split_all;
  repeat split; ent_unfold; p_build Pc Pp Pm Po.

Section Closure.
Variable P : (R -> R) -> Prop.
Hypothesis HP : closed P.

Lemma mP_mmul (A B : R -> M3) : mP P A -> mP P B -> mP P (fun t => mmul (A t) (B t)).
Proof. intros. closure_entries HP. Qed.
Lemma mP_madd (A B : R -> M3) : mP P A -> mP P B -> mP P (fun t => madd (A t) (B t)).
Proof. intros. closure_entries HP. Qed.
Lemma mP_mscale (c : R) (A : R -> M3) : mP P A -> mP P (fun t => mscale c (A t)).
Proof. intros. closure_entries HP. Qed.
Lemma mP_mT (A : R -> M3) : mP P A -> mP P (fun t => mT (A t)).
Proof. intros. closure_entries HP. Qed.
Lemma mP_sk (A : R -> M3) : mP P A -> mP P (fun t => sk (A t)).
Proof. intros. closure_entries HP. Qed.
Lemma mP_hat (u : R -> V3) : vP P u -> mP P (fun t => hat (u t)).
Proof. intros. closure_entries HP. Qed.
Lemma vP_vee (A : R -> M3) : mP P A -> vP P (fun t => vee (A t)).
Proof. intros. closure_entries HP. Qed.
Lemma vP_vadd (u v : R -> V3) : vP P u -> vP P v -> vP P (fun t => vadd (u t) (v t)).
Proof. intros. closure_entries HP. Qed.
Lemma vP_vscale (c : R) (u : R -> V3) : vP P u -> vP P (fun t => vscale c (u t)).
Proof. intros. closure_entries HP. Qed.
Lemma vP_mvmul (A : R -> M3) (u : R -> V3) : mP P A -> vP P u -> vP P (fun t => mvmul (A t) (u t)).
Proof. intros. closure_entries HP. Qed.
Lemma P_phi (A : R -> M3) : mP P A -> P (fun t => phi (A t)).
Proof. intros. closure_entries HP. Qed.
End Closure.

(** [struct_build HP] proves [mP P (fun t => e t)] (or [vP]) for [e] built with the
    paper's matrix operations from trajectories whose property is a hypothesis. *)
Ltac struct_build HP :=
  lazymatch goal with
  | |- mP ?P (fun t => mmul (@?A t) (@?B t)) => refine (mP_mmul P HP A B _ _); struct_build HP
  | |- mP ?P (fun t => madd (@?A t) (@?B t)) => refine (mP_madd P HP A B _ _); struct_build HP
  | |- mP ?P (fun t => mscale ?c (@?A t)) => refine (mP_mscale P HP c A _); struct_build HP
  | |- mP ?P (fun t => mT (@?A t)) => refine (mP_mT P HP A _); struct_build HP
  | |- mP ?P (fun t => sk (@?A t)) => refine (mP_sk P HP A _); struct_build HP
  | |- mP ?P (fun t => hat (@?u t)) => refine (mP_hat P HP u _); struct_build HP
  | |- vP ?P (fun t => vee (@?A t)) => refine (vP_vee P HP A _); struct_build HP
  | |- vP ?P (fun t => vadd (@?u t) (@?v t)) => refine (vP_vadd P HP u v _ _); struct_build HP
  | |- vP ?P (fun t => vscale ?c (@?u t)) => refine (vP_vscale P HP c u _); struct_build HP
  | |- vP ?P (fun t => mvmul (@?A t) (@?u t)) => refine (vP_mvmul P HP A u _ _); struct_build HP
  | |- _ => assumption
  end.

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
  intro H. unfold mP. repeat split; exists 1; intros t Ht; apply (rot_entries_le_1 _ (H t Ht)).
Qed.

Lemma mbl_of_deriv (A DA : R -> M3) :
  (forall t, 0 <= t -> is_mderiv A t (DA t)) -> mbd A -> mbd DA -> mbl A.
Proof.
  intros D HA HD. unfold mP, is_mderiv in *.
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
  unfold phi, vsub, e3 in *. so3_unfold. lra.
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
    by (destruct A, B; unfold fro2; so3_unfold; lra).
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
    by (destruct Q; unfold fro2; so3_unfold; lra).
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

Lemma msub_Z3 (A : M3) : msub A Z3 = A.
Proof. destruct A. so3_split; so3_unfold; ring. Qed.

Lemma vdot_vsub_le (a b c : V3) :
  vdot (vsub a c) (vsub a c) <= 2 * vdot (vsub b a) (vsub b a) + 2 * vdot (vsub b c) (vsub b c).
Proof.
  pose proof (vdot_self_nonneg (vsub (vsub b a) (vsub c b))) as P.
  destruct a, b, c. unfold vsub in *. so3_unfold. nra.
Qed.

Lemma abs_v_le_vnorm (u : V3) : Rabs (v1 u) <= vnorm u /\ Rabs (v2 u) <= vnorm u /\ Rabs (v3 u) <= vnorm u.
Proof.
  unfold vnorm. destruct u as [a b c]. unfold vdot; simpl.
  repeat split; rewrite <- sqrt_Rsqr_abs; apply sqrt_le_1_alt; unfold Rsqr; nra.
Qed.

(** The derivative of a matrix trajectory vanishes when the trajectory converges and
    the derivative is bounded and Lipschitz (Barbalat's second form, entry by entry). *)
Lemma rate_entry (e de : R -> R) :
  (forall t, 0 <= t -> is_derive e t (de t)) -> vanishes e -> bl de -> vanishes de.
Proof.
  intros D V [B [L [_ Lip]]]. apply (barbalat_rate e de 0 D).
  - apply (vanishes_le _ _ V). intros t _. rewrite Rminus_0_r. lra.
  - exact (lipschitz_unif_cont de L Lip).
Qed.

Lemma mrate (A DA : R -> M3) :
  (forall t, 0 <= t -> is_mderiv A t (DA t)) -> mvanishes A -> mbl DA -> mvanishes DA.
Proof.
  intros D HA HD. unfold mvanishes, mP, is_mderiv in *.
  destruct HA as [a11 [a12 [a13 [a21 [a22 [a23 [a31 [a32 a33]]]]]]]].
  destruct HD as [d11 [d12 [d13 [d21 [d22 [d23 [d31 [d32 d33]]]]]]]].
  repeat split;
  match goal with
  | |- vanishes (fun t => ?p (DA t)) =>
      apply (rate_entry (fun t => p (A t)));
      [ intros t Ht; pose proof (D t Ht); m_intro; assumption | assumption | assumption ]
  end.
Qed.

(** ** Along solutions *)
Section LaSalle.
Variables (Rr : M3) (Rb Rl : R -> M3) (ws : R -> V3) (Sh dSh : R -> R) (ks lam Bw Lw : R).
Hypothesis ks_pos : 0 < ks.
Hypothesis lam_pos : 0 < lam.
Hypothesis Rr_rot : is_rot Rr.
Hypothesis Rb_rot : forall t, 0 <= t -> is_rot (Rb t).
Hypothesis Rl_rot : forall t, 0 <= t -> is_rot (Rl t).
Hypothesis Rb_sol : forall t, 0 <= t ->
  is_mderiv Rb t (mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t))))).
Hypothesis Rl_sol : forall t, 0 <= t ->
  is_mderiv Rl t (mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                         (mvmul (mT (Rl t)) (ws t))))).
Hypothesis Sh_deriv : forall t, 0 <= t -> is_derive Sh t (dSh t).
Hypothesis Sh_supply : forall t, 0 <= t ->
  dSh t <= vdot (vee (sk (mmul (mT (Rl t)) Rr))) (mvmul (mT (Rl t)) (ws t)).
Hypothesis Sh_nonneg : forall t, 0 <= t -> 0 <= Sh t.
Hypothesis item2 : forall t, 0 <= t -> lam_min_spec (mmul (mT Rr) (Rl t)) lam.
Hypothesis init : 1 <= tr (mmul (mT Rr) (Rb 0)).
(** The human command is bounded (item 4 bounds the human's output for a bounded input,
    and the input [sk(R_l^T R_r)^vee] is bounded) ... *)
Hypothesis ws_bounded : forall t, 0 <= t -> vnorm (ws t) <= Bw.
(** ... and Lipschitz (a bounded rate: not in Assumption 1; an LTI human with bounded
    state and input has it). *)
Hypothesis ws_lipschitz : forall s t, 0 <= s -> 0 <= t ->
  vnorm (vsub (ws t) (ws s)) <= Lw * Rabs (t - s).
(** Assumption 1, item 3, in asymptotic form: if the operator's command dies out, the
    leader's axis reaches the reference axis [d_r = R_r e3]. *)
Hypothesis item3_asymptotic :
  vanishes (fun t => vnorm (ws t)) -> vanishes (fun t => vnorm (vsub (mvmul (Rl t) e3) (mvmul Rr e3))).

Lemma ws_bd : vP bd ws.
Proof.
  unfold vP. repeat split; exists Bw; intros t Ht; pose proof (abs_v_le_vnorm (ws t)) as A;
    pose proof (ws_bounded t Ht); split_all; lra.
Qed.

Lemma ws_bl : vP bl ws.
Proof.
  unfold vP. repeat split; exists Bw, Lw; split;
    try (intros t Ht; pose proof (abs_v_le_vnorm (ws t)) as A;
         pose proof (ws_bounded t Ht); split_all; lra);
    intros s t Hs Ht; cbv beta; pose proof (abs_v_le_vnorm (vsub (ws t) (ws s))) as A;
    pose proof (ws_lipschitz s t Hs Ht);
    destruct (ws t) as [a1 a2 a3], (ws s) as [b1 b2 b3]; unfold vsub, vadd, vneg in *;
    cbn [v1 v2 v3] in *; split_all;
    unfold Rminus at 1; lra.
Qed.

Lemma Rl_mbl : mbl Rl.
Proof.
  apply (mbl_of_deriv Rl (fun t => mmul (Rl t) (hat (vadd (vscale ks (vee (sk (mmul (mT (Rl t)) (Rb t)))))
                                                          (mvmul (mT (Rl t)) (ws t)))))
           Rl_sol (rot_mbd Rl Rl_rot)).
  pose proof (rot_mbd Rl Rl_rot). pose proof (rot_mbd Rb Rb_rot). pose proof ws_bd.
  struct_build bd_closed.
Qed.

Lemma Rb_mbl : mbl Rb.
Proof.
  apply (mbl_of_deriv Rb (fun t => mscale ks (mmul (Rb t) (sk (mmul (mT (Rb t)) (Rl t)))))
           Rb_sol (rot_mbd Rb Rb_rot)).
  pose proof (rot_mbd Rl Rl_rot). pose proof (rot_mbd Rb Rb_rot).
  struct_build bd_closed.
Qed.

Lemma phi_rel_nonneg (t : R) : 0 <= t -> 0 <= phi (mmul (mT (Rl t)) (Rb t)).
Proof.
  intro Ht. exact (phi_rel_rot_nonneg _ _ (Rl_rot t Ht) (Rb_rot t Ht)).
Qed.

(** Step 1: [phi(R_l^T R-bar) -> 0], with the Lipschitz rate proved from a bounded command. *)
Theorem sync_phi_vanishes : vanishes (fun t => phi (mmul (mT (Rl t)) (Rb t))).
Proof.
  assert (P : bl (fun t => phi (mmul (mT (Rl t)) (Rb t)))).
  { pose proof Rl_mbl. pose proof Rb_mbl.
    apply (P_phi bl bl_closed (fun t => mmul (mT (Rl t)) (Rb t))). struct_build bl_closed. }
  destruct P as [B [L [_ Lip]]].
  assert (C : forall eps, 0 < eps ->
            exists N, 0 <= N /\ forall t, N <= t -> phi (mmul (mT (Rl t)) (Rb t)) < eps).
  { apply (phi_sync_converges Rr Rb Rl ws Sh dSh ks lam (Rabs L + 1)); try assumption.
    - pose proof (Rabs_pos L). lra.
    - intros s t Hs Ht. specialize (Lip s t Hs Ht). pose proof (Rle_abs L).
      pose proof (Rabs_pos (t - s)). nra. }
  intros eps He. destruct (C eps He) as [N [HN H]]. exists N. split; [ exact HN | ].
  intros t Ht. rewrite Rabs_right by (apply Rle_ge, phi_rel_nonneg; lra). exact (H t Ht).
Qed.

(** [R_l^T R-bar -> I] (Frobenius norm) and [d_l - d-bar -> 0]. *)
Theorem sync_axes :
  vanishes (fun t => fro2 (msub (mmul (mT (Rl t)) (Rb t)) I3)) /\
  vanishes (fun t => vnorm (vsub (mvmul (Rl t) e3) (mvmul (Rb t) e3))).
Proof.
  pose proof (vanishes_scale 4 _ sync_phi_vanishes) as V4. split.
  - apply (vanishes_le _ _ V4). intros t Ht.
    rewrite (fro2_minus_I _ (is_rot_relative _ _ (Rl_rot t Ht) (Rb_rot t Ht))). lra.
  - apply vanishes_vnorm, (vanishes_le _ _ V4). intros t Ht.
    pose proof (axes_gap _ _ (Rl_rot t Ht) (Rb_rot t Ht)).
    pose proof (vdot_self_nonneg (vsub (mvmul (Rl t) e3) (mvmul (Rb t) e3))).
    rewrite !Rabs_right; lra.
Qed.

(** The LaSalle step's derivative along the solution. *)
Lemma rel_deriv (t : R) : 0 <= t ->
  is_mderiv (fun s => msub (mmul (mT (Rl s)) (Rb s)) I3) t (rel_rate ks (Rl t) (Rb t) (ws t)).
Proof.
  intro Ht.
  pose proof (mderiv_msub _ _ t _ _
                (mderiv_mmul (fun s => mT (Rl s)) Rb t _ _ (mderiv_mT Rl t _ (Rl_sol t Ht)) (Rb_sol t Ht))
                (mderiv_const I3 t)) as D.
  rewrite msub_Z3 in D. exact D.
Qed.

Theorem rel_rate_along (t : R) : 0 <= t ->
  is_mderiv (fun s => mmul (mT (Rl s)) (Rb s)) t
    (msub (mscale (- ks) (madd (mmul (mmul (mT (Rl t)) (Rb t)) (sk (mmul (mT (Rl t)) (Rb t))))
                               (mmul (sk (mmul (mT (Rl t)) (Rb t))) (mmul (mT (Rl t)) (Rb t)))))
          (mmul (mT (Rl t)) (mmul (hat (ws t)) (Rb t)))).
Proof.
  intro Ht. rewrite <- (rel_rate_identity ks (Rl t) (Rb t) (ws t) (Rl_rot t Ht)).
  exact (mderiv_mmul (fun s => mT (Rl s)) Rb t _ _ (mderiv_mT Rl t _ (Rl_sol t Ht)) (Rb_sol t Ht)).
Qed.

(** Step 2: [d/dt (R_l^T R-bar) -> 0] (Barbalat's second form) and so [omega_h^s -> 0]. *)
Theorem rate_vanishes : vanishes (fun t => fro2 (rel_rate ks (Rl t) (Rb t) (ws t))).
Proof.
  apply entries_vanish_fro2.
  apply (mrate (fun s => msub (mmul (mT (Rl s)) (Rb s)) I3)); [ exact rel_deriv | | ].
  - apply fro2_vanishes_entries. exact (proj1 sync_axes).
  - pose proof Rl_mbl. pose proof Rb_mbl. pose proof ws_bl. unfold rel_rate.
    struct_build bl_closed.
Qed.

Theorem command_vanishes : vanishes (fun t => vnorm (ws t)).
Proof.
  apply vanishes_vnorm.
  pose proof (vanishes_plus _ _ (vanishes_scale (16 * (ks * ks)) _ sync_phi_vanishes) rate_vanishes) as S.
  apply (vanishes_le _ _ S). intros t Ht.
  pose proof (command_from_rate ks (Rl t) (Rb t) (ws t) (Rl_rot t Ht) (Rb_rot t Ht)).
  pose proof (vdot_self_nonneg (ws t)).
  pose proof (phi_rel_nonneg t Ht). pose proof (fro2_nonneg (rel_rate ks (Rl t) (Rb t) (ws t))).
  assert (0 <= 16 * (ks * ks) * phi (mmul (mT (Rl t)) (Rb t)))
    by (apply Rmult_le_pos; [ pose proof (sq_nonneg ks); lra | assumption ]).
  rewrite !Rabs_right; lra.
Qed.

(** Step 3: with item 3 in asymptotic form, [d-bar -> d_r] (the control objective of Section 2). *)
Theorem dbar_converges : vanishes (fun t => vnorm (vsub (mvmul (Rb t) e3) (mvmul Rr e3))).
Proof.
  apply vanishes_vnorm.
  pose proof (vnorm_vanishes _ (proj2 sync_axes)) as A.
  pose proof (vnorm_vanishes _ (item3_asymptotic command_vanishes)) as B.
  pose proof (vanishes_plus _ _ (vanishes_scale 2 _ A) (vanishes_scale 2 _ B)) as S.
  apply (vanishes_le _ _ S). intros t _.
  pose proof (vdot_vsub_le (mvmul (Rb t) e3) (mvmul (Rl t) e3) (mvmul Rr e3)).
  pose proof (vdot_self_nonneg (vsub (mvmul (Rb t) e3) (mvmul Rr e3))).
  pose proof (vdot_self_nonneg (vsub (mvmul (Rl t) e3) (mvmul (Rb t) e3))).
  pose proof (vdot_self_nonneg (vsub (mvmul (Rl t) e3) (mvmul Rr e3))).
  rewrite !Rabs_right; lra.
Qed.

End LaSalle.
