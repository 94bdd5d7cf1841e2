"""Untrusted search: a Gram-matrix SDP solved by Clarabel through cvxpy.

Unknowns: one PSD matrix per block. Constraints: for every monomial, the coefficient
of sum_k <Q_k, H_k (x) z_k z_k^T> equals the target's (Parrilo 2003). The target is
scaled to unit largest coefficient for the solver and the Grams are scaled back. The
objective is zero (a feasibility problem): an interior-point method then ends near the
analytic centre of the feasible set, which leaves room for the exact rounding of
:mod:`verify.sos.rounding`. Nothing here is trusted; a failed or inaccurate solve only
means "no certificate".
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field

import numpy as np

from verify.sos import poly as pl
from verify.sos.program import Block

TOLERANCE = 1e-10  # Clarabel's feasibility and gap tolerances (measured: enough to round)


@dataclass
class SearchResult:
    grams: list[np.ndarray] | None
    status: str
    seconds: float
    sizes: list[int] = field(default_factory=list)


def constraint_rows(blocks: list[Block], target: pl.Poly):
    """Monomial index, and per block a sparse map from vec(Q) (row-major) to monomials."""
    from scipy.sparse import coo_matrix

    monomials: dict[pl.Monomial, int] = {m: k for k, m in enumerate(sorted(target))}
    maps = []
    for blk in blocks:
        n = blk.gram_size
        rows, cols, vals = [], [], []
        for r in range(n):
            for s in range(n):
                for m, c in blk.entry_polynomial(r, s).items():
                    k = monomials.setdefault(m, len(monomials))
                    rows.append(k)
                    cols.append(r * n + s)
                    vals.append(float(c))
        maps.append((rows, cols, vals, n))
    size = len(monomials)
    mats = [coo_matrix((v, (r, c)), shape=(size, n * n)).tocsr() for r, c, v, n in maps]
    return monomials, mats


def solve(blocks: list[Block], target: pl.Poly, *, time_limit: float = 60.0) -> SearchResult:
    import cvxpy as cp

    start = time.perf_counter()
    monomials, mats = constraint_rows(blocks, target)
    scale = max(abs(float(c)) for c in target.values())
    rhs = np.zeros(len(monomials))
    for m, c in target.items():
        rhs[monomials[m]] = float(c) / scale
    grams = [cp.Variable((b.gram_size, b.gram_size), PSD=True) for b in blocks]
    lhs = sum(a @ cp.vec(q, order="C") for a, q in zip(mats, grams, strict=True))
    problem = cp.Problem(cp.Minimize(0), [lhs == rhs])
    try:
        with warnings.catch_warnings():  # an inaccurate solve is judged by the exact check
            warnings.simplefilter("ignore")
            problem.solve(solver="CLARABEL", tol_feas=TOLERANCE, tol_gap_abs=TOLERANCE,
                          tol_gap_rel=TOLERANCE, time_limit=time_limit, max_iter=200)
    except (cp.error.SolverError, ValueError, ArithmeticError) as exc:
        return SearchResult(None, f"solver failed: {exc}", time.perf_counter() - start)
    status = str(problem.status)
    sizes = [b.gram_size for b in blocks]
    if status not in ("optimal", "optimal_inaccurate") or any(q.value is None for q in grams):
        return SearchResult(None, f"solver status {status}", time.perf_counter() - start, sizes)
    values = [scale * (q.value + q.value.T) / 2 for q in grams]
    return SearchResult(values, status, time.perf_counter() - start, sizes)
