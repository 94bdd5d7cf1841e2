(** * QCert: rational matrices, the KYP matrix, and definiteness from exact witnesses

    For the certificates of the paper's Section 4: the human's model H is passive when
    its realisation has a KYP certificate P ([kyp_certified]), and passive on a band
    when it has a generalized KYP certificate ([gkyp_certified]).

    Matrices are data: lists of rows of rationals [Q].  Products, transposes and the
    KYP matrix of the positive-real lemma are computed by Coq from that data.  What a
    reader audits are the definitions [qform], [pos_def], [neg_semidef] and [kyp]
    below: a matrix is positive definite when its quadratic form over the *reals* is
    positive at every non-zero real vector.

    A certificate proves such a statement from a witness: a shift [eps], a list of
    weighted vectors [(d_k, l_k)] and nothing else.  Coq computes the residual
    [R = M - eps I - sum_k d_k l_k l_k^T] itself and checks, by computation on [Q],
    that every [d_k >= 0] and that [R] is diagonally dominant in the sense
    [R_ii >= 1/2 sum_(j <> i) (|R_ij| + |R_ji|)].  The lemma [psd_check_sound],
    proved once here, turns a successful check into
    [x^T M x >= eps |x|^2] for every real [x].  An exact LDL^T factor is the witness
    with [R = 0]; a rounded Cholesky factor with a small dominant residual is another.
    No axiom is added: only Coq's standard axioms of the reals are used. *)

From Coq Require Import QArith Qabs Qreals Reals List Lra Lia.
Import ListNotations.

(** ** Matrices as data *)

Definition matQ := list (list Q).

(** The entry in row [i], column [j] (0 outside the data). *)
Definition entry (M : matQ) (i j : nat) : Q := nth j (nth i M nil) 0%Q.

(** Exact arithmetic on [Q] with shortcuts for speed: [qadd a b == a + b] and
    [qmul a b = a * b] (lemmas [Q2R_qadd], [Q2R_qmul] below).  Fractions are not reduced:
    the exporter writes each matrix over one common denominator (or two, for short and
    long entries), so that the terms of a sum share theirs and are added by their
    numerators; every product, in [qadd] too, multiplies the shorter number into the
    longer ([Pos.mul] costs the length of its first argument times the result's). *)
Definition pmul (x y : positive) : positive :=
  if Pos.leb (Pos.size x) (Pos.size y) then Pos.mul x y else Pos.mul y x.
Definition zmul (x y : Z) : Z :=
  match x, y with
  | Z0, _ | _, Z0 => Z0
  | Zpos a, Zpos b | Zneg a, Zneg b => Zpos (pmul a b)
  | Zpos a, Zneg b | Zneg a, Zpos b => Zneg (pmul a b)
  end.
Definition qmul (a b : Q) : Q := Qmake (zmul (Qnum a) (Qnum b)) (pmul (Qden a) (Qden b)).
Definition qadd (a b : Q) : Q :=
  if Z.eqb (Qnum a) 0 then b else if Z.eqb (Qnum b) 0 then a
  else if Pos.eqb (Qden a) (Qden b) then Qmake (Qnum a + Qnum b) (Qden a)
  else Qmake (zmul (Qnum a) (Zpos (Qden b)) + zmul (Qnum b) (Zpos (Qden a)))
             (pmul (Qden a) (Qden b)).

Fixpoint zipw (f : Q -> Q -> Q) (u v : list Q) : list Q :=
  match u, v with
  | a :: u', b :: v' => f a b :: zipw f u' v'
  | _, _ => nil
  end.

Fixpoint dot_plain (u v : list Q) : Q :=
  match u, v with
  | a :: u', b :: v' => qadd (qmul a b) (dot_plain u' v')
  | _, _ => 0%Q
  end.

Fixpoint same_den (d : positive) (u : list Q) : bool :=
  match u with nil => true | a :: u' => Pos.eqb (Qden a) d && same_den d u' end.

Fixpoint dot_num (u v : list Q) : Z :=
  match u, v with
  | a :: u', b :: v' => (zmul (Qnum a) (Qnum b) + dot_num u' v')%Z
  | _, _ => 0%Z
  end.

(** Bins of a sum: [(d1, d2, s)] stands for [s / (d1 d2)].  A product of entries with
    denominators [d1] and [d2] adds its numerator to the bin of [(d1, d2)], so that a
    sum whose terms have a few distinct denominators (a matrix written over one
    denominator per group of entries) is a few sums of numerators (lemma [Q2R_dot_bins]). *)
Definition bin := (positive * positive * Z)%type.

Fixpoint bin_add (d1 d2 : positive) (z : Z) (bs : list bin) : list bin :=
  match bs with
  | nil => [(d1, d2, z)]
  | (e1, e2, s) :: bs' =>
      if Pos.eqb e1 d1 && Pos.eqb e2 d2 then (e1, e2, (s + z)%Z) :: bs'
      else (e1, e2, s) :: bin_add d1 d2 z bs'
  end.

Fixpoint dot_bins (u v : list Q) (bs : list bin) : list bin :=
  match u, v with
  | a :: u', b :: v' => dot_bins u' v' (bin_add (Qden a) (Qden b) (zmul (Qnum a) (Qnum b)) bs)
  | _, _ => bs
  end.

Fixpoint bins_sum (bs : list bin) : Q :=
  match bs with
  | nil => 0%Q
  | (d1, d2, s) :: bs' => qadd (Qmake s (pmul d1 d2)) (bins_sum bs')
  end.

(** The dot product u . v (lemma [Q2R_dot]); when the entries of u share one
    denominator and those of v another, the numerators' products are summed once over
    the product of the two denominators; otherwise by bins of denominators. *)
Definition dot (u v : list Q) : Q :=
  match u, v with
  | a :: _, b :: _ =>
      if same_den (Qden a) u && same_den (Qden b) v
      then Qmake (dot_num u v) (pmul (Qden a) (Qden b)) else bins_sum (dot_bins u v nil)
  | _, _ => 0%Q
  end.

Definition ncols (M : matQ) : nat := length (hd nil M).

(** Transpose, product, sum, difference, negation, and 2x2 blocks. *)
Definition tr (M : matQ) : matQ :=
  map (fun j => map (fun row => nth j row 0%Q) M) (seq 0 (ncols M)).
Definition mmul (A B : matQ) : matQ :=
  let Bt := tr B in map (fun row => map (fun col => dot row col) Bt) A.
Fixpoint madd (A B : matQ) : matQ :=
  match A, B with
  | r :: A', s :: B' => zipw qadd r s :: madd A' B'
  | _, _ => nil
  end.
Definition mneg (A : matQ) : matQ := map (map Qopp) A.
Definition msub (A B : matQ) : matQ := madd A (mneg B).
Fixpoint hcat (A B : matQ) : matQ :=
  match A, B with
  | r :: A', s :: B' => (r ++ s) :: hcat A' B'
  | _, _ => nil
  end.
Definition block (TL TR BL BR : matQ) : matQ := hcat TL TR ++ hcat BL BR.

(** The KYP matrix of the positive-real lemma for x' = A x + B u, y = C x + D u:
    M(P) = [[A^T P + P A, P B - C^T], [B^T P - C, -(D + D^T)]]. *)
Definition kyp (A B C D P : matQ) : matQ :=
  block (madd (mmul (tr A) P) (mmul P A)) (msub (mmul P B) (tr C))
        (msub (mmul (tr B) P) C) (mneg (madd D (tr D))).

(** [M] has [r] rows of [c] entries each. *)
Definition has_shape (r c : nat) (M : matQ) : Prop :=
  length M = r /\ Forall (fun row => length row = c) M.

Definition has_shape_b (r c : nat) (M : matQ) : bool :=
  Nat.eqb (length M) r && forallb (fun row => Nat.eqb (length row) c) M.

Lemma has_shape_b_sound r c M : has_shape_b r c M = true -> has_shape r c M.
Proof.
  unfold has_shape_b, has_shape. rewrite andb_true_iff, Nat.eqb_eq, forallb_forall.
  intros [H1 H2]. split; [exact H1|]. apply Forall_forall. intros row Hin.
  apply Nat.eqb_eq, H2, Hin.
Qed.

(** ** What the certificates state, over the reals *)

Open Scope R_scope.

Fixpoint sumR (n : nat) (f : nat -> R) : R :=
  match n with O => 0 | S k => sumR k f + f k end.

(** x^T M x for a real vector x of length n (x given by its coordinates). *)
Definition qform (n : nat) (M : matQ) (x : nat -> R) : R :=
  sumR n (fun i => sumR n (fun j => Q2R (entry M i j) * (x i * x j))).

Definition nonzero (n : nat) (x : nat -> R) : Prop := exists i, (i < n)%nat /\ x i <> 0.

(** M = M^T (as an n x n matrix of rationals). *)
Definition symmetric (n : nat) (M : matQ) : Prop :=
  forall i j, (i < n)%nat -> (j < n)%nat -> (entry M i j == entry M j i)%Q.

(** M > 0: x^T M x > 0 for every real x <> 0. *)
Definition pos_def (n : nat) (M : matQ) : Prop :=
  forall x, nonzero n x -> 0 < qform n M x.

(** M >= 0 and M <= 0 as quadratic forms over the reals. *)
Definition pos_semidef (n : nat) (M : matQ) : Prop := forall x, 0 <= qform n M x.
Definition neg_semidef (n : nat) (M : matQ) : Prop := forall x, qform n M x <= 0.

(** ** Finite sums *)

Lemma sumR_ext n f g : (forall i, (i < n)%nat -> f i = g i) -> sumR n f = sumR n g.
Proof.
  induction n; intros H; simpl; [reflexivity|].
  rewrite IHn by (intros; apply H; lia). rewrite H by lia. reflexivity.
Qed.

Lemma sumR_plus n f g : sumR n (fun i => f i + g i) = sumR n f + sumR n g.
Proof. induction n; simpl; [lra|]. rewrite IHn. lra. Qed.

Lemma sumR_scal n c f : sumR n (fun i => c * f i) = c * sumR n f.
Proof. induction n; simpl; [lra|]. rewrite IHn. lra. Qed.

Lemma sumR_opp n f : sumR n (fun i => - f i) = - sumR n f.
Proof. induction n; simpl; [lra|]. rewrite IHn. lra. Qed.

Lemma sumR_zero n : sumR n (fun _ => 0) = 0.
Proof. induction n; simpl; [lra|]. rewrite IHn. lra. Qed.

Lemma sumR_le n f g : (forall i, (i < n)%nat -> f i <= g i) -> sumR n f <= sumR n g.
Proof.
  induction n; intros H; simpl; [lra|].
  apply Rplus_le_compat; [apply IHn; intros; apply H; lia | apply H; lia].
Qed.

Lemma sumR_nonneg n f : (forall i, (i < n)%nat -> 0 <= f i) -> 0 <= sumR n f.
Proof. intros H. rewrite <- (sumR_zero n). apply sumR_le. exact H. Qed.

Lemma sumR_pos n f k :
  (forall i, (i < n)%nat -> 0 <= f i) -> (k < n)%nat -> 0 < f k -> 0 < sumR n f.
Proof.
  induction n; intros H Hk Hf; [lia|]. simpl.
  destruct (Nat.eq_dec k n) as [->|Hne].
  - pose proof (sumR_nonneg n f (fun i Hi => H i ltac:(lia))). lra.
  - pose proof (H n ltac:(lia)). pose proof (IHn (fun i Hi => H i ltac:(lia)) ltac:(lia) Hf).
    lra.
Qed.

Lemma sumR_swap n m (f : nat -> nat -> R) :
  sumR n (fun i => sumR m (fun j => f i j)) = sumR m (fun j => sumR n (fun i => f i j)).
Proof.
  induction n; simpl.
  - rewrite sumR_zero. reflexivity.
  - rewrite IHn, <- sumR_plus. reflexivity.
Qed.

(** Splitting off the diagonal term: [delta i j] is 1 on the diagonal, 0 elsewhere. *)
Definition offd (i j : nat) (r : R) : R := if Nat.eqb i j then 0 else r.

Lemma sumR_split n i f :
  (i < n)%nat -> sumR n f = f i + sumR n (fun j => offd i j (f j)).
Proof.
  unfold offd. induction n; intros Hi; [lia|]. simpl.
  destruct (Nat.eq_dec i n) as [->|Hne].
  - rewrite Nat.eqb_refl.
    rewrite (sumR_ext n (fun j => if Nat.eqb n j then 0 else f j) f).
    + lra.
    + intros j Hj. destruct (Nat.eqb_spec n j); [lia|reflexivity].
  - rewrite IHn by lia. apply Nat.eqb_neq in Hne. rewrite Hne. lra.
Qed.

(** Sums over a list of witness terms. *)
Fixpoint lsum {T : Type} (ws : list T) (g : T -> R) : R :=
  match ws with nil => 0 | w :: ws' => g w + lsum ws' g end.

Lemma sumR_lsum {T : Type} n (ws : list T) (g : nat -> T -> R) :
  sumR n (fun i => lsum ws (g i)) = lsum ws (fun w => sumR n (fun i => g i w)).
Proof.
  induction ws as [|w ws IH]; simpl.
  - apply sumR_zero.
  - rewrite sumR_plus, IH. reflexivity.
Qed.

Lemma lsum_ext {T : Type} (ws : list T) g h :
  (forall w, g w = h w) -> lsum ws g = lsum ws h.
Proof. intros H. induction ws; simpl; [reflexivity|]. rewrite H, IHws. reflexivity. Qed.

Lemma lsum_nonneg {T : Type} (ws : list T) g :
  (forall w, In w ws -> 0 <= g w) -> 0 <= lsum ws g.
Proof.
  induction ws as [|w ws IH]; intros H; simpl; [lra|].
  pose proof (H w (or_introl eq_refl)). pose proof (IH (fun v Hv => H v (or_intror Hv))).
  lra.
Qed.

(** ** Gershgorin: a diagonally dominant matrix has a non-negative quadratic form *)

Lemma offdiag_bound a xi xj :
  -(Rabs a * (xi * xi + xj * xj) / 2) <= a * (xi * xj).
Proof.
  destruct (Rcase_abs a) as [Ha|Ha];
    [rewrite Rabs_left by exact Ha | rewrite Rabs_right by exact Ha].
  - assert (0 <= (- a) * ((xi - xj) * (xi - xj)))
      by (apply Rmult_le_pos; [lra | apply Rle_0_sqr]).
    lra.
  - assert (0 <= a * ((xi + xj) * (xi + xj)))
      by (apply Rmult_le_pos; [lra | apply Rle_0_sqr]).
    lra.
Qed.

Lemma sumR_scal_r n f c : sumR n (fun j => f j * c) = sumR n f * c.
Proof. induction n; simpl; [lra|]. rewrite IHn. lra. Qed.

Lemma sumR_comb n f g h a b :
  sumR n (fun i => f i + a * g i + b * h i) = sumR n f + a * sumR n g + b * sumR n h.
Proof. rewrite !sumR_plus, !sumR_scal. reflexivity. Qed.

Lemma gershgorin n (r : nat -> nat -> R) (x : nat -> R) :
  (forall i, (i < n)%nat ->
     sumR n (fun j => offd i j (Rabs (r i j) + Rabs (r j i))) / 2 <= r i i) ->
  0 <= sumR n (fun i => sumR n (fun j => r i j * (x i * x j))).
Proof.
  intros Hdom.
  pose (c i j := offd i j (Rabs (r i j))).
  pose (S1 i := sumR n (fun j => c i j * (x i * x i))).
  pose (S2 i := sumR n (fun j => c i j * (x j * x j))).
  pose (S3 i := sumR n (fun j => c j i * (x i * x i))).
  (* each row: its off-diagonal part is at least -1/2 sum_j c_ij (x_i^2 + x_j^2) *)
  assert (Hrow : forall i, (i < n)%nat ->
            r i i * (x i * x i) + (-/2) * S1 i + (-/2) * S2 i
            <= sumR n (fun j => r i j * (x i * x j))).
  { intros i Hi. rewrite (sumR_split n i (fun j => r i j * (x i * x j))) by exact Hi.
    assert (E : (-/2) * S1 i + (-/2) * S2 i
                = sumR n (fun j => 0 + (-/2) * (c i j * (x i * x i))
                                     + (-/2) * (c i j * (x j * x j)))).
    { rewrite sumR_comb, sumR_zero. unfold S1, S2. lra. }
    assert (sumR n (fun j => 0 + (-/2) * (c i j * (x i * x i)) + (-/2) * (c i j * (x j * x j)))
            <= sumR n (fun j => offd i j (r i j * (x i * x j)))).
    { apply sumR_le. intros j _. unfold c, offd. destruct (Nat.eqb i j).
      - lra.
      - pose proof (offdiag_bound (r i j) (x i) (x j)). lra. }
    lra. }
  eapply Rle_trans; [|apply sumR_le; exact Hrow].
  rewrite sumR_comb.
  assert (H2 : sumR n S2 = sumR n S3)
    by exact (sumR_swap n n (fun i j => c i j * (x j * x j))).
  rewrite H2, <- sumR_comb.
  apply sumR_nonneg. intros i Hi.
  assert (Hc : sumR n (fun j => offd i j (Rabs (r i j) + Rabs (r j i)))
               = sumR n (fun j => c i j) + sumR n (fun j => c j i)).
  { rewrite <- sumR_plus. apply sumR_ext. intros j _. unfold c, offd.
    rewrite (Nat.eqb_sym j i). destruct (Nat.eqb i j); lra. }
  pose proof (Hdom i Hi) as Hd. rewrite Hc in Hd.
  assert (E1 : S1 i = sumR n (fun j => c i j) * (x i * x i)) by apply sumR_scal_r.
  assert (E3 : S3 i = sumR n (fun j => c j i) * (x i * x i)) by apply sumR_scal_r.
  cbv beta. rewrite E1, E3.
  assert (0 <= x i * x i) by apply Rle_0_sqr.
  assert (0 <= x i * x i * (r i i - (sumR n (fun j => c i j) + sumR n (fun j => c j i)) / 2))
    by (apply Rmult_le_pos; lra).
  lra.
Qed.

(** ** From rationals to reals *)

Lemma Q2R_zero : Q2R 0 = 0.
Proof. unfold Q2R. simpl. lra. Qed.

Lemma Q2R_red q : Q2R (Qred q) = Q2R q.
Proof. apply Qeq_eqR, Qred_correct. Qed.

Lemma Q2R_num0 d : Q2R (Qmake 0 d) = 0.
Proof. unfold Q2R. simpl. ring. Qed.

Lemma pmul_mul x y : pmul x y = Pos.mul x y.
Proof. unfold pmul. destruct (Pos.leb _ _); [reflexivity | apply Pos.mul_comm]. Qed.

Lemma zmul_mul x y : zmul x y = Z.mul x y.
Proof. destruct x, y; simpl; rewrite ?pmul_mul; reflexivity. Qed.

Lemma Q2R_qadd a b : Q2R (qadd a b) = Q2R a + Q2R b.
Proof.
  destruct a as [na da], b as [nb db]. unfold qadd. simpl.
  destruct (Z.eqb_spec na 0) as [->|Ha]; [rewrite Q2R_num0; ring|].
  destruct (Z.eqb_spec nb 0) as [->|Hb]; [rewrite Q2R_num0; ring|].
  destruct (Pos.eqb_spec da db) as [<-|Hd].
  - unfold Q2R. simpl. rewrite plus_IZR. ring.
  - rewrite !zmul_mul, pmul_mul. exact (Q2R_plus (na # da) (nb # db)).
Qed.

Lemma Q2R_qmul a b : Q2R (qmul a b) = Q2R a * Q2R b.
Proof.
  unfold qmul. rewrite zmul_mul, pmul_mul. apply Q2R_mult.
Qed.

Fixpoint dotR (u v : list Q) : R :=
  match u, v with
  | a :: u', b :: v' => Q2R a * Q2R b + dotR u' v'
  | _, _ => 0
  end.

Lemma Q2R_dot_plain u v : Q2R (dot_plain u v) = dotR u v.
Proof.
  revert v. induction u as [|a u IH]; intros [|b v]; simpl; try apply Q2R_zero.
  rewrite Q2R_qadd, Q2R_qmul, IH. reflexivity.
Qed.

Lemma Q2R_dot_num du dv u v :
  same_den du u = true -> same_den dv v = true ->
  Q2R (Qmake (dot_num u v) (pmul du dv)) = dotR u v.
Proof.
  revert v. induction u as [|[na da] u IH]; intros [|[nb db] v] Hu Hv; simpl;
    try apply Q2R_num0.
  simpl in Hu, Hv. apply andb_true_iff in Hu as [Hu Hu']. apply andb_true_iff in Hv as [Hv Hv'].
  apply Pos.eqb_eq in Hu. apply Pos.eqb_eq in Hv. subst.
  rewrite <- (IH v Hu' Hv'). rewrite zmul_mul, pmul_mul.
  unfold Q2R. simpl. rewrite plus_IZR, mult_IZR, Pos2Z.inj_mul, mult_IZR. field.
  split; apply not_0_IZR; discriminate.
Qed.

Lemma Q2R_bin_add d1 d2 z bs :
  Q2R (bins_sum (bin_add d1 d2 z bs)) = Q2R (bins_sum bs) + Q2R (Qmake z (pmul d1 d2)).
Proof.
  induction bs as [|[[e1 e2] s] bs IH]; simpl.
  - rewrite Q2R_qadd, Q2R_zero. ring.
  - destruct (Pos.eqb_spec e1 d1) as [->|_]; simpl;
      [destruct (Pos.eqb_spec e2 d2) as [->|_]; simpl|].
    + rewrite !Q2R_qadd. unfold Q2R. simpl. rewrite plus_IZR. ring.
    + rewrite !Q2R_qadd, IH. ring.
    + rewrite !Q2R_qadd, IH. ring.
Qed.

Lemma Q2R_dot_bins u v bs :
  Q2R (bins_sum (dot_bins u v bs)) = Q2R (bins_sum bs) + dotR u v.
Proof.
  revert v bs. induction u as [|a u IH]; intros [|b v] bs; simpl; try ring.
  rewrite IH, Q2R_bin_add.
  change (Qmake (zmul (Qnum a) (Qnum b)) (pmul (Qden a) (Qden b))) with (qmul a b).
  rewrite Q2R_qmul. ring.
Qed.

Lemma Q2R_dot u v : Q2R (dot u v) = dotR u v.
Proof.
  destruct u as [|a u'], v as [|b v']; try apply Q2R_zero.
  unfold dot. destruct (same_den (Qden a) (a :: u') && same_den (Qden b) (b :: v')) eqn:H.
  - apply andb_true_iff in H as [Hu Hv]. apply Q2R_dot_num; assumption.
  - rewrite Q2R_dot_bins. simpl. rewrite Q2R_zero. ring.
Qed.

Lemma Q2R_Qabs q : Q2R (Qabs q) = Rabs (Q2R q).
Proof.
  destruct q as [a b]. unfold Q2R, Qabs. simpl. rewrite Rabs_mult, abs_IZR.
  f_equal. rewrite Rabs_right; [reflexivity|].
  apply Rle_ge, Rlt_le, Rinv_0_lt_compat, IZR_lt. lia.
Qed.

Lemma Qle_bool_R a b : Qle_bool a b = true -> Q2R a <= Q2R b.
Proof. intros H. apply Qle_Rle, Qle_bool_imp_le, H. Qed.

Lemma forallb_seq (p : nat -> bool) n :
  forallb p (seq 0 n) = true -> forall i, (i < n)%nat -> p i = true.
Proof.
  rewrite forallb_forall. intros H i Hi. apply H, in_seq. lia.
Qed.

(** ** Witnesses, re-checked by computation on Q *)

(** A witness term (d, l) stands for d l l^T. *)
Definition term := (Q * list Q)%type.

Fixpoint termsQ (ws : list term) (i j : nat) : Q :=
  match ws with
  | nil => 0%Q
  | (d, l) :: ws' => qadd (qmul d (qmul (nth i l 0%Q) (nth j l 0%Q))) (termsQ ws' i j)
  end.

Definition delta (eps : Q) (i j : nat) : Q := if Nat.eqb i j then eps else 0%Q.

(** R = M - eps I - sum_k d_k l_k l_k^T, entry by entry. *)
Definition resid (M : matQ) (eps : Q) (ws : list term) (i j : nat) : Q :=
  qadd (entry M i j) (Qopp (qadd (delta eps i j) (termsQ ws i j))).

Fixpoint sumQ (n : nat) (f : nat -> Q) : Q :=
  match n with O => 0%Q | S k => qadd (sumQ k f) (f k) end.

Definition offdQ (i j : nat) (q : Q) : Q := if Nat.eqb i j then 0%Q else q.

(** The sum f 0 + ... + f (n - 1) by bins of denominators (lemma [Q2R_sumQb]): the
    terms of a row of a residual have a few distinct denominators. *)
Fixpoint sum_bins (n : nat) (f : nat -> Q) (bs : list bin) : list bin :=
  match n with O => bs | S k => sum_bins k f (bin_add (Qden (f k)) 1 (Qnum (f k)) bs) end.

Definition sumQb (n : nat) (f : nat -> Q) : Q := bins_sum (sum_bins n f nil).

(** Every row i of r: sum_(j <> i) (|r_ij| + |r_ji|) <= 2 r_ii. *)
Definition dominant (n : nat) (r : nat -> nat -> Q) : bool :=
  forallb (fun i => Qle_bool (sumQb n (fun j => offdQ i j (qadd (Qabs (r i j)) (Qabs (r j i)))))
                             (2 * r i i)) (seq 0 n).

(** The n x n matrix of the entries [f i j], computed once (the check reads each
    residual entry twice: lemma [entry_tabulate]). *)
Definition tabulate (n : nat) (f : nat -> nat -> Q) : matQ :=
  map (fun i => map (fun j => f i j) (seq 0 n)) (seq 0 n).

Definition psd_check (n : nat) (M : matQ) (eps : Q) (ws : list term) : bool :=
  Qle_bool 0 eps && forallb (fun w => Qle_bool 0 (fst w)) ws
  && dominant n (entry (tabulate n (resid M eps ws))).

Lemma entry_tabulate n f i j :
  (i < n)%nat -> (j < n)%nat -> entry (tabulate n f) i j = f i j.
Proof.
  intros Hi Hj. unfold entry, tabulate.
  rewrite (nth_indep _ nil (map (fun j => f i j) (seq 0 n)))
    by (rewrite map_length, seq_length; exact Hi).
  rewrite (map_nth (fun i => map (fun j => f i j) (seq 0 n))), seq_nth by exact Hi.
  rewrite (nth_indep _ 0%Q (f i 0%nat)) by (rewrite map_length, seq_length; exact Hj).
  rewrite (map_nth (fun j => f i j)), seq_nth by exact Hj. reflexivity.
Qed.

Lemma sumQ_ext n f g : (forall j, (j < n)%nat -> f j = g j) -> sumQ n f = sumQ n g.
Proof.
  induction n; intros H; simpl; [reflexivity|].
  rewrite IHn by (intros; apply H; lia). rewrite H by lia. reflexivity.
Qed.

Lemma sumQb_ext n f g : (forall j, (j < n)%nat -> f j = g j) -> sumQb n f = sumQb n g.
Proof.
  unfold sumQb. generalize (@nil bin) as bs.
  induction n; intros bs H; simpl; [reflexivity|].
  rewrite H by lia. apply IHn. intros; apply H; lia.
Qed.

Lemma dominant_tabulate n r :
  dominant n (entry (tabulate n r)) = true -> dominant n r = true.
Proof.
  unfold dominant. rewrite !forallb_forall. intros H i Hin.
  pose proof (H i Hin) as Hi. apply in_seq in Hin.
  rewrite (entry_tabulate n r i i) in Hi by lia.
  rewrite (sumQb_ext n _ (fun j => offdQ i j (qadd (Qabs (r i j)) (Qabs (r j i))))) in Hi.
  - exact Hi.
  - intros j Hj. rewrite !entry_tabulate by lia. reflexivity.
Qed.

Definition pd_check (n : nat) (M : matQ) (eps : Q) (ws : list term) : bool :=
  negb (Qle_bool eps 0) && psd_check n M eps ws.

(** Equality of rationals; over one denominator, of their numerators. *)
Definition qeqb (a b : Q) : bool :=
  if Pos.eqb (Qden a) (Qden b) then Z.eqb (Qnum a) (Qnum b) else Qeq_bool a b.

Lemma qeqb_sound a b : qeqb a b = true -> (a == b)%Q.
Proof.
  destruct a as [na da], b as [nb db]. unfold qeqb. simpl.
  destruct (Pos.eqb_spec da db) as [<-|_].
  - intros H. apply Z.eqb_eq in H. subst. reflexivity.
  - apply Qeq_bool_iff.
Qed.

Definition sym_check (n : nat) (M : matQ) : bool :=
  forallb (fun i => forallb (fun j => qeqb (entry M i j) (entry M j i)) (seq 0 n))
          (seq 0 n).

Lemma Q2R_termsQ ws i j :
  Q2R (termsQ ws i j)
  = lsum ws (fun w => Q2R (fst w) * (Q2R (nth i (snd w) 0%Q) * Q2R (nth j (snd w) 0%Q))).
Proof.
  induction ws as [|[d l] ws IH]; simpl; [apply Q2R_zero|].
  rewrite Q2R_qadd, !Q2R_qmul, IH. reflexivity.
Qed.

Lemma Q2R_sumQ n f : Q2R (sumQ n f) = sumR n (fun j => Q2R (f j)).
Proof. induction n; simpl; [apply Q2R_zero|]. rewrite Q2R_qadd, IHn. reflexivity. Qed.

Lemma Q2R_sum_bins n f bs :
  Q2R (bins_sum (sum_bins n f bs)) = Q2R (bins_sum bs) + sumR n (fun j => Q2R (f j)).
Proof.
  revert bs. induction n; intros bs; simpl; [ring|].
  rewrite IHn, Q2R_bin_add, pmul_mul, Pos.mul_1_r.
  destruct (f n) as [a b]. simpl. ring.
Qed.

Lemma Q2R_sumQb n f : Q2R (sumQb n f) = sumR n (fun j => Q2R (f j)).
Proof. unfold sumQb. rewrite Q2R_sum_bins. simpl. rewrite Q2R_zero. ring. Qed.

Lemma lsum_scal_r {T : Type} (ws : list T) g c : lsum ws g * c = lsum ws (fun w => g w * c).
Proof. induction ws; simpl; [lra|]. rewrite <- IHws. lra. Qed.

Lemma qform_split n M eps ws x :
  qform n M x
  = sumR n (fun i => sumR n (fun j => Q2R (resid M eps ws i j) * (x i * x j)))
    + sumR n (fun i => sumR n (fun j => Q2R (delta eps i j) * (x i * x j)))
    + sumR n (fun i => sumR n (fun j => Q2R (termsQ ws i j) * (x i * x j))).
Proof.
  unfold qform. rewrite <- !sumR_plus. apply sumR_ext. intros i _.
  rewrite <- !sumR_plus. apply sumR_ext. intros j _.
  unfold resid. rewrite Q2R_qadd, Q2R_opp, Q2R_qadd. ring.
Qed.

Lemma delta_part n eps x :
  sumR n (fun i => sumR n (fun j => Q2R (delta eps i j) * (x i * x j)))
  = Q2R eps * sumR n (fun i => x i * x i).
Proof.
  rewrite <- sumR_scal. apply sumR_ext. intros i Hi.
  rewrite (sumR_split n i) by exact Hi. cbv beta.
  rewrite (sumR_ext n _ (fun _ => 0)), sumR_zero.
  - unfold delta. rewrite Nat.eqb_refl. ring.
  - intros j _. unfold offd, delta. destruct (Nat.eqb i j); [reflexivity|].
    rewrite Q2R_zero. ring.
Qed.

(** l . x, the linear form of a witness vector. *)
Definition lin (n : nat) (l : list Q) (x : nat -> R) : R :=
  sumR n (fun i => Q2R (nth i l 0%Q) * x i).

Lemma terms_part n ws x :
  sumR n (fun i => sumR n (fun j => Q2R (termsQ ws i j) * (x i * x j)))
  = lsum ws (fun w => Q2R (fst w) * (lin n (snd w) x * lin n (snd w) x)).
Proof.
  transitivity (sumR n (fun i => sumR n (fun j => lsum ws (fun w =>
     (Q2R (fst w) * (Q2R (nth i (snd w) 0%Q) * x i)) * (Q2R (nth j (snd w) 0%Q) * x j))))).
  { apply sumR_ext. intros i _. apply sumR_ext. intros j _.
    rewrite Q2R_termsQ, lsum_scal_r. apply lsum_ext. intros w. ring. }
  rewrite (sumR_ext n _ (fun i => lsum ws (fun w => sumR n (fun j =>
     (Q2R (fst w) * (Q2R (nth i (snd w) 0%Q) * x i)) * (Q2R (nth j (snd w) 0%Q) * x j)))))
    by (intros; apply sumR_lsum).
  rewrite sumR_lsum. apply lsum_ext. intros w. unfold lin.
  rewrite (sumR_ext n _ (fun i => (Q2R (fst w) * (Q2R (nth i (snd w) 0%Q) * x i))
                                  * sumR n (fun j => Q2R (nth j (snd w) 0%Q) * x j)))
    by (intros; apply sumR_scal).
  rewrite sumR_scal_r, sumR_scal. ring.
Qed.

(** The soundness of the check, proved once: x^T M x >= eps |x|^2 for every real x. *)
Theorem psd_check_sound n M eps ws :
  psd_check n M eps ws = true ->
  forall x, Q2R eps * sumR n (fun i => x i * x i) <= qform n M x.
Proof.
  unfold psd_check. rewrite !andb_true_iff. intros [[Heps Hws] Hdom] x.
  apply dominant_tabulate in Hdom.
  rewrite (qform_split n M eps ws x), delta_part, terms_part.
  assert (Ht : 0 <= lsum ws (fun w => Q2R (fst w) * (lin n (snd w) x * lin n (snd w) x))).
  { apply lsum_nonneg. intros w Hw. rewrite forallb_forall in Hws.
    apply Rmult_le_pos; [|apply Rle_0_sqr].
    rewrite <- Q2R_zero. apply Qle_bool_R, Hws, Hw. }
  assert (Hg : 0 <= sumR n (fun i => sumR n (fun j => Q2R (resid M eps ws i j) * (x i * x j)))).
  { apply (gershgorin n (fun i j => Q2R (resid M eps ws i j))). intros i Hi.
    pose proof (forallb_seq _ n Hdom i Hi) as H. apply Qle_bool_R in H.
    rewrite Q2R_sumQb, Q2R_mult in H.
    replace (Q2R 2) with 2 in H by (unfold Q2R; simpl; field).
    rewrite (sumR_ext n _ (fun j => Q2R (offdQ i j (qadd (Qabs (resid M eps ws i j))
                                                        (Qabs (resid M eps ws j i)))))).
    - lra.
    - intros j _. unfold offd, offdQ. destruct (Nat.eqb i j); [apply eq_sym, Q2R_zero|].
      rewrite Q2R_qadd, !Q2R_Qabs. reflexivity. }
  lra.
Qed.

Theorem pd_check_sound n M eps ws : pd_check n M eps ws = true -> pos_def n M.
Proof.
  unfold pd_check. rewrite andb_true_iff, negb_true_iff. intros [Heps Hc] x [k [Hk Hx]].
  assert (0 < Q2R eps).
  { rewrite <- Q2R_zero. apply Qlt_Rlt, Qnot_le_lt. intros Hle.
    apply Qle_bool_iff in Hle. congruence. }
  assert (0 < sumR n (fun i => x i * x i)).
  { apply (sumR_pos n _ k); [intros; apply Rle_0_sqr | exact Hk |].
    destruct (Rlt_dec 0 (x k)) as [Hp|Hp]; [nra|]. assert (x k < 0) by lra. nra. }
  pose proof (psd_check_sound n M eps ws Hc x). nra.
Qed.

Lemma entry_mneg M i j : entry (mneg M) i j = Qopp (entry M i j).
Proof.
  unfold entry, mneg. pose proof (map_nth (map Qopp) M nil i) as H. simpl in H.
  rewrite H. pose proof (map_nth Qopp (nth i M nil) 0%Q j) as H'. simpl in H'.
  exact H'.
Qed.

Theorem nsd_check_sound n M eps ws : psd_check n (mneg M) eps ws = true -> neg_semidef n M.
Proof.
  intros Hc x. pose proof (psd_check_sound n (mneg M) eps ws Hc x) as H.
  assert (0 <= Q2R eps * sumR n (fun i => x i * x i)).
  { apply Rmult_le_pos; [|apply sumR_nonneg; intros; apply Rle_0_sqr].
    unfold psd_check in Hc. rewrite !andb_true_iff in Hc. destruct Hc as [[He _] _].
    rewrite <- Q2R_zero. apply Qle_bool_R, He. }
  assert (qform n (mneg M) x = - qform n M x).
  { unfold qform. rewrite <- sumR_opp. apply sumR_ext. intros i _.
    rewrite <- sumR_opp. apply sumR_ext. intros j _.
    rewrite entry_mneg, Q2R_opp. ring. }
  lra.
Qed.

Theorem sym_check_sound n M : sym_check n M = true -> symmetric n M.
Proof.
  intros H i j Hi Hj. apply qeqb_sound.
  exact (forallb_seq _ n (forallb_seq _ n H i Hi) j Hj).
Qed.

(** ** Passivity in the LMI form of the KYP (positive-real) lemma *)

(** c I, the m x m identity scaled by c. *)
Definition scaled_identity (m : nat) (c : Q) : matQ :=
  map (fun i => map (fun j => if Nat.eqb i j then c else 0%Q) (seq 0 m)) (seq 0 m).

(** The realisation (A, B, C, D) of H, with n states and m ports, has a KYP certificate P:
    the shapes match, P = P^T, P > 0 and M(P) <= 0.  Then V(x) = x^T P x / 2 is a
    storage function, V' <= u^T y along x' = A x + B u, y = C x + D u, so H is passive. *)
Definition kyp_certified (n m : nat) (A B C D P : matQ) : Prop :=
  has_shape n n A /\ has_shape n m B /\ has_shape m n C /\ has_shape m m D
  /\ has_shape n n P /\ symmetric n P /\ pos_def n P /\ neg_semidef (n + m) (kyp A B C D P).

(** Everything [kyp_certified] asks, decided by one computation on the data and the
    witnesses (eP, wP) for P > 0 and (eM, wM) for -M(P) >= 0. *)
Definition kyp_check (n m : nat) (A B C D P : matQ) (eP : Q) (wP : list term)
    (eM : Q) (wM : list term) : bool :=
  has_shape_b n n A && has_shape_b n m B && has_shape_b m n C && has_shape_b m m D
  && has_shape_b n n P && sym_check n P && pd_check n P eP wP
  && psd_check (n + m) (mneg (kyp A B C D P)) eM wM.

Theorem kyp_check_sound n m A B C D P eP wP eM wM :
  kyp_check n m A B C D P eP wP eM wM = true -> kyp_certified n m A B C D P.
Proof.
  unfold kyp_check. rewrite !andb_true_iff.
  intros [[[[[[[HA HB] HC] HD] HP] Hs] Hpd] Hnsd].
  exact (conj (has_shape_b_sound _ _ _ HA) (conj (has_shape_b_sound _ _ _ HB)
    (conj (has_shape_b_sound _ _ _ HC) (conj (has_shape_b_sound _ _ _ HD)
    (conj (has_shape_b_sound _ _ _ HP) (conj (sym_check_sound n P Hs)
    (conj (pd_check_sound n P eP wP Hpd) (nsd_check_sound (n + m) _ eM wM Hnsd)))))))).
Qed.

(** ** Passivity on a band: the generalized KYP lemma (Iwasaki and Hara, IEEE TAC 2005) *)

Definition mscale (c : Q) (M : matQ) : matQ := map (map (qmul c)) M.
Definition zeros (r c : nat) : matQ := map (fun _ => map (fun _ => 0%Q) (seq 0 c)) (seq 0 r).

(** The real form [[Re, -Im], [Im, Re]] of the complex matrix Xr + j Xi: a Hermitian
    matrix is >= 0 exactly when its real form is. *)
Definition embed (Xr Xi : matQ) : matQ := block Xr (mneg Xi) Xi Xr.

(** L(P, Q) = N^H (Phi (x) P + Psi (x) Q) N + Theta for the band [w1, w2], with
    N = [[A, B], [I, 0]], Phi = [[0, 1], [1, 0]], Psi = [[-1, j wc], [-j wc, -w1 w2]],
    wc = (w1 + w2)/2 and Theta = -[[0, C^T], [C, D + D^T]]; its real and imaginary
    parts, for P = Pr + j Pi and Q = Qr + j Qi. *)
Definition gkyp_N (n m : nat) (A B : matQ) : matQ :=
  block A B (scaled_identity n 1) (zeros n m).
Definition gkyp_re (n m : nat) (A B C D Pr Pi Qr Qi : matQ) (w1 w2 : Q) : matQ :=
  let wc := ((w1 + w2) / 2)%Q in
  let N := gkyp_N n m A B in
  let Wr := block (mneg Qr) (msub Pr (mscale wc Qi)) (madd Pr (mscale wc Qi))
                  (mneg (mscale (w1 * w2) Qr)) in
  let Theta := block (zeros n n) (mneg (tr C)) (mneg C) (mneg (madd D (tr D))) in
  madd (mmul (mmul (tr N) Wr) N) Theta.
Definition gkyp_im (n m : nat) (A B C D Pr Pi Qr Qi : matQ) (w1 w2 : Q) : matQ :=
  let wc := ((w1 + w2) / 2)%Q in
  let N := gkyp_N n m A B in
  let Wi := block (mneg Qi) (madd Pi (mscale wc Qr)) (msub Pi (mscale wc Qr))
                  (mneg (mscale (w1 * w2) Qi)) in
  mmul (mmul (tr N) Wi) N.

(** M = -M^T. *)
Definition skew (n : nat) (M : matQ) : Prop :=
  forall i j, (i < n)%nat -> (j < n)%nat -> (entry M i j == - entry M j i)%Q.

Definition skew_check (n : nat) (M : matQ) : bool :=
  forallb (fun i => forallb (fun j => qeqb (entry M i j) (Qopp (entry M j i))) (seq 0 n))
          (seq 0 n).

Lemma skew_check_sound n M : skew_check n M = true -> skew n M.
Proof.
  intros H i j Hi Hj. apply qeqb_sound.
  exact (forallb_seq _ n (forallb_seq _ n H i Hi) j Hj).
Qed.

Theorem psd_check_semidef n M eps ws : psd_check n M eps ws = true -> pos_semidef n M.
Proof.
  intros Hc x. pose proof (psd_check_sound n M eps ws Hc x) as H.
  assert (0 <= Q2R eps * sumR n (fun i => x i * x i)).
  { apply Rmult_le_pos; [|apply sumR_nonneg; intros; apply Rle_0_sqr].
    unfold psd_check in Hc. rewrite !andb_true_iff in Hc. destruct Hc as [[He _] _].
    rewrite <- Q2R_zero. apply Qle_bool_R, He. }
  lra.
Qed.

(** The band certificate: P, Q Hermitian, Q >= 0 and L(P, Q) <= 0 on 0 <= w1 < w2, both
    as real quadratic forms of the real forms.  Then H(jw) + H(jw)^H >= 0 for every w in
    [w1, w2] where H(jw) is defined (the generalized KYP lemma). *)
Definition gkyp_certified (n m : nat) (A B C D Pr Pi Qr Qi : matQ) (w1 w2 : Q) : Prop :=
  has_shape n n A /\ has_shape n m B /\ has_shape m n C /\ has_shape m m D
  /\ has_shape n n Pr /\ has_shape n n Pi /\ has_shape n n Qr /\ has_shape n n Qi
  /\ (0 <= w1)%Q /\ (w1 < w2)%Q
  /\ symmetric n Pr /\ skew n Pi /\ symmetric n Qr /\ skew n Qi
  /\ pos_semidef (2 * n) (embed Qr Qi)
  /\ neg_semidef (2 * (n + m)) (embed (gkyp_re n m A B C D Pr Pi Qr Qi w1 w2)
                                      (gkyp_im n m A B C D Pr Pi Qr Qi w1 w2)).

Definition gkyp_check (n m : nat) (A B C D Pr Pi Qr Qi : matQ) (w1 w2 : Q)
    (eQ : Q) (wQ : list term) (eL : Q) (wL : list term) : bool :=
  has_shape_b n n A && has_shape_b n m B && has_shape_b m n C && has_shape_b m m D
  && has_shape_b n n Pr && has_shape_b n n Pi && has_shape_b n n Qr && has_shape_b n n Qi
  && Qle_bool 0 w1 && negb (Qle_bool w2 w1)
  && sym_check n Pr && skew_check n Pi && sym_check n Qr && skew_check n Qi
  && psd_check (2 * n) (embed Qr Qi) eQ wQ
  && psd_check (2 * (n + m)) (mneg (embed (gkyp_re n m A B C D Pr Pi Qr Qi w1 w2)
                                          (gkyp_im n m A B C D Pr Pi Qr Qi w1 w2))) eL wL.

Theorem gkyp_check_sound n m A B C D Pr Pi Qr Qi w1 w2 eQ wQ eL wL :
  gkyp_check n m A B C D Pr Pi Qr Qi w1 w2 eQ wQ eL wL = true ->
  gkyp_certified n m A B C D Pr Pi Qr Qi w1 w2.
Proof.
  unfold gkyp_check. rewrite !andb_true_iff, negb_true_iff.
  intros [[[[[[[[[[[[[[[HA HB] HC] HD] HPr] HPi] HQr] HQi] Hw1] Hw2] HsP] HkP] HsQ] HkQ] HQ] HL].
  assert (Hlt : (w1 < w2)%Q).
  { apply Qnot_le_lt. intros Hle. apply Qle_bool_iff in Hle. congruence. }
  split; [apply has_shape_b_sound, HA|]. split; [apply has_shape_b_sound, HB|].
  split; [apply has_shape_b_sound, HC|]. split; [apply has_shape_b_sound, HD|].
  split; [apply has_shape_b_sound, HPr|]. split; [apply has_shape_b_sound, HPi|].
  split; [apply has_shape_b_sound, HQr|]. split; [apply has_shape_b_sound, HQi|].
  split; [apply Qle_bool_iff, Hw1|]. split; [exact Hlt|].
  split; [apply sym_check_sound, HsP|]. split; [apply skew_check_sound, HkP|].
  split; [apply sym_check_sound, HsQ|]. split; [apply skew_check_sound, HkQ|].
  split; [apply (psd_check_semidef _ _ _ _ HQ)|].
  apply (nsd_check_sound _ _ _ _ HL).
Qed.
