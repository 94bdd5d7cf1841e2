(** * PoleCert: every eigenvalue of A in the open left half-plane, from a Lyapunov witness

    For the pole conditions of positive realness (the paper's Section 4: a positive-real
    certificate of the human's model).  [hurwitz n A] says what a reader audits: every
    complex eigenpair A (xr + j xi) = (sr + j si) (xr + j xi), xr + j xi <> 0, has
    sr < 0.  Then H(s) = C (sI - A)^-1 B + D has no pole with Re s >= 0 (every pole of H
    is an eigenvalue of A, the one textbook step not proved here), so the residue
    conditions at imaginary-axis poles hold vacuously.

    The witness is a rational symmetric Q with Q > 0 and A^T Q + Q A < 0, both re-checked
    by the definiteness checks of [QCert.v] ([pd_check], exact LDL^T or dominant
    residual).  The soundness ([lyapunov_sound], proved once): for an eigenpair,
    x^H (A^T Q + Q A) x = 2 sr x^H Q x, negative on the left, so sr < 0 because
    x^H Q x > 0.  No axiom is added. *)

From Coq Require Import QArith Qabs Qreals Reals List Lra Lia.
From VerifyCoq Require Import QCert.
Import ListNotations.

Open Scope R_scope.

(** (A u)_k for a real vector u. *)
Definition Av (n : nat) (A : matQ) (u : nat -> R) (k : nat) : R :=
  sumR n (fun i => Q2R (entry A k i) * u i).

(** A (xr + j xi) = (sr + j si) (xr + j xi), coordinate by coordinate. *)
Definition eigenpair (n : nat) (A : matQ) (sr si : R) (xr xi : nat -> R) : Prop :=
  forall k, (k < n)%nat ->
    Av n A xr k = sr * xr k - si * xi k /\ Av n A xi k = si * xr k + sr * xi k.

(** Every eigenvalue of A has a negative real part. *)
Definition hurwitz (n : nat) (A : matQ) : Prop :=
  forall sr si xr xi, (nonzero n xr \/ nonzero n xi) -> eigenpair n A sr si xr xi -> sr < 0.

(** A^T Q + Q A, entry (i, j) = sum_k (A_ki Q_kj + Q_ik A_kj). *)
Definition lyap (n : nat) (A P : matQ) : matQ :=
  tabulate n (fun i j => sumQ n (fun k => qadd (qmul (entry A k i) (entry P k j))
                                               (qmul (entry P i k) (entry A k j)))).

Definition lyapunov_check (n : nat) (A P : matQ) (eQ : Q) (wQ : list term)
    (eL : Q) (wL : list term) : bool :=
  has_shape_b n n A && has_shape_b n n P && sym_check n P && pd_check n P eQ wQ
  && pd_check n (mneg (lyap n A P)) eL wL.

(** ** Bilinear forms *)

Definition bf (n : nat) (P : matQ) (a b : nat -> R) : R :=
  sumR n (fun k => sumR n (fun j => Q2R (entry P k j) * (a k * b j))).

Lemma bf_qform n P x : bf n P x x = qform n P x.
Proof. reflexivity. Qed.

Lemma bf_ext_l n P a a' b : (forall k, (k < n)%nat -> a k = a' k) -> bf n P a b = bf n P a' b.
Proof.
  intros H. unfold bf. apply sumR_ext. intros k Hk. rewrite H by exact Hk. reflexivity.
Qed.

Lemma bf_comb_l n P a1 a2 c1 c2 b :
  bf n P (fun k => c1 * a1 k + c2 * a2 k) b = c1 * bf n P a1 b + c2 * bf n P a2 b.
Proof.
  unfold bf. rewrite <- !sumR_scal, <- sumR_plus. apply sumR_ext. intros k _.
  rewrite <- !sumR_scal, <- sumR_plus. apply sumR_ext. intros j _. ring.
Qed.

Lemma bf_sym n P a b : symmetric n P -> bf n P a b = bf n P b a.
Proof.
  intros Hs. unfold bf. rewrite sumR_swap. apply sumR_ext. intros j Hj.
  apply sumR_ext. intros k Hk. rewrite (Qeq_eqR _ _ (Hs j k Hj Hk)). ring.
Qed.

(** x^T (A^T Q + Q A) x = (A x)^T Q x + x^T Q (A x). *)
Lemma qform_lyap n A P x :
  qform n (lyap n A P) x = bf n P (Av n A x) x + bf n P x (Av n A x).
Proof.
  unfold qform, lyap, bf, Av.
  transitivity (sumR n (fun i => sumR n (fun j => sumR n (fun k =>
     Q2R (entry A k i) * Q2R (entry P k j) * (x i * x j)
     + Q2R (entry P i k) * Q2R (entry A k j) * (x i * x j))))).
  { apply sumR_ext. intros i Hi. apply sumR_ext. intros j Hj.
    rewrite entry_tabulate by assumption. rewrite Q2R_sumQ, <- sumR_scal_r.
    apply sumR_ext. intros k _. rewrite Q2R_qadd, !Q2R_qmul. ring. }
  transitivity (sumR n (fun i => sumR n (fun j => sumR n (fun k =>
     Q2R (entry A k i) * Q2R (entry P k j) * (x i * x j))))
   + sumR n (fun i => sumR n (fun j => sumR n (fun k =>
     Q2R (entry P i k) * Q2R (entry A k j) * (x i * x j))))).
  { rewrite <- sumR_plus. apply sumR_ext. intros i _. rewrite <- sumR_plus.
    apply sumR_ext. intros j _. apply sumR_plus. }
  f_equal.
  - (* both sides are sum over i, j, k of A_ki Q_kj x_i x_j, in another order *)
    transitivity (sumR n (fun k => sumR n (fun j => sumR n (fun i =>
                    Q2R (entry A k i) * Q2R (entry P k j) * (x i * x j))))).
    + rewrite sumR_swap. symmetry. rewrite sumR_swap. apply sumR_ext. intros j _.
      apply sumR_swap.
    + apply sumR_ext. intros k _. apply sumR_ext. intros j _.
      transitivity (sumR n (fun i => Q2R (entry P k j) * (x j * (Q2R (entry A k i) * x i)))).
      { apply sumR_ext. intros i _. ring. }
      rewrite sumR_scal, sumR_scal. ring.
  - apply sumR_ext. intros i _. rewrite sumR_swap. apply sumR_ext. intros k _.
    transitivity (sumR n (fun j => Q2R (entry P i k) * (x i * (Q2R (entry A k j) * x j)))).
    { apply sumR_ext. intros j _. ring. }
    rewrite sumR_scal, sumR_scal. reflexivity.
Qed.

Lemma qform_mneg n M x : qform n (mneg M) x = - qform n M x.
Proof.
  unfold qform. rewrite <- sumR_opp. apply sumR_ext. intros i _.
  rewrite <- sumR_opp. apply sumR_ext. intros j _. rewrite entry_mneg, Q2R_opp. ring.
Qed.

Lemma norm2_pos n x : nonzero n x -> 0 < sumR n (fun i => x i * x i).
Proof.
  intros [k [Hk Hx]]. apply (sumR_pos n _ k); [intros; apply Rle_0_sqr | exact Hk |].
  destruct (Rlt_dec 0 (x k)) as [Hp|Hp]; [nra|]. assert (x k < 0) by lra. nra.
Qed.

Lemma pd_check_bound n M e ws : pd_check n M e ws = true ->
  0 < Q2R e /\ forall x, Q2R e * sumR n (fun i => x i * x i) <= qform n M x.
Proof.
  unfold pd_check. rewrite andb_true_iff, negb_true_iff. intros [He Hc]. split.
  - rewrite <- Q2R_zero. apply Qlt_Rlt, Qnot_le_lt. intros Hle.
    apply Qle_bool_iff in Hle. congruence.
  - exact (psd_check_sound n M e ws Hc).
Qed.

(** ** The soundness of the Lyapunov check, proved once *)
Theorem lyapunov_sound n A P eQ wQ eL wL :
  lyapunov_check n A P eQ wQ eL wL = true -> hurwitz n A.
Proof.
  unfold lyapunov_check. rewrite !andb_true_iff.
  intros [[[[_ _] Hs] Hpd] HL] sr si xr xi Hnz Heig.
  apply sym_check_sound in Hs.
  destruct (pd_check_bound _ _ _ _ Hpd) as [HeQ HQ].
  destruct (pd_check_bound _ _ _ _ HL) as [HeL HM].
  assert (Hr : bf n P (Av n A xr) xr = sr * bf n P xr xr + (- si) * bf n P xi xr).
  { rewrite <- bf_comb_l. apply bf_ext_l. intros k Hk. destruct (Heig k Hk) as [E _].
    rewrite E. ring. }
  assert (Hi : bf n P (Av n A xi) xi = si * bf n P xr xi + sr * bf n P xi xi).
  { rewrite <- bf_comb_l. apply bf_ext_l. intros k Hk. destruct (Heig k Hk) as [_ E].
    rewrite E. ring. }
  assert (Hsum : qform n (lyap n A P) xr + qform n (lyap n A P) xi
                 = 2 * sr * (qform n P xr + qform n P xi)).
  { rewrite !qform_lyap, (bf_sym n P xr (Av n A xr) Hs), (bf_sym n P xi (Av n A xi) Hs).
    rewrite Hr, Hi, (bf_sym n P xi xr Hs). unfold qform. fold (bf n P xr xr).
    fold (bf n P xi xi). ring. }
  assert (Hn : 0 < sumR n (fun i => xr i * xr i) + sumR n (fun i => xi i * xi i)).
  { assert (0 <= sumR n (fun i => xr i * xr i))
      by (apply sumR_nonneg; intros; apply Rle_0_sqr).
    assert (0 <= sumR n (fun i => xi i * xi i))
      by (apply sumR_nonneg; intros; apply Rle_0_sqr).
    destruct Hnz as [Hz | Hz]; pose proof (norm2_pos n _ Hz); lra. }
  pose proof (HQ xr) as Q1. pose proof (HQ xi) as Q2.
  pose proof (HM xr) as M1. pose proof (HM xi) as M2. rewrite qform_mneg in M1, M2.
  assert (HqP : 0 < qform n P xr + qform n P xi) by nra.
  assert (Hneg : qform n (lyap n A P) xr + qform n (lyap n A P) xi < 0) by nra.
  rewrite Hsum in Hneg. nra.
Qed.
