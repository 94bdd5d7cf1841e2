(** * WitnessCert: a model that is not positive real, from a witness Coq re-checks

    For the gate's negative verdicts (the paper's Section 4: the human's model identified
    at a high stiffness is not passive).  A passive linear model has a positive real
    transfer matrix H(s) = C (sI - A)^-1 B + D: no pole in Re s > 0 and
    H(jw) + H(jw)^H >= 0 at every real w where H(jw) is defined.  Both conditions are
    stated here from the definitions of [BandCert.v]:

    - [fdi_holds]: the frequency-domain inequality, with H(jw) = N(jw) / d(jw), where
      d(s) = det(sI - A) and N(s) = C Adj(s) B + d(s) D are computed by Coq from the
      data (as in BandCert.v's header);
    - [no_rhp_root]: d has no root s with Re s > 0 (every pole of H is a root of d).

    [positive_real] is their conjunction (the residue conditions at imaginary-axis poles
    are left out: leaving out a condition only makes the refuted statement weaker, so a
    refutation of [positive_real] refutes positive realness).

    Two kinds of witness, each checked by computation on [Q] and proved sound once:

    - a frequency witness (w, z), w >= 0 rational, z a vector of complex rationals:
      Coq computes d(jw) and N(jw) over the complex rationals (pairs of [Q]), checks
      d(jw) <> 0 and Re z^H Mt(w) z < 0, where Mt(w) = |d(jw)|^2 (H(jw) + H(jw)^H);
      then Re z^H (H(jw) + H(jw)^H) z < 0 and [fdi_holds] fails ([fdi_witness_sound]).
      A witness "at infinity" (v^T (D + D^T) v < 0) is written as a frequency witness
      at a finite w where the same vector works;
    - an unstable witness [s1, s2], 0 < s1 < s2 rational: Coq checks
      d(s1) d(s2) <= 0, so d has a real root in [s1, s2] by the intermediate value
      theorem and [no_rhp_root] fails ([unstable_witness_sound]).

    No axiom is added. *)

From Coq Require Import QArith Qabs Qreals Reals List Lra Lia.
From Coq Require Import Rsqrt_def Ranalysis1.
From VerifyCoq Require Import QCert BandCert.
Import ListNotations.

Open Scope R_scope.

(** ** What a refutation denies *)

(** p(s) at a complex s = (Re s, Im s), by Horner's rule. *)
Fixpoint at_c (p : poly) (s : R * R) : R * R :=
  match p with
  | nil => (0, 0)
  | a :: p' => cadd (Q2R a, 0) (cmul s (at_c p' s))
  end.

(** d has no root in the open right half-plane. *)
Definition no_rhp_root (d : poly) : Prop :=
  forall s : R * R, 0 < fst s -> at_c d s <> (0, 0).

(** The realisation (A, B, C, D) has a positive real transfer matrix: the
    frequency-domain inequality holds and det(sI - A) has no root with Re s > 0. *)
Definition positive_real (n m : nat) (A B C D : matQ) : Prop :=
  fdi_holds n m A B C D /\ no_rhp_root (fst (charpoly_adj n A)).

(** ** Exact evaluation over Q and over the complex rationals *)

Fixpoint pevalQ (p : poly) (x : Q) : Q :=
  match p with nil => 0%Q | a :: p' => radd a (rmul x (pevalQ p' x)) end.

Lemma Q2R_pevalQ p x : Q2R (pevalQ p x) = peval p (Q2R x).
Proof.
  induction p as [|a p IH]; simpl; [apply Q2R_0|]. rewrite Q2R_radd, Q2R_rmul, IH.
  reflexivity.
Qed.

Definition cQ := (Q * Q)%type.
Definition cR (z : cQ) : R * R := (Q2R (fst z), Q2R (snd z)).
Definition cmulQ (u v : cQ) : cQ :=
  (radd (rmul (fst u) (fst v)) (Qopp (rmul (snd u) (snd v))),
   radd (rmul (fst u) (snd v)) (rmul (snd u) (fst v))).
Definition cconjQ (u : cQ) : cQ := (fst u, Qopp (snd u)).

Lemma cR_mul u v : cR (cmulQ u v) = cmul (cR u) (cR v).
Proof.
  unfold cR, cmulQ, cmul. simpl. rewrite !Q2R_radd, Q2R_opp, !Q2R_rmul. f_equal; ring.
Qed.

Lemma cR_conj u : cR (cconjQ u) = cconj (cR u).
Proof. unfold cR, cconjQ, cconj. simpl. rewrite Q2R_opp. reflexivity. Qed.

(** Re z^H M z over the complex rationals. *)
Definition hformQ (m : nat) (M : nat -> nat -> cQ) (z : nat -> cQ) : Q :=
  sumQ m (fun i => sumQ m (fun k => fst (cmulQ (cconjQ (z i)) (cmulQ (M i k) (z k))))).

Lemma Q2R_hformQ m M z :
  Q2R (hformQ m M z) = hform m (fun i k => cR (M i k)) (fun i => cR (z i)).
Proof.
  unfold hformQ, hform. rewrite Q2R_sumQ. apply sumR_ext. intros i _.
  rewrite Q2R_sumQ. apply sumR_ext. intros k _.
  change (Q2R (fst (cmulQ (cconjQ (z i)) (cmulQ (M i k) (z k)))))
    with (fst (cR (cmulQ (cconjQ (z i)) (cmulQ (M i k) (z k))))).
  rewrite !cR_mul, cR_conj. reflexivity.
Qed.

(** ** The Hermitian part of N / d is the Hermitian numerator over |d|^2 *)

(** Mt = N conj(d) + d N^H, entry (i, k), from the values N(jw) and d(jw) = (p, q). *)
Definition mt_at (Nv : nat -> nat -> R * R) (p q : R) (i k : nat) : R * R :=
  (p * (fst (Nv i k) + fst (Nv k i)) + q * (snd (Nv i k) + snd (Nv k i)),
   p * (snd (Nv i k) - snd (Nv k i)) - q * (fst (Nv i k) - fst (Nv k i))).

Lemma hform_herm_of m Nv p q z :
  p * p + q * q <> 0 ->
  hform m (herm_of Nv (p, q)) z = hform m (mt_at Nv p q) z / (p * p + q * q).
Proof.
  intros Hn. unfold hform, Rdiv. rewrite <- sumR_scal_r. apply sumR_ext. intros i _.
  rewrite <- sumR_scal_r. apply sumR_ext. intros k _.
  unfold herm_of, mt_at, cadd, cmul, cconj, cdiv. simpl. field. exact Hn.
Qed.

(** ** The frequency witness *)

(** [model_ok] by computation, with [fl] the value of [charpoly_adj n A] (computed once
    by the caller). *)
Definition model_ok_fl (n m : nat) (A B C D : matQ) (fl : list Q * list matQ) : bool :=
  has_shape_b n n A && has_shape_b n m B && has_shape_b m n C && has_shape_b m m D
  && resolvent_ok n A (zeros n n) (fst fl) (snd fl).

Definition model_ok_b (n m : nat) (A B C D : matQ) : bool :=
  model_ok_fl n m A B C D (charpoly_adj n A).

Lemma model_ok_b_sound n m A B C D : model_ok_b n m A B C D = true -> model_ok n m A B C D.
Proof.
  unfold model_ok_b, model_ok_fl. rewrite !andb_true_iff. intros [[[[HA HB] HC] HD] Hres].
  split; [apply has_shape_b_sound, HA|]. split; [apply has_shape_b_sound, HB|].
  split; [apply has_shape_b_sound, HC|]. split; [apply has_shape_b_sound, HD|].
  exact Hres.
Qed.

(** The complex vector z of a witness, entry i (0 beyond the list). *)
Definition zvec (zs : list cQ) (i : nat) : cQ := nth i zs (0%Q, 0%Q).

(** Mt(w) at the rational w, entry (i, k), computed on Q from the polynomials of
    BandCert.v ([mt_re], [mt_im]). *)
Definition mtQ (N : nat -> nat -> poly) (d : poly) (w : Q) (i k : nat) : cQ :=
  (pevalQ (mt_re N d i k) w, pevalQ (mt_im N d i k) w).

(** p(jw) over the complex rationals, from the real and imaginary parts of p. *)
Definition jw_valQ (p : poly) (w : Q) : cQ :=
  (pevalQ (fst (jw_parts p)) w, pevalQ (snd (jw_parts p)) w).

(** The same entry of Mt(w) as [mtQ], from the values d(jw) = [dv] and N(jw): the
    numbers are those of the values, where [mtQ] first forms Mt's polynomials (whose
    coefficients are products of N's and d's) and then evaluates them. *)
Definition mtQv (N : nat -> nat -> poly) (dv : cQ) (w : Q) (i k : nat) : cQ :=
  let nik := jw_valQ (N i k) w in
  let nki := jw_valQ (N k i) w in
  (radd (rmul (fst dv) (radd (fst nik) (fst nki))) (rmul (snd dv) (radd (snd nik) (snd nki))),
   radd (rmul (fst dv) (radd (snd nik) (Qopp (snd nki))))
        (Qopp (rmul (snd dv) (radd (fst nik) (Qopp (fst nki)))))).

Lemma cR_mtQv N d w i k p q :
  at_jw d (Q2R w) = (p, q) ->
  cR (mtQv N (jw_valQ d w) w i k) = mt_at (fun i k => at_jw (N i k) (Q2R w)) p q i k.
Proof.
  intros Ed. unfold mtQv, jw_valQ, cR, mt_at. cbn [fst snd].
  repeat rewrite ?Q2R_radd, ?Q2R_rmul, ?Q2R_opp.
  rewrite !Q2R_pevalQ, !jw_re, !jw_im, Ed. cbn [fst snd]. f_equal; ring.
Qed.

Definition fdi_witness_check (n m : nat) (A B C D : matQ) (w : Q) (zs : list cQ) : bool :=
  let fl := charpoly_adj n A in
  let d := fst fl in
  let N := tf_num C B D d (snd fl) in
  let dv := jw_valQ d w in
  model_ok_fl n m A B C D fl && Qle_bool 0 w
  && negb (Qeq_bool (radd (rmul (fst dv) (fst dv)) (rmul (snd dv) (snd dv))) 0)
  && negb (Qle_bool 0 (hformQ m (mtQv N dv w) (zvec zs))).

Theorem fdi_witness_point n m A B C D w zs :
  fdi_witness_check n m A B C D w zs = true ->
  model_ok n m A B C D /\ 0 <= Q2R w /\ ~ hermitian_part_psd_at n m A B C D (Q2R w).
Proof.
  unfold fdi_witness_check. cbv zeta. rewrite !andb_true_iff, !negb_true_iff.
  intros [[[Hm Hw] Hd] Hneg]. unfold jw_valQ at 1 2 3 4 in Hd. cbn [fst snd] in Hd. split; [exact (model_ok_b_sound n m A B C D Hm)|].
  assert (Hw0 : 0 <= Q2R w) by (rewrite <- Q2R_0; apply Qle_bool_R, Hw).
  split; [exact Hw0|]. intros Hpsd.
  set (d := fst (charpoly_adj n A)) in *.
  set (N := tf_num C B D d (snd (charpoly_adj n A))) in *.
  unfold hermitian_part_psd_at in Hpsd.
  fold d in Hpsd. fold N in Hpsd.
  destruct (at_jw d (Q2R w)) as [p q] eqn:Ed.
  assert (Ep : p = Q2R (pevalQ (fst (jw_parts d)) w))
    by (rewrite Q2R_pevalQ, jw_re, Ed; reflexivity).
  assert (Eq : q = Q2R (pevalQ (snd (jw_parts d)) w))
    by (rewrite Q2R_pevalQ, jw_im, Ed; reflexivity).
  assert (Hn : p * p + q * q <> 0).
  { intros H0. assert (Hz : Q2R (radd (rmul (pevalQ (fst (jw_parts d)) w)
                                            (pevalQ (fst (jw_parts d)) w))
                                      (rmul (pevalQ (snd (jw_parts d)) w)
                                            (pevalQ (snd (jw_parts d)) w))) = Q2R 0).
    { rewrite Q2R_radd, !Q2R_rmul, <- Ep, <- Eq, Q2R_0. exact H0. }
    apply eqR_Qeq in Hz. apply Qeq_bool_iff in Hz. congruence. }
  assert (Hne : (p, q) <> (0, 0)).
  { intros E. injection E as -> ->. apply Hn. ring. }
  specialize (Hpsd Hne (fun i => cR (zvec zs i))).
  rewrite hform_herm_of in Hpsd by exact Hn.
  assert (Emt : hform m (mt_at (fun i k => at_jw (N i k) (Q2R w)) p q)
                        (fun i => cR (zvec zs i))
                = Q2R (hformQ m (mtQv N (jw_valQ d w) w) (zvec zs))).
  { rewrite Q2R_hformQ. unfold hform. apply sumR_ext. intros i _. apply sumR_ext.
    intros k _. rewrite (cR_mtQv N d w i k p q Ed). reflexivity. }
  rewrite Emt in Hpsd.
  assert (Hlt : Q2R (hformQ m (mtQv N (jw_valQ d w) w) (zvec zs)) < 0).
  { apply Rnot_le_lt. intros Hle. rewrite <- Q2R_0 in Hle. apply Rle_Qle in Hle.
    apply Qle_bool_iff in Hle. congruence. }
  assert (Hpos : 0 < p * p + q * q).
  { assert (0 <= p * p) by apply Rle_0_sqr. assert (0 <= q * q) by apply Rle_0_sqr. lra. }
  assert (0 < / (p * p + q * q)) by (apply Rinv_0_lt_compat, Hpos).
  unfold Rdiv in Hpsd. nra.
Qed.

Theorem fdi_witness_sound n m A B C D w zs :
  fdi_witness_check n m A B C D w zs = true ->
  model_ok n m A B C D /\ ~ fdi_holds n m A B C D.
Proof.
  intros H. destruct (fdi_witness_point _ _ _ _ _ _ _ _ H) as [Hok [Hw Hno]].
  split; [exact Hok|]. intros [_ Hall]. exact (Hno (Hall _ Hw)).
Qed.

(** On a band [w1, w2]: a frequency witness inside the band refutes [band_passive]. *)
Theorem not_band_passive_of_fdi n m A B C D w1 w2 w zs :
  fdi_witness_check n m A B C D w zs && Qle_bool w1 w && Qle_bool w w2 = true ->
  model_ok n m A B C D /\ ~ band_passive n m A B C D w1 w2.
Proof.
  rewrite !andb_true_iff. intros [[H H1] H2].
  destruct (fdi_witness_point _ _ _ _ _ _ _ _ H) as [Hok [_ Hno]].
  split; [exact Hok|]. intros [_ [_ Hall]].
  apply Hno, Hall. split; apply Qle_bool_R; assumption.
Qed.

(** ** The unstable witness: a sign change of d on [s1, s2], 0 < s1 *)

Lemma peval_continuous p : continuity (peval p).
Proof.
  induction p as [|a p IH]; simpl.
  - apply continuity_const. intros x y. reflexivity.
  - apply (continuity_plus (fct_cte (Q2R a)) (mult_fct id (peval p))).
    + apply continuity_const. intros x y. reflexivity.
    + apply continuity_mult; [apply derivable_continuous, derivable_id | exact IH].
Qed.

Lemma at_c_real p x : at_c p (x, 0) = (peval p x, 0).
Proof.
  induction p as [|a p IH]; simpl; [reflexivity|]. rewrite IH.
  unfold cadd, cmul. simpl. f_equal; ring.
Qed.

Definition unstable_witness_check (n : nat) (A : matQ) (s1 s2 : Q) : bool :=
  let d := fst (charpoly_adj n A) in
  negb (Qle_bool s1 0) && Qle_bool s1 s2
  && Qle_bool (rmul (pevalQ d s1) (pevalQ d s2)) 0.

Theorem unstable_witness_sound n A s1 s2 :
  unstable_witness_check n A s1 s2 = true -> ~ no_rhp_root (fst (charpoly_adj n A)).
Proof.
  unfold unstable_witness_check. cbv zeta. rewrite !andb_true_iff, negb_true_iff.
  intros [[Hs1 H12] Hsign] Hno.
  set (d := fst (charpoly_adj n A)) in *.
  assert (Hpos : 0 < Q2R s1).
  { apply Rnot_le_lt. intros Hle. rewrite <- Q2R_0 in Hle. apply Rle_Qle in Hle.
    apply Qle_bool_iff in Hle. congruence. }
  assert (Hle : Q2R s1 <= Q2R s2) by (apply Qle_bool_R, H12).
  assert (Hs : peval d (Q2R s1) * peval d (Q2R s2) <= 0).
  { rewrite <- !Q2R_pevalQ, <- Q2R_rmul, <- Q2R_0. apply Qle_bool_R, Hsign. }
  destruct (IVT_cor (peval d) (Q2R s1) (Q2R s2) (peval_continuous d) Hle Hs)
    as [x [[Hx1 _] Hx]].
  apply (Hno (x, 0)); simpl; [lra|]. rewrite at_c_real, Hx. reflexivity.
Qed.

(** ** Refutations of positive realness *)

Theorem not_positive_real_of_fdi n m A B C D w zs :
  fdi_witness_check n m A B C D w zs = true ->
  model_ok n m A B C D /\ ~ positive_real n m A B C D.
Proof.
  intros H. destruct (fdi_witness_sound _ _ _ _ _ _ _ _ H) as [Hok Hno].
  split; [exact Hok|]. intros [Hf _]. exact (Hno Hf).
Qed.

Theorem not_positive_real_of_unstable n m A B C D s1 s2 :
  model_ok_b n m A B C D && unstable_witness_check n A s1 s2 = true ->
  model_ok n m A B C D /\ ~ positive_real n m A B C D.
Proof.
  rewrite andb_true_iff. intros [Hm Hu]. split; [exact (model_ok_b_sound _ _ _ _ _ _ Hm)|].
  intros [_ Hr]. exact (unstable_witness_sound _ _ _ _ Hu Hr).
Qed.
