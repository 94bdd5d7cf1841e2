(** * Trajectories: matrix- and vector-valued functions of time and their derivatives

    A trajectory is a function [R -> M3] (or [R -> V3]); its derivative at [t] is taken
    entry by entry with Coquelicot's [is_derive] (the derivative of a real function of a
    real variable).  The rules below (constant, sum, scaling, product, transpose, [hat],
    [tr], [sk], [sym], [phi], matrix-vector product, dot product) are proved once, so the
    time derivatives of the paper's proofs (Section 3, Lemma 1 and Theorem 1) are kernel
    theorems about every differentiable trajectory, not computations of ours. *)

From Coq Require Import Reals Lra.
Local Set Warnings "-ambiguous-paths".
From Coquelicot Require Import Coquelicot.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

(** ** Scalar rules in the shape the entry-wise proofs use *)

Lemma d_plus (f g : R -> R) (t df dg : R) :
  is_derive f t df -> is_derive g t dg -> is_derive (fun s => f s + g s) t (df + dg).
Proof. intros Hf Hg. exact (is_derive_plus f g t df dg Hf Hg). Qed.

Lemma d_mult (f g : R -> R) (t df dg : R) :
  is_derive f t df -> is_derive g t dg ->
  is_derive (fun s => f s * g s) t (df * g t + f t * dg).
Proof. intros Hf Hg. exact (is_derive_mult f g t df dg Hf Hg (fun n m => Rmult_comm n m)). Qed.

Lemma d_const (c t : R) : is_derive (fun _ => c) t 0.
Proof. exact (is_derive_const c t). Qed.

Lemma d_opp (f : R -> R) (t df : R) :
  is_derive f t df -> is_derive (fun s => - f s) t (- df).
Proof. intro Hf. exact (is_derive_opp f t df Hf). Qed.

Lemma d_minus (f g : R -> R) (t df dg : R) :
  is_derive f t df -> is_derive g t dg -> is_derive (fun s => f s - g s) t (df - dg).
Proof. intros Hf Hg. exact (is_derive_minus f g t df dg Hf Hg). Qed.

Lemma d_eq (f : R -> R) (t l l' : R) : is_derive f t l -> l = l' -> is_derive f t l'.
Proof. intros H <-. exact H. Qed.

Lemma d_div (f : R -> R) (t df c : R) :
  is_derive f t df -> is_derive (fun s => f s / c) t (df / c).
Proof.
  intro Hf. unfold Rdiv.
  apply (d_eq (fun s => f s * / c) t (df * / c + f t * 0)); [ | ring ].
  apply (d_mult f (fun _ => / c) t df 0 Hf (d_const (/ c) t)).
Qed.



(** [d_auto] proves [is_derive (fun s => e s) t ?] for [e] built with [+], [-], [*]
    (and division by a constant) from functions whose derivatives are hypotheses. *)
Ltac d_build :=
  lazymatch goal with
  | |- is_derive (fun s => @?f s + @?g s) ?t _ => refine (d_plus f g t _ _ _ _); d_build
  | |- is_derive (fun s => @?f s * @?g s) ?t _ => refine (d_mult f g t _ _ _ _); d_build
  | |- is_derive (fun s => @?f s - @?g s) ?t _ => refine (d_minus f g t _ _ _ _); d_build
  | |- is_derive (fun s => - @?f s) ?t _ => refine (d_opp f t _ _); d_build
  | |- is_derive (fun s => @?f s / ?c) ?t _ => refine (d_div f t _ c _); d_build
  | |- is_derive (fun _ => ?c) ?t _ => exact (d_const c t)
  | |- is_derive ?f ?t _ =>
      match goal with H : is_derive f t _ |- _ => exact H end
  end.

Ltac d_auto :=
  eapply d_eq; [ d_build | cbv beta; first [ lra | ring | field ] ].

(** ** Entry-wise derivatives *)

Definition is_mderiv (A : R -> M3) (t : R) (D : M3) : Prop :=
  is_derive (fun s => m11 (A s)) t (m11 D) /\ is_derive (fun s => m12 (A s)) t (m12 D) /\
  is_derive (fun s => m13 (A s)) t (m13 D) /\ is_derive (fun s => m21 (A s)) t (m21 D) /\
  is_derive (fun s => m22 (A s)) t (m22 D) /\ is_derive (fun s => m23 (A s)) t (m23 D) /\
  is_derive (fun s => m31 (A s)) t (m31 D) /\ is_derive (fun s => m32 (A s)) t (m32 D) /\
  is_derive (fun s => m33 (A s)) t (m33 D).

Definition is_vderiv (u : R -> V3) (t : R) (d : V3) : Prop :=
  is_derive (fun s => v1 (u s)) t (v1 d) /\ is_derive (fun s => v2 (u s)) t (v2 d) /\
  is_derive (fun s => v3 (u s)) t (v3 d).

Ltac m_intro := intros; repeat match goal with H : _ /\ _ |- _ => destruct H end.
Ltac m_split := repeat match goal with |- _ /\ _ => split end.
Ltac m_entries := m_intro; unfold is_mderiv, is_vderiv in *; m_intro; m_split;
  cbv beta delta [mmul madd mscale mT msub mneg hat vee tr sk sym mvmul vadd vscale
    vdot phi I3 Z3 vzero];
  cbn [m11 m12 m13 m21 m22 m23 m31 m32 m33 v1 v2 v3];
  d_auto.

Lemma mderiv_const (C : M3) (t : R) : is_mderiv (fun _ => C) t Z3.
Proof. unfold is_mderiv, Z3; simpl; m_split; apply d_const. Qed.

Lemma vderiv_const (c : V3) (t : R) : is_vderiv (fun _ => c) t vzero.
Proof. unfold is_vderiv, vzero; simpl; m_split; apply d_const. Qed.

Lemma mderiv_madd (A B : R -> M3) (t : R) (DA DB : M3) :
  is_mderiv A t DA -> is_mderiv B t DB -> is_mderiv (fun s => madd (A s) (B s)) t (madd DA DB).
Proof. m_entries. Qed.

Lemma mderiv_mscale (c : R) (A : R -> M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_mderiv (fun s => mscale c (A s)) t (mscale c DA).
Proof. intro H. pose proof (d_const c t). m_entries. Qed.

Lemma mderiv_msub (A B : R -> M3) (t : R) (DA DB : M3) :
  is_mderiv A t DA -> is_mderiv B t DB -> is_mderiv (fun s => msub (A s) (B s)) t (msub DA DB).
Proof. intros HA HB. pose proof (d_const (-1) t). m_entries. Qed.

(** The product rule: [d/dt (A B) = A' B + A B']. *)
Lemma mderiv_mmul (A B : R -> M3) (t : R) (DA DB : M3) :
  is_mderiv A t DA -> is_mderiv B t DB ->
  is_mderiv (fun s => mmul (A s) (B s)) t (madd (mmul DA (B t)) (mmul (A t) DB)).
Proof. m_entries. Qed.

Lemma mderiv_mT (A : R -> M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_mderiv (fun s => mT (A s)) t (mT DA).
Proof. m_entries. Qed.

Lemma mderiv_sk (A : R -> M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_mderiv (fun s => sk (A s)) t (sk DA).
Proof. intro H. apply mderiv_mscale, mderiv_msub; [ exact H | apply mderiv_mT, H ]. Qed.

Lemma mderiv_sym (A : R -> M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_mderiv (fun s => sym (A s)) t (sym DA).
Proof. intro H. apply mderiv_mscale, mderiv_madd; [ exact H | apply mderiv_mT, H ]. Qed.

Lemma mderiv_hat (u : R -> V3) (t : R) (du : V3) :
  is_vderiv u t du -> is_mderiv (fun s => hat (u s)) t (hat du).
Proof. intro H. pose proof (d_const 0 t). m_entries. Qed.

Lemma vderiv_vee (A : R -> M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_vderiv (fun s => vee (A s)) t (vee DA).
Proof. m_entries. Qed.

Lemma deriv_tr (A : R -> M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_derive (fun s => tr (A s)) t (tr DA).
Proof. m_entries. Qed.

Lemma deriv_phi (A : R -> M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_derive (fun s => phi (A s)) t (- tr DA / 2).
Proof. m_entries. Qed.

Lemma vderiv_vadd (u v : R -> V3) (t : R) (du dv : V3) :
  is_vderiv u t du -> is_vderiv v t dv -> is_vderiv (fun s => vadd (u s) (v s)) t (vadd du dv).
Proof. m_entries. Qed.

Lemma vderiv_vscale (c : R) (u : R -> V3) (t : R) (du : V3) :
  is_vderiv u t du -> is_vderiv (fun s => vscale c (u s)) t (vscale c du).
Proof. m_entries. Qed.

Lemma vderiv_mvmul (A : R -> M3) (u : R -> V3) (t : R) (DA : M3) (du : V3) :
  is_mderiv A t DA -> is_vderiv u t du ->
  is_vderiv (fun s => mvmul (A s) (u s)) t (vadd (mvmul DA (u t)) (mvmul (A t) du)).
Proof. m_entries. Qed.

Lemma deriv_vdot (u v : R -> V3) (t : R) (du dv : V3) :
  is_vderiv u t du -> is_vderiv v t dv ->
  is_derive (fun s => vdot (u s) (v s)) t (vdot du (v t) + vdot (u t) dv).
Proof. m_entries. Qed.

(** Extensionality: a derivative is unchanged when the trajectory is rewritten
    pointwise (e.g. by an identity of the prelude). *)
Lemma mderiv_ext (A B : R -> M3) (t : R) (D : M3) :
  (forall s, A s = B s) -> is_mderiv A t D -> is_mderiv B t D.
Proof.
  intros E H. assert (F : A = B) by (apply FunctionalExtensionality.functional_extensionality; exact E).
  rewrite <- F. exact H.
Qed.

Lemma mderiv_unique_eq (A : R -> M3) (t : R) (D D' : M3) :
  is_mderiv A t D -> D = D' -> is_mderiv A t D'.
Proof. intros H <-. exact H. Qed.

Lemma deriv_unique_eq (f : R -> R) (t : R) (d d' : R) :
  is_derive f t d -> d = d' -> is_derive f t d'.
Proof. intros H <-. exact H. Qed.

(** ** The rules for derivative theorems of derivation steps ([ctx.ddt])

    A derivation whose first expression is [ctx.ddt(e)] is exported with a theorem
    [is_derive (fun s => e(s)) t (D(t))] (entry by entry for vectors and matrices) for
    every trajectory satisfying the declared dynamics at [t].  [traj_deriv] proves it:
    [d_traj] walks the term [e] and applies the rules above (and those below), so Coq
    forms the derivative; [traj_close] then shows, entry by entry with [lra] (for which
    a monomial is an atom: a polynomial identity is linear in them; many times faster
    than [ring] here), else [ring] or [field] (where a constant divides), that the
    derivative Coq formed is the stated [D(t)]. *)

Lemma vderiv_unique_eq (u : R -> V3) (t : R) (d d' : V3) :
  is_vderiv u t d -> d = d' -> is_vderiv u t d'.
Proof. intros H <-. exact H. Qed.

Lemma mderiv_mneg (A : R -> M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_mderiv (fun s => mneg (A s)) t (mneg DA).
Proof. intro H. pose proof (d_const (-1) t). m_entries. Qed.

Lemma vderiv_vneg (u : R -> V3) (t : R) (du : V3) :
  is_vderiv u t du -> is_vderiv (fun s => vneg (u s)) t (vneg du).
Proof. intro H. unfold vneg. m_entries. Qed.

(** Scaling by a function of time: [d/dt (c A) = c' A + c A']. *)
Lemma mderiv_mscale_fun (c : R -> R) (A : R -> M3) (t dc : R) (DA : M3) :
  is_derive c t dc -> is_mderiv A t DA ->
  is_mderiv (fun s => mscale (c s) (A s)) t (madd (mscale dc (A t)) (mscale (c t) DA)).
Proof.
  intros Hc HA. assert (Hc' : is_derive (fun s => c s) t dc) by exact Hc. clear Hc.
  m_entries.
Qed.

Lemma vderiv_vscale_fun (c : R -> R) (u : R -> V3) (t dc : R) (du : V3) :
  is_derive c t dc -> is_vderiv u t du ->
  is_vderiv (fun s => vscale (c s) (u s)) t (vadd (vscale dc (u t)) (vscale (c t) du)).
Proof.
  intros Hc Hu. assert (Hc' : is_derive (fun s => c s) t dc) by exact Hc. clear Hc.
  m_entries.
Qed.

Lemma mderiv_outer (u v : R -> V3) (t : R) (du dv : V3) :
  is_vderiv u t du -> is_vderiv v t dv ->
  is_mderiv (fun s => outer (u s) (v s)) t (madd (outer du (v t)) (outer (u t) dv)).
Proof. intros Hu Hv. unfold outer. m_entries. Qed.

Lemma d_cos (f : R -> R) (t df : R) :
  is_derive f t df -> is_derive (fun s => cos (f s)) t (- sin (f t) * df).
Proof.
  intro Hf. apply (d_eq _ t (df * - sin (f t))); [ | ring ].
  exact (is_derive_comp cos f t (- sin (f t)) df (is_derive_cos (f t)) Hf).
Qed.

Lemma d_sin (f : R -> R) (t df : R) :
  is_derive f t df -> is_derive (fun s => sin (f s)) t (cos (f t) * df).
Proof.
  intro Hf. apply (d_eq _ t (df * cos (f t))); [ | ring ].
  exact (is_derive_comp sin f t (cos (f t)) df (is_derive_sin (f t)) Hf).
Qed.

(** [d_traj] proves [is_derive f t ?d] ([is_mderiv], [is_vderiv]) by the structure of
    [f]: a constant, an operation of the prelude applied to functions of [s] (one rule
    each), or a trajectory whose derivative at [t] is a hypothesis (the declared
    dynamics). *)
Ltac d_traj :=
  lazymatch goal with
  | |- is_derive (fun _ => ?c) ?t _ => exact (d_const c t)
  | |- is_mderiv (fun _ => ?C) ?t _ => exact (mderiv_const C t)
  | |- is_vderiv (fun _ => ?c) ?t _ => exact (vderiv_const c t)
  | |- is_derive (fun s => @?f s + @?g s) ?t _ => refine (d_plus f g t _ _ _ _); [d_traj | d_traj]
  | |- is_derive (fun s => @?f s * @?g s) ?t _ => refine (d_mult f g t _ _ _ _); [d_traj | d_traj]
  | |- is_derive (fun s => @?f s - @?g s) ?t _ => refine (d_minus f g t _ _ _ _); [d_traj | d_traj]
  | |- is_derive (fun s => - @?f s) ?t _ => refine (d_opp f t _ _); d_traj
  | |- is_derive (fun s => cos (@?f s)) ?t _ => refine (d_cos f t _ _); d_traj
  | |- is_derive (fun s => sin (@?f s)) ?t _ => refine (d_sin f t _ _); d_traj
  | |- is_derive (fun s => tr (@?A s)) ?t _ => refine (deriv_tr A t _ _); d_traj
  | |- is_derive (fun s => phi (@?A s)) ?t _ => refine (deriv_phi A t _ _); d_traj
  | |- is_derive (fun s => vdot (@?u s) (@?v s)) ?t _ =>
      refine (deriv_vdot u v t _ _ _ _); [d_traj | d_traj]
  | |- is_mderiv (fun s => madd (@?A s) (@?B s)) ?t _ =>
      refine (mderiv_madd A B t _ _ _ _); [d_traj | d_traj]
  | |- is_mderiv (fun s => msub (@?A s) (@?B s)) ?t _ =>
      refine (mderiv_msub A B t _ _ _ _); [d_traj | d_traj]
  | |- is_mderiv (fun s => mmul (@?A s) (@?B s)) ?t _ =>
      refine (mderiv_mmul A B t _ _ _ _); [d_traj | d_traj]
  | |- is_mderiv (fun s => mscale (@?c s) (@?A s)) ?t _ =>
      refine (mderiv_mscale_fun c A t _ _ _ _); [d_traj | d_traj]
  | |- is_mderiv (fun s => mneg (@?A s)) ?t _ => refine (mderiv_mneg A t _ _); d_traj
  | |- is_mderiv (fun s => mT (@?A s)) ?t _ => refine (mderiv_mT A t _ _); d_traj
  | |- is_mderiv (fun s => sk (@?A s)) ?t _ => refine (mderiv_sk A t _ _); d_traj
  | |- is_mderiv (fun s => sym (@?A s)) ?t _ => refine (mderiv_sym A t _ _); d_traj
  | |- is_mderiv (fun s => hat (@?u s)) ?t _ => refine (mderiv_hat u t _ _); d_traj
  | |- is_mderiv (fun s => outer (@?u s) (@?v s)) ?t _ =>
      refine (mderiv_outer u v t _ _ _ _); [d_traj | d_traj]
  | |- is_vderiv (fun s => vadd (@?u s) (@?v s)) ?t _ =>
      refine (vderiv_vadd u v t _ _ _ _); [d_traj | d_traj]
  | |- is_vderiv (fun s => vscale (@?c s) (@?u s)) ?t _ =>
      refine (vderiv_vscale_fun c u t _ _ _ _); [d_traj | d_traj]
  | |- is_vderiv (fun s => vneg (@?u s)) ?t _ => refine (vderiv_vneg u t _ _); d_traj
  | |- is_vderiv (fun s => mvmul (@?A s) (@?u s)) ?t _ =>
      refine (vderiv_mvmul A u t _ _ _ _); [d_traj | d_traj]
  | |- is_vderiv (fun s => vee (@?A s)) ?t _ => refine (vderiv_vee A t _ _); d_traj
  | |- is_derive _ ?t _ => match goal with H : is_derive _ t _ |- _ => exact H end
  | |- is_mderiv _ ?t _ => match goal with H : is_mderiv _ t _ |- _ => exact H end
  | |- is_vderiv _ ?t _ => match goal with H : is_vderiv _ t _ |- _ => exact H end
  end.

(** The derivative Coq formed equals the stated one: entry by entry, a polynomial
    identity in the entries of the trajectories' values at [t] (and [cos], [sin] of
    angles), decided by [lra] (else [ring], else [field]). *)
Ltac traj_close :=
  cbv beta;
  repeat match goal with
  | H : is_derive _ _ _ |- _ => clear H
  | H : is_mderiv _ _ _ |- _ => clear H
  | H : is_vderiv _ _ _ |- _ => clear H
  | H : _ = _ |- _ => clear H
  end;
  repeat match goal with
  | |- context [ ?x ?t ] =>
      is_var x; is_var t;
      lazymatch type of x with
      | R -> M3 => generalize (x t); intros []
      | R -> V3 => generalize (x t); intros []
      end
  | |- context [ ?x ] =>
      is_var x;
      lazymatch type of x with
      | M3 => generalize x; intros []
      | V3 => generalize x; intros []
      end
  end;
  first [ apply m3_ext | apply v3_ext | idtac ];
  cbv beta iota zeta delta [phi sk sym hat vee outer tr I3 Z3 mT mvmul mmul msub mneg
    mscale madd vdot vzero vscale vneg vadd v1 v2 v3 m11 m12 m13 m21 m22 m23 m31 m32 m33];
  first [ lra | ring | field ].

(** A derivative theorem: the rules, then the algebra. *)
Ltac traj_deriv :=
  lazymatch goal with
  | |- is_derive _ _ _ => eapply deriv_unique_eq; [ d_traj | traj_close ]
  | |- is_mderiv _ _ _ => eapply mderiv_unique_eq; [ d_traj | traj_close ]
  | |- is_vderiv _ _ _ => eapply vderiv_unique_eq; [ d_traj | traj_close ]
  end.

(** ** The same rules in the shape of the exporter's derivative trees

    The variants below differ from the rules above only in the shape of the derivative
    they state: a constant factor or summand contributes nothing (no [0 * _] or [Z3]
    terms), as in the trees of [verify.proof.calculus].  With them [d_mirror] forms a
    derivative that is, in the usual case, the stated one letter for letter, so the
    theorem closes by [reflexivity]; otherwise [traj_close] decides the difference.
    Each variant is proved with the rules above ([d_traj], [traj_close]). *)

Ltac traj_prove :=
  intros;
  lazymatch goal with
  | |- is_derive _ _ _ => eapply deriv_unique_eq; [ d_traj | traj_close ]
  | |- is_mderiv _ _ _ => eapply mderiv_unique_eq; [ d_traj | traj_close ]
  | |- is_vderiv _ _ _ => eapply vderiv_unique_eq; [ d_traj | traj_close ]
  end.

Lemma d_plus_l (c : R) (g : R -> R) (t dg : R) :
  is_derive g t dg -> is_derive (fun s => c + g s) t dg.
Proof. traj_prove. Qed.
Lemma d_plus_r (f : R -> R) (c t df : R) :
  is_derive f t df -> is_derive (fun s => f s + c) t df.
Proof. traj_prove. Qed.
Lemma d_mult_l (c : R) (g : R -> R) (t dg : R) :
  is_derive g t dg -> is_derive (fun s => c * g s) t (c * dg).
Proof. traj_prove. Qed.
Lemma d_mult_r (f : R -> R) (c t df : R) :
  is_derive f t df -> is_derive (fun s => f s * c) t (df * c).
Proof. traj_prove. Qed.
Lemma d_cos_tree (f : R -> R) (t df : R) :
  is_derive f t df -> is_derive (fun s => cos (f s)) t (- (sin (f t) * df)).
Proof. intro H. apply (d_eq _ t _ _ (d_cos f t df H)). ring. Qed.
Lemma deriv_phi_tree (A : R -> M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_derive (fun s => phi (A s)) t ((1/2) * tr (mneg DA)).
Proof. traj_prove. Qed.
Lemma deriv_vdot_l (c : V3) (v : R -> V3) (t : R) (dv : V3) :
  is_vderiv v t dv -> is_derive (fun s => vdot c (v s)) t (vdot c dv).
Proof. traj_prove. Qed.
Lemma deriv_vdot_r (u : R -> V3) (c : V3) (t : R) (du : V3) :
  is_vderiv u t du -> is_derive (fun s => vdot (u s) c) t (vdot du c).
Proof. traj_prove. Qed.
Lemma mderiv_madd_l (C : M3) (B : R -> M3) (t : R) (DB : M3) :
  is_mderiv B t DB -> is_mderiv (fun s => madd C (B s)) t DB.
Proof. traj_prove. Qed.
Lemma mderiv_madd_r (A : R -> M3) (C : M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_mderiv (fun s => madd (A s) C) t DA.
Proof. traj_prove. Qed.
Lemma mderiv_mscale_r (c : R -> R) (C : M3) (t dc : R) :
  is_derive c t dc -> is_mderiv (fun s => mscale (c s) C) t (mscale dc C).
Proof. traj_prove. Qed.
Lemma mderiv_mmul_l (C : M3) (B : R -> M3) (t : R) (DB : M3) :
  is_mderiv B t DB -> is_mderiv (fun s => mmul C (B s)) t (mmul C DB).
Proof. traj_prove. Qed.
Lemma mderiv_mmul_r (A : R -> M3) (C : M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_mderiv (fun s => mmul (A s) C) t (mmul DA C).
Proof. traj_prove. Qed.
Lemma mderiv_outer_l (c : V3) (v : R -> V3) (t : R) (dv : V3) :
  is_vderiv v t dv -> is_mderiv (fun s => outer c (v s)) t (outer c dv).
Proof. traj_prove. Qed.
Lemma mderiv_outer_r (u : R -> V3) (c : V3) (t : R) (du : V3) :
  is_vderiv u t du -> is_mderiv (fun s => outer (u s) c) t (outer du c).
Proof. traj_prove. Qed.
Lemma vderiv_vadd_l (c : V3) (v : R -> V3) (t : R) (dv : V3) :
  is_vderiv v t dv -> is_vderiv (fun s => vadd c (v s)) t dv.
Proof. traj_prove. Qed.
Lemma vderiv_vadd_r (u : R -> V3) (c : V3) (t : R) (du : V3) :
  is_vderiv u t du -> is_vderiv (fun s => vadd (u s) c) t du.
Proof. traj_prove. Qed.
Lemma vderiv_vscale_l (c : R) (u : R -> V3) (t : R) (du : V3) :
  is_vderiv u t du -> is_vderiv (fun s => vscale c (u s)) t (vscale c du).
Proof. traj_prove. Qed.
Lemma vderiv_vscale_r (c : R -> R) (w : V3) (t dc : R) :
  is_derive c t dc -> is_vderiv (fun s => vscale (c s) w) t (vscale dc w).
Proof. traj_prove. Qed.
Lemma vderiv_mvmul_l (C : M3) (u : R -> V3) (t : R) (du : V3) :
  is_vderiv u t du -> is_vderiv (fun s => mvmul C (u s)) t (mvmul C du).
Proof. traj_prove. Qed.
Lemma vderiv_mvmul_r (A : R -> M3) (w : V3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_vderiv (fun s => mvmul (A s) w) t (mvmul DA w).
Proof. traj_prove. Qed.

(** [d_mirror]: [d_traj] with the variants first (a constant side matched by a pattern
    without [s]; a [match], so a pattern whose constant side does mention [s] fails and
    the next rule is tried). *)
Ltac d_mirror :=
  match goal with
  | |- is_derive (fun _ => ?c) ?t _ => exact (d_const c t)
  | |- is_mderiv (fun _ => ?C) ?t _ => exact (mderiv_const C t)
  | |- is_vderiv (fun _ => ?c) ?t _ => exact (vderiv_const c t)
  | |- is_derive (fun s => ?c + @?g s) ?t _ => refine (d_plus_l c g t _ _); d_mirror
  | |- is_derive (fun s => @?f s + ?c) ?t _ => refine (d_plus_r f c t _ _); d_mirror
  | |- is_derive (fun s => @?f s + @?g s) ?t _ => refine (d_plus f g t _ _ _ _); [d_mirror | d_mirror]
  | |- is_derive (fun s => ?c * @?g s) ?t _ => refine (d_mult_l c g t _ _); d_mirror
  | |- is_derive (fun s => @?f s * ?c) ?t _ => refine (d_mult_r f c t _ _); d_mirror
  | |- is_derive (fun s => @?f s * @?g s) ?t _ => refine (d_mult f g t _ _ _ _); [d_mirror | d_mirror]
  | |- is_derive (fun s => - @?f s) ?t _ => refine (d_opp f t _ _); d_mirror
  | |- is_derive (fun s => cos (@?f s)) ?t _ => refine (d_cos_tree f t _ _); d_mirror
  | |- is_derive (fun s => sin (@?f s)) ?t _ => refine (d_sin f t _ _); d_mirror
  | |- is_derive (fun s => tr (@?A s)) ?t _ => refine (deriv_tr A t _ _); d_mirror
  | |- is_derive (fun s => phi (@?A s)) ?t _ => refine (deriv_phi_tree A t _ _); d_mirror
  | |- is_derive (fun s => vdot ?c (@?v s)) ?t _ => refine (deriv_vdot_l c v t _ _); d_mirror
  | |- is_derive (fun s => vdot (@?u s) ?c) ?t _ => refine (deriv_vdot_r u c t _ _); d_mirror
  | |- is_derive (fun s => vdot (@?u s) (@?v s)) ?t _ =>
      refine (deriv_vdot u v t _ _ _ _); [d_mirror | d_mirror]
  | |- is_mderiv (fun s => madd ?C (@?B s)) ?t _ => refine (mderiv_madd_l C B t _ _); d_mirror
  | |- is_mderiv (fun s => madd (@?A s) ?C) ?t _ => refine (mderiv_madd_r A C t _ _); d_mirror
  | |- is_mderiv (fun s => madd (@?A s) (@?B s)) ?t _ =>
      refine (mderiv_madd A B t _ _ _ _); [d_mirror | d_mirror]
  | |- is_mderiv (fun s => mmul ?C (@?B s)) ?t _ => refine (mderiv_mmul_l C B t _ _); d_mirror
  | |- is_mderiv (fun s => mmul (@?A s) ?C) ?t _ => refine (mderiv_mmul_r A C t _ _); d_mirror
  | |- is_mderiv (fun s => mmul (@?A s) (@?B s)) ?t _ =>
      refine (mderiv_mmul A B t _ _ _ _); [d_mirror | d_mirror]
  | |- is_mderiv (fun s => mscale ?c (@?A s)) ?t _ => refine (mderiv_mscale c A t _ _); d_mirror
  | |- is_mderiv (fun s => mscale (@?c s) ?C) ?t _ => refine (mderiv_mscale_r c C t _ _); d_mirror
  | |- is_mderiv (fun s => mscale (@?c s) (@?A s)) ?t _ =>
      refine (mderiv_mscale_fun c A t _ _ _ _); [d_mirror | d_mirror]
  | |- is_mderiv (fun s => mneg (@?A s)) ?t _ => refine (mderiv_mneg A t _ _); d_mirror
  | |- is_mderiv (fun s => mT (@?A s)) ?t _ => refine (mderiv_mT A t _ _); d_mirror
  | |- is_mderiv (fun s => sk (@?A s)) ?t _ => refine (mderiv_sk A t _ _); d_mirror
  | |- is_mderiv (fun s => sym (@?A s)) ?t _ => refine (mderiv_sym A t _ _); d_mirror
  | |- is_mderiv (fun s => hat (@?u s)) ?t _ => refine (mderiv_hat u t _ _); d_mirror
  | |- is_mderiv (fun s => outer ?c (@?v s)) ?t _ => refine (mderiv_outer_l c v t _ _); d_mirror
  | |- is_mderiv (fun s => outer (@?u s) ?c) ?t _ => refine (mderiv_outer_r u c t _ _); d_mirror
  | |- is_mderiv (fun s => outer (@?u s) (@?v s)) ?t _ =>
      refine (mderiv_outer u v t _ _ _ _); [d_mirror | d_mirror]
  | |- is_vderiv (fun s => vadd ?c (@?v s)) ?t _ => refine (vderiv_vadd_l c v t _ _); d_mirror
  | |- is_vderiv (fun s => vadd (@?u s) ?c) ?t _ => refine (vderiv_vadd_r u c t _ _); d_mirror
  | |- is_vderiv (fun s => vadd (@?u s) (@?v s)) ?t _ =>
      refine (vderiv_vadd u v t _ _ _ _); [d_mirror | d_mirror]
  | |- is_vderiv (fun s => vscale ?c (@?u s)) ?t _ => refine (vderiv_vscale_l c u t _ _); d_mirror
  | |- is_vderiv (fun s => vscale (@?c s) ?w) ?t _ => refine (vderiv_vscale_r c w t _ _); d_mirror
  | |- is_vderiv (fun s => vscale (@?c s) (@?u s)) ?t _ =>
      refine (vderiv_vscale_fun c u t _ _ _ _); [d_mirror | d_mirror]
  | |- is_vderiv (fun s => vneg (@?u s)) ?t _ => refine (vderiv_vneg u t _ _); d_mirror
  | |- is_vderiv (fun s => mvmul ?C (@?u s)) ?t _ => refine (vderiv_mvmul_l C u t _ _); d_mirror
  | |- is_vderiv (fun s => mvmul (@?A s) ?w) ?t _ => refine (vderiv_mvmul_r A w t _ _); d_mirror
  | |- is_vderiv (fun s => mvmul (@?A s) (@?u s)) ?t _ =>
      refine (vderiv_mvmul A u t _ _ _ _); [d_mirror | d_mirror]
  | |- is_vderiv (fun s => vee (@?A s)) ?t _ => refine (vderiv_vee A t _ _); d_mirror
  | |- is_derive _ ?t _ => match goal with H : is_derive _ t _ |- _ => exact H end
  | |- is_mderiv _ ?t _ => match goal with H : is_mderiv _ t _ |- _ => exact H end
  | |- is_vderiv _ ?t _ => match goal with H : is_vderiv _ t _ |- _ => exact H end
  end.

(** The stated derivative is the formed one letter for letter, or [traj_close]. *)
Ltac traj_same :=
  cbv beta;
  first [ lazymatch goal with |- ?a = ?a => reflexivity end | traj_close ].
