(** * BandCert: passivity on a frequency band, from polynomial non-negativity

    For the exact-band certificates of the paper's Section 4 (nu(w) >= 0 on a band
    [w1, w2], [verify gate --band]): the Hermitian part H(jw) + H(jw)^H of the human's
    model is positive semidefinite at every w of the band where H(jw) is defined.

    What a reader audits ([band_passive] and [hermitian_part_psd_at] below):

    - Coq computes from the model's A (as data) its characteristic polynomial
      d(s) = det(sI - A) and the adjugate Adj(s) of sI - A by the Faddeev-LeVerrier
      recursion ([charpoly_adj]), and checks the identity (sI - A) Adj(s) = d(s) I
      coefficient by coefficient ([resolvent_ok]).  Hence, wherever d(jw) <> 0,
      (jwI - A)^-1 = Adj(jw) / d(jw) and
          H(jw) = C (jwI - A)^-1 B + D = N(jw) / d(jw),   N(s) = C Adj(s) B + d(s) D,
      N computed by Coq too ([tf_num]).  This last line (a matrix inverse from the
      checked identity) is the one step of the translation not proved here.
    - The claim: for every real w in [w1, w2] with d(jw) <> 0 and every complex vector z,
      Re z^H (H(jw) + H(jw)^H) z >= 0, with H(jw)_ik = N_ik(jw) / d(jw) evaluated in
      complex arithmetic written out on pairs of reals ([at_jw], [cdiv], [hform]).

    How it is proved ([band_check_sound], once for every certificate): the Hermitian
    numerator Mt(w) = |d(jw)|^2 (H(jw) + H(jw)^H) has real polynomial entries, computed
    by Coq from N and d.  For m = 1 port, Mt >= 0 iff its entry is >= 0; for m = 2, a
    Hermitian 2 x 2 matrix is >= 0 iff its trace and determinant are (lemma [herm2]).  Each
    of these real polynomials p is shown >= 0 on [w1, w2] from a witness Coq re-checks:
    p = g^2 q, and [w1, w2] cut into pieces [u, v] on each of which
    q(x) = sum_k c_k (x - u)^(i_k) (v - x)^(j_k) with every c_k >= 0 (a Bernstein form):
    both identities are checked by computing with polynomials over Q.

    The same for the frequency-domain inequality of positive realness on all of [0, oo)
    ([fdi_holds], [fdi_check_sound]): the last piece is a half line [u, oo) on which
    q(x) = sum_k c_k (x - u)^(i_k) with every c_k >= 0.  (Positive realness also asks
    that H have no pole in Re s > 0 and only simple imaginary-axis poles with Hermitian
    positive semidefinite residues: those conditions are not stated here.) *)

From Coq Require Import QArith Qabs Qreals Reals List Lra Lia.
From VerifyCoq Require Import QCert.
Import ListNotations.

(** ** Polynomials over Q as data: coefficient lists, lowest degree first *)

Definition poly := list Q.

(** Sum and product of rationals, reduced (keeps the numbers short). *)
Definition radd (a b : Q) : Q := Qred (Qplus a b).
Definition rmul (a b : Q) : Q := Qred (Qmult a b).

Fixpoint padd (p q : poly) : poly :=
  match p, q with
  | nil, _ => q
  | _, nil => p
  | a :: p', b :: q' => radd a b :: padd p' q'
  end.
Definition pscale (c : Q) (p : poly) : poly := map (rmul c) p.
Definition pneg (p : poly) : poly := map Qopp p.
Definition psub (p q : poly) : poly := padd p (pneg q).
Fixpoint pmul (p q : poly) : poly :=
  match p with
  | nil => nil
  | a :: p' => padd (pscale a q) (0%Q :: pmul p' q)
  end.
Definition ppow (p : poly) (k : nat) : poly := Nat.iter k (pmul p) [1%Q].

(** Every coefficient is zero. *)
Fixpoint pzero (p : poly) : bool :=
  match p with nil => true | a :: p' => Z.eqb (Qnum a) 0 && pzero p' end.

(** The real and imaginary parts of p(jw), as real polynomials in w: with
    p(s) = a + s p'(s), p(jw) = (a - w Im p'(jw)) + j (w Re p'(jw)). *)
Fixpoint jw_parts (p : poly) : poly * poly :=
  match p with
  | nil => (nil, nil)
  | a :: p' => let ri := jw_parts p' in
               (padd [a] (0%Q :: pneg (snd ri)), 0%Q :: fst ri)
  end.

(** ** Matrices of the model: characteristic polynomial, adjugate, transfer numerator *)

Definition mred (M : matQ) : matQ := map (map Qred) M.
Definition mtrace (n : nat) (M : matQ) : Q := sumQ n (fun i => entry M i i).

(** Faddeev-LeVerrier: M_1 = I, c_(n-k) = -tr(A M_k) / k, M_(k+1) = A M_k + c_(n-k) I.
    Returns d's coefficients [c_0; ...; c_n] (c_n = 1) and Adj's coefficient matrices
    [M_n; ...; M_1] (M_k multiplies s^(n-k)), both lowest degree first. *)
Fixpoint same_den_mat (d : positive) (M : matQ) : bool :=
  match M with nil => true | row :: M' => same_den d row && same_den_mat d M' end.

(** One step: c = -tr(A M_k) / k and M_(k+1) = A M_k + c I.  When A is written over one
    denominator e, A M_k is over e^k and the numerator of its trace is divisible by k
    (the numbers of the recursion on the integer matrix e A are integers), so c and
    M_(k+1) are kept over e^k, unreduced: the next product then sums numerators
    ([dot]'s fast path) instead of adding fractions over different denominators (whose
    lengths multiply).  Otherwise c and M_(k+1) are reduced entry by entry.  Either way
    the values are the same rationals; nothing is proved about them here: [resolvent_ok]
    checks the result. *)
Definition fl_step (n k : nat) (AM : matQ) : Q * matQ :=
  let t := mtrace n AM in
  let kz := Z.of_nat k in
  if same_den_mat (Qden t) AM && Z.eqb (Z.rem (Qnum t) kz) 0 then
    let c := Qmake (Z.opp (Z.quot (Qnum t) kz)) (Qden t) in
    (c, madd AM (scaled_identity n c))
  else
    let c := Qred (Qopp t / inject_Z kz) in
    (c, mred (madd AM (scaled_identity n c))).

Fixpoint fl_loop (A : matQ) (n steps k : nat) (Mk : matQ) (cs : list Q) (Ms : list matQ)
    : list Q * list matQ :=
  match steps with
  | O => (cs, Ms)
  | S st =>
      let cM := fl_step n k (mmul A Mk) in
      fl_loop A n st (S k) (snd cM) (fst cM :: cs) (Mk :: Ms)
  end.

Definition charpoly_adj (n : nat) (A : matQ) : list Q * list matQ :=
  fl_loop A n n 1 (scaled_identity n 1) [1%Q] nil.

Definition mat_zero (M : matQ) : bool := forallb pzero M.

(** (sI - A) Adj(s) = d(s) I, coefficient by coefficient: the coefficient of s^j on the
    left is Adj_(j-1) - A Adj_j (Adj_(-1) = Adj_n = 0).  [prev] is Adj_(j-1). *)
Fixpoint resolvent_ok (n : nat) (A prev : matQ) (cs : list Q) (Ms : list matQ) : bool :=
  match cs, Ms with
  | c :: cs', M :: Ms' =>
      mat_zero (msub (msub prev (mmul A M)) (scaled_identity n c))
      && resolvent_ok n A M cs' Ms'
  | c :: nil, nil => mat_zero (msub prev (scaled_identity n c))
  | _, _ => false
  end.

Fixpoint zip2 {X Y Z : Type} (f : X -> Y -> Z) (xs : list X) (ys : list Y) : list Z :=
  match xs, ys with
  | x :: xs', y :: ys' => f x y :: zip2 f xs' ys'
  | _, _ => nil
  end.

(** N(s) = C Adj(s) B + d(s) D, entry (i, k): its coefficient of s^j is
    (C Adj_j B)_ik + c_j D_ik (Adj_n = 0), lowest degree first. *)
Definition num_coeffs (C B : matQ) (cs : list Q) (Ms : list matQ) : list (matQ * Q) :=
  zip2 (fun c M => (mmul (mmul C M) B, c)) cs (Ms ++ [nil]).
(** The coefficient matrices are bound before [i k]: [let N := tf_num C B D cs Ms in ...]
    computes them once for all entries under [vm_compute] (call by value). *)
Definition tf_num (C B D : matQ) (cs : list Q) (Ms : list matQ) : nat -> nat -> poly :=
  let NC := num_coeffs C B cs Ms in
  fun i k => map (fun x => Qred (qadd (entry (fst x) i k) (qmul (snd x) (entry D i k)))) NC.

(** ** What a band certificate states, over the reals *)

Open Scope R_scope.

(** Complex numbers as pairs (real part, imaginary part). *)
Definition cadd (z u : R * R) : R * R := (fst z + fst u, snd z + snd u).
Definition cmul (z u : R * R) : R * R :=
  (fst z * fst u - snd z * snd u, fst z * snd u + snd z * fst u).
Definition cconj (z : R * R) : R * R := (fst z, - snd z).
Definition cdiv (z u : R * R) : R * R :=
  let r := fst u * fst u + snd u * snd u in
  ((fst z * fst u + snd z * snd u) / r, (snd z * fst u - fst z * snd u) / r).

(** p(jw), by Horner's rule in complex arithmetic. *)
Fixpoint at_jw (p : poly) (w : R) : R * R :=
  match p with
  | nil => (0, 0)
  | a :: p' => cadd (Q2R a, 0) (cmul (0, w) (at_jw p' w))
  end.

(** H(jw) + H(jw)^H, entry (i, k), for H(jw)_ik = N_ik(jw) / d(jw). *)
Definition herm_of (Nv : nat -> nat -> R * R) (dv : R * R) (i k : nat) : R * R :=
  cadd (cdiv (Nv i k) dv) (cconj (cdiv (Nv k i) dv)).

(** Re z^H M z for an m x m complex matrix M and a complex vector z. *)
Definition hform (m : nat) (M : nat -> nat -> R * R) (z : nat -> R * R) : R :=
  sumR m (fun i => sumR m (fun k => fst (cmul (cconj (z i)) (cmul (M i k) (z k))))).

(** At the frequency w: H(jw) + H(jw)^H >= 0 when d(jw) <> 0, with H(jw) = N(jw) / d(jw)
    as in the header. *)
Definition hermitian_part_psd_at (n m : nat) (A B C D : matQ) (w : R) : Prop :=
  at_jw (fst (charpoly_adj n A)) w <> (0, 0) ->
  forall z, 0 <= hform m (herm_of (fun i k => at_jw (tf_num C B D (fst (charpoly_adj n A))
                                                        (snd (charpoly_adj n A)) i k) w)
                                  (at_jw (fst (charpoly_adj n A)) w)) z.

(** The data describe a model: the shapes match and (sI - A) Adj(s) = d(s) I. *)
Definition model_ok (n m : nat) (A B C D : matQ) : Prop :=
  has_shape n n A /\ has_shape n m B /\ has_shape m n C /\ has_shape m m D
  /\ resolvent_ok n A (zeros n n) (fst (charpoly_adj n A)) (snd (charpoly_adj n A)) = true.

(** The model (A, B, C, D), n states and m ports, is passive on [w1, w2], w1 < w2:
    H(jw) + H(jw)^H >= 0 at every w of the band where d(jw) <> 0. *)
Definition band_passive (n m : nat) (A B C D : matQ) (w1 w2 : Q) : Prop :=
  model_ok n m A B C D /\ (w1 < w2)%Q
  /\ forall w, Q2R w1 <= w <= Q2R w2 -> hermitian_part_psd_at n m A B C D w.

(** The frequency-domain inequality of positive realness: H(jw) + H(jw)^H >= 0 at every
    w >= 0 where d(jw) <> 0 (for w < 0, H(-jw) is the conjugate of H(jw), so the same). *)
Definition fdi_holds (n m : nat) (A B C D : matQ) : Prop :=
  model_ok n m A B C D /\ forall w, 0 <= w -> hermitian_part_psd_at n m A B C D w.

(** ** Polynomial evaluation respects the operations *)

Fixpoint peval (p : poly) (x : R) : R :=
  match p with nil => 0 | a :: p' => Q2R a + x * peval p' x end.

Lemma Q2R_radd a b : Q2R (radd a b) = Q2R a + Q2R b.
Proof. unfold radd. rewrite Q2R_red. apply Q2R_plus. Qed.

Lemma Q2R_rmul a b : Q2R (rmul a b) = Q2R a * Q2R b.
Proof. unfold rmul. rewrite Q2R_red. apply Q2R_mult. Qed.

Lemma Q2R_0 : Q2R 0%Q = 0.
Proof. unfold Q2R. simpl. field. Qed.

Lemma Q2R_1 : Q2R 1%Q = 1.
Proof. unfold Q2R. simpl. field. Qed.

Lemma peval_add p q x : peval (padd p q) x = peval p x + peval q x.
Proof.
  revert q. induction p as [|a p IH]; intros [|b q]; simpl; try ring.
  rewrite Q2R_radd, IH. ring.
Qed.

Lemma peval_scale c p x : peval (pscale c p) x = Q2R c * peval p x.
Proof.
  induction p as [|a p IH]; simpl; [ring|]. rewrite Q2R_rmul, IH. ring.
Qed.

Lemma peval_neg p x : peval (pneg p) x = - peval p x.
Proof. induction p as [|a p IH]; simpl; [ring|]. rewrite Q2R_opp, IH. ring. Qed.

Lemma peval_sub p q x : peval (psub p q) x = peval p x - peval q x.
Proof. unfold psub. rewrite peval_add, peval_neg. ring. Qed.

Lemma peval_mul p q x : peval (pmul p q) x = peval p x * peval q x.
Proof.
  induction p as [|a p IH]; simpl; [ring|].
  rewrite peval_add, peval_scale. simpl. rewrite IH, Q2R_0. ring.
Qed.

Lemma peval_pow p k x : peval (ppow p k) x = pow (peval p x) k.
Proof.
  induction k as [|k IH]; simpl.
  - rewrite Q2R_1. ring.
  - unfold ppow in *. simpl. rewrite peval_mul, IH. reflexivity.
Qed.

Lemma pzero_sound p x : pzero p = true -> peval p x = 0.
Proof.
  induction p as [|[na da] p IH]; simpl; [reflexivity|].
  rewrite andb_true_iff, Z.eqb_eq. intros [-> Hp]. rewrite IH by exact Hp.
  unfold Q2R. simpl. ring.
Qed.

Lemma pzero_sub p q x : pzero (psub p q) = true -> peval p x = peval q x.
Proof. intros H. pose proof (pzero_sound _ x H) as E. rewrite peval_sub in E. lra. Qed.

Lemma jw_parts_sound p w :
  peval (fst (jw_parts p)) w = fst (at_jw p w) /\ peval (snd (jw_parts p)) w = snd (at_jw p w).
Proof.
  induction p as [|a p [IHr IHi]]; [split; reflexivity|].
  cbn [jw_parts fst snd at_jw]. rewrite peval_add. cbn [peval].
  rewrite peval_neg, IHr, IHi, Q2R_0. unfold cadd, cmul. cbn [fst snd]. split; ring.
Qed.

Lemma jw_re p w : peval (fst (jw_parts p)) w = fst (at_jw p w).
Proof. apply jw_parts_sound. Qed.

Lemma jw_im p w : peval (snd (jw_parts p)) w = snd (at_jw p w).
Proof. apply jw_parts_sound. Qed.

(** ** Non-negativity on an interval from a witness *)

(** A piece [u, v] of the band and its terms (c, i, j): c (x - u)^i (v - x)^j. *)
Definition bterm := (Q * nat * nat)%type.
Definition piece := (Q * Q * list bterm)%type.

Definition bern (u v : Q) (ts : list bterm) : poly :=
  fold_right (fun t acc => let '(c, i, j) := t in
                padd (pscale c (pmul (ppow [Qopp u; 1%Q] i) (ppow [v; (-1)%Q] j))) acc)
             nil ts.

Definition piece_ok (q : poly) (pc : piece) : bool :=
  let '(u, v, ts) := pc in
  pzero (psub q (bern u v ts)) && forallb (fun t => let '(c, _, _) := t in Qle_bool 0 c) ts.

(** The pieces start at a, each starts where the last ended, the last ends at b. *)
Fixpoint cover_ok (a b : Q) (q : poly) (ps : list piece) : bool :=
  match ps with
  | nil => false
  | pc :: ps' =>
      let '(u, v, _) := pc in
      Qeq_bool u a && piece_ok q pc &&
      match ps' with nil => Qeq_bool v b | _ => cover_ok v b q ps' end
  end.

(** p = g^2 q, and q >= 0 on [a, b] piece by piece. *)
Definition nonneg_cert := (poly * poly * list piece)%type.

Definition nonneg_ok (a b : Q) (p : poly) (c : nonneg_cert) : bool :=
  let '(g, q, ps) := c in pzero (psub p (pmul (pmul g g) q)) && cover_ok a b q ps.

Lemma bern_nonneg u v ts x :
  forallb (fun t => let '(c, _, _) := t in Qle_bool 0 c) ts = true ->
  Q2R u <= x <= Q2R v -> 0 <= peval (bern u v ts) x.
Proof.
  intros Hc Hx. induction ts as [|[[c i] j] ts IH]; simpl; [lra|].
  simpl in Hc. apply andb_true_iff in Hc as [Hc0 Hc].
  rewrite peval_add, peval_scale, peval_mul, !peval_pow. cbn [peval].
  rewrite Q2R_opp, Q2R_1.
  replace (Q2R (-1)%Q) with (-1) by (unfold Q2R; simpl; field).
  apply Qle_bool_R in Hc0. rewrite Q2R_0 in Hc0.
  pose proof (IH Hc).
  assert (0 <= (- Q2R u + x * (1 + x * 0)) ^ i) by (apply pow_le; lra).
  assert (0 <= (Q2R v + x * (-1 + x * 0)) ^ j) by (apply pow_le; lra).
  assert (0 <= Q2R c * ((- Q2R u + x * (1 + x * 0)) ^ i * (Q2R v + x * (-1 + x * 0)) ^ j))
    by (apply Rmult_le_pos; [lra | apply Rmult_le_pos; lra]).
  lra.
Qed.

Lemma piece_sound q pc x :
  piece_ok q pc = true -> let '(u, v, _) := pc in Q2R u <= x <= Q2R v -> 0 <= peval q x.
Proof.
  destruct pc as [[u v] ts]. unfold piece_ok. rewrite andb_true_iff. intros [Hid Hc] Hx.
  rewrite (pzero_sub _ _ x Hid). apply bern_nonneg; assumption.
Qed.

Lemma Qeq_bool_R a b : Qeq_bool a b = true -> Q2R a = Q2R b.
Proof. intros H. apply Qeq_eqR, Qeq_bool_iff, H. Qed.

Lemma cover_sound ps : forall a b q, cover_ok a b q ps = true ->
  forall x, Q2R a <= x <= Q2R b -> 0 <= peval q x.
Proof.
  induction ps as [|pc ps IH]; intros a b q H x Hx; simpl in H; [discriminate|].
  destruct pc as [[u v] ts]. rewrite !andb_true_iff in H. destruct H as [[Hu Hp] Hrest].
  apply Qeq_bool_R in Hu.
  destruct (Rle_dec x (Q2R v)) as [Hle|Hgt].
  - exact (piece_sound q (u, v, ts) x Hp ltac:(lra)).
  - destruct ps as [|pc' ps'].
    + apply Qeq_bool_R in Hrest. lra.
    + apply (IH v b q Hrest x). lra.
Qed.

Theorem nonneg_sound a b p c : nonneg_ok a b p c = true ->
  forall x, Q2R a <= x <= Q2R b -> 0 <= peval p x.
Proof.
  destruct c as [[g q] ps]. unfold nonneg_ok. rewrite andb_true_iff. intros [Hid Hc] x Hx.
  rewrite (pzero_sub _ _ x Hid), !peval_mul.
  pose proof (cover_sound ps a b q Hc x Hx).
  assert (0 <= peval g x * peval g x) by apply Rle_0_sqr.
  apply Rmult_le_pos; assumption.
Qed.

(** A half line [u, oo): q(x) = sum_k c_k (x - u)^(i_k), every c_k >= 0 (its Taylor
    coefficients at u). *)
Definition ray := (Q * list (Q * nat))%type.

Definition ray_poly (u : Q) (ts : list (Q * nat)) : poly :=
  fold_right (fun t acc => padd (pscale (fst t) (ppow [Qopp u; 1%Q] (snd t))) acc) nil ts.

Definition ray_ok (q : poly) (r : ray) : bool :=
  pzero (psub q (ray_poly (fst r) (snd r))) && forallb (fun t => Qle_bool 0 (fst t)) (snd r).

(** p = g^2 q; q >= 0 on [a, u] piece by piece (no piece when u = a) and on [u, oo). *)
Definition ray_cert := (poly * poly * list piece * ray)%type.

Definition ray_nonneg_ok (a : Q) (p : poly) (c : ray_cert) : bool :=
  let '(g, q, ps, r) := c in
  pzero (psub p (pmul (pmul g g) q))
  && match ps with nil => Qeq_bool (fst r) a | _ => cover_ok a (fst r) q ps end
  && ray_ok q r.

Lemma ray_poly_nonneg u ts x :
  forallb (fun t => Qle_bool 0 (fst t)) ts = true -> Q2R u <= x -> 0 <= peval (ray_poly u ts) x.
Proof.
  intros Hc Hx. induction ts as [|[c i] ts IH]; simpl; [lra|].
  simpl in Hc. apply andb_true_iff in Hc as [Hc0 Hc].
  rewrite peval_add, peval_scale, peval_pow. cbn [peval]. rewrite Q2R_opp, Q2R_1.
  apply Qle_bool_R in Hc0. rewrite Q2R_0 in Hc0.
  pose proof (IH Hc).
  assert (0 <= (- Q2R u + x * (1 + x * 0)) ^ i) by (apply pow_le; lra).
  assert (0 <= Q2R c * (- Q2R u + x * (1 + x * 0)) ^ i) by (apply Rmult_le_pos; lra).
  lra.
Qed.

Theorem ray_nonneg_sound a p c : ray_nonneg_ok a p c = true ->
  forall x, Q2R a <= x -> 0 <= peval p x.
Proof.
  destruct c as [[[g q] ps] [u ts]]. unfold ray_nonneg_ok. rewrite !andb_true_iff.
  intros [[Hid Hcov] Hray] x Hx.
  rewrite (pzero_sub _ _ x Hid), !peval_mul.
  assert (0 <= peval q x).
  { destruct (Rle_dec x (Q2R u)) as [Hle|Hgt].
    - destruct ps as [|pc ps'].
      + apply Qeq_bool_R in Hcov. simpl in Hcov.
        unfold ray_ok in Hray. apply andb_true_iff in Hray as [Hr Hc]. simpl in Hr, Hc.
        rewrite (pzero_sub _ _ x Hr). apply ray_poly_nonneg; [exact Hc | simpl; lra].
      + exact (cover_sound (pc :: ps') a u q Hcov x ltac:(simpl; lra)).
    - unfold ray_ok in Hray. apply andb_true_iff in Hray as [Hr Hc]. simpl in Hr, Hc.
      rewrite (pzero_sub _ _ x Hr). apply ray_poly_nonneg; [exact Hc | lra]. }
  assert (0 <= peval g x * peval g x) by apply Rle_0_sqr.
  apply Rmult_le_pos; assumption.
Qed.

(** ** The Hermitian numerator and its sign polynomials *)

(** Mt(w) = N(jw) conj(d(jw)) + d(jw) N(jw)^H, entry (i, k): real and imaginary parts. *)
Definition mt_re (N : nat -> nat -> poly) (d : poly) (i k : nat) : poly :=
  let dr := fst (jw_parts d) in let di := snd (jw_parts d) in
  padd (pmul dr (padd (fst (jw_parts (N i k))) (fst (jw_parts (N k i)))))
       (pmul di (padd (snd (jw_parts (N i k))) (snd (jw_parts (N k i))))).
Definition mt_im (N : nat -> nat -> poly) (d : poly) (i k : nat) : poly :=
  let dr := fst (jw_parts d) in let di := snd (jw_parts d) in
  psub (pmul dr (psub (snd (jw_parts (N i k))) (snd (jw_parts (N k i)))))
       (pmul di (psub (fst (jw_parts (N i k))) (fst (jw_parts (N k i))))).

(** The polynomials whose non-negativity on the band is the claim: for one port the
    entry of Mt; for two, its trace and its determinant. *)
Definition sign_polys (m : nat) (N : nat -> nat -> poly) (d : poly) : list poly :=
  match m with
  | 1%nat => [mt_re N d 0 0]
  | 2%nat => let s00 := mt_re N d 0 0 in let s11 := mt_re N d 1 1 in
             let s01 := mt_re N d 0 1 in let t01 := mt_im N d 0 1 in
             [padd s00 s11; psub (pmul s00 s11) (padd (pmul s01 s01) (pmul t01 t01))]
  | _ => nil
  end.

Lemma sign_polys_ext m N1 N2 d : (m = 1 \/ m = 2)%nat ->
  (forall i k, (i < m)%nat -> (k < m)%nat -> N1 i k = N2 i k) ->
  sign_polys m N1 d = sign_polys m N2 d.
Proof.
  intros [-> | ->] H; unfold sign_polys, mt_re, mt_im; cbv zeta;
    rewrite ?(H 0%nat 0%nat), ?(H 0%nat 1%nat), ?(H 1%nat 0%nat), ?(H 1%nat 1%nat) by lia;
    reflexivity.
Qed.

(** The entries N i k (i, k < m) computed once, as a table. *)
Definition num_table (m : nat) (N : nat -> nat -> poly) : list (list poly) :=
  map (fun i => map (fun k => N i k) (seq 0 m)) (seq 0 m).

Lemma nth_map_seq {T : Type} (f : nat -> T) m i d : (i < m)%nat ->
  nth i (map f (seq 0 m)) d = f i.
Proof.
  intros Hi. rewrite (nth_indep _ d (f 0%nat)) by (rewrite map_length, seq_length; exact Hi).
  rewrite map_nth, seq_nth by exact Hi. reflexivity.
Qed.

Lemma num_table_nth m N i k : (i < m)%nat -> (k < m)%nat ->
  nth k (nth i (num_table m N) nil) nil = N i k.
Proof.
  intros Hi Hk. unfold num_table.
  rewrite (nth_map_seq (fun i => map (fun k => N i k) (seq 0 m))) by exact Hi. cbv beta.
  apply (nth_map_seq (fun k => N i k)), Hk.
Qed.

Lemma peval_mt_re N d i k w :
  peval (mt_re N d i k) w
  = fst (at_jw d w) * (fst (at_jw (N i k) w) + fst (at_jw (N k i) w))
    + snd (at_jw d w) * (snd (at_jw (N i k) w) + snd (at_jw (N k i) w)).
Proof. unfold mt_re. rewrite peval_add, !peval_mul, !peval_add, !jw_re, !jw_im. ring. Qed.

Lemma peval_mt_im N d i k w :
  peval (mt_im N d i k) w
  = fst (at_jw d w) * (snd (at_jw (N i k) w) - snd (at_jw (N k i) w))
    - snd (at_jw d w) * (fst (at_jw (N i k) w) - fst (at_jw (N k i) w)).
Proof. unfold mt_im. rewrite peval_sub, !peval_mul, !peval_sub, !jw_re, !jw_im. ring. Qed.

(** A Hermitian 2 x 2 matrix [[al, be + j ga], [be - j ga, ep]] with a non-negative trace
    and determinant has a non-negative form. *)
Lemma herm2 al ep be ga x1 y1 x2 y2 :
  0 <= al + ep -> 0 <= al * ep - be * be - ga * ga ->
  0 <= al * (x1 * x1 + y1 * y1) + ep * (x2 * x2 + y2 * y2)
       + 2 * (be * (x1 * x2 + y1 * y2) - ga * (x1 * y2 - y1 * x2)).
Proof.
  intros Ht Hd.
  assert (Hbg : 0 <= be * be + ga * ga) by nra.
  assert (Hz2 : 0 <= x2 * x2 + y2 * y2) by nra.
  destruct (Rlt_dec 0 al) as [Ha|Ha].
  - assert (E : al * (al * (x1 * x1 + y1 * y1) + ep * (x2 * x2 + y2 * y2)
                 + 2 * (be * (x1 * x2 + y1 * y2) - ga * (x1 * y2 - y1 * x2)))
              = (al * x1 + be * x2 - ga * y2) * (al * x1 + be * x2 - ga * y2)
                + (al * y1 + be * y2 + ga * x2) * (al * y1 + be * y2 + ga * x2)
                + (al * ep - be * be - ga * ga) * (x2 * x2 + y2 * y2)) by ring.
    assert (0 <= (al * ep - be * be - ga * ga) * (x2 * x2 + y2 * y2))
      by (apply Rmult_le_pos; assumption).
    assert (0 <= (al * x1 + be * x2 - ga * y2) * (al * x1 + be * x2 - ga * y2))
      by apply Rle_0_sqr.
    assert (0 <= (al * y1 + be * y2 + ga * x2) * (al * y1 + be * y2 + ga * x2))
      by apply Rle_0_sqr.
    apply (Rmult_le_reg_l al); [exact Ha|]. rewrite Rmult_0_r, E. lra.
  - assert (Hep : 0 <= ep) by lra.
    assert (al * ep <= 0) by nra.
    assert (Hb : be * be + ga * ga = 0) by lra.
    assert (be = 0) by nra. assert (ga = 0) by nra.
    assert (al = 0 \/ ep = 0) as Hz by nra.
    subst be ga.
    destruct Hz as [-> | ->]; [nra|].
    assert (al = 0) by lra. subst al. nra.
Qed.

Lemma pair_nonzero (p q : R) : (p, q) <> (0, 0) -> p * p + q * q <> 0.
Proof.
  intros Hne H. apply Hne.
  assert (p = 0) by nra. assert (q = 0) by nra. subst. reflexivity.
Qed.

(** The form of H(jw) + H(jw)^H is the form of Mt(w) divided by |d(jw)|^2. *)
Lemma hform2_eq (Nv : nat -> nat -> R * R) (p q : R) (z : nat -> R * R) :
  p * p + q * q <> 0 ->
  hform 2 (herm_of Nv (p, q)) z
  = (let sr i k := p * (fst (Nv i k) + fst (Nv k i)) + q * (snd (Nv i k) + snd (Nv k i)) in
     let si i k := p * (snd (Nv i k) - snd (Nv k i)) - q * (fst (Nv i k) - fst (Nv k i)) in
     let x1 := fst (z 0%nat) in let y1 := snd (z 0%nat) in
     let x2 := fst (z 1%nat) in let y2 := snd (z 1%nat) in
     sr 0%nat 0%nat * (x1 * x1 + y1 * y1) + sr 1%nat 1%nat * (x2 * x2 + y2 * y2)
     + 2 * (sr 0%nat 1%nat * (x1 * x2 + y1 * y2) - si 0%nat 1%nat * (x1 * y2 - y1 * x2)))
    / (p * p + q * q).
Proof.
  (* linear in 1 / (p^2 + q^2): with its inverse as an atom, lra decides it *)
  intros _. unfold hform, herm_of, cadd, cmul, cconj, cdiv. simpl. cbv zeta. unfold Rdiv.
  generalize (/ (p * p + q * q)); intro t. lra.
Qed.

Lemma hform1_eq (Nv : nat -> nat -> R * R) (p q : R) (z : nat -> R * R) :
  p * p + q * q <> 0 ->
  hform 1 (herm_of Nv (p, q)) z
  = (p * (fst (Nv 0%nat 0%nat) + fst (Nv 0%nat 0%nat))
     + q * (snd (Nv 0%nat 0%nat) + snd (Nv 0%nat 0%nat)))
    * (fst (z 0%nat) * fst (z 0%nat) + snd (z 0%nat) * snd (z 0%nat)) / (p * p + q * q).
Proof.
  intros Hn. unfold hform, herm_of, cadd, cmul, cconj, cdiv. simpl. field. exact Hn.
Qed.

(** ** The check, and its soundness proved once *)

Fixpoint all_nonneg (a b : Q) (ps : list poly) (cs : list nonneg_cert) : bool :=
  match ps, cs with
  | nil, nil => true
  | p :: ps', c :: cs' => nonneg_ok a b p c && all_nonneg a b ps' cs'
  | _, _ => false
  end.

Definition model_check (n m : nat) (A B C D : matQ) : bool :=
  has_shape_b n n A && has_shape_b n m B && has_shape_b m n C && has_shape_b m m D
  && resolvent_ok n A (zeros n n) (fst (charpoly_adj n A)) (snd (charpoly_adj n A))
  && (Nat.eqb m 1 || Nat.eqb m 2).

(** The sign polynomials of the model, as Coq computes them (each entry of N once). *)
Definition model_signs (n m : nat) (A B C D : matQ) : list poly :=
  let fl := charpoly_adj n A in
  let T := num_table m (tf_num C B D (fst fl) (snd fl)) in
  sign_polys m (fun i k => nth k (nth i T nil) nil) (fst fl).

Definition band_check (n m : nat) (A B C D : matQ) (w1 w2 : Q)
    (certs : list nonneg_cert) : bool :=
  model_check n m A B C D && negb (Qle_bool w2 w1)
  && all_nonneg w1 w2 (model_signs n m A B C D) certs.

Lemma model_check_sound n m A B C D :
  model_check n m A B C D = true -> model_ok n m A B C D /\ (m = 1 \/ m = 2)%nat.
Proof.
  unfold model_check. rewrite !andb_true_iff, orb_true_iff, !Nat.eqb_eq.
  intros [[[[[HA HB] HC] HD] Hres] Hm].
  split; [|exact Hm].
  split; [apply has_shape_b_sound, HA|]. split; [apply has_shape_b_sound, HB|].
  split; [apply has_shape_b_sound, HC|]. split; [apply has_shape_b_sound, HD|].
  exact Hres.
Qed.

(** Non-negative sign polynomials at w give H(jw) + H(jw)^H >= 0 there (one or two ports). *)
Lemma psd_at_of_signs n m A B C D w : (m = 1 \/ m = 2)%nat ->
  (forall k p, nth_error (model_signs n m A B C D) k = Some p -> 0 <= peval p w) ->
  hermitian_part_psd_at n m A B C D w.
Proof.
  intros Hm Hnn Hd z. unfold model_signs in Hnn. cbv zeta in Hnn.
  rewrite (sign_polys_ext m _ (tf_num C B D (fst (charpoly_adj n A)) (snd (charpoly_adj n A))))
    in Hnn by (exact Hm || (intros i k Hi Hk; apply num_table_nth; assumption)).
  set (d := fst (charpoly_adj n A)) in *.
  set (N := tf_num C B D d (snd (charpoly_adj n A))) in *.
  destruct (at_jw d w) as [p q] eqn:Ed.
  pose proof (pair_nonzero p q Hd) as Hn.
  assert (Hpos : 0 < p * p + q * q).
  { assert (0 <= p * p) by apply Rle_0_sqr. assert (0 <= q * q) by apply Rle_0_sqr. lra. }
  destruct Hm as [-> | ->].
  - rewrite hform1_eq by exact Hn.
    pose proof (Hnn 0%nat _ eq_refl) as H1. rewrite peval_mt_re, Ed in H1. simpl in H1.
    unfold Rdiv. apply Rmult_le_pos; [|apply Rlt_le, Rinv_0_lt_compat, Hpos].
    apply Rmult_le_pos; [exact H1|]. nra.
  - rewrite hform2_eq by exact Hn.
    pose proof (Hnn 0%nat _ eq_refl) as H1.
    pose proof (Hnn 1%nat _ eq_refl) as H2.
    rewrite peval_add, !peval_mt_re, Ed in H1. simpl in H1.
    rewrite peval_sub, peval_add, !peval_mul, !peval_mt_re, !peval_mt_im, Ed in H2.
    simpl in H2.
    unfold Rdiv. apply Rmult_le_pos; [|apply Rlt_le, Rinv_0_lt_compat, Hpos]. cbv zeta.
    apply herm2; lra.
Qed.

Lemma all_nonneg_nth a b ps cs : all_nonneg a b ps cs = true ->
  forall k p, nth_error ps k = Some p -> forall x, Q2R a <= x <= Q2R b -> 0 <= peval p x.
Proof.
  revert cs. induction ps as [|p0 ps IH]; intros [|c cs] H k p Hk x Hx; simpl in H;
    try discriminate.
  - destruct k; discriminate.
  - apply andb_true_iff in H as [H0 H]. destruct k as [|k]; simpl in Hk.
    + injection Hk as <-. exact (nonneg_sound a b p0 c H0 x Hx).
    + exact (IH cs H k p Hk x Hx).
Qed.

Theorem band_check_sound n m A B C D w1 w2 certs :
  band_check n m A B C D w1 w2 certs = true -> band_passive n m A B C D w1 w2.
Proof.
  unfold band_check. rewrite !andb_true_iff, negb_true_iff.
  intros [[Hmodel Hw] Hall].
  destruct (model_check_sound _ _ _ _ _ _ Hmodel) as [Hok Hm].
  split; [exact Hok|].
  split; [apply Qnot_le_lt; intros Hle; apply Qle_bool_iff in Hle; congruence|].
  intros w Hx. apply (psd_at_of_signs _ _ _ _ _ _ w Hm).
  intros k p Hk. exact (all_nonneg_nth _ _ _ _ Hall k p Hk w Hx).
Qed.

(** ** The frequency-domain inequality on [0, oo) *)

Fixpoint all_ray_nonneg (ps : list poly) (cs : list ray_cert) : bool :=
  match ps, cs with
  | nil, nil => true
  | p :: ps', c :: cs' => ray_nonneg_ok 0 p c && all_ray_nonneg ps' cs'
  | _, _ => false
  end.

Definition fdi_check (n m : nat) (A B C D : matQ) (certs : list ray_cert) : bool :=
  model_check n m A B C D && all_ray_nonneg (model_signs n m A B C D) certs.

Lemma all_ray_nonneg_nth ps cs : all_ray_nonneg ps cs = true ->
  forall k p, nth_error ps k = Some p -> forall x, 0 <= x -> 0 <= peval p x.
Proof.
  revert cs. induction ps as [|p0 ps IH]; intros [|c cs] H k p Hk x Hx; simpl in H;
    try discriminate.
  - destruct k; discriminate.
  - apply andb_true_iff in H as [H0 H]. destruct k as [|k]; simpl in Hk.
    + injection Hk as <-. apply (ray_nonneg_sound 0 p0 c H0 x). rewrite Q2R_0. exact Hx.
    + exact (IH cs H k p Hk x Hx).
Qed.

Theorem fdi_check_sound n m A B C D certs :
  fdi_check n m A B C D certs = true -> fdi_holds n m A B C D.
Proof.
  unfold fdi_check. rewrite andb_true_iff. intros [Hmodel Hall].
  destruct (model_check_sound _ _ _ _ _ _ Hmodel) as [Hok Hm].
  split; [exact Hok|].
  intros w Hx. apply (psd_at_of_signs _ _ _ _ _ _ w Hm).
  intros k p Hk. exact (all_ray_nonneg_nth _ _ Hall k p Hk w Hx).
Qed.
