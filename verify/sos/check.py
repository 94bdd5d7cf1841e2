"""Trusted exact check of an SOS certificate: the identity, then every Gram PSD.

Given the target p, blocks (multiplier H_k, basis z_k) and rational Gram matrices Q_k:

1. every Q_k is square of the block's size and symmetric;
2. p == sum_k sum_{r,s} (Q_k)_rs (H_k)_{i(r) i(s)} z_{a(r)} z_{a(s)} as polynomials with
   rational coefficients (:func:`verify.sos.program.expand`), exactly;
3. every Q_k is PSD, decided exactly (:func:`verify.passivity.check.psd.psd_exact`: a
   dominance certificate over the integers, else a fraction-free LDL^T with zero pivots
   on the integer numerators).

That p >= 0 then follows from each H_k being PSD on R^n, which is the caller's to
establish (the grounds of each multiplier are re-derived from the claim, see
:mod:`verify.proof.sos_step`). No floating point decides anything here.
"""

from __future__ import annotations

from dataclasses import dataclass

from verify.passivity.check.psd import psd_exact
from verify.sos import poly as pl
from verify.sos.program import Block, expand


@dataclass(frozen=True)
class SosCheck:
    ok: bool
    reason: str


def check_identity_and_psd(target: pl.Poly, blocks, grams) -> SosCheck:
    if len(blocks) != len(grams):
        return SosCheck(False, "one Gram matrix per block is needed")
    total: pl.Poly = {}
    for k, (b, q) in enumerate(zip(blocks, grams, strict=True)):
        if not isinstance(b, Block):
            return SosCheck(False, f"block {k} is malformed")
        h = b.multiplier.matrix
        if any(len(row) != len(h) for row in h) or any(
                h[i][j] != h[j][i] for i in range(len(h)) for j in range(i)):
            return SosCheck(False, f"block {k}: multiplier is not a symmetric matrix")
        n = b.gram_size
        if len(q) != n or any(len(row) != n for row in q):
            return SosCheck(False, f"block {k}: Gram matrix must be {n} x {n}")
        if any(q[r][s] != q[s][r] for r in range(n) for s in range(r)):
            return SosCheck(False, f"block {k}: Gram matrix is not symmetric")
        total = pl.add(total, expand(b, q))
    difference = pl.add(target, pl.scale(-1, total))
    if difference:
        return SosCheck(False, f"the identity fails in {len(difference)} coefficient(s)")
    for k, (b, q) in enumerate(zip(blocks, grams, strict=True)):
        if not q:
            continue
        result = psd_exact(q)
        if not result.ok:
            return SosCheck(False, f"block {k} ({b.multiplier.grounds}): Gram matrix is not "
                                   f"PSD ({result.reason})")
    sizes = "+".join(str(b.gram_size) for b in blocks)
    return SosCheck(True, f"exact identity with {len(blocks)} PSD Gram block(s) of size {sizes}")
