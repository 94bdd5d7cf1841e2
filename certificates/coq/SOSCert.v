(** * Sum-of-squares certificates checked by computation

    A polynomial is data: a list of terms (exponents, rational coefficient) over the
    variables of an environment [env : list R] (a term [(m, c)] denotes
    [c * env_1^m_1 * env_2^m_2 * ...]).  [peval env p] is its value.  Nothing below
    trusts the exporter: the exporter hands over polynomials and numbers, and [vm_compute]
    runs the checks whose soundness is proved here once.

    - [poly_zero p = true] (sort the terms, add the coefficients of equal exponents,
      drop zeros, nothing left) implies [peval env p = 0] for every [env];
    - a certificate is a list of blocks: a multiplier [H] (a k x k matrix of
      polynomials) and squares [(d, u)] (a rational [d], a k-vector [u] of
      polynomials); [cert_ok target blocks = true] checks, exactly, the identity
      [target = sum over blocks and squares of d * u^T H u], that every [d] is
      non-negative and that every [u] has [H]'s size;
    - [sos_nonneg]: if, moreover, each multiplier is positive semidefinite at [env]
      (the unit proves that from the paper's hypotheses), then [0 <= peval env target].

    This is the kernel's side of the SOS steps (paper, Lemma 1 and Theorem 1; the
    certificates' LDL^T squares). *)

From Coq Require Import QArith Qreals Reals List Lra Psatz Sorting.Permutation
  Sorting.Mergesort Orders Bool.
From VerifyCoq Require Import SO3.
Import ListNotations.
Open Scope R_scope.

Definition mono := list nat.
Definition term := (mono * Q)%type.
Definition poly := list term.

(** ** Values *)

Fixpoint meval (env : list R) (m : mono) : R :=
  match m with
  | nil => 1
  | k :: m' => (hd 0 env) ^ k * meval (tl env) m'
  end.

Fixpoint peval (env : list R) (p : poly) : R :=
  match p with
  | nil => 0
  | (m, c) :: p' => Q2R c * meval env m + peval env p'
  end.

Fixpoint mono_mul (a b : mono) : mono :=
  match a, b with
  | nil, _ => b
  | _, nil => a
  | x :: a', y :: b' => (x + y)%nat :: mono_mul a' b'
  end.

Lemma meval_nil env m : meval env m = meval env m * meval env nil.
Proof. simpl. ring. Qed.

Lemma meval_mul env a b : meval env (mono_mul a b) = meval env a * meval env b.
Proof.
  revert env b. induction a as [|x a IH]; intros env b.
  - simpl. ring.
  - destruct b as [|y b]; simpl.
    + ring.
    + rewrite IH, pow_add. ring.
Qed.

Definition pscale (c : Q) (p : poly) : poly := map (fun t => (fst t, (c * snd t)%Q)) p.

Definition pmul_term (t : term) (q : poly) : poly :=
  map (fun u => (mono_mul (fst t) (fst u), (snd t * snd u)%Q)) q.

Fixpoint pmul (p q : poly) : poly :=
  match p with
  | nil => nil
  | t :: p' => pmul_term t q ++ pmul p' q
  end.

Lemma peval_app env p q : peval env (p ++ q) = peval env p + peval env q.
Proof. induction p as [|[m c] p IH]; simpl; [ring | rewrite IH; ring]. Qed.

Lemma peval_scale env c p : peval env (pscale c p) = Q2R c * peval env p.
Proof.
  induction p as [|[m d] p IH]; simpl; [ring|]. rewrite IH, Q2R_mult. ring.
Qed.

Lemma peval_mul_term env t q :
  peval env (pmul_term t q) = Q2R (snd t) * meval env (fst t) * peval env q.
Proof.
  destruct t as [m c]. induction q as [|[m' d] q IH]; simpl in *; [ring|].
  rewrite IH, Q2R_mult, meval_mul. ring.
Qed.

Lemma peval_mul env p q : peval env (pmul p q) = peval env p * peval env q.
Proof.
  induction p as [|[m c] p IH]; simpl; [ring|].
  rewrite peval_app, peval_mul_term, IH. simpl. ring.
Qed.

(** ** Normal form: sort, add equal exponents, drop zero coefficients *)

Fixpoint mono_leb (a b : mono) : bool :=
  match a, b with
  | nil, _ => true
  | _ :: _, nil => false
  | x :: a', y :: b' => if Nat.ltb x y then true else if Nat.ltb y x then false
                        else mono_leb a' b'
  end.

Lemma mono_leb_total a b : mono_leb a b = true \/ mono_leb b a = true.
Proof.
  revert b. induction a as [|x a IH]; intros [|y b]; simpl; auto.
  destruct (Nat.ltb x y) eqn:E1; auto. destruct (Nat.ltb y x) eqn:E2; auto.
Qed.

Module TermOrder <: Orders.TotalLeBool.
  Definition t := term.
  Definition leb (a b : term) := mono_leb (fst a) (fst b).
  Theorem leb_total : forall a b, leb a b = true \/ leb b a = true.
  Proof. intros a b. apply mono_leb_total. Qed.
End TermOrder.

Module TermSort := Sort TermOrder.

Lemma peval_perm env p q : Permutation p q -> peval env p = peval env q.
Proof.
  induction 1 as [|[m c] p q _ IH|[m c] [m' d] p|p q r _ IH1 _ IH2]; simpl; try lra.
Qed.

Fixpoint mono_eqb (a b : mono) : bool :=
  match a, b with
  | nil, nil => true
  | x :: a', y :: b' => Nat.eqb x y && mono_eqb a' b'
  | _, _ => false
  end.

Lemma mono_eqb_eq a b : mono_eqb a b = true -> a = b.
Proof.
  revert b. induction a as [|x a IH]; intros [|y b]; simpl; try discriminate; auto.
  intros H. apply andb_true_iff in H as [H1 H2].
  apply Nat.eqb_eq in H1. rewrite H1, (IH b H2). reflexivity.
Qed.

Lemma Q2R_Qred q : Q2R (Qred q) = Q2R q.
Proof. apply Qeq_eqR, Qred_correct. Qed.

(** Merge runs of equal exponents ([m], [c] is the run so far). *)
Fixpoint merge_runs (m : mono) (c : Q) (p : poly) : poly :=
  match p with
  | nil => [(m, c)]
  | (m', d) :: p' =>
      if mono_eqb m m' then merge_runs m (Qred (c + d)) p'
      else (m, c) :: merge_runs m' d p'
  end.

Lemma peval_merge_runs env m c p :
  peval env (merge_runs m c p) = Q2R c * meval env m + peval env p.
Proof.
  revert m c. induction p as [|[m' d] p IH]; intros m c; cbn [merge_runs peval]; [ring|].
  destruct (mono_eqb m m') eqn:E.
  - apply mono_eqb_eq in E. subst m'. rewrite IH, Q2R_Qred, Q2R_plus. ring.
  - cbn [peval]. rewrite IH. ring.
Qed.

Definition drop_zeros (p : poly) : poly :=
  filter (fun t => negb (Qeq_bool (snd t) 0)) p.

Lemma peval_drop_zeros env p : peval env (drop_zeros p) = peval env p.
Proof.
  induction p as [|[m c] p IH]; simpl; [reflexivity|].
  destruct (Qeq_bool c 0) eqn:E; simpl; rewrite IH; [|reflexivity].
  apply Qeq_bool_eq, Qeq_eqR in E. rewrite E. unfold Q2R. simpl. ring.
Qed.

(** Trailing zero exponents removed, so that equal monomials are equal lists. *)
Fixpoint trim (m : mono) : mono :=
  match m with
  | nil => nil
  | k :: m' => match k, trim m' with O, nil => nil | _, t => k :: t end
  end.

Lemma meval_trim env m : meval env (trim m) = meval env m.
Proof.
  revert env. induction m as [|k m IH]; intros env; simpl; [reflexivity|].
  destruct k as [|k]; destruct (trim m) as [|x t] eqn:E; simpl; rewrite <- (IH (tl env));
    simpl; ring.
Qed.

Definition trim_all (p : poly) : poly := map (fun t => (trim (fst t), snd t)) p.

Lemma peval_trim_all env p : peval env (trim_all p) = peval env p.
Proof.
  induction p as [|[m c] p IH]; simpl; [reflexivity|]. rewrite IH, meval_trim. reflexivity.
Qed.

Definition normal (p : poly) : poly :=
  match TermSort.sort (trim_all p) with
  | nil => nil
  | (m, c) :: p' => drop_zeros (merge_runs m c p')
  end.

Lemma peval_normal env p : peval env (normal p) = peval env p.
Proof.
  unfold normal. rewrite <- (peval_trim_all env p).
  rewrite (peval_perm env (trim_all p) _ (TermSort.Permuted_sort (trim_all p))).
  destruct (TermSort.sort (trim_all p)) as [|[m c] q]; [reflexivity|].
  rewrite peval_drop_zeros, peval_merge_runs. reflexivity.
Qed.

Definition poly_zero (p : poly) : bool :=
  match normal p with nil => true | _ => false end.

Lemma poly_zero_sound env p : poly_zero p = true -> peval env p = 0.
Proof.
  unfold poly_zero. intros H. rewrite <- (peval_normal env p).
  destruct (normal p); [reflexivity | discriminate].
Qed.

Definition pneg (p : poly) : poly := pscale (-1)%Q p.

(** ** Certificates *)

Fixpoint dotP (u v : list poly) : poly :=
  match u, v with
  | a :: u', b :: v' => normal (pmul a b) ++ dotP u' v'
  | _, _ => nil
  end.

Fixpoint dotR (u v : list R) : R :=
  match u, v with
  | a :: u', b :: v' => a * b + dotR u' v'
  | _, _ => 0
  end.

Lemma peval_dotP env u v :
  peval env (dotP u v) = dotR (map (peval env) u) (map (peval env) v).
Proof.
  revert v. induction u as [|a u IH]; intros [|b v]; simpl; try reflexivity.
  rewrite peval_app, peval_normal, peval_mul, IH. reflexivity.
Qed.

(** [u^T H u], with [H u] normalised first. *)
Definition qformP (H : list (list poly)) (u : list poly) : poly :=
  dotP u (map (fun row => normal (dotP row u)) H).

(** The quadratic form of a real matrix (a list of rows) at [x]. *)
Definition qfR (M : list (list R)) (x : list R) : R :=
  dotR x (map (fun row => dotR row x) M).

Definition evalM (env : list R) (H : list (list poly)) : list (list R) :=
  map (map (peval env)) H.

Lemma peval_qformP env H u :
  peval env (qformP H u) = qfR (evalM env H) (map (peval env) u).
Proof.
  unfold qformP, qfR, evalM. rewrite peval_dotP. f_equal.
  rewrite !map_map. apply map_ext. intros row.
  rewrite peval_normal, peval_dotP. reflexivity.
Qed.

Record block := mkBlock { mult : list (list poly); squares : list (Q * list poly) }.

Definition block_poly (b : block) : poly :=
  flat_map (fun s => pscale (fst s) (qformP (mult b) (snd s))) (squares b).

Definition cert_poly (bs : list block) : poly := flat_map block_poly bs.

Definition block_shape_ok (b : block) : bool :=
  forallb (fun s => Qle_bool 0 (fst s) && Nat.eqb (length (snd s)) (length (mult b)))
          (squares b).

Definition cert_ok (target : poly) (bs : list block) : bool :=
  forallb block_shape_ok bs && poly_zero (target ++ pneg (cert_poly bs)).

(** A multiplier positive semidefinite at [env]: its quadratic form is non-negative at
    every real vector of its size. *)
Definition mult_psd (env : list R) (H : list (list poly)) : Prop :=
  forall x : list R, length x = length H -> 0 <= qfR (evalM env H) x.

Lemma Qle_bool_R a : Qle_bool 0 a = true -> 0 <= Q2R a.
Proof.
  intros H. apply Qle_bool_iff, Qle_Rle in H. unfold Q2R in H at 1. simpl in H. lra.
Qed.

Lemma block_nonneg env b :
  block_shape_ok b = true -> mult_psd env (mult b) -> 0 <= peval env (block_poly b).
Proof.
  unfold block_shape_ok, block_poly. intros Hs Hm.
  induction (squares b) as [|[d u] ss IH]; simpl in *; [lra|].
  apply andb_true_iff in Hs as [Hs Hss]. apply andb_true_iff in Hs as [Hd Hl].
  rewrite peval_app, peval_scale, peval_qformP.
  apply Rplus_le_le_0_compat; [|exact (IH Hss)].
  apply Rmult_le_pos; [exact (Qle_bool_R d Hd)|].
  apply Hm. rewrite map_length. apply Nat.eqb_eq, Hl.
Qed.

Lemma cert_poly_nonneg env bs :
  forallb block_shape_ok bs = true -> (forall b, In b bs -> mult_psd env (mult b)) ->
  0 <= peval env (cert_poly bs).
Proof.
  induction bs as [|b bs IH]; simpl; intros Hs Hm; [lra|].
  apply andb_true_iff in Hs as [Hb Hbs]. rewrite peval_app.
  apply Rplus_le_le_0_compat; [apply block_nonneg; auto|apply IH; auto].
Qed.

Theorem sos_nonneg env target bs :
  cert_ok target bs = true -> (forall b, In b bs -> mult_psd env (mult b)) ->
  0 <= peval env target.
Proof.
  unfold cert_ok. intros H Hm. apply andb_true_iff in H as [Hs Hz].
  apply (poly_zero_sound env) in Hz.
  rewrite peval_app in Hz. unfold pneg in Hz. rewrite peval_scale in Hz.
  assert (E : Q2R (-1) = -1) by (unfold Q2R; simpl; lra). rewrite E in Hz.
  pose proof (cert_poly_nonneg env bs Hs Hm). lra.
Qed.

(** ** Multipliers from the paper's facts *)

(** A 1 x 1 multiplier [g] is positive semidefinite when [0 <= g]. *)
Lemma mult_psd_scalar env g : 0 <= peval env g -> mult_psd env [[g]].
Proof.
  intros Hg [|x [|y xs]]; simpl; try discriminate. intros _.
  unfold qfR, evalM; simpl. nra.
Qed.

(** A 3 x 3 multiplier whose quadratic form is [c] times a non-negative one. *)
Lemma mult_psd_3 env H (c : R) (Q : R -> R -> R -> R) :
  length H = 3%nat -> 0 <= c -> (forall a b d, 0 <= Q a b d) ->
  (forall a b d, qfR (evalM env H) [a; b; d] = c * Q a b d) -> mult_psd env H.
Proof.
  intros Hl Hc HQ E [|a [|b [|d [|e xs]]]]; rewrite Hl; simpl; try discriminate.
  intros _. rewrite E. apply Rmult_le_pos; auto.
Qed.

Definition blocks_psd (env : list R) (bs : list block) : Prop :=
  forall b, In b bs -> mult_psd env (mult b).

Lemma blocks_psd_cons env b bs :
  mult_psd env (mult b) -> blocks_psd env bs -> blocks_psd env (b :: bs).
Proof. intros H1 H2 x [<-|Hx]; auto. Qed.

Lemma blocks_psd_nil env : blocks_psd env nil.
Proof. intros x []. Qed.

(** ** From the certificate to the step *)

(** [slack * D = F * T] with [D > 0], [F >= 0], [T >= 0] gives [slack >= 0]. *)
Lemma slack_nonneg (s D F T : R) :
  s * D = F * T -> 0 < D -> 0 <= F -> 0 <= T -> 0 <= s.
Proof.
  intros E HD HF HT. assert (0 <= F * T) by (apply Rmult_le_pos; auto).
  destruct (Rle_or_lt 0 s) as [|Hs]; [assumption|]. nra.
Qed.

Lemma qn_pos (q : quat) : qn q <> 0 -> 0 < qn q.
Proof.
  unfold qn. intros H.
  destruct (Rle_lt_or_eq_dec 0 (qw q * qw q + qx q * qx q + qy q * qy q + qz q * qz q))
    as [|E]; [nra|assumption|]. symmetry in E. contradiction.
Qed.

Lemma chart_den_pos (a b : R) : 0 < 1 + a * a + b * b.
Proof. nra. Qed.

Lemma angle_den_pos (t : R) : 0 < 1 + t * t.
Proof. nra. Qed.

(** The paper's charts: the stereographic unit vector and the half-angle tangent (they
    miss the pole [(0, 0, 1)] and the angle pi; see the units' comments). *)
Definition stereo (a b : R) : V3 :=
  mkV (2 * a / (1 + a * a + b * b)) (2 * b / (1 + a * a + b * b))
      ((a * a + b * b - 1) / (1 + a * a + b * b)).

(** Non-zero denominators of [field] in the SOS units: quaternion norms and the charts'
    [1 + a^2 + b^2], [1 + t^2]. *)
Ltac sos_nonzero :=
  so3_nonzero;
  repeat match goal with
  | |- 1 + ?a * ?a + ?b * ?b <> 0 => apply Rgt_not_eq, chart_den_pos
  | |- 1 + ?t * ?t <> 0 => apply Rgt_not_eq, angle_den_pos
  end.

(** ** Integer coefficients: a plainer value for [field] *)

Fixpoint zeval (env : list R) (p : poly) : R :=
  match p with
  | nil => 0
  | (m, c) :: p' => IZR (Qnum c) * meval env m + zeval env p'
  end.

Definition all_int (p : poly) : bool := forallb (fun t => Pos.eqb (Qden (snd t)) 1) p.

Lemma zeval_peval env p : all_int p = true -> peval env p = zeval env p.
Proof.
  induction p as [|[m [n d]] p IH]; cbn [peval zeval all_int forallb]; [reflexivity|].
  intros H. apply andb_true_iff in H as [H1 H2]. cbn [snd Qden] in H1.
  apply Pos.eqb_eq in H1. subst d.
  rewrite (IH H2). unfold Q2R. simpl. field.
Qed.

Definition evalMZ (env : list R) (H : list (list poly)) : list (list R) :=
  map (map (zeval env)) H.

Definition all_int_matrix (H : list (list poly)) : bool := forallb (forallb all_int) H.

Lemma evalM_Z env H : all_int_matrix H = true -> evalM env H = evalMZ env H.
Proof.
  unfold evalM, evalMZ, all_int_matrix. induction H as [|row H IH]; simpl; [reflexivity|].
  intros E. apply andb_true_iff in E as [E1 E2]. rewrite (IH E2). f_equal.
  induction row as [|p row IHr]; simpl in *; [reflexivity|].
  apply andb_true_iff in E1 as [Ep Er]. rewrite (zeval_peval env p Ep), (IHr Er).
  reflexivity.
Qed.

(** ** The link by computation, at the level of the prelude's operations

    A unit's statement is written with the prelude's definitions ([rot q], [mmul], [mT],
    [sk], [hat], [vee], [tr], [phi], [vdot], ...).  [sx], [mx], [vx] are that language
    (scalars, matrices, vectors): its leaves are the parameters (the entries of [env]),
    the rotations [rot q] (with the position of [q]'s entries in [env]) and the vectors
    (with the position of their entries).  [sden], [mden], [vden] give a term's value with
    the prelude's own operations, so that a statement and the denotation of its reading
    are the same term up to unfolding the denotation: the kernel checks that cheaply.
    [evs], [evm], [evv] compute the value of every scalar, of every entry of a matrix or
    vector, as a polynomial over a product of powers of quaternion norms ([sv]), each
    matrix subexpression once; [ev_sound] proves them right once.  So a unit's link needs
    no [field] on large polynomials and no unfolding of its statement into a tree of
    reals: the tactic [sos_reify] reads the statement (a few dozen operations) and
    [vm_compute] compares the polynomials. *)

(** The norm of the quaternion whose entries are [env_p .. env_(p+3)]. *)
Definition qnR (env : list R) (p : nat) : R :=
  nth p env 0 * nth p env 0 + nth (S p) env 0 * nth (S p) env 0 +
  nth (S (S p)) env 0 * nth (S (S p)) env 0 +
  nth (S (S (S p))) env 0 * nth (S (S (S p))) env 0.

(** Denominators: [e_p] is the power of the norm of the quaternion at [env_p]. *)
Fixpoint denp (env : list R) (p : nat) (e : list nat) : R :=
  match e with
  | nil => 1
  | k :: e' => qnR env p ^ k * denp env (S p) e'
  end.

Fixpoint eadd (a b : list nat) : list nat :=
  match a, b with
  | nil, _ => b
  | _, nil => a
  | x :: a', y :: b' => (x + y)%nat :: eadd a' b'
  end.

Fixpoint emax (a b : list nat) : list nat :=
  match a, b with
  | nil, _ => b
  | _, nil => a
  | x :: a', y :: b' => Nat.max x y :: emax a' b'
  end.

(** [c - a] entrywise (for [a <= c]). *)
Fixpoint ediff (a c : list nat) : list nat :=
  match a, c with
  | nil, _ => c
  | _, nil => nil
  | x :: a', y :: c' => (y - x)%nat :: ediff a' c'
  end.

Lemma denp_eadd env p a b : denp env p (eadd a b) = denp env p a * denp env p b.
Proof.
  revert p b. induction a as [|x a IH]; intros p [|y b]; simpl; try ring.
  rewrite IH, pow_add. ring.
Qed.

Lemma eadd_ediff_self a : eadd a (ediff a a) = a.
Proof.
  induction a as [|x a IH]; simpl; [reflexivity|]. rewrite IH. f_equal. lia.
Qed.

Lemma eadd_ediff_l a b : eadd a (ediff a (emax a b)) = emax a b.
Proof.
  revert b. induction a as [|x a IH]; intros [|y b]; simpl; try reflexivity.
  - rewrite eadd_ediff_self. f_equal. lia.
  - rewrite IH. f_equal. lia.
Qed.

Lemma emax_comm a b : emax a b = emax b a.
Proof.
  revert b. induction a as [|x a IH]; intros [|y b]; simpl; try reflexivity.
  rewrite IH, Nat.max_comm. reflexivity.
Qed.

Fixpoint mono_at (p k : nat) : mono :=
  match p with O => [k] | S p' => 0%nat :: mono_at p' k end.

Lemma meval_at env p k : meval env (mono_at p k) = nth p env 0 ^ k.
Proof.
  revert env. induction p as [|p IH]; intros env; simpl.
  - destruct env; simpl; ring.
  - rewrite IH. destruct env; simpl; [destruct p; simpl; ring | ring].
Qed.

Definition qnP (p : nat) : poly :=
  [(mono_at p 2, 1%Q); (mono_at (S p) 2, 1%Q); (mono_at (S (S p)) 2, 1%Q);
   (mono_at (S (S (S p))) 2, 1%Q)].

Lemma peval_qnP env p : peval env (qnP p) = qnR env p.
Proof.
  unfold qnP, qnR. cbn [peval]. rewrite !meval_at.
  replace (Q2R 1) with 1 by (unfold Q2R; simpl; field). ring.
Qed.

Definition pone : poly := [(nil, 1%Q)].

Lemma peval_pone env : peval env pone = 1.
Proof. unfold pone. cbn [peval meval]. unfold Q2R. simpl. field. Qed.

Fixpoint ppow (a : poly) (k : nat) : poly :=
  match k with O => pone | S k' => normal (pmul a (ppow a k')) end.

Lemma peval_ppow env a k : peval env (ppow a k) = peval env a ^ k.
Proof.
  induction k as [|k IH]; simpl; [apply (peval_pone env)|].
  rewrite peval_normal, peval_mul, IH. reflexivity.
Qed.

Fixpoint liftP (p : nat) (d : list nat) : poly :=
  match d with
  | nil => pone
  | k :: d' => normal (pmul (ppow (qnP p) k) (liftP (S p) d'))
  end.

Lemma peval_liftP env p d : peval env (liftP p d) = denp env p d.
Proof.
  revert p. induction d as [|k d IH]; intros p; simpl; [apply (peval_pone env)|].
  rewrite peval_normal, peval_mul, peval_ppow, peval_qnP, IH. reflexivity.
Qed.

Lemma denp_at_from env c p k : denp env c (mono_at p k) = qnR env (c + p) ^ k.
Proof.
  revert c. induction p as [|p IH]; intros c; simpl.
  - rewrite Nat.add_0_r. ring.
  - rewrite IH, Nat.add_succ_r. simpl. ring.
Qed.

Lemma denp_at env p k : denp env 0 (mono_at p k) = qnR env p ^ k.
Proof. apply denp_at_from. Qed.

Fixpoint exps_ok_from (qs : list nat) (c : nat) (e : list nat) : bool :=
  match e with
  | nil => true
  | k :: e' => (Nat.eqb k 0 || existsb (Nat.eqb c) qs) && exps_ok_from qs (S c) e'
  end.

Lemma qnR_nonneg env p : 0 <= qnR env p.
Proof. unfold qnR. nra. Qed.

Lemma denp_pos env qs c e :
  Forall (fun p => qnR env p <> 0) qs -> exps_ok_from qs c e = true -> 0 < denp env c e.
Proof.
  intros Hq. revert c. induction e as [|k e IH]; intros c H; simpl in *; [lra|].
  apply andb_true_iff in H as [Hk He]. apply Rmult_lt_0_compat; [|exact (IH _ He)].
  apply orb_true_iff in Hk as [Hk|Hk].
  - apply Nat.eqb_eq in Hk. subst k. simpl. lra.
  - apply existsb_exists in Hk as [p [Hin Hp]]. apply Nat.eqb_eq in Hp. subst p.
    rewrite Forall_forall in Hq. apply pow_lt.
    destruct (Rle_lt_or_eq_dec _ _ (qnR_nonneg env c)) as [|E]; [assumption|].
    exfalso. exact (Hq c Hin (eq_sym E)).
Qed.

Lemma denp_nonneg env c e : 0 <= denp env c e.
Proof.
  revert c. induction e as [|k e IH]; intros c; simpl; [lra|].
  apply Rmult_le_pos; [apply pow_le, qnR_nonneg | apply IH].
Qed.

Lemma denp_zeros env c e : forallb (Nat.eqb 0) e = true -> denp env c e = 1.
Proof.
  revert c. induction e as [|k e IH]; intros c H; simpl in *; [reflexivity|].
  apply andb_true_iff in H as [Hk He]. destruct k; [|discriminate].
  rewrite (IH _ He). ring.
Qed.

(** [n] times the product of norms [d] (nothing to compute for [0] or for [d = 1]). *)
Definition lift (n : poly) (d : list nat) : poly :=
  match n with
  | nil => nil
  | _ => if forallb (Nat.eqb 0) d then n else pmul n (liftP 0 d)
  end.

Lemma peval_lift env n d : peval env (lift n d) = peval env n * denp env 0 d.
Proof.
  unfold lift. destruct n as [|t n]; [simpl; ring|].
  destruct (forallb (Nat.eqb 0) d) eqn:E.
  - rewrite (denp_zeros env 0 d E). ring.
  - rewrite peval_mul, peval_liftP. reflexivity.
Qed.

(** *** Values: a polynomial over a product of powers of norms *)

Definition sv := (poly * list nat)%type.

(** [v] is the value of [x]: [x * den = numerator]. *)
Definition srel (env : list R) (x : R) (v : sv) : Prop :=
  x * denp env 0 (snd v) = peval env (fst v).

Definition sv_q (c : Q) : sv := ([(nil, c)], nil).
Definition sv_var (i : nat) : sv := ([(mono_at i 1, 1%Q)], nil).
Definition sv_add (a b : sv) : sv :=
  let e := emax (snd a) (snd b) in
  (normal (lift (fst a) (ediff (snd a) e) ++ lift (fst b) (ediff (snd b) e)), e).
Definition sv_mul (a b : sv) : sv := (normal (pmul (fst a) (fst b)), eadd (snd a) (snd b)).
Definition sv_neg (a : sv) : sv := (pneg (fst a), snd a).
Definition sv_sub (a b : sv) : sv := sv_add a (sv_neg b).
Definition sv_scq (c : Q) (a : sv) : sv := (pscale c (fst a), snd a).

Lemma Q2R_1 : Q2R 1 = 1.
Proof. unfold Q2R. simpl. field. Qed.

Lemma sv_q_ok env c : srel env (Q2R c) (sv_q c).
Proof. unfold srel, sv_q. cbn [fst snd denp peval meval]. ring. Qed.

Lemma sv_Z_ok env z : srel env (IZR z) (sv_q (inject_Z z)).
Proof. unfold srel, sv_q. cbn [fst snd denp peval meval]. unfold Q2R. simpl. field. Qed.

Lemma sv_var_ok env i : srel env (nth i env 0) (sv_var i).
Proof.
  unfold srel, sv_var. cbn [fst snd denp peval]. rewrite meval_at, Q2R_1. ring.
Qed.

Lemma sv_add_ok env x y a b :
  srel env x a -> srel env y b -> srel env (x + y) (sv_add a b).
Proof.
  unfold srel, sv_add. destruct a as [na ea], b as [nb eb]. cbn [fst snd]. intros Ha Hb.
  rewrite peval_normal, peval_app, !peval_lift, <- Ha, <- Hb.
  assert (E1 : denp env 0 (emax ea eb)
               = denp env 0 ea * denp env 0 (ediff ea (emax ea eb)))
    by (rewrite <- denp_eadd, eadd_ediff_l; reflexivity).
  assert (E2 : denp env 0 (emax ea eb)
               = denp env 0 eb * denp env 0 (ediff eb (emax ea eb)))
    by (rewrite <- denp_eadd, (emax_comm ea eb), eadd_ediff_l; reflexivity).
  rewrite Rmult_plus_distr_r. f_equal; [rewrite E1 | rewrite E2]; ring.
Qed.

Lemma sv_mul_ok env x y a b :
  srel env x a -> srel env y b -> srel env (x * y) (sv_mul a b).
Proof.
  unfold srel, sv_mul. destruct a as [na ea], b as [nb eb]. cbn [fst snd]. intros Ha Hb.
  rewrite peval_normal, peval_mul, denp_eadd, <- Ha, <- Hb. ring.
Qed.

Lemma sv_neg_ok env x a : srel env x a -> srel env (- x) (sv_neg a).
Proof.
  unfold srel, sv_neg, pneg. destruct a as [na ea]. cbn [fst snd]. intros Ha.
  rewrite peval_scale, <- Ha. unfold Q2R. simpl. field.
Qed.

Lemma sv_sub_ok env x y a b :
  srel env x a -> srel env y b -> srel env (x - y) (sv_sub a b).
Proof. intros Ha Hb. unfold Rminus. apply sv_add_ok; [exact Ha | apply sv_neg_ok, Hb]. Qed.

Lemma sv_divc_ok env x a d :
  srel env x a -> srel env (x / IZR (Zpos d)) (sv_scq (1 # d) a).
Proof.
  unfold srel, sv_scq. destruct a as [na ea]. cbn [fst snd]. intros Ha.
  rewrite peval_scale, <- Ha. unfold Q2R. simpl. field. apply not_0_IZR. discriminate.
Qed.

Lemma sv_half_ok env : srel env (1 / 2) (sv_q (1 # 2)).
Proof.
  replace (1 / 2) with (Q2R (1 # 2)) by (unfold Q2R; simpl; field). apply sv_q_ok.
Qed.

Lemma sv_zero_ok env : srel env 0 (sv_q 0).
Proof. apply (sv_Z_ok env 0). Qed.

Lemma sv_one_ok env : srel env 1 (sv_q 1).
Proof. apply (sv_Z_ok env 1). Qed.

Lemma sv_mone_ok env : srel env (-1) (sv_q (-1)).
Proof. apply (sv_Z_ok env (-1)). Qed.

(** Vectors and matrices: one value per entry. *)
Record vv := VV { f1 : sv; f2 : sv; f3 : sv }.
Record mv := MV { e11 : sv; e12 : sv; e13 : sv; e21 : sv; e22 : sv; e23 : sv;
                  e31 : sv; e32 : sv; e33 : sv }.

Definition vrel env (u : V3) (a : vv) : Prop :=
  srel env (v1 u) (f1 a) /\ srel env (v2 u) (f2 a) /\ srel env (v3 u) (f3 a).

Definition mrel env (A : M3) (a : mv) : Prop :=
  srel env (m11 A) (e11 a) /\ srel env (m12 A) (e12 a) /\ srel env (m13 A) (e13 a) /\
  srel env (m21 A) (e21 a) /\ srel env (m22 A) (e22 a) /\ srel env (m23 A) (e23 a) /\
  srel env (m31 A) (e31 a) /\ srel env (m32 A) (e32 a) /\ srel env (m33 A) (e33 a).

(** The prelude's operations on values, entry by entry as in [SO3.v]. *)
Definition mv_I3 : mv := let o := sv_q 1 in let z := sv_q 0 in MV o z z z o z z z o.
Definition mv_Z3 : mv := let z := sv_q 0 in MV z z z z z z z z z.
Definition mv_add (a b : mv) : mv :=
  MV (sv_add (e11 a) (e11 b)) (sv_add (e12 a) (e12 b)) (sv_add (e13 a) (e13 b))
     (sv_add (e21 a) (e21 b)) (sv_add (e22 a) (e22 b)) (sv_add (e23 a) (e23 b))
     (sv_add (e31 a) (e31 b)) (sv_add (e32 a) (e32 b)) (sv_add (e33 a) (e33 b)).
Definition mv_scale (c : sv) (a : mv) : mv :=
  MV (sv_mul c (e11 a)) (sv_mul c (e12 a)) (sv_mul c (e13 a))
     (sv_mul c (e21 a)) (sv_mul c (e22 a)) (sv_mul c (e23 a))
     (sv_mul c (e31 a)) (sv_mul c (e32 a)) (sv_mul c (e33 a)).
Definition mv_neg (a : mv) : mv := mv_scale (sv_q (-1)) a.
Definition mv_sub (a b : mv) : mv := mv_add a (mv_neg b).
Definition mv_mul (a b : mv) : mv :=
  let d x1 x2 x3 y1 y2 y3 := sv_add (sv_add (sv_mul x1 y1) (sv_mul x2 y2)) (sv_mul x3 y3) in
  MV (d (e11 a) (e12 a) (e13 a) (e11 b) (e21 b) (e31 b))
     (d (e11 a) (e12 a) (e13 a) (e12 b) (e22 b) (e32 b))
     (d (e11 a) (e12 a) (e13 a) (e13 b) (e23 b) (e33 b))
     (d (e21 a) (e22 a) (e23 a) (e11 b) (e21 b) (e31 b))
     (d (e21 a) (e22 a) (e23 a) (e12 b) (e22 b) (e32 b))
     (d (e21 a) (e22 a) (e23 a) (e13 b) (e23 b) (e33 b))
     (d (e31 a) (e32 a) (e33 a) (e11 b) (e21 b) (e31 b))
     (d (e31 a) (e32 a) (e33 a) (e12 b) (e22 b) (e32 b))
     (d (e31 a) (e32 a) (e33 a) (e13 b) (e23 b) (e33 b)).
Definition mv_T (a : mv) : mv :=
  MV (e11 a) (e21 a) (e31 a) (e12 a) (e22 a) (e32 a) (e13 a) (e23 a) (e33 a).
Definition mv_sk (a : mv) : mv := mv_scale (sv_q (1 # 2)) (mv_sub a (mv_T a)).
Definition mv_sym (a : mv) : mv := mv_scale (sv_q (1 # 2)) (mv_add a (mv_T a)).
Definition mv_hat (u : vv) : mv :=
  let z := sv_q 0 in
  MV z (sv_neg (f3 u)) (f2 u) (f3 u) z (sv_neg (f1 u)) (sv_neg (f2 u)) (f1 u) z.
Definition mv_outer (u w : vv) : mv :=
  MV (sv_mul (f1 u) (f1 w)) (sv_mul (f1 u) (f2 w)) (sv_mul (f1 u) (f3 w))
     (sv_mul (f2 u) (f1 w)) (sv_mul (f2 u) (f2 w)) (sv_mul (f2 u) (f3 w))
     (sv_mul (f3 u) (f1 w)) (sv_mul (f3 u) (f2 w)) (sv_mul (f3 u) (f3 w)).
Definition mv_symm (a11 a22 a33 a12 a13 a23 : sv) : mv :=
  MV a11 a12 a13 a12 a22 a23 a13 a23 a33.
Definition vv_zero : vv := let z := sv_q 0 in VV z z z.
Definition vv_add (u w : vv) : vv :=
  VV (sv_add (f1 u) (f1 w)) (sv_add (f2 u) (f2 w)) (sv_add (f3 u) (f3 w)).
Definition vv_neg (u : vv) : vv := VV (sv_neg (f1 u)) (sv_neg (f2 u)) (sv_neg (f3 u)).
Definition vv_scale (c : sv) (u : vv) : vv :=
  VV (sv_mul c (f1 u)) (sv_mul c (f2 u)) (sv_mul c (f3 u)).
Definition vv_mv (a : mv) (u : vv) : vv :=
  let d x1 x2 x3 := sv_add (sv_add (sv_mul x1 (f1 u)) (sv_mul x2 (f2 u))) (sv_mul x3 (f3 u)) in
  VV (d (e11 a) (e12 a) (e13 a)) (d (e21 a) (e22 a) (e23 a)) (d (e31 a) (e32 a) (e33 a)).
Definition vv_vee (a : mv) : vv :=
  VV (sv_scq (1 # 2) (sv_sub (e32 a) (e23 a))) (sv_scq (1 # 2) (sv_sub (e13 a) (e31 a)))
     (sv_scq (1 # 2) (sv_sub (e21 a) (e12 a))).
Definition sv_tr (a : mv) : sv := sv_add (sv_add (e11 a) (e22 a)) (e33 a).
(** [tr (A B)] without the off-diagonal entries of [A B]. *)
Definition sv_trmul (a b : mv) : sv :=
  let d x1 x2 x3 y1 y2 y3 := sv_add (sv_add (sv_mul x1 y1) (sv_mul x2 y2)) (sv_mul x3 y3) in
  sv_add (sv_add (d (e11 a) (e12 a) (e13 a) (e11 b) (e21 b) (e31 b))
                 (d (e21 a) (e22 a) (e23 a) (e12 b) (e22 b) (e32 b)))
         (d (e31 a) (e32 a) (e33 a) (e13 b) (e23 b) (e33 b)).
Definition sv_phi (a : mv) : sv := sv_scq (1 # 2) (sv_tr (mv_sub mv_I3 a)).
Definition sv_vdot (u w : vv) : sv :=
  sv_add (sv_add (sv_mul (f1 u) (f1 w)) (sv_mul (f2 u) (f2 w))) (sv_mul (f3 u) (f3 w)).

(** The rotation [rot q] whose [q] has its entries at [env_p .. env_(p+3)]. *)
Definition mv_rot (p : nat) : mv :=
  let u := VV (sv_var (S p)) (sv_var (S (S p))) (sv_var (S (S (S p)))) in
  mv_add mv_I3 (mv_scale ([(nil, 2%Q)], mono_at p 1)
                         (mv_add (mv_scale (sv_var p) (mv_hat u)) (mv_mul (mv_hat u) (mv_hat u)))).

(** Entries by number, for the multipliers' entries ([m11 A] is [ment 0 A]). *)
Definition ment (k : nat) (A : M3) : R :=
  match k with
  | 0%nat => m11 A | 1%nat => m12 A | 2%nat => m13 A | 3%nat => m21 A | 4%nat => m22 A
  | 5%nat => m23 A | 6%nat => m31 A | 7%nat => m32 A | _ => m33 A
  end.

Definition mv_ent (k : nat) (a : mv) : sv :=
  match k with
  | 0%nat => e11 a | 1%nat => e12 a | 2%nat => e13 a | 3%nat => e21 a | 4%nat => e22 a
  | 5%nat => e23 a | 6%nat => e31 a | 7%nat => e32 a | _ => e33 a
  end.

Definition vent (k : nat) (u : V3) : R := match k with 0%nat => v1 u | 1%nat => v2 u | _ => v3 u end.
Definition vv_ent (k : nat) (a : vv) : sv :=
  match k with 0%nat => f1 a | 1%nat => f2 a | _ => f3 a end.

(** Each operation's value is right. *)
Ltac rel_go :=
  repeat match goal with
  | |- _ /\ _ => split
  | |- srel _ (_ + _) (sv_add _ _) => apply sv_add_ok
  | |- srel _ (_ * _) (sv_mul _ _) => apply sv_mul_ok
  | |- srel _ (- _) (sv_neg _) => apply sv_neg_ok
  | |- srel _ (_ - _) (sv_sub _ _) => apply sv_sub_ok
  | |- srel _ (_ / IZR (Zpos _)) (sv_scq _ _) => apply sv_divc_ok
  | |- srel _ (IZR Z0) (sv_q 0) => apply sv_zero_ok
  | |- srel _ (IZR (Zpos xH)) (sv_q 1) => apply sv_one_ok
  | |- srel _ (IZR (Zneg xH)) (sv_q (-1)) => apply sv_mone_ok
  | |- srel _ (IZR (Zpos xH) / IZR (Zpos (xO xH))) (sv_q (1 # 2)) => apply sv_half_ok
  | H : ?P |- ?P => exact H
  end.

Lemma mv_I3_ok env : mrel env I3 mv_I3.
Proof. unfold mrel, mv_I3, I3. cbn -[srel sv_q]. rel_go. Qed.

Lemma mv_Z3_ok env : mrel env Z3 mv_Z3.
Proof. unfold mrel, mv_Z3, Z3. cbn -[srel sv_q]. rel_go. Qed.

Ltac rel_destr :=
  repeat match goal with
  | H : mrel _ _ _ |- _ => unfold mrel in H; destruct H as (?&?&?&?&?&?&?&?&?)
  | H : vrel _ _ _ |- _ => unfold vrel in H; destruct H as (?&?&?)
  end.

Lemma mv_add_ok env A B a b : mrel env A a -> mrel env B b -> mrel env (madd A B) (mv_add a b).
Proof. intros. rel_destr. unfold mrel, madd, mv_add. cbn -[srel sv_add]. rel_go. Qed.

Lemma mv_scale_ok env c A x a :
  srel env c x -> mrel env A a -> mrel env (mscale c A) (mv_scale x a).
Proof. intros. rel_destr. unfold mrel, mscale, mv_scale. cbn -[srel sv_mul]. rel_go. Qed.

Lemma mv_neg_ok env A a : mrel env A a -> mrel env (mneg A) (mv_neg a).
Proof. intros. unfold mneg, mv_neg. apply mv_scale_ok; [apply sv_mone_ok | assumption]. Qed.

Lemma mv_sub_ok env A B a b : mrel env A a -> mrel env B b -> mrel env (msub A B) (mv_sub a b).
Proof. intros. unfold msub, mv_sub. apply mv_add_ok; [|apply mv_neg_ok]; assumption. Qed.

Lemma mv_mul_ok env A B a b : mrel env A a -> mrel env B b -> mrel env (mmul A B) (mv_mul a b).
Proof. intros. rel_destr. unfold mrel, mmul, mv_mul. cbn -[srel sv_add sv_mul]. rel_go. Qed.

Lemma mv_T_ok env A a : mrel env A a -> mrel env (mT A) (mv_T a).
Proof. intros. rel_destr. unfold mrel, mT, mv_T. cbn -[srel]. rel_go. Qed.

Lemma mv_sk_ok env A a : mrel env A a -> mrel env (sk A) (mv_sk a).
Proof.
  intros. unfold sk, mv_sk. apply mv_scale_ok; [apply sv_half_ok|].
  apply mv_sub_ok; [|apply mv_T_ok]; assumption.
Qed.

Lemma mv_sym_ok env A a : mrel env A a -> mrel env (sym A) (mv_sym a).
Proof.
  intros. unfold sym, mv_sym. apply mv_scale_ok; [apply sv_half_ok|].
  apply mv_add_ok; [|apply mv_T_ok]; assumption.
Qed.

Lemma mv_hat_ok env u a : vrel env u a -> mrel env (hat u) (mv_hat a).
Proof. intros. rel_destr. unfold mrel, hat, mv_hat. cbn -[srel sv_neg sv_q]. rel_go. Qed.

Lemma mv_outer_ok env u w a b : vrel env u a -> vrel env w b -> mrel env (outer u w) (mv_outer a b).
Proof. intros. rel_destr. unfold mrel, outer, mv_outer. cbn -[srel sv_mul]. rel_go. Qed.

Lemma mv_symm_ok env x11 x22 x33 x12 x13 x23 a11 a22 a33 a12 a13 a23 :
  srel env x11 a11 -> srel env x22 a22 -> srel env x33 a33 -> srel env x12 a12 ->
  srel env x13 a13 -> srel env x23 a23 ->
  mrel env (symm x11 x22 x33 x12 x13 x23) (mv_symm a11 a22 a33 a12 a13 a23).
Proof. intros. unfold mrel, symm, mv_symm. cbn -[srel]. rel_go. Qed.

Lemma vv_zero_ok env : vrel env vzero vv_zero.
Proof. unfold vrel, vzero, vv_zero. cbn -[srel sv_q]. rel_go. Qed.

Lemma vv_add_ok env u w a b : vrel env u a -> vrel env w b -> vrel env (vadd u w) (vv_add a b).
Proof. intros. rel_destr. unfold vrel, vadd, vv_add. cbn -[srel sv_add]. rel_go. Qed.

Lemma vv_neg_ok env u a : vrel env u a -> vrel env (vneg u) (vv_neg a).
Proof. intros. rel_destr. unfold vrel, vneg, vv_neg. cbn -[srel sv_neg]. rel_go. Qed.

Lemma vv_scale_ok env c u x a :
  srel env c x -> vrel env u a -> vrel env (vscale c u) (vv_scale x a).
Proof. intros. rel_destr. unfold vrel, vscale, vv_scale. cbn -[srel sv_mul]. rel_go. Qed.

Lemma vv_mv_ok env A u a b : mrel env A a -> vrel env u b -> vrel env (mvmul A u) (vv_mv a b).
Proof. intros. rel_destr. unfold vrel, mvmul, vv_mv. cbn -[srel sv_add sv_mul]. rel_go. Qed.

Lemma vv_vee_ok env A a : mrel env A a -> vrel env (vee A) (vv_vee a).
Proof. intros. rel_destr. unfold vrel, vee, vv_vee. cbn -[srel sv_scq sv_sub]. rel_go. Qed.

Lemma sv_tr_ok env A a : mrel env A a -> srel env (tr A) (sv_tr a).
Proof. intros. rel_destr. unfold tr, sv_tr. cbn -[srel sv_add]. rel_go. Qed.

Lemma sv_trmul_ok env A B a b :
  mrel env A a -> mrel env B b -> srel env (tr (mmul A B)) (sv_trmul a b).
Proof. intros. rel_destr. unfold tr, mmul, sv_trmul. cbn -[srel sv_add sv_mul]. rel_go. Qed.

Lemma sv_phi_ok env A a : mrel env A a -> srel env (phi A) (sv_phi a).
Proof.
  intros. unfold phi, sv_phi. apply (sv_divc_ok env _ _ 2).
  apply sv_tr_ok, mv_sub_ok; [apply mv_I3_ok | assumption].
Qed.

Lemma sv_vdot_ok env u w a b : vrel env u a -> vrel env w b -> srel env (vdot u w) (sv_vdot a b).
Proof. intros. rel_destr. unfold vdot, sv_vdot. cbn -[srel sv_add sv_mul]. rel_go. Qed.

Lemma mv_ent_ok env k A a : mrel env A a -> srel env (ment k A) (mv_ent k a).
Proof.
  intros H. rel_destr.
  do 8 (destruct k as [|k]; [assumption|]). assumption.
Qed.

Lemma vv_ent_ok env k u a : vrel env u a -> srel env (vent k u) (vv_ent k a).
Proof.
  intros H. rel_destr. do 2 (destruct k as [|k]; [assumption|]). assumption.
Qed.

Lemma mv_rot_ok env q p :
  qw q = nth p env 0 -> qx q = nth (S p) env 0 -> qy q = nth (S (S p)) env 0 ->
  qz q = nth (S (S (S p))) env 0 -> qn q <> 0 -> mrel env (rot q) (mv_rot p).
Proof.
  intros Hw Hx Hy Hz Hn. unfold rot, mv_rot.
  assert (Hu : vrel env (qvec q) (VV (sv_var (S p)) (sv_var (S (S p))) (sv_var (S (S (S p)))))).
  { unfold vrel, qvec. cbn [v1 v2 v3 f1 f2 f3]. rewrite Hx, Hy, Hz.
    split; [|split]; apply sv_var_ok. }
  apply mv_add_ok; [apply mv_I3_ok|]. apply mv_scale_ok.
  - unfold srel. cbn [fst snd peval meval]. rewrite denp_at.
    assert (E : qn q = qnR env p) by (unfold qn, qnR; rewrite Hw, Hx, Hy, Hz; reflexivity).
    rewrite <- E. unfold Q2R. simpl. field. exact Hn.
  - apply mv_add_ok; [apply mv_scale_ok; [rewrite Hw; apply sv_var_ok | apply mv_hat_ok, Hu]|].
    apply mv_mul_ok; apply mv_hat_ok, Hu.
Qed.

(** *** The language and its reading *)

Inductive mx : Type :=
| MRot (q : quat) (p : nat)   (* rot q, q's entries at env_p .. env_(p+3) *)
| MI3 | MZ3
| MAdd (a b : mx) | MSub (a b : mx) | MNeg (a : mx) | MScale (c : sx) (a : mx)
| MMul (a b : mx) | MT (a : mx) | MSk (a : mx) | MSym (a : mx)
| MHat (u : vx) | MOuter (u w : vx)
| MSymm (a11 a22 a33 a12 a13 a23 : sx)
with vx : Type :=
| VVar (u : V3) (p : nat)     (* a vector, its entries at env_p .. env_(p+2) *)
| VZero | VAdd (u w : vx) | VNeg (u : vx) | VScale (c : sx) (u : vx)
| VMv (a : mx) (u : vx) | VVee (a : mx)
with sx : Type :=
| SZ (z : Z)                  (* IZR z *)
| SV (i : nat)                (* the parameter env_i *)
| SDivC (a : sx) (d : positive)  (* a / IZR (Zpos d) *)
| SAdd (a b : sx) | SMul (a b : sx) | SNeg (a : sx) | SSub (a b : sx)
| STr (a : mx) | STrMul (a b : mx) | SPhi (a : mx) | SVdot (u w : vx)
| SEnt (k : nat) (a : mx) | SVEnt (k : nat) (u : vx).

Fixpoint mden (env : list R) (a : mx) : M3 :=
  match a with
  | MRot q _ => rot q
  | MI3 => I3
  | MZ3 => Z3
  | MAdd a b => madd (mden env a) (mden env b)
  | MSub a b => msub (mden env a) (mden env b)
  | MNeg a => mneg (mden env a)
  | MScale c a => mscale (sden env c) (mden env a)
  | MMul a b => mmul (mden env a) (mden env b)
  | MT a => mT (mden env a)
  | MSk a => sk (mden env a)
  | MSym a => sym (mden env a)
  | MHat u => hat (vden env u)
  | MOuter u w => outer (vden env u) (vden env w)
  | MSymm a11 a22 a33 a12 a13 a23 =>
      symm (sden env a11) (sden env a22) (sden env a33) (sden env a12) (sden env a13)
           (sden env a23)
  end
with vden (env : list R) (u : vx) : V3 :=
  match u with
  | VVar u _ => u
  | VZero => vzero
  | VAdd u w => vadd (vden env u) (vden env w)
  | VNeg u => vneg (vden env u)
  | VScale c u => vscale (sden env c) (vden env u)
  | VMv a u => mvmul (mden env a) (vden env u)
  | VVee a => vee (mden env a)
  end
with sden (env : list R) (r : sx) : R :=
  match r with
  | SZ z => IZR z
  | SV i => nth i env 0
  | SDivC a d => sden env a / IZR (Zpos d)
  | SAdd a b => sden env a + sden env b
  | SMul a b => sden env a * sden env b
  | SNeg a => - sden env a
  | SSub a b => sden env a - sden env b
  | STr a => tr (mden env a)
  | STrMul a b => tr (mmul (mden env a) (mden env b))
  | SPhi a => phi (mden env a)
  | SVdot u w => vdot (vden env u) (vden env w)
  | SEnt k a => ment k (mden env a)
  | SVEnt k u => vent k (vden env u)
  end.

(** What the reading takes for granted at its leaves: a rotation's [q] has its entries
    where the leaf says and a non-zero norm; a vector has its entries where it says. *)
Fixpoint mleaves (env : list R) (a : mx) : Prop :=
  match a with
  | MRot q p =>
      qw q = nth p env 0 /\ qx q = nth (S p) env 0 /\ qy q = nth (S (S p)) env 0 /\
      qz q = nth (S (S (S p))) env 0 /\ qn q <> 0
  | MI3 | MZ3 => True
  | MAdd a b | MSub a b | MMul a b => mleaves env a /\ mleaves env b
  | MNeg a | MT a | MSk a | MSym a => mleaves env a
  | MScale c a => sleaves env c /\ mleaves env a
  | MHat u => vleaves env u
  | MOuter u w => vleaves env u /\ vleaves env w
  | MSymm a11 a22 a33 a12 a13 a23 =>
      sleaves env a11 /\ sleaves env a22 /\ sleaves env a33 /\ sleaves env a12 /\
      sleaves env a13 /\ sleaves env a23
  end
with vleaves (env : list R) (u : vx) : Prop :=
  match u with
  | VVar u p => v1 u = nth p env 0 /\ v2 u = nth (S p) env 0 /\ v3 u = nth (S (S p)) env 0
  | VZero => True
  | VAdd u w => vleaves env u /\ vleaves env w
  | VNeg u => vleaves env u
  | VScale c u => sleaves env c /\ vleaves env u
  | VMv a u => mleaves env a /\ vleaves env u
  | VVee a => mleaves env a
  end
with sleaves (env : list R) (r : sx) : Prop :=
  match r with
  | SZ _ | SV _ => True
  | SDivC a _ | SNeg a => sleaves env a
  | SAdd a b | SMul a b | SSub a b => sleaves env a /\ sleaves env b
  | STr a | SPhi a | SEnt _ a => mleaves env a
  | STrMul a b => mleaves env a /\ mleaves env b
  | SVdot u w => vleaves env u /\ vleaves env w
  | SVEnt _ u => vleaves env u
  end.

Fixpoint evm (a : mx) : mv :=
  match a with
  | MRot _ p => mv_rot p
  | MI3 => mv_I3
  | MZ3 => mv_Z3
  | MAdd a b => mv_add (evm a) (evm b)
  | MSub a b => mv_sub (evm a) (evm b)
  | MNeg a => mv_neg (evm a)
  | MScale c a => mv_scale (evs c) (evm a)
  | MMul a b => mv_mul (evm a) (evm b)
  | MT a => mv_T (evm a)
  | MSk a => mv_sk (evm a)
  | MSym a => mv_sym (evm a)
  | MHat u => mv_hat (evv u)
  | MOuter u w => mv_outer (evv u) (evv w)
  | MSymm a11 a22 a33 a12 a13 a23 =>
      mv_symm (evs a11) (evs a22) (evs a33) (evs a12) (evs a13) (evs a23)
  end
with evv (u : vx) : vv :=
  match u with
  | VVar _ p => VV (sv_var p) (sv_var (S p)) (sv_var (S (S p)))
  | VZero => vv_zero
  | VAdd u w => vv_add (evv u) (evv w)
  | VNeg u => vv_neg (evv u)
  | VScale c u => vv_scale (evs c) (evv u)
  | VMv a u => vv_mv (evm a) (evv u)
  | VVee a => vv_vee (evm a)
  end
with evs (r : sx) : sv :=
  match r with
  | SZ z => sv_q (inject_Z z)
  | SV i => sv_var i
  | SDivC a d => sv_scq (1 # d) (evs a)
  | SAdd a b => sv_add (evs a) (evs b)
  | SMul a b => sv_mul (evs a) (evs b)
  | SNeg a => sv_neg (evs a)
  | SSub a b => sv_sub (evs a) (evs b)
  | STr a => sv_tr (evm a)
  | STrMul a b => sv_trmul (evm a) (evm b)
  | SPhi a => sv_phi (evm a)
  | SVdot u w => sv_vdot (evv u) (evv w)
  | SEnt k a => mv_ent k (evm a)
  | SVEnt k u => vv_ent k (evv u)
  end.

Scheme mx_ind2 := Induction for mx Sort Prop
  with vx_ind2 := Induction for vx Sort Prop
  with sx_ind2 := Induction for sx Sort Prop.
Combined Scheme ex_ind2 from mx_ind2, vx_ind2, sx_ind2.

Theorem ev_sound env :
  (forall a, mleaves env a -> mrel env (mden env a) (evm a)) /\
  (forall u, vleaves env u -> vrel env (vden env u) (evv u)) /\
  (forall r, sleaves env r -> srel env (sden env r) (evs r)).
Proof.
  apply ex_ind2; cbn [mleaves vleaves sleaves mden vden sden evm evv evs]; intros;
    repeat match goal with H : _ /\ _ |- _ => destruct H end.
  - apply mv_rot_ok; assumption.
  - apply mv_I3_ok.
  - apply mv_Z3_ok.
  - apply mv_add_ok; auto.
  - apply mv_sub_ok; auto.
  - apply mv_neg_ok; auto.
  - apply mv_scale_ok; auto.
  - apply mv_mul_ok; auto.
  - apply mv_T_ok; auto.
  - apply mv_sk_ok; auto.
  - apply mv_sym_ok; auto.
  - apply mv_hat_ok; auto.
  - apply mv_outer_ok; auto.
  - apply mv_symm_ok; auto.
  - unfold vrel. cbn [f1 f2 f3].
    repeat match goal with H : ?x = nth _ _ _ |- context [?x] => rewrite H; clear H end.
    split; [|split]; apply sv_var_ok.
  - apply vv_zero_ok.
  - apply vv_add_ok; auto.
  - apply vv_neg_ok; auto.
  - apply vv_scale_ok; auto.
  - apply vv_mv_ok; auto.
  - apply vv_vee_ok; auto.
  - apply sv_Z_ok.
  - apply sv_var_ok.
  - apply sv_divc_ok; auto.
  - apply sv_add_ok; auto.
  - apply sv_mul_ok; auto.
  - apply sv_neg_ok; auto.
  - apply sv_sub_ok; auto.
  - apply sv_tr_ok; auto.
  - apply sv_trmul_ok; auto.
  - apply sv_phi_ok; auto.
  - apply sv_vdot_ok; auto.
  - apply mv_ent_ok; auto.
  - apply vv_ent_ok; auto.
Qed.

(** *** Rotations meeting their transposes: [R^T R = R R^T = I] in products

    Before evaluation, every product is read as a chain of factors (transposes pushed to
    the factors), and adjacent factors [rot q^T rot q] or [rot q rot q^T] (the same
    parameters) are cancelled, as the prelude's [so3_norm] does by rewriting.  The value
    of a product of rotations then keeps the denominators of the rotations left in it:
    [(R_r^T R_l)^T (R_r^T R)] is evaluated as [R_l^T R]. *)

Definition fac := (mx * bool)%type.  (* a factor, transposed when [true] *)

Definition fmx (f : fac) : mx := if snd f then MT (fst f) else fst f.

Fixpoint build (l : list fac) : mx :=
  match l with
  | nil => MI3
  | [f] => fmx f
  | f :: l' => MMul (fmx f) (build l')
  end.

(** [f g = I]: the same rotation, once transposed. *)
Definition rot_inv (f g : fac) : bool :=
  match fst f, fst g with
  | MRot _ p, MRot _ p' => Nat.eqb p p' && negb (Bool.eqb (snd f) (snd g))
  | _, _ => false
  end.

Fixpoint cancel1 (l : list fac) : list fac :=
  match l with
  | f :: ((g :: l'') as l') => if rot_inv f g then l'' else f :: cancel1 l'
  | _ => l
  end.

Fixpoint cancel (fuel : nat) (l : list fac) : list fac :=
  match fuel with O => l | S k => cancel k (cancel1 l) end.

Fixpoint simp_m (a : mx) : mx :=
  match a with
  | MMul a b => let l := chain false a ++ chain false b in build (cancel (length l) l)
  | MT a => let l := chain true a in build (cancel (length l) l)
  | MRot q p => MRot q p
  | MI3 => MI3
  | MZ3 => MZ3
  | MAdd a b => MAdd (simp_m a) (simp_m b)
  | MSub a b => MSub (simp_m a) (simp_m b)
  | MNeg a => MNeg (simp_m a)
  | MScale c a => MScale (simp_s c) (simp_m a)
  | MSk a => MSk (simp_m a)
  | MSym a => MSym (simp_m a)
  | MHat u => MHat (simp_v u)
  | MOuter u w => MOuter (simp_v u) (simp_v w)
  | MSymm a11 a22 a33 a12 a13 a23 =>
      MSymm (simp_s a11) (simp_s a22) (simp_s a33) (simp_s a12) (simp_s a13) (simp_s a23)
  end
with chain (t : bool) (a : mx) : list fac :=
  match a with
  | MMul a b => if t then chain true b ++ chain true a else chain false a ++ chain false b
  | MT a => chain (negb t) a
  | MRot q p => [(MRot q p, t)]
  | MI3 => [(MI3, t)]
  | MZ3 => [(MZ3, t)]
  | MAdd a b => [(MAdd (simp_m a) (simp_m b), t)]
  | MSub a b => [(MSub (simp_m a) (simp_m b), t)]
  | MNeg a => [(MNeg (simp_m a), t)]
  | MScale c a => [(MScale (simp_s c) (simp_m a), t)]
  | MSk a => [(MSk (simp_m a), t)]
  | MSym a => [(MSym (simp_m a), t)]
  | MHat u => [(MHat (simp_v u), t)]
  | MOuter u w => [(MOuter (simp_v u) (simp_v w), t)]
  | MSymm a11 a22 a33 a12 a13 a23 =>
      [(MSymm (simp_s a11) (simp_s a22) (simp_s a33) (simp_s a12) (simp_s a13)
              (simp_s a23), t)]
  end
with simp_v (u : vx) : vx :=
  match u with
  | VVar u p => VVar u p
  | VZero => VZero
  | VAdd u w => VAdd (simp_v u) (simp_v w)
  | VNeg u => VNeg (simp_v u)
  | VScale c u => VScale (simp_s c) (simp_v u)
  | VMv a u => VMv (simp_m a) (simp_v u)
  | VVee a => VVee (simp_m a)
  end
with simp_s (r : sx) : sx :=
  match r with
  | SZ z => SZ z
  | SV i => SV i
  | SDivC a d => SDivC (simp_s a) d
  | SAdd a b => SAdd (simp_s a) (simp_s b)
  | SMul a b => SMul (simp_s a) (simp_s b)
  | SNeg a => SNeg (simp_s a)
  | SSub a b => SSub (simp_s a) (simp_s b)
  | STr a => STr (simp_m a)
  | STrMul a b => STrMul (simp_m a) (simp_m b)
  | SPhi a => SPhi (simp_m a)
  | SVdot u w => SVdot (simp_v u) (simp_v w)
  | SEnt k a => SEnt k (simp_m a)
  | SVEnt k u => SVEnt k (simp_v u)
  end.

Definition fden env (f : fac) : M3 := if snd f then mT (mden env (fst f)) else mden env (fst f).

Fixpoint cden env (l : list fac) : M3 :=
  match l with nil => I3 | f :: l' => mmul (fden env f) (cden env l') end.

Definition fleaves env (l : list fac) : Prop := Forall (fun f => mleaves env (fst f)) l.

Lemma cden_app env l1 l2 : cden env (l1 ++ l2) = mmul (cden env l1) (cden env l2).
Proof.
  induction l1 as [|f l1 IH]; simpl; [symmetry; apply mmul_I3_l|].
  rewrite IH, mmul_assoc. reflexivity.
Qed.

Lemma build_ok env l :
  fleaves env l -> mleaves env (build l) /\ mden env (build l) = cden env l.
Proof.
  induction l as [|f l IH]; intros H; [split; [exact I | reflexivity]|].
  inversion H as [|? ? Hf Hl]; subst.
  assert (Hfm : mleaves env (fmx f) /\ mden env (fmx f) = fden env f)
    by (unfold fmx, fden; destruct (snd f); split; auto).
  destruct l as [|g l].
  - cbn [build cden]. destruct Hfm as [Hfm Efm]. split; [exact Hfm|].
    rewrite Efm, mmul_I3_r. reflexivity.
  - destruct (IH Hl) as [IH1 IH2]. destruct Hfm as [Hfm Efm].
    change (build (f :: g :: l)) with (MMul (fmx f) (build (g :: l))).
    split; [split; assumption|]. cbn [mden]. rewrite IH2, Efm. reflexivity.
Qed.

Lemma rot_same q q' p env :
  qw q = nth p env 0 /\ qx q = nth (S p) env 0 /\ qy q = nth (S (S p)) env 0 /\
  qz q = nth (S (S (S p))) env 0 /\ qn q <> 0 ->
  qw q' = nth p env 0 /\ qx q' = nth (S p) env 0 /\ qy q' = nth (S (S p)) env 0 /\
  qz q' = nth (S (S (S p))) env 0 /\ qn q' <> 0 -> rot q = rot q'.
Proof.
  destruct q, q'. simpl. intros (->&->&->&->&_) (->&->&->&->&_). reflexivity.
Qed.

Lemma cancel1_ok env l :
  fleaves env l -> fleaves env (cancel1 l) /\ cden env (cancel1 l) = cden env l.
Proof.
  induction l as [|f l IH]; intros H; [split; [exact H | reflexivity]|].
  inversion H as [|? ? Hf Hl]; subst.
  destruct l as [|g l]; [split; [exact H | reflexivity]|].
  change (cancel1 (f :: g :: l))
    with (if rot_inv f g then l else f :: cancel1 (g :: l)).
  destruct (rot_inv f g) eqn:E.
  - inversion Hl as [|? ? Hg Hl']; subst. split; [exact Hl'|].
    destruct f as [[] tf]; try discriminate. destruct g as [[] tg]; try discriminate.
    unfold rot_inv in E. cbn [fst snd] in *. apply andb_true_iff in E as [Ep Et].
    apply Nat.eqb_eq in Ep. subst.
    cbn [cden]. unfold fden. cbn [fst snd mden].
    rewrite (rot_same q0 q p0 env Hg Hf). destruct Hf as (_&_&_&_&Hn).
    rewrite <- mmul_assoc.
    destruct tf, tg; try discriminate; cbn [fst snd].
    + rewrite (rot_orthogonal q Hn), mmul_I3_l. reflexivity.
    + rewrite (rot_orthogonal_r q Hn), mmul_I3_l. reflexivity.
  - destruct (IH Hl) as [IH1 IH2]. split; [constructor; assumption|].
    cbn [cden]. rewrite IH2. reflexivity.
Qed.

Lemma cancel_ok env n l :
  fleaves env l -> fleaves env (cancel n l) /\ cden env (cancel n l) = cden env l.
Proof.
  revert l. induction n as [|n IH]; intros l H; [split; [exact H | reflexivity]|].
  cbn [cancel]. destruct (cancel1_ok env l H) as [H1 E1].
  destruct (IH _ H1) as [H2 E2]. split; [exact H2|]. rewrite E2, E1. reflexivity.
Qed.

Lemma bc_ok env l :
  fleaves env l -> mleaves env (build (cancel (length l) l)) /\
                   mden env (build (cancel (length l) l)) = cden env l.
Proof.
  intros H. destruct (cancel_ok env (length l) l H) as [H1 E1].
  destruct (build_ok env _ H1) as [H2 E2]. split; [exact H2|]. rewrite E2, E1. reflexivity.
Qed.

Definition chain_ok env a : Prop :=
  forall t, fleaves env (chain t a) /\
            cden env (chain t a) = if t then mT (mden env a) else mden env a.

Definition simp_ok env a : Prop :=
  mleaves env (simp_m a) /\ mden env (simp_m a) = mden env a.

Lemma chain_one env (x y : mx) t :
  mleaves env x -> mden env x = mden env y ->
  fleaves env [(x, t)] /\ cden env [(x, t)] = if t then mT (mden env y) else mden env y.
Proof.
  intros Hx E. split; [repeat constructor; exact Hx|].
  cbn [cden]. rewrite mmul_I3_r. unfold fden. cbn [fst snd]. rewrite E. reflexivity.
Qed.

Lemma mmul_case env a b :
  chain_ok env a -> chain_ok env b -> simp_ok env (MMul a b) /\ chain_ok env (MMul a b).
Proof.
  intros Ha Hb. destruct (Ha false) as [Ha1 Ea1], (Hb false) as [Hb1 Eb1].
  split.
  - unfold simp_ok. cbn [simp_m].
    assert (H : fleaves env (chain false a ++ chain false b))
      by (apply Forall_app; split; assumption).
    destruct (bc_ok env _ H) as [H1 E1]. split; [exact H1|].
    rewrite E1, cden_app, Ea1, Eb1. reflexivity.
  - intros [|].
    + destruct (Ha true) as [Ha2 Ea2], (Hb true) as [Hb2 Eb2]. cbn [chain].
      split; [apply Forall_app; split; assumption|].
      rewrite cden_app, Ea2, Eb2. cbn [mden]. symmetry. apply mT_mmul.
    + cbn [chain]. split; [apply Forall_app; split; assumption|].
      rewrite cden_app, Ea1, Eb1. reflexivity.
Qed.

Lemma mt_case env a : chain_ok env a -> simp_ok env (MT a) /\ chain_ok env (MT a).
Proof.
  intros Ha. split.
  - destruct (Ha true) as [H1 E1]. unfold simp_ok. cbn [simp_m].
    destruct (bc_ok env _ H1) as [H2 E2]. split; [exact H2|]. rewrite E2, E1. reflexivity.
  - intros [|]; cbn [chain negb mden].
    + destruct (Ha false) as [H1 E1]. split; [exact H1|]. rewrite E1, mT_mT. reflexivity.
    + exact (Ha true).
Qed.

Local Ltac simp_leaves :=
  repeat match goal with
  | |- _ /\ _ => split
  | |- True => exact I
  | |- _ => assumption
  end.

Local Ltac simp_eq :=
  repeat match goal with
  | H : mden _ _ = _ |- _ => rewrite H; clear H
  | H : vden _ _ = _ |- _ => rewrite H; clear H
  | H : sden _ _ = _ |- _ => rewrite H; clear H
  end; reflexivity.

Lemma simp_sound env :
  (forall a, mleaves env a -> simp_ok env a /\ chain_ok env a) /\
  (forall u, vleaves env u -> vleaves env (simp_v u) /\ vden env (simp_v u) = vden env u) /\
  (forall r, sleaves env r -> sleaves env (simp_s r) /\ sden env (simp_s r) = sden env r).
Proof.
  apply ex_ind2; intros; cbn [mleaves vleaves sleaves] in *;
    repeat match goal with
    | H : _ /\ _ |- _ => destruct H
    | H : ?P -> _, H' : ?P |- _ => specialize (H H')
    | H : simp_ok _ _ |- _ => unfold simp_ok in H
    end;
      lazymatch goal with
        | |- simp_ok _ (MMul _ _) /\ _ => apply mmul_case; assumption
        | |- simp_ok _ (MT _) /\ _ => apply mt_case; assumption
        | |- simp_ok ?env ?y /\ _ =>
            assert (S : simp_ok env y)
              by (unfold simp_ok; cbn [simp_m mleaves mden]; split; [simp_leaves | simp_eq]);
            split; [exact S | intros t; destruct S as [S1 S2]; unfold simp_ok in S1, S2;
                                cbn [chain]; cbn [simp_m] in S1, S2;
                                exact (chain_one env _ y t S1 S2)]
        | |- _ => cbn [simp_v simp_s vleaves sleaves mleaves vden sden mden];
                  split; [simp_leaves | simp_eq]
        end.
Qed.

(** [d]: the denominator the exporter expects (powers of norms); the check lifts the
    computed value and the target to the larger of the two. *)
Definition link_check (qs : list nat) (r : sx) (d : list nat) (target : poly) : bool :=
  let (n, e) := evs (simp_s r) in
  let m := emax e d in
  exps_ok_from qs 0 m && poly_zero (lift n (ediff e m) ++ pneg (lift target (ediff d m))).

(** The link of a unit: its slack [s] is the expression [r], whose value times a positive
    product of norms is the target polynomial times a non-negative one. *)
Theorem link_ok env qs r (s : R) d target :
  Forall (fun p => qnR env p <> 0) qs -> sleaves env r -> s = sden env r ->
  link_check qs r d target = true ->
  exists D F, 0 < D /\ 0 <= F /\ s * D = F * peval env target.
Proof.
  intros Hq Hl Hs H. unfold link_check in H.
  destruct (proj2 (proj2 (simp_sound env)) r Hl) as [Hl' Es]. rewrite <- Es in Hs.
  pose proof (proj2 (proj2 (ev_sound env)) _ Hl') as Hev. unfold srel in Hev.
  destruct (evs (simp_s r)) as [n e]. cbn [fst snd] in Hev.
  apply andb_true_iff in H as [He Hz].
  exists (denp env 0 (emax e d)), (denp env 0 (ediff d (emax e d))).
  split; [exact (denp_pos env qs 0 _ Hq He)|]. split; [apply denp_nonneg|].
  subst s. rewrite <- (eadd_ediff_l e d), denp_eadd, <- Rmult_assoc, Hev.
  rewrite (eadd_ediff_l e d).
  apply (poly_zero_sound env) in Hz. rewrite peval_app in Hz. unfold pneg in Hz.
  rewrite peval_scale, !peval_lift in Hz.
  assert (E : Q2R (-1) = -1) by (unfold Q2R; simpl; lra). rewrite E in Hz. lra.
Qed.

(** Reading a statement into [sx] ([l]: the parameters, as [env] lists them). *)
Ltac sos_index x l :=
  lazymatch l with
  | x :: _ => constr:(O)
  | _ :: ?l' => let n := sos_index x l' in constr:(S n)
  end.

Ltac sos_reify_m l t :=
  lazymatch t with
  | rot ?q => let p := sos_index (qw q) l in constr:(MRot q p)
  | I3 => constr:(MI3)
  | Z3 => constr:(MZ3)
  | madd ?a ?b => let ra := sos_reify_m l a in let rb := sos_reify_m l b in constr:(MAdd ra rb)
  | msub ?a ?b => let ra := sos_reify_m l a in let rb := sos_reify_m l b in constr:(MSub ra rb)
  | mneg ?a => let ra := sos_reify_m l a in constr:(MNeg ra)
  | mscale ?c ?a => let rc := sos_reify l c in let ra := sos_reify_m l a in constr:(MScale rc ra)
  | mmul ?a ?b => let ra := sos_reify_m l a in let rb := sos_reify_m l b in constr:(MMul ra rb)
  | mT ?a => let ra := sos_reify_m l a in constr:(MT ra)
  | sk ?a => let ra := sos_reify_m l a in constr:(MSk ra)
  | sym ?a => let ra := sos_reify_m l a in constr:(MSym ra)
  | hat ?u => let ru := sos_reify_v l u in constr:(MHat ru)
  | outer ?u ?w => let ru := sos_reify_v l u in let rw := sos_reify_v l w in constr:(MOuter ru rw)
  | symm ?a11 ?a22 ?a33 ?a12 ?a13 ?a23 =>
      let r11 := sos_reify l a11 in let r22 := sos_reify l a22 in
      let r33 := sos_reify l a33 in let r12 := sos_reify l a12 in
      let r13 := sos_reify l a13 in let r23 := sos_reify l a23 in
      constr:(MSymm r11 r22 r33 r12 r13 r23)
  end
with sos_reify_v l t :=
  lazymatch t with
  | vzero => constr:(VZero)
  | vadd ?u ?w => let ru := sos_reify_v l u in let rw := sos_reify_v l w in constr:(VAdd ru rw)
  | vneg ?u => let ru := sos_reify_v l u in constr:(VNeg ru)
  | vscale ?c ?u => let rc := sos_reify l c in let ru := sos_reify_v l u in constr:(VScale rc ru)
  | mvmul ?a ?u => let ra := sos_reify_m l a in let ru := sos_reify_v l u in constr:(VMv ra ru)
  | vee ?a => let ra := sos_reify_m l a in constr:(VVee ra)
  | ?u => let p := sos_index (v1 u) l in constr:(VVar u p)
  end
with sos_reify l t :=
  lazymatch t with
  | ?a + ?b => let ra := sos_reify l a in let rb := sos_reify l b in constr:(SAdd ra rb)
  | ?a * ?b => let ra := sos_reify l a in let rb := sos_reify l b in constr:(SMul ra rb)
  | ?a - ?b => let ra := sos_reify l a in let rb := sos_reify l b in constr:(SSub ra rb)
  | - ?a => let ra := sos_reify l a in constr:(SNeg ra)
  | ?a / IZR (Zpos ?d) => let ra := sos_reify l a in constr:(SDivC ra d)
  | IZR ?z => constr:(SZ z)
  | tr (mmul ?a ?b) =>
      let ra := sos_reify_m l a in let rb := sos_reify_m l b in constr:(STrMul ra rb)
  | tr ?a => let ra := sos_reify_m l a in constr:(STr ra)
  | phi ?a => let ra := sos_reify_m l a in constr:(SPhi ra)
  | vdot ?u ?w => let ru := sos_reify_v l u in let rw := sos_reify_v l w in constr:(SVdot ru rw)
  | m11 ?a => let ra := sos_reify_m l a in constr:(SEnt 0 ra)
  | m12 ?a => let ra := sos_reify_m l a in constr:(SEnt 1 ra)
  | m13 ?a => let ra := sos_reify_m l a in constr:(SEnt 2 ra)
  | m21 ?a => let ra := sos_reify_m l a in constr:(SEnt 3 ra)
  | m22 ?a => let ra := sos_reify_m l a in constr:(SEnt 4 ra)
  | m23 ?a => let ra := sos_reify_m l a in constr:(SEnt 5 ra)
  | m31 ?a => let ra := sos_reify_m l a in constr:(SEnt 6 ra)
  | m32 ?a => let ra := sos_reify_m l a in constr:(SEnt 7 ra)
  | m33 ?a => let ra := sos_reify_m l a in constr:(SEnt 8 ra)
  | ?x => let i := sos_index x l in constr:(SV i)
  end.

(** The leaves' conditions: equalities of a leaf's entries with the parameters (by
    conversion) and the rotations' non-zero norms (the unit's hypotheses). *)
Ltac sos_leaves :=
  cbn [sleaves mleaves vleaves];
  repeat match goal with
  | |- _ /\ _ => split
  | |- True => exact I
  | |- _ = _ => reflexivity
  | |- qn _ <> 0 => assumption
  end.

(** Proves [exists D F, 0 < D /\ 0 <= F /\ s * D = F * peval env target] by [link_ok]:
    [params] is the list [env] stands for, [qs] the positions of the quaternions, [Hq]
    their norms' non-vanishing, [fe] the factors divided out of the target.  The check
    [link_check] is evaluated once, by the kernel at [Qed] ([vm_cast_no_check]); [vm_compute]
    here would evaluate it a second time, in the tactic. *)
Ltac sos_link params qs Hq fe :=
  lazymatch goal with
  | |- exists D F, 0 < D /\ 0 <= F /\ ?s * D = F * peval ?env ?t =>
      let r := sos_reify params s in
      apply (link_ok env qs r s fe t Hq);
        [sos_leaves | reflexivity | vm_cast_no_check (eq_refl true)]
  end.

(** ** Multipliers' entries by computation *)

Fixpoint eqb_list (a b : list nat) : bool :=
  match a, b with
  | nil, nil => true
  | x :: a', y :: b' => Nat.eqb x y && eqb_list a' b'
  | _, _ => false
  end.

Lemma eqb_list_eq a b : eqb_list a b = true -> a = b.
Proof.
  revert b. induction a as [|x a IH]; intros [|y b]; simpl; try discriminate; auto.
  intros H. apply andb_true_iff in H as [H1 H2]. apply Nat.eqb_eq in H1.
  rewrite H1, (IH b H2). reflexivity.
Qed.

(** [v] is [h] over [den d] exactly: [v]'s denominator divides [den d]. *)
Definition entry_check (v : sv) (d : list nat) (h : poly) : bool :=
  eqb_list (emax (snd v) d) d && poly_zero (lift (fst v) (ediff (snd v) d) ++ pneg h).

Lemma entry_ok env x v d h :
  srel env x v -> entry_check v d h = true -> peval env h = x * denp env 0 d.
Proof.
  unfold srel, entry_check. destruct v as [n e]. cbn [fst snd]. intros Hev H.
  apply andb_true_iff in H as [Hd Hz]. apply eqb_list_eq in Hd.
  rewrite <- Hd at 1. rewrite <- (eadd_ediff_l e d), denp_eadd, <- Rmult_assoc, Hev.
  rewrite Hd.
  apply (poly_zero_sound env) in Hz. rewrite peval_app in Hz. unfold pneg in Hz.
  rewrite peval_scale, peval_lift in Hz.
  assert (E : Q2R (-1) = -1) by (unfold Q2R; simpl; lra). rewrite E in Hz. lra.
Qed.

(** A 3 x 3 multiplier that is [c * D] times a matrix with a non-negative quadratic form,
    entry by entry. *)
Lemma mult_psd_9 env (h11 h12 h13 h21 h22 h23 h31 h32 h33 : poly) (M : M3) (c D : R) :
  0 <= c -> 0 <= D -> (forall v, 0 <= qform M v) ->
  peval env h11 = c * m11 M * D -> peval env h12 = c * m12 M * D ->
  peval env h13 = c * m13 M * D -> peval env h21 = c * m21 M * D ->
  peval env h22 = c * m22 M * D -> peval env h23 = c * m23 M * D ->
  peval env h31 = c * m31 M * D -> peval env h32 = c * m32 M * D ->
  peval env h33 = c * m33 M * D ->
  mult_psd env [[h11; h12; h13]; [h21; h22; h23]; [h31; h32; h33]].
Proof.
  intros Hc HD HM E11 E12 E13 E21 E22 E23 E31 E32 E33 [|a [|b [|d [|e xs]]]];
    simpl; try discriminate. intros _.
  unfold qfR, evalM. cbn [map dotR].
  rewrite E11, E12, E13, E21, E22, E23, E31, E32, E33.
  specialize (HM (mkV a b d)). unfold qform, vdot, mvmul in HM. simpl in HM.
  replace (a * (c * m11 M * D * a + (c * m12 M * D * b + (c * m13 M * D * d + 0))) +
           (b * (c * m21 M * D * a + (c * m22 M * D * b + (c * m23 M * D * d + 0))) +
            (d * (c * m31 M * D * a + (c * m32 M * D * b + (c * m33 M * D * d + 0))) + 0)))
    with (c * D * (a * (m11 M * a + m12 M * b + m13 M * d) +
                   b * (m21 M * a + m22 M * b + m23 M * d) +
                   d * (m31 M * a + m32 M * b + m33 M * d))) by ring.
  apply Rmult_le_pos; [apply Rmult_le_pos|]; assumption.
Qed.

(** The entries of a 3 x 3 multiplier [c * D * M] by computation: [c] and [M] read as
    expressions ([rc], [rM]), evaluated once, each entry compared with [H]'s. *)
Definition psd9_check (rc : sx) (rM : mx) (d : list nat)
    (h11 h12 h13 h21 h22 h23 h31 h32 h33 : poly) : bool :=
  let c := evs (simp_s rc) in
  let m := evm (simp_m rM) in
  entry_check (sv_mul c (e11 m)) d h11 && entry_check (sv_mul c (e12 m)) d h12 &&
  entry_check (sv_mul c (e13 m)) d h13 && entry_check (sv_mul c (e21 m)) d h21 &&
  entry_check (sv_mul c (e22 m)) d h22 && entry_check (sv_mul c (e23 m)) d h23 &&
  entry_check (sv_mul c (e31 m)) d h31 && entry_check (sv_mul c (e32 m)) d h32 &&
  entry_check (sv_mul c (e33 m)) d h33.

Theorem mult_psd_9r env rc rM d (h11 h12 h13 h21 h22 h23 h31 h32 h33 : poly) :
  sleaves env rc -> mleaves env rM -> 0 <= sden env rc ->
  (forall v, 0 <= qform (mden env rM) v) ->
  psd9_check rc rM d h11 h12 h13 h21 h22 h23 h31 h32 h33 = true ->
  mult_psd env [[h11; h12; h13]; [h21; h22; h23]; [h31; h32; h33]].
Proof.
  intros Hc HM Hc0 HMq Hk.
  destruct (proj2 (proj2 (simp_sound env)) rc Hc) as [Hc' Ec].
  destruct (proj1 (simp_sound env) rM HM) as [[HM' EM] _].
  pose proof (proj2 (proj2 (ev_sound env)) _ Hc') as Vc. rewrite Ec in Vc.
  pose proof (proj1 (ev_sound env) _ HM') as VM. rewrite EM in VM.
  unfold psd9_check in Hk. cbv zeta in Hk. do 8 (apply andb_true_iff in Hk as [Hk ?]).
  destruct VM as (V11&V12&V13&V21&V22&V23&V31&V32&V33).
  apply (mult_psd_9 env _ _ _ _ _ _ _ _ _ (mden env rM) (sden env rc) (denp env 0 d) Hc0
           (denp_nonneg env 0 d) HMq);
    (eapply entry_ok; [apply sv_mul_ok; eassumption | eassumption]).
Qed.

(** Proves [mult_psd env H] for [H = c * D * M] entry by entry, [D] the product of norms
    [d], by [mult_psd_9r] (its check evaluated once, by the kernel at [Qed], as in
    [sos_link]); leaves [0 <= c] and [forall v, 0 <= qform M v] (up to reading). *)
Ltac sos_psd9 params c M d :=
  lazymatch goal with
  | |- mult_psd ?env _ =>
      let rc := sos_reify params c in
      let rM := sos_reify_m params M in
      refine (mult_psd_9r env rc rM d _ _ _ _ _ _ _ _ _ _ _ _ _ _);
        [sos_leaves | sos_leaves | | | vm_cast_no_check (eq_refl true)]
  end.

(** ** Equalities by computation

    [x = y] when both values, lifted to a common product of norms (non-zero: the
    quaternions [qs]), have the same numerator.  For matrices and vectors, entry by
    entry.  This proves the derivations' algebraic steps that are identities in the
    parameters (paper, Lemma 1 and Theorem 1 proofs), with [rot q^T rot q] cancelled as
    in [so3_norm]. *)
Definition sv_eqb (qs : list nat) (a b : sv) : bool :=
  let m := emax (snd a) (snd b) in
  exps_ok_from qs 0 m &&
  poly_zero (lift (fst a) (ediff (snd a) m) ++ pneg (lift (fst b) (ediff (snd b) m))).

Lemma sv_eqb_ok env qs x y a b :
  Forall (fun p => qnR env p <> 0) qs -> srel env x a -> srel env y b ->
  sv_eqb qs a b = true -> x = y.
Proof.
  unfold sv_eqb, srel. destruct a as [na ea], b as [nb eb]. cbn [fst snd].
  intros Hq Ha Hb H. apply andb_true_iff in H as [He Hz].
  pose proof (denp_pos env qs 0 _ Hq He) as Hp.
  apply (poly_zero_sound env) in Hz. rewrite peval_app in Hz. unfold pneg in Hz.
  rewrite peval_scale, !peval_lift in Hz.
  assert (E : Q2R (-1) = -1) by (unfold Q2R; simpl; lra). rewrite E in Hz.
  assert (E1 : denp env 0 (emax ea eb) = denp env 0 ea * denp env 0 (ediff ea (emax ea eb)))
    by (rewrite <- denp_eadd, eadd_ediff_l; reflexivity).
  assert (E2 : denp env 0 (emax ea eb) = denp env 0 eb * denp env 0 (ediff eb (emax ea eb)))
    by (rewrite <- denp_eadd, (emax_comm ea eb), eadd_ediff_l; reflexivity).
  apply (Rmult_eq_reg_r (denp env 0 (emax ea eb))); [|lra].
  rewrite E1 at 1. rewrite E2. rewrite <- !Rmult_assoc, Ha, Hb. lra.
Qed.

Definition eqs_check (qs : list nat) (r1 r2 : sx) : bool :=
  sv_eqb qs (evs (simp_s r1)) (evs (simp_s r2)).

Definition eqm_check (qs : list nat) (a1 a2 : mx) : bool :=
  let a := evm (simp_m a1) in
  let b := evm (simp_m a2) in
  sv_eqb qs (e11 a) (e11 b) && sv_eqb qs (e12 a) (e12 b) && sv_eqb qs (e13 a) (e13 b) &&
  sv_eqb qs (e21 a) (e21 b) && sv_eqb qs (e22 a) (e22 b) && sv_eqb qs (e23 a) (e23 b) &&
  sv_eqb qs (e31 a) (e31 b) && sv_eqb qs (e32 a) (e32 b) && sv_eqb qs (e33 a) (e33 b).

Definition eqv_check (qs : list nat) (u1 u2 : vx) : bool :=
  let a := evv (simp_v u1) in
  let b := evv (simp_v u2) in
  sv_eqb qs (f1 a) (f1 b) && sv_eqb qs (f2 a) (f2 b) && sv_eqb qs (f3 a) (f3 b).

Theorem eq_by_eval env qs r1 r2 (x y : R) :
  Forall (fun p => qnR env p <> 0) qs -> sleaves env r1 -> sleaves env r2 ->
  x = sden env r1 -> y = sden env r2 -> eqs_check qs r1 r2 = true -> x = y.
Proof.
  intros Hq H1 H2 -> -> H.
  destruct (proj2 (proj2 (simp_sound env)) r1 H1) as [H1' E1].
  destruct (proj2 (proj2 (simp_sound env)) r2 H2) as [H2' E2].
  rewrite <- E1, <- E2.
  exact (sv_eqb_ok env qs _ _ _ _ Hq (proj2 (proj2 (ev_sound env)) _ H1')
           (proj2 (proj2 (ev_sound env)) _ H2') H).
Qed.

Theorem eqm_by_eval env qs a1 a2 (A B : M3) :
  Forall (fun p => qnR env p <> 0) qs -> mleaves env a1 -> mleaves env a2 ->
  A = mden env a1 -> B = mden env a2 -> eqm_check qs a1 a2 = true -> A = B.
Proof.
  intros Hq H1 H2 -> -> H.
  destruct (proj1 (simp_sound env) a1 H1) as [[H1' E1] _].
  destruct (proj1 (simp_sound env) a2 H2) as [[H2' E2] _].
  rewrite <- E1, <- E2.
  pose proof (proj1 (ev_sound env) _ H1') as V1. pose proof (proj1 (ev_sound env) _ H2') as V2.
  unfold eqm_check in H. cbv zeta in H. do 8 (apply andb_true_iff in H as [H ?]).
  unfold mrel in V1, V2.
  destruct V1 as (A11&A12&A13&A21&A22&A23&A31&A32&A33).
  destruct V2 as (B11&B12&B13&B21&B22&B23&B31&B32&B33).
  apply m3_ext; eapply sv_eqb_ok; eassumption.
Qed.

Theorem eqv_by_eval env qs u1 u2 (u w : V3) :
  Forall (fun p => qnR env p <> 0) qs -> vleaves env u1 -> vleaves env u2 ->
  u = vden env u1 -> w = vden env u2 -> eqv_check qs u1 u2 = true -> u = w.
Proof.
  intros Hq H1 H2 -> -> H.
  destruct (proj1 (proj2 (simp_sound env)) u1 H1) as [H1' E1].
  destruct (proj1 (proj2 (simp_sound env)) u2 H2) as [H2' E2].
  rewrite <- E1, <- E2.
  pose proof (proj1 (proj2 (ev_sound env)) _ H1') as V1.
  pose proof (proj1 (proj2 (ev_sound env)) _ H2') as V2.
  unfold eqv_check in H. cbv zeta in H. do 2 (apply andb_true_iff in H as [H ?]).
  unfold vrel in V1, V2.
  destruct V1 as (A1&A2&A3). destruct V2 as (B1&B2&B3).
  apply v3_ext; eapply sv_eqb_ok; eassumption.
Qed.

(** The norms' non-vanishing at the positions [qs], from the unit's hypotheses. *)
Ltac sos_qs :=
  repeat match goal with
  | |- Forall _ nil => apply Forall_nil
  | |- Forall _ (_ :: _) => apply Forall_cons
  | |- qnR _ _ <> 0 => assumption
  end.

(** Proves [lhs = rhs] (scalars, matrices or vectors) by computation: [params] is the
    list [env] stands for, [qs] the positions of the quaternions in it.  The check is
    evaluated once, by the kernel at [Qed]. *)
Ltac sos_eq params qs :=
  lazymatch goal with
  | |- @eq M3 ?a ?b =>
      let ra := sos_reify_m params a in let rb := sos_reify_m params b in
      refine (eqm_by_eval params qs ra rb a b _ _ _ eq_refl eq_refl _);
        [sos_qs | sos_leaves | sos_leaves | vm_cast_no_check (eq_refl true)]
  | |- @eq V3 ?a ?b =>
      let ra := sos_reify_v params a in let rb := sos_reify_v params b in
      refine (eqv_by_eval params qs ra rb a b _ _ _ eq_refl eq_refl _);
        [sos_qs | sos_leaves | sos_leaves | vm_cast_no_check (eq_refl true)]
  | |- @eq R ?a ?b =>
      let ra := sos_reify params a in let rb := sos_reify params b in
      refine (eq_by_eval params qs ra rb a b _ _ _ eq_refl eq_refl _);
        [sos_qs | sos_leaves | sos_leaves | vm_cast_no_check (eq_refl true)]
  end.
