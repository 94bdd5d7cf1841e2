(** Exact-band certificate reconstructed-k_s-2.5-band-0-1.5-f0739b7ae628.json: exported by verify; checked by coqc.
    Model: reconstructed k_s = 2.5
    Source file: ../verify/data/models/reconstructed_ks2p5.toml
    Fingerprint (sha256 of the exact A, B, C, D): f0739b7ae628a192db3b213a05f7ac7f6403c55126008a80f1164da6071094aa
    Claim: H(jw) + H(jw)^H >= 0 for 0 <= w <= 3/2 rad/s wherever H(jw) is
    defined ([band_passive] in BandCert.v): Coq computes d(s) = det(sI - A) and Adj(s),
    checks (sI - A) Adj(s) = d(s) I, and states Re z^H (H(jw) + H(jw)^H) z >= 0 for H(jw) =
    N(jw) / d(jw), N(s) = C Adj(s) B + d(s) D.  Trusted, not proved here: that this H(jw) is
    C (jwI - A)^-1 B + D (a matrix inverse from the checked identity).
    The witnesses: for each sign polynomial p of the Hermitian numerator (BandCert.v),
    p = g^2 q and q = sum c (x - u)^i (v - x)^j with c >= 0 on each piece [u, v] of the band. *)

From Coq Require Import QArith List.
From VerifyCoq Require Import QCert BandCert.
Import ListNotations.
Local Open Scope Q_scope.

(** The model: 4 states, 2 port(s); x' = A x + B u, y = C x + D u. *)
Definition A : matQ :=
  [[(0 # 1); (1 # 1); (0 # 1); (0 # 1)];
   [(-2 # 1); (-1 # 1); (0 # 1); (0 # 1)];
   [(0 # 1); (0 # 1); (0 # 1); (1 # 1)];
   [(0 # 1); (0 # 1); (-2 # 1); (-1 # 1)]].
Definition B : matQ :=
  [[(0 # 1); (0 # 1)];
   [(1 # 1); (0 # 1)];
   [(0 # 1); (0 # 1)];
   [(0 # 1); (1 # 1)]].
Definition C : matQ :=
  [[(2 # 2); (1 # 2); (0 # 2); (0 # 2)];
   [(0 # 2); (0 # 2); (2 # 2); (1 # 2)]].
Definition D : matQ :=
  [[(0 # 20); (1 # 20)];
   [(-1 # 20); (0 # 20)]].
Definition w1 : Q := (0 # 1).
Definition w2 : Q := (3 # 2).

(** Witnesses (data Coq re-checks), one per sign polynomial: (g, q, pieces). *)
Definition cert1 : nonneg_cert :=
  ([(1 # 1)],
   [(32 # 1); (0 # 1); (-32 # 1); (0 # 1); (14 # 1); (0 # 1); (-2 # 1)],
   [((0 # 1), (3 # 2),
     [((2048 # 729), 0%nat, 6%nat); ((4096 # 243), 1%nat, 5%nat); ((8704 # 243), 2%nat, 4%nat); ((22528 # 729), 3%nat, 3%nat); ((2536 # 243), 4%nat, 2%nat); ((976 # 243), 5%nat, 1%nat); ((518 # 729), 6%nat, 0%nat)])]).
Definition cert2 : nonneg_cert :=
  ([(-16 # 1); (0 # 1); (16 # 1); (0 # 1); (-7 # 1); (0 # 1); (1 # 1)],
   [(1 # 1)],
   [((0 # 1), (3 # 2),
     [((1 # 1), 0%nat, 0%nat)])]).
Definition certs : list nonneg_cert := [cert1; cert2].

Theorem passive_on_band : band_passive 4 2 A B C D w1 w2.
Proof.
  apply (band_check_sound 4 2 A B C D w1 w2 certs).
  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)
Qed.
