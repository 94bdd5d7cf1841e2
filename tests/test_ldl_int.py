"""The fraction-free LDLᵀ on integers decides definiteness as the rational LDLᵀ does.

Matrices X = L D Lᵀ (L unit lower triangular, small integers) have the inertia of D
(Sylvester's law), so the answer is known before any check runs: D holds positive,
zero (semidefinite, a zero pivot with a zero row in the middle) and negative entries.
FLINT's fraction-free LU, the symmetric Bareiss loop and the rational reference
:func:`verify.passivity.check.exact.psd_ldl` must all give it.
"""

from __future__ import annotations

import numpy as np
import pytest
from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check.ldl_int import bareiss_psd, psd_integer
from verify.passivity.check.psd import psd_exact

SEED = 20261129


def _ldl(rng: np.random.Generator, pivots: list[int], big: bool) -> list[list[int]]:
    n = len(pivots)
    L = np.eye(n, dtype=object)
    for i in range(n):
        for j in range(i):
            L[i, j] = int(rng.integers(-9, 10)) * (2**70 + 1 if big and (i + j) % 3 == 0
                                                   else 1)
    X = L.dot(np.diag(np.array(pivots, dtype=object))).dot(L.T)
    return [[int(x) for x in row] for row in X]


def _cases(count: int):
    rng = np.random.default_rng(SEED)
    for k in range(count):
        n = int(rng.integers(1, 9))
        pivots = [int(rng.integers(1, 50)) for _ in range(n)]
        kind = k % 4
        if kind == 1:  # semidefinite: zero pivots anywhere, even first
            for _ in range(int(rng.integers(1, n + 1))):
                pivots[int(rng.integers(0, n))] = 0
        elif kind == 2:  # one negative pivot
            pivots[int(rng.integers(0, n))] = -int(rng.integers(1, 5))
        elif kind == 3:  # a zero and a negative pivot
            pivots[int(rng.integers(0, n))] = 0
            pivots[int(rng.integers(0, n))] = -1
        yield pivots, _ldl(rng, pivots, big=k % 2 == 0)


@pytest.mark.parametrize("strict", [False, True])
def test_the_integer_routes_and_the_rational_reference_agree_with_the_inertia(strict):
    seen = set()
    for pivots, X in _cases(1200):
        truth = all(p > 0 for p in pivots) if strict else all(p >= 0 for p in pivots)
        rational = [[mpq(x) for x in row] for row in X]
        answers = (psd_integer(X, strict=strict).ok, bareiss_psd(X, strict=strict).ok,
                   ex.psd_ldl(rational, strict=strict).ok)
        assert answers == (truth,) * 3, (pivots, X)
        seen.add(truth)
    assert seen == {True, False}


def test_zero_pivot_with_a_non_zero_row_is_refused():
    assert not bareiss_psd([[0, 1], [1, 0]]).ok
    assert not psd_integer([[0, 1], [1, 5]]).ok
    result = bareiss_psd([[1, 1, 2], [1, 1, 2], [2, 2, 4]])  # rank one: two zero pivots
    assert result.ok and "2 zero pivot(s)" in result.reason
    assert not bareiss_psd([[1, 1, 2], [1, 1, 2], [2, 2, 4]], strict=True).ok


def test_a_non_symmetric_or_non_square_matrix_is_refused():
    assert not psd_integer([[1, 2], [0, 1]]).ok
    assert not psd_integer([[1, 0]]).ok


def test_the_psd_test_falls_back_to_the_integer_route_on_semidefinite_rationals():
    """A rank-deficient matrix with long rationals: no float margin, so the exact
    fallback decides, and it agrees with the rational reference on both sides."""
    rng = np.random.default_rng(SEED + 1)
    n = 12
    G = [[mpq(int(rng.integers(-2**40, 2**40)), 2**45 + 3) for _ in range(n - 3)]
         for _ in range(n)]
    X = ex.matmul(G, ex.transpose(G))
    result = psd_exact(X)
    assert result.ok and "fraction-free" in result.reason
    assert ex.psd_ldl(X).ok
    Y = [row[:] for row in X]
    Y[n - 1][n - 1] -= mpq(1, 2**200)  # just outside: below any float test
    assert not psd_exact(Y).ok
    assert not ex.psd_ldl(Y).ok
