"""Hostile cases for exact model input and exact realisation.

Every number of a model denotes its exact value, transfer functions are realised over Q,
float views never crash, and a non-minimal state space is named in the verdict. Cases
come in both file forms (state space and transfer function) where both apply.

Every all-frequency verdict below is decided (up to 60 states the exact
frequency-domain decision leaves nothing inconclusive), and never the wrong way; the
finite-band gate may still be inconclusive on data beyond the float range.
"""

from __future__ import annotations

import math
import sys
from fractions import Fraction as Q
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from flint import fmpq
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from verify.cli import main
from verify.errors import VerifyInputError
from verify.inputs.numbers import decimal_literal, rational, to_float
from verify.passivity.check.realization import (
    _companion_columns,
    _elements,
    _observable_quotient,
    check_realization,
    is_minimal,
    minimal_part,
)
from verify.passivity.decision import INCONCLUSIVE, NOT_PASSIVE, PASSIVE, decide
from verify.passivity.gate import parse_margin
from verify.passivity.io.model_file import load_model
from verify.passivity.model import LTIModel, from_python, from_state_space, from_transfer_function

s = sp.Symbol("s")


# --------------------------------------------------------------------------- helpers


def toml_number(x) -> str:
    """A TOML literal that denotes x exactly (ints as ints, Fractions as exact decimals)."""
    if isinstance(x, int):
        return str(x)
    x = Q(x)
    for k in range(0, 1100):
        if (x * 10**k).denominator == 1:
            return f"{x * 10**k}e-{k}" if k else str(x)
    raise ValueError(f"{x} has no finite decimal expansion")


def toml_value(v) -> str:
    if isinstance(v, list | tuple):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return toml_number(v)


def write_ss(tmp_path: Path, A, B, C, D, name="m.toml") -> Path:
    text = "[state_space]\n" + "".join(f"{k} = {toml_value(v)}\n" for k, v in
                                       zip("ABCD", (A, B, C, D), strict=True))
    path = tmp_path / name
    path.write_text(text)
    return path


def write_tf(tmp_path: Path, num, den, name="m.toml") -> Path:
    path = tmp_path / name
    path.write_text(f"[transfer_function]\nnum = {toml_value(num)}\nden = {toml_value(den)}\n")
    return path


def sym(x) -> sp.Rational:
    q = Q(int(x.numerator), int(x.denominator))
    return sp.Rational(q.numerator, q.denominator)


def transfer_matrix(model: LTIModel) -> sp.Matrix:
    """C (sI - A)^-1 B + D of the exact model, by sympy (independent of FLINT)."""
    em = model.exact
    n, m = em.n, em.m
    D = sp.Matrix(m, m, lambda i, j: sym(em.D[i][j]))
    if n == 0:
        return D
    A = sp.Matrix(n, n, lambda i, j: sym(em.A[i][j]))
    B = sp.Matrix(n, m, lambda i, j: sym(em.B[i][j]))
    C = sp.Matrix(m, n, lambda i, j: sym(em.C[i][j]))
    X = (s * sp.eye(n) - A).LUsolve(B)
    return (C * X + D).applyfunc(sp.cancel)


def expected_matrix(num, den) -> sp.Matrix:
    def poly(c):
        return sum(sp.Rational(Q(x)) * s**k for k, x in enumerate(reversed(c)))

    m = len(num)
    return sp.Matrix(m, m, lambda i, j: sp.cancel(poly(num[i][j]) / poly(den[i][j])))


def assert_realises(model: LTIModel, num, den) -> None:
    """The realisation's transfer matrix equals num/den exactly (rational functions).

    Symbolically (sympy) for small models; for larger ones by exact values at rational
    points: each element of the difference is P(s)/(den(s) chi_A(s)) with deg P <
    deg den + n, so it vanishes identically when it vanishes at that many non-poles.
    """
    if model.n <= 4:
        diff = (transfer_matrix(model) - expected_matrix(num, den)).applyfunc(sp.cancel)
        assert diff == sp.zeros(*diff.shape)
        return
    em = model.exact
    n, m = em.n, em.m
    A = [[Q(int(x.numerator), int(x.denominator)) for x in row] for row in em.A]
    needed = max(len(c) for row in den for c in row) + n
    found, s0 = 0, Q(0)
    while found < needed:
        s0 += Q(1, 3)
        dens = [[sum(Q(c) * s0**k for k, c in enumerate(reversed(d))) for d in row]
                for row in den]
        if any(v == 0 for row in dens for v in row):
            continue
        X = solve([[s0 * (i == j) - A[i][j] for j in range(n)] for i in range(n)],
                  [[Q(int(x.numerator), int(x.denominator)) for x in row] for row in em.B])
        if X is None:
            continue  # s0 is an eigenvalue of A
        for i in range(m):
            for j in range(m):
                value = sum(Q(int(em.C[i][k].numerator), int(em.C[i][k].denominator)) * X[k][j]
                            for k in range(n)) + Q(int(em.D[i][j].numerator),
                                                   int(em.D[i][j].denominator))
                expected = sum(Q(c) * s0**k for k, c in enumerate(reversed(num[i][j])))
                assert value == expected / dens[i][j], (s0, i, j)
        found += 1


def solve(M: list[list[Q]], R: list[list[Q]]) -> list[list[Q]] | None:
    """Exact Gauss-Jordan M X = R over Fractions; None when M is singular."""
    n = len(M)
    a = [row[:] + r[:] for row, r in zip(M, R, strict=True)]
    for col in range(n):
        piv = next((r for r in range(col, n) if a[r][col] != 0), None)
        if piv is None:
            return None
        a[col], a[piv] = a[piv], a[col]
        for r in range(n):
            if r != col and a[r][col] != 0:
                f = a[r][col] / a[col][col]
                a[r] = [x - f * y for x, y in zip(a[r], a[col], strict=True)]
    return [[a[i][n + j] / a[i][i] for j in range(len(R[0]))] for i in range(n)]


def assert_minimal(model: LTIModel) -> None:
    assert minimal_part(model.exact).hidden == 0


def assert_never_wrong(model: LTIModel, truth: str, *, margin=Q(0)) -> str:
    """The verdict is the truth or inconclusive (never the opposite); returns it."""
    verdict = decide(model, margin).verdict
    assert verdict in (truth, INCONCLUSIVE), verdict
    return verdict


# --------------------------------------------------------------------------- the number rule


@pytest.mark.parametrize("text, value", [
    ("0.1", Q(1, 10)), ("-0.0", Q(0)), ("+2.5", Q(5, 2)), ("1E5", Q(100000)),
    ("1_000.5e-3", Q(2001, 2000)), ("1e-300", Q(1, 10**300)), ("7e+2", Q(700)),
])
def test_a_decimal_denotes_the_decimal_it_spells(text, value):
    assert decimal_literal(text) == value


def test_decimal_exponent_is_bounded_and_non_finite_is_refused(tmp_path):
    path = write_tf(tmp_path, [[[1]]], [[[1, 1]]])
    path.write_text("[transfer_function]\nnum = [[[1e99999]]]\nden = [[[1.0, 1.0]]]\n")
    with pytest.raises(VerifyInputError, match="exponent beyond"):
        load_model(path)
    for bad in ("nan", "inf", "-inf", "+nan"):
        path.write_text(f"[transfer_function]\nnum = [[[{bad}]]]\nden = [[[1.0, 1.0]]]\n")
        with pytest.raises(VerifyInputError, match=r"num\[0\]\[0\]\[0\]: NaN or Inf"):
            load_model(path)


def test_an_integer_beyond_pythons_digit_limit_is_read_and_one_beyond_ours_refused(tmp_path):
    """Integers of any size up to 20000 digits are read exactly (Python's own limit of 4300
    digits does not apply to a model file); a longer run of digits is one line."""
    import sys

    path = tmp_path / "m.toml"
    path.write_text("[state_space]\nA = []\nB = []\nC = []\nD = [[" + "9" * 5000 + "]]\n")
    limit = sys.get_int_max_str_digits()
    model = load_model(path)
    assert sys.get_int_max_str_digits() == limit  # restored after the parse
    assert model.exact.D[0][0] == 10**5000 - 1
    path.write_text("[state_space]\nA = []\nB = []\nC = []\nD = [[" + "9" * 20001 + "]]\n")
    with pytest.raises(VerifyInputError, match="more than 20000 digits") as err:
        load_model(path)
    assert "\n" not in str(err.value)


def test_conversion_helper_is_exact_and_refuses_non_numbers():
    assert rational(0.1, "x") == mpq(3602879701896397, 2**55)  # a float is its binary value
    assert rational(Q(1, 10), "x") == mpq(1, 10)
    assert rational(np.int64(-7), "x") == -7
    assert rational(5e-324, "x") == mpq(1, 2**1074)
    assert rational(2**200 + 1, "x") == 2**200 + 1
    for bad in (True, "1", None, 1j, math.nan, math.inf):
        with pytest.raises(VerifyInputError):
            rational(bad, "x")
    third = np.longdouble(1) / 3  # wider than a double: still its exact binary value
    assert rational(third, "x") == mpq(*third.as_integer_ratio()) != mpq(float(third))
    model = from_state_space(np.array([[-third]]), [[1]], [[1]], [[0]])
    assert model.exact.A == [[-mpq(*third.as_integer_ratio())]]
    assert to_float(mpq(10**400)) == math.inf and to_float(mpq(-(10**400))) == -math.inf
    assert to_float(mpq(1, 10**400)) == 0.0 and to_float(mpq(1, 3)) == 1 / 3


BIG_D = [[1, 2147483648], [0, 1152921504606846975]]  # det(D + D^T) = -4 exactly


@pytest.mark.parametrize("form", ["state_space", "transfer_function"])
def test_big_integers_are_exact(tmp_path, form):
    if form == "state_space":
        path = write_ss(tmp_path, [], [], [], BIG_D)
    else:
        path = write_tf(tmp_path, [[[x] for x in row] for row in BIG_D], [[[1], [1]], [[1], [1]]])
    model = load_model(path)
    assert model.exact.D == [[mpq(x) for x in row] for row in BIG_D]
    d = decide(model)
    assert d.verdict == NOT_PASSIVE and d.witness.kind == "infinity"
    v = [Q(x) for x in d.witness.data["v"]]
    S = [[BIG_D[i][j] + BIG_D[j][i] for j in range(2)] for i in range(2)]
    assert sum(v[i] * S[i][j] * v[j] for i in range(2) for j in range(2)) < 0


def test_decimals_decide_the_decimal_model_not_its_float_rounding(tmp_path):
    # D = [[0.3, 0.9], [0.9, 2.7]]: D + D^T is singular PSD in decimals (0.3 * 2.7 = 0.9^2);
    # the binary floats nearest to these decimals give det < 0, a different model.
    D = [[Q(3, 10), Q(9, 10)], [Q(9, 10), Q(27, 10)]]
    as_floats = [[Q(float(x)) for x in row] for row in D]
    assert as_floats[0][0] * as_floats[1][1] - as_floats[0][1] ** 2 < 0
    file_model = load_model(write_ss(tmp_path, [], [], [], D))
    assert file_model.exact.D == [[mpq(x) for x in row] for row in D]
    assert decide(file_model).verdict == PASSIVE
    float_model = from_state_space([], [], [], [[0.3, 0.9], [0.9, 2.7]])
    assert decide(float_model).verdict == NOT_PASSIVE  # the binary values, exactly


@pytest.mark.parametrize("form", ["state_space", "transfer_function"])
def test_static_gain_indefinite_by_1e_17(tmp_path, form):
    D = [[1, 1], [1, 1 - Q(1, 10**17)]]  # det(D + D^T) = -4e-17 < 0
    path = write_ss(tmp_path, [], [], [], D) if form == "state_space" else write_tf(
        tmp_path, [[[x] for x in row] for row in D], [[[1], [1]], [[1], [1]]])
    d = decide(load_model(path))
    assert d.verdict == NOT_PASSIVE and d.witness.kind == "infinity"


@pytest.mark.parametrize("form", ["state_space", "transfer_function"])
def test_static_gain_on_the_boundary_is_passive(tmp_path, form):
    for D in ([[1, 1], [1, 1]], [[Q(3, 10), Q(1, 10)], [Q(-1, 10), 0]],
              [[0, 7], [-7, 0]]):  # det(D + D^T) = 0 each time (the last is lossless)
        path = write_ss(tmp_path, [], [], [], D) if form == "state_space" else write_tf(
            tmp_path, [[[x] for x in row] for row in D], [[[1], [1]], [[1], [1]]])
        assert decide(load_model(path)).verdict == PASSIVE


# --------------------------------------------------------------------------- exact realisation

REALISATIONS = {
    # name: (num, den, McMillan degree)
    "[[1,1],[1,1]]/(s+1)": ([[[1], [1]], [[1], [1]]], [[[1, 1]] * 2] * 2, 1),
    "[[2,1],[1,2]]/s": ([[[2], [1]], [[1], [2]]], [[[1, 0]] * 2] * 2, 2),
    "[[2,1],[1,2]]/(s+1)": ([[[2], [1]], [[1], [2]]], [[[1, 1]] * 2] * 2, 2),
    "lossless (2s^3+18s^2+24s+26)/(s^3+4s^2+2s+8)": ([[[2, 18, 24, 26]]], [[[1, 4, 2, 8]]], 3),
    "common factor (s^2+1)(s+2)/((s^2+s+1)(s+2))": ([[[1, 2, 1, 2]]], [[[1, 3, 3, 2]]], 2),
    "near cancellation (s-1-2^-40)/(s^2-1)": ([[[1, -1 - Q(1, 2**40)]]], [[[1, 0, -1]]], 2),
    "exact cancellation (s-1)/(s^2-1)": ([[[1, -1]]], [[[1, 0, -1]]], 1),
    "s/(s^2+0.1)": ([[[1, 0]]], [[[1, 0, Q(1, 10)]]], 2),
    "(s+2)/(s^2+2s+2)": ([[[1, 2]]], [[[1, 2, 2]]], 2),
    "1 - s/(s^2+1)": ([[[1, -1, 1]]], [[[1, 0, 1]]], 2),
    "repeated pole 1/(s+1)^2": ([[[1]]], [[[1, 2, 1]]], 2),
    "repeated j-axis pole 1/(s^2+1)^2": ([[[1]]], [[[1, 0, 2, 0, 1]]], 4),
    "shared pole in a row": ([[[1], [2]], [[0], [1]]], [[[1, 1], [1, 1]], [[1], [1, 2]]], 2),
    "shared poles, rank-2 residue": ([[[1], [1]], [[1], [2]]], [[[1, 1]] * 2] * 2, 2),
    "1/(1e-300 s + 1)": ([[[1]]], [[[Q(1, 10**300), 1]]], 1),
    "non-monic, unnormalised": ([[[6, 3]]], [[[4, 6, 2]]], 1),  # 3(2s+1)/(2(2s+1)(s+1))
    # big integers and long decimals: equal as floats, different as written
    "big-integer cancellation (s + 2^60 + 1)/(s + 2^60 + 1)": (
        [[[1, 2**60 + 1]]], [[[1, 2**60 + 1]]], 0),
    "big-integer near cancellation (s + 2^60 + 1)/(s + 2^60)": (
        [[[1, 2**60 + 1]]], [[[1, 2**60]]], 1),
    "decimal near cancellation (s + 0.1)/(s + 0.1000000000000000001)": (
        [[[1, Q(1, 10)]]], [[[1, Q(10**18 + 1, 10**19)]]], 1),
    "zero element": ([[[0], [1]], [[1], [0]]], [[[1, 5], [1, 1]], [[1, 1], [3]]], 2),
}


def circulant(m: int) -> list[list[int]]:
    c = [3, 1, 0, 0, 1] if m == 5 else [2, 1, 1]  # c[k] = c[m - k]: symmetric
    return [[c[(j - i) % m] for j in range(m)] for i in range(m)]


for _m in (3, 5):
    REALISATIONS[f"circulant {_m}x{_m} over (s+1)"] = (
        [[[x] for x in row] for row in circulant(_m)], [[[1, 1]] * _m] * _m,
        int(sp.Matrix(circulant(_m)).rank()))


@pytest.mark.parametrize("name", sorted(REALISATIONS))
def test_exact_minimal_realisation(name, tmp_path):
    num, den, degree = REALISATIONS[name]
    for model in (from_transfer_function(num, den), load_model(write_tf(tmp_path, num, den))):
        assert model.n == degree
        assert_realises(model, num, den)
        assert_minimal(model)
        assert model.realization.startswith("exact minimal realisation over Q")


@st.composite
def _transfer_matrices(draw):
    """Random 2 x 2 transfer matrices with small rational coefficients, shared poles and
    common factors likely (so that cancellation and non-minimal stacks are exercised)."""
    small = st.integers(-3, 3)
    factors = [[1, draw(small)], [1, draw(small), draw(st.integers(0, 3))]]
    num, den = [], []
    for _ in range(2):
        nrow, drow = [], []
        for _ in range(2):
            d = [Q(1)]
            for f in draw(st.lists(st.sampled_from(factors), max_size=2)):
                d = [sum((d[i] * f[k - i] for i in range(len(d)) if 0 <= k - i < len(f)),
                         Q(0)) for k in range(len(d) + len(f) - 1)]
            nrow.append([Q(draw(small), draw(st.integers(1, 4)))
                         for _ in range(draw(st.integers(1, len(d))))])
            drow.append([x * draw(st.integers(1, 3)) for x in d])
        num.append(nrow)
        den.append(drow)
    return num, den


@settings(max_examples=30, deadline=None)
@given(_transfer_matrices())
def test_random_transfer_matrices_realise_exactly_and_minimally(data):
    num, den = data
    model = from_transfer_function(num, den)
    assert_realises(model, num, den)
    n = model.n
    if n:  # minimal by an independent rank computation (sympy)
        em = model.exact
        A = sp.Matrix(n, n, lambda i, j: sym(em.A[i][j]))
        B = sp.Matrix(n, 2, lambda i, j: sym(em.B[i][j]))
        C = sp.Matrix(2, n, lambda i, j: sym(em.C[i][j]))
        ctrb = sp.Matrix.hstack(*[A**k * B for k in range(n)])
        obsv = sp.Matrix.vstack(*[C * A**k for k in range(n)])
        assert ctrb.rank() == n and obsv.rank() == n


def test_near_cancellation_keeps_the_unstable_mode():
    num, den, _ = REALISATIONS["near cancellation (s-1-2^-40)/(s^2-1)"]
    model = from_transfer_function(num, den)
    A = sp.Matrix(2, 2, lambda i, j: sym(model.exact.A[i][j]))
    assert A.charpoly(s).as_expr().subs(s, 1) == 0  # the pole at s = 1 is kept exactly
    d = decide(model)
    assert d.verdict == NOT_PASSIVE and d.certificate is None


def test_realisation_is_deterministic_and_exact():
    """Same input, same exact matrices: here the controllable canonical form itself."""
    model = from_transfer_function([[[2, 18, 24, 26]]], [[[1, 4, 2, 8]]])
    q = lambda rows: [[mpq(x) for x in row] for row in rows]  # noqa: E731
    assert model.exact.A == q([[0, 1, 0], [0, 0, 1], [-8, -2, -4]])
    assert model.exact.B == q([[0], [0], [1]])
    assert model.exact.C == q([[10, 20, 10]])  # 2 + (10 s^2 + 20 s + 10)/den
    assert model.exact.D == q([[2]])
    again = from_transfer_function([[[2.0, 18.0, 24.0, 26.0]]], [[[1.0, 4.0, 2.0, 8.0]]])
    assert again.exact.fingerprint() == model.exact.fingerprint()


def test_the_exact_check_catches_a_wrong_realisation():
    elements = _elements([[[1, 2]]], [[[1, 3, 2]]], "t")  # (s+2)/((s+1)(s+2)) = 1/(s+1)
    A, B, C, D = _companion_columns(elements)
    A, B, C = _observable_quotient(A, B, C)
    assert check_realization(elements, A, B, C, D) is None
    C[0, 0] += fmpq(1, 2**80)
    assert "Markov parameter 0" in check_realization(elements, A, B, C, D)
    A2, B2, C2, D2 = _companion_columns(elements)
    D2[0, 0] = 1
    assert "feedthrough" in check_realization(elements, A2, B2, C2, D2)


def test_python_objects_are_their_binary_values():
    import control

    model = from_python(control.tf([1.0, 0.1], [1.0, 0.3, 0.1]))
    assert_realises(model, [[[Q(1.0), Q(0.1)]]], [[[Q(1.0), Q(0.3), Q(0.1)]]])
    ss = from_python(control.ss([[-0.1]], [[1.0]], [[1.0]], [[0.0]]))
    assert ss.exact.A == [[mpq(0.1) * -1]]


# --------------------------------------------------------------------------- verdicts, both forms

# (name, state space or None, transfer function or None, truth, needs the frequency route)
#   every case is decided exactly (KYP certificate, witness, or the exact frequency-domain
#   decision of positive realness for the flagged ones).
LOSSLESS_SS = ([[0, 1, 0], [0, 0, 1], [-8, -2, -4]], [[0], [0], [1]], [[10, 20, 10]], [[2]])
VERDICTS = [
    ("[[1,1],[1,1]]/(s+1)", ([[-1]], [[1, 1]], [[1], [1]], [[0, 0], [0, 0]]),
     REALISATIONS["[[1,1],[1,1]]/(s+1)"][:2], PASSIVE, False),
    ("[[2,1],[1,2]]/s", ([[0, 0], [0, 0]], [[1, 0], [0, 1]], [[2, 1], [1, 2]],
                         [[0, 0], [0, 0]]), REALISATIONS["[[2,1],[1,2]]/s"][:2], PASSIVE, True),
    ("[[2,1],[1,2]]/(s+1)", ([[-1, 0], [0, -1]], [[1, 0], [0, 1]], [[2, 1], [1, 2]],
                             [[0, 0], [0, 0]]), REALISATIONS["[[2,1],[1,2]]/(s+1)"][:2],
     PASSIVE, True),
    ("lossless 3rd order", LOSSLESS_SS,
     REALISATIONS["lossless (2s^3+18s^2+24s+26)/(s^3+4s^2+2s+8)"][:2], PASSIVE, True),
    ("common factor", None, REALISATIONS["common factor (s^2+1)(s+2)/((s^2+s+1)(s+2))"][:2],
     PASSIVE, True),
    ("near cancellation", ([[0, 1], [1, 0]], [[0], [1]], [[-1 - Q(1, 2**40), 1]], [[0]]),
     REALISATIONS["near cancellation (s-1-2^-40)/(s^2-1)"][:2], NOT_PASSIVE, True),
    ("s/(s^2+0.1)", ([[0, 1], [Q(-1, 10), 0]], [[0], [1]], [[0, 1]], [[0]]),
     REALISATIONS["s/(s^2+0.1)"][:2], PASSIVE, True),
    ("(s+2)/(s^2+2s+2)", ([[0, 1], [-2, -2]], [[0], [1]], [[2, 1]], [[0]]),
     REALISATIONS["(s+2)/(s^2+2s+2)"][:2], PASSIVE, True),
    ("1 - s/(s^2+1): negative residue at +-j", ([[0, 1], [-1, 0]], [[0], [1]], [[0, -1]],
                                                [[1]]),
     REALISATIONS["1 - s/(s^2+1)"][:2], NOT_PASSIVE, False),
    ("s/(s^2+1) with a positive residue", ([[0, 1], [-1, 0]], [[0], [1]], [[0, 1]], [[0]]),
     ([[[1, 0]]], [[[1, 0, 1]]]), PASSIVE, True),
    ("1/(s^2+1): residue not Hermitian PSD", None, ([[[1]]], [[[1, 0, 1]]]), NOT_PASSIVE,
     True),
    ("non-minimal twin of [[2,1],[1,2]]/s (a hidden stable mode)",
     ([[0, 0, 0], [0, 0, 0], [0, 0, -1]], [[1, 0], [0, 1], [0, 0]], [[2, 1, 1], [1, 2, 0]],
      [[0, 0], [0, 0]]), None, PASSIVE, True),
    ("lossless MIMO [[s, 1], [-1, s]]/(s^2+4)", None,
     ([[[1, 0], [1]], [[-1], [1, 0]]], [[[1, 0, 4]] * 2] * 2), PASSIVE, True),
    ("repeated j-axis pole", None, REALISATIONS["repeated j-axis pole 1/(s^2+1)^2"][:2],
     NOT_PASSIVE, False),
    ("1/(1e-300 s + 1)", ([[-(10**300)]], [[1]], [[10**300]], [[0]]),
     REALISATIONS["1/(1e-300 s + 1)"][:2], PASSIVE, False),
    ("circulant 3x3 over (s+1)", None, REALISATIONS["circulant 3x3 over (s+1)"][:2], PASSIVE,
     True),
    ("circulant 5x5 over (s+1)", None, REALISATIONS["circulant 5x5 over (s+1)"][:2], PASSIVE,
     True),
    ("non-symmetric circulant 5x5 over (s+1)", None,
     ([[[[3, 1, 0, 1, 0][(j - i) % 5]] for j in range(5)] for i in range(5)],
      [[[1, 1]] * 5] * 5), NOT_PASSIVE, True),  # skew part dominates at high frequency
    ("near cancellation at 2^-60 scale, stable side", None,
     ([[[1, 1 + Q(1, 2**60)]]], [[[1, 2, 1]]]), PASSIVE, True),
    ("near cancellation at 2^-60 scale, unstable side", None,
     ([[[1, -1 + Q(1, 2**60)]]], [[[1, 0, -1]]]), NOT_PASSIVE, True),
    ("near cancellation of a j-axis pair", None,
     ([[[1, 0, 1 + Q(1, 10**12)]]], [[[1, 1, 1, 1]]]), NOT_PASSIVE, False),
]


@pytest.mark.parametrize("case", VERDICTS, ids=[c[0] for c in VERDICTS])
def test_verdicts_in_both_forms(case, tmp_path):
    name, ss_data, tf_data, truth, _kyp_route_suffices = case
    models = []
    if ss_data is not None:
        models.append(load_model(write_ss(tmp_path, *ss_data, name="ss.toml")))
    if tf_data is not None:
        models.append(load_model(write_tf(tmp_path, *tf_data, name="tf.toml")))
    for model in models:
        verdict = assert_never_wrong(model, truth)
        assert verdict == truth, (name, model.source)


# --------------------------------------------------------------------------- float views

def test_float_views_of_extreme_entries_never_crash(tmp_path):
    cases = [
        # A = -1e150, B = C = 1e150: H = 1e300/(s + 1e150), passive
        (([[-1e150]], [[1e150]], [[1e150]], [[0.0]]), PASSIVE),
        # subnormal entries: H = 2^-2148/(s + 2^-1074), passive
        (([[-5e-324]], [[5e-324]], [[5e-324]], [[0.0]]), PASSIVE),
        # entries beyond the float range (exact integers): float view is +-inf
        (([[-(10**400)]], [[1]], [[1]], [[0]]), PASSIVE),
        (([[10**400]], [[1]], [[1]], [[0]]), NOT_PASSIVE),  # an unstable pole
        (([], [], [], [[-(10**400)]]), NOT_PASSIVE),
    ]
    for data, truth in cases:
        model = load_model(write_ss(tmp_path, *[
            [[Q(x) if isinstance(x, float) else x for x in row] for row in M] for M in data]))
        assert model.A.dtype == np.float64
        assert assert_never_wrong(model, truth) == truth
    huge = from_state_space([[-(10**400)]], [[1]], [[1]], [[0]])
    assert huge.A[0, 0] == -math.inf and not huge.float_view_finite
    assert huge.exact.A == [[mpq(-(10**400))]]


def test_band_and_indices_on_data_beyond_the_float_range():
    from verify.passivity.band import decide_band
    from verify.passivity.indices import indices

    model = from_state_space([[-(10**400)]], [[1]], [[1]], [[0]])  # 1/(s + 1e400): passive
    assert decide_band(model, (Q(0), Q(1))).verdict in (PASSIVE, INCONCLUSIVE)
    ifp, _ = indices(model)
    assert ifp.upper is None or ifp.upper >= 0  # an exact bound, never below the truth 0
    unstable = from_state_space([[10**400]], [[1]], [[1]], [[0]])
    assert decide_band(unstable, (Q(0), Q(1))).verdict in (NOT_PASSIVE, INCONCLUSIVE)


def test_margin_beyond_the_float_range(tmp_path, capsys):
    margin = parse_margin("1e400")
    assert margin == 10**400
    model = from_transfer_function([[[1]]], [[[1, 1]]])
    d = decide(model, margin)
    assert d.verdict == NOT_PASSIVE and d.witness.kind == "infinity"
    assert "-2e+400" in d.reason
    with pytest.raises(VerifyInputError, match="not a finite number"):
        parse_margin("1e99999999")
    path = write_tf(tmp_path, [[[1]]], [[[1, 1]]])
    code = main(["gate", str(path), "--margin", "1e400", "--certificates", str(tmp_path)])
    assert code == 1 and "FAIL" in capsys.readouterr().out
    assert parse_margin("1/100") == Q(1, 100) and parse_margin(" 0.01 ") == Q(1, 100)


def test_cli_on_tiny_time_constant_is_not_bad_input(tmp_path, capsys):
    path = tmp_path / "tiny.toml"
    path.write_text("[transfer_function]\nnum = [[[1.0]]]\nden = [[[1e-300, 1.0]]]\n")
    code = main(["gate", str(path), "--certificates", str(tmp_path)])
    out = capsys.readouterr()
    assert code == 0 and "Traceback" not in out.err + out.out
    assert "PASS" in out.out


# --------------------------------------------------------------------------- non-minimal input


def test_hidden_modes_are_counted_and_located_exactly():
    # uncontrollable unstable mode, 1/(s+1) visible
    part = minimal_part(from_state_space([[-1, 0], [0, 1]], [[1], [0]], [[1, 1]], [[0]]).exact)
    assert (part.uncontrollable, part.unobservable, part.hidden_rhp) == (1, 0, 1)
    assert part.hidden_poly == ("1", "-1")
    # unobservable lossless pair (hidden modes on the axis) beside 1/(s+2)
    A = [[-2, 0, 0], [0, 0, 1], [0, -1, 0]]
    part = minimal_part(from_state_space(A, [[1], [1], [0]], [[1, 0, 0]], [[0]]).exact)
    assert (part.uncontrollable, part.unobservable, part.hidden_axis, part.hidden_rhp) == \
        (0, 2, 2, 0)
    # a hidden stable mode in a 2-port model
    A = [[-1, 0, 0], [0, -2, 0], [0, 0, -3]]
    B = [[1, 0], [0, 1], [0, 0]]
    part = minimal_part(from_state_space(A, B, [[1, 0, 5], [0, 1, 0]], [[0, 0], [0, 0]]).exact)
    assert (part.uncontrollable, part.unobservable, part.hidden_rhp, part.hidden_axis) == \
        (1, 0, 0, 0)
    assert part.model.n == 2


@pytest.mark.parametrize("A, B, C, D, truth, fragments", [
    # 1/(s+1) plus an unobservable unstable mode: positive real, no storage on that state
    ([[-1, 0], [0, 3]], [[1], [1]], [[1, 0]], [[0]], PASSIVE, ["1 in Re s > 0", "not on the "
                                                                "given state"]),
    # 1/(s+1) plus an uncontrollable mode at 0 (on the axis)
    ([[-1, 0], [0, 0]], [[1], [0]], [[1, 1]], [[0]], PASSIVE, ["on the imaginary axis"]),
    # -1/(s+1) (not passive) plus a hidden stable mode
    ([[-1, 0], [0, -5]], [[1], [0]], [[-1, 1]], [[0]], NOT_PASSIVE, ["1 in Re s < 0"]),
])
def test_non_minimal_state_space_says_what_is_decided(A, B, C, D, truth, fragments, tmp_path,
                                                      capsys):
    model = load_model(write_ss(tmp_path, A, B, C, D))
    d = decide(model)
    assert d.note and d.note in d.reason
    main(["gate", model.source, "--certificates", str(tmp_path / "certs")])
    assert "not minimal" in capsys.readouterr().out  # on the PASS line too
    assert d.verdict == truth
    assert "not minimal" in d.reason and "positive realness of the transfer function" in d.reason
    for fragment in fragments:
        assert fragment in d.reason
    if d.certificate is not None:
        assert d.certificate.model.n == 1  # the KYP certificate is on the minimal part


def test_minimality_fast_path_and_exact_fallback():
    rng = np.random.default_rng(5)
    A = rng.standard_normal((40, 40)) - 8 * np.eye(40)
    model = from_state_space(A, rng.standard_normal((40, 3)), rng.standard_normal((3, 40)),
                             np.eye(3))
    assert is_minimal(model.exact)
    # denominators divisible by the prime of the modular test: decided exactly anyway
    p = 2**61 - 1
    q = Q(1, p)
    model = from_state_space([[-q, 0], [0, -2 * q]], [[1], [0]], [[1, 1]], [[0]])
    assert not is_minimal(model.exact)
    assert minimal_part(model.exact).uncontrollable == 1
    twin = from_state_space([[-q, 0], [0, -2 * q]], [[1], [1]], [[1, 1]], [[0]])
    assert is_minimal(twin.exact)


def _hidden_pair_model(visible: int, seed: int) -> LTIModel:
    """T blockdiag(A_v, A_h) T^-1 with an undriven hidden block A_h (eigenvalues
    1 +- j sqrt(6)) and dense rational data: the hidden modes are not visible in A."""
    import random

    rnd = random.Random(seed)
    n = visible + 2
    blocks = sp.zeros(n, n)
    for i in range(visible):
        for j in range(visible):
            blocks[i, j] = sp.Rational(rnd.randint(-9, 9), rnd.randint(1, 5)) - 20 * (i == j)
    blocks[visible:, visible:] = sp.Matrix([[1, -3], [2, 1]])
    blocks[0, visible] = 1  # the visible part sees the hidden block, not the other way
    T = sp.Matrix(n, n, lambda i, j: rnd.randint(-3, 3) + 5 * (i == j))
    Bb = sp.Matrix(n, 2, lambda i, j: rnd.randint(-3, 3) if i < visible else 0)
    Cb = sp.Matrix(2, n, lambda i, j: rnd.randint(-3, 3))
    Ti = T.inv()

    def rows(M):
        return [[Q(int(x.p), int(x.q)) for x in row] for row in M.tolist()]

    return from_state_space(rows(T * blocks * Ti), rows(T * Bb), rows(Cb * Ti),
                            [[0, 0], [0, 0]])


@pytest.mark.parametrize("visible, seed", [(4, 1), (8, 2)])
def test_multimodular_row_space_equals_exact_elimination(visible, seed):
    from verify.passivity.check.realization import (
        _fm,
        _invariant_row_space,
        _invariant_row_space_exact,
    )

    model = _hidden_pair_model(visible, seed)
    part = minimal_part(model.exact)
    assert (part.uncontrollable, part.unobservable, part.hidden_rhp) == (2, 0, 2)
    assert part.hidden_poly == ("1", "-2", "7")  # s^2 - 2 s + 7
    n = model.n
    At, Bt = _fm(model.exact.A, n, n).transpose(), _fm(model.exact.B, n, 2).transpose()
    assert _invariant_row_space(At, Bt) == _invariant_row_space_exact(At, Bt)
    d = decide(model)
    assert "not minimal" in d.reason and "2 in Re s > 0" in d.reason


def test_non_minimal_dense_float_model_is_reduced_exactly():
    # 30 dense float states, the last one undriven and unseen by the others
    rng = np.random.default_rng(0)
    n = 30
    A = rng.standard_normal((n, n)) - 12 * np.eye(n)
    A[-1, :-1] = 0.0
    B = rng.standard_normal((n, 2))
    B[-1] = 0.0
    model = from_state_space(A, B, rng.standard_normal((2, n)), np.eye(2))
    part = minimal_part(model.exact)
    assert (part.uncontrollable, part.unobservable) == (1, 0)
    assert part.hidden_poly == ("1", str(-mpq(A[-1, -1])))
    assert is_minimal(part.model)


def test_zero_input_or_output_matrices():
    for B, C, counts in (([[0], [0]], [[1, 1]], (2, 0)), ([[1], [1]], [[0, 0]], (0, 2))):
        model = from_state_space([[-1, 0], [0, -2]], B, C, [[1]])
        part = minimal_part(model.exact)
        assert (part.uncontrollable, part.unobservable) == counts and part.model.n == 0
        assert decide(model).verdict == PASSIVE


def test_exact_model_is_the_source_of_truth():
    """The exact data win over float arrays passed beside them (replace keeps exact)."""
    import dataclasses

    model = from_state_space([[-(2**60) - 1]], [[1]], [[1]], [[0]])
    renamed = dataclasses.replace(model, name="other")
    assert renamed.exact.A == [[mpq(-(2**60) - 1)]]
    assert float(renamed.A[0, 0]) == -(2.0**60)  # the view rounds; the truth does not


def test_simulated_human_of_a_non_minimal_model_uses_the_certified_state():
    from verify.sim.humans import LTIHuman

    A = [[-1, 0, 0], [0, 3, 0], [0, 0, -2]]  # the mode at 3 is unobservable
    model = from_state_space(A, [[1, 0], [1, 0], [0, 1]], [[1, 0, 0], [0, 0, 1]],
                             [[0, 0], [0, 0]])
    human, decision = LTIHuman.gated(model)
    assert decision.verdict == PASSIVE and human.state_size == 2
    assert human.storage(np.ones(2)) == pytest.approx(
        0.5 * float(sum(sum(row) for row in decision.certificate.P)))


if __name__ == "__main__":  # pragma: no cover
    sys.exit(pytest.main([__file__, "-q"]))
