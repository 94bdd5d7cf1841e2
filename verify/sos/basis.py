"""Monomial bases for the Gram blocks (untrusted: any basis is sound, a good one is small).

For a block with multiplier H and basis z, every term of H z z^T must fit the target's
support if no cancellation is needed. We keep the monomials m with, per variable v,
2 m_v + e_v within the target's range of degrees in v for the multiplier's exponents e,
the same for each group of variables (a quaternion: the target is homogeneous in it, so
the basis is too) and for the total degree (the half Newton polytope idea of Reznick
1978, relaxed to boxes); then drop monomials whose diagonal term 2m + e cannot be
matched by the target or by any other pair of the basis, until none is left (Loefberg
2009, diagonal inconsistency).
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from verify.sos import poly as pl
from verify.sos.program import Multiplier


def _ranges(exps: Sequence[pl.Monomial], idx: Sequence[int]) -> tuple[int, int]:
    sums = [sum(m[i] for i in idx) for m in exps]
    return min(sums), max(sums)


def choose_basis(
    target: pl.Poly,
    multiplier: Multiplier,
    groups: Sequence[Sequence[int]],
    *,
    max_degree: int | None = None,
    limit: int = 400,
) -> tuple[pl.Monomial, ...]:
    """Candidate basis for one block; empty when the multiplier cannot fit the target."""
    if not target:
        return ()
    t_exps = list(target)
    h_exps = multiplier.exponents()
    if not h_exps:
        return ()
    top = max_degree if max_degree is not None else pl.degree(target)
    h_hi_total = max(sum(e) for e in h_exps)
    if top < h_hi_total:
        return ()
    per_group: list[list[tuple[int, ...]]] = []
    for idx in groups:
        t_lo, t_hi = _ranges(t_exps, idx)
        _h_lo, h_hi = _ranges(h_exps, idx)
        d_lo = max(0, -((h_hi - t_lo) // 2))  # some term reaches the lowest degree
        d_hi = (t_hi - h_hi) // 2  # no term goes above the highest degree
        if d_hi < d_lo:
            return ()
        options = []
        for d in range(d_lo, d_hi + 1):
            for m in pl.monomials_of_degree(len(idx), d):
                ok = True
                for pos, i in enumerate(idx):
                    if 2 * m[pos] + _ranges(h_exps, [i])[1] > _ranges(t_exps, [i])[1]:
                        ok = False
                        break
                if ok:
                    options.append(m)
        if not options:
            return ()
        per_group.append(options)
    n = sum(len(g) for g in groups)
    basis = []
    count = 1
    for options in per_group:
        count *= len(options)
    if count > 50 * limit:
        return ()
    for combo in itertools.product(*per_group):
        m = [0] * n
        for idx, part in zip(groups, combo, strict=True):
            for pos, i in enumerate(idx):
                m[i] = part[pos]
        if 2 * sum(m) + h_hi_total <= top:
            basis.append(tuple(m))
    return tuple(_prune(sorted(basis), target, multiplier))[:limit] if basis else ()


def _prune(basis: list[pl.Monomial], target: pl.Poly, multiplier: Multiplier):
    """Drop m when no term of H's diagonal times m^2 can be produced or matched."""
    diag = [e for i in range(multiplier.size) for e in multiplier.matrix[i][i]]
    if not diag:
        return []
    support = set(target)
    basis = list(basis)
    changed = True
    while changed:
        changed = False
        products: dict[pl.Monomial, int] = {}
        for a, b in itertools.combinations(basis, 2):
            for e in multiplier.exponents():
                products[pl.mono_mul(e, pl.mono_mul(a, b))] = 1
        keep = []
        for m in basis:
            sq = pl.mono_mul(m, m)
            tops = [pl.mono_mul(e, sq) for e in diag]
            if any(t in support or t in products for t in tops):
                keep.append(m)
        if len(keep) < len(basis):
            basis, changed = keep, True
    return basis
