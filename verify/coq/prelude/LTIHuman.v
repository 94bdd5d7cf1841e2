(** * The human as an LTI system along a solution: its storage from a KYP certificate

    The paper's Section 4 identifies the operator as a linear model H with a
    realisation x' = A x + B u, y = C x + D u, and Theorem 1 needs the human to be
    passive (Assumption 1, item 5) with a storage function.  Here the realisation is the
    rational data of a KYP certificate unit ([QCert.v]: [matQ], read into the reals
    entry by entry through [Q2R]) and the state is a trajectory [x : R -> nat -> R]
    (coordinates [0 .. n-1]).  Proved once, for every [n], [m] and every solution:
    if [kyp_certified n m A B C D P] then [S = x^T P x / 2] is differentiable with
    [S' = (P x) . (A x + B u)], and
    [S' - u . y = (1/2) [x; u]^T M(P) [x; u] <= 0] ([storage_supply_identity],
    [storage_dissipation]), [S >= 0] ([storage_nonneg]), and [c |x|^2 <= 2 S] for some
    [c > 0] ([storage_coercive]: a positive definite form is coercive, [pd_coercive], by
    induction on the dimension with the Schur complement), so a bounded storage bounds
    the state.

    Only the statements of [QCert.v] are used ([kyp_certified], [kyp] and the matrix
    operations it is written with, [qform], [pos_def], [neg_semidef], [symmetric]), and
    the meaning of its matrix operations over the reals, proved here entry by entry
    from their definitions ([entry_mmul], [entry_tr], [entry_madd], [entry_block]). *)

From Coq Require Import QArith Qreals Reals List Lra Lia Psatz.
Import ListNotations.
Local Set Warnings "-ambiguous-paths -notation-overridden".
From Coquelicot Require Import Coquelicot.
From VerifyCoq Require Import QCert Traj.
Open Scope R_scope.

(** ** The rational matrices over the reals *)


Lemma nth_map' {X Y : Type} (g : X -> Y) (l : list X) j d d' :
  (j < length l)%nat -> nth j (map g l) d = g (nth j l d').
Proof. intros H. rewrite (nth_indep _ d (g d')) by (rewrite map_length; exact H). apply map_nth. Qed.

Lemma shape_row r c M i : has_shape r c M -> (i < r)%nat -> length (nth i M nil) = c.
Proof. intros [HL HF] Hi. rewrite Forall_forall in HF. apply HF, nth_In. lia. Qed.

Lemma ncols_shape r c M : has_shape r c M -> (0 < r)%nat -> ncols M = c.
Proof.
  intros [HL HF] Hr. destruct M as [|row M]; simpl in HL; [lia|].
  unfold ncols; simpl. inversion HF; assumption.
Qed.

Lemma nth_tr k c B j : has_shape k c B -> (0 < k)%nat -> (j < c)%nat ->
  nth j (QCert.tr B) nil = map (fun row => nth j row 0%Q) B.
Proof.
  intros HB Hk Hj. pose proof (ncols_shape k c B HB Hk) as Hc.
  unfold QCert.tr. rewrite Hc.
  rewrite (nth_map' _ _ j nil 0%nat) by (rewrite seq_length; exact Hj).
  rewrite seq_nth by exact Hj. reflexivity.
Qed.

Lemma has_shape_tr r c M : has_shape r c M -> (0 < r)%nat -> has_shape c r (QCert.tr M).
Proof.
  intros HS Hr. pose proof (ncols_shape r c M HS Hr) as Hc. destruct HS as [HL HF].
  unfold QCert.tr. rewrite Hc. split; [rewrite map_length, seq_length; reflexivity|].
  apply Forall_forall. intros row Hin. apply in_map_iff in Hin. destruct Hin as [j [<- _]].
  rewrite map_length. exact HL.
Qed.

Lemma entry_tr r c M i j : has_shape r c M -> (0 < r)%nat -> (i < c)%nat -> (j < r)%nat ->
  entry (QCert.tr M) i j = entry M j i.
Proof.
  intros HS Hr Hi Hj. unfold entry at 1. rewrite (nth_tr r c M i HS Hr Hi).
  rewrite (nth_map' _ _ j 0%Q nil) by (destruct HS; lia). reflexivity.
Qed.

Lemma has_shape_mmul r k c A B :
  has_shape r k A -> has_shape k c B -> (0 < k)%nat -> has_shape r c (QCert.mmul A B).
Proof.
  intros [HL HF] HB Hk. destruct (has_shape_tr k c B HB Hk) as [HTL _].
  unfold QCert.mmul; cbv zeta. split; [rewrite map_length; exact HL|].
  apply Forall_forall. intros row Hin. apply in_map_iff in Hin. destruct Hin as [a [<- _]].
  rewrite map_length. exact HTL.
Qed.

Lemma sumR_shift k f : sumR (S k) f = f 0%nat + sumR k (fun l => f (S l)).
Proof. induction k; simpl; [lra|]. simpl in IHk. rewrite IHk. lra. Qed.

Lemma dotR_sum u v : length u = length v ->
  dotR u v = sumR (length u) (fun l => Q2R (nth l u 0%Q) * Q2R (nth l v 0%Q)).
Proof.
  revert v. induction u as [|a u IH]; intros [|b v] H; simpl in H; try discriminate.
  - reflexivity.
  - cbn [length]. rewrite sumR_shift. cbn [dotR]. rewrite (IH v) by lia. reflexivity.
Qed.

(** The entries of the data as real numbers. *)
Definition mR (M : matQ) (i j : nat) : R := Q2R (entry M i j).

Lemma entry_mmul r k c A B i j :
  has_shape r k A -> has_shape k c B -> (0 < k)%nat -> (i < r)%nat -> (j < c)%nat ->
  Q2R (entry (QCert.mmul A B) i j) = sumR k (fun l => mR A i l * mR B l j).
Proof.
  intros HA HB Hk Hi Hj. pose proof (has_shape_tr k c B HB Hk) as [HTL _].
  unfold entry at 1, QCert.mmul; cbv zeta.
  rewrite (nth_map' _ A i nil nil) by (destruct HA; lia).
  rewrite (nth_map' _ _ j 0%Q nil) by lia.
  rewrite Q2R_dot, (nth_tr k c B j HB Hk Hj).
  rewrite dotR_sum by (rewrite map_length, (shape_row r k A i HA Hi); destruct HB; lia).
  rewrite (shape_row r k A i HA Hi). apply sumR_ext. intros l Hl. unfold mR, entry.
  rewrite (nth_map' _ B l 0%Q nil) by (destruct HB; lia). reflexivity.
Qed.

Lemma nth_madd A B i : (i < length A)%nat -> (i < length B)%nat ->
  nth i (QCert.madd A B) nil = zipw qadd (nth i A nil) (nth i B nil).
Proof.
  revert B i. induction A as [|r A IH]; intros [|s B] i HA HB; simpl in *; try lia.
  destruct i; [reflexivity|]. apply IH; lia.
Qed.

Lemma nth_zipw f u v j : (j < length u)%nat -> (j < length v)%nat ->
  nth j (zipw f u v) 0%Q = f (nth j u 0%Q) (nth j v 0%Q).
Proof.
  revert v j. induction u as [|a u IH]; intros [|b v] j Hu Hv; simpl in *; try lia.
  destruct j; [reflexivity|]. apply IH; lia.
Qed.

Lemma length_zipw f u v : length (zipw f u v) = Nat.min (length u) (length v).
Proof. revert v. induction u as [|a u IH]; intros [|b v]; simpl; auto. Qed.

Lemma has_shape_madd r c A B : has_shape r c A -> has_shape r c B -> has_shape r c (QCert.madd A B).
Proof.
  revert r B. induction A as [|a A IH]; intros r [|b B] [HLA HFA] [HLB HFB];
    simpl in *; subst r; try discriminate.
  - split; [reflexivity | constructor].
  - injection HLB as HLB. inversion HFA as [|? ? Ha HFA']; inversion HFB as [|? ? Hb HFB']; subst.
    destruct (IH (length A) B (conj eq_refl HFA') (conj HLB HFB')) as [H1 H2].
    split; [simpl; congruence|]. constructor; [rewrite length_zipw; lia | exact H2].
Qed.

Lemma entry_madd r c A B i j :
  has_shape r c A -> has_shape r c B -> (i < r)%nat -> (j < c)%nat ->
  Q2R (entry (QCert.madd A B) i j) = mR A i j + mR B i j.
Proof.
  intros HA HB Hi Hj. unfold entry at 1. rewrite nth_madd by (destruct HA, HB; lia).
  rewrite nth_zipw by (rewrite ?(shape_row r c A i HA Hi), ?(shape_row r c B i HB Hi); lia).
  apply Q2R_qadd.
Qed.

Lemma has_shape_mneg r c M : has_shape r c M -> has_shape r c (QCert.mneg M).
Proof.
  intros [HL HF]. unfold QCert.mneg. split; [rewrite map_length; exact HL|].
  apply Forall_forall. intros row Hin. apply in_map_iff in Hin. destruct Hin as [a [<- Ha]].
  rewrite map_length. rewrite Forall_forall in HF. apply HF, Ha.
Qed.

Lemma mR_mneg M i j : mR (QCert.mneg M) i j = - mR M i j.
Proof. unfold mR. rewrite entry_mneg. apply Q2R_opp. Qed.

Lemma nth_hcat A B i : (i < length A)%nat -> (i < length B)%nat ->
  nth i (hcat A B) nil = nth i A nil ++ nth i B nil.
Proof.
  revert B i. induction A as [|r A IH]; intros [|s B] i HA HB; simpl in *; try lia.
  destruct i; [reflexivity|]. apply IH; lia.
Qed.

Lemma length_hcat A B : length (hcat A B) = Nat.min (length A) (length B).
Proof. revert B. induction A as [|a A IH]; intros [|b B]; simpl; auto. Qed.

(** The four blocks of [block TL TR BL BR]. *)
Lemma entry_block r1 r2 c1 c2 TL TR BL BR i j :
  has_shape r1 c1 TL -> has_shape r1 c2 TR -> has_shape r2 c1 BL -> has_shape r2 c2 BR ->
  (i < r1 + r2)%nat -> (j < c1 + c2)%nat ->
  entry (block TL TR BL BR) i j =
  if Nat.ltb i r1 then (if Nat.ltb j c1 then entry TL i j else entry TR i (j - c1))
  else (if Nat.ltb j c1 then entry BL (i - r1) j else entry BR (i - r1) (j - c1)).
Proof.
  intros HTL HTR HBL HBR Hi Hj. unfold block, entry.
  assert (L1 : length (hcat TL TR) = r1)
    by (rewrite length_hcat; destruct HTL as [-> _], HTR as [-> _]; lia).
  destruct (Nat.ltb_spec i r1) as [Hr|Hr].
  - rewrite app_nth1 by lia. rewrite nth_hcat by (destruct HTL, HTR; lia).
    destruct (Nat.ltb_spec j c1) as [Hc|Hc].
    + rewrite app_nth1 by (rewrite (shape_row r1 c1 TL i HTL Hr); lia). reflexivity.
    + rewrite app_nth2 by (rewrite (shape_row r1 c1 TL i HTL Hr); lia).
      rewrite (shape_row r1 c1 TL i HTL Hr). reflexivity.
  - rewrite app_nth2 by lia. rewrite L1.
    rewrite nth_hcat by (destruct HBL, HBR; lia).
    destruct (Nat.ltb_spec j c1) as [Hc|Hc].
    + rewrite app_nth1 by (rewrite (shape_row r2 c1 BL (i - r1) HBL ltac:(lia)); lia).
      reflexivity.
    + rewrite app_nth2 by (rewrite (shape_row r2 c1 BL (i - r1) HBL ltac:(lia)); lia).
      rewrite (shape_row r2 c1 BL (i - r1) HBL ltac:(lia)). reflexivity.
Qed.

(** ** Bilinear forms and matrix-vector products over the reals *)

Definition rowsum (c : nat) (M : matQ) (y : nat -> R) (i : nat) : R :=
  sumR c (fun j => mR M i j * y j).
Definition colsum (r : nat) (M : matQ) (x : nat -> R) (j : nat) : R :=
  sumR r (fun i => mR M i j * x i).
(** [x^T M y] for [M] with [r] rows and [c] columns. *)
Definition bf (r c : nat) (M : matQ) (x y : nat -> R) : R :=
  sumR r (fun i => sumR c (fun j => mR M i j * (x i * y j))).
(** [x . y] in [R^k]. *)
Definition vdotn (k : nat) (x y : nat -> R) : R := sumR k (fun i => x i * y i).

Lemma qform_bf n M x : qform n M x = bf n n M x x.
Proof. reflexivity. Qed.

Lemma vdotn_ext k x y x' y' :
  (forall i, (i < k)%nat -> x i = x' i) -> (forall i, (i < k)%nat -> y i = y' i) ->
  vdotn k x y = vdotn k x' y'.
Proof. intros Hx Hy. apply sumR_ext. intros i Hi. rewrite Hx, Hy by exact Hi. reflexivity. Qed.

Lemma vdotn_comm k x y : vdotn k x y = vdotn k y x.
Proof. apply sumR_ext. intros. ring. Qed.

Lemma vdotn_plus_r k x y z : vdotn k x (fun i => y i + z i) = vdotn k x y + vdotn k x z.
Proof. unfold vdotn. rewrite <- sumR_plus. apply sumR_ext. intros. ring. Qed.

Lemma bf_rows r c M x y : bf r c M x y = vdotn r x (rowsum c M y).
Proof.
  apply sumR_ext. intros i _. unfold rowsum. rewrite <- sumR_scal.
  apply sumR_ext. intros. ring.
Qed.

Lemma bf_cols r c M x y : bf r c M x y = vdotn c (colsum r M x) y.
Proof.
  unfold bf, vdotn, colsum. rewrite sumR_swap. apply sumR_ext. intros j _.
  rewrite <- sumR_scal_r. apply sumR_ext. intros. ring.
Qed.

Lemma bf_madd r c A B x y : has_shape r c A -> has_shape r c B ->
  bf r c (QCert.madd A B) x y = bf r c A x y + bf r c B x y.
Proof.
  intros HA HB. unfold bf. rewrite <- sumR_plus. apply sumR_ext. intros i Hi.
  rewrite <- sumR_plus. apply sumR_ext. intros j Hj. unfold mR at 1.
  rewrite (entry_madd r c A B i j HA HB Hi Hj). ring.
Qed.

Lemma bf_mneg r c M x y : bf r c (QCert.mneg M) x y = - bf r c M x y.
Proof.
  unfold bf. rewrite <- sumR_opp. apply sumR_ext. intros i _.
  rewrite <- sumR_opp. apply sumR_ext. intros j _. rewrite mR_mneg. ring.
Qed.

Lemma bf_msub r c A B x y : has_shape r c A -> has_shape r c B ->
  bf r c (QCert.msub A B) x y = bf r c A x y - bf r c B x y.
Proof.
  intros HA HB. unfold QCert.msub. rewrite (bf_madd r c) by (auto using has_shape_mneg).
  rewrite bf_mneg. ring.
Qed.

Lemma bf_tr r c M x y : has_shape r c M -> (0 < r)%nat ->
  bf c r (QCert.tr M) x y = bf r c M y x.
Proof.
  intros HS Hr. unfold bf. rewrite sumR_swap. apply sumR_ext. intros i Hi.
  apply sumR_ext. intros j Hj. unfold mR. rewrite (entry_tr r c M j i HS Hr Hj Hi). ring.
Qed.

Lemma bf_mmul r k c F G x y : has_shape r k F -> has_shape k c G -> (0 < k)%nat ->
  bf r c (QCert.mmul F G) x y = vdotn k (colsum r F x) (rowsum c G y).
Proof.
  intros HF HG Hk. unfold bf, vdotn, colsum, rowsum.
  transitivity (sumR r (fun i => sumR c (fun j =>
                  sumR k (fun l => (mR F i l * x i) * (mR G l j * y j))))).
  { apply sumR_ext. intros i Hi. apply sumR_ext. intros j Hj. unfold mR at 1.
    rewrite (entry_mmul r k c F G i j HF HG Hk Hi Hj), <- sumR_scal_r.
    apply sumR_ext. intros. ring. }
  rewrite (sumR_ext r _ (fun i => sumR k (fun l => sumR c (fun j =>
             (mR F i l * x i) * (mR G l j * y j))))) by (intros; apply sumR_swap).
  rewrite sumR_swap. apply sumR_ext. intros l _. rewrite <- sumR_scal_r.
  apply sumR_ext. intros i _. rewrite <- sumR_scal. reflexivity.
Qed.

Lemma colsum_tr r c M x j : has_shape r c M -> (0 < r)%nat -> (j < r)%nat ->
  colsum c (QCert.tr M) x j = rowsum c M x j.
Proof.
  intros HS Hr Hj. apply sumR_ext. intros i Hi. unfold mR.
  rewrite (entry_tr r c M i j HS Hr Hi Hj). reflexivity.
Qed.

Lemma colsum_sym n P x j : symmetric n P -> (j < n)%nat -> colsum n P x j = rowsum n P x j.
Proof.
  intros HS Hj. apply sumR_ext. intros i Hi. unfold mR.
  rewrite (Qeq_eqR _ _ (HS i j Hi Hj)). reflexivity.
Qed.

(** ** The KYP matrix as a quadratic form *)

(** [[x; u]]: the first [n] coordinates from [x], the next from [u]. *)
Definition join (n : nat) (x u : nat -> R) (i : nat) : R :=
  if Nat.ltb i n then x i else u (i - n)%nat.

Lemma sumR_app n m f : sumR (n + m) f = sumR n f + sumR m (fun j => f (n + j)%nat).
Proof.
  induction m; simpl; [rewrite Nat.add_0_r; lra|].
  rewrite Nat.add_succ_r. simpl. rewrite IHm. lra.
Qed.

Lemma qform_block n m TL TR BL BR x u :
  has_shape n n TL -> has_shape n m TR -> has_shape m n BL -> has_shape m m BR ->
  qform (n + m) (block TL TR BL BR) (join n x u)
  = bf n n TL x x + bf n m TR x u + bf m n BL u x + bf m m BR u u.
Proof.
  intros HTL HTR HBL HBR. unfold qform.
  rewrite sumR_app.
  assert (E : forall i j, (i < n + m)%nat -> (j < n + m)%nat ->
            Q2R (entry (block TL TR BL BR) i j) * (join n x u i * join n x u j)
            = if Nat.ltb i n then (if Nat.ltb j n then mR TL i j * (x i * x j)
                                   else mR TR i (j - n) * (x i * u (j - n)%nat))
              else (if Nat.ltb j n then mR BL (i - n) j * (u (i - n)%nat * x j)
                    else mR BR (i - n) (j - n) * (u (i - n)%nat * u (j - n)%nat))).
  { intros i j Hi Hj. rewrite (entry_block n m n m TL TR BL BR i j) by assumption.
    unfold join, mR. destruct (Nat.ltb i n), (Nat.ltb j n); reflexivity. }
  rewrite (sumR_ext n _ (fun i => sumR n (fun j => mR TL i j * (x i * x j))
                                   + sumR m (fun j => mR TR i j * (x i * u j)))).
  2: { intros i Hi. rewrite sumR_app. f_equal.
       - apply sumR_ext. intros j Hj. rewrite E by lia.
         destruct (Nat.ltb_spec i n); [|lia]. destruct (Nat.ltb_spec j n); [reflexivity|lia].
       - apply sumR_ext. intros j Hj. rewrite E by lia.
         destruct (Nat.ltb_spec i n); [|lia]. destruct (Nat.ltb_spec (n + j) n); [lia|].
         replace (n + j - n)%nat with j by lia. reflexivity. }
  rewrite (sumR_ext m _ (fun i => sumR n (fun j => mR BL i j * (u i * x j))
                                  + sumR m (fun j => mR BR i j * (u i * u j)))).
  2: { intros i Hi. rewrite sumR_app. f_equal.
       - apply sumR_ext. intros j Hj. rewrite E by lia.
         destruct (Nat.ltb_spec (n + i) n); [lia|]. destruct (Nat.ltb_spec j n); [|lia].
         replace (n + i - n)%nat with i by lia. reflexivity.
       - apply sumR_ext. intros j Hj. rewrite E by lia.
         destruct (Nat.ltb_spec (n + i) n); [lia|]. destruct (Nat.ltb_spec (n + j) n); [lia|].
         replace (n + i - n)%nat with i by lia. replace (n + j - n)%nat with j by lia.
         reflexivity. }
  rewrite !sumR_plus. unfold bf. ring.
Qed.

(** [[x; u]^T M(P) [x; u] = 2 (P x) . (A x + B u) - 2 u . (C x + D u)] for symmetric [P]. *)
Theorem kyp_form n m A B C D P x u :
  (0 < n)%nat -> (0 < m)%nat ->
  has_shape n n A -> has_shape n m B -> has_shape m n C -> has_shape m m D ->
  has_shape n n P -> symmetric n P ->
  qform (n + m) (kyp A B C D P) (join n x u)
  = 2 * vdotn n (rowsum n P x) (fun i => rowsum n A x i + rowsum m B u i)
    - 2 * vdotn m u (fun k => rowsum n C x k + rowsum m D u k).
Proof.
  intros Hn Hm HA HB HC HD HP HS.
  pose proof (has_shape_tr n n A HA Hn) as HAt.
  pose proof (has_shape_tr n m B HB Hn) as HBt.
  pose proof (has_shape_tr m n C HC Hm) as HCt.
  pose proof (has_shape_tr m m D HD Hm) as HDt.
  unfold kyp. rewrite qform_block.
  2: { apply has_shape_madd; apply (has_shape_mmul n n n); auto. }
  2: { unfold QCert.msub. apply has_shape_madd; [apply (has_shape_mmul n n m); auto|].
       apply has_shape_mneg; auto. }
  2: { unfold QCert.msub. apply has_shape_madd; [apply (has_shape_mmul m n n); auto|].
       apply has_shape_mneg; auto. }
  2: { apply has_shape_mneg, has_shape_madd; auto. }
  rewrite (bf_madd n n) by (apply (has_shape_mmul n n n); auto).
  rewrite (bf_msub n m) by (try apply (has_shape_mmul n n m); auto).
  rewrite (bf_msub m n) by (try apply (has_shape_mmul m n n); auto).
  rewrite bf_mneg, (bf_madd m m) by auto.
  rewrite (bf_mmul n n n (QCert.tr A) P), (bf_mmul n n n P A), (bf_mmul n n m P B),
          (bf_mmul m n n (QCert.tr B) P) by auto.
  rewrite (bf_tr m n C), (bf_tr m m D) by auto.
  rewrite (vdotn_ext n (colsum n (QCert.tr A) x) _ (rowsum n A x) (rowsum n P x))
    by (auto; intros; apply (colsum_tr n n); auto).
  rewrite (vdotn_ext n (colsum n P x) _ (rowsum n P x) (rowsum n A x))
    by (auto; intros; apply colsum_sym; auto).
  rewrite (vdotn_ext n (colsum n P x) _ (rowsum n P x) (rowsum m B u))
    by (auto; intros; apply colsum_sym; auto).
  rewrite (vdotn_ext n (colsum m (QCert.tr B) u) _ (rowsum m B u) (rowsum n P x))
    by (auto; intros; apply (colsum_tr n m); auto).
  rewrite !bf_rows, !vdotn_plus_r.
  rewrite (vdotn_comm n (rowsum n A x)), (vdotn_comm n (rowsum m B u)). ring.
Qed.

(** ** Along a solution *)

Lemma is_derive_sumR k (f : R -> nat -> R) (df : nat -> R) t :
  (forall i, (i < k)%nat -> is_derive (fun s => f s i) t (df i)) ->
  is_derive (fun s => sumR k (f s)) t (sumR k df).
Proof.
  induction k; intros H; simpl.
  - apply (is_derive_const 0 t).
  - apply (is_derive_plus (fun s => sumR k (f s)) (fun s => f s k)).
    + apply IHk. intros; apply H; lia.
    + apply H; lia.
Qed.

Lemma nonzero_or_zero n x : nonzero n x \/ forall i, (i < n)%nat -> x i = 0.
Proof.
  induction n.
  - right. intros; lia.
  - destruct IHn as [[i [Hi Hx]] | Z]; [left; exists i; split; [lia | exact Hx] |].
    destruct (Req_dec (x n) 0) as [E | E].
    + right. intros i Hi. destruct (Nat.eq_dec i n) as [-> | Ne]; [exact E | apply Z; lia].
    + left. exists n. split; [lia | exact E].
Qed.

Lemma pos_def_nonneg n P x : pos_def n P -> 0 <= qform n P x.
Proof.
  intros H. destruct (nonzero_or_zero n x) as [Nz | Z].
  - apply Rlt_le, H, Nz.
  - unfold qform. rewrite (sumR_ext n _ (fun _ => 0)); [rewrite sumR_zero; lra|].
    intros i Hi. rewrite (sumR_ext n _ (fun _ => 0)); [apply sumR_zero|].
    intros j Hj. rewrite (Z i Hi). ring.
Qed.

(** ** A positive definite form is bounded below by a positive multiple of |x|^2 *)

Definition qf (n : nat) (M : nat -> nat -> R) (x : nat -> R) : R :=
  sumR n (fun i => sumR n (fun j => M i j * (x i * x j))).
Definition normsq (n : nat) (x : nat -> R) : R := sumR n (fun i => x i * x i).

Lemma sq_nonneg' n x : 0 <= normsq n x.
Proof. apply sumR_nonneg. intros. apply Rle_0_sqr. Qed.

Lemma sum_sq_bound n (z : nat -> R) : sumR n z * sumR n z <= 2 ^ n * normsq n z.
Proof.
  unfold normsq. induction n; simpl; [lra|].
  set (s := sumR n z). set (Q := sumR n (fun i => z i * z i)). set (p := 2 ^ n).
  assert (1 <= p) by (apply pow_R1_Rle; lra).
  pose proof (Rle_0_sqr (s - z n)). pose proof (Rle_0_sqr (z n)).
  assert (A1 : z n * z n <= p * (z n * z n)).
  { rewrite <- (Rmult_1_l (z n * z n)) at 1. apply Rmult_le_compat_r; [apply Rle_0_sqr | lra]. }
  assert (A2 : (s + z n) * (s + z n) <= 2 * (s * s) + 2 * (z n * z n)).
  { unfold Rsqr in *. nra. }
  assert (A3 : 2 * p * (Q + z n * z n) = 2 * (p * Q) + 2 * (p * (z n * z n))) by ring.
  rewrite A3. fold s Q p in IHn. lra.
Qed.

Lemma term_le_sum n f i : (forall j, (j < n)%nat -> 0 <= f j) -> (i < n)%nat -> f i <= sumR n f.
Proof.
  intros H Hi. rewrite (sumR_split n i f Hi).
  assert (0 <= sumR n (fun j => offd i j (f j))).
  { apply sumR_nonneg. intros j Hj. unfold offd. destruct (Nat.eqb i j); [lra | apply H, Hj]. }
  lra.
Qed.

Lemma sumR_minus n f g : sumR n (fun j => f j - g j) = sumR n f - sumR n g.
Proof. unfold Rminus. rewrite sumR_plus, sumR_opp. reflexivity. Qed.

(** Peeling the last coordinate: with [a = M n n > 0] and the Schur complement
    [S i j = M i j - M i n M n j / a], [x^T M x = x'^T S x' + a (x_n + beta)^2]. *)
Lemma qf_schur n M x :
  (forall i j, M i j = M j i) -> M n n <> 0 ->
  qf (S n) M x = qf n (fun i j => M i j - M i n * M n j / M n n) x
                 + M n n * (x n + sumR n (fun i => M n i * x i) / M n n)
                          * (x n + sumR n (fun i => M n i * x i) / M n n).
Proof.
  intros Hs Ha. unfold qf. cbn [sumR].
  rewrite sumR_plus.
  set (s := sumR n (fun i => M n i * x i)).
  assert (E1 : sumR n (fun i => M i n * (x i * x n)) = s * x n).
  { unfold s. rewrite <- sumR_scal_r. apply sumR_ext. intros i _. rewrite (Hs i n). ring. }
  assert (E2 : sumR n (fun j => M n j * (x n * x j)) = s * x n).
  { unfold s. rewrite <- sumR_scal_r. apply sumR_ext. intros j _. ring. }
  assert (E3 : sumR n (fun i => sumR n (fun j => (M i j - M i n * M n j / M n n) * (x i * x j)))
               = sumR n (fun i => sumR n (fun j => M i j * (x i * x j))) - s * (s / M n n)).
  { rewrite (sumR_ext n _ (fun i => sumR n (fun j => M i j * (x i * x j))
                                    - (M n i * x i) * (s / M n n))).
    - rewrite sumR_minus, sumR_scal_r. reflexivity.
    - intros i _.
      assert (F : (M n i * x i) * (s / M n n)
                  = sumR n (fun j => (M n i * x i / M n n) * (M n j * x j))).
      { rewrite sumR_scal. unfold s. field. exact Ha. }
      rewrite F, <- sumR_minus. apply sumR_ext. intros j _. rewrite (Hs i n). field. exact Ha. }
  rewrite E1, E2, E3. field. exact Ha.
Qed.

Lemma qf_last_unit n M :
  qf (S n) M (fun i => if Nat.eqb i n then 1 else 0) = M n n.
Proof.
  set (e := fun i => if Nat.eqb i n then 1 else 0).
  assert (Z : forall i, (i < n)%nat -> e i = 0).
  { intros i Hi. unfold e. destruct (Nat.eqb_spec i n); [lia | reflexivity]. }
  assert (En : e n = 1) by (unfold e; rewrite Nat.eqb_refl; reflexivity).
  unfold qf. cbn [sumR].
  rewrite (sumR_ext n _ (fun _ => 0)).
  - rewrite sumR_zero, (sumR_ext n (fun j => M n j * (e n * e j)) (fun _ => 0)).
    + rewrite sumR_zero, En. ring.
    + intros j Hj. rewrite (Z j Hj). ring.
  - intros i Hi. rewrite (sumR_ext n _ (fun _ => 0)).
    + rewrite sumR_zero, (Z i Hi). ring.
    + intros j _. rewrite (Z i Hi). ring.
Qed.

Lemma sq_weighted n (b x : nat -> R) :
  normsq n (fun i => b i * x i) <= normsq n b * normsq n x.
Proof.
  unfold normsq. rewrite <- sumR_scal. apply sumR_le. intros i Hi.
  assert (b i * b i <= sumR n (fun j => b j * b j)).
  { apply (term_le_sum n (fun j => b j * b j)); [intros; apply Rle_0_sqr | exact Hi]. }
  pose proof (Rle_0_sqr (x i)). unfold Rsqr in *. nra.
Qed.

Lemma step_aux (mn K S2 X Y : R) :
  0 < mn -> 0 <= K -> 0 <= S2 -> 0 <= Y -> X <= 2 * Y + 2 * (K * S2) ->
  mn / (3 + 2 * K) * (S2 + X) <= mn * S2 + mn * Y.
Proof.
  intros Hm HK HS HY HX.
  assert (Hd : 0 < 3 + 2 * K) by lra.
  apply (Rmult_le_reg_l (3 + 2 * K)); [exact Hd |].
  replace ((3 + 2 * K) * (mn / (3 + 2 * K) * (S2 + X))) with (mn * (S2 + X)) by (field; lra).
  assert (mn * X <= mn * (2 * Y + 2 * (K * S2))) by (apply Rmult_le_compat_l; lra).
  assert (0 <= mn * Y) by (apply Rmult_le_pos; lra).
  assert (0 <= mn * (K * Y)) by (apply Rmult_le_pos; [lra | apply Rmult_le_pos; lra]).
  nra.
Qed.

(** A positive definite (symmetric) form is coercive: [x^T M x >= c |x|^2] for some
    [c > 0] (by induction on the dimension, with the Schur complement). *)
Theorem pd_coercive n (M : nat -> nat -> R) :
  (forall i j, M i j = M j i) ->
  (forall x, nonzero n x -> 0 < qf n M x) ->
  exists c, 0 < c /\ forall x, c * normsq n x <= qf n M x.
Proof.
  revert M. induction n as [|n IH]; intros M Hs Hpd.
  - exists 1. split; [lra|]. intros x. unfold normsq, qf; simpl. lra.
  - set (a := M n n).
    assert (Ha : 0 < a).
    { unfold a. rewrite <- qf_last_unit. apply Hpd. exists n.
      rewrite Nat.eqb_refl. split; [lia | lra]. }
    set (Sc := fun i j => M i j - M i n * M n j / a).
    assert (HsS : forall i j, Sc i j = Sc j i).
    { intros i j. unfold Sc. rewrite (Hs i j), (Hs i n), (Hs n j), (Rmult_comm (M n i) (M j n)). reflexivity. }
    assert (HpdS : forall x, nonzero n x -> 0 < qf n Sc x).
    { intros x [k [Hk Hx]].
      set (b := sumR n (fun i => M n i * x i) / a).
      set (y := fun i => if Nat.ltb i n then x i else - b).
      assert (Ey : forall i, (i < n)%nat -> y i = x i).
      { intros i Hi. unfold y. destruct (Nat.ltb_spec i n); [reflexivity | lia]. }
      assert (Pos : 0 < qf (S n) M y).
      { apply Hpd. exists k. split; [lia|]. rewrite Ey by exact Hk. exact Hx. }
      rewrite (qf_schur n M y Hs ltac:(unfold a in Ha; lra)) in Pos.
      assert (Eb : sumR n (fun i => M n i * y i) / M n n = b).
      { unfold b, a. f_equal. apply sumR_ext. intros i Hi. rewrite Ey by exact Hi. reflexivity. }
      assert (Yn : y n = - b) by (unfold y; destruct (Nat.ltb_spec n n); [lia | reflexivity]).
      rewrite Eb, Yn in Pos.
      assert (Eq : qf n (fun i j => M i j - M i n * M n j / M n n) y = qf n Sc x).
      { unfold qf, Sc, a. apply sumR_ext. intros i Hi. apply sumR_ext. intros j Hj.
        rewrite !Ey by assumption. reflexivity. }
      rewrite Eq in Pos. lra. }
    destruct (IH Sc HsS HpdS) as [c' [Hc' Hb]].
    set (K := 2 ^ n * normsq n (fun i => M n i) / (a * a)).
    assert (HK : 0 <= K).
    { unfold K. apply Rmult_le_pos; [apply Rmult_le_pos; [apply pow_le; lra | apply sq_nonneg'] |].
      apply Rlt_le, Rinv_0_lt_compat, Rmult_lt_0_compat; exact Ha. }
    set (mn := Rmin c' a).
    assert (Hmn : 0 < mn) by (unfold mn; apply Rmin_pos; assumption).
    exists (mn / (3 + 2 * K)). split; [apply Rdiv_lt_0_compat; lra |]. intros x.
    set (s := sumR n (fun i => M n i * x i)).
    set (yy := x n + s / a).
    rewrite (qf_schur n M x Hs ltac:(unfold a in Ha; lra)). fold a s yy.
    assert (Q1 : c' * normsq n x <= qf n Sc x) by apply Hb.
    assert (Bs : s / a * (s / a) <= K * normsq n x).
    { unfold K. pose proof (sum_sq_bound n (fun i => M n i * x i)) as C1. fold s in C1.
      pose proof (sq_weighted n (fun i => M n i) x) as C2.
      assert (P2 : 0 <= 2 ^ n) by (apply pow_le; lra).
      assert (C3 : s * s <= 2 ^ n * (normsq n (fun i => M n i) * normsq n x)).
      { eapply Rle_trans; [exact C1 |]. apply Rmult_le_compat_l; [exact P2 | exact C2]. }
      replace (s / a * (s / a)) with (s * s / (a * a)) by (field; lra).
      replace (2 ^ n * normsq n (fun i => M n i) / (a * a) * normsq n x)
        with (2 ^ n * (normsq n (fun i => M n i) * normsq n x) / (a * a)) by (field; lra).
      apply Rmult_le_compat_r; [apply Rlt_le, Rinv_0_lt_compat, Rmult_lt_0_compat; exact Ha |].
      exact C3. }
    assert (Xn : x n * x n <= 2 * (yy * yy) + 2 * (K * normsq n x)).
    { replace (x n) with (yy - s / a) by (unfold yy; ring).
      pose proof (Rle_0_sqr (yy + s / a)). unfold Rsqr in *. nra. }
    assert (Sq : normsq (S n) x = normsq n x + x n * x n) by reflexivity.
    rewrite Sq.
    assert (Mc : mn <= c') by apply Rmin_l.
    assert (Ma : mn <= a) by apply Rmin_r.
    pose proof (sq_nonneg' n x) as Sx. pose proof (Rle_0_sqr yy) as Y2. unfold Rsqr in Y2.
    pose proof (step_aux mn K (normsq n x) (x n * x n) (yy * yy) Hmn HK Sx Y2 Xn) as Step.
    assert (mn * normsq n x <= c' * normsq n x) by (apply Rmult_le_compat_r; assumption).
    assert (mn * (yy * yy) <= a * (yy * yy)) by (apply Rmult_le_compat_r; assumption).
    assert (E : qf n (fun i j => M i j - M i n * M n j / a) x = qf n Sc x) by reflexivity.
    rewrite E. clearbody Sc K mn s yy a. lra.
Qed.

(** [P > 0] over the first [n] coordinates: [x^T P x >= c |x|^2] for some [c > 0]. *)
Theorem pos_def_coercive n P : symmetric n P -> pos_def n P ->
  exists c, 0 < c /\ forall x, c * normsq n x <= qform n P x.
Proof.
  intros HS Hpd.
  set (M := fun i j => if Nat.ltb i n && Nat.ltb j n then mR P i j else 0).
  assert (E : forall x, qf n M x = qform n P x).
  { intros x. unfold qf, qform, M. apply sumR_ext. intros i Hi. apply sumR_ext. intros j Hj.
    destruct (Nat.ltb_spec i n); [|lia]. destruct (Nat.ltb_spec j n); [|lia]. reflexivity. }
  destruct (pd_coercive n M) as [c [Hc B]].
  - intros i j. unfold M. destruct (Nat.ltb_spec i n), (Nat.ltb_spec j n); simpl; try reflexivity.
    unfold mR. apply Qeq_eqR, HS; assumption.
  - intros x Hx. rewrite E. apply Hpd, Hx.
  - exists c. split; [exact Hc|]. intros x. rewrite <- E. apply B.
Qed.

Section Storage.
(** The human: [n] states, [m] ports, a realisation with a KYP certificate [P]. *)
Variables (n m : nat) (A B C D P : matQ).
Hypothesis n_pos : (0 < n)%nat.
Hypothesis m_pos : (0 < m)%nat.
Hypothesis cert : kyp_certified n m A B C D P.
(** A state trajectory [x] and an input [u] (any functions of time). *)
Variables (x u : R -> nat -> R).

(** [x' = A x + B u] and [y = C x + D u]. *)
Definition lti_rate (t : R) (i : nat) : R := rowsum n A (x t) i + rowsum m B (u t) i.
Definition lti_out (t : R) (k : nat) : R := rowsum n C (x t) k + rowsum m D (u t) k.

(** The storage [S = x^T P x / 2], its rate along the state equation, the supply [u . y]. *)
Definition storage (t : R) : R := qform n P (x t) / 2.
Definition storage_rate (t : R) : R := vdotn n (rowsum n P (x t)) (lti_rate t).
Definition supply (t : R) : R := vdotn m (u t) (lti_out t).

Lemma storage_derive (t : R) :
  (forall i, (i < n)%nat -> is_derive (fun s => x s i) t (lti_rate t i)) ->
  is_derive storage t (storage_rate t).
Proof.
  intros Hx. destruct cert as [_ [_ [_ [_ [HP [HS _]]]]]].
  unfold storage, qform. eapply d_eq.
  - apply d_div.
    apply (is_derive_sumR n (fun s i => sumR n (fun j => Q2R (entry P i j) * (x s i * x s j)))
             (fun i => sumR n (fun j => mR P i j * (lti_rate t i * x t j + x t i * lti_rate t j)))).
    intros i Hi.
    apply (is_derive_sumR n (fun s j => Q2R (entry P i j) * (x s i * x s j))).
    intros j Hj. pose proof (Hx i Hi). pose proof (Hx j Hj). unfold mR. d_auto.
  - transitivity (bf n n P (lti_rate t) (x t) / 2 + bf n n P (x t) (lti_rate t) / 2).
    + assert (E : sumR n (fun i => sumR n (fun j =>
                      mR P i j * (lti_rate t i * x t j + x t i * lti_rate t j)))
                  = bf n n P (lti_rate t) (x t) + bf n n P (x t) (lti_rate t)).
      { unfold bf. rewrite <- sumR_plus. apply sumR_ext. intros i _.
        rewrite <- sumR_plus. apply sumR_ext. intros. ring. }
      rewrite E. field.
    + rewrite bf_rows, bf_cols.
      rewrite (vdotn_ext n (colsum n P (x t)) _ (rowsum n P (x t)) (lti_rate t))
        by (auto; intros; apply colsum_sym; auto).
      unfold storage_rate. rewrite vdotn_comm. field.
Qed.

(** The dissipation identity: [S' - u . y = (1/2) [x; u]^T M(P) [x; u]]. *)
Theorem storage_supply_identity (t : R) :
  storage_rate t - supply t = qform (n + m) (kyp A B C D P) (join n (x t) (u t)) / 2.
Proof.
  destruct cert as [HA [HB [HC [HD [HP [HS _]]]]]].
  rewrite kyp_form by assumption. unfold storage_rate, supply, lti_rate, lti_out. field.
Qed.

(** [S' <= u . y]: the human is passive with the storage [S] (Assumption 1, item 5). *)
Theorem storage_dissipation (t : R) : storage_rate t <= supply t.
Proof.
  pose proof (storage_supply_identity t) as E.
  destruct cert as [_ [_ [_ [_ [_ [_ [_ Hneg]]]]]]].
  pose proof (Hneg (join n (x t) (u t))). lra.
Qed.

(** [S >= 0] ([P > 0]). *)
Theorem storage_nonneg (t : R) : 0 <= storage t.
Proof.
  destruct cert as [_ [_ [_ [_ [_ [_ [Hpd _]]]]]]].
  unfold storage. pose proof (pos_def_nonneg n P (x t) Hpd). lra.
Qed.

(** The state is bounded by its storage: [c |x|^2 <= 2 S] for a [c > 0] from [P > 0]. *)
Theorem storage_coercive : exists c, 0 < c /\ forall t, c * normsq n (x t) <= 2 * storage t.
Proof.
  destruct cert as [_ [_ [_ [_ [_ [HS [Hpd _]]]]]]].
  destruct (pos_def_coercive n P HS Hpd) as [c [Hc Low]].
  exists c. split; [exact Hc|]. intros t. unfold storage. pose proof (Low (x t)). lra.
Qed.

End Storage.
