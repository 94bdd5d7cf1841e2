(** * RobustCert: passivity of every model of an identified region, by boxes Coq checks

    For the robust verdicts of the paper's Section 4 ("Human Modeling"): the human's
    operator is identified as a 2 x 2 transfer matrix of the paper's structure,

        H_th(s) = [[ (b1_1 s + b0_1) / (s^2 + a1_1 s + a0_1),  c12 ],
                   [ c21,  (b1_2 s + b0_2) / (s^2 + a1_2 s + a0_2) ]],

    with a parameter vector th = (b1_1, b0_1, a1_1, a0_1, b1_2, b0_2, a1_2, a0_2, c12, c21)
    and a confidence region {th : (th - thc)^T Si (th - thc) <= chi2}, Si the inverse of
    the identification's covariance Sg.  What a reader audits:

    - [in_region]: the region, with [qform] of QCert.v over the *reals*;
    - [paper_herm], [paper_psd_at], [paper_band_passive]: H_th(jw) + H_th(jw)^H >= 0 at
      every w of the band where H_th(jw) is defined, from the complex arithmetic of
      BandCert.v ([cadd], [cdiv], [cconj], [hform]) on pairs of reals;
    - the theorems a unit proves: [robust_band_sound] (every model of the region is
      passive on the band) and [robust_refutation_sound] (no model of it is).

    How it is proved, once here:

    - the region's dual bound ([dual_bound]): when Si is symmetric, positive semidefinite
      and Si Sg = I (all checked on [Q]), every th of the region has
      2 v.(th - thc) - v^T Sg v <= chi2 for every real v.  With v along a coordinate this
      is the enclosing box (|phi_k - phic_k| <= r_k when r_k^2 >= chi2 Sg_kk), along a
      gradient the first-order bound of a linear leaf;
    - the conditions depend on th through phi = (th_0 .. th_7, th_8 + th_9) and the
      frequency t = w^2; a tree of midpoint splits covers the root box
      [phic - r, phic + r] x [w1^2, w2^2] ([tree_sound]);
    - a leaf is decided by interval arithmetic on [Q] over the leaf's box: the natural
      interval extension of an expression encloses its values ([eiv_sound]); the
      first-order form carries enclosures of the slopes ([egr_sound]);
    - for the paper's structure, N_i = Re(num_i(jw) conj(den_i(jw))) > 0, N_2 > 0 and
      4 N_1 N_2 - c^2 D_1 D_2 > 0 (c = c12 + c21, D_i = |den_i(jw)|^2) make the 2 x 2
      Hermitian part positive semidefinite ([herm2] of BandCert.v); a real direction v
      with v_1^2 N_1 D_2 + v_2^2 N_2 D_1 + v_1 v_2 c D_1 D_2 < 0 and D_i > 0 makes it
      fail.

    The expressions are those of the Python checker (verify/passivity/check/robust_band.py,
    [leaf_bounds], [direction_bounds]) written as terms, so Coq's interval bounds are the
    ones the certificate claims;
    - a leaf [ROut y] shows that its box misses the region: the dual bound along the
      rational direction y ([out_ok_sound]; y is the tangent plane's normal, rounded);
    - [hurwitz2]: s^2 + a1 s + a0 has both roots in Re s < 0 iff a1 > 0 and a0 > 0, for
      a claim at every frequency over a box of the paper's second-order denominators.

    No axiom is added. *)

From Coq Require Import QArith Qabs Qround Qreals Reals List Lra Lia.
From VerifyCoq Require Import QCert BandCert.
Import ListNotations.

(** ** Intervals over Q *)

Definition iv := (Q * Q)%type.

Definition qmin (a b : Q) : Q := if Qle_bool a b then a else b.
Definition qmax (a b : Q) : Q := if Qle_bool a b then b else a.

Definition iadd (a b : iv) : iv := (Qred (fst a + fst b), Qred (snd a + snd b)).
Definition isub (a b : iv) : iv := (Qred (fst a - snd b), Qred (snd a - fst b)).
Definition iscale (k : Z) (a : iv) : iv :=
  if Z.leb 0 k then (Qred (inject_Z k * fst a), Qred (inject_Z k * snd a))
  else (Qred (inject_Z k * snd a), Qred (inject_Z k * fst a)).
Definition imul (a b : iv) : iv :=
  let p1 := Qred (fst a * fst b) in let p2 := Qred (fst a * snd b) in
  let p3 := Qred (snd a * fst b) in let p4 := Qred (snd a * snd b) in
  (qmin (qmin p1 p2) (qmin p3 p4), qmax (qmax p1 p2) (qmax p3 p4)).
Definition isqr (a : iv) : iv :=
  let lo := fst a in let hi := snd a in
  if Qle_bool 0 lo then (Qred (lo * lo), Qred (hi * hi))
  else if Qle_bool hi 0 then (Qred (hi * hi), Qred (lo * lo))
  else (0%Q, qmax (Qred (lo * lo)) (Qred (hi * hi))).
Fixpoint qpow (q : Q) (m : nat) : Q :=
  match m with O => 1%Q | S m' => Qred (qpow q m' * q) end.
Fixpoint ipow_mul (a : iv) (m : nat) : iv :=
  match m with O => (1%Q, 1%Q) | S m' => imul (ipow_mul a m') a end.
(** t^m for t >= 0 (monotone), as the Python checker; a product otherwise. *)
Definition ipow (a : iv) (m : nat) : iv :=
  if Qle_bool 0 (fst a) then (qpow (fst a) m, qpow (snd a) m) else ipow_mul a m.

Open Scope R_scope.

Definition in_iv (a : iv) (x : R) : Prop := Q2R (fst a) <= x <= Q2R (snd a).

Lemma Q2R_inject_Z z : Q2R (inject_Z z) = IZR z.
Proof. unfold Q2R, inject_Z. simpl. field. Qed.

Lemma qmin_le a b : Q2R (qmin a b) <= Q2R a /\ Q2R (qmin a b) <= Q2R b.
Proof.
  unfold qmin. destruct (Qle_bool a b) eqn:E.
  - apply Qle_bool_iff, Qle_Rle in E. lra.
  - assert (b <= a)%Q by (apply Qlt_le_weak, Qnot_le_lt; intro H; apply Qle_bool_iff in H;
      congruence). apply Qle_Rle in H. lra.
Qed.

Lemma qmax_ge a b : Q2R a <= Q2R (qmax a b) /\ Q2R b <= Q2R (qmax a b).
Proof.
  unfold qmax. destruct (Qle_bool a b) eqn:E.
  - apply Qle_bool_iff, Qle_Rle in E. lra.
  - assert (b <= a)%Q by (apply Qlt_le_weak, Qnot_le_lt; intro H; apply Qle_bool_iff in H;
      congruence). apply Qle_Rle in H. lra.
Qed.

Lemma iadd_sound a b x y : in_iv a x -> in_iv b y -> in_iv (iadd a b) (x + y).
Proof. unfold in_iv, iadd. cbn [fst snd]. rewrite !Q2R_red, !Q2R_plus. lra. Qed.

Lemma isub_sound a b x y : in_iv a x -> in_iv b y -> in_iv (isub a b) (x - y).
Proof. unfold in_iv, isub. cbn [fst snd]. rewrite !Q2R_red, !Q2R_minus. lra. Qed.

Lemma iscale_sound k a x : in_iv a x -> in_iv (iscale k a) (IZR k * x).
Proof.
  unfold in_iv, iscale. destruct (Z.leb 0 k) eqn:E; cbn [fst snd];
    rewrite !Q2R_red, !Q2R_mult, !Q2R_inject_Z; intros [H1 H2].
  - apply Z.leb_le, IZR_le in E. split; apply Rmult_le_compat_l; lra.
  - apply Z.leb_gt, IZR_lt in E. split; nra.
Qed.

Lemma mul_between a b c d x y : a <= x <= b -> c <= y <= d ->
  (a * c <= x * y \/ a * d <= x * y \/ b * c <= x * y \/ b * d <= x * y) /\
  (x * y <= a * c \/ x * y <= a * d \/ x * y <= b * c \/ x * y <= b * d).
Proof.
  intros Hx Hy.
  destruct (Rle_dec 0 y) as [Py|Py]; destruct (Rle_dec 0 a) as [Pa|Pa];
    destruct (Rle_dec 0 b) as [Pb|Pb]; split; nra.
Qed.

Lemma imul_sound a b x y : in_iv a x -> in_iv b y -> in_iv (imul a b) (x * y).
Proof.
  unfold in_iv, imul. cbv zeta. cbn [fst snd]. intros Hx Hy.
  pose proof (mul_between _ _ _ _ _ _ Hx Hy) as [Hl Hh].
  pose proof (qmin_le (Qred (fst a * fst b)) (Qred (fst a * snd b))) as M1.
  pose proof (qmin_le (Qred (snd a * fst b)) (Qred (snd a * snd b))) as M2.
  pose proof (qmin_le (qmin (Qred (fst a * fst b)) (Qred (fst a * snd b)))
                      (qmin (Qred (snd a * fst b)) (Qred (snd a * snd b)))) as M3.
  pose proof (qmax_ge (Qred (fst a * fst b)) (Qred (fst a * snd b))) as X1.
  pose proof (qmax_ge (Qred (snd a * fst b)) (Qred (snd a * snd b))) as X2.
  pose proof (qmax_ge (qmax (Qred (fst a * fst b)) (Qred (fst a * snd b)))
                      (qmax (Qred (snd a * fst b)) (Qred (snd a * snd b)))) as X3.
  rewrite !Q2R_red, !Q2R_mult in M1, M2, X1, X2.
  split; [destruct Hl as [|[|[|]]] | destruct Hh as [|[|[|]]]]; lra.
Qed.

Lemma isqr_sound a x : in_iv a x -> in_iv (isqr a) (x * x).
Proof.
  unfold in_iv, isqr. intros Hx.
  destruct (Qle_bool 0 (fst a)) eqn:E1; [|destruct (Qle_bool (snd a) 0) eqn:E2]; cbn [fst snd].
  - apply Qle_bool_iff, Qle_Rle in E1. rewrite Q2R_0 in E1.
    rewrite !Q2R_red, !Q2R_mult. split; nra.
  - apply Qle_bool_iff, Qle_Rle in E2. rewrite Q2R_0 in E2.
    rewrite !Q2R_red, !Q2R_mult. split; nra.
  - pose proof (qmax_ge (Qred (fst a * fst a)) (Qred (snd a * snd a))) as X.
    rewrite !Q2R_red, !Q2R_mult in X. rewrite Q2R_0.
    split; [apply Rle_0_sqr|].
    destruct (Rle_dec 0 x); [apply (Rle_trans _ (Q2R (snd a) * Q2R (snd a))); nra|].
    apply (Rle_trans _ (Q2R (fst a) * Q2R (fst a))); nra.
Qed.

Lemma Q2R_qpow q m : Q2R (qpow q m) = pow (Q2R q) m.
Proof.
  induction m as [|m IH]; cbn [qpow]; [apply Q2R_1|].
  rewrite Q2R_red, Q2R_mult, IH. simpl. ring.
Qed.

Lemma ipow_sound a x m : in_iv a x -> in_iv (ipow a m) (pow x m).
Proof.
  intros Hx. unfold ipow. destruct (Qle_bool 0 (fst a)) eqn:E.
  - apply Qle_bool_iff, Qle_Rle in E. rewrite Q2R_0 in E.
    unfold in_iv in *. cbn [fst snd]. rewrite !Q2R_qpow.
    split; apply pow_incr; lra.
  - induction m as [|m IH]; cbn [ipow_mul pow].
    + unfold in_iv. cbn [fst snd]. rewrite Q2R_1. lra.
    + replace (x * x ^ m) with (x ^ m * x) by ring. apply imul_sound; assumption.
Qed.

(** ** Expressions: the terms the Python checker evaluates *)

(** [EVar k]: the coordinate k of phi; [ET m]: t^m for the frequency t (t = w^2). *)
Inductive expr :=
| EVar (k : nat) | EConst (q : Q) | EAdd (a b : expr) | ESub (a b : expr)
| EScale (k : Z) (a : expr) | EMul (a b : expr) | ESqr (a : expr) | ET (m : nat).

Fixpoint ereal (p : nat -> R) (t : R) (e : expr) : R :=
  match e with
  | EVar k => p k
  | EConst q => Q2R q
  | EAdd a b => ereal p t a + ereal p t b
  | ESub a b => ereal p t a - ereal p t b
  | EScale k a => IZR k * ereal p t a
  | EMul a b => ereal p t a * ereal p t b
  | ESqr a => ereal p t a * ereal p t a
  | ET m => pow t m
  end.

Definition zero_iv : iv := (0%Q, 0%Q).

(** The natural interval extension over a box of phi (a list of intervals) and t in T. *)
Fixpoint eiv (B : list iv) (T : iv) (e : expr) : iv :=
  match e with
  | EVar k => nth k B zero_iv
  | EConst q => (q, q)
  | EAdd a b => iadd (eiv B T a) (eiv B T b)
  | ESub a b => isub (eiv B T a) (eiv B T b)
  | EScale k a => iscale k (eiv B T a)
  | EMul a b => imul (eiv B T a) (eiv B T b)
  | ESqr a => isqr (eiv B T a)
  | ET m => ipow T m
  end.

(** p lies in the box B: every coordinate in its interval (0 outside the list). *)
Definition in_box (B : list iv) (p : nat -> R) : Prop := forall k, in_iv (nth k B zero_iv) (p k).

Theorem eiv_sound B T p t e : in_box B p -> in_iv T t -> in_iv (eiv B T e) (ereal p t e).
Proof.
  intros HB HT. induction e; simpl.
  - apply HB.
  - unfold in_iv. simpl. lra.
  - apply iadd_sound; assumption.
  - apply isub_sound; assumption.
  - apply iscale_sound; assumption.
  - apply imul_sound; assumption.
  - apply isqr_sound; assumption.
  - apply ipow_sound; assumption.
Qed.

(** ** Slopes: the first-order form *)

(** Lists of intervals added, subtracted, ... coordinate by coordinate; a missing
    coordinate is the zero interval. *)
Lemma nth_nil_iv j : nth j (@nil iv) zero_iv = zero_iv.
Proof. destruct j; reflexivity. Qed.

Fixpoint gzip (f : iv -> iv -> iv) (u v : list iv) : list iv :=
  match u with
  | nil => map (f zero_iv) v
  | a :: u' => match v with
               | nil => f a zero_iv :: gzip f u' nil
               | b :: v' => f a b :: gzip f u' v'
               end
  end.

Lemma nth_gzip f u v k :
  nth k (gzip f u v) zero_iv = f (nth k u zero_iv) (nth k v zero_iv)
  \/ (nth k (gzip f u v) zero_iv = zero_iv /\ nth k u zero_iv = zero_iv
      /\ nth k v zero_iv = zero_iv).
Proof.
  revert u v. induction k as [|k IH]; intros [|a u] [|b v]; simpl; auto.
  - destruct (IH nil v) as [H|[H [_ H2]]]; simpl in H; [left|right]; rewrite H;
      [destruct k; reflexivity|auto].
  - destruct (IH u nil) as [H|[H [H1 _]]]; [left|right]; rewrite H; [|auto].
    destruct k; reflexivity.
Qed.


Fixpoint unit_grad (k : nat) : list iv :=
  match k with O => [(1%Q, 1%Q)] | S k' => zero_iv :: unit_grad k' end.

(** (value over the box, slope enclosures), as the Python checker's [GradOps]. *)
Fixpoint egr (B : list iv) (T : iv) (e : expr) : iv * list iv :=
  match e with
  | EVar k => (nth k B zero_iv, unit_grad k)
  | EConst q => ((q, q), nil)
  | EAdd a b => let (va, ga) := egr B T a in let (vb, gb) := egr B T b in
                (iadd va vb, gzip iadd ga gb)
  | ESub a b => let (va, ga) := egr B T a in let (vb, gb) := egr B T b in
                (isub va vb, gzip isub ga gb)
  | EScale k a => let (va, ga) := egr B T a in (iscale k va, map (iscale k) ga)
  | EMul a b => let (va, ga) := egr B T a in let (vb, gb) := egr B T b in
                (imul va vb, gzip (fun x y => iadd (imul va y) (imul vb x)) ga gb)
  | ESqr a => let (va, ga) := egr B T a in
              (isqr va, map (fun x => iscale 2 (imul va x)) ga)
  | ET m => (ipow T m, nil)
  end.

Lemma egr_value B T e : fst (egr B T e) = eiv B T e.
Proof.
  induction e; simpl; auto;
    repeat match goal with
           | |- context [egr B T ?a] => destruct (egr B T a) eqn:?
           end; simpl in *; subst; reflexivity.
Qed.

Lemma in_zero x : in_iv zero_iv x -> x = 0.
Proof. unfold in_iv, zero_iv. simpl. rewrite Q2R_0. lra. Qed.

Lemma zero_in : in_iv zero_iv 0.
Proof. unfold in_iv, zero_iv. simpl. rewrite Q2R_0. lra. Qed.

Lemma nth_unit_grad k j :
  (j = k /\ nth j (unit_grad k) zero_iv = (1%Q, 1%Q))
  \/ (j <> k /\ nth j (unit_grad k) zero_iv = zero_iv).
Proof.
  revert j. induction k as [|k IH]; intros [|j]; simpl.
  - left. auto.
  - right. split; [lia|]. destruct j; reflexivity.
  - right. split; [lia|reflexivity].
  - destruct (IH j) as [[-> H]|[H1 H2]]; [left|right]; split; auto.
Qed.

Lemma sumR_delta n k (f : nat -> R) : (k < n)%nat ->
  sumR n (fun j => (if Nat.eqb j k then 1 else 0) * f j) = f k.
Proof.
  induction n as [|n IH]; intros Hk; [lia|]. simpl.
  destruct (Nat.eq_dec k n) as [->|Hne].
  - rewrite Nat.eqb_refl.
    rewrite (sumR_ext n _ (fun _ => 0)), sumR_zero; [ring|].
    intros j Hj. destruct (Nat.eqb_spec j n); [lia|ring].
  - rewrite IH by lia. destruct (Nat.eqb_spec n k); [lia|ring].
Qed.

Lemma nth_map_iv (f : iv -> iv) l j :
  nth j (map f l) zero_iv = f (nth j l zero_iv)
  \/ (nth j (map f l) zero_iv = zero_iv /\ nth j l zero_iv = zero_iv).
Proof.
  revert l. induction j as [|j IH]; intros [|a l]; simpl; auto;
    right; destruct j; auto.
Qed.

Lemma iscale2_sum a x y : in_iv a x -> in_iv a y -> in_iv (iscale 2 a) (x + y).
Proof.
  unfold in_iv, iscale. cbn [Z.leb Z.compare fst snd]. rewrite !Q2R_red, !Q2R_mult, !Q2R_inject_Z. lra.
Qed.

Lemma sumR_zero' n (f : nat -> R) : (forall k, f k = 0) -> sumR n f = 0.
Proof. intros H. rewrite (sumR_ext n f (fun _ => 0)) by (intros; apply H). apply sumR_zero. Qed.

(** The slope form: for p, p0 in the box (same t), f(p) - f(p0) = sum_k s_k (p_k - p0_k)
    with every s_k in the k-th slope enclosure. *)
Definition slope_ok (n : nat) (G : list iv) (p p0 : nat -> R) (d : R) : Prop :=
  exists s : nat -> R, (forall k, in_iv (nth k G zero_iv) (s k))
                       /\ d = sumR n (fun k => s k * (p k - p0 k)).

Theorem egr_sound n B T p p0 t e :
  in_box B p -> in_box B p0 -> in_iv T t ->
  (forall k, (n <= k)%nat -> p k = p0 k) ->
  slope_ok n (snd (egr B T e)) p p0 (ereal p t e - ereal p0 t e).
Proof.
  intros HB HB0 HT Hout. induction e; simpl.
  - exists (fun j => if Nat.eqb j k then 1 else 0). split.
    + intros j. destruct (nth_unit_grad k j) as [[-> H]|[H1 H2]].
      * rewrite H, Nat.eqb_refl. unfold in_iv. simpl. rewrite Q2R_1. lra.
      * rewrite H2. destruct (Nat.eqb_spec j k); [lia|]. apply zero_in.
    + destruct (Nat.lt_ge_cases k n) as [Hk|Hk].
      * rewrite (sumR_delta n k (fun j => p j - p0 j)) by exact Hk. reflexivity.
      * rewrite Hout by exact Hk. rewrite sumR_zero'; [ring|].
        intros j. destruct (Nat.eqb_spec j k); [|ring]. subst. rewrite Hout by exact Hk. ring.
  - exists (fun _ => 0). split; [intros k; rewrite nth_nil_iv; apply zero_in|].
    rewrite sumR_zero'; [ring|intros; ring].
  - destruct (egr B T e1) as [va ga] eqn:Ea. destruct (egr B T e2) as [vb gb] eqn:Eb.
    simpl in *. destruct IHe1 as [sa [Ha Da]]. destruct IHe2 as [sb [Hb Db]].
    exists (fun k => sa k + sb k). split.
    + intros k. destruct (nth_gzip iadd ga gb k) as [H|[H [H1 H2]]]; rewrite H.
      * apply iadd_sound; [apply Ha|apply Hb].
      * pose proof (Ha k) as A. pose proof (Hb k) as B'. rewrite H1 in A. rewrite H2 in B'.
        apply in_zero in A. apply in_zero in B'. rewrite A, B'. replace (0 + 0) with 0 by ring.
        apply zero_in.
    + rewrite (sumR_ext n _ (fun k => sa k * (p k - p0 k) + sb k * (p k - p0 k)))
        by (intros; ring). rewrite sumR_plus, <- Da, <- Db. ring.
  - destruct (egr B T e1) as [va ga] eqn:Ea. destruct (egr B T e2) as [vb gb] eqn:Eb.
    simpl in *. destruct IHe1 as [sa [Ha Da]]. destruct IHe2 as [sb [Hb Db]].
    exists (fun k => sa k - sb k). split.
    + intros k. destruct (nth_gzip isub ga gb k) as [H|[H [H1 H2]]]; rewrite H.
      * apply isub_sound; [apply Ha|apply Hb].
      * pose proof (Ha k) as A. pose proof (Hb k) as B'. rewrite H1 in A. rewrite H2 in B'.
        apply in_zero in A. apply in_zero in B'. rewrite A, B'. replace (0 - 0) with 0 by ring.
        apply zero_in.
    + rewrite (sumR_ext n _ (fun k => sa k * (p k - p0 k) + - (sb k * (p k - p0 k))))
        by (intros; ring). rewrite sumR_plus, sumR_opp, <- Da, <- Db. ring.
  - destruct (egr B T e) as [va ga] eqn:Ea. simpl in *. destruct IHe as [sa [Ha Da]].
    exists (fun j => IZR k * sa j). split.
    + intros j. destruct (nth_map_iv (iscale k) ga j) as [H|[H H1]]; rewrite H.
      * apply iscale_sound, Ha.
      * pose proof (Ha j) as A. rewrite H1 in A. apply in_zero in A. rewrite A.
        replace (IZR k * 0) with 0 by ring. apply zero_in.
    + rewrite (sumR_ext n _ (fun j => IZR k * (sa j * (p j - p0 j)))) by (intros; ring).
      rewrite sumR_scal, <- Da. ring.
  - pose proof (egr_value B T e1) as V1. pose proof (egr_value B T e2) as V2.
    destruct (egr B T e1) as [va ga] eqn:Ea. destruct (egr B T e2) as [vb gb] eqn:Eb.
    simpl in *. destruct IHe1 as [sa [Ha Da]]. destruct IHe2 as [sb [Hb Db]].
    pose proof (eiv_sound B T p t e1 HB HT) as Pa. rewrite <- V1 in Pa.
    pose proof (eiv_sound B T p0 t e2 HB0 HT) as Pb. rewrite <- V2 in Pb.
    exists (fun k => ereal p t e1 * sb k + ereal p0 t e2 * sa k). split.
    + intros k.
      destruct (nth_gzip (fun x y => iadd (imul va y) (imul vb x)) ga gb k)
        as [H|[H [H1 H2]]]; rewrite H.
      * apply iadd_sound; apply imul_sound; auto.
      * pose proof (Ha k) as A. pose proof (Hb k) as B'. rewrite H1 in A. rewrite H2 in B'.
        apply in_zero in A. apply in_zero in B'. rewrite A, B'.
        replace (ereal p t e1 * 0 + ereal p0 t e2 * 0) with 0 by ring. apply zero_in.
    + rewrite (sumR_ext n _ (fun k => ereal p t e1 * (sb k * (p k - p0 k))
                                      + ereal p0 t e2 * (sa k * (p k - p0 k))))
        by (intros; ring). rewrite sumR_plus, !sumR_scal, <- Da, <- Db. ring.
  - pose proof (egr_value B T e) as V. destruct (egr B T e) as [va ga] eqn:Ea.
    simpl in *. destruct IHe as [sa [Ha Da]].
    pose proof (eiv_sound B T p t e HB HT) as Pa. rewrite <- V in Pa.
    pose proof (eiv_sound B T p0 t e HB0 HT) as Pa0. rewrite <- V in Pa0.
    exists (fun k => (ereal p t e + ereal p0 t e) * sa k). split.
    + intros k. destruct (nth_map_iv (fun x => iscale 2 (imul va x)) ga k) as [H|[H H1]];
        rewrite H.
      * replace ((ereal p t e + ereal p0 t e) * sa k)
          with (ereal p t e * sa k + ereal p0 t e * sa k) by ring.
        apply iscale2_sum; apply imul_sound; auto.
      * pose proof (Ha k) as A. rewrite H1 in A. apply in_zero in A. rewrite A.
        replace ((ereal p t e + ereal p0 t e) * 0) with 0 by ring. apply zero_in.
    + rewrite (sumR_ext n _ (fun k => (ereal p t e + ereal p0 t e) * (sa k * (p k - p0 k))))
        by (intros; ring). rewrite sumR_scal, <- Da. ring.
  - exists (fun _ => 0). split; [intros k; rewrite nth_nil_iv; apply zero_in|].
    rewrite sumR_zero'; [ring|intros; ring].
Qed.

(** ** The region: its dual bound, proved once *)

Definition mv (n : nat) (M : matQ) (x : nat -> R) (i : nat) : R :=
  sumR n (fun j => Q2R (entry M i j) * x j).

(** Si Sg = I, exactly. *)
Definition inv_check (n : nat) (Si Sg : matQ) : bool :=
  forallb (fun i => forallb (fun k =>
    Qeq_bool (sumQ n (fun j => Qmult (entry Si i j) (entry Sg j k)))
             (if Nat.eqb i k then 1%Q else 0%Q)) (seq 0 n)) (seq 0 n).

Lemma inv_check_R n Si Sg : inv_check n Si Sg = true -> forall i k, (i < n)%nat -> (k < n)%nat ->
  sumR n (fun j => Q2R (entry Si i j) * Q2R (entry Sg j k)) = if Nat.eqb i k then 1 else 0.
Proof.
  intros H i k Hi Hk. pose proof (forallb_seq _ n H i Hi) as H1. cbv beta in H1.
  pose proof (forallb_seq _ n H1 k Hk) as H2. cbv beta in H2.
  apply Qeq_bool_iff, Qeq_eqR in H2. rewrite Q2R_sumQ in H2.
  rewrite (sumR_ext n _ (fun j => Q2R (entry Si i j * entry Sg j k))) by (intros; apply eq_sym, Q2R_mult).
  rewrite H2. destruct (Nat.eqb i k); [apply Q2R_1|apply Q2R_0].
Qed.

Lemma mv_inv n Si Sg v i : inv_check n Si Sg = true -> (i < n)%nat ->
  mv n Si (mv n Sg v) i = v i.
Proof.
  intros H Hi. unfold mv.
  rewrite (sumR_ext n _ (fun j => sumR n (fun k => Q2R (entry Si i j) * Q2R (entry Sg j k) * v k)))
    by (intros j _; rewrite <- sumR_scal; apply sumR_ext; intros; ring).
  rewrite sumR_swap.
  rewrite (sumR_ext n _ (fun k => (if Nat.eqb k i then 1 else 0) * v k)).
  - apply sumR_delta, Hi.
  - intros k Hk. rewrite sumR_scal_r.
    rewrite (inv_check_R n Si Sg H i k Hi Hk), Nat.eqb_sym. reflexivity.
Qed.

Lemma qform_mv n M x : qform n M x = sumR n (fun i => x i * mv n M x i).
Proof.
  unfold qform, mv. apply sumR_ext. intros i _. rewrite <- sumR_scal. apply sumR_ext.
  intros; ring.
Qed.

(** For Si = Si^T >= 0 with Si Sg = I: d^T Si d >= 2 v.d - v^T Sg v for every real v. *)
Theorem dual_bound n Si Sg d v :
  symmetric n Si -> inv_check n Si Sg = true -> pos_semidef n Si ->
  2 * sumR n (fun i => v i * d i) - sumR n (fun i => v i * mv n Sg v i) <= qform n Si d.
Proof.
  intros Hs Hinv Hpsd. set (u := mv n Sg v).
  pose proof (Hpsd (fun i => d i - u i)) as H0. unfold qform in H0.
  rewrite (sumR_ext n _ (fun i => sumR n (fun j => Q2R (entry Si i j) * (d i * d j))
                                  - d i * mv n Si u i - u i * mv n Si d i
                                  + u i * mv n Si u i)) in H0.
  2: { intros i _. unfold mv. rewrite <- !sumR_scal. unfold Rminus.
       rewrite <- !sumR_opp, <- !sumR_plus.
       apply sumR_ext. intros; ring. }
  unfold Rminus in H0. rewrite !sumR_plus, !sumR_opp in H0. fold (qform n Si d) in H0.
  assert (E1 : sumR n (fun i => d i * mv n Si u i) = sumR n (fun i => v i * d i)).
  { apply sumR_ext. intros i Hi. unfold u. rewrite mv_inv by assumption. ring. }
  assert (E2 : sumR n (fun i => u i * mv n Si d i) = sumR n (fun i => d i * mv n Si u i)).
  { unfold mv. rewrite (sumR_ext n (fun i => u i * _)
                         (fun i => sumR n (fun j => Q2R (entry Si i j) * u i * d j)))
      by (intros; rewrite <- sumR_scal; apply sumR_ext; intros; ring).
    rewrite sumR_swap. apply sumR_ext. intros j Hj. rewrite <- sumR_scal. apply sumR_ext.
    intros i Hi. rewrite (Qeq_eqR _ _ (Hs i j Hi Hj)). ring. }
  assert (E3 : sumR n (fun i => u i * mv n Si u i) = sumR n (fun i => v i * mv n Sg v i)).
  { apply sumR_ext. intros i Hi. unfold u at 2. rewrite mv_inv by assumption. unfold u. ring. }
  rewrite E2, E1, E3 in H0. unfold u. lra.
Qed.

(** A scalar consequence: if 2 t a - t^2 q <= c for every t and q > 0, then a^2 <= c q. *)
Lemma dual_scalar a q c : 0 < q -> (forall t, 2 * t * a - t * t * q <= c) -> a * a <= c * q.
Proof.
  intros Hq H. specialize (H (a / q)).
  replace (2 * (a / q) * a - a / q * (a / q) * q) with (a * a / q) in H by (field; lra).
  apply (Rmult_le_compat_r q) in H; [|lra].
  replace (a * a / q * q) with (a * a) in H by (field; lra). exact H.
Qed.

(** ** The paper's parameters: th (10 coordinates) and phi (9) *)

(** The region: (th - thc)^T Si (th - thc) <= chi2. *)
Definition dvec (thc : list Q) (th : nat -> R) (i : nat) : R := th i - Q2R (nth i thc 0%Q).
Definition in_region (Si : matQ) (thc : list Q) (chi2 : Q) (th : nat -> R) : Prop :=
  qform 10 Si (dvec thc th) <= Q2R chi2.

(** phi = (th_0, .., th_7, th_8 + th_9): the conditions depend on c12, c21 through c. *)
Definition phi (th : nat -> R) (k : nat) : R :=
  if Nat.ltb k 8 then th k else if Nat.eqb k 8 then th 8%nat + th 9%nat else 0.
Definition phicQ (thc : list Q) : list Q :=
  map (fun k => if Nat.eqb k 8 then Qred (nth 8 thc 0%Q + nth 9 thc 0%Q) else nth k thc 0%Q)
      (seq 0 9).
(** A vector y on phi, lifted to th (y_8 for both c12 and c21). *)
Definition liftQ (y : list Q) : list Q := map (fun i => nth (Nat.min i 8) y 0%Q) (seq 0 10).
Definition vecR (l : list Q) (i : nat) : R := Q2R (nth i l 0%Q).

(** y^T Sg y for the lifted y, on Q, reducing every term (the general form). *)
Definition qQ_red (Sg : matQ) (l : list Q) : Q :=
  sumQ 10 (fun i => sumQ 10 (fun j => Qred (entry Sg i j * (nth i l 0%Q * nth j l 0%Q)))).

(** The same sum without reductions ([qmul], [qadd]): fast when the entries of l share
    one denominator and those of Sg too, since the terms then share theirs. *)
Definition qQ_with (Sg : matQ) (l : list Q) : Q :=
  sumQ 10 (fun i => sumQ 10 (fun j => qmul (entry Sg i j) (qmul (nth i l 0%Q) (nth j l 0%Q)))).

(** y written over one denominator, the lcm of its denominators.  Nothing is assumed of
    it: [qQ] compares it with y entry by entry ([Qeq_bool]) before using it. *)
Definition qcommon (y : list Q) : list Q :=
  let d := Z.to_pos (fold_left (fun a q => Z.lcm a (Zpos (Qden q))) y 1%Z) in
  map (fun q => Qmake (Qnum q * (Zpos d / Zpos (Qden q))) d) y.

(** y^T Sg y for the lifted y, on Q.  The gradient directions of linear leaves have
    entries of some 45 digits; reducing each of the 100 terms by a gcd cost seconds in
    the kernel, so the sum is taken over one common denominator when y has one. *)
Definition qQ (Sg : matQ) (y : list Q) : Q :=
  let l := liftQ y in
  let l' := liftQ (qcommon y) in
  if forallb (fun i => Qeq_bool (nth i l 0%Q) (nth i l' 0%Q)) (seq 0 10) then qQ_with Sg l'
  else qQ_red Sg l.

Lemma Q2R_qQ Sg y : Q2R (qQ Sg y) = sumR 10 (fun i => vecR (liftQ y) i * mv 10 Sg (vecR (liftQ y)) i).
Proof.
  unfold qQ. destruct (forallb _ (seq 0 10)) eqn:E.
  - assert (Hl : forall i, (i < 10)%nat ->
                 Q2R (nth i (liftQ (qcommon y)) 0%Q) = vecR (liftQ y) i).
    { intros i Hi. unfold vecR. pose proof (forallb_seq _ 10 E i Hi) as H. cbv beta in H.
      apply Qeq_bool_iff, Qeq_eqR in H. rewrite H. reflexivity. }
    unfold qQ_with, mv. rewrite Q2R_sumQ. apply sumR_ext. intros i Hi.
    rewrite Q2R_sumQ, <- sumR_scal. apply sumR_ext. intros j Hj.
    rewrite !Q2R_qmul, (Hl i Hi), (Hl j Hj). unfold vecR. ring.
  - unfold qQ_red, mv, vecR. rewrite Q2R_sumQ. apply sumR_ext. intros i _.
    rewrite Q2R_sumQ, <- sumR_scal. apply sumR_ext. intros j _.
    rewrite Q2R_red, !Q2R_mult. ring.
Qed.

Lemma lift_dot y thc th :
  sumR 10 (fun i => vecR (liftQ y) i * dvec thc th i)
  = sumR 9 (fun k => vecR y k * (phi th k - vecR (phicQ thc) k)).
Proof.
  unfold vecR, dvec, phi, liftQ, phicQ. cbn -[Q2R Qred Qplus]. rewrite Q2R_red, Q2R_plus. ring.
Qed.

Lemma mv_scal n M x t i : mv n M (fun j => t * x j) i = t * mv n M x i.
Proof. unfold mv. rewrite <- sumR_scal. apply sumR_ext. intros; ring. Qed.

Definition region_ok (Si Sg : matQ) (eps : Q) (ws : list term) : bool :=
  sym_check 10 Si && inv_check 10 Si Sg && psd_check 10 Si eps ws.

(** The dual bound on phi: for th in the region, 2 t y.(phi - phic) - t^2 y^T Sg y <= chi2. *)
Lemma region_dual Si Sg eps ws thc chi2 th y t :
  region_ok Si Sg eps ws = true -> in_region Si thc chi2 th ->
  2 * t * sumR 9 (fun k => vecR y k * (phi th k - vecR (phicQ thc) k))
  - t * t * Q2R (qQ Sg y) <= Q2R chi2.
Proof.
  unfold region_ok. rewrite !andb_true_iff. intros [[Hs Hi] Hp] Hr.
  pose proof (dual_bound 10 Si Sg (dvec thc th) (fun i => t * vecR (liftQ y) i)
                (sym_check_sound _ _ Hs) Hi (psd_check_semidef _ _ _ _ Hp)) as H.
  unfold in_region in Hr. rewrite <- lift_dot, Q2R_qQ.
  cbv beta in H.
  rewrite (sumR_ext 10 (fun i => t * vecR (liftQ y) i * dvec thc th i)
                       (fun i => t * (vecR (liftQ y) i * dvec thc th i))) in H by (intros; ring).
  rewrite sumR_scal in H.
  assert (E : sumR 10 (fun i => t * vecR (liftQ y) i * mv 10 Sg (fun i0 => t * vecR (liftQ y) i0) i)
              = t * t * sumR 10 (fun i => vecR (liftQ y) i * mv 10 Sg (vecR (liftQ y)) i)).
  { rewrite <- !sumR_scal. apply sumR_ext. intros i _. rewrite mv_scal. ring. }
  rewrite E in H. lra.
Qed.

(** ** The enclosing box *)

Definition unitQ (k : nat) : list Q := map (fun j => if Nat.eqb j k then 1%Q else 0%Q) (seq 0 9).

(** r_k >= 0 and r_k^2 >= chi2 Sg_phi,kk > 0 for every coordinate of phi. *)
Definition encl_ok (Sg : matQ) (chi2 : Q) (r : list Q) : bool :=
  forallb (fun k => let q := qQ Sg (unitQ k) in let rk := nth k r 0%Q in
                    Qle_bool 0 rk && negb (Qle_bool q 0) && Qle_bool (chi2 * q) (rk * rk))
          (seq 0 9).

Lemma sumR_unit k (f : nat -> R) : (k < 9)%nat -> sumR 9 (fun j => vecR (unitQ k) j * f j) = f k.
Proof.
  intros Hk. rewrite <- (sumR_delta 9 k f Hk). apply sumR_ext. intros j Hj.
  unfold vecR, unitQ. rewrite (nth_map_seq (fun j => if Nat.eqb j k then 1%Q else 0%Q))
    by exact Hj.
  destruct (Nat.eqb j k); [rewrite Q2R_1|rewrite Q2R_0]; reflexivity.
Qed.

Lemma Qlt_of_negb a b : negb (Qle_bool a b) = true -> Q2R b < Q2R a.
Proof.
  intros H. apply negb_true_iff in H. apply Qlt_Rlt, Qnot_le_lt. intros Hl.
  apply Qle_bool_iff in Hl. congruence.
Qed.

Theorem enclosure Si Sg eps ws thc chi2 r th k :
  region_ok Si Sg eps ws = true -> encl_ok Sg chi2 r = true -> in_region Si thc chi2 th ->
  (k < 9)%nat -> Rabs (phi th k - vecR (phicQ thc) k) <= Q2R (nth k r 0%Q).
Proof.
  intros Hreg Henc Hr Hk. pose proof (forallb_seq _ 9 Henc k Hk) as H. cbv zeta beta in H.
  rewrite !andb_true_iff in H. destruct H as [[H0 Hq] Hle].
  apply Qle_bool_R in H0, Hle. rewrite Q2R_0 in H0. rewrite !Q2R_mult in Hle.
  apply Qlt_of_negb in Hq. rewrite Q2R_0 in Hq.
  assert (Hd : forall t, 2 * t * (phi th k - vecR (phicQ thc) k) - t * t * Q2R (qQ Sg (unitQ k))
                        <= Q2R chi2).
  { intros t. pose proof (region_dual Si Sg eps ws thc chi2 th (unitQ k) t Hreg Hr) as H.
    rewrite sumR_unit in H by exact Hk. exact H. }
  pose proof (dual_scalar _ _ _ Hq Hd) as Hs.
  apply (Rle_trans _ (Rabs (Q2R (nth k r 0%Q)))).
  - apply Rsqr_le_abs_0. unfold Rsqr. lra.
  - rewrite Rabs_right by lra. lra.
Qed.

(** ** The paper's model class and what a verdict states *)

(** Diagonal element i (0 or 1): (b1 s + b0) / (s^2 + a1 s + a0) at s = jw, with
    (b1, b0, a1, a0) = (th_4i, th_4i+1, th_4i+2, th_4i+3). *)
Definition num_at (th : nat -> R) (i : nat) (w : R) : R * R :=
  (th (4 * i + 1)%nat, th (4 * i)%nat * w).
Definition den_at (th : nat -> R) (i : nat) (w : R) : R * R :=
  (th (4 * i + 3)%nat - w * w, th (4 * i + 2)%nat * w).

(** H_th(jw): the diagonal elements and the constant off-diagonal ones c12, c21. *)
Definition paper_H (th : nat -> R) (w : R) (i k : nat) : R * R :=
  match i, k with
  | O, O => cdiv (num_at th 0 w) (den_at th 0 w)
  | O, S O => (th 8%nat, 0)
  | S O, O => (th 9%nat, 0)
  | S O, S O => cdiv (num_at th 1 w) (den_at th 1 w)
  | _, _ => (0, 0)
  end.

Definition paper_herm (th : nat -> R) (w : R) (i k : nat) : R * R :=
  cadd (paper_H th w i k) (cconj (paper_H th w k i)).

(** At w: H_th(jw) + H_th(jw)^H >= 0 where H_th(jw) is defined (as BandCert.v's
    [hermitian_part_psd_at]). *)
Definition paper_psd_at (th : nat -> R) (w : R) : Prop :=
  den_at th 0 w <> (0, 0) -> den_at th 1 w <> (0, 0) ->
  forall z, 0 <= hform 2 (paper_herm th w) z.

(** The model H_th is passive on the band [w1, w2] (as BandCert.v's [band_passive]). *)
Definition paper_band_passive (th : nat -> R) (w1 w2 : Q) : Prop :=
  forall w, Q2R w1 <= w <= Q2R w2 -> paper_psd_at th w.

(** ** The conditions, as the Python checker's terms (robust_band.py) *)

Definition el_b (i : nat) : list expr := [EVar (4 * i + 1); EVar (4 * i)].
Definition el_a (i : nat) : list expr := [EVar (4 * i + 3); EVar (4 * i + 2); EConst 1].

(** N_i(x) = C_0 + C_1 x and D_i(x) = E_0 + E_1 x + E_2 x^2 ([n_coefficients],
    [d_coefficients], [polynomial]). *)
Definition n_expr (i : nat) : expr :=
  let b0 := EVar (4 * i + 1) in let b1 := EVar (4 * i) in
  let a0 := EVar (4 * i + 3) in let a1 := EVar (4 * i + 2) in
  let C0 := EAdd (EConst 0) (EScale 1 (EMul b0 a0)) in
  let C1 := EAdd (EAdd (EConst 0) (EScale (-1) (EMul b0 (EConst 1)))) (EScale 1 (EMul b1 a1)) in
  EAdd (EAdd (EConst 0) C0) (EMul C1 (ET 1)).
Definition d_expr (i : nat) : expr :=
  let a0 := EVar (4 * i + 3) in let a1 := EVar (4 * i + 2) in
  let E0 := ESqr a0 in
  let E1 := EAdd (ESqr a1) (EScale (-2) (EMul a0 (EConst 1))) in
  let E2 := ESqr (EConst 1) in
  EAdd (EAdd (EAdd (EConst 0) E0) (EMul E1 (ET 1))) (EMul E2 (ET 2)).
(** 4 N_1 N_2 - c^2 D_1 D_2 ([leaf_bounds], variable x). *)
Definition det_expr : expr :=
  ESub (EScale 4 (EMul (n_expr 0) (n_expr 1)))
       (EMul (ESqr (EVar 8)) (EMul (d_expr 0) (d_expr 1))).
(** v_1^2 N_1 D_2 + v_2^2 N_2 D_1 + v_1 v_2 c D_1 D_2 ([direction_bounds]). *)
Definition g_expr (v1 v2 : Q) : expr :=
  EAdd (EAdd (EMul (EMul (ESqr (EConst v1)) (n_expr 0)) (d_expr 1))
             (EMul (EMul (ESqr (EConst v2)) (n_expr 1)) (d_expr 0)))
       (EMul (EMul (EMul (EConst v1) (EConst v2)) (EVar 8)) (EMul (d_expr 0) (d_expr 1))).

(** The point of the tree's box: phi, then x = w^2. *)
Definition point (th : nat -> R) (x : R) (k : nat) : R := if Nat.eqb k 9 then x else phi th k.

Lemma n_real th x w i : (i < 2)%nat -> x = w * w ->
  ereal (point th x) x (n_expr i)
  = fst (num_at th i w) * fst (den_at th i w) + snd (num_at th i w) * snd (den_at th i w).
Proof.
  intros Hi ->. destruct i as [|[|i]]; [| |lia]; unfold point, phi, num_at, den_at; simpl;
    rewrite ?Q2R_0, ?Q2R_1; ring.
Qed.

Lemma d_real th x w i : (i < 2)%nat -> x = w * w ->
  ereal (point th x) x (d_expr i)
  = fst (den_at th i w) * fst (den_at th i w) + snd (den_at th i w) * snd (den_at th i w).
Proof.
  intros Hi ->. destruct i as [|[|i]]; [| |lia]; unfold point, phi, num_at, den_at; simpl;
    rewrite ?Q2R_0, ?Q2R_1; ring.
Qed.

Lemma c_real th x : ereal (point th x) x (EVar 8) = th 8%nat + th 9%nat.
Proof. reflexivity. Qed.

(** N_i > 0 forces den_i(jw) <> 0 (then num_i conj den_i would be 0). *)
Lemma den_pos (nr ni dr di : R) : 0 < nr * dr + ni * di -> 0 < dr * dr + di * di.
Proof.
  intros H. destruct (Req_dec dr 0) as [->|Hr].
  - destruct (Req_dec di 0) as [->|Hi]; [lra|]. nra.
  - assert (0 < dr * dr) by (apply Rsqr_pos_lt in Hr; unfold Rsqr in Hr; exact Hr). nra.
Qed.

Lemma den_nonzero (p : R * R) : 0 < fst p * fst p + snd p * snd p -> p <> (0, 0).
Proof. intros H E. rewrite E in H. simpl in H. lra. Qed.

(** The form of H(jw) + H(jw)^H for the paper's structure. *)
Lemma paper_hform th w z :
  let D0 := fst (den_at th 0 w) * fst (den_at th 0 w) + snd (den_at th 0 w) * snd (den_at th 0 w) in
  let D1 := fst (den_at th 1 w) * fst (den_at th 1 w) + snd (den_at th 1 w) * snd (den_at th 1 w) in
  let N0 := fst (num_at th 0 w) * fst (den_at th 0 w) + snd (num_at th 0 w) * snd (den_at th 0 w) in
  let N1 := fst (num_at th 1 w) * fst (den_at th 1 w) + snd (num_at th 1 w) * snd (den_at th 1 w) in
  D0 <> 0 -> D1 <> 0 ->
  hform 2 (paper_herm th w) z
  = (2 * N0 / D0) * (fst (z 0%nat) * fst (z 0%nat) + snd (z 0%nat) * snd (z 0%nat))
    + (2 * N1 / D1) * (fst (z 1%nat) * fst (z 1%nat) + snd (z 1%nat) * snd (z 1%nat))
    + 2 * ((th 8%nat + th 9%nat) * (fst (z 0%nat) * fst (z 1%nat) + snd (z 0%nat) * snd (z 1%nat))
           - 0 * (fst (z 0%nat) * snd (z 1%nat) - snd (z 0%nat) * fst (z 1%nat))).
Proof.
  (* with [N_i] and [D_i] kept as atoms, [field] works on a small rational function *)
  intros D0 D1 N0 N1 H0 H1.
  unfold hform, paper_herm, paper_H, cadd, cmul, cconj, cdiv. cbn [sumR fst snd].
  fold D0 D1 N0 N1. field. split; assumption.
Qed.

Lemma psd_of_conditions th w :
  let x := w * w in
  0 < ereal (point th x) x (n_expr 0) -> 0 < ereal (point th x) x (n_expr 1) ->
  0 < ereal (point th x) x det_expr -> paper_psd_at th w.
Proof.
  intros x Hn0 Hn1 Hdet _ _ z.
  rewrite n_real with (w := w) in Hn0, Hn1 by (reflexivity || lia).
  pose proof (den_pos _ _ _ _ Hn0) as Hd0. pose proof (den_pos _ _ _ _ Hn1) as Hd1.
  unfold det_expr in Hdet. cbn [ereal] in Hdet.
  rewrite !n_real with (w := w), !d_real with (w := w) in Hdet by (reflexivity || lia).
  replace (point th x 8%nat) with (th 8%nat + th 9%nat) in Hdet by reflexivity.
  rewrite paper_hform by lra.
  set (N0 := fst (num_at th 0 w) * fst (den_at th 0 w) + snd (num_at th 0 w) * snd (den_at th 0 w)) in *.
  set (N1 := fst (num_at th 1 w) * fst (den_at th 1 w) + snd (num_at th 1 w) * snd (den_at th 1 w)) in *.
  set (D0 := fst (den_at th 0 w) * fst (den_at th 0 w) + snd (den_at th 0 w) * snd (den_at th 0 w)) in *.
  set (D1 := fst (den_at th 1 w) * fst (den_at th 1 w) + snd (den_at th 1 w) * snd (den_at th 1 w)) in *.
  set (c := th 8%nat + th 9%nat) in *.
  apply herm2.
  - assert (0 < 2 * N0 / D0) by (apply Rdiv_lt_0_compat; lra).
    assert (0 < 2 * N1 / D1) by (apply Rdiv_lt_0_compat; lra). lra.
  - replace (2 * N0 / D0 * (2 * N1 / D1) - c * c - 0 * 0)
      with ((4 * N0 * N1 - c * c * (D0 * D1)) / (D0 * D1)) by (field; lra).
    apply Rlt_le, Rdiv_lt_0_compat; [lra|]. apply Rmult_lt_0_compat; lra.
Qed.

(** A real direction (v1, v2) with g < 0 and D_1, D_2 > 0 refutes the form at w. *)
Lemma not_psd_of_direction th w v1 v2 :
  let x := w * w in
  0 < ereal (point th x) x (d_expr 0) -> 0 < ereal (point th x) x (d_expr 1) ->
  ereal (point th x) x (g_expr v1 v2) < 0 -> ~ paper_psd_at th w.
Proof.
  intros x Hd0 Hd1 Hg Hpsd.
  rewrite d_real with (w := w) in Hd0, Hd1 by (reflexivity || lia).
  unfold g_expr in Hg. cbn [ereal] in Hg.
  rewrite !n_real with (w := w), !d_real with (w := w) in Hg by (reflexivity || lia).
  replace (point th x 8%nat) with (th 8%nat + th 9%nat) in Hg by reflexivity.
  specialize (Hpsd (den_nonzero _ Hd0) (den_nonzero _ Hd1)
                   (fun i => if Nat.eqb i 0 then (Q2R v1, 0) else (Q2R v2, 0))).
  rewrite paper_hform in Hpsd by lra. cbn [Nat.eqb fst snd] in Hpsd.
  set (N0 := fst (num_at th 0 w) * fst (den_at th 0 w) + snd (num_at th 0 w) * snd (den_at th 0 w)) in *.
  set (N1 := fst (num_at th 1 w) * fst (den_at th 1 w) + snd (num_at th 1 w) * snd (den_at th 1 w)) in *.
  set (D0 := fst (den_at th 0 w) * fst (den_at th 0 w) + snd (den_at th 0 w) * snd (den_at th 0 w)) in *.
  set (D1 := fst (den_at th 1 w) * fst (den_at th 1 w) + snd (den_at th 1 w) * snd (den_at th 1 w)) in *.
  set (c := th 8%nat + th 9%nat) in *.
  replace (2 * N0 / D0 * (Q2R v1 * Q2R v1 + 0 * 0) + 2 * N1 / D1 * (Q2R v2 * Q2R v2 + 0 * 0)
           + 2 * (c * (Q2R v1 * Q2R v2 + 0 * 0) - 0 * (Q2R v1 * 0 - 0 * Q2R v2)))
    with (2 * (Q2R v1 * Q2R v1 * N0 * D1 + Q2R v2 * Q2R v2 * N1 * D0
               + Q2R v1 * Q2R v2 * c * (D0 * D1)) / (D0 * D1)) in Hpsd by (field; lra).
  assert (0 < D0 * D1) by (apply Rmult_lt_0_compat; lra).
  assert (2 * (Q2R v1 * Q2R v1 * N0 * D1 + Q2R v2 * Q2R v2 * N1 * D0
               + Q2R v1 * Q2R v2 * c * (D0 * D1)) / (D0 * D1) < 0).
  { unfold Rdiv. rewrite Rmult_comm. apply Rmult_lt_reg_l with (D0 * D1); [lra|].
    rewrite <- Rmult_assoc, Rinv_r by lra. rewrite Rmult_0_r. lra. }
  lra.
Qed.

(** ** Leaves and the tree of boxes *)

Definition mid (a : iv) : Q := Qred ((fst a + snd a) * (1 # 2)).

Lemma Q2R_mid a : Q2R (mid a) = (Q2R (fst a) + Q2R (snd a)) / 2.
Proof.
  unfold mid. rewrite Q2R_red, Q2R_mult, Q2R_plus.
  replace (Q2R (1 # 2)) with (/ 2) by (unfold Q2R; simpl; field). field.
Qed.

(** The box with the first n coordinates at their midpoints. *)
Definition centre_box (n : nat) (B : list iv) : list iv :=
  map (fun k => if Nat.ltb k n then (mid (nth k B zero_iv), mid (nth k B zero_iv))
                else nth k B zero_iv) (seq 0 (length B)).

Lemma nth_centre_box n B k : (k < length B)%nat ->
  nth k (centre_box n B) zero_iv
  = if Nat.ltb k n then (mid (nth k B zero_iv), mid (nth k B zero_iv)) else nth k B zero_iv.
Proof. intros Hk. unfold centre_box. apply (nth_map_seq (fun k => _)), Hk. Qed.

Lemma nth_centre_box_out n B k : (length B <= k)%nat -> nth k (centre_box n B) zero_iv = zero_iv.
Proof. intros Hk. apply nth_overflow. unfold centre_box. rewrite map_length, seq_length. exact Hk. Qed.

Definition centre_point (n : nat) (B : list iv) (p : nat -> R) (k : nat) : R :=
  if Nat.ltb k n then Q2R (mid (nth k B zero_iv)) else p k.

Lemma centre_point_in n B p : in_box B p ->
  in_box B (centre_point n B p) /\ in_box (centre_box n B) (centre_point n B p).
Proof.
  intros HB. split; intros k; pose proof (HB k) as Hk; unfold centre_point, in_iv in *.
  - destruct (Nat.ltb k n); [|exact Hk]. rewrite Q2R_mid. lra.
  - destruct (Nat.lt_ge_cases k (length B)) as [Hl|Hl].
    + rewrite nth_centre_box by exact Hl.
      destruct (Nat.ltb k n); [cbn [fst snd]; lra|exact Hk].
    + rewrite nth_centre_box_out by exact Hl. rewrite (nth_overflow B zero_iv Hl) in Hk |- *.
      destruct (Nat.ltb k n); [|exact Hk]. rewrite Q2R_mid. cbn [fst snd] in *. lra.
Qed.

Lemma sumR_sub n f g : sumR n (fun k => f k - g k) = sumR n f - sumR n g.
Proof. unfold Rminus. rewrite sumR_plus, sumR_opp. reflexivity. Qed.

(** The first-order bound of a linear leaf: e >= c on the box's part of the region. *)
Definition lin_ok (Sg : matQ) (chi2 : Q) (phic : list Q) (B : list iv) (T : iv) (e : expr)
    (c s : Q) : bool :=
  let V := eiv (centre_box 9 B) T e in
  let G := snd (egr B T e) in
  let y := map (fun k => Qopp (mid (nth k G zero_iv))) (seq 0 9) in
  let q := qQ Sg y in
  let bound := (fst V - s + sumQ 9 (fun k =>
      let g := nth k G zero_iv in let b := nth k B zero_iv in
      Qred (mid g * (nth k phic 0%Q - mid b)
            - (snd g - fst g) * (1 # 2) * ((snd b - fst b) * (1 # 2)))))%Q in
  negb (Qle_bool c 0) && Qle_bool 0 s && negb (Qle_bool q 0) && Qle_bool (chi2 * q) (s * s)
  && Qle_bool c bound.

Lemma slope_term glo ghi sk lo hi pk pc :
  glo <= sk <= ghi -> lo <= pk <= hi ->
  sk * (pk - (lo + hi) / 2)
  >= (glo + ghi) / 2 * (pk - pc)
     + ((glo + ghi) / 2 * (pc - (lo + hi) / 2) - (ghi - glo) / 2 * ((hi - lo) / 2)).
Proof.
  intros Hs Hp. set (u := sk - (glo + ghi) / 2). set (v := pk - (lo + hi) / 2).
  assert (0 <= ((ghi - glo) / 2 + u) * ((hi - lo) / 2 + v)) by (apply Rmult_le_pos; unfold u, v; lra).
  assert (0 <= ((ghi - glo) / 2 - u) * ((hi - lo) / 2 - v)) by (apply Rmult_le_pos; unfold u, v; lra).
  unfold u, v in *. nra.
Qed.

Theorem lin_ok_sound Si Sg eps ws thc chi2 B T e c s th x :
  region_ok Si Sg eps ws = true -> in_region Si thc chi2 th ->
  lin_ok Sg chi2 (phicQ thc) B T e c s = true ->
  in_box B (point th x) -> in_iv T x -> 0 < ereal (point th x) x e.
Proof.
  intros Hreg Hr Hok HB HT. unfold lin_ok in Hok. cbv zeta in Hok.
  rewrite !andb_true_iff in Hok. destruct Hok as [[[[Hc Hs] Hq] Hsq] Hb].
  apply Qlt_of_negb in Hc, Hq. rewrite Q2R_0 in Hc, Hq.
  apply Qle_bool_R in Hs, Hsq, Hb. rewrite Q2R_0 in Hs. rewrite !Q2R_mult in Hsq.
  set (p := point th x) in *. set (p0 := centre_point 9 B p).
  destruct (centre_point_in 9 B p HB) as [HB0 HC0].
  set (G := snd (egr B T e)) in *.
  set (y := map (fun k => Qopp (mid (nth k G zero_iv))) (seq 0 9)) in *.
  pose proof (eiv_sound _ T p0 x e HC0 HT) as HV.
  destruct (egr_sound 9 B T p p0 x e HB HB0 HT) as [sl [Hsl Heq]].
  { intros k Hk. unfold p0, centre_point. destruct (Nat.ltb_spec k 9); [lia|reflexivity]. }
  fold G in Hsl.
  (* the region: -m.(phi - phic) <= s *)
  set (a := sumR 9 (fun k => vecR y k * (phi th k - vecR (phicQ thc) k))).
  assert (Ha : a <= Q2R s).
  { pose proof (dual_scalar a _ _ Hq (fun t => region_dual Si Sg eps ws thc chi2 th y t Hreg Hr))
      as H. apply (Rle_trans _ (Rabs a)); [apply Rle_abs|].
    apply (Rle_trans _ (Rabs (Q2R s))); [apply Rsqr_le_abs_0; unfold Rsqr; lra|].
    rewrite Rabs_right; lra. }
  assert (Hsum : sumR 9 (fun k => sl k * (p k - p0 k))
                 >= - a + sumR 9 (fun k => Q2R (Qred (mid (nth k G zero_iv)
                        * (nth k (phicQ thc) 0%Q - mid (nth k B zero_iv))
                        - (snd (nth k G zero_iv) - fst (nth k G zero_iv)) * (1 # 2)
                          * ((snd (nth k B zero_iv) - fst (nth k B zero_iv)) * (1 # 2)))))).
  { unfold a. rewrite <- sumR_opp, <- sumR_plus. apply Rle_ge, sumR_le. intros k Hk.
    unfold y, vecR. rewrite (nth_map_seq (fun k => Qopp (mid (nth k G zero_iv)))) by exact Hk.
    rewrite Q2R_red, Q2R_minus, !Q2R_mult, !Q2R_minus, !Q2R_opp, !Q2R_mid.
    replace (Q2R (1 # 2)) with (/ 2) by (unfold Q2R; simpl; field).
    assert (Ep : phi th k = p k) by (unfold p, point; destruct (Nat.eqb_spec k 9); [lia|reflexivity]).
    assert (Ep0 : p0 k = (Q2R (fst (nth k B zero_iv)) + Q2R (snd (nth k B zero_iv))) / 2).
    { unfold p0, centre_point. destruct (Nat.ltb_spec k 9); [|lia]. apply Q2R_mid. }
    rewrite Ep, Ep0. apply Rge_le.
    pose proof (slope_term _ _ (sl k) _ _ (p k) (Q2R (nth k (phicQ thc) 0%Q)) (Hsl k) (HB k)) as H.
    unfold Rdiv in *. lra. }
  rewrite Q2R_plus, Q2R_minus, Q2R_sumQ in Hb.
  unfold in_iv in HV. lra.
Qed.


(** A linear leaf with its direction given ([RLinY]): the same first-order form as
    [lin_ok], with the region's term bounded along a rational direction y that the unit
    supplies (short, rounded by the exporter) instead of the gradient midpoints computed
    here.  For the slope s_k in G_k and phi_k in b_k with midpoint m_k,
    s_k (phi_k - m_k) = (s_k + y_k)(phi_k - m_k) - y_k (phi_k - phic_k) - y_k (phic_k - m_k),
    and the first product is bounded below by interval multiplication.  The region gives
    y.(phi - phic) <= s when chi2 y^T Sg y <= s^2.  Nothing is assumed of y: with
    y = -(midpoints of G) this is [lin_ok]'s bound. *)
Definition dir_term (g b : iv) (yk pc : Q) : Q :=
  Qred (- yk * (pc - mid b) + fst (imul (iadd g (yk, yk)) (isub b (mid b, mid b)))).

Definition lin_dir_core (Sg : matQ) (chi2 : Q) (phic : list Q) (B : list iv) (V : iv)
    (G : list iv) (c s : Q) (y : list Q) : bool :=
  let q := qQ Sg y in
  let bound := (fst V - s + sumQ 9 (fun k =>
      dir_term (nth k G zero_iv) (nth k B zero_iv) (nth k y 0%Q) (nth k phic 0%Q)))%Q in
  negb (Qle_bool c 0) && Qle_bool 0 s && negb (Qle_bool q 0) && Qle_bool (chi2 * q) (s * s)
  && Qle_bool c bound.

Definition lin_dir_ok (Sg : matQ) (chi2 : Q) (phic : list Q) (B : list iv) (T : iv) (e : expr)
    (c s : Q) (y : list Q) : bool :=
  lin_dir_core Sg chi2 phic B (eiv (centre_box 9 B) T e) (snd (egr B T e)) c s y.

(** The three conditions of a linear leaf with N_1, N_2 and their slopes computed once:
    [det_expr] is built from [n_expr 0] and [n_expr 1], so [eiv] and [egr] of [det_expr]
    are these terms ([lin_leaf_dir]). *)
Definition egr_det (B : list iv) (T : iv) (g0 g1 : iv * list iv) : iv * list iv :=
  match (match (match g0 with (va, ga) => match g1 with (vb, gb) =>
                  (imul va vb, gzip (fun x y => iadd (imul va y) (imul vb x)) ga gb) end end)
         with (va, ga) => (iscale 4 va, map (iscale 4) ga) end) with
  | (va, ga) => match egr B T (EMul (ESqr (EVar 8)) (EMul (d_expr 0) (d_expr 1))) with
                | (vb, gb) => (isub va vb, gzip isub ga gb) end
  end.

Definition eiv_det (B : list iv) (T : iv) (n0 n1 : iv) : iv :=
  isub (iscale 4 (imul n0 n1))
       (imul (isqr (nth 8 B zero_iv)) (imul (eiv B T (d_expr 0)) (eiv B T (d_expr 1)))).

Definition lin_leaf (Sg : matQ) (chi2 : Q) (phic : list Q) (B : list iv) (T : iv)
    (c0 c1 c2 s0 s1 s2 : Q) (y0 y1 y2 : list Q) : bool :=
  let C := centre_box 9 B in
  let v0 := eiv C T (n_expr 0) in let v1 := eiv C T (n_expr 1) in
  let g0 := egr B T (n_expr 0) in let g1 := egr B T (n_expr 1) in
  lin_dir_core Sg chi2 phic B v0 (snd g0) c0 s0 y0
  && lin_dir_core Sg chi2 phic B v1 (snd g1) c1 s1 y1
  && lin_dir_core Sg chi2 phic B (eiv_det C T v0 v1) (snd (egr_det B T g0 g1)) c2 s2 y2.

Lemma lin_leaf_dir Sg chi2 phic B T c0 c1 c2 s0 s1 s2 y0 y1 y2 :
  lin_leaf Sg chi2 phic B T c0 c1 c2 s0 s1 s2 y0 y1 y2
  = lin_dir_ok Sg chi2 phic B T (n_expr 0) c0 s0 y0
    && lin_dir_ok Sg chi2 phic B T (n_expr 1) c1 s1 y1
    && lin_dir_ok Sg chi2 phic B T det_expr c2 s2 y2.
Proof. reflexivity. Qed.

Lemma dir_term_le g b yk pc sk pk : in_iv g sk -> in_iv b pk ->
  Q2R (dir_term g b yk pc) - Q2R yk * (pk - Q2R pc) <= sk * (pk - Q2R (mid b)).
Proof.
  intros Hg Hb. unfold dir_term.
  assert (Hy : in_iv (yk, yk) (Q2R yk)) by (unfold in_iv; cbn [fst snd]; lra).
  assert (Hm : in_iv (mid b, mid b) (Q2R (mid b))) by (unfold in_iv; cbn [fst snd]; lra).
  pose proof (imul_sound _ _ _ _ (iadd_sound _ _ _ _ Hg Hy) (isub_sound _ _ _ _ Hb Hm)) as H.
  unfold in_iv in H. destruct H as [H _].
  rewrite Q2R_red, Q2R_plus, Q2R_mult, Q2R_opp, Q2R_minus. nra.
Qed.

Local Strategy expand [lin_dir_ok lin_dir_core].

Theorem lin_dir_ok_sound Si Sg eps ws thc chi2 B T e c s y th x :
  region_ok Si Sg eps ws = true -> in_region Si thc chi2 th ->
  lin_dir_ok Sg chi2 (phicQ thc) B T e c s y = true ->
  in_box B (point th x) -> in_iv T x -> 0 < ereal (point th x) x e.
Proof.
  intros Hreg Hr Hok HB HT. unfold lin_dir_ok, lin_dir_core in Hok. cbv zeta in Hok.
  rewrite !andb_true_iff in Hok. destruct Hok as [[[[Hc Hs] Hq] Hsq] Hb].
  apply Qlt_of_negb in Hc, Hq. rewrite Q2R_0 in Hc, Hq.
  apply Qle_bool_R in Hs, Hsq, Hb. rewrite Q2R_0 in Hs. rewrite !Q2R_mult in Hsq.
  set (p := point th x) in *. set (p0 := centre_point 9 B p).
  destruct (centre_point_in 9 B p HB) as [HB0 HC0].
  set (G := snd (egr B T e)) in *.
  pose proof (eiv_sound _ T p0 x e HC0 HT) as HV.
  destruct (egr_sound 9 B T p p0 x e HB HB0 HT) as [sl [Hsl Heq]].
  { intros k Hk. unfold p0, centre_point. destruct (Nat.ltb_spec k 9); [lia|reflexivity]. }
  fold G in Hsl.
  set (a := sumR 9 (fun k => vecR y k * (phi th k - vecR (phicQ thc) k))).
  assert (Ha : a <= Q2R s).
  { pose proof (dual_scalar a _ _ Hq (fun t => region_dual Si Sg eps ws thc chi2 th y t Hreg Hr))
      as H. apply (Rle_trans _ (Rabs a)); [apply Rle_abs|].
    apply (Rle_trans _ (Rabs (Q2R s))); [apply Rsqr_le_abs_0; unfold Rsqr; lra|].
    rewrite Rabs_right; lra. }
  assert (Hsum : sumR 9 (fun k => sl k * (p k - p0 k))
                 >= - a + sumR 9 (fun k => Q2R (dir_term (nth k G zero_iv) (nth k B zero_iv)
                                                        (nth k y 0%Q) (nth k (phicQ thc) 0%Q)))).
  { unfold a. rewrite <- sumR_opp, <- sumR_plus. apply Rle_ge, sumR_le. intros k Hk.
    assert (Ep : phi th k = p k) by (unfold p, point; destruct (Nat.eqb_spec k 9); [lia|reflexivity]).
    assert (Ep0 : p0 k = Q2R (mid (nth k B zero_iv))).
    { unfold p0, centre_point. destruct (Nat.ltb_spec k 9); [reflexivity|lia]. }
    rewrite Ep, Ep0. unfold vecR.
    pose proof (dir_term_le _ _ (nth k y 0%Q) (nth k (phicQ thc) 0%Q) (sl k) (p k) (Hsl k) (HB k))
      as H. lra. }
  rewrite Q2R_plus, Q2R_minus, Q2R_sumQ in Hb.
  unfold in_iv in HV. lra.
Qed.



(** ** A box the region misses: the dual bound along a fixed direction *)

(** A leaf [ROut y]: y is a rational direction on phi (9 coordinates).  For th in the
    region, [region_dual] at t = 1 gives 2 y.(phi - phic) - y^T Sg y <= chi2; if the least
    value of 2 y.(phi - phic) over the box, less y^T Sg y, exceeds chi2, no point of the
    box is in the region.  With y = Sg_phi^-1 (p - phic) this is the tangent plane of the
    region's quadratic form at p (the Python checker's [outside_bound]): q(p) + g.(phi - p)
    = 2 y.(phi - phic) - y^T Sg_phi y for g = 2 y.  Nothing is assumed of y: any rational
    direction that passes the test is sound, so the exporter may round it. *)
Definition out_term (yk pc : Q) (b : iv) : Q := qmin (yk * (fst b - pc)) (yk * (snd b - pc)).

Definition out_ok (Sg : matQ) (chi2 : Q) (phic : list Q) (B : list iv) (y : list Q) : bool :=
  let lb := sumQ 9 (fun k => out_term (nth k y 0%Q) (nth k phic 0%Q) (nth k B zero_iv)) in
  negb (Qle_bool (lb + lb - qQ Sg y) chi2).

Lemma out_term_le yk pc b x : in_iv b x ->
  Q2R (out_term yk pc b) <= Q2R yk * (x - Q2R pc).
Proof.
  unfold out_term, in_iv. intros Hx.
  pose proof (qmin_le (yk * (fst b - pc)) (yk * (snd b - pc))) as [H1 H2].
  rewrite !Q2R_mult, !Q2R_minus in H1, H2.
  destruct (Rle_dec 0 (Q2R yk)).
  - apply (Rle_trans _ _ _ H1). apply Rmult_le_compat_l; lra.
  - apply (Rle_trans _ _ _ H2). nra.
Qed.

(** The kernel checks the [Qed]s below by converting [out_ok ...] with its body; it is told
    to unfold [out_ok] first.  Otherwise it may unfold [negb] and [Qle_bool] on the other
    side and reduce the symbolic sums under them, which did not finish in minutes. *)
Local Strategy expand [out_ok].

(** A leaf [ROut y] that passes holds no point of the region. *)
Theorem out_ok_sound Si Sg eps ws thc chi2 B y th x :
  region_ok Si Sg eps ws = true -> in_region Si thc chi2 th ->
  out_ok Sg chi2 (phicQ thc) B y = true -> in_box B (point th x) -> False.
Proof.
  intros Hreg Hr Hok HB. unfold out_ok in Hok. cbv zeta in Hok.
  apply Qlt_of_negb in Hok. rewrite Q2R_minus, Q2R_plus, Q2R_sumQ in Hok.
  pose proof (region_dual Si Sg eps ws thc chi2 th y 1 Hreg Hr) as Hd.
  assert (Hs : sumR 9 (fun k => Q2R (out_term (nth k y 0%Q) (nth k (phicQ thc) 0%Q)
                                                (nth k B zero_iv)))
               <= sumR 9 (fun k => vecR y k * (phi th k - vecR (phicQ thc) k))).
  { apply sumR_le. intros k Hk.
    assert (Ep : phi th k = point th x k)
      by (unfold point; destruct (Nat.eqb_spec k 9); [lia|reflexivity]).
    rewrite Ep. unfold vecR. apply out_term_le, HB. }
  lra.
Qed.

(** A leaf: [RPos c0 c1 c2] (N_1, N_2, det >= c > 0 by intervals), [RLin c0 c1 c2 s0 s1 s2]
    (the same by the first-order form), [RNeg c]
    (g <= c < 0 by intervals), [RNegLin c s] (the same by the first-order form),
    [ROut y] (the box misses the region, [out_ok]). *)
Inductive rleaf :=
| RPos (c0 c1 c2 : Q) | RLin (c0 c1 c2 s0 s1 s2 : Q) | RNeg (c : Q) | RNegLin (c s : Q)
| ROut (y : list Q)
| RLinY (c0 c1 c2 s0 s1 s2 : Q) (y0 y1 y2 : list Q).

(** A tree of midpoint splits: [RSplit k l r] cuts coordinate k, left half first;
    [RGrid k t] rounds the current box outwards to the grid 1/k (each corner to a
    multiple of 1/k, [grid_box]) and checks t on that larger box, whose numbers are
    short. *)
Inductive rtree := RLeaf (l : rleaf) | RSplit (k : nat) (l r : rtree) | RGrid (k : positive) (t : rtree).

Definition gdown (k : positive) (a : Q) : Q := Qmake (Qfloor (a * inject_Z (Zpos k))) k.
Definition gup (k : positive) (a : Q) : Q := Qmake (Qceiling (a * inject_Z (Zpos k))) k.
Definition grid_box (k : positive) (B : list iv) : list iv :=
  map (fun b => (gdown k (fst b), gup k (snd b))) B.

Lemma grid_scale k z : (Qmake z k * inject_Z (Zpos k) == inject_Z z)%Q.
Proof. unfold Qeq, inject_Z. simpl. rewrite Pos.mul_1_r. ring. Qed.

Lemma grid_pos k : (0 < inject_Z (Zpos k))%Q.
Proof. unfold Qlt, inject_Z. simpl. lia. Qed.

Lemma gdown_le k a : Q2R (gdown k a) <= Q2R a.
Proof.
  apply Qle_Rle. unfold gdown. apply (Qmult_le_r _ _ _ (grid_pos k)).
  rewrite grid_scale. apply Qfloor_le.
Qed.

Lemma gup_ge k a : Q2R a <= Q2R (gup k a).
Proof.
  apply Qle_Rle. unfold gup. apply (Qmult_le_r _ _ _ (grid_pos k)).
  rewrite grid_scale. apply Qle_ceiling.
Qed.

Lemma grid_box_in k B p : in_box B p -> in_box (grid_box k B) p.
Proof.
  intros HB j. pose proof (HB j) as H. unfold grid_box.
  destruct (Nat.lt_ge_cases j (length B)) as [Hj|Hj].
  - rewrite (nth_indep _ zero_iv (gdown k (fst zero_iv), gup k (snd zero_iv)))
      by (rewrite map_length; exact Hj).
    rewrite (map_nth (fun b => (gdown k (fst b), gup k (snd b)))).
    unfold in_iv in *. cbn [fst snd]. destruct H as [H1 H2].
    split; [eapply Rle_trans; [apply gdown_le|exact H1]|eapply Rle_trans; [exact H2|apply gup_ge]].
  - rewrite nth_overflow by (rewrite map_length; exact Hj).
    rewrite nth_overflow in H by exact Hj. exact H.
Qed.

Fixpoint set_nth (B : list iv) (k : nat) (x : iv) : list iv :=
  match B, k with
  | nil, _ => nil
  | _ :: B', O => x :: B'
  | b :: B', S k' => b :: set_nth B' k' x
  end.

Lemma nth_set_nth B k x j : (k < length B)%nat ->
  nth j (set_nth B k x) zero_iv = if Nat.eqb j k then x else nth j B zero_iv.
Proof.
  revert k j. induction B as [|b B IH]; intros k j Hk; simpl in Hk; [lia|].
  destruct k as [|k], j as [|j]; simpl; try reflexivity. apply IH. lia.
Qed.

Fixpoint check_tree (ok : list iv -> rleaf -> bool) (B : list iv) (t : rtree) : bool :=
  match t with
  | RLeaf l => ok B l
  | RSplit k l r =>
      let b := nth k B zero_iv in
      Nat.ltb k (length B) && check_tree ok (set_nth B k (fst b, mid b)) l
      && check_tree ok (set_nth B k (mid b, snd b)) r
  | RGrid k' t' => check_tree ok (grid_box k' B) t'
  end.

(** The leaves cover the box: a property every leaf's box gives holds on the whole box. *)
Theorem tree_sound (ok : list iv -> rleaf -> bool) (p : nat -> R) (P : Prop) :
  (forall B l, ok B l = true -> in_box B p -> P) ->
  forall t B, check_tree ok B t = true -> in_box B p -> P.
Proof.
  intros Hleaf t. induction t as [l|k l IHl r IHr|g t IH]; intros B Hc HB; simpl in Hc.
  - exact (Hleaf B l Hc HB).
  - rewrite !andb_true_iff in Hc. destruct Hc as [[Hk Hl] Hr]. apply Nat.ltb_lt in Hk.
    pose proof (HB k) as Hpk. unfold in_iv in Hpk.
    destruct (Rle_dec (p k) (Q2R (mid (nth k B zero_iv)))) as [Hle|Hgt].
    + apply (IHl _ Hl). intros j. rewrite nth_set_nth by exact Hk.
      destruct (Nat.eqb_spec j k) as [->|_]; [unfold in_iv; cbn [fst snd]; lra|apply HB].
    + apply (IHr _ Hr). intros j. rewrite nth_set_nth by exact Hk.
      destruct (Nat.eqb_spec j k) as [->|_]; [unfold in_iv; cbn [fst snd]; lra|apply HB].
  - exact (IH _ Hc (grid_box_in g B p HB)).
Qed.

Definition pos_ok (I : iv) (c : Q) : bool := negb (Qle_bool c 0) && Qle_bool c (fst I).

Lemma pos_ok_sound I c v : pos_ok I c = true -> in_iv I v -> 0 < v.
Proof.
  unfold pos_ok, in_iv. rewrite andb_true_iff. intros [H1 H2] Hv.
  apply Qlt_of_negb in H1. apply Qle_bool_R in H2. rewrite Q2R_0 in H1. lra.
Qed.

(** The three enclosures of a positive leaf, N_1 and N_2 computed once: the same
    intervals as [eiv] of [n_expr 0], [n_expr 1] and [det_expr] ([pos_leaf_eiv]), since
    [det_expr] is built from [n_expr 0] and [n_expr 1]. *)
Definition pos_leaf (B : list iv) (T : iv) (c0 c1 c2 : Q) : bool :=
  let n0 := eiv B T (n_expr 0) in let n1 := eiv B T (n_expr 1) in
  let det := isub (iscale 4 (imul n0 n1))
                  (imul (isqr (nth 8 B zero_iv)) (imul (eiv B T (d_expr 0)) (eiv B T (d_expr 1)))) in
  pos_ok n0 c0 && pos_ok n1 c1 && pos_ok det c2.

Lemma pos_leaf_eiv B T c0 c1 c2 :
  pos_leaf B T c0 c1 c2 = pos_ok (eiv B T (n_expr 0)) c0 && pos_ok (eiv B T (n_expr 1)) c1
                          && pos_ok (eiv B T det_expr) c2.
Proof. reflexivity. Qed.

(** A leaf of a band certificate (the frequency t = w^2 is coordinate 9 of the box). *)
Definition band_leaf (Sg : matQ) (chi2 : Q) (phic : list Q) (B : list iv) (l : rleaf) : bool :=
  let T := nth 9 B zero_iv in
  match l with
  | RPos c0 c1 c2 => pos_leaf B T c0 c1 c2
  | RLin c0 c1 c2 s0 s1 s2 => lin_ok Sg chi2 phic B T (n_expr 0) c0 s0
                              && lin_ok Sg chi2 phic B T (n_expr 1) c1 s1
                              && lin_ok Sg chi2 phic B T det_expr c2 s2
  | ROut y => out_ok Sg chi2 phic B y
  | RLinY c0 c1 c2 s0 s1 s2 y0 y1 y2 => lin_leaf Sg chi2 phic B T c0 c1 c2 s0 s1 s2 y0 y1 y2
  | _ => false
  end.

(** A leaf of a refutation at the frequency w* (coordinate 9 is the point w*^2). *)
Definition refute_leaf (Sg : matQ) (chi2 : Q) (phic : list Q) (v1 v2 : Q) (B : list iv)
    (l : rleaf) : bool :=
  let T := nth 9 B zero_iv in
  let dpos := pos_ok (eiv B T (d_expr 0)) (fst (eiv B T (d_expr 0)))
              && pos_ok (eiv B T (d_expr 1)) (fst (eiv B T (d_expr 1))) in
  match l with
  | RNeg c => negb (Qle_bool 0 c) && Qle_bool (snd (eiv B T (g_expr v1 v2))) c && dpos
  | RNegLin c s => negb (Qle_bool 0 c) && dpos
                   && lin_ok Sg chi2 phic B T (EScale (-1) (g_expr v1 v2)) (Qopp c) s
  | _ => false
  end.

Definition root_box (thc r : list Q) : list iv :=
  map (fun k => (Qred (nth k (phicQ thc) 0%Q - nth k r 0%Q),
                 Qred (nth k (phicQ thc) 0%Q + nth k r 0%Q))) (seq 0 9).

Lemma root_box_in Si Sg eps ws thc chi2 r th x T :
  region_ok Si Sg eps ws = true -> encl_ok Sg chi2 r = true -> in_region Si thc chi2 th ->
  in_iv T x -> in_box (root_box thc r ++ [T]) (point th x).
Proof.
  intros Hreg Henc Hr HT k. unfold root_box.
  destruct (Nat.lt_ge_cases k 9) as [Hk|Hk].
  - rewrite app_nth1 by (rewrite map_length, seq_length; exact Hk).
    rewrite (nth_map_seq (fun k => (Qred (nth k (phicQ thc) 0%Q - nth k r 0%Q),
                                    Qred (nth k (phicQ thc) 0%Q + nth k r 0%Q)))) by exact Hk.
    pose proof (enclosure Si Sg eps ws thc chi2 r th k Hreg Henc Hr Hk) as H.
    assert (H' : - Q2R (nth k r 0%Q) <= phi th k - vecR (phicQ thc) k <= Q2R (nth k r 0%Q)).
    { destruct (Rcase_abs (phi th k - vecR (phicQ thc) k));
        [rewrite Rabs_left in H by lra|rewrite Rabs_right in H by lra]; lra. }
    clear H. unfold in_iv, point, vecR in *. cbn [fst snd].
    destruct (Nat.eqb_spec k 9); [lia|]. rewrite !Q2R_red, Q2R_minus, Q2R_plus. lra.
  - rewrite app_nth2 by (rewrite map_length, seq_length; exact Hk).
    rewrite map_length, seq_length. destruct (Nat.eq_dec k 9) as [->|Hne].
    + simpl. unfold point. simpl. exact HT.
    + rewrite nth_overflow by (simpl; lia). unfold point, phi, in_iv, zero_iv. cbn [fst snd].
      destruct (Nat.eqb_spec k 9); [lia|]. destruct (Nat.ltb_spec k 8); [lia|].
      destruct (Nat.eqb_spec k 8); [lia|]. rewrite Q2R_0. lra.
Qed.

(** ** The checks a unit runs, and their soundness *)

Definition robust_band_check (Si Sg : matQ) (eps : Q) (ws : list term) (thc : list Q)
    (chi2 : Q) (r : list Q) (w1 w2 : Q) (t : rtree) : bool :=
  region_ok Si Sg eps ws && encl_ok Sg chi2 r && Qle_bool 0 w1 && Qle_bool w1 w2
  && check_tree (band_leaf Sg chi2 (phicQ thc))
                (root_box thc r ++ [(Qred (w1 * w1), Qred (w2 * w2))]) t.

(** A passing check includes [Si Sg = I]: a unit checks it once, with the rest. *)
Lemma robust_band_check_inv Si Sg eps ws thc chi2 r w1 w2 t :
  robust_band_check Si Sg eps ws thc chi2 r w1 w2 t = true -> inv_check 10 Si Sg = true.
Proof. unfold robust_band_check, region_ok. rewrite !andb_true_iff. tauto. Qed.

(** Every model of the region is passive on [w1, w2]. *)
Theorem robust_band_sound Si Sg eps ws thc chi2 r w1 w2 t :
  robust_band_check Si Sg eps ws thc chi2 r w1 w2 t = true ->
  forall th, in_region Si thc chi2 th -> paper_band_passive th w1 w2.
Proof.
  unfold robust_band_check. rewrite !andb_true_iff.
  intros [[[[Hreg Henc] Hw1] Hw12] Ht] th Hr w Hw.
  apply Qle_bool_R in Hw1, Hw12. rewrite Q2R_0 in Hw1.
  set (x := w * w).
  assert (HT : in_iv (Qred (w1 * w1), Qred (w2 * w2)) x).
  { unfold in_iv, x. cbn [fst snd]. rewrite !Q2R_red, !Q2R_mult. split; nra. }
  pose proof (root_box_in Si Sg eps ws thc chi2 r th x _ Hreg Henc Hr HT) as Hroot.
  refine (tree_sound _ (point th x) _ _ t _ Ht Hroot). intros B l Hl HB.
  unfold band_leaf in Hl. cbv zeta in Hl.
  assert (HTx : in_iv (nth 9 B zero_iv) x).
  { pose proof (HB 9%nat) as H. unfold point in H. simpl in H. exact H. }
  destruct l; try discriminate; rewrite ?pos_leaf_eiv, ?lin_leaf_dir, ?andb_true_iff in Hl.
  - destruct Hl as [[H0 H1] H2]. apply psd_of_conditions.
    + exact (pos_ok_sound _ _ _ H0 (eiv_sound _ _ _ _ _ HB HTx)).
    + exact (pos_ok_sound _ _ _ H1 (eiv_sound _ _ _ _ _ HB HTx)).
    + exact (pos_ok_sound _ _ _ H2 (eiv_sound _ _ _ _ _ HB HTx)).
  - destruct Hl as [[H0 H1] H2]. apply psd_of_conditions.
    + exact (lin_ok_sound Si Sg eps ws thc chi2 B _ _ _ _ th x Hreg Hr H0 HB HTx).
    + exact (lin_ok_sound Si Sg eps ws thc chi2 B _ _ _ _ th x Hreg Hr H1 HB HTx).
    + exact (lin_ok_sound Si Sg eps ws thc chi2 B _ _ _ _ th x Hreg Hr H2 HB HTx).
  - exfalso. exact (out_ok_sound Si Sg eps ws thc chi2 B y th x Hreg Hr Hl HB).
  - destruct Hl as [[H0 H1] H2]. apply psd_of_conditions.
    + exact (lin_dir_ok_sound Si Sg eps ws thc chi2 B _ _ _ _ _ th x Hreg Hr H0 HB HTx).
    + exact (lin_dir_ok_sound Si Sg eps ws thc chi2 B _ _ _ _ _ th x Hreg Hr H1 HB HTx).
    + exact (lin_dir_ok_sound Si Sg eps ws thc chi2 B _ _ _ _ _ th x Hreg Hr H2 HB HTx).
Qed.

Definition robust_refutation_check (Si Sg : matQ) (eps : Q) (ws : list term) (thc : list Q)
    (chi2 : Q) (r : list Q) (w1 w2 ws_ v1 v2 : Q) (t : rtree) : bool :=
  region_ok Si Sg eps ws && encl_ok Sg chi2 r && Qle_bool w1 ws_ && Qle_bool ws_ w2
  && check_tree (refute_leaf Sg chi2 (phicQ thc) v1 v2)
                (root_box thc r ++ [(Qred (ws_ * ws_), Qred (ws_ * ws_))]) t.

Lemma robust_refutation_check_inv Si Sg eps ws thc chi2 r w1 w2 ws_ v1 v2 t :
  robust_refutation_check Si Sg eps ws thc chi2 r w1 w2 ws_ v1 v2 t = true ->
  inv_check 10 Si Sg = true.
Proof. unfold robust_refutation_check, region_ok. rewrite !andb_true_iff. tauto. Qed.

(** No model of the region is passive on [w1, w2]: each fails at w*. *)
Theorem robust_refutation_sound Si Sg eps ws thc chi2 r w1 w2 ws_ v1 v2 t :
  robust_refutation_check Si Sg eps ws thc chi2 r w1 w2 ws_ v1 v2 t = true ->
  forall th, in_region Si thc chi2 th -> ~ paper_band_passive th w1 w2.
Proof.
  unfold robust_refutation_check. rewrite !andb_true_iff.
  intros [[[[Hreg Henc] Hw1] Hw2] Ht] th Hr Hpass.
  apply Qle_bool_R in Hw1, Hw2.
  set (w := Q2R ws_). set (x := w * w).
  assert (HT : in_iv (Qred (ws_ * ws_), Qred (ws_ * ws_)) x).
  { unfold in_iv, x, w. cbn [fst snd]. rewrite !Q2R_red, !Q2R_mult. lra. }
  pose proof (root_box_in Si Sg eps ws thc chi2 r th x _ Hreg Henc Hr HT) as Hroot.
  refine (tree_sound _ (point th x) _ _ t _ Ht Hroot). intros B l Hl HB.
  unfold refute_leaf in Hl. cbv zeta in Hl.
  assert (HTx : in_iv (nth 9 B zero_iv) x).
  { pose proof (HB 9%nat) as H. unfold point in H. simpl in H. exact H. }
  assert (Hpsd : paper_psd_at th w) by (apply Hpass; unfold w; lra).
  destruct l; try discriminate; rewrite ?andb_true_iff in Hl.
  - destruct Hl as [[Hc Hg] [Hd0 Hd1]].
    apply Qlt_of_negb in Hc. apply Qle_bool_R in Hg. rewrite Q2R_0 in Hc.
    pose proof (eiv_sound _ _ _ _ (g_expr v1 v2) HB HTx) as G. unfold in_iv in G.
    assert (Hneg : ereal (point th x) x (g_expr v1 v2) < 0) by lra.
    exact (not_psd_of_direction th w v1 v2
             (pos_ok_sound _ _ _ Hd0 (eiv_sound _ _ _ _ _ HB HTx))
             (pos_ok_sound _ _ _ Hd1 (eiv_sound _ _ _ _ _ HB HTx)) Hneg Hpsd).
  - destruct Hl as [[Hc [Hd0 Hd1]] Hlin].
    pose proof (lin_ok_sound Si Sg eps ws thc chi2 B _ _ _ _ th x Hreg Hr Hlin HB HTx) as G.
    cbn [ereal] in G.
    assert (Hneg : ereal (point th x) x (g_expr v1 v2) < 0) by lra.
    exact (not_psd_of_direction th w v1 v2
             (pos_ok_sound _ _ _ Hd0 (eiv_sound _ _ _ _ _ HB HTx))
             (pos_ok_sound _ _ _ Hd1 (eiv_sound _ _ _ _ _ HB HTx)) Hneg Hpsd).

Qed.

(** ** Second-order denominators: the Hurwitz condition, proved once *)

(** s^2 + a1 s + a0 at a complex s = (x, y), with BandCert.v's [cmul] and [cadd]. *)
Definition quad_at (a1 a0 : R) (s : R * R) : R * R :=
  cadd (cmul s s) (cadd (cmul (a1, 0) s) (a0, 0)).

Lemma quad_at_zero a1 a0 x y :
  quad_at a1 a0 (x, y) = (0, 0) <-> x * x - y * y + a1 * x + a0 = 0 /\ y * (2 * x + a1) = 0.
Proof.
  unfold quad_at, cadd, cmul. cbn [fst snd]. rewrite pair_equal_spec.
  split; intros [H1 H2]; split; lra.
Qed.

Lemma quad_real_root a1 a0 : 0 <= a1 * a1 - 4 * a0 ->
  quad_at a1 a0 ((- a1 + sqrt (a1 * a1 - 4 * a0)) / 2, 0) = (0, 0).
Proof.
  intros Hd. apply quad_at_zero. pose proof (sqrt_sqrt _ Hd) as Hs. split; [nra|ring].
Qed.

(** s^2 + a1 s + a0 (a1, a0 real) has both roots in the open left half-plane iff
    a1 > 0 and a0 > 0: the Routh-Hurwitz condition of degree 2. *)
Theorem hurwitz2 a1 a0 :
  (forall s, quad_at a1 a0 s = (0, 0) -> fst s < 0) <-> 0 < a1 /\ 0 < a0.
Proof.
  split.
  - intros H.
    assert (Ha0 : 0 < a0).
    { destruct (Rlt_le_dec 0 a0) as [|Hle]; [assumption|exfalso].
      assert (Hd : 0 <= a1 * a1 - 4 * a0) by nra.
      pose proof (H _ (quad_real_root a1 a0 Hd)) as Hx. cbn [fst] in Hx.
      assert (Habs : Rabs a1 <= sqrt (a1 * a1 - 4 * a0)).
      { rewrite <- sqrt_Rsqr_abs. apply sqrt_le_1_alt. unfold Rsqr. lra. }
      pose proof (Rle_abs a1). lra. }
    split; [|exact Ha0].
    destruct (Rlt_le_dec 0 a1) as [|Hle]; [assumption|exfalso].
    destruct (Rle_lt_dec 0 (a1 * a1 - 4 * a0)) as [Hd|Hd].
    + pose proof (H _ (quad_real_root a1 a0 Hd)) as Hx. cbn [fst] in Hx.
      pose proof (sqrt_pos (a1 * a1 - 4 * a0)). lra.
    + assert (Hn : 0 <= 4 * a0 - a1 * a1) by lra.
      assert (Hz : quad_at a1 a0 (- a1 / 2, sqrt (4 * a0 - a1 * a1) / 2) = (0, 0)).
      { apply quad_at_zero. pose proof (sqrt_sqrt _ Hn) as Hs. split; [nra|field]. }
      pose proof (H _ Hz) as Hx. cbn [fst] in Hx. lra.
  - intros [Ha1 Ha0] [x y] Hz. apply quad_at_zero in Hz. destruct Hz as [H1 H2].
    cbn [fst]. destruct (Req_dec y 0) as [->|Hy].
    + nra.
    + apply Rmult_integral in H2. destruct H2 as [H2|H2]; [contradiction|lra].
Qed.

(** Over a box of coefficients: a lower bound a1 >= l1 > 0, a0 >= l0 > 0 makes every
    denominator of the box Hurwitz (the degree-2 case needs no Kharitonov premise). *)
Corollary hurwitz2_box (l1 l0 : Q) a1 a0 :
  (0 < l1)%Q -> (0 < l0)%Q -> Q2R l1 <= a1 -> Q2R l0 <= a0 ->
  forall s, quad_at a1 a0 s = (0, 0) -> fst s < 0.
Proof.
  intros H1 H0 L1 L0. apply hurwitz2.
  apply Qlt_Rlt in H1, H0. rewrite Q2R_0 in H1, H0. lra.
Qed.
