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
  eapply d_eq; [ d_build | cbv beta; first [ ring | field ] ].

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
Proof. intro H. pose proof (d_const (1/2) t). pose proof (d_const (-1) t). m_entries. Qed.

Lemma mderiv_sym (A : R -> M3) (t : R) (DA : M3) :
  is_mderiv A t DA -> is_mderiv (fun s => sym (A s)) t (sym DA).
Proof. intro H. pose proof (d_const (1/2) t). m_entries. Qed.

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
