"""From a floating-point Gram solution to an exact rational one (Peyrl & Parrilo 2008).

1. Round every Gram entry to a rational with a bounded denominator (continued
   fractions). When the exact solution is simple, this often lands on it exactly.
2. Correct exactly: the rounded Grams miss the target's coefficients by a small
   residual r. Solve A dx = r exactly (sparse elimination over the rationals, pivots on
   diagonal Gram entries first, other unknowns left as rounded), so that the corrected
   Grams satisfy p = sum <Q_k, H_k (x) z_k z_k^T> *exactly*. Peyrl and Parrilo project
   orthogonally; any exact point of the affine space will do, and the correction is of
   the order of the rounding error, which the PSD margin of an interior solution absorbs.
3. The trusted check (:mod:`verify.sos.check`) decides; a failed attempt tries a finer
   denominator. Floating point only proposes; the exact check disposes.
"""

from __future__ import annotations

import heapq
from fractions import Fraction

import numpy as np
from gmpy2 import mpq

from verify.sos import poly as pl
from verify.sos.program import Block, expand

DENOMINATORS = (1, 12, 360, 10**4, 10**6, 2**30)


def _round(x: float, bound: int) -> mpq:
    f = Fraction(float(x)).limit_denominator(bound)
    return mpq(f.numerator, f.denominator)


def round_grams(grams: list[np.ndarray], bound: int) -> list[list[list[mpq]]]:
    out = []
    for g in grams:
        n = g.shape[0]
        q = [[mpq(0)] * n for _ in range(n)]
        for r in range(n):
            for s in range(r, n):
                q[r][s] = q[s][r] = _round(g[r, s], bound)
        out.append(q)
    return out


def _columns(blocks: list[Block]):
    """Unknowns (block, r, s), r <= s, diagonal ones first; rows per monomial."""
    cols: list[tuple[int, int, int]] = []
    for k, b in enumerate(blocks):
        cols += [(k, r, r) for r in range(b.gram_size)]
    for k, b in enumerate(blocks):
        cols += [(k, r, s) for r in range(b.gram_size) for s in range(r + 1, b.gram_size)]
    rows: dict[pl.Monomial, dict[int, mpq]] = {}
    for c, (k, r, s) in enumerate(cols):
        w = 1 if r == s else 2
        for m, v in blocks[k].entry_polynomial(r, s).items():
            rows.setdefault(m, {})[c] = rows.get(m, {}).get(c, 0) + w * v
    return cols, rows


def correct(blocks: list[Block], grams, target: pl.Poly, structure=None):
    """Exactly corrected copies of ``grams`` (None when the residual is out of reach)."""
    cols, rows = structure or _columns(blocks)
    total = pl.add(*(expand(b, q) for b, q in zip(blocks, grams, strict=True)))
    residual = pl.add(target, pl.scale(-1, total))
    if not residual:
        return grams
    pivots: list[tuple[int, dict[int, mpq], mpq]] = []
    pivot_of: dict[int, int] = {}
    for m in sorted(set(rows) | set(residual)):
        row = dict(rows.get(m, {}))
        rhs = residual.get(m, mpq(0))
        # eliminate earlier pivots in creation order: pivot row i only holds pivots > i
        queue = sorted(pivot_of[c] for c in row if c in pivot_of)
        heapq.heapify(queue)
        done: set[int] = set()
        while queue:
            i = heapq.heappop(queue)
            pc, prow, prhs = pivots[i]
            if i in done or pc not in row:
                continue
            done.add(i)
            f = row[pc]
            for j, v in prow.items():
                nv = row.get(j, 0) - f * v
                if nv:
                    if j not in row and j in pivot_of:
                        heapq.heappush(queue, pivot_of[j])
                    row[j] = nv
                else:
                    row.pop(j, None)
            rhs -= f * prhs
        row = {j: v for j, v in row.items() if v}
        if not row:
            if rhs:
                return None
            continue
        pc = min(row)
        f = row[pc]
        row = {j: v / f for j, v in row.items()}
        pivot_of[pc] = len(pivots)
        pivots.append((pc, row, rhs / f))
    dx: dict[int, mpq] = {}
    for pc, row, rhs in reversed(pivots):
        dx[pc] = rhs - sum((v * dx.get(j, 0) for j, v in row.items() if j != pc), mpq(0))
    out = [[list(r) for r in q] for q in grams]
    for c, v in dx.items():
        k, r, s = cols[c]
        out[k][r][s] += v
        if r != s:
            out[k][s][r] += v
    return out
