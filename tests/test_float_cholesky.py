"""The verified floating-point Cholesky test never accepts what the exact check refuses.

2 400 random exact rational symmetric matrices, seeded numpy: strictly definite ones,
ones whose smallest pivot sits just inside and just outside Rump's bound c (and at
-c, -c/16, ...), semidefinite ones (a zero pivot), and KYP state blocks
-(Aᵀ P + P A) of lossless port-Hamiltonian models at P = Q + t E (t of both signs,
near zero). Every matrix is X = L D Lᵀ with L unit lower triangular, so its inertia is
D's (Sylvester), and the exact LDLᵀ check decides it again; the float test must say
"positive definite" only where both do.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check import intmat
from verify.passivity.check.float_cholesky import (
    alpha,
    cholesky_completes,
    gamma,
    required_shift,
    verified_pd,
)

SEED = 20261128


def _ldl(rng: np.random.Generator, n: int, pivots: list[Fraction]) -> ex.RationalMatrix:
    """L diag(pivots) Lᵀ, L unit lower triangular with short dyadic entries (exact)."""
    L = [[mpq(int(i == j)) if j >= i else mpq(int(rng.integers(-64, 65)), 32)
          for j in range(n)] for i in range(n)]
    L = ex.transpose(L)  # lower triangular
    D = [[mpq(pivots[i]) if i == j else mpq(0) for j in range(n)] for i in range(n)]
    return ex.matmul(ex.matmul(L, D), ex.transpose(L))


def _bound(X: ex.RationalMatrix) -> Fraction:
    """About Rump's c for X at its own scale (to place pivots around it)."""
    n = len(X)
    top = max(abs(Fraction(x)) for row in X for x in row)
    return required_shift([float(top)] * n, float(top)) or Fraction(1, 2**60)


def _pivot_cases(rng: np.random.Generator, count: int):
    kinds = ("strict", "near+", "near-", "semidefinite", "negative")
    for k in range(count):
        kind = kinds[k % len(kinds)]
        n = int(rng.integers(1, 11))
        pivots = [Fraction(int(rng.integers(1, 100)), int(rng.integers(1, 50)))
                  for _ in range(n)]
        X = _ldl(rng, n, pivots)
        c = _bound(X)
        j = int(rng.integers(0, n))
        scale = Fraction(2) ** int(rng.integers(-6, 7))
        if kind == "near+":
            pivots[j] = c * scale
        elif kind == "near-":
            pivots[j] = -c * scale
        elif kind == "semidefinite":
            pivots[j] = Fraction(0)
        elif kind == "negative":
            pivots[j] = -Fraction(int(rng.integers(1, 100)), 2 ** int(rng.integers(0, 60)))
        if kind != "strict":
            X = _ldl(rng, n, pivots)
        yield kind, X, all(p > 0 for p in pivots)


def _lossless_cases(rng: np.random.Generator, count: int):
    """-(Aᵀ P + P A) for x' = J Q x (R = 0), P = Q + t E: near zero, either sign."""
    for _ in range(count):
        n = int(rng.integers(2, 9))
        J = rng.integers(-8, 9, (n, n)).astype(float)
        J = J - J.T
        Q = np.diag(2.0 ** rng.integers(-2, 3, n))
        R = np.diag(rng.integers(0, 2, n).astype(float)) * 2.0 ** -40  # nearly lossless
        A = ex.to_rational((J - R) @ Q)
        E = rng.integers(-4, 5, (n, n))
        E = E + E.T
        t = mpq(int(rng.choice([-1, 1])), 2 ** int(rng.integers(30, 60)))
        P = [[mpq(Q[i, j]) + t * int(E[i, j]) for j in range(n)] for i in range(n)]
        AtP = ex.matmul(ex.transpose(A), P)
        yield "lossless", ex.scale(-1, ex.add(AtP, ex.transpose(AtP))), None


def test_never_accepts_what_the_exact_check_refuses() -> None:
    rng = np.random.default_rng(SEED)
    cases = list(_pivot_cases(rng, 2000)) + list(_lossless_cases(rng, 400))
    assert len(cases) >= 2400
    accepted = {kind: 0 for kind, _, _ in cases}
    for kind, X, truth in cases:
        exact = ex.pd_ldl(X).ok
        if truth is not None:
            assert exact == truth  # Sylvester: the exact check agrees with the pivots
        fast = verified_pd(intmat.from_rational(X))
        assert not fast or exact, (kind, X)
        accepted[kind] += fast
    # the float test does its job where there is room (so this test can fail both ways)
    assert accepted["strict"] >= 350
    assert accepted["near-"] == accepted["semidefinite"] == accepted["negative"] == 0


def test_the_shift_is_the_theorem_s() -> None:
    u = Fraction(1, 2**53)
    assert gamma(3) == 3 * u / (1 - 3 * u)
    assert alpha(4) == gamma(5) / (1 - gamma(5))
    # c for diag(1, 1) with no off-diagonal part: alpha_2 * 2 + 6 * 2 * (2 + 1) eta + eta
    eta = Fraction(1, 2**1074)
    assert required_shift([1.0, 1.0], 0.0) == alpha(2) * 2 + 36 * eta + (u * 0 + eta)


def test_a_matrix_inside_the_rounding_error_is_not_proved() -> None:
    # diag(1, 1e-20): positive definite, but its margin is far below c
    X = [[mpq(1), mpq(0)], [mpq(0), mpq(1, 10**20)]]
    assert ex.pd_ldl(X).ok
    assert not verified_pd(intmat.from_rational(X))
    assert verified_pd(intmat.from_rational([[mpq(1), mpq(0)], [mpq(0), mpq(1, 10**6)]]))


@pytest.mark.parametrize("F, ok", [
    (np.array([[4.0, 2.0], [2.0, 3.0]]), True),
    (np.array([[1.0, 2.0], [2.0, 1.0]]), False),
    (np.array([[0.0]]), False),
    (np.array([[np.nan]]), False),
])
def test_cholesky_completes(F, ok) -> None:
    assert cholesky_completes(F) is ok
