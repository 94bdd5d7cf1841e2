(** KYP certificate reconstructed-k_s-3.0-99babda880e6.json: exported by verify; checked by coqc.
    Model: reconstructed k_s = 3.0
    Source file: verify/data/models/reconstructed_ks3p0.toml
    Fingerprint (sha256 of the exact A, B, C, D): 99babda880e694ef995d0c7ea536c7385aff424110cd10f829a99cc382daffe8
    Claim: H is passive, in the LMI form of the KYP lemma: P = P^T, P > 0 and
    M(P) = [[A^T P + P A, P B - C^T], [B^T P - C, -(D + D^T)]] <= 0,
    both as real quadratic forms ([kyp_certified] in QCert.v). *)

From Coq Require Import QArith List.
From VerifyCoq Require Import QCert.
Import ListNotations.
Local Open Scope Q_scope.

(** The model: 4 states, 2 ports; x' = A x + B u, y = C x + D u.
    Each matrix is written over one common denominator ((2 # 2) is 1, (0 # 2) is 0).
    *)
Definition A : matQ :=
  [[(0 # 2); (2 # 2); (0 # 2); (0 # 2)];
   [(-3 # 2); (-4 # 2); (0 # 2); (0 # 2)];
   [(0 # 2); (0 # 2); (0 # 2); (2 # 2)];
   [(0 # 2); (0 # 2); (-3 # 2); (-4 # 2)]].
Definition B : matQ :=
  [[(0 # 1); (0 # 1)];
   [(1 # 1); (0 # 1)];
   [(0 # 1); (0 # 1)];
   [(0 # 1); (1 # 1)]].
Definition C : matQ :=
  [[(4 # 5); (6 # 5); (0 # 5); (0 # 5)];
   [(0 # 5); (0 # 5); (4 # 5); (6 # 5)]].
Definition D : matQ :=
  [[(0 # 20); (1 # 20)];
   [(-1 # 20); (0 # 20)]].

(** The certificate. *)
Definition P : matQ :=
  [[(545 # 160); (128 # 160); (0 # 160); (0 # 160)];
   [(128 # 160); (192 # 160); (0 # 160); (0 # 160)];
   [(0 # 160); (0 # 160); (545 # 160); (128 # 160)];
   [(0 # 160); (0 # 160); (128 # 160); (192 # 160)]].

(** Witnesses (data Coq re-checks): P - eP I = sum of wP terms + a dominant residual (exact LDLᵀ);
    -M(P) - eM I likewise (exact LDLᵀ). *)
Definition eP : Q := (1 # 8).
Definition wP : list term :=
  [((275625 # 84000), [(525 # 525); (128 # 525); (0 # 525); (0 # 525)]);
   ((73916 # 84000), [(0 # 525); (525 # 525); (0 # 525); (0 # 525)]);
   ((275625 # 84000), [(0 # 525); (0 # 525); (525 # 525); (128 # 525)]);
   ((73916 # 84000), [(0 # 525); (0 # 525); (0 # 525); (525 # 525)])].
Definition eM : Q := (0 # 1).
Definition wM : list term :=
  [((147456 # 61440), [(384 # 384); (-1 # 384); (0 # 384); (0 # 384); (0 # 384); (0 # 384)]);
   ((196607 # 61440), [(0 # 384); (384 # 384); (0 # 384); (0 # 384); (0 # 384); (0 # 384)]);
   ((147456 # 61440), [(0 # 384); (0 # 384); (384 # 384); (-1 # 384); (0 # 384); (0 # 384)]);
   ((196607 # 61440), [(0 # 384); (0 # 384); (0 # 384); (384 # 384); (0 # 384); (0 # 384)])].

Theorem passive : kyp_certified 4 2 A B C D P.
Proof.
  apply (kyp_check_sound 4 2 A B C D P eP wP eM wM).
  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)
Qed.
