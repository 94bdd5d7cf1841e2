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

(** ** The fast check: integers on machine words (bignums' [BigZ]) *)

From Bignums Require Import BigZ.
From Coq Require Uint63.

(** *** Matrices over any type, read through a map to the reals *)

Section Generic.
Variable T : Type.
Variable z : T.

Definition gentry (M : list (list T)) (i j : nat) : T := nth j (nth i M nil) z.

Definition gshape (r c : nat) (M : list (list T)) : Prop :=
  length M = r /\ Forall (fun row => length row = c) M.

Definition gshape_b (r c : nat) (M : list (list T)) : bool :=
  Nat.eqb (length M) r && forallb (fun row => Nat.eqb (length row) c) M.

Lemma gshape_b_sound r c M : gshape_b r c M = true -> gshape r c M.
Proof.
  unfold gshape_b, gshape. rewrite andb_true_iff, Nat.eqb_eq, forallb_forall.
  intros [H1 H2]. split; [exact H1|]. apply Forall_forall. intros row Hin.
  apply Nat.eqb_eq, H2, Hin.
Qed.

Lemma gshape_row r c M i : gshape r c M -> (i < r)%nat -> length (nth i M nil) = c.
Proof.
  intros [HM HF] Hi. rewrite Forall_forall in HF. apply HF, nth_In. lia.
Qed.

Lemma gcol_nth Y j k : nth k (map (fun row => nth j row z) Y) z = gentry Y k j.
Proof.
  unfold gentry. pose proof (map_nth (fun row => nth j row z) Y nil k) as E. simpl in E.
  destruct j; exact E.
Qed.

Definition gtr (M : list (list T)) : list (list T) :=
  map (fun j => map (fun row => nth j row z) M) (seq 0 (length (hd nil M))).

Lemma gtr_shape r c M : gshape r c M -> (0 < r)%nat -> gshape c r (gtr M).
Proof.
  intros [HM HF] Hr. destruct M as [|row M']; [simpl in HM; lia|].
  pose proof (Forall_inv HF) as Hrow. simpl in Hrow. unfold gtr. simpl hd. split.
  - rewrite map_length, seq_length. exact Hrow.
  - apply Forall_forall. intros col Hin. apply in_map_iff in Hin as [j [<- _]].
    rewrite map_length. exact HM.
Qed.

Lemma gtr_entry r c M i j :
  gshape r c M -> (0 < r)%nat -> (i < c)%nat -> (j < r)%nat ->
  gentry (gtr M) i j = gentry M j i.
Proof.
  intros [HM HF] Hr Hi Hj. unfold gentry, gtr.
  assert (Hc : length (hd nil M) = c).
  { destruct M as [|row M']; [simpl in HM; lia|]. exact (Forall_inv HF). }
  rewrite Hc.
  rewrite (nth_indep _ nil (map (fun row => nth i row z) M))
    by (rewrite map_length, seq_length; exact Hi).
  rewrite (map_nth (fun j0 => map (fun row => nth j0 row z) M)), seq_nth by exact Hi.
  simpl. pose proof (map_nth (fun row => nth i row z) M nil j) as E. simpl in E.
  destruct i; exact E.
Qed.

Fixpoint gzipw (f : T -> T -> T) (u v : list T) : list T :=
  match u, v with
  | a :: u', b :: v' => f a b :: gzipw f u' v'
  | _, _ => nil
  end.

Fixpoint gmadd (f : T -> T -> T) (A B : list (list T)) : list (list T) :=
  match A, B with
  | r :: A', s :: B' => gzipw f r s :: gmadd f A' B'
  | _, _ => nil
  end.

Lemma gzipw_length f u v : length (gzipw f u v) = Nat.min (length u) (length v).
Proof. revert v; induction u; intros [|b v]; simpl; auto. Qed.

Lemma gzipw_nth f u v j :
  (j < length u)%nat -> (j < length v)%nat -> nth j (gzipw f u v) z = f (nth j u z) (nth j v z).
Proof.
  revert v j; induction u as [|a u IH]; intros [|b v] j Hu Hv; simpl in *; try lia.
  destruct j; [reflexivity|]. apply IH; lia.
Qed.

Lemma gmadd_shape f r c A B : gshape r c A -> gshape r c B -> gshape r c (gmadd f A B).
Proof.
  intros [HA FA] [HB FB]. subst r. revert B HB FB.
  induction FA as [|ra A Hra FA IH]; intros [|rb B] HB FB; simpl in *; try discriminate.
  - split; [reflexivity | constructor].
  - injection HB as HB. pose proof (Forall_inv FB) as Hrb. simpl in Hrb.
    destruct (IH B HB (Forall_inv_tail FB)) as [H1 H2].
    split; [simpl; lia|]. constructor; [|exact H2]. rewrite gzipw_length. lia.
Qed.

Lemma gmadd_entry f r c A B i j :
  gshape r c A -> gshape r c B -> (i < r)%nat -> (j < c)%nat ->
  gentry (gmadd f A B) i j = f (gentry A i j) (gentry B i j).
Proof.
  intros HA HB Hi Hj. unfold gentry.
  assert (E : nth i (gmadd f A B) nil = gzipw f (nth i A nil) (nth i B nil)).
  { destruct HA as [HA _], HB as [HB _]. clear - HA HB Hi. revert B i r HA HB Hi.
    induction A as [|ra A IH]; intros [|rb B] i r HA HB Hi; simpl in *; try lia.
    destruct i; [reflexivity|]. apply (IH B i (pred r)); lia. }
  rewrite E. apply gzipw_nth.
  - rewrite (gshape_row r c A i HA Hi). exact Hj.
  - rewrite (gshape_row r c B i HB Hi). exact Hj.
Qed.

Definition gmap (g : T -> T) (M : list (list T)) : list (list T) := map (map g) M.

Lemma gmap_shape g r c M : gshape r c M -> gshape r c (gmap g M).
Proof.
  intros [HM HF]. unfold gmap. split; [rewrite map_length; exact HM|].
  rewrite Forall_forall in *. intros row Hin. apply in_map_iff in Hin as [row' [<- Hin]].
  rewrite map_length. apply HF, Hin.
Qed.

Lemma gmap_entry g r c M i j :
  gshape r c M -> (i < r)%nat -> (j < c)%nat -> gentry (gmap g M) i j = g (gentry M i j).
Proof.
  intros HM Hi Hj. unfold gentry, gmap.
  rewrite (nth_indep _ nil (map g nil)) by (destruct HM; rewrite map_length; lia).
  rewrite (map_nth (map g) M nil i).
  rewrite (nth_indep _ z (g z)) by (rewrite map_length, (gshape_row r c M i HM Hi); exact Hj).
  apply map_nth.
Qed.

Definition gmm (f : list T -> list T -> T) (X Y : list (list T)) : list (list T) :=
  let Yt := gtr Y in map (fun row => map (fun col => f row col) Yt) X.

Lemma gmm_shape f r k c X Y :
  gshape r k X -> gshape k c Y -> (0 < k)%nat -> gshape r c (gmm f X Y).
Proof.
  intros [HX _] HY Hk. destruct (gtr_shape k c Y HY Hk) as [Ht _]. unfold gmm.
  split; [rewrite map_length; exact HX|]. apply Forall_forall. intros row Hin.
  apply in_map_iff in Hin as [row' [<- _]]. rewrite map_length. exact Ht.
Qed.

Lemma gmm_entry f r k c X Y i j :
  gshape r k X -> gshape k c Y -> (0 < k)%nat -> (i < r)%nat -> (j < c)%nat ->
  gentry (gmm f X Y) i j = f (nth i X nil) (map (fun row => nth j row z) Y).
Proof.
  intros HX HY Hk Hi Hj. unfold gentry, gmm.
  pose proof (gtr_shape k c Y HY Hk) as [Ht Ft].
  rewrite (nth_indep _ nil ((fun row => map (fun col => f row col) (gtr Y)) nil))
    by (destruct HX; rewrite map_length; lia).
  rewrite (map_nth (fun row => map (fun col => f row col) (gtr Y)) X nil i).
  rewrite (nth_indep _ z (f (nth i X nil) nil)) by (rewrite map_length; lia).
  rewrite (map_nth (fun col => f (nth i X nil) col) (gtr Y) nil j). f_equal.
  unfold gtr. destruct HY as [HY FY]. destruct Y as [|row Y']; [simpl in HY; lia|].
  pose proof (Forall_inv FY) as Hrow. simpl in Hrow. simpl hd. rewrite Hrow.
  rewrite (nth_indep _ nil (map (fun row0 => nth j row0 z) (row :: Y')))
    by (rewrite map_length, seq_length; exact Hj).
  rewrite (map_nth (fun j0 => map (fun row0 => nth j0 row0 z) (row :: Y'))), seq_nth
    by exact Hj.
  reflexivity.
Qed.

Fixpoint ghcat (A B : list (list T)) : list (list T) :=
  match A, B with
  | r :: A', s :: B' => (r ++ s) :: ghcat A' B'
  | _, _ => nil
  end.

Definition gblock (TL TR BL BR : list (list T)) : list (list T) := ghcat TL TR ++ ghcat BL BR.

Lemma ghcat_shape r c1 c2 A B :
  gshape r c1 A -> gshape r c2 B -> gshape r (c1 + c2) (ghcat A B).
Proof.
  intros [HA FA] [HB FB]. subst r. revert B HB FB.
  induction FA as [|ra A Hra FA IH]; intros [|rb B] HB FB; simpl in *; try discriminate.
  - split; [reflexivity | constructor].
  - injection HB as HB. pose proof (Forall_inv FB) as Hrb. simpl in Hrb.
    destruct (IH B HB (Forall_inv_tail FB)) as [H1 H2].
    split; [simpl; lia|]. constructor; [|exact H2]. rewrite app_length. lia.
Qed.

Lemma ghcat_entry r c1 c2 A B i j :
  gshape r c1 A -> gshape r c2 B -> (i < r)%nat -> (j < c1 + c2)%nat ->
  gentry (ghcat A B) i j
  = if Nat.ltb j c1 then gentry A i j else gentry B i (j - c1).
Proof.
  intros HA HB Hi Hj. unfold gentry.
  assert (E : nth i (ghcat A B) nil = nth i A nil ++ nth i B nil).
  { destruct HA as [HA _], HB as [HB _]. clear - HA HB Hi. revert B i r HA HB Hi.
    induction A as [|ra A IH]; intros [|rb B] i r HA HB Hi; simpl in *; try lia.
    destruct i; [reflexivity|]. apply (IH B i (pred r)); lia. }
  rewrite E. pose proof (gshape_row r c1 A i HA Hi) as Ha.
  destruct (Nat.ltb_spec j c1).
  - apply app_nth1. lia.
  - rewrite app_nth2 by lia. rewrite Ha. reflexivity.
Qed.

Lemma gblock_shape r1 r2 c1 c2 TL TR BL BR :
  gshape r1 c1 TL -> gshape r1 c2 TR -> gshape r2 c1 BL -> gshape r2 c2 BR ->
  gshape (r1 + r2) (c1 + c2) (gblock TL TR BL BR).
Proof.
  intros H1 H2 H3 H4. pose proof (ghcat_shape _ _ _ _ _ H1 H2) as [Ha Fa].
  pose proof (ghcat_shape _ _ _ _ _ H3 H4) as [Hb Fb]. unfold gblock.
  split; [rewrite app_length; lia|]. apply Forall_app. split; assumption.
Qed.

Lemma gblock_entry r1 r2 c1 c2 TL TR BL BR i j :
  gshape r1 c1 TL -> gshape r1 c2 TR -> gshape r2 c1 BL -> gshape r2 c2 BR ->
  (i < r1 + r2)%nat -> (j < c1 + c2)%nat ->
  gentry (gblock TL TR BL BR) i j
  = if Nat.ltb i r1 then gentry (ghcat TL TR) i j else gentry (ghcat BL BR) (i - r1) j.
Proof.
  intros H1 H2 H3 H4 Hi Hj. pose proof (ghcat_shape _ _ _ _ _ H1 H2) as [Ha _].
  unfold gentry, gblock. destruct (Nat.ltb_spec i r1).
  - rewrite app_nth1 by lia. reflexivity.
  - rewrite app_nth2 by lia. rewrite Ha. reflexivity.
Qed.

Definition gtab (n : nat) (f : nat -> nat -> T) : list (list T) :=
  map (fun i => map (fun j => f i j) (seq 0 n)) (seq 0 n).

Lemma gtab_shape n f : gshape n n (gtab n f).
Proof.
  unfold gtab. split; [rewrite map_length, seq_length; reflexivity|].
  apply Forall_forall. intros row Hin. apply in_map_iff in Hin as [i [<- _]].
  rewrite map_length, seq_length. reflexivity.
Qed.

Lemma gtab_entry n f i j : (i < n)%nat -> (j < n)%nat -> gentry (gtab n f) i j = f i j.
Proof.
  intros Hi Hj. unfold gentry, gtab.
  rewrite (nth_indep _ nil (map (fun j => f i j) (seq 0 n)))
    by (rewrite map_length, seq_length; exact Hi).
  rewrite (map_nth (fun i => map (fun j => f i j) (seq 0 n))), seq_nth by exact Hi.
  rewrite (nth_indep _ z (f i 0%nat)) by (rewrite map_length, seq_length; exact Hj).
  rewrite (map_nth (fun j => f i j)), seq_nth by exact Hj. reflexivity.
Qed.

(** Rows scaled by the weights: row k times [ds_k]. *)
Fixpoint gsrows (mul : T -> T -> T) (ds : list T) (L : list (list T)) : list (list T) :=
  match ds, L with
  | d :: ds', r :: L' => map (mul d) r :: gsrows mul ds' L'
  | _, _ => nil
  end.

Lemma gsrows_shape mul k c ds L :
  length ds = k -> gshape k c L -> gshape k c (gsrows mul ds L).
Proof.
  intros Hd [HL FL]. rewrite <- HL in *. clear HL k. revert ds Hd.
  induction FL as [|r L Hr FL IH]; intros [|d ds] Hd; simpl in *; try discriminate.
  - split; [reflexivity | constructor].
  - injection Hd as Hd. destruct (IH ds Hd) as [H1 H2].
    split; [simpl; lia|]. constructor; [rewrite map_length; exact Hr | exact H2].
Qed.

Lemma gsrows_entry mul k c ds L i j :
  length ds = k -> gshape k c L -> (i < k)%nat -> (j < c)%nat ->
  gentry (gsrows mul ds L) i j = mul (nth i ds z) (gentry L i j).
Proof.
  intros Hd HL Hi Hj. unfold gentry.
  assert (E : nth i (gsrows mul ds L) nil = map (mul (nth i ds z)) (nth i L nil)).
  { destruct HL as [HL _]. clear - Hd HL Hi. revert ds i k Hd HL Hi.
    induction L as [|r L IH]; intros [|d ds] i k Hd HL Hi; simpl in *; try lia.
    destruct i; [reflexivity|]. apply (IH ds i (pred k)); lia. }
  rewrite E, (nth_indep _ z (mul (nth i ds z) z))
    by (rewrite map_length, (gshape_row k c L i HL Hi); exact Hj).
  apply map_nth.
Qed.

End Generic.

Arguments gentry {T}. Arguments gshape {T}. Arguments gshape_b {T}. Arguments gtr {T}.
Arguments gzipw {T}. Arguments gmadd {T}. Arguments gmap {T}. Arguments gmm {T}.
Arguments ghcat {T}. Arguments gblock {T}. Arguments gtab {T}. Arguments gsrows {T}.

(** The sum of n terms, taken from the front. *)
Lemma sumR_front n f : sumR (S n) f = f O + sumR n (fun k => f (S k)).
Proof.
  induction n; simpl in *; [lra|]. rewrite IHn. lra.
Qed.

(** *** The same operations on [matQ] *)

Lemma tr_g M : tr M = gtr 0%Q M.
Proof. reflexivity. Qed.

Lemma zipw_g f u v : zipw f u v = gzipw f u v.
Proof. revert v; induction u; intros [|b v]; simpl; f_equal; auto. Qed.

Lemma madd_g A B : madd A B = gmadd qadd A B.
Proof.
  revert B; induction A; intros [|s B]; simpl; f_equal; auto using zipw_g.
Qed.

Lemma mmul_g A B : mmul A B = gmm 0%Q dot A B.
Proof. reflexivity. Qed.

Lemma hcat_g A B : hcat A B = ghcat A B.
Proof. revert B; induction A; intros [|s B]; simpl; f_equal; auto. Qed.

Lemma block_g TL TR BL BR : block TL TR BL BR = gblock TL TR BL BR.
Proof. unfold block, gblock. rewrite !hcat_g. reflexivity. Qed.

Lemma dotR_sum u v :
  length u = length v ->
  dotR u v = sumR (length u) (fun k => Q2R (nth k u 0%Q) * Q2R (nth k v 0%Q)).
Proof.
  revert v; induction u as [|a u IH]; intros [|b v] H; try (simpl in H; lia).
  - simpl. lra.
  - change (dotR (a :: u) (b :: v)) with (Q2R a * Q2R b + dotR u v).
    change (length (a :: u)) with (S (length u)). rewrite sumR_front.
    rewrite IH by (simpl in H; lia). reflexivity.
Qed.

Lemma has_shape_g r c (M : matQ) : has_shape r c M <-> gshape r c M.
Proof. reflexivity. Qed.

(** *** Integers on machine words *)

Definition zR (x : BigZ.t_) : R := IZR (BigZ.to_Z x).

Fixpoint zdot (u v : list BigZ.t_) : BigZ.t_ :=
  match u, v with
  | a :: u', b :: v' => BigZ.add (BigZ.mul a b) (zdot u' v')
  | _, _ => BigZ.zero
  end.

Lemma zR_add a b : zR (BigZ.add a b) = zR a + zR b.
Proof. unfold zR. rewrite BigZ.spec_add, plus_IZR. reflexivity. Qed.
Lemma zR_mul a b : zR (BigZ.mul a b) = zR a * zR b.
Proof. unfold zR. rewrite BigZ.spec_mul, mult_IZR. reflexivity. Qed.
Lemma zR_opp a : zR (BigZ.opp a) = - zR a.
Proof. unfold zR. rewrite BigZ.spec_opp, opp_IZR. reflexivity. Qed.
Lemma zR_abs a : zR (BigZ.abs a) = Rabs (zR a).
Proof. unfold zR. rewrite BigZ.spec_abs, abs_IZR. reflexivity. Qed.
Lemma zR_zero : zR BigZ.zero = 0.
Proof. unfold zR. rewrite BigZ.spec_0. reflexivity. Qed.

Lemma zdot_sum u v :
  length u = length v ->
  zR (zdot u v) = sumR (length u) (fun k => zR (nth k u BigZ.zero) * zR (nth k v BigZ.zero)).
Proof.
  revert v; induction u as [|a u IH]; intros [|b v] H; try (simpl in H; lia).
  - simpl. rewrite zR_zero. lra.
  - change (zdot (a :: u) (b :: v)) with (BigZ.add (BigZ.mul a b) (zdot u v)).
    change (length (a :: u)) with (S (length u)). rewrite sumR_front.
    rewrite zR_add, zR_mul, IH by (simpl in H; lia). reflexivity.
Qed.

Definition zentry (M : list (list BigZ.t_)) (i j : nat) : BigZ.t_ := @gentry BigZ.t_ BigZ.zero M i j.

(** [Xz] holds the entries of [X] times [s]: [X = Xz / s]. *)
Definition repr (r c : nat) (X : matQ) (Xz : list (list BigZ.t_)) (s : R) : Prop :=
  has_shape r c X /\ gshape r c Xz /\
  forall i j, (i < r)%nat -> (j < c)%nat -> Q2R (entry X i j) * s = zR (zentry Xz i j).

Lemma repr_s r c X Xz s t : s = t -> repr r c X Xz s -> repr r c X Xz t.
Proof. intros <-. auto. Qed.

Lemma repr_tr r c X Xz s :
  (0 < r)%nat -> repr r c X Xz s -> repr c r (tr X) (gtr BigZ.zero Xz) s.
Proof.
  intros Hr [HX [HZ HE]]. split; [|split].
  - apply (gtr_shape _ _ r c X HX Hr).
  - apply (gtr_shape _ _ r c Xz HZ Hr).
  - intros i j Hi Hj. unfold zentry in *. rewrite tr_g.
    change (entry (gtr 0%Q X) i j) with (gentry 0%Q (gtr 0%Q X) i j).
    rewrite (gtr_entry _ _ r c X i j HX Hr Hi Hj), (gtr_entry _ _ r c Xz i j HZ Hr Hi Hj).
    apply HE; assumption.
Qed.

Lemma repr_mm r k c X Xz Y Yz s t :
  (0 < k)%nat -> repr r k X Xz s -> repr k c Y Yz t ->
  repr r c (mmul X Y) (gmm BigZ.zero zdot Xz Yz) (s * t).
Proof.
  intros Hk [HX [HXz EX]] [HY [HYz EY]]. split; [|split].
  - rewrite mmul_g. apply (gmm_shape _ _ _ r k c X Y HX HY Hk).
  - apply (gmm_shape _ _ _ r k c Xz Yz HXz HYz Hk).
  - intros i j Hi Hj. unfold zentry in *. rewrite mmul_g.
    change (entry (gmm 0%Q dot X Y) i j) with (gentry 0%Q (gmm 0%Q dot X Y) i j).
    rewrite (gmm_entry _ _ _ r k c X Y i j HX HY Hk Hi Hj).
    rewrite (gmm_entry _ _ _ r k c Xz Yz i j HXz HYz Hk Hi Hj).
    assert (LX : length (nth i X nil) = k) by exact (gshape_row _ r k X i HX Hi).
    assert (LXz : length (nth i Xz nil) = k) by exact (gshape_row _ r k Xz i HXz Hi).
    assert (LY : length Y = k) by (destruct HY; assumption).
    assert (LYz : length Yz = k) by (destruct HYz; assumption).
    rewrite Q2R_dot, dotR_sum by (rewrite map_length; lia).
    rewrite zdot_sum by (rewrite map_length; lia). rewrite LX, LXz.
    rewrite <- sumR_scal_r. apply sumR_ext. intros kk Hkk.
    rewrite (gcol_nth _ 0%Q), (gcol_nth BigZ.t_ BigZ.zero).
    pose proof (EX i kk Hi Hkk) as E1. pose proof (EY kk j Hkk Hj) as E2.
    unfold zentry, entry, gentry in *.
    transitivity ((Q2R (nth kk (nth i X nil) 0%Q) * s) * (Q2R (nth j (nth kk Y nil) 0%Q) * t));
      [ring | rewrite E1, E2; reflexivity].
Qed.

Lemma repr_add r c X Xz Y Yz s :
  repr r c X Xz s -> repr r c Y Yz s -> repr r c (madd X Y) (gmadd BigZ.add Xz Yz) s.
Proof.
  intros [HX [HXz EX]] [HY [HYz EY]]. rewrite madd_g. split; [|split].
  - apply (gmadd_shape _ qadd r c X Y HX HY).
  - apply (gmadd_shape _ BigZ.add r c Xz Yz HXz HYz).
  - intros i j Hi Hj. unfold zentry in *.
    change (entry (gmadd qadd X Y) i j) with (gentry 0%Q (gmadd qadd X Y) i j).
    rewrite (gmadd_entry _ _ qadd r c X Y i j HX HY Hi Hj).
    rewrite (gmadd_entry _ _ BigZ.add r c Xz Yz i j HXz HYz Hi Hj).
    rewrite Q2R_qadd, zR_add, <- (EX i j Hi Hj), <- (EY i j Hi Hj).
    unfold entry, gentry. ring.
Qed.

Lemma repr_neg r c X Xz s : repr r c X Xz s -> repr r c (mneg X) (gmap BigZ.opp Xz) s.
Proof.
  intros [HX [HXz EX]]. split; [|split].
  - apply (gmap_shape _ Qopp r c X HX).
  - apply (gmap_shape _ BigZ.opp r c Xz HXz).
  - intros i j Hi Hj. unfold zentry in *. rewrite entry_mneg.
    rewrite (gmap_entry _ _ BigZ.opp r c Xz i j HXz Hi Hj).
    rewrite Q2R_opp, zR_opp, <- (EX i j Hi Hj). unfold entry, gentry. ring.
Qed.

Lemma repr_sub r c X Xz Y Yz s :
  repr r c X Xz s -> repr r c Y Yz s ->
  repr r c (msub X Y) (gmadd BigZ.add Xz (gmap BigZ.opp Yz)) s.
Proof. intros HX HY. apply repr_add; [exact HX | apply repr_neg, HY]. Qed.

Lemma repr_scale r c X Xz s k :
  repr r c X Xz s -> repr r c X (gmap (BigZ.mul k) Xz) (s * zR k).
Proof.
  intros [HX [HXz EX]]. split; [exact HX|split].
  - apply (gmap_shape _ _ r c Xz HXz).
  - intros i j Hi Hj. unfold zentry in *.
    rewrite (gmap_entry _ _ _ r c Xz i j HXz Hi Hj), zR_mul.
    rewrite <- (EX i j Hi Hj). unfold gentry. ring.
Qed.

Lemma repr_block r1 r2 c1 c2 TL TR BL BR TLz TRz BLz BRz s :
  repr r1 c1 TL TLz s -> repr r1 c2 TR TRz s -> repr r2 c1 BL BLz s -> repr r2 c2 BR BRz s ->
  repr (r1 + r2) (c1 + c2) (block TL TR BL BR) (gblock TLz TRz BLz BRz) s.
Proof.
  intros [H1 [Z1 E1]] [H2 [Z2 E2]] [H3 [Z3 E3]] [H4 [Z4 E4]]. rewrite block_g.
  split; [|split].
  - apply gblock_shape; assumption.
  - apply gblock_shape; assumption.
  - intros i j Hi Hj. unfold zentry in *.
    change (entry (gblock TL TR BL BR) i j) with (gentry 0%Q (gblock TL TR BL BR) i j).
    rewrite (gblock_entry _ _ r1 r2 c1 c2 TL TR BL BR i j H1 H2 H3 H4 Hi Hj).
    rewrite (gblock_entry _ _ r1 r2 c1 c2 TLz TRz BLz BRz i j Z1 Z2 Z3 Z4 Hi Hj).
    destruct (Nat.ltb_spec i r1).
    + rewrite (ghcat_entry _ _ r1 c1 c2 TL TR i j H1 H2), (ghcat_entry _ _ r1 c1 c2 TLz TRz i j Z1 Z2)
        by assumption.
      destruct (Nat.ltb_spec j c1); [apply E1 | apply E2]; lia.
    + rewrite (ghcat_entry _ _ r2 c1 c2 BL BR (i - r1) j H3 H4),
        (ghcat_entry _ _ r2 c1 c2 BLz BRz (i - r1) j Z3 Z4) by lia.
      destruct (Nat.ltb_spec j c1); [apply E3 | apply E4]; lia.
Qed.

(** *** The KYP matrix on integers: [Mz = L M(P)] with [L = a p b c d] *)

Definition zmm (X Y : list (list BigZ.t_)) := gmm BigZ.zero zdot X Y.
Definition ztr (X : list (list BigZ.t_)) := gtr BigZ.zero X.
Definition zadd (X Y : list (list BigZ.t_)) := gmadd BigZ.add X Y.
Definition zneg (X : list (list BigZ.t_)) := gmap BigZ.opp X.
Definition zscale (k : BigZ.t_) (X : list (list BigZ.t_)) := gmap (BigZ.mul k) X.

(** [TLz] stands for the top-left block A^T P + P A times [a p] (lemma [repr_kyp]); the
    check computes it as [X^T + X] with [X = s P A] (P symmetric: [repr_tl]). *)
Definition zkyp (TLz Bz Cz Dz Pz : list (list BigZ.t_)) (a b c d p : BigZ.t_) :=
  let pb := BigZ.mul p b in
  let ad := BigZ.mul a d in
  gblock (zscale (BigZ.mul (BigZ.mul b c) d) TLz)
         (zscale ad (zadd (zscale c (zmm Pz Bz)) (zneg (zscale pb (ztr Cz)))))
         (zscale ad (zadd (zscale c (zmm (ztr Bz) Pz)) (zneg (zscale pb Cz))))
         (zscale (BigZ.mul (BigZ.mul a p) (BigZ.mul b c)) (zneg (zadd Dz (ztr Dz)))).

Lemma repr_kyp n m A B C D P TLz Bz Cz Dz Pz a b c d p :
  (0 < n)%nat -> (0 < m)%nat ->
  repr n n (madd (mmul (tr A) P) (mmul P A)) TLz (zR a * zR p) ->
  repr n m B Bz (zR b) -> repr m n C Cz (zR c) ->
  repr m m D Dz (zR d) -> repr n n P Pz (zR p) ->
  repr (n + m) (n + m) (kyp A B C D P) (zkyp TLz Bz Cz Dz Pz a b c d p)
       (zR a * zR p * zR b * zR c * zR d).
Proof.
  intros Hn Hm HTL HB HC HD HP. unfold kyp, zkyp, zmm, ztr, zadd, zneg, zscale.
  apply repr_block.
  - eapply repr_s; [|apply repr_scale, HTL]. rewrite !zR_mul; ring.
  - eapply repr_s; [|apply repr_scale, repr_sub;
      [apply repr_scale, (repr_mm n n m); [exact Hn | exact HP | exact HB]
      |eapply repr_s; [|apply repr_scale, (repr_tr m n); [exact Hm | exact HC]]]];
      [rewrite !zR_mul; ring | rewrite !zR_mul; ring].
  - eapply repr_s; [|apply repr_scale, repr_sub;
      [apply repr_scale, (repr_mm m n n); [exact Hn | apply (repr_tr n m); [exact Hn | exact HB] | exact HP]
      |eapply repr_s; [|apply repr_scale; exact HC]]];
      [rewrite !zR_mul; ring | rewrite !zR_mul; ring].
  - eapply repr_s; [|apply repr_scale, repr_neg, repr_add;
      [exact HD | apply repr_tr; assumption]]. rewrite !zR_mul; ring.
Qed.

Lemma repr_ext r c X Xz Yz s :
  repr r c X Xz s -> gshape r c Yz ->
  (forall i j, (i < r)%nat -> (j < c)%nat -> zR (zentry Xz i j) = zR (zentry Yz i j)) ->
  repr r c X Yz s.
Proof.
  intros [HX [_ E]] HY EY. split; [exact HX | split; [exact HY|]].
  intros i j Hi Hj. rewrite <- EY by assumption. apply E; assumption.
Qed.

Lemma zmm_val r k c X Y i j :
  gshape r k X -> gshape k c Y -> (0 < k)%nat -> (i < r)%nat -> (j < c)%nat ->
  zR (zentry (zmm X Y) i j) = sumR k (fun t => zR (zentry X i t) * zR (zentry Y t j)).
Proof.
  intros HX HY Hk Hi Hj. unfold zentry, zmm.
  rewrite (gmm_entry _ _ _ r k c X Y i j HX HY Hk Hi Hj).
  rewrite zdot_sum by (rewrite map_length, (gshape_row _ r k X i HX Hi); destruct HY; lia).
  rewrite (gshape_row _ r k X i HX Hi). apply sumR_ext. intros t Ht.
  rewrite (gcol_nth _ BigZ.zero). reflexivity.
Qed.

(** *** Witnesses on integers *)

Definition qformZ (n : nat) (M : list (list BigZ.t_)) (x : nat -> R) : R :=
  sumR n (fun i => sumR n (fun j => zR (zentry M i j) * (x i * x j))).

Lemma qform_repr n X Xz s x : repr n n X Xz s -> qform n X x * s = qformZ n Xz x.
Proof.
  intros [_ [_ E]]. unfold qform, qformZ. rewrite <- sumR_scal_r. apply sumR_ext.
  intros i Hi. rewrite <- sumR_scal_r. apply sumR_ext. intros j Hj.
  rewrite <- (E i j Hi Hj). ring.
Qed.

Definition zsum (u : list BigZ.t_) : BigZ.t_ := fold_right BigZ.add BigZ.zero u.

Lemma zsum_sum u : zR (zsum u) = sumR (length u) (fun j => zR (nth j u BigZ.zero)).
Proof.
  induction u as [|a u IH]; [simpl; apply zR_zero|].
  change (zsum (a :: u)) with (BigZ.add a (zsum u)).
  change (length (a :: u)) with (S (length u)). rewrite sumR_front, zR_add, IH.
  reflexivity.
Qed.

(** Every row i of R: R_ii >= 0 and sum_j (|R_ij| + |R_ji|) <= 4 R_ii, that is
    sum_(j <> i) (|R_ij| + |R_ji|) <= 2 R_ii. *)
Definition zdominant (n : nat) (R : list (list BigZ.t_)) : bool :=
  let T := zadd (gmap BigZ.abs R) (gmap BigZ.abs (ztr R)) in
  forallb (fun i => let r := zentry R i i in let r2 := BigZ.add r r in
             BigZ.leb BigZ.zero r && BigZ.leb (zsum (nth i T nil)) (BigZ.add r2 r2))
          (seq 0 n).

Lemma zR_leb a b : BigZ.leb a b = true -> zR a <= zR b.
Proof.
  intros H. rewrite BigZ.spec_leb in H. apply Z.leb_le in H. apply IZR_le, H.
Qed.

Lemma zR_ltb a b : BigZ.ltb a b = true -> zR a < zR b.
Proof.
  intros H. rewrite BigZ.spec_ltb in H. apply Z.ltb_lt in H. apply IZR_lt, H.
Qed.

Lemma zdominant_sound n R x :
  (0 < n)%nat -> gshape n n R -> zdominant n R = true ->
  0 <= qformZ n R x.
Proof.
  intros Hn HR Hd. unfold qformZ.
  apply (gershgorin n (fun i j => zR (zentry R i j))). intros i Hi.
  unfold zdominant in Hd. pose proof (forallb_seq _ n Hd i Hi) as H. cbv zeta in H.
  apply andb_true_iff in H as [H0 H4]. apply zR_leb in H0. apply zR_leb in H4.
  rewrite zR_zero in H0. rewrite !zR_add in H4.
  pose proof (gtr_shape _ BigZ.zero n n R HR Hn) as HRt.
  pose proof (gmap_shape _ BigZ.abs n n R HR) as HA.
  pose proof (gmap_shape _ BigZ.abs n n _ HRt) as HAt.
  pose proof (gmadd_shape _ BigZ.add n n _ _ HA HAt) as HT.
  rewrite zsum_sum in H4. unfold zadd, ztr in H4.
  rewrite (gshape_row _ n n _ i HT Hi) in H4.
  assert (E : forall j, (j < n)%nat ->
     zR (nth j (nth i (gmadd BigZ.add (gmap BigZ.abs R) (gmap BigZ.abs (gtr BigZ.zero R))) nil) BigZ.zero)
     = Rabs (zR (zentry R i j)) + Rabs (zR (zentry R j i))).
  { intros j Hj.
    change (nth j (nth i (gmadd BigZ.add (gmap BigZ.abs R) (gmap BigZ.abs (gtr BigZ.zero R))) nil) BigZ.zero)
      with (gentry BigZ.zero (gmadd BigZ.add (gmap BigZ.abs R) (gmap BigZ.abs (gtr BigZ.zero R))) i j).
    rewrite (gmadd_entry _ _ _ n n _ _ i j HA HAt Hi Hj), zR_add.
    rewrite (gmap_entry _ _ _ n n _ i j HR Hi Hj), (gmap_entry _ _ _ n n _ i j HRt Hi Hj).
    rewrite (gtr_entry _ _ n n R i j HR Hn Hi Hj), !zR_abs. reflexivity. }
  rewrite (sumR_ext n _ _ E) in H4.
  rewrite (sumR_split n i) in H4 by exact Hi. cbv beta in H4.
  rewrite Rabs_right in H4 by lra. lra.
Qed.

Definition zdelta (n : nat) (e : BigZ.t_) : list (list BigZ.t_) :=
  gtab n (fun i j => if Nat.eqb i j then e else BigZ.zero).

Definition zresid (n : nat) (M : list (list BigZ.t_)) (e den c : BigZ.t_)
    (ds : list BigZ.t_) (L : list (list BigZ.t_)) : list (list BigZ.t_) :=
  zadd (zscale den M) (zneg (zadd (zdelta n e) (zscale c (zmm (ztr L) (gsrows BigZ.mul ds L))))).

(** [den M - e I - c sum_k d_k l_k l_k^T] is diagonally dominant (the rows of [L] are the
    [l_k]), with [e >= 0], [den > 0], [c >= 0] and every [d_k >= 0]: then
    [x^T M x >= (e / den) |x|^2] (lemma [zpsd_check_sound]).  The common factor [c] of
    the weights is applied after the sum, so that the products stay short. *)
Definition zpsd_check (n : nat) (M : list (list BigZ.t_)) (e den c : BigZ.t_)
    (ds : list BigZ.t_) (L : list (list BigZ.t_)) : bool :=
  BigZ.leb BigZ.zero e && BigZ.ltb BigZ.zero den && BigZ.leb BigZ.zero c
  && forallb (BigZ.leb BigZ.zero) ds
  && Nat.eqb (length ds) (length L) && Nat.ltb 0 (length L) && Nat.ltb 0 n
  && gshape_b (length L) n L && gshape_b n n M
  && zdominant n (zresid n M e den c ds L).

Lemma sumR_lin n a b f g h :
  sumR n (fun i => a * f i - b * g i - h i) = a * sumR n f - b * sumR n g - sumR n h.
Proof. induction n; simpl; [ring|]. rewrite IHn. ring. Qed.

Lemma zpsd_check_sound n M e den c ds L :
  zpsd_check n M e den c ds L = true ->
  forall x, zR e * sumR n (fun i => x i * x i) <= zR den * qformZ n M x.
Proof.
  unfold zpsd_check. rewrite !andb_true_iff.
  intros [[[[[[[[[He Hden] Hc] Hds] HK] HK0] Hn] HL] HM] Hdom] x.
  apply zR_leb in Hc. rewrite zR_zero in Hc. apply zR_leb in He. apply zR_ltb in Hden. rewrite zR_zero in He, Hden.
  apply Nat.eqb_eq in HK. apply Nat.ltb_lt in HK0. apply Nat.ltb_lt in Hn.
  apply gshape_b_sound in HL. apply gshape_b_sound in HM.
  set (K := length L) in *.
  pose proof (gtr_shape _ BigZ.zero K n L HL HK0) as HLt.
  pose proof (gsrows_shape _ BigZ.mul K n ds L HK HL) as HDL.
  pose proof (gmm_shape _ BigZ.zero zdot n K n _ _ HLt HDL HK0) as HS0.
  pose proof (gmap_shape _ (BigZ.mul c) n n _ HS0) as HS.
  pose proof (gtab_shape _ n (fun i j => if Nat.eqb i j then e else BigZ.zero)) as HD.
  pose proof (gmadd_shape _ BigZ.add n n _ _ HD HS) as HDS.
  pose proof (gmap_shape _ BigZ.opp n n _ HDS) as HnDS.
  pose proof (gmap_shape _ (BigZ.mul den) n n _ HM) as HdM.
  pose proof (gmadd_shape _ BigZ.add n n _ _ HdM HnDS) as HR.
  (* the entries of S = sum_k d_k l_k l_k^T *)
  set (S0 := gmm BigZ.zero zdot (gtr BigZ.zero L) (gsrows BigZ.mul ds L)) in *.
  set (S := gmap (BigZ.mul c) S0) in *.
  assert (ES : forall i j, (i < n)%nat -> (j < n)%nat ->
            zR (zentry S0 i j)
            = sumR K (fun k => zR (nth k ds BigZ.zero) * (zR (zentry L k i) * zR (zentry L k j)))).
  { intros i j Hi Hj. unfold zentry, S0.
    rewrite (gmm_entry _ _ _ n K n _ _ i j HLt HDL HK0 Hi Hj).
    rewrite zdot_sum by (rewrite map_length, (gshape_row _ n K _ i HLt Hi); destruct HDL; lia).
    rewrite (gshape_row _ n K _ i HLt Hi). apply sumR_ext. intros k Hk.
    rewrite (gcol_nth _ BigZ.zero).
    change (nth k (nth i (gtr BigZ.zero L) nil) BigZ.zero)
      with (gentry BigZ.zero (gtr BigZ.zero L) i k).
    rewrite (gtr_entry _ _ K n L i k HL HK0 Hi Hk).
    rewrite (gsrows_entry _ _ _ K n ds L k j HK HL Hk Hj), zR_mul. ring. }
  (* the entries of R *)
  set (Rz := zresid n M e den c ds L) in *.
  assert (ER : forall i j, (i < n)%nat -> (j < n)%nat ->
            zR (zentry Rz i j)
            = zR den * zR (zentry M i j) - ((if Nat.eqb i j then zR e else 0)
                                            + zR (zentry S i j))).
  { intros i j Hi Hj. unfold Rz, zresid, zadd, zneg, zscale, zmm, ztr, zdelta, zentry.
    rewrite (gmadd_entry _ _ _ n n _ _ i j HdM HnDS Hi Hj), zR_add.
    rewrite (gmap_entry _ _ _ n n _ i j HM Hi Hj), zR_mul.
    rewrite (gmap_entry _ _ _ n n _ i j HDS Hi Hj), zR_opp.
    rewrite (gmadd_entry _ _ _ n n _ _ i j HD HS Hi Hj), zR_add.
    rewrite (gtab_entry _ _ n _ i j Hi Hj). fold S.
    destruct (Nat.eqb i j); [|rewrite zR_zero]; unfold zentry; ring. }
  pose proof (zdominant_sound n Rz x Hn HR Hdom) as HRx.
  (* x^T R x = den x^T M x - e |x|^2 - x^T S x *)
  assert (Row : forall i, (i < n)%nat ->
            sumR n (fun j => zR (zentry Rz i j) * (x i * x j))
            = zR den * sumR n (fun j => zR (zentry M i j) * (x i * x j))
              - 1 * (zR e * (x i * x i)) - sumR n (fun j => zR (zentry S i j) * (x i * x j))).
  { intros i Hi.
    rewrite (sumR_ext n _ (fun j => zR den * (zR (zentry M i j) * (x i * x j))
              - 1 * ((if Nat.eqb i j then zR e else 0) * (x i * x j))
              - zR (zentry S i j) * (x i * x j)))
      by (intros j Hj; rewrite ER by assumption; ring).
    rewrite sumR_lin. f_equal. f_equal. f_equal.
    rewrite (sumR_split n i) by exact Hi. rewrite Nat.eqb_refl.
    rewrite (sumR_ext n _ (fun _ => 0)), sumR_zero; [ring|].
    intros j _. unfold offd. destruct (Nat.eqb_spec i j); [reflexivity | ring]. }
  assert (Split : qformZ n Rz x
                  = zR den * qformZ n M x - 1 * (zR e * sumR n (fun i => x i * x i))
                    - qformZ n S x).
  { unfold qformZ. rewrite (sumR_ext n _ _ Row), sumR_lin, sumR_scal. reflexivity. }
  (* x^T S x = sum_k d_k (l_k . x)^2 >= 0 *)
  assert (HSx0 : 0 <= qformZ n S0 x).
  { unfold qformZ.
    rewrite (sumR_ext n _ (fun i => sumR n (fun j => sumR K (fun k =>
               zR (nth k ds BigZ.zero) * ((zR (zentry L k i) * x i) * (zR (zentry L k j) * x j)))))).
    2: { intros i Hi. apply sumR_ext. intros j Hj. rewrite ES by assumption.
         rewrite <- sumR_scal_r. apply sumR_ext. intros k _. ring. }
    rewrite (sumR_ext n _ (fun i => sumR K (fun k => sumR n (fun j =>
               zR (nth k ds BigZ.zero) * ((zR (zentry L k i) * x i) * (zR (zentry L k j) * x j))))))
      by (intros; apply sumR_swap).
    rewrite sumR_swap. apply sumR_nonneg. intros k Hk.
    rewrite (sumR_ext n _ (fun i => (zR (nth k ds BigZ.zero) * (zR (zentry L k i) * x i))
               * sumR n (fun j => zR (zentry L k j) * x j)))
      by (intros; rewrite <- sumR_scal; apply sumR_ext; intros; ring).
    rewrite sumR_scal_r, sumR_scal.
    assert (0 <= zR (nth k ds BigZ.zero)).
    { rewrite forallb_forall in Hds. rewrite <- zR_zero. apply zR_leb, Hds, nth_In. lia. }
    assert (Hsq : 0 <= sumR n (fun i => zR (zentry L k i) * x i)
                       * sumR n (fun j => zR (zentry L k j) * x j)) by apply Rle_0_sqr.
    nra. }
  assert (HSx : 0 <= qformZ n S x).
  { replace (qformZ n S x) with (zR c * qformZ n S0 x); [apply Rmult_le_pos; assumption|].
    unfold qformZ. rewrite <- sumR_scal. apply sumR_ext. intros i Hi.
    rewrite <- sumR_scal. apply sumR_ext. intros j Hj. unfold S, zentry.
    rewrite (gmap_entry _ _ _ n n _ i j HS0 Hi Hj), zR_mul. ring. }
  lra.
Qed.

(** *** Data on machine words *)

(** An integer written on machine words: [Wp w] is w, [Wn w] is -w, [Wl neg second ws]
    is +-(w_0 + 2^62 w_1 + 2^124 w_2 + ...); [second] chooses the second of a matrix's
    two denominators. *)
Inductive wnum : Set :=
  | Wp (w : Uint63.int) | Wn (w : Uint63.int) | Wl (neg second : bool) (ws : list Uint63.int).

Definition wbase : Z := 4611686018427387904.

Fixpoint limbsZ (ws : list Uint63.int) : Z :=
  match ws with nil => 0%Z | w :: ws' => (Uint63.to_Z w + wbase * limbsZ ws')%Z end.

Definition wZ (x : wnum) : Z :=
  match x with
  | Wp w => Uint63.to_Z w
  | Wn w => Z.opp (Uint63.to_Z w)
  | Wl s _ ws => if s then Z.opp (limbsZ ws) else limbsZ ws
  end.

Definition wsecond (x : wnum) : bool := match x with Wl _ t _ => t | _ => false end.

(** A matrix as data: two denominators and its entries' numerators on machine words. *)
Definition wmat := (positive * positive * list (list wnum))%type.

Definition wq (d1 d2 : positive) (x : wnum) : Q := Qmake (wZ x) (if wsecond x then d2 else d1).

(** The rational matrix the data stands for (what the statement is about). *)
Definition qmatw (X : wmat) : matQ := let '(d1, d2, W) := X in map (map (wq d1 d2)) W.

Definition bw (w : Uint63.int) : BigZ.t_ := BigZ.Pos (BigN.N0 w).

Definition bbase : BigZ.t_ := BigZ.of_Z wbase.

Fixpoint limbsB (b : BigZ.t_) (ws : list Uint63.int) : BigZ.t_ :=
  match ws with nil => BigZ.zero | w :: ws' => BigZ.add (bw w) (BigZ.mul b (limbsB b ws')) end.

Definition wB (b : BigZ.t_) (x : wnum) : BigZ.t_ :=
  match x with
  | Wp w => bw w
  | Wn w => BigZ.opp (bw w)
  | Wl s _ ws => if s then BigZ.opp (limbsB b ws) else limbsB b ws
  end.

Lemma wB_spec x : zR (wB bbase x) = IZR (wZ x).
Proof.
  assert (L : forall ws, BigZ.to_Z (limbsB bbase ws) = limbsZ ws).
  { induction ws as [|w ws IH]; cbn [limbsB limbsZ]; [apply BigZ.spec_0|].
    rewrite BigZ.spec_add, BigZ.spec_mul, IH. unfold bbase. rewrite BigZ.spec_of_Z.
    reflexivity. }
  unfold zR. destruct x as [w|w|[|] t ws]; cbn [wB wZ].
  - reflexivity.
  - rewrite BigZ.spec_opp. reflexivity.
  - rewrite BigZ.spec_opp, L. reflexivity.
  - rewrite L. reflexivity.
Qed.

Definition zpos (d : positive) : BigZ.t_ := BigZ.of_Z (Zpos d).

Lemma zR_zpos d : zR (zpos d) = IZR (Zpos d).
Proof. unfold zR, zpos. rewrite BigZ.spec_of_Z. reflexivity. Qed.

(** The integer matrix [d1 d2 X] of the data. *)
Definition zmatw (X : wmat) : list (list BigZ.t_) :=
  let '(d1, d2, W) := X in
  let b1 := zpos d1 in let b2 := zpos d2 in let b := bbase in
  map (map (fun x => BigZ.mul (wB b x) (if wsecond x then b1 else b2))) W.

Definition wscale (X : wmat) : BigZ.t_ := let '(d1, d2, _) := X in BigZ.mul (zpos d1) (zpos d2).

Definition wshape_b (r c : nat) (X : wmat) : bool := let '(_, _, W) := X in gshape_b r c W.

Lemma map2_shape {A B : Type} (f : A -> B) r c W :
  gshape r c W -> gshape r c (map (map f) W).
Proof.
  intros [HW FW]. split; [rewrite map_length; exact HW|].
  rewrite Forall_forall in *. intros row Hin. apply in_map_iff in Hin as [row' [<- Hin]].
  rewrite map_length. apply FW, Hin.
Qed.

Lemma map2_entry {A B : Type} (f : A -> B) (za : A) (zb : B) r c W i j :
  gshape r c W -> (i < r)%nat -> (j < c)%nat ->
  nth j (nth i (map (map f) W) nil) zb = f (nth j (nth i W nil) za).
Proof.
  intros HW Hi Hj.
  rewrite (nth_indep _ nil (map f nil)) by (destruct HW; rewrite map_length; lia).
  rewrite (map_nth (map f) W nil i).
  rewrite (nth_indep _ zb (f za)) by (rewrite map_length, (gshape_row _ r c W i HW Hi); exact Hj).
  apply map_nth.
Qed.

Lemma repr_wmat r c X :
  wshape_b r c X = true -> repr r c (qmatw X) (zmatw X) (zR (wscale X)).
Proof.
  destruct X as [[d1 d2] W]. cbn [wshape_b qmatw zmatw wscale]. intros HW. apply gshape_b_sound in HW.
  split; [|split].
  - apply map2_shape, HW.
  - apply map2_shape, HW.
  - intros i j Hi Hj. unfold entry, zentry, gentry.
    rewrite (map2_entry _ (Wl false false nil) _ r c W i j HW Hi Hj).
    rewrite (map2_entry _ (Wl false false nil) _ r c W i j HW Hi Hj).
    set (x := nth j (nth i W nil) (Wl false false nil)).
    assert (IZR (Zpos d1) <> 0) by (apply not_0_IZR; discriminate).
    assert (IZR (Zpos d2) <> 0) by (apply not_0_IZR; discriminate).
    unfold wq, Q2R. destruct (wsecond x); cbn [Qnum Qden];
      rewrite !zR_mul, wB_spec, !zR_zpos; field; auto.
Qed.

(** The entries of a matrix's data over its first ([second = false]) or second
    denominator, as integers (0 elsewhere): [zmatw X = d2 zpart false X + d1 zpart true X]. *)
Definition zpart (second : bool) (X : wmat) : list (list BigZ.t_) :=
  let '(_, _, W) := X in let b := bbase in
  map (map (fun x => if Bool.eqb (wsecond x) second then wB b x else BigZ.zero)) W.

Lemma wshape_parts r c X :
  wshape_b r c X = true ->
  gshape r c (zmatw X) /\ gshape r c (zpart true X) /\ gshape r c (zpart false X).
Proof.
  destruct X as [[d1 d2] W]. cbn [wshape_b zmatw zpart]. intros HW.
  apply gshape_b_sound in HW. split; [|split]; apply map2_shape, HW.
Qed.

Lemma zpart_val r c X i j :
  wshape_b r c X = true -> (i < r)%nat -> (j < c)%nat ->
  zR (zentry (zmatw X) i j)
  = zR (zpos (fst (fst X))) * zR (zentry (zpart true X) i j)
    + zR (zpos (snd (fst X))) * zR (zentry (zpart false X) i j).
Proof.
  destruct X as [[d1 d2] W]. cbn [wshape_b zmatw zpart fst snd]. intros HW Hi Hj.
  apply gshape_b_sound in HW. unfold zentry, gentry.
  rewrite (map2_entry _ (Wl false false nil) _ r c W i j HW Hi Hj).
  rewrite (map2_entry _ (Wl false false nil) _ r c W i j HW Hi Hj).
  rewrite (map2_entry _ (Wl false false nil) _ r c W i j HW Hi Hj).
  destruct (wsecond (nth j (nth i W nil) (Wl false false nil))); cbn [Bool.eqb];
    rewrite ?zR_mul, ?zR_zero; ring.
Qed.

(** s P A, from the two parts of P's data (the long entries of P are few). *)
Definition zPA (A P : wmat) : list (list BigZ.t_) :=
  zadd (zscale (zpos (fst (fst P))) (zmm (zpart true P) (zmatw A)))
       (zscale (zpos (snd (fst P))) (zmm (zpart false P) (zmatw A))).

Lemma zPA_shape n A P :
  (0 < n)%nat -> wshape_b n n A = true -> wshape_b n n P = true -> gshape n n (zPA A P).
Proof.
  intros Hn HA HP. destruct (wshape_parts _ _ _ HA) as [SA _].
  destruct (wshape_parts _ _ _ HP) as [_ [S1 S2]]. unfold zPA, zadd, zscale, zmm.
  apply gmadd_shape; apply gmap_shape; eapply gmm_shape; eassumption.
Qed.

Lemma zPA_val n A P i j :
  (0 < n)%nat -> wshape_b n n A = true -> wshape_b n n P = true -> (i < n)%nat -> (j < n)%nat ->
  zR (zentry (zPA A P) i j)
  = sumR n (fun t => zR (zentry (zmatw P) i t) * zR (zentry (zmatw A) t j)).
Proof.
  intros Hn HA HP Hi Hj. destruct (wshape_parts _ _ _ HA) as [SA _].
  destruct (wshape_parts _ _ _ HP) as [_ [S1 S2]].
  pose proof (gmm_shape _ BigZ.zero zdot n n n _ _ S1 SA Hn) as M1.
  pose proof (gmm_shape _ BigZ.zero zdot n n n _ _ S2 SA Hn) as M2.
  pose proof (gmap_shape _ (BigZ.mul (zpos (fst (fst P)))) n n _ M1) as N1.
  pose proof (gmap_shape _ (BigZ.mul (zpos (snd (fst P)))) n n _ M2) as N2.
  unfold zPA, zadd, zscale. unfold zentry at 1.
  rewrite (gmadd_entry _ _ _ n n _ _ i j N1 N2 Hi Hj), zR_add.
  rewrite (gmap_entry _ _ _ n n _ i j M1 Hi Hj), (gmap_entry _ _ _ n n _ i j M2 Hi Hj).
  rewrite !zR_mul.
  change (gentry BigZ.zero (gmm BigZ.zero zdot (zpart true P) (zmatw A)) i j)
    with (zentry (zmm (zpart true P) (zmatw A)) i j).
  change (gentry BigZ.zero (gmm BigZ.zero zdot (zpart false P) (zmatw A)) i j)
    with (zentry (zmm (zpart false P) (zmatw A)) i j).
  rewrite (zmm_val n n n _ _ i j S1 SA Hn Hi Hj), (zmm_val n n n _ _ i j S2 SA Hn Hi Hj).
  rewrite <- !sumR_scal, <- sumR_plus. apply sumR_ext. intros t Ht.
  rewrite (zpart_val n n P i t HP Hi Ht). ring.
Qed.

(** A small matrix given as rationals (the feedthrough D, maybe shifted), checked equal to
    integers over one denominator: [Qnum D_ij * dD = W_ij * Qden D_ij]. *)
Definition dcheck (m : nat) (D : matQ) (dD : positive) (W : list (list wnum)) : bool :=
  has_shape_b m m D && gshape_b m m W &&
  forallb (fun i => forallb (fun j =>
     Z.eqb (Qnum (entry D i j) * Zpos dD)
           (wZ (nth j (nth i W nil) (Wl false false nil)) * Zpos (Qden (entry D i j))))
     (seq 0 m)) (seq 0 m).

Lemma repr_dcheck m D dD W :
  dcheck m D dD W = true -> repr m m D (map (map (wB bbase)) W) (zR (zpos dD)).
Proof.
  unfold dcheck. rewrite !andb_true_iff. intros [[HD HW] H].
  apply has_shape_b_sound in HD. apply gshape_b_sound in HW.
  split; [exact HD | split; [apply map2_shape, HW|]].
  intros i j Hi Hj. unfold zentry, gentry.
  rewrite (map2_entry _ (Wl false false nil) _ m m W i j HW Hi Hj), wB_spec, zR_zpos.
  pose proof (forallb_seq _ m (forallb_seq _ m H i Hi) j Hj) as E. cbv beta in E.
  apply Z.eqb_eq in E. destruct (entry D i j) as [a b]. cbn [Qnum Qden] in E.
  unfold Q2R. cbn [Qnum Qden].
  assert (Hb : IZR (Zpos b) <> 0) by (apply not_0_IZR; discriminate).
  apply (f_equal IZR) in E. rewrite !mult_IZR in E.
  apply (Rmult_eq_reg_r (IZR (Zpos b))); [|exact Hb].
  transitivity (IZR a * IZR (Zpos dD)); [field; exact Hb | rewrite E; ring].
Qed.

Fixpoint zeql (u v : list BigZ.t_) : bool :=
  match u, v with
  | nil, nil => true
  | a :: u', b :: v' => BigZ.eqb a b && zeql u' v'
  | _, _ => false
  end.

Fixpoint zeqm (X Y : list (list BigZ.t_)) : bool :=
  match X, Y with
  | nil, nil => true
  | r :: X', s :: Y' => zeql r s && zeqm X' Y'
  | _, _ => false
  end.

Lemma zeql_nth u v j : zeql u v = true -> zR (nth j u BigZ.zero) = zR (nth j v BigZ.zero).
Proof.
  revert v j; induction u as [|a u IH]; intros [|b v] j H; cbn [zeql] in H; try discriminate.
  - reflexivity.
  - apply andb_true_iff in H as [H1 H2]. destruct j; cbn [nth]; [|apply IH, H2].
    unfold zR. rewrite BigZ.spec_eqb in H1. apply Z.eqb_eq in H1. rewrite H1.
    reflexivity.
Qed.

Lemma zeqm_entry X Y i j : zeqm X Y = true -> zR (zentry X i j) = zR (zentry Y i j).
Proof.
  revert Y i; induction X as [|r X IH]; intros [|s Y] i H; cbn [zeqm] in H; try discriminate.
  - reflexivity.
  - apply andb_true_iff in H as [H1 H2]. unfold zentry, gentry. destruct i; cbn [nth].
    + apply zeql_nth, H1.
    + apply IH, H2.
Qed.

(** A witness on machine words: [(e, den, weights, vectors)]. *)
Definition wwit := (wnum * wnum * wnum * list wnum * list (list wnum))%type.

Definition wpsd_check (n : nat) (M : list (list BigZ.t_)) (w : wwit) : bool :=
  let '(e, den, c, ds, L) := w in
  let b := bbase in
  zpsd_check n M (wB b e) (wB b den) (wB b c) (map (wB b) ds) (map (map (wB b)) L).

Definition wwit_e (w : wwit) : BigZ.t_ := let '(e, _, _, _, _) := w in wB bbase e.

Lemma wpsd_check_sound n M w :
  wpsd_check n M w = true ->
  exists e den, zR e = zR (wwit_e w) /\ 0 <= zR e /\ 0 < zR den /\
  forall x, zR e * sumR n (fun i => x i * x i) <= zR den * qformZ n M x.
Proof.
  destruct w as [[[[e den] c] ds] L]. unfold wpsd_check. intros H.
  exists (wB bbase e), (wB bbase den). split; [reflexivity|].
  pose proof H as H'. unfold zpsd_check in H'. rewrite !andb_true_iff in H'.
  destruct H' as [[[[[[[[[He Hd] _] _] _] _] _] _] _] _]. apply zR_ltb in Hd.
  apply zR_leb in He. rewrite zR_zero in Hd, He. split; [exact He|]. split; [exact Hd|].
  exact (zpsd_check_sound _ _ _ _ _ _ _ H).
Qed.

(** The whole check of [kyp_certified], on integers: the data of A, B, C, P on machine
    words (two denominators each), D as rationals with its integers, and the witnesses
    for [P > 0] and [-M(P) >= 0] on the integer matrices [Pz = s P] and
    [Mz = L M(P)]. *)
Definition kyp_wcheck (n m : nat) (A B C : wmat) (D : matQ) (dD : positive)
    (WD : list (list wnum)) (P : wmat) (wP wM : wwit) : bool :=
  let Az := zmatw A in let Bz := zmatw B in let Cz := zmatw C in let Pz := zmatw P in
  let Dz := map (map (wB bbase)) WD in
  Nat.ltb 0 n && Nat.ltb 0 m
  && wshape_b n n A && wshape_b n m B && wshape_b m n C && wshape_b n n P
  && dcheck m D dD WD
  && zeqm Pz (ztr Pz)
  && BigZ.ltb BigZ.zero (wwit_e wP) && wpsd_check n Pz wP
  && let PA := zPA A P in
     wpsd_check (n + m)
       (zneg (zkyp (zadd (ztr PA) PA) Bz Cz Dz Pz (wscale A) (wscale B) (wscale C) (zpos dD)
                   (wscale P))) wM.

Lemma repr_pos r c X Xz s : 0 < s -> repr r c X Xz s -> forall i j, (i < r)%nat -> (j < c)%nat ->
  Q2R (entry X i j) = zR (zentry Xz i j) / s.
Proof. intros Hs [_ [_ E]] i j Hi Hj. rewrite <- (E i j Hi Hj). field. lra. Qed.

Lemma zR_scale_pos X : 0 < zR (wscale X).
Proof.
  destruct X as [[d1 d2] W]. cbn [wscale]. rewrite zR_mul, !zR_zpos.
  apply Rmult_lt_0_compat; apply IZR_lt; reflexivity.
Qed.

Theorem kyp_wcheck_sound n m A B C D dD WD P wP wM :
  kyp_wcheck n m A B C D dD WD P wP wM = true ->
  kyp_certified n m (qmatw A) (qmatw B) (qmatw C) D (qmatw P).
Proof.
  unfold kyp_wcheck. rewrite !andb_true_iff.
  intros [[[[[[[[[[Hn Hm] HA] HB] HC] HP] HD] Hsym] HeP] HwP] HwM].
  apply Nat.ltb_lt in Hn. apply Nat.ltb_lt in Hm.
  pose proof (repr_wmat _ _ _ HA) as RA. pose proof (repr_wmat _ _ _ HB) as RB.
  pose proof (repr_wmat _ _ _ HC) as RC. pose proof (repr_wmat _ _ _ HP) as RP.
  pose proof (repr_dcheck _ _ _ _ HD) as RD.
  (* the top-left block, computed as X^T + X with X = s P A *)
  assert (RTL : repr n n (madd (mmul (tr (qmatw A)) (qmatw P)) (mmul (qmatw P) (qmatw A)))
                  (zadd (ztr (zPA A P)) (zPA A P)) (zR (wscale A) * zR (wscale P))).
  { pose proof (repr_add _ _ _ _ _ _ _
      (repr_mm n n n _ _ _ _ _ _ Hn (repr_tr n n _ _ _ Hn RA) RP)
      (repr_s _ _ _ _ _ _ (Rmult_comm _ _) (repr_mm n n n _ _ _ _ _ _ Hn RP RA))) as R0.
    destruct (wshape_parts _ _ _ HA) as [SA _]. destruct (wshape_parts _ _ _ HP) as [SP _].
    pose proof (zPA_shape n A P Hn HA HP) as SPA.
    pose proof (gtr_shape _ BigZ.zero n n _ SPA Hn) as SPAt.
    apply (repr_ext _ _ _ _ _ _ R0).
    - apply gmadd_shape; assumption.
    - intros i j Hi Hj. unfold zadd, zentry.
      rewrite (gmadd_entry _ _ _ n n _ _ i j SPAt SPA Hi Hj).
      pose proof (gtr_shape _ BigZ.zero n n _ SA Hn) as SAt.
      pose proof (gmm_shape _ BigZ.zero zdot n n n _ _ SAt SP Hn) as M1.
      pose proof (gmm_shape _ BigZ.zero zdot n n n _ _ SP SA Hn) as M2.
      rewrite (gmadd_entry _ _ _ n n _ _ i j M1 M2 Hi Hj), !zR_add.
      rewrite (gtr_entry _ _ n n _ i j SPA Hn Hi Hj).
      change (gentry BigZ.zero (zPA A P) j i) with (zentry (zPA A P) j i).
      change (gentry BigZ.zero (zPA A P) i j) with (zentry (zPA A P) i j).
      change (gentry BigZ.zero (gmm BigZ.zero zdot (gtr BigZ.zero (zmatw A)) (zmatw P)) i j)
        with (zentry (zmm (ztr (zmatw A)) (zmatw P)) i j).
      change (gentry BigZ.zero (gmm BigZ.zero zdot (zmatw P) (zmatw A)) i j)
        with (zentry (zmm (zmatw P) (zmatw A)) i j).
      rewrite (zPA_val n A P i j Hn HA HP Hi Hj), (zPA_val n A P j i Hn HA HP Hj Hi).
      rewrite (zmm_val n n n (ztr (zmatw A)) (zmatw P) i j SAt SP Hn Hi Hj).
      rewrite (zmm_val n n n (zmatw P) (zmatw A) i j SP SA Hn Hi Hj).
      f_equal. apply sumR_ext. intros t Ht.
      rewrite (zeqm_entry _ _ t j Hsym). unfold ztr, zentry.
      rewrite (gtr_entry _ _ n n _ t j SP Hn Ht Hj), (gtr_entry _ _ n n _ i t SA Hn Hi Ht).
      ring. }
  pose proof (repr_kyp n m _ _ _ _ _ _ _ _ _ _ _ _ _ _ _ Hn Hm RTL RB RC RD RP) as RK.
  apply repr_neg in RK.
  assert (Hs : 0 < zR (wscale P)) by apply zR_scale_pos.
  assert (HL : 0 < zR (wscale A) * zR (wscale P) * zR (wscale B) * zR (wscale C)
                   * zR (zpos dD)).
  { pose proof (zR_scale_pos A). pose proof (zR_scale_pos B). pose proof (zR_scale_pos C).
    assert (0 < zR (zpos dD)) by (rewrite zR_zpos; apply IZR_lt; reflexivity).
    repeat apply Rmult_lt_0_compat; assumption. }
  destruct RA as [SA _]. destruct RB as [SB _]. destruct RC as [SC _].
  pose proof RP as [SP _]. pose proof RD as [SD _].
  split; [exact SA|]. split; [exact SB|]. split; [exact SC|]. split; [exact SD|].
  split; [exact SP|]. split; [|split].
  - (* P = P^T *)
    intros i j Hi Hj. apply eqR_Qeq.
    rewrite (repr_pos _ _ _ _ _ Hs RP i j Hi Hj), (repr_pos _ _ _ _ _ Hs RP j i Hj Hi).
    rewrite (zeqm_entry _ _ i j Hsym). unfold ztr, zentry.
    destruct RP as [_ [ZP _]]. rewrite (gtr_entry _ _ n n _ i j ZP Hn Hi Hj). reflexivity.
  - (* P > 0 *)
    intros x [k [Hk Hx]]. apply wpsd_check_sound in HwP as [e [den [He [_ [Hden Hq]]]]].
    apply zR_ltb in HeP. rewrite zR_zero, <- He in HeP.
    pose proof (Hq x) as Hq. rewrite <- (qform_repr _ _ _ _ x RP) in Hq.
    assert (0 < sumR n (fun i => x i * x i)).
    { apply (sumR_pos n _ k); [intros; apply Rle_0_sqr | exact Hk |].
      destruct (Rlt_dec 0 (x k)) as [Hp|Hp]; [nra|]. assert (x k < 0) by lra. nra. }
    assert (0 < zR e * sumR n (fun i => x i * x i)) by (apply Rmult_lt_0_compat; lra).
    assert (0 < zR den * (qform n (qmatw P) x * zR (wscale P))) by lra.
    assert (0 < qform n (qmatw P) x * zR (wscale P)).
    { apply (Rmult_lt_reg_l (zR den)); lra. }
    apply (Rmult_lt_reg_r (zR (wscale P))); lra.
  - (* M(P) <= 0 *)
    intros x. apply wpsd_check_sound in HwM as [e [den [_ [He [Hden Hq]]]]].
    pose proof (Hq x) as Hq. unfold zneg in Hq. rewrite <- (qform_repr _ _ _ _ x RK) in Hq.
    assert (0 <= zR e * sumR (n + m) (fun i => x i * x i)).
    { apply Rmult_le_pos; [exact He | apply sumR_nonneg; intros; apply Rle_0_sqr]. }
    assert (Hneg : qform (n + m) (mneg (kyp (qmatw A) (qmatw B) (qmatw C) D (qmatw P))) x
                   = - qform (n + m) (kyp (qmatw A) (qmatw B) (qmatw C) D (qmatw P)) x).
    { unfold qform. rewrite <- sumR_opp. apply sumR_ext. intros i _.
      rewrite <- sumR_opp. apply sumR_ext. intros j _.
      rewrite entry_mneg, Q2R_opp. ring. }
    rewrite Hneg in Hq.
    set (q := qform (n + m) (kyp (qmatw A) (qmatw B) (qmatw C) D (qmatw P)) x) in *.
    set (Ls := zR (wscale A) * zR (wscale P) * zR (wscale B) * zR (wscale C) * zR (zpos dD)) in *.
    assert (0 <= zR den * (- q * Ls)) by lra.
    assert (0 <= - q * Ls).
    { destruct (Rle_dec 0 (- q * Ls)) as [Hok|Hno]; [exact Hok|].
      assert (zR den * (- q * Ls) < 0) by nra. lra. }
    destruct (Rle_dec q 0) as [Hok|Hno]; [exact Hok|].
    assert (- q * Ls < 0) by nra. lra.
Qed.
