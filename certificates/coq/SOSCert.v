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

(** ** The link by computation: scalar expressions over the parameters

    After the prelude's definitions are unfolded, a statement about rotations, vectors and
    scalars is a real expression built from [+], [*], [-], integer constants, the
    parameters (the entries of [env]), [/ IZR z] and [/ qn q].  [sx] is that language;
    [ev] computes its value as a polynomial over one denominator, a product of powers
    of quaternion norms ([den]); [ev_sound] proves that value right once, so a unit's
    link needs no [field] on large polynomials: the tactic [sos_reify] reads the
    unfolded statement into [sx] and [vm_compute] compares the polynomials. *)

Inductive sx : Type :=
| SZ (z : Z)            (* IZR z *)
| SV (i : nat)          (* the parameter env_i *)
| SInvC (d : positive)  (* / IZR (Zpos d) *)
| SInvQ (p : nat)       (* / |q|^2 for the quaternion at env_p .. env_(p+3) *)
| SAdd (a b : sx) | SMul (a b : sx) | SNeg (a : sx).

Definition qnR (env : list R) (p : nat) : R :=
  nth p env 0 * nth p env 0 + nth (S p) env 0 * nth (S p) env 0 +
  nth (S (S p)) env 0 * nth (S (S p)) env 0 +
  nth (S (S (S p))) env 0 * nth (S (S (S p))) env 0.

Fixpoint sden (env : list R) (r : sx) : R :=
  match r with
  | SZ z => IZR z
  | SV i => nth i env 0
  | SInvC d => / IZR (Zpos d)
  | SInvQ p => / qnR env p
  | SAdd a b => sden env a + sden env b
  | SMul a b => sden env a * sden env b
  | SNeg a => - sden env a
  end.

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

Fixpoint ev (r : sx) : poly * list nat :=
  match r with
  | SZ z => ([(nil, inject_Z z)], nil)
  | SV i => ([(mono_at i 1, 1%Q)], nil)
  | SInvC d => ([(nil, (1 # d)%Q)], nil)
  | SInvQ p => (pone, mono_at p 1)
  | SAdd a b =>
      let (na, ea) := ev a in let (nb, eb) := ev b in
      let e := emax ea eb in
      (normal (pmul na (liftP 0 (ediff ea e)) ++ pmul nb (liftP 0 (ediff eb e))), e)
  | SMul a b =>
      let (na, ea) := ev a in let (nb, eb) := ev b in (normal (pmul na nb), eadd ea eb)
  | SNeg a => let (na, ea) := ev a in (pneg na, ea)
  end.

Fixpoint sx_valid (qs : list nat) (r : sx) : bool :=
  match r with
  | SInvQ p => existsb (Nat.eqb p) qs
  | SAdd a b | SMul a b => sx_valid qs a && sx_valid qs b
  | SNeg a => sx_valid qs a
  | _ => true
  end.

Lemma denp_at_from env c p k : denp env c (mono_at p k) = qnR env (c + p) ^ k.
Proof.
  revert c. induction p as [|p IH]; intros c; simpl.
  - rewrite Nat.add_0_r. ring.
  - rewrite IH, Nat.add_succ_r. simpl. ring.
Qed.

Lemma denp_at env p k : denp env 0 (mono_at p k) = qnR env p ^ k.
Proof. apply denp_at_from. Qed.

Lemma ev_sound env qs r :
  Forall (fun p => qnR env p <> 0) qs -> sx_valid qs r = true ->
  sden env r * denp env 0 (snd (ev r)) = peval env (fst (ev r)).
Proof.
  intros Hq. induction r as [z|i|d|p|a IHa b IHb|a IHa b IHb|a IHa]; simpl; intros Hv.
  - unfold Q2R. simpl. field.
  - rewrite meval_at. unfold Q2R. simpl. field.
  - unfold Q2R. simpl. field. apply not_0_IZR. discriminate.
  - apply existsb_exists in Hv as [p' [Hin Hp]]. apply Nat.eqb_eq in Hp. subst p'.
    rewrite Forall_forall in Hq. pose proof (Hq p Hin) as Hn.
    rewrite denp_at. unfold pone. cbn [peval meval]. unfold Q2R. simpl. field. exact Hn.
  - apply andb_true_iff in Hv as [Ha Hb].
    destruct (ev a) as [na ea], (ev b) as [nb eb]. simpl in *.
    rewrite peval_normal, peval_app, !peval_mul, !peval_liftP.
    rewrite <- (IHa Ha), <- (IHb Hb).
    assert (E1 : denp env 0 (emax ea eb)
                 = denp env 0 ea * denp env 0 (ediff ea (emax ea eb)))
      by (rewrite <- denp_eadd, eadd_ediff_l; reflexivity).
    assert (E2 : denp env 0 (emax ea eb)
                 = denp env 0 eb * denp env 0 (ediff eb (emax ea eb)))
      by (rewrite <- denp_eadd, (emax_comm ea eb), eadd_ediff_l; reflexivity).
    rewrite Rmult_plus_distr_r. f_equal; [rewrite E1 | rewrite E2]; ring.
  - apply andb_true_iff in Hv as [Ha Hb].
    destruct (ev a) as [na ea], (ev b) as [nb eb]. simpl in *.
    rewrite peval_normal, peval_mul, denp_eadd, <- (IHa Ha), <- (IHb Hb). ring.
  - destruct (ev a) as [na ea]. simpl in *. unfold pneg.
    rewrite peval_scale, <- (IHa Hv). unfold Q2R. simpl. field.
Qed.

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

(** [d]: the denominator the exporter expects (powers of norms); the check lifts the
    computed value and the target to the larger of the two. *)
Definition link_check (qs : list nat) (r : sx) (d : list nat) (target : poly) : bool :=
  let (n, e) := ev r in
  let m := emax e d in
  sx_valid qs r && exps_ok_from qs 0 m
  && poly_zero (pmul n (liftP 0 (ediff e m)) ++ pneg (pmul (liftP 0 (ediff d m)) target)).

(** The link of a unit: its slack [s] is the expression [r], whose value times a positive
    product of norms is the target polynomial times a non-negative one. *)
Theorem link_ok env qs r (s : R) d target :
  Forall (fun p => qnR env p <> 0) qs -> s = sden env r ->
  link_check qs r d target = true ->
  exists D F, 0 < D /\ 0 <= F /\ s * D = F * peval env target.
Proof.
  intros Hq Hs H. unfold link_check in H.
  pose proof (ev_sound env qs r Hq) as Hev.
  destruct (ev r) as [n e]. simpl in Hev.
  apply andb_true_iff in H as [H Hz]. apply andb_true_iff in H as [Hv He].
  specialize (Hev Hv).
  exists (denp env 0 (emax e d)), (denp env 0 (ediff d (emax e d))).
  split; [exact (denp_pos env qs 0 _ Hq He)|]. split; [apply denp_nonneg|].
  subst s. rewrite <- (eadd_ediff_l e d), denp_eadd, <- Rmult_assoc, Hev.
  rewrite (eadd_ediff_l e d).
  apply (poly_zero_sound env) in Hz. rewrite peval_app in Hz. unfold pneg in Hz.
  rewrite peval_scale, !peval_mul, !peval_liftP in Hz.
  assert (E : Q2R (-1) = -1) by (unfold Q2R; simpl; lra). rewrite E in Hz. lra.
Qed.

(** Reading an unfolded real expression into [sx] ([l]: the parameters, unfolded). *)
Ltac sos_index x l :=
  lazymatch l with
  | x :: _ => constr:(O)
  | _ :: ?l' => let n := sos_index x l' in constr:(S n)
  end.

Ltac sos_reify l t :=
  lazymatch t with
  | ?a + ?b => let ra := sos_reify l a in let rb := sos_reify l b in constr:(SAdd ra rb)
  | ?a * ?b => let ra := sos_reify l a in let rb := sos_reify l b in constr:(SMul ra rb)
  | - ?a => let ra := sos_reify l a in constr:(SNeg ra)
  | / IZR (Zpos ?d) => constr:(SInvC d)
  | / qn ?q =>
      let w := eval cbv delta [qw] beta iota in (qw q) in
      let p := sos_index w l in constr:(SInvQ p)
  | IZR ?z => constr:(SZ z)
  | ?x => let i := sos_index x l in constr:(SV i)
  end.

(** The prelude's definitions unfolded, the quaternion norm kept (it becomes [SInvQ]). *)
Ltac sos_unfold_in t :=
  eval cbv beta iota zeta delta [rot qvec phi fro2 det sk sym hat vee symm outer tr I3 Z3
     mT mvmul mmul msub mneg mscale madd vdot vzero vscale vneg vadd row1 row2 row3 qform
     v1 v2 v3 m11 m12 m13 m21 m22 m23 m31 m32 m33 qw qx qy qz Rdiv Rminus] in t.

(** Proves [exists D F, 0 < D /\ 0 <= F /\ s * D = F * peval env target] by [link_ok]:
    [params] is the list [env] stands for, [qs] the positions of the quaternions, [Hq]
    their norms' non-vanishing, [fe] the factors divided out of the target.  The check
    [link_check] is evaluated once, by the kernel at [Qed] ([vm_cast_no_check]); [vm_compute]
    here would evaluate it a second time, in the tactic. *)
Ltac sos_link params qs Hq fe :=
  lazymatch goal with
  | |- exists D F, 0 < D /\ 0 <= F /\ ?s * D = F * peval ?env ?t =>
      let l := sos_unfold_in params in
      let s' := sos_unfold_in s in
      let r := sos_reify l s' in
      apply (link_ok env qs r s fe t Hq); [reflexivity | vm_cast_no_check (eq_refl true)]
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

(** [s * den d = h] exactly, when [s]'s computed denominator divides [den d]. *)
Definition exact_check (qs : list nat) (r : sx) (d : list nat) (h : poly) : bool :=
  let (n, e) := ev r in
  sx_valid qs r && eqb_list (emax e d) d
  && poly_zero (pmul n (liftP 0 (ediff e d)) ++ pneg h).

Theorem exact_ok env qs r (s : R) d h :
  Forall (fun p => qnR env p <> 0) qs -> s = sden env r ->
  exact_check qs r d h = true -> peval env h = s * denp env 0 d.
Proof.
  intros Hq Hs H. unfold exact_check in H.
  pose proof (ev_sound env qs r Hq) as Hev.
  destruct (ev r) as [n e]. simpl in Hev.
  apply andb_true_iff in H as [H Hz]. apply andb_true_iff in H as [Hv Hd].
  apply eqb_list_eq in Hd. specialize (Hev Hv).
  subst s. rewrite <- Hd at 1. rewrite <- (eadd_ediff_l e d), denp_eadd, <- Rmult_assoc, Hev.
  rewrite Hd.
  apply (poly_zero_sound env) in Hz. rewrite peval_app in Hz. unfold pneg in Hz.
  rewrite peval_scale, peval_mul, peval_liftP in Hz.
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

(** Proves [peval env h = s * denp env 0 d] by [exact_ok] (its check evaluated once, by the
    kernel at [Qed], as in [sos_link]). *)
Ltac sos_exact params qs Hq :=
  lazymatch goal with
  | |- peval ?env ?h = ?s * denp ?env 0 ?d =>
      let l := sos_unfold_in params in
      let s' := sos_unfold_in s in
      let r := sos_reify l s' in
      apply (exact_ok env qs r s d h Hq); [reflexivity | vm_cast_no_check (eq_refl true)]
  end.
