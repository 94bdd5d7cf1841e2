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
Import Uint63.
Local Open Scope Q_scope.
Local Open Scope uint63_scope.

(** The model: 4 states, 2 ports; x' = A x + B u, y = C x + D u.
    A, B, C (and P below) are data on machine words ([qmatw] in QCert.v): two
    denominators, then each entry's numerator, (Wp k) = k, (Wn k) = -k, and
    (Wl neg second [k0; k1; ...]) = +-(k0 + 2^62 k1 + ...) over the second
    denominator when second = true, else over the first. *)
Definition WA : wmat :=
  (2%positive, 1%positive,
   [[(Wp 0); (Wp 2); (Wp 0); (Wp 0)];
   [(Wn 3); (Wn 4); (Wp 0); (Wp 0)];
   [(Wp 0); (Wp 0); (Wp 0); (Wp 2)];
   [(Wp 0); (Wp 0); (Wn 3); (Wn 4)]]).
Definition A : matQ := qmatw WA.
Definition WB : wmat :=
  (1%positive, 1%positive,
   [[(Wp 0); (Wp 0)];
   [(Wp 1); (Wp 0)];
   [(Wp 0); (Wp 0)];
   [(Wp 0); (Wp 1)]]).
Definition B : matQ := qmatw WB.
Definition WC : wmat :=
  (5%positive, 1%positive,
   [[(Wp 4); (Wp 6); (Wp 0); (Wp 0)];
   [(Wp 0); (Wp 0); (Wp 4); (Wp 6)]]).
Definition C : matQ := qmatw WC.
Definition D : matQ :=
  [[(0 # 20); (1 # 20)];
   [(-1 # 20); (0 # 20)]].
(** D times dD, as integers (Coq checks that they are). *)
Definition dD : positive := 20%positive.
Definition WD : list (list wnum) :=
  [[(Wp 0); (Wp 1)];
   [(Wn 1); (Wp 0)]].

(** The certificate. *)
Definition WP : wmat :=
  (160%positive, 1%positive,
   [[(Wp 545); (Wp 128); (Wp 0); (Wp 0)];
   [(Wp 128); (Wp 192); (Wp 0); (Wp 0)];
   [(Wp 0); (Wp 0); (Wp 545); (Wp 128)];
   [(Wp 0); (Wp 0); (Wp 128); (Wp 192)]]).
Definition P : matQ := qmatw WP.

(** Witnesses (data Coq re-checks) on the integer matrices s P and L M(P), where
    Coq computes both from the data: (e, den, [w_k], [u_k]) such that
    den X - e I - sum_k w_k u_k u_k^T is diagonally dominant
    (P: exact LDLᵀ; -M(P): exact LDLᵀ). *)
Definition wP : wwit :=
  ((Wp 10500), (Wp 525), (Wp 1),
   [(Wp 1); (Wp 73916); (Wp 1); (Wp 73916)],
   [[(Wp 525); (Wp 128); (Wp 0); (Wp 0)];
   [(Wp 0); (Wp 1); (Wp 0); (Wp 0)];
   [(Wp 0); (Wp 0); (Wp 525); (Wp 128)];
   [(Wp 0); (Wp 0); (Wp 0); (Wp 1)]]).
Definition wM : wwit :=
  ((Wp 0), (Wp 48), (Wp 25),
   [(Wp 1); (Wp 196607); (Wp 1); (Wp 196607)],
   [[(Wp 384); (Wn 1); (Wp 0); (Wp 0); (Wp 0); (Wp 0)];
   [(Wp 0); (Wp 1); (Wp 0); (Wp 0); (Wp 0); (Wp 0)];
   [(Wp 0); (Wp 0); (Wp 384); (Wn 1); (Wp 0); (Wp 0)];
   [(Wp 0); (Wp 0); (Wp 0); (Wp 1); (Wp 0); (Wp 0)]]).

Theorem passive : kyp_certified 4 2 A B C D P.
Proof.
  apply (kyp_wcheck_sound 4 2 WA WB WC D dD WD WP wP wM).
  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)
Qed.
