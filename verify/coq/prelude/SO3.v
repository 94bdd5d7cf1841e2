(** * SO(3) prelude: the paper's notation on 3x3 real matrices

    Every exported statement is written with the definitions below and nothing else.
    They follow the paper's Section 3 and the proof language of [verify.proof]:

    - a vector is a record of 3 reals, a matrix a record of 9 reals (row by row), so
      that after unfolding, [ring] and [field] decide identities entry by entry;
    - [sk M = (M - M^T)/2], [sym M = (M + M^T)/2], [hat v] is the matrix of [v x .],
      [vee M] is the vector of the skew part of [M] (so [vee (hat v) = v]),
      [tr] is the trace, [phi R = tr(I - R)/2] (Theorem 1's energy function),
      [fro2 M = tr(M^T M)] the squared Frobenius norm;
    - rotations are given by quaternions: [rot q = I + 2 (w hat(v) + hat(v)^2) / |q|^2]
      for [q = (w, v)] with [|q|^2 <> 0].

    Why quaternions and not "entries with R^T R = I, det R = 1 as hypotheses": with
    quaternions the entries of a rotation are rational functions of four free reals,
    so an identity between expressions in rotations is a rational-function identity
    that [field] decides by itself, with the one hypothesis [|q|^2 <> 0].  With
    orthogonality hypotheses every identity would need an ideal-membership
    certificate in nine entries per rotation.  Nothing is lost: [RotSurj.v] proves
    that every rotation matrix is [rot q] for some [q] with [qn q <> 0]
    ([rot_surjective], Shepperd's case split; the angle pi included:
    [q = (0, 1, 0, 0)] gives [diag(1, -1, -1)]).  So "for all q with |q|^2 <> 0,
    P(rot q)" is "for all rotations R, P(R)".  [rot_orthogonal] below proves the
    converse direction: every [rot q] is a rotation ([R^T R = I] and [det R = 1]).

    Unit vectors are vectors with the hypothesis [vdot u u = 1]; angles are reals
    and [cos], [sin] are the standard library's functions; lambda_min(A) is a real
    number with the hypothesis [lam_min_spec]: [sym A - lam I] is positive
    semidefinite, stated as a quadratic form. *)

From Coq Require Import Reals Lra Psatz.
Open Scope R_scope.

(** ** Vectors and matrices *)

Record V3 := mkV { v1 : R; v2 : R; v3 : R }.

Record M3 := mkM {
  m11 : R; m12 : R; m13 : R;
  m21 : R; m22 : R; m23 : R;
  m31 : R; m32 : R; m33 : R }.

Definition vadd (u v : V3) : V3 := mkV (v1 u + v1 v) (v2 u + v2 v) (v3 u + v3 v).
Definition vneg (u : V3) : V3 := mkV (- v1 u) (- v2 u) (- v3 u).
Definition vscale (c : R) (u : V3) : V3 := mkV (c * v1 u) (c * v2 u) (c * v3 u).
Definition vzero : V3 := mkV 0 0 0.
Definition vdot (u v : V3) : R := v1 u * v1 v + v2 u * v2 v + v3 u * v3 v.

Definition madd (A B : M3) : M3 :=
  mkM (m11 A + m11 B) (m12 A + m12 B) (m13 A + m13 B)
      (m21 A + m21 B) (m22 A + m22 B) (m23 A + m23 B)
      (m31 A + m31 B) (m32 A + m32 B) (m33 A + m33 B).

Definition mscale (c : R) (A : M3) : M3 :=
  mkM (c * m11 A) (c * m12 A) (c * m13 A)
      (c * m21 A) (c * m22 A) (c * m23 A)
      (c * m31 A) (c * m32 A) (c * m33 A).

Definition mneg (A : M3) : M3 := mscale (-1) A.
Definition msub (A B : M3) : M3 := madd A (mneg B).

(** Matrix product (row i of A times column j of B). *)
Definition mmul (A B : M3) : M3 :=
  mkM (m11 A * m11 B + m12 A * m21 B + m13 A * m31 B)
      (m11 A * m12 B + m12 A * m22 B + m13 A * m32 B)
      (m11 A * m13 B + m12 A * m23 B + m13 A * m33 B)
      (m21 A * m11 B + m22 A * m21 B + m23 A * m31 B)
      (m21 A * m12 B + m22 A * m22 B + m23 A * m32 B)
      (m21 A * m13 B + m22 A * m23 B + m23 A * m33 B)
      (m31 A * m11 B + m32 A * m21 B + m33 A * m31 B)
      (m31 A * m12 B + m32 A * m22 B + m33 A * m32 B)
      (m31 A * m13 B + m32 A * m23 B + m33 A * m33 B).

(** Matrix times vector. *)
Definition mvmul (A : M3) (u : V3) : V3 :=
  mkV (m11 A * v1 u + m12 A * v2 u + m13 A * v3 u)
      (m21 A * v1 u + m22 A * v2 u + m23 A * v3 u)
      (m31 A * v1 u + m32 A * v2 u + m33 A * v3 u).

Definition mT (A : M3) : M3 :=
  mkM (m11 A) (m21 A) (m31 A)
      (m12 A) (m22 A) (m32 A)
      (m13 A) (m23 A) (m33 A).

Definition I3 : M3 := mkM 1 0 0  0 1 0  0 0 1.
Definition Z3 : M3 := mkM 0 0 0  0 0 0  0 0 0.

Definition tr (A : M3) : R := m11 A + m22 A + m33 A.

(** [u v^T] *)
Definition outer (u v : V3) : M3 :=
  mkM (v1 u * v1 v) (v1 u * v2 v) (v1 u * v3 v)
      (v2 u * v1 v) (v2 u * v2 v) (v2 u * v3 v)
      (v3 u * v1 v) (v3 u * v2 v) (v3 u * v3 v).

(** A symmetric matrix from its six free entries (the chart of a symmetric variable). *)
Definition symm (a11 a22 a33 a12 a13 a23 : R) : M3 :=
  mkM a11 a12 a13  a12 a22 a23  a13 a23 a33.

(** ** The paper's operations (Section 3, Lemma 1, Theorem 1) *)

Definition sk (A : M3) : M3 := mscale (1/2) (msub A (mT A)).
Definition sym (A : M3) : M3 := mscale (1/2) (madd A (mT A)).

(** [hat v] is the matrix of the cross product: [mvmul (hat v) w = v x w]. *)
Definition hat (v : V3) : M3 :=
  mkM 0 (- v3 v) (v2 v)
      (v3 v) 0 (- v1 v)
      (- v2 v) (v1 v) 0.

(** [vee] of the skew part: [vee (hat v) = v], [vee A = vee (sk A)]. *)
Definition vee (A : M3) : V3 :=
  mkV ((m32 A - m23 A) / 2) ((m13 A - m31 A) / 2) ((m21 A - m12 A) / 2).

Definition phi (A : M3) : R := tr (msub I3 A) / 2.
Definition fro2 (A : M3) : R := tr (mmul (mT A) A).
Definition det (A : M3) : R :=
  m11 A * (m22 A * m33 A - m23 A * m32 A)
  - m12 A * (m21 A * m33 A - m23 A * m31 A)
  + m13 A * (m21 A * m32 A - m22 A * m31 A).

(** The rows of a matrix, as vectors. *)
Definition row1 (G : M3) : V3 := mkV (m11 G) (m12 G) (m13 G).
Definition row2 (G : M3) : V3 := mkV (m21 G) (m22 G) (m23 G).
Definition row3 (G : M3) : V3 := mkV (m31 G) (m32 G) (m33 G).

(** The quadratic form of [A] at [v]: [v^T A v]. *)
Definition qform (A : M3) (v : V3) : R := vdot v (mvmul A v).

(** ** Rotations by quaternions *)

Record quat := mkQ { qw : R; qx : R; qy : R; qz : R }.
Definition qvec (q : quat) : V3 := mkV (qx q) (qy q) (qz q).
Definition qn (q : quat) : R := qw q * qw q + qx q * qx q + qy q * qy q + qz q * qz q.

Definition rot (q : quat) : M3 :=
  madd I3 (mscale (2 / qn q)
                  (madd (mscale (qw q) (hat (qvec q))) (mmul (hat (qvec q)) (hat (qvec q))))).

(** ** Extensionality and the tactic that decides identities entry by entry *)

Lemma v3_ext : forall u v : V3,
  v1 u = v1 v -> v2 u = v2 v -> v3 u = v3 v -> u = v.
Proof. intros [] [] ; simpl; intros; subst; reflexivity. Qed.

Lemma m3_ext : forall A B : M3,
  m11 A = m11 B -> m12 A = m12 B -> m13 A = m13 B ->
  m21 A = m21 B -> m22 A = m22 B -> m23 A = m23 B ->
  m31 A = m31 B -> m32 A = m32 B -> m33 A = m33 B -> A = B.
Proof. intros [] [] ; simpl; intros; subst; reflexivity. Qed.

(** Unfold every definition of the prelude and reduce the record projections. *)
Ltac so3_unfold :=
  cbv beta iota zeta delta [rot qvec qn phi fro2 det sk sym hat vee symm outer tr I3 Z3
         mT mvmul mmul msub mneg mscale madd vdot vzero vscale vneg vadd row1 row2 row3 qform
         v1 v2 v3 m11 m12 m13 m21 m22 m23 m31 m32 m33 qw qx qy qz] in *.

(** An identity of polynomials with rational coefficients (no quaternion norm in a
    denominator): unfolded in the goal only, decided by [lra], for which every
    nonlinear monomial is an atom.  It is many times faster than [field] here. *)
Ltac so3_poly :=
  cbv beta iota zeta delta [rot qvec qn phi fro2 det sk sym hat vee symm outer tr I3 Z3
         mT mvmul mmul msub mneg mscale madd vdot vzero vscale vneg vadd row1 row2 row3 qform
         v1 v2 v3 m11 m12 m13 m21 m22 m23 m31 m32 m33 qw qx qy qz];
  lra.

(** Split a vector or matrix equation into its entries. *)
Ltac so3_split :=
  first [ apply m3_ext | apply v3_ext | idtac ].

(** Non-zero denominators of [field]: each is a product of quaternion norms. *)
Ltac so3_nonzero :=
  repeat split;
  repeat match goal with
  | |- _ * _ <> 0 => apply Rmult_integral_contrapositive_currified
  | |- _ ^ _ <> 0 => apply pow_nonzero
  end;
  try assumption; try lra.

(** From a cofactor identity [a - b = c * g] and [g = 0], conclude [a = b]. *)
Lemma eq_by_cofactors_1 : forall a b c1 g1 : R,
  g1 = 0 -> a - b = c1 * g1 -> a = b.
Proof. intros a b c1 g1 H1 E. rewrite H1 in E. lra. Qed.

Lemma eq_by_cofactors_2 : forall a b c1 g1 c2 g2 : R,
  g1 = 0 -> g2 = 0 -> a - b = c1 * g1 + c2 * g2 -> a = b.
Proof. intros a b c1 g1 c2 g2 H1 H2 E. rewrite H1, H2 in E. lra. Qed.

Lemma eq_by_cofactors_3 : forall a b c1 g1 c2 g2 c3 g3 : R,
  g1 = 0 -> g2 = 0 -> g3 = 0 -> a - b = c1 * g1 + c2 * g2 + c3 * g3 -> a = b.
Proof. intros a b c1 g1 c2 g2 c3 g3 H1 H2 H3 E. rewrite H1, H2, H3 in E. lra. Qed.

Lemma eq_by_cofactors_4 : forall a b c1 g1 c2 g2 c3 g3 c4 g4 : R,
  g1 = 0 -> g2 = 0 -> g3 = 0 -> g4 = 0 ->
  a - b = c1 * g1 + c2 * g2 + c3 * g3 + c4 * g4 -> a = b.
Proof.
  intros a b c1 g1 c2 g2 c3 g3 c4 g4 H1 H2 H3 H4 E. rewrite H1, H2, H3, H4 in E. lra.
Qed.

(** From [a - b = s] and [s = 0] (a sum of cofactors times vanishing generators). *)
Lemma eq_by_sum (a b s : R) : s = 0 -> a - b = s -> a = b.
Proof. intros H E. rewrite H in E. lra. Qed.

(** [sin^2 + cos^2 = 1] as a generator that vanishes. *)
Lemma circle (t : R) : cos t * cos t + sin t * sin t - 1 = 0.
Proof. pose proof (sin2_cos2 t) as H. unfold Rsqr in H. lra. Qed.

(** [rot q] is a rotation: orthogonal with determinant 1.  With [s = 2/|q|^2] and
    [K = hat(v)], [R = I + s (w K + K^2)]; as polynomials in [s] and [q] (no division),
    [R^T R = R R^T = I + s (2 - s |q|^2) K^2] and [det R - 1 = s |v|^2 (s |q|^2 - 2)],
    which [lra] checks entry by entry (monomials are its atoms); [s |q|^2 = 2] ends
    the proofs.  ([field] on the entries as rational functions costs many times more.) *)
Lemma rot_scale_norm (q : quat) : qn q <> 0 -> 2 / qn q * qn q = 2.
Proof. intro H. field. exact H. Qed.

(** R^T R and R R^T, with s = 2/|q|^2: both are I + s (2 - s |q|^2) hat(v)^2 entry by entry
    (a polynomial identity in s, by lra), and s |q|^2 = 2. *)
Ltac rot_orthogonal_by_scale q :=
  let H := fresh "H" in let Hs := fresh "Hs" in let s := fresh "s" in
  intro H; pose proof (rot_scale_norm q H) as Hs; unfold rot; revert Hs;
  generalize (2 / qn q); intros s Hs; destruct q as [w x y z];
  transitivity (madd I3 (mscale (s * (2 - s * qn (mkQ w x y z)))
                               (mmul (hat (qvec (mkQ w x y z))) (hat (qvec (mkQ w x y z))))));
  [ so3_split; so3_unfold; lra
  | replace (s * (2 - s * qn (mkQ w x y z))) with 0 by (rewrite Hs; ring);
    so3_split; so3_unfold; lra ].

Lemma rot_orthogonal (q : quat) : qn q <> 0 -> mmul (mT (rot q)) (rot q) = I3.
Proof. rot_orthogonal_by_scale q. Qed.

Lemma rot_orthogonal_r (q : quat) : qn q <> 0 -> mmul (rot q) (mT (rot q)) = I3.
Proof. rot_orthogonal_by_scale q. Qed.

Lemma rot_det (q : quat) : qn q <> 0 -> det (rot q) = 1.
Proof.
  intro H. pose proof (rot_scale_norm q H) as Hs. unfold rot. revert Hs.
  generalize (2 / qn q); intros s Hs. destruct q as [w x y z].
  apply (eq_by_cofactors_1 _ _ (s * (x * x + y * y + z * z)) (s * qn (mkQ w x y z) - 2)).
  - lra.
  - so3_unfold. lra.
Qed.

(** ** Matrix-level normal form (rewriting before going to entries)

    An identity between expressions in rotations often holds only because some
    rotation meets its transpose ([R^T R = I]).  Proving it entry by entry in quaternion
    coordinates makes [field] expand rational functions of high degree.  Instead the
    goal is first rewritten at matrix level: [sk], [sym], [msub], [mneg] unfolded into
    [madd] and [mscale] (by [unfold]: as rewriting rules their left sides would match
    their own results up to unfolding), transposes pushed down to the leaves, products distributed
    over sums, scalars pulled out, products associated to the right, and every
    adjacent [R^T R] or [R R^T] of a rotation cancelled; rotations are taken out of
    [hat] ([hat (R u) = R hat(u) R^T]).  What is left usually holds for any matrix in place of each
    rotation, and [field] decides it on small polynomials.  The lemmas below are
    general facts on free 3x3 matrices, proved once; only the [rot_*] ones use that
    [rot q] is a rotation, with the hypothesis [qn q <> 0]. *)

Lemma vneg_unfold (u : V3) : vneg u = vscale (-1) u.
Proof. destruct u. apply v3_ext; simpl; ring. Qed.

Lemma mT_madd (A B : M3) : mT (madd A B) = madd (mT A) (mT B).
Proof. reflexivity. Qed.

Lemma mT_mscale (c : R) (A : M3) : mT (mscale c A) = mscale c (mT A).
Proof. reflexivity. Qed.

Lemma mT_mmul (A B : M3) : mT (mmul A B) = mmul (mT B) (mT A).
Proof. destruct A, B. so3_split; so3_unfold; lra. Qed.

Lemma mT_mT (A : M3) : mT (mT A) = A.
Proof. destruct A. reflexivity. Qed.

Lemma mT_I3 : mT I3 = I3.
Proof. reflexivity. Qed.

Lemma mT_hat (v : V3) : mT (hat v) = mscale (-1) (hat v).
Proof. destruct v. so3_split; so3_unfold; lra. Qed.

Lemma mscale_mscale (a b : R) (A : M3) : mscale a (mscale b A) = mscale (a * b) A.
Proof. destruct A. so3_split; so3_unfold; lra. Qed.

Lemma vscale_vscale (a b : R) (u : V3) : vscale a (vscale b u) = vscale (a * b) u.
Proof. destruct u. so3_split; so3_unfold; lra. Qed.

Lemma mmul_madd_l (A B C : M3) : mmul (madd A B) C = madd (mmul A C) (mmul B C).
Proof. destruct A, B, C. so3_split; so3_unfold; lra. Qed.

Lemma mmul_madd_r (A B C : M3) : mmul A (madd B C) = madd (mmul A B) (mmul A C).
Proof. destruct A, B, C. so3_split; so3_unfold; lra. Qed.

Lemma mmul_mscale_l (c : R) (A B : M3) : mmul (mscale c A) B = mscale c (mmul A B).
Proof. destruct A, B. so3_split; so3_unfold; lra. Qed.

Lemma mmul_mscale_r (c : R) (A B : M3) : mmul A (mscale c B) = mscale c (mmul A B).
Proof. destruct A, B. so3_split; so3_unfold; lra. Qed.

Lemma mmul_assoc (A B C : M3) : mmul (mmul A B) C = mmul A (mmul B C).
Proof. destruct A, B, C. so3_split; so3_unfold; lra. Qed.

Lemma mmul_I3_l (A : M3) : mmul I3 A = A.
Proof. destruct A. so3_split; so3_unfold; lra. Qed.

Lemma mmul_I3_r (A : M3) : mmul A I3 = A.
Proof. destruct A. so3_split; so3_unfold; lra. Qed.

Lemma mvmul_mmul (A B : M3) (u : V3) : mvmul (mmul A B) u = mvmul A (mvmul B u).
Proof. destruct A, B, u. so3_split; so3_unfold; lra. Qed.

Lemma mvmul_madd (A B : M3) (u : V3) : mvmul (madd A B) u = vadd (mvmul A u) (mvmul B u).
Proof. destruct A, B, u. so3_split; so3_unfold; lra. Qed.

Lemma mvmul_vadd (A : M3) (u v : V3) : mvmul A (vadd u v) = vadd (mvmul A u) (mvmul A v).
Proof. destruct A, u, v. so3_split; so3_unfold; lra. Qed.

Lemma mvmul_mscale (c : R) (A : M3) (u : V3) : mvmul (mscale c A) u = vscale c (mvmul A u).
Proof. destruct A, u. so3_split; so3_unfold; lra. Qed.

Lemma mvmul_vscale (c : R) (A : M3) (u : V3) : mvmul A (vscale c u) = vscale c (mvmul A u).
Proof. destruct A, u. so3_split; so3_unfold; lra. Qed.

Lemma mvmul_I3 (u : V3) : mvmul I3 u = u.
Proof. destruct u. so3_split; so3_unfold; lra. Qed.

(** The rotation facts of the normal form: [R^T R = R R^T = I] (in a product). *)
Lemma rot_cancel_l (q : quat) : qn q <> 0 -> forall A : M3, mmul (mT (rot q)) (mmul (rot q) A) = A.
Proof. intros H A. rewrite <- mmul_assoc, (rot_orthogonal q H). apply mmul_I3_l. Qed.

Lemma rot_cancel_r (q : quat) : qn q <> 0 -> forall A : M3, mmul (rot q) (mmul (mT (rot q)) A) = A.
Proof. intros H A. rewrite <- mmul_assoc, (rot_orthogonal_r q H). apply mmul_I3_l. Qed.

Lemma rot_vcancel_l (q : quat) : qn q <> 0 -> forall u : V3, mvmul (mT (rot q)) (mvmul (rot q) u) = u.
Proof. intros H u. rewrite <- mvmul_mmul, (rot_orthogonal q H). apply mvmul_I3. Qed.

Lemma rot_vcancel_r (q : quat) : qn q <> 0 -> forall u : V3, mvmul (rot q) (mvmul (mT (rot q)) u) = u.
Proof. intros H u. rewrite <- mvmul_mmul, (rot_orthogonal_r q H). apply mvmul_I3. Qed.

(** [hat] is linear, [hat (vee A) = sk A], and [hat (R u) = R hat(u) R^T] for a
    rotation [R] (this needs [det R = 1]): the normal form takes rotations out of
    [hat], so that they can meet their transposes. *)
Lemma hat_vadd (u v : V3) : hat (vadd u v) = madd (hat u) (hat v).
Proof. destruct u, v. so3_split; so3_unfold; lra. Qed.

Lemma hat_vscale (c : R) (u : V3) : hat (vscale c u) = mscale c (hat u).
Proof. destruct u. so3_split; so3_unfold; lra. Qed.

Lemma hat_vee (A : M3) : hat (vee A) = mscale (1/2) (madd A (mscale (-1) (mT A))).
Proof. destruct A. so3_split; so3_unfold; field. Qed.

(** [vee(A) . v = -tr(A hat(v))/2]: a dot product with a [vee] becomes a trace, where
    the rotations of [v] come out of the [hat]. *)
Lemma vdot_vee_l (A : M3) (v : V3) : vdot (vee A) v = (-1/2) * tr (mmul A (hat v)).
Proof. destruct A, v. so3_unfold. field. Qed.

Lemma vdot_vee_r (A : M3) (u : V3) : vdot u (vee A) = (-1/2) * tr (mmul A (hat u)).
Proof. destruct A, u. so3_unfold. field. Qed.

(** For any matrix [M]: [M^T hat(M u) M = det(M) hat(u)] (a polynomial identity). *)
Lemma hat_adj (M : M3) (u : V3) :
  mmul (mT M) (mmul (hat (mvmul M u)) M) = mscale (det M) (hat u).
Proof. destruct M, u. so3_split; so3_unfold; lra. Qed.

Lemma rot_hat (q : quat) : qn q <> 0 -> forall u : V3,
  hat (mvmul (rot q) u) = mmul (rot q) (mmul (hat u) (mT (rot q))).
Proof.
  intros H u.
  assert (E : mmul (mT (rot q)) (mmul (hat (mvmul (rot q) u)) (rot q)) = hat u).
  { rewrite hat_adj, (rot_det q H). destruct u. so3_split; so3_unfold; lra. }
  rewrite <- E, !mmul_assoc, (rot_orthogonal_r q H), mmul_I3_r, (rot_cancel_r q H).
  reflexivity.
Qed.

Lemma rot_hat_T (q : quat) : qn q <> 0 -> forall u : V3,
  hat (mvmul (mT (rot q)) u) = mmul (mT (rot q)) (mmul (hat u) (rot q)).
Proof.
  intros H u. set (v := mvmul (mT (rot q)) u).
  assert (E : hat u = mmul (rot q) (mmul (hat v) (mT (rot q)))).
  { rewrite <- (rot_hat q H v). unfold v. rewrite (rot_vcancel_r q H u). reflexivity. }
  rewrite E, !mmul_assoc, (rot_cancel_l q H), (rot_orthogonal q H), mmul_I3_r.
  reflexivity.
Qed.

#[export] Hint Rewrite vneg_unfold
  mT_madd mT_mscale mT_mmul mT_mT mT_I3 mT_hat mscale_mscale vscale_vscale
  mmul_madd_l mmul_madd_r mmul_mscale_l mmul_mscale_r mmul_assoc mmul_I3_l mmul_I3_r
  mvmul_mmul mvmul_madd mvmul_vadd mvmul_mscale mvmul_vscale mvmul_I3 hat_vadd hat_vscale hat_vee
  vdot_vee_l vdot_vee_r
  : so3_norm.
#[export] Hint Rewrite rot_cancel_l rot_cancel_r rot_vcancel_l rot_vcancel_r
  rot_orthogonal rot_orthogonal_r using assumption : so3_norm.
#[export] Hint Rewrite rot_hat rot_hat_T using assumption : so3_hat.

(** The normal form of the goal; [so3_norm_hat] also takes rotations out of [hat]
    (which helps when a rotation inside a [hat] meets its transpose outside, and
    hinders when a trace would have to be turned cyclically to see a cancellation). *)
Ltac so3_norm := unfold sk, sym, msub, mneg; autorewrite with so3_norm.
Ltac so3_norm_hat := unfold sk, sym, msub, mneg; autorewrite with so3_norm so3_hat.

(** ** Non-negative quantities (the kernel facts of [verify.proof.justify]) *)

Lemma sq_nonneg (x : R) : 0 <= x * x.
Proof. nra. Qed.

Lemma vdot_self_nonneg (u : V3) : 0 <= vdot u u.
Proof. destruct u. unfold vdot; simpl. nra. Qed.

Lemma fro2_nonneg (A : M3) : 0 <= fro2 A.
Proof. destruct A. so3_unfold. nra. Qed.

(** [tr(A G^T G)] is the sum of the quadratic forms of [A] at the rows of [G]. *)
Lemma trace_gram_rows (A G : M3) :
  tr (mmul A (mmul (mT G) G)) = qform A (row1 G) + qform A (row2 G) + qform A (row3 G).
Proof. destruct A, G. unfold qform, row1, row2, row3. so3_unfold. ring. Qed.

(** A symmetric matrix is its own symmetric part. *)
Lemma sym_of_symmetric (A : M3) : mT A = A -> sym A = A.
Proof. intro H. unfold sym. rewrite H. destruct A. so3_split; so3_unfold; field. Qed.

(** For symmetric [A]: [tr(A B) = tr(A sym(B))]. *)
Lemma trace_sym_right (A B : M3) : mT A = A -> tr (mmul A B) = tr (mmul A (sym B)).
Proof.
  intro H. destruct A, B. unfold mT in H. injection H; intros.
  so3_unfold. subst. field.
Qed.

(** [lam] is at most the smallest eigenvalue of [sym A] (the proof language's
    spectral fact for lambda_min(A)): [sym A - lam I] is positive semidefinite. *)
Definition lam_min_spec (A : M3) (lam : R) : Prop :=
  forall v : V3, 0 <= qform (msub (sym A) (mscale lam I3)) v.

(** [A] is positive semidefinite / definite as a quadratic form of its symmetric part. *)
Definition psd (A : M3) : Prop := forall v : V3, 0 <= qform (sym A) v.
Definition pd (A : M3) : Prop := forall v : V3, v <> vzero -> 0 < qform (sym A) v.

(** The trace inequality with its premise (Lemma 1, repaired):
    for symmetric [A] and [sym B = c G^T G] with [c >= 0],
    [tr(A B) - lam tr(B) >= 0] whenever [sym A - lam I] is PSD. *)
Lemma trace_lower_bound (A B G : M3) (c lam : R) :
  mT A = A -> sym B = mscale c (mmul (mT G) G) -> 0 <= c -> lam_min_spec A lam ->
  0 <= tr (mmul A B) - lam * tr B.
Proof.
  intros HA HB Hc Hl.
  assert (E : tr (mmul A B) - lam * tr B
              = c * tr (mmul (msub (sym A) (mscale lam I3)) (mmul (mT G) G))).
  { rewrite (trace_sym_right A B HA).
    assert (Hs : sym A = A) by (apply sym_of_symmetric; exact HA).
    assert (Et : tr B = tr (sym B)) by (destruct B; so3_unfold; field).
    rewrite Et, HB, Hs. destruct A, G. so3_unfold. ring. }
  rewrite E, trace_gram_rows.
  apply Rmult_le_pos; [exact Hc |].
  pose proof (Hl (row1 G)). pose proof (Hl (row2 G)). pose proof (Hl (row3 G)). lra.
Qed.

(** [tr(A B) >= 0] for [A] symmetric PSD and [sym B = c G^T G], [c >= 0]. *)
Lemma trace_psd_product (A B G : M3) (c : R) :
  mT A = A -> psd A -> sym B = mscale c (mmul (mT G) G) -> 0 <= c ->
  0 <= tr (mmul A B).
Proof.
  intros HA Hp HB Hc.
  assert (Hs : sym A = A) by (apply sym_of_symmetric; exact HA).
  rewrite (trace_sym_right A B HA), HB.
  assert (E : tr (mmul A (mscale c (mmul (mT G) G))) = c * tr (mmul A (mmul (mT G) G)))
    by (destruct A, G; so3_unfold; ring).
  rewrite E, trace_gram_rows.
  apply Rmult_le_pos; [exact Hc |].
  pose proof (Hp (row1 G)). pose proof (Hp (row2 G)). pose proof (Hp (row3 G)).
  rewrite Hs in *. lra.
Qed.

(** A positive definite matrix is positive semidefinite. *)
Lemma pd_psd (A : M3) : pd A -> psd A.
Proof.
  intros H v.
  destruct (Req_dec (v1 v) 0), (Req_dec (v2 v) 0), (Req_dec (v3 v) 0);
  try (apply Rlt_le, H; intro E; rewrite E in *; simpl in *; lra).
  destruct v; simpl in *; subst. unfold qform. so3_unfold. lra.
Qed.

(** [tr(A B) >= 0] for [A = sym X] with [X] assumed positive (semi)definite. *)
Lemma trace_pd_product (A X B G : M3) (c : R) :
  mT A = A -> A = sym X -> pd X -> sym B = mscale c (mmul (mT G) G) -> 0 <= c ->
  0 <= tr (mmul A B).
Proof.
  intros HA HX Hp HB Hc. apply (trace_psd_product A B G c HA); [| exact HB | exact Hc].
  intro v. rewrite (sym_of_symmetric A HA), HX. apply pd_psd. exact Hp.
Qed.

Lemma trace_psd_assumed_product (A X B G : M3) (c : R) :
  mT A = A -> A = sym X -> psd X -> sym B = mscale c (mmul (mT G) G) -> 0 <= c ->
  0 <= tr (mmul A B).
Proof.
  intros HA HX Hp HB Hc. apply (trace_psd_product A B G c HA); [| exact HB | exact Hc].
  intro v. rewrite (sym_of_symmetric A HA), HX. apply Hp.
Qed.

(** An inequality from its slack written as a sum of non-negative terms. *)
Lemma le_by_slack (a b s : R) : b + - a = s -> 0 <= s -> a <= b.
Proof. intros E H. lra. Qed.

Lemma ge_by_slack (a b s : R) : a + - b = s -> 0 <= s -> a >= b.
Proof. intros E H. lra. Qed.

(** Chaining the steps of a derivation into its claim. *)
Lemma eq_le_trans (a b c : R) : a = b -> b <= c -> a <= c.
Proof. intros -> H. exact H. Qed.

Lemma le_eq_trans (a b c : R) : a <= b -> b = c -> a <= c.
Proof. intros H <-. exact H. Qed.

Lemma eq_ge_trans (a b c : R) : a = b -> b >= c -> a >= c.
Proof. intros -> H. exact H. Qed.

Lemma ge_eq_trans (a b c : R) : a >= b -> b = c -> a >= c.
Proof. intros H <-. exact H. Qed.
