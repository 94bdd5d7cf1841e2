(** * Every rotation matrix is [rot q] (Shepperd's case split)

    [SO3.v] writes rotations as [rot q] for a quaternion [q].  This file proves that
    nothing is lost: every 3x3 matrix [M] with [M^T M = I] and [det M = 1] equals
    [rot q] for some [q] with [qn q <> 0].  The quaternion is read off the matrix
    without square roots, scaled by [4 w] (or [4 x], [4 y], [4 z]): the four numbers
    [1 + tr M], [1 + 2 m11 - tr M], [1 + 2 m22 - tr M], [1 + 2 m33 - tr M] add up to 4,
    so one of them is positive, and each case gives one candidate (Shepperd 1978).
    Every identity is an ideal membership in the entries of [M] modulo [M^T M = I] and
    [det M = 1].  [orth_cofactors] derives, once and with explicit cofactors, that
    every entry of [M] equals its cofactor and that the rows are orthonormal; each
    identity of the four cases is then a linear combination of those equations with
    constant coefficients, which [lra] finds (a monomial is an atom for it).  This
    replaced 40 calls of [nsatz] (a Groebner basis each) and most of this file's
    compile time. *)

From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.

(** [rot q] entry by entry, cleared of its denominator. *)
Lemma rot_entries (w x y z a b c d e f g h i : R) :
  let n := w * w + x * x + y * y + z * z in
  n <> 0 ->
  n * (a - 1) = 2 * (- (y * y + z * z)) -> n * b = 2 * (- w * z + x * y) ->
  n * c = 2 * (w * y + x * z) -> n * d = 2 * (w * z + x * y) ->
  n * (e - 1) = 2 * (- (x * x + z * z)) -> n * f = 2 * (- w * x + y * z) ->
  n * g = 2 * (- w * y + x * z) -> n * h = 2 * (w * x + y * z) ->
  n * (i - 1) = 2 * (- (x * x + y * y)) ->
  rot (mkQ w x y z) = mkM a b c d e f g h i.
Proof.
  intros n Hn Ha Hb Hc Hd He Hf Hg Hh Hi. unfold n in *.
  apply m3_ext; so3_unfold;
  match goal with
  | |- ?l = ?r => apply (Rmult_eq_reg_l (w * w + x * x + y * y + z * z)); [ | exact Hn ];
                  field_simplify; [ | exact Hn ]
  end; lra.
Qed.

Definition orth (a b c d e f g h i : R) : Prop :=
  a * a + d * d + g * g = 1 /\ a * b + d * e + g * h = 0 /\ a * c + d * f + g * i = 0 /\
  b * b + e * e + h * h = 1 /\ b * c + e * f + h * i = 0 /\ c * c + f * f + i * i = 1 /\
  a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g) = 1.

(** What [orth] gives beyond its seven equations: every entry equals its cofactor
    ([M^T] is the adjugate [C] of [M], as [M^T - C = (M^T M - I) C - (det M - 1) M^T]
    entry by entry) and the rows are orthonormal ([M M^T = M C = det M I]).  Each
    identity is proved from its explicit cofactors by [ring]. *)
Lemma orth_cofactors (a b c d e f g h i : R) : orth a b c d e f g h i ->
  a = e * i - f * h /\ b = f * g - d * i /\ c = d * h - e * g /\
  d = c * h - b * i /\ e = a * i - c * g /\ f = b * g - a * h /\
  g = b * f - c * e /\ h = c * d - a * f /\ i = a * e - b * d /\
  a * a + b * b + c * c = 1 /\ a * d + b * e + c * f = 0 /\ a * g + b * h + c * i = 0 /\
  d * d + e * e + f * f = 1 /\ d * g + e * h + f * i = 0 /\ g * g + h * h + i * i = 1.
Proof.
  intros (o11 & o12 & o13 & o22 & o23 & o33 & dt).
  assert (Ca : a = e * i - f * h).
  { apply (eq_by_cofactors_4 _ _ (e * i - f * h) _ (f * g - d * i) _ (d * h - e * g) _ (- a) _
      (Rminus_diag_eq _ _ o11) (Rminus_diag_eq _ _ o12) (Rminus_diag_eq _ _ o13) (Rminus_diag_eq _ _ dt)); ring. }
  assert (Cb : b = f * g - d * i).
  { apply (eq_by_cofactors_4 _ _ (e * i - f * h) _ (f * g - d * i) _ (d * h - e * g) _ (- b) _
      (Rminus_diag_eq _ _ o12) (Rminus_diag_eq _ _ o22) (Rminus_diag_eq _ _ o23) (Rminus_diag_eq _ _ dt)); ring. }
  assert (Cc : c = d * h - e * g).
  { apply (eq_by_cofactors_4 _ _ (e * i - f * h) _ (f * g - d * i) _ (d * h - e * g) _ (- c) _
      (Rminus_diag_eq _ _ o13) (Rminus_diag_eq _ _ o23) (Rminus_diag_eq _ _ o33) (Rminus_diag_eq _ _ dt)); ring. }
  assert (Cd : d = c * h - b * i).
  { apply (eq_by_cofactors_4 _ _ (c * h - b * i) _ (a * i - c * g) _ (b * g - a * h) _ (- d) _
      (Rminus_diag_eq _ _ o11) (Rminus_diag_eq _ _ o12) (Rminus_diag_eq _ _ o13) (Rminus_diag_eq _ _ dt)); ring. }
  assert (Ce : e = a * i - c * g).
  { apply (eq_by_cofactors_4 _ _ (c * h - b * i) _ (a * i - c * g) _ (b * g - a * h) _ (- e) _
      (Rminus_diag_eq _ _ o12) (Rminus_diag_eq _ _ o22) (Rminus_diag_eq _ _ o23) (Rminus_diag_eq _ _ dt)); ring. }
  assert (Cf : f = b * g - a * h).
  { apply (eq_by_cofactors_4 _ _ (c * h - b * i) _ (a * i - c * g) _ (b * g - a * h) _ (- f) _
      (Rminus_diag_eq _ _ o13) (Rminus_diag_eq _ _ o23) (Rminus_diag_eq _ _ o33) (Rminus_diag_eq _ _ dt)); ring. }
  assert (Cg : g = b * f - c * e).
  { apply (eq_by_cofactors_4 _ _ (b * f - c * e) _ (c * d - a * f) _ (a * e - b * d) _ (- g) _
      (Rminus_diag_eq _ _ o11) (Rminus_diag_eq _ _ o12) (Rminus_diag_eq _ _ o13) (Rminus_diag_eq _ _ dt)); ring. }
  assert (Ch : h = c * d - a * f).
  { apply (eq_by_cofactors_4 _ _ (b * f - c * e) _ (c * d - a * f) _ (a * e - b * d) _ (- h) _
      (Rminus_diag_eq _ _ o12) (Rminus_diag_eq _ _ o22) (Rminus_diag_eq _ _ o23) (Rminus_diag_eq _ _ dt)); ring. }
  assert (Ci : i = a * e - b * d).
  { apply (eq_by_cofactors_4 _ _ (b * f - c * e) _ (c * d - a * f) _ (a * e - b * d) _ (- i) _
      (Rminus_diag_eq _ _ o13) (Rminus_diag_eq _ _ o23) (Rminus_diag_eq _ _ o33) (Rminus_diag_eq _ _ dt)); ring. }
  assert (r11 : a * a + b * b + c * c = 1).
  { apply (eq_by_cofactors_4 _ _ a _ b _ c _ 1 _
      (Rminus_diag_eq _ _ Ca) (Rminus_diag_eq _ _ Cb) (Rminus_diag_eq _ _ Cc) (Rminus_diag_eq _ _ dt)); ring. }
  assert (r12 : a * d + b * e + c * f = 0).
  { apply (eq_by_cofactors_3 _ _ a _ b _ c _
      (Rminus_diag_eq _ _ Cd) (Rminus_diag_eq _ _ Ce) (Rminus_diag_eq _ _ Cf)); ring. }
  assert (r13 : a * g + b * h + c * i = 0).
  { apply (eq_by_cofactors_3 _ _ a _ b _ c _
      (Rminus_diag_eq _ _ Cg) (Rminus_diag_eq _ _ Ch) (Rminus_diag_eq _ _ Ci)); ring. }
  assert (r22 : d * d + e * e + f * f = 1).
  { apply (eq_by_cofactors_4 _ _ d _ e _ f _ 1 _
      (Rminus_diag_eq _ _ Cd) (Rminus_diag_eq _ _ Ce) (Rminus_diag_eq _ _ Cf) (Rminus_diag_eq _ _ dt)); ring. }
  assert (r23 : d * g + e * h + f * i = 0).
  { apply (eq_by_cofactors_3 _ _ d _ e _ f _
      (Rminus_diag_eq _ _ Cg) (Rminus_diag_eq _ _ Ch) (Rminus_diag_eq _ _ Ci)); ring. }
  assert (r33 : g * g + h * h + i * i = 1).
  { apply (eq_by_cofactors_4 _ _ g _ h _ i _ 1 _
      (Rminus_diag_eq _ _ Cg) (Rminus_diag_eq _ _ Ch) (Rminus_diag_eq _ _ Ci) (Rminus_diag_eq _ _ dt)); ring. }
  repeat split; assumption.
Qed.

Lemma shepperd_w (a b c d e f g h i : R) : orth a b c d e f g h i -> 0 < 1 + a + e + i ->
  rot (mkQ (1 + a + e + i) (h - f) (c - g) (d - b)) = mkM a b c d e f g h i.
Proof.
  intros O Hp.
  destruct (orth_cofactors _ _ _ _ _ _ _ _ _ O)
    as (Ca & Cb & Cc & Cd & Ce & Cf & Cg & Ch & Ci & r11 & r12 & r13 & r22 & r23 & r33).
  destruct O as (o11 & o12 & o13 & o22 & o23 & o33 & _).
  assert (E : (1 + a + e + i) * (1 + a + e + i) + (h - f) * (h - f) + (c - g) * (c - g)
              + (d - b) * (d - b) = 4 * (1 + a + e + i)) by (clear Hp; lra).
  apply rot_entries; cbv zeta; rewrite E; [ lra | clear Hp E; lra .. ].
Qed.

Lemma shepperd_x (a b c d e f g h i : R) : orth a b c d e f g h i -> 0 < 1 + a - e - i ->
  rot (mkQ (h - f) (1 + a - e - i) (b + d) (c + g)) = mkM a b c d e f g h i.
Proof.
  intros O Hp.
  destruct (orth_cofactors _ _ _ _ _ _ _ _ _ O)
    as (Ca & Cb & Cc & Cd & Ce & Cf & Cg & Ch & Ci & r11 & r12 & r13 & r22 & r23 & r33).
  destruct O as (o11 & o12 & o13 & o22 & o23 & o33 & _).
  assert (E : (h - f) * (h - f) + (1 + a - e - i) * (1 + a - e - i) + (b + d) * (b + d)
              + (c + g) * (c + g) = 4 * (1 + a - e - i)) by (clear Hp; lra).
  apply rot_entries; cbv zeta; rewrite E; [ lra | clear Hp E; lra .. ].
Qed.

Lemma shepperd_y (a b c d e f g h i : R) : orth a b c d e f g h i -> 0 < 1 - a + e - i ->
  rot (mkQ (c - g) (b + d) (1 - a + e - i) (f + h)) = mkM a b c d e f g h i.
Proof.
  intros O Hp.
  destruct (orth_cofactors _ _ _ _ _ _ _ _ _ O)
    as (Ca & Cb & Cc & Cd & Ce & Cf & Cg & Ch & Ci & r11 & r12 & r13 & r22 & r23 & r33).
  destruct O as (o11 & o12 & o13 & o22 & o23 & o33 & _).
  assert (E : (c - g) * (c - g) + (b + d) * (b + d) + (1 - a + e - i) * (1 - a + e - i)
              + (f + h) * (f + h) = 4 * (1 - a + e - i)) by (clear Hp; lra).
  apply rot_entries; cbv zeta; rewrite E; [ lra | clear Hp E; lra .. ].
Qed.

Lemma shepperd_z (a b c d e f g h i : R) : orth a b c d e f g h i -> 0 < 1 - a - e + i ->
  rot (mkQ (d - b) (c + g) (f + h) (1 - a - e + i)) = mkM a b c d e f g h i.
Proof.
  intros O Hp.
  destruct (orth_cofactors _ _ _ _ _ _ _ _ _ O)
    as (Ca & Cb & Cc & Cd & Ce & Cf & Cg & Ch & Ci & r11 & r12 & r13 & r22 & r23 & r33).
  destruct O as (o11 & o12 & o13 & o22 & o23 & o33 & _).
  assert (E : (d - b) * (d - b) + (c + g) * (c + g) + (f + h) * (f + h)
              + (1 - a - e + i) * (1 - a - e + i) = 4 * (1 - a - e + i)) by (clear Hp; lra).
  apply rot_entries; cbv zeta; rewrite E; [ lra | clear Hp E; lra .. ].
Qed.

Lemma qn_nonzero (w x y z : R) : 0 < w \/ 0 < x \/ 0 < y \/ 0 < z -> qn (mkQ w x y z) <> 0.
Proof.
  unfold qn; simpl. intro H.
  pose proof (Rle_0_sqr w). pose proof (Rle_0_sqr x). pose proof (Rle_0_sqr y).
  pose proof (Rle_0_sqr z). unfold Rsqr in *.
  destruct H as [H | [H | [H | H]]]; pose proof (Rmult_lt_0_compat _ _ H H); lra.
Qed.

(** A rotation matrix: [M^T M = I] and [det M = 1]. *)
Definition is_rot (M : M3) : Prop := mmul (mT M) M = I3 /\ det M = 1.

(** Every rotation matrix is [rot q] for a quaternion with [qn q <> 0]: the statements
    of the prelude "for every [q] with [qn q <> 0]" are statements about every rotation. *)
Theorem rot_surjective (M : M3) : is_rot M -> exists q : quat, qn q <> 0 /\ rot q = M.
Proof.
  destruct M as [a b c d e f g h i]. intros [HO Hd].
  unfold mmul, mT, I3, det in HO, Hd; simpl in HO, Hd. injection HO; intros.
  assert (O : orth a b c d e f g h i) by (unfold orth; repeat split; lra).
  destruct (Rlt_dec 0 (1 + a + e + i)) as [Hw | Hw].
  { exists (mkQ (1 + a + e + i) (h - f) (c - g) (d - b)). split; [ | exact (shepperd_w _ _ _ _ _ _ _ _ _ O Hw) ].
    apply qn_nonzero. left. exact Hw. }
  destruct (Rlt_dec 0 (1 + a - e - i)) as [Hx | Hx].
  { exists (mkQ (h - f) (1 + a - e - i) (b + d) (c + g)). split; [ | exact (shepperd_x _ _ _ _ _ _ _ _ _ O Hx) ].
    apply qn_nonzero. right; left. exact Hx. }
  destruct (Rlt_dec 0 (1 - a + e - i)) as [Hy | Hy].
  { exists (mkQ (c - g) (b + d) (1 - a + e - i) (f + h)). split; [ | exact (shepperd_y _ _ _ _ _ _ _ _ _ O Hy) ].
    apply qn_nonzero. right; right; left. exact Hy. }
  destruct (Rlt_dec 0 (1 - a - e + i)) as [Hz | Hz].
  { exists (mkQ (d - b) (c + g) (f + h) (1 - a - e + i)). split; [ | exact (shepperd_z _ _ _ _ _ _ _ _ _ O Hz) ].
    apply qn_nonzero. right; right; right. exact Hz. }
  exfalso. lra.
Qed.
