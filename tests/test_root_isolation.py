"""Real-root isolation and signs at roots without Sturm sequences (verify.passivity.check.qpoly),
checked against Sturm counts and high-precision root enclosures; the complete route on
lossless and tangent models of moderate size."""

from __future__ import annotations

import itertools
import random

import numpy as np
import pytest
from flint import arb, fmpq, fmpq_poly
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from verify.passivity.check import exact as ex
from verify.passivity.check import qpoly as qp
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.frequency_domain import analyse
from verify.passivity.check.realization import minimal_part
from verify.passivity.decision import NOT_PASSIVE, PASSIVE, decide
from verify.passivity.model import from_state_space


def _factors(rng: random.Random) -> list[fmpq_poly]:
    out = []
    for _ in range(rng.randint(1, 6)):
        kind = rng.random()
        if kind < 0.5:
            out.append(fmpq_poly([-fmpq(rng.randint(-20, 20), rng.randint(1, 4)), 1]))
        elif kind < 0.8:
            out.append(fmpq_poly([rng.randint(1, 5), 0, 1]))  # complex pair
        else:
            out.append(fmpq_poly([-rng.randint(2, 7), 0, 1]))  # irrational real pair
    return out


def _random_squarefree(rng: random.Random, factors=None) -> fmpq_poly:
    p = fmpq_poly([1])
    for f in factors or _factors(rng):
        p *= f
    return qp.squarefree_part(p)


def test_isolation_agrees_with_sturm():
    rng = random.Random(1)
    for _ in range(150):
        p = _random_squarefree(rng)
        intervals = qp.isolate_real_roots(p)
        assert len(intervals) == qp.count_roots(p) == qp.count_real_roots(p)
        for (_, b), (c, _) in itertools.pairwise(intervals):
            assert b <= c
        for a, b in intervals:
            if a == b:
                assert p(a) == 0
            else:
                assert qp.count_roots(p, a, b) == 1


def test_all_real_fast_path_is_only_taken_when_it_is_proved():
    p = fmpq_poly([1])
    for k in range(1, 12):
        p *= fmpq_poly([-fmpq(k * k, 7), 1])
    assert len(qp.all_real_brackets(p)) == 11
    assert qp.all_real_brackets(p * fmpq_poly([1, 0, 1])) is None
    # two roots 1e-40 apart: arb needs precision, the sign changes prove it
    close = fmpq_poly([-1, 1]) * fmpq_poly([-(1 + fmpq(1, 10**40)), 1])
    assert qp.count_real_roots(close) == 2


def _reference_sign(g: fmpq_poly, rho: fmpq_poly, interval) -> int:
    a, b = interval
    if a == b:
        return qp.sign(g(a))
    if (g % rho).is_zero():
        return 0
    h = (g % rho).gcd(rho)
    if h.degree() >= 1 and qp.count_roots(h, a, b) == 1:
        return 0
    for prec in (256, 1024, 4096):
        with qp.precision(prec):
            (root,) = [r.real for r, _ in rho.complex_roots()
                       if r.imag == 0 and arb(a) < r.real and r.real <= arb(b)]
            value = sum((arb(c) * root**k for k, c in enumerate(g.coeffs())), arb(0))
            if value > 0:
                return 1
            if value < 0:
                return -1
    raise AssertionError("reference undecided")


def test_sign_at_root_agrees_with_enclosures():
    rng = random.Random(2)
    for _ in range(120):
        factors = _factors(rng)
        rho = _random_squarefree(rng, factors)
        g = fmpq_poly([rng.randint(-9, 9) for _ in range(rng.randint(1, 7))])
        if rng.random() < 0.3:  # g vanishes at some roots of rho
            g *= rng.choice(factors)
        if rng.random() < 0.2 and rho.degree() >= 1:
            g = g * fmpq_poly(rho.coeffs()) + fmpq_poly([0, 1])
        reduced = qp.reduce_mod(g, rho)
        for interval in qp.isolate_real_roots(rho):
            expected = _reference_sign(g, rho, interval)
            assert qp.sign_at_root(g, rho, interval) == expected
            assert qp.sign_at_root(g, rho, interval, reduced) == expected


def test_sign_at_a_root_where_g_nearly_vanishes():
    rho = fmpq_poly([-2, 0, 1])  # roots +-sqrt 2
    g = fmpq_poly([-fmpq(14142135623730950488016887, 10**25), 1])  # just below sqrt 2
    (neg, pos) = qp.isolate_real_roots(rho)
    assert qp.sign_at_root(g, rho, pos) == 1
    assert qp.sign_at_root(g, rho, neg) == -1


def lossless(n: int, m: int, seed: int):
    rng = np.random.default_rng(seed)
    J = rng.standard_normal((n, n))
    J = J - J.T
    Q = np.diag(2.0 ** rng.integers(-2, 3, n))
    G = rng.standard_normal((n, m))
    return from_state_space(J @ Q, G, G.T @ Q, np.zeros((m, m)), name=f"lossless {n}")


def test_lossless_poles_are_all_found_on_the_axis():
    model = lossless(24, 2, 3)
    an = analyse(minimal_part(model.exact).model, certify=False)
    assert an.verdict == "passive"
    assert len(an.poles_on_axis) == 12
    assert all(p.lo >= 0 and p.hi > p.lo for p in an.poles_on_axis)
    assert all(min(p.signs) >= 0 for p in an.poles_on_axis)


@pytest.mark.parametrize("n", [20])
def test_lossless_and_flipped_lossless(n):
    model = lossless(n, 2, n)
    assert decide(model).verdict == PASSIVE
    flipped = from_state_space(model.A, model.B, -model.C, model.D, name="flipped")
    assert decide(flipped).verdict == NOT_PASSIVE


# cross-check of the axis-pole facts against the former Sturm-sequence route -------------

def _sturm_sign_at_root(g: fmpq_poly, rho: fmpq_poly, interval) -> int:
    """The former implementation: Sturm counts to halve (a, b] until g has no root in it."""
    a, b = interval
    if a == b:
        return qp.sign(g(a))
    r = g % rho
    if r.is_zero():
        return 0
    h = r.gcd(rho)
    if h.degree() >= 1 and qp.count_roots(h, a, b) == 1:
        return 0
    seq = qp.sturm_sequence(r) if r.degree() >= 1 else None
    while True:
        if r.degree() < 1 or (qp.count_roots(r, a, b, seq) == 0 and r(b) != 0):
            return qp.sign(r(b))
        mid = (a + b) / 2
        if rho(mid) == 0:
            return qp.sign(r(mid))
        if qp.count_roots(rho, a, mid) == 1:
            b = mid
        else:
            a = mid


@st.composite
def axis_models(draw):
    """Integer models x' = (J - R) x + B u, y = C x + D u with J skew: R = 0 gives
    imaginary-axis poles, C = B^T lossless; other draws give anything."""
    n, m = draw(st.integers(1, 5)), draw(st.integers(1, 2))
    small = st.integers(-3, 3)
    J = [[0] * n for _ in range(n)]
    for i in range(n):
        for j in range(i + 1, n):
            J[i][j] = draw(small)
            J[j][i] = -J[i][j]
    damp = draw(st.sampled_from([0, 0, 1]))
    A = [[J[i][j] - (damp if i == j else 0) for j in range(n)] for i in range(n)]
    B = [[draw(small) for _ in range(m)] for _ in range(n)]
    C = [[B[j][i] for j in range(n)] for i in range(m)] if draw(st.booleans()) else \
        [[draw(small) for _ in range(n)] for _ in range(m)]
    D = [[draw(st.integers(0, 2)) if i == j else 0 for j in range(m)] for i in range(m)]
    return ExactModel(*(ex.to_rational(np.array(x, dtype=float).reshape(r, c))
                        for x, r, c in ((A, n, n), (B, n, m), (C, m, n), (D, m, m))))


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(axis_models())
def test_axis_pole_facts_agree_with_the_sturm_route(model):
    an = analyse(model, certify=False)
    if an.split is None or an.split.a.degree() < 1 or not an.residue_forms:
        return
    rho = an.split.rho
    assert len(qp.isolate_real_roots(rho)) == qp.count_roots(rho)
    nonnegative = qp.count_roots(rho, fmpq(0), "+inf") + (rho(0) == 0)
    assert len(an.poles_on_axis) == nonnegative
    for pole in an.poles_on_axis:
        interval = (pole.lo, pole.hi)
        if pole.lo != pole.hi:
            assert qp.count_roots(rho, pole.lo, pole.hi) == 1 and pole.lo >= 0
        else:
            assert rho(pole.lo) == 0
        assert pole.signs == [_sturm_sign_at_root(g, rho, interval)
                              for g in an.residue_forms]


def _routh_rational(p: fmpq_poly) -> list:
    """The former Routh table over Q (the reference for the integer-row version)."""
    c = p.coeffs()[::-1]
    if c and c[0] < 0:
        c = [-x for x in c]
    r0, r1 = c[0::2], c[1::2]
    column = [r0[0]] if r0 else []
    rows = [r0, r1]
    for _ in range(len(c) - 1):
        top, bottom = rows[-2], rows[-1]
        if not bottom or bottom[0] <= 0:
            column.append(bottom[0] if bottom else fmpq(0))
            return column
        column.append(bottom[0])
        nxt = []
        for k in range(len(top) - 1):
            below = bottom[k + 1] if k + 1 < len(bottom) else fmpq(0)
            nxt.append((bottom[0] * top[k + 1] - top[0] * below) / bottom[0])
        rows.append(nxt)
    return column


def test_routh_column_is_the_exact_rational_column():
    rng = random.Random(9)
    for _ in range(300):
        if rng.random() < 0.5:
            p = fmpq_poly([fmpq(rng.randint(-20, 20), rng.randint(1, 6))
                           for _ in range(rng.randint(1, 10))])
        else:  # Hurwitz products, where the table runs to the end
            p = fmpq_poly([1])
            for _ in range(rng.randint(1, 7)):
                p *= fmpq_poly([fmpq(rng.randint(1, 9), rng.randint(1, 5)), 1])
        if p.is_zero():
            continue
        assert qp.routh_first_column(p) == _routh_rational(p)
        assert qp.routh_first_column(-p) == _routh_rational(-p)
