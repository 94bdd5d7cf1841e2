"""The gate's coarse KYP certificate when P B = C^T binds (D + D^T singular).

Only the pivot rows and columns of P are solved for exactly; every other entry stays on
the coarse grid, so the certificate is short where it can be (and cheap for Coq's
kernel to re-check) while meeting the equality exactly.
"""

from __future__ import annotations

import numpy as np
import pytest
from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import check_kyp
from verify.passivity.decision import decide
from verify.passivity.model import from_state_space
from verify.passivity.port_hamiltonian import random_port_hamiltonian
from verify.passivity.search.canonical import coarse_kyp, pivot_rows, solve_pivot_rows


def q(rows):
    return [[mpq(x) for x in row] for row in rows]


def _bits(x: mpq) -> int:
    return max(int(x.numerator).bit_length(), int(x.denominator).bit_length())


@pytest.fixture(scope="module")
def gate_certificate():
    A, B, C, D = random_port_hamiltonian(12, 2, np.random.default_rng([11, 12]), False)
    d = decide(from_state_space(A, B, C, D, name="pH n=12"))
    assert d.certificate is not None, d.reason
    return d.certificate


def test_pivot_rows_pick_an_invertible_block_by_exact_elimination():
    G = q([[0, 0], [1, 2], [3, 1], [3, 5]])
    rows = pivot_rows(G)
    assert rows == [2, 3]  # 3 is the largest first-column entry; the tie goes to row 2
    assert ex.determinant([G[i] for i in rows]) != 0
    assert pivot_rows(q([[1, 2], [2, 4], [3, 6]])) is None  # rank 1 < 2 columns


def test_solving_the_pivot_rows_meets_the_equality_and_keeps_the_rest():
    G = q([[1, 0], [0, 1], [1, 1]])
    solution = q([[2, 1, 0], [1, 3, 1], [0, 1, 5]])
    target = ex.matmul(solution, G)
    P = q([[9, 9, 9], [9, 9, 9], [9, 9, 5]])  # only the free entry P[2][2] = 5 is used
    out = solve_pivot_rows(P, G, target, [0, 1])
    assert ex.matmul(out, G) == target and ex.is_symmetric(out)
    assert out == solution  # given the free block, the solution is unique


def test_the_gate_certificate_is_short_off_the_pivot_rows(gate_certificate):
    model, P0 = gate_certificate.model, gate_certificate.P
    P = coarse_kyp(model, P0)
    assert check_kyp(model, P).ok
    assert ex.matmul(P, model.B) == ex.transpose(model.C)  # D = 0: P B = C^T exactly
    rows = pivot_rows(model.B)
    assert rows is not None and len(rows) == 2
    free = [i for i in range(model.n) if i not in rows]
    short = max(_bits(P[i][j]) for i in free for j in free)
    long = max(_bits(P[i][j]) for i in rows for j in range(model.n))
    assert short <= 40 < long  # the grid's few bits; the pivot rows carry the rest
    assert all(int(P[i][j].denominator) & (int(P[i][j].denominator) - 1) == 0
               for i in free for j in free)  # dyadic
    # the decision's own P is short off its pivot rows too (a dyadic rounding corrected
    # on k rows, verify.passivity.search.kyp._ShortRounding), longer than the grid's
    assert check_kyp(model, P0).ok and max(_bits(x) for row in P0 for x in row) >= long


def test_last_bit_noise_in_the_proposal_leaves_the_certificate_unchanged(gate_certificate):
    """The pivot rows depend on the exact B only, the other entries on P's grid rounding,
    so noise far below the grid (a proposal from another BLAS) gives the same bytes."""
    model, P0 = gate_certificate.model, gate_certificate.P
    noise = mpq(1, 2**90)
    noisy = [[x + noise for x in row] for row in P0]
    assert coarse_kyp(model, noisy) == coarse_kyp(model, P0)
