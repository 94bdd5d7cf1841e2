"""Hostile numbers in positive-realness certificates: one strict spelling, bounded work.

Every number of a ``verify-pr-certificate/1`` file is read by
:func:`verify.inputs.numbers.strict_rational`; exponents and degrees are bounded before
the checker multiplies anything out (an exponent 10^9 once aborted the process in FLINT).
"""

from __future__ import annotations

import json
import subprocess
import sys
import time
from fractions import Fraction

import pytest
from gmpy2 import mpq

from verify.errors import VerifyInputError
from verify.inputs.numbers import decimal_literal, parse_number, strict_rational
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.fd_certificate import check_pr_certificate_data
from verify.passivity.fd_decision import decide_positive_real


def _passive_json() -> dict:
    # 2 + 5/(s+4) + 5s/(s^2+2): positive real, with an imaginary-axis pole pair
    A = [[0, 1, 0], [-2, 0, 0], [0, 0, -4]]
    model = ExactModel(*([[mpq(x) for x in row] for row in M]
                         for M in (A, [[0], [1], [1]], [[0, 5, 5]], [[2]])))
    _v, _r, cert, _w = decide_positive_real(model, "h", "h.toml", {"margin": "0"})
    return json.loads(json.dumps(cert.to_json()))


@pytest.fixture(scope="module")
def passive():
    data = _passive_json()
    assert check_pr_certificate_data(data).ok
    return data


def _edited(data, edit):
    copy = json.loads(json.dumps(data))
    edit(copy)
    return copy


def _first_factor(d):
    return d["hermitian"]["minor_sums"][0]["nonnegativity"]["factors"][0]


# ------------------------------------------------------------------ spellings

SPELLINGS = ["2/4", "-2/2", "1.0", " x ", " 2", "2 ", "+2", "02", "-0", "3/1", "0/5", "1e3",
             "1/0", "", "2//4", "0x10", "١"]


@pytest.mark.parametrize("text", SPELLINGS)
def test_strict_parser_refuses_other_spellings(text):
    with pytest.raises(VerifyInputError, match=r"^where: ") as info:
        strict_rational(text, "where")
    assert "\n" not in str(info.value)


@pytest.mark.parametrize(("text", "value"), [("0", mpq(0)), ("-7", mpq(-7)),
                                             ("-3/4", mpq(-3, 4)), ("10/3", mpq(10, 3))])
def test_strict_parser_reads_the_canonical_spelling(text, value):
    assert strict_rational(text, "x") == value and str(value) == text


def test_strict_parser_refuses_non_strings_and_huge_texts():
    for value in (2, 0.5, None, ["1"], True):
        with pytest.raises(VerifyInputError, match="expected a rational as a string"):
            strict_rational(value, "x")
    start = time.perf_counter()
    with pytest.raises(VerifyInputError, match="a number of 100001 characters is not a rational"):
        strict_rational("1" * 100_001, "x")
    assert time.perf_counter() - start < 5  # refused from the length, not converted


@pytest.mark.parametrize("text", [*SPELLINGS[:4], "1e99999999"])
@pytest.mark.parametrize("place", ["model", "coefficient", "content"])
def test_pr_certificate_refuses_loose_spellings(passive, text, place):
    def edit(d):
        if place == "model":
            d["model"]["D"][0][0] = text
        elif place == "coefficient":
            _first_factor(d)["poly"][0] = text
        else:
            d["hermitian"]["minor_sums"][0]["nonnegativity"]["content"] = text
    start = time.perf_counter()
    with pytest.raises(ValueError, match="malformed certificate"):
        check_pr_certificate_data(_edited(passive, edit))
    assert time.perf_counter() - start < 5  # "1e99999999" took 235 s before


# ------------------------------------------------------------------ bounded work


@pytest.mark.parametrize(("exponent", "pattern"), [
    (10**9, r"exponent 1000000000 outside 1\.\.10000"),
    (2**80, r"exponent of 81 bits outside"),
    (0, r"exponent 0 outside"),
    (-3, r"exponent -3 outside"),
    (5001, r"product of the factors has degree above the limit 10000"),
])
def test_huge_exponents_are_refused_before_any_power(passive, exponent, pattern):
    data = _edited(passive, lambda d: _first_factor(d).__setitem__("exponent", exponent))
    assert len(_first_factor(data)["poly"]) >= 3  # a factor of degree >= 2
    with pytest.raises(ValueError, match=pattern):
        check_pr_certificate_data(data)


def test_exponent_1e9_does_not_abort_the_process(passive, tmp_path):
    """FLINT aborts (SIGABRT) on a power too large; the reader must refuse it first."""
    path = tmp_path / "c.json"
    path.write_text(json.dumps(_edited(
        passive, lambda d: _first_factor(d).__setitem__("exponent", 10**9))))
    code = ("import sys\nfrom verify.passivity.check.fd_certificate import "
            "check_pr_certificate_file\n"
            "try:\n    check_pr_certificate_file(sys.argv[1])\n"
            "except ValueError as exc:\n    print('refused', exc)\n")
    done = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0 and "refused" in done.stdout and "exponent" in done.stdout


def test_degree_of_a_polynomial_is_bounded(passive):
    data = _edited(passive, lambda d: _first_factor(d).__setitem__("poly", ["1"] * 10_002))
    with pytest.raises(ValueError, match="degree 10001 above the limit 10000"):
        check_pr_certificate_data(data)


# ------------------------------------------------------------------ model-file numbers


@pytest.mark.parametrize("text", ["1e99999999", "-1e99999999", "1e-99999999", "1e-4300",
                                  "1." + "0" * 5000, "12e3999"])
def test_decimal_limits_are_checked_before_any_work(text):
    start = time.perf_counter()
    with pytest.raises(ValueError, match=r"exponent beyond \+-4300|more than 4000"):
        decimal_literal(text)
    with pytest.raises(VerifyInputError, match="--margin"):
        parse_number(text, "--margin", "--margin 0.1")
    assert time.perf_counter() - start < 1


def test_a_long_spelling_of_a_small_exponent_is_read_exactly():
    assert decimal_literal("1e" + "0" * 5000 + "1") == 10
    assert decimal_literal("-25e-" + "0" * 100 + "1") == Fraction(-5, 2)
    with pytest.raises(ValueError, match="exponent beyond"):
        decimal_literal("1e" + "1" * 13)  # too many significant exponent digits


def test_model_file_entry_1e99999999_is_one_line(tmp_path, capsys):
    from verify.cli import main

    path = tmp_path / "m.toml"
    path.write_text('[state_space]\nA = [[-1e99999999]]\nB = [[1]]\nC = [[1]]\nD = [[1]]\n')
    start = time.perf_counter()
    assert main(["gate", str(path), "--certificates", str(tmp_path / "certs")]) == 2
    assert time.perf_counter() - start < 10
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "exponent beyond +-4300" in err
