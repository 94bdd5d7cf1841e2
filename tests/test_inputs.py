"""The input layer: hostile values for every input kind give one line naming the argument.

Input kinds: network files, model files, the model constructor, command-line numbers
(``--margin``, ``--band``, ``--tolerance``) and ``simulate`` options. Each refuses NaN,
Inf, bool, text, a wrong shape and a huge exponent with one :class:`VerifyInputError`
line, and the exact flavour keeps every number exact.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from gmpy2 import mpq

from verify.errors import VerifyInputError
from verify.inputs import (
    exact_array,
    parse_number,
    positive_real,
    rational,
    read_toml,
    real,
    real_array,
)
from verify.network_file import load_network
from verify.passivity.band import parse_band
from verify.passivity.gate import parse_margin, parse_tolerance
from verify.passivity.io.model_file import load_model
from verify.passivity.model import from_state_space
from verify.sim.command import SimulateSettings, run_simulate


def one_line(call, *fragments: str) -> str:
    with pytest.raises(VerifyInputError) as info:
        call()
    message = str(info.value)
    assert "\n" not in message
    for fragment in fragments:
        assert fragment in message, message
    return message


# --------------------------------------------------------------------------- the validators


@pytest.mark.parametrize(
    ("value", "fragment"),
    [
        (float("nan"), "NaN or Inf"),
        (float("inf"), "NaN or Inf"),
        (np.float32("-inf"), "NaN or Inf"),
        (True, "got bool True"),
        (np.bool_(False), "got bool"),
        ("1.5", "got str '1.5'"),
        (None, "got NoneType None"),
        (1 + 2j, "got complex"),
    ],
)
def test_scalar_refusals_name_argument_value_and_fix(value, fragment):
    for convert in (rational, real, positive_real):
        message = one_line(lambda c=convert: c(value, "arg"), "arg", fragment)
        assert ";" in message  # the fix follows the problem


def test_exact_flavour_is_exact_and_float_flavour_rounds():
    assert rational(0.1, "x") == mpq(3602879701896397, 2**55)
    assert rational(Fraction(1, 10), "x") == mpq(1, 10)
    assert rational(10**400, "x") == mpq(10**400)
    assert real(Fraction(1, 3), "x") == 1 / 3
    one_line(lambda: real(10**400, "big"), "big", "too large for a float")
    one_line(lambda: positive_real(0, "--step"), "--step must be a positive number")
    assert positive_real(np.int64(2), "x") == 2.0


def test_arrays_refuse_by_index_ragged_and_shape():
    one_line(lambda: exact_array([[1, 2], [3, float("nan")]], "M"), "M[1][1]: NaN or Inf")
    one_line(lambda: exact_array(np.array([[1.0, np.inf]]), "M"), "M[0][1]: NaN or Inf")
    one_line(lambda: exact_array([[1, 2], [3]], "M"), "M: ragged nesting")
    one_line(lambda: real_array([[1, True]], "M"), "M[0][1]", "bool")
    one_line(lambda: real_array([[1.0, 2.0]], "M", (None, 3)), "expected shape (n, 3)",
             "got (1, 2)")
    nested, shape = exact_array(np.array([[1, 2]], dtype=np.int64), "M")
    assert shape == (1, 2) and nested == [[mpq(1), mpq(2)]]
    assert real_array([[1, 2]], "M", (None, 2)).dtype == np.float64


@pytest.mark.parametrize("text", ["nan", "inf", "-inf", "true", "abc", "1e99999", "1/0", "",
                                  "0x10"])
def test_command_line_numbers(text):
    one_line(lambda: parse_number(text, "--flag", "--flag 0.5"), "--flag", repr(text.strip()),
             "not a finite number", "write e.g. --flag 0.5")


def test_command_line_numbers_are_the_decimal_they_spell():
    assert parse_number(" 0.1 ", "--x", "") == Fraction(1, 10)
    assert parse_number("1/3", "--x", "") == Fraction(1, 3)
    assert parse_number("1_000.5e-3", "--x", "") == Fraction(2001, 2000)


# --------------------------------------------------------------------------- the flags


@pytest.mark.parametrize("text", ["nan", "inf", "yes", "1e5000"])
def test_margin_tolerance_band_refuse_hostile_text(text):
    one_line(lambda: parse_margin(text), "--margin", "not a finite number")
    one_line(lambda: parse_tolerance(text), "--tolerance", "not a finite number")
    one_line(lambda: parse_band(f"0:{text}"), "--band", "not a finite number")
    one_line(lambda: parse_band(f"{text}:1"), "--band", "not a finite number")


def test_band_and_tolerance_ranges():
    assert parse_band("0:1.5") == (0, Fraction(3, 2))
    one_line(lambda: parse_band("1:0"), "need W1 < W2")
    one_line(lambda: parse_band("0:1:2"), "expected W1:W2")
    one_line(lambda: parse_tolerance("-1e-3"), "negative")


@pytest.mark.parametrize(
    ("changes", "fragment"),
    [
        ({"k_s": float("nan")}, "--ks"),
        ({"k_s": float("inf")}, "--ks"),
        ({"k_s": True}, "bool"),
        ({"seconds": float("nan")}, "--seconds"),
        ({"step": -1.0}, "--step must be a positive number"),
        ({"human": "static", "gain": float("inf")}, "--gain"),
        ({"human": "static", "gain": "2"}, "--gain"),
    ],
)
def test_simulate_options(tmp_path, changes, fragment):
    settings = SimulateSettings(**{"seconds": 0.1, "out": tmp_path / "out", "plots": False,
                                   **changes})
    one_line(lambda: run_simulate(settings), fragment)
    assert not (tmp_path / "out").exists()


# --------------------------------------------------------------------------- the files

NETWORK_CASES = {
    "nan": ("quaternions = [[nan, 0.0, 0.0, 0.0]]", "quaternions[0][0]: NaN or Inf"),
    "inf": ("rotations = [[[inf, 0, 0], [0, 1, 0], [0, 0, 1]]]", "rotations[0][0][0]: NaN"),
    "bool": ("quaternions = [[1.0, false, 0.0, 0.0]]", "quaternions[0][1]: expected a real"),
    "text": ('quaternions = [[1.0, "0", 0.0, 0.0]]', "got str '0'"),
    "shape": ("quaternions = [[1.0, 0.0, 0.0]]", "expected shape (n, 4), got (1, 3)"),
    "flat": ("quaternions = [1.0, 0.0, 0.0, 0.0]", "expected shape (n, 4), got (4,)"),
    "huge integer": ("quaternions = [[1" + "0" * 400 + ", 0, 0, 0]]", "too large for a float"),
    "huge exponent": ("quaternions = [[1e99999, 0, 0, 0]]", "quaternions[0][0]: NaN or Inf"),
}


@pytest.mark.parametrize("case", sorted(NETWORK_CASES))
def test_network_files(tmp_path, case):
    text, fragment = NETWORK_CASES[case]
    path = tmp_path / "net.toml"
    path.write_text(text + "\n")
    one_line(lambda: load_network(path), str(path), fragment)


SS = "[state_space]\nA = [[-1.0]]\nB = [[1.0]]\nC = [[1.0]]\nD = [[{d}]]\n"
MODEL_CASES = {
    "nan": (SS.format(d="nan"), "D[0][0]: NaN or Inf"),
    "inf": (SS.format(d="-inf"), "D[0][0]: NaN or Inf"),
    "bool": (SS.format(d="true"), "D[0][0]: expected a real number, got bool"),
    "text": (SS.format(d='"1"'), "D[0][0]: expected a real number, got str"),
    "shape": (SS.format(d="[1.0]"), "D: expected an m x m matrix"),
    "not square": (SS.format(d="1.0], [2.0"), "H must be square"),
    "huge exponent": (SS.format(d="1e5000"), "number out of range"),
    "k_s bool": ("k_s = true\n" + SS.format(d="0.0"), "'k_s': expected a real number"),
    "k_s huge": ("k_s = 1e400\n" + SS.format(d="0.0"), "'k_s': ", "too large for a float"),
}


@pytest.mark.parametrize("case", sorted(MODEL_CASES))
def test_model_files(tmp_path, case):
    text, *fragments = MODEL_CASES[case]
    path = tmp_path / "model.toml"
    path.write_text(text)
    one_line(lambda: load_model(path), str(path), *fragments)


def test_model_file_numbers_are_exact(tmp_path):
    path = tmp_path / "model.toml"
    path.write_text(SS.format(d="0.1"))
    assert load_model(path).exact.D == [[mpq(1, 10)]]
    assert read_toml(path)["state_space"]["D"] == [[0.1]]  # the float flavour


@pytest.mark.parametrize(
    ("D", "fragment"),
    [
        ([[float("nan")]], "D[0][0]: NaN or Inf"),
        ([[True]], "D[0][0]: expected a real number, got bool"),
        ([["1"]], "D[0][0]: expected a real number, got str"),
        (np.array([[np.inf]]), "D[0][0]: NaN or Inf"),
        ([[1.0, 2.0]], "H must be square"),
    ],
)
def test_model_constructor(D, fragment):
    one_line(lambda: from_state_space([[-1.0]], [[1.0]], [[1.0]], D), "model 'model'", fragment)


@pytest.mark.parametrize(("tolerance", "fragment"),
                         [(float("nan"), "NaN or Inf"), (-1e-9, "must be >= 0"),
                          (True, "bool")])
def test_network_tolerance(tmp_path, tolerance, fragment):
    """A NaN tolerance would let every matrix pass as a rotation (NaN comparisons fail)."""
    path = tmp_path / "net.toml"
    path.write_text("rotations = [[[2.0, 0, 0], [0, 1, 0], [0, 0, 1]]]\n")
    one_line(lambda: load_network(path, tolerance=tolerance), "--tolerance", fragment)


def test_written_decimal_is_its_value_and_prints_as_written():
    import pickle

    from verify.inputs.numbers import WrittenDecimal, written_decimal
    from verify.validation import shown

    x = written_decimal("-1.50")
    assert isinstance(x, WrittenDecimal) and x == Fraction(-3, 2)
    assert hash(x) == hash(Fraction(-3, 2))
    assert str(x) == repr(x) == shown(x) == "-1.50"
    assert type(x + 1) is Fraction and x + 1 == Fraction(-1, 2)  # arithmetic: plain values
    assert pickle.loads(pickle.dumps(x)) == x and type(pickle.loads(pickle.dumps(x))) is Fraction
    assert written_decimal("nan") != written_decimal("nan")  # stays a float for the caller
    with pytest.raises(ValueError, match="exponent beyond"):
        written_decimal("1e99999999")


def test_read_toml_keeps_written_text_only_when_asked(tmp_path):
    from verify.inputs import read_toml

    path = tmp_path / "x.toml"
    path.write_text("a = 2.50\nb = 3\n")
    assert repr(read_toml(path, exact=True)["a"]) == "Fraction(5, 2)"
    assert repr(read_toml(path, exact=True, written=True)["a"]) == "2.50"
    assert read_toml(path)["a"] == 2.5 and read_toml(path, exact=True, written=True)["b"] == 3
