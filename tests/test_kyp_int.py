"""The integer KYP matrix and the fast KYP check agree with the exact rational ones.

``negated_kyp_matrix`` (FLINT integers, split through a certificate's long pivot rows or
not) equals −M(P) of :func:`kyp_matrix` entry by entry; the fast check
(:func:`verified_kyp`, :func:`verified_kyp_split`) accepts a certificate only where the
exact route (psd_exact on P and on −M(P)) accepts it, on gate certificates and on 300
perturbations of them of both signs.
"""

from __future__ import annotations

import numpy as np
import pytest
from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import (
    _split_inputs,
    kyp_matrix,
    verified_kyp,
    verified_kyp_split,
)
from verify.passivity.check.kyp_int import (
    SplitP,
    heavy_indices,
    int_matrix,
    negated_kyp_matrix,
    split_rational,
)
from verify.passivity.check.psd import psd_exact
from verify.passivity.decision import decide
from verify.passivity.model import from_state_space
from verify.passivity.port_hamiltonian import random_port_hamiltonian
from verify.passivity.search.kyp import rational_p


def _exact_ok(model, P) -> bool:
    negm = ex.scale(-1, _split_inputs(model, kyp_matrix(model, P)))
    return psd_exact(P, strict=True).ok and psd_exact(negm).ok


@pytest.fixture(scope="module", params=[(16, 0.0), (14, 0.05)])
def certified(request):
    n, s = request.param
    A, B, C, D = random_port_hamiltonian(n, 2, np.random.default_rng([5, n]), False)
    d = decide(from_state_space(A, B, C, D + s * np.eye(2), name="pH"))
    assert d.certificate is not None, d.reason
    return d.certificate.model, d.certificate.P


def test_integer_kyp_matrix_is_the_exact_one(certified) -> None:
    model, P = certified
    n = model.n
    expected = ex.scale(-1, kyp_matrix(model, P))
    for kw in ({"P": P}, {"P": P, "Pi": int_matrix(P, n, n)}):
        rows, d = negated_kyp_matrix(*model.integer, **kw)
        assert [[mpq(z, d) for z in row] for row in rows] == expected
    # the same through an explicit split on the first two indices (long pivot rows)
    heavy = [0, 1]
    others = list(range(2, n))
    zero = mpq(0)
    light = int_matrix([[x if i >= 2 and j >= 2 else zero for j, x in enumerate(row)]
                        for i, row in enumerate(P)], n, n)
    sp = SplitP(light, heavy, int_matrix([P[i] for i in heavy], 2, n),
                int_matrix([[P[i][j] for j in heavy] for i in others], n - 2, 2))
    assert rational_p(sp) == P
    rows, d = negated_kyp_matrix(*model.integer, split=sp)
    assert [[mpq(z, d) for z in row] for row in rows] == expected


def test_a_gate_certificate_has_long_entries_on_its_pivot_rows_only(certified) -> None:
    model, P = certified
    if all(x == 0 for row in model.D for x in row):  # D = 0: P B = Cᵀ binds
        heavy = heavy_indices(P)
        assert heavy is not None and len(heavy) == 2
        assert split_rational(P) is not None


def test_fast_check_never_accepts_what_the_exact_check_refuses(certified) -> None:
    model, P = certified
    n = model.n
    assert verified_kyp(model, P) is not None and _exact_ok(model, P)
    rng = np.random.default_rng(7)
    # directions w with Bᵀ w = 0 keep P B = Cᵀ (so the margin decides), single entries
    # break it (then -M(P) has a zero diagonal block beside a nonzero one)
    kernel = ex.kernel_basis(ex.transpose(model.B))
    accepted = refused = 0
    for case in range(150):
        eps = int(rng.choice([-1, 1])) * int(rng.integers(1, 9)) \
            / mpq(2) ** int(rng.integers(-4, 50))
        Q = [row[:] for row in P]
        if case % 2 and kernel and kernel[0]:
            col = int(rng.integers(0, len(kernel[0])))
            w = [row[col] for row in kernel]
            Q = [[x + eps * w[a] * w[b] for b, x in enumerate(row)] for a, row in enumerate(Q)]
        else:
            i, j = (int(v) for v in rng.integers(0, n, 2))
            Q[i][j] += eps
            if i != j:
                Q[j][i] += eps
        fast = verified_kyp(model, Q)
        exact = _exact_ok(model, Q)
        assert fast is None or exact
        accepted += fast is not None
        refused += not exact
        sp = split_rational(Q)
        if sp is not None:
            assert verified_kyp_split(model, sp) is None or exact
    assert accepted and refused, (accepted, refused)  # both outcomes occur


def test_a_split_that_is_not_symmetric_is_refused(certified) -> None:
    model, P = certified
    sp = split_rational(P)
    if sp is None:  # D > 0: no long pivot rows to split on
        return
    assert verified_kyp_split(model, sp) is not None
    rows = [row[:] for row in sp.light.rows]
    i, j = sp.others[0], sp.others[1]
    rows[i][j] += 1  # L no longer symmetric, by one unit of its last place
    bad = SplitP(int_matrix([[mpq(z, sp.light.d) for z in row] for row in rows],
                            model.n, model.n), sp.heavy, sp.rows, sp.cols)
    assert verified_kyp_split(model, bad) is None
