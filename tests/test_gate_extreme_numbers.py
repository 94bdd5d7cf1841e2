"""Hostile numbers at the gate's edges: no crash on any number the input layer accepts.

Grouped by class: exact numbers too long for Python's int-to-str limit (4300 digits; model
entries sit at the input layer's own limit of 4000 digits, 1e3999, and the gate's exact
work on them produces numbers of tens of thousands of digits),
numbers beyond the float range in file names, messages and JSON, and negative values in
both spellings of ``--margin``, ``--tolerance`` and ``--band``. Exit 3 (an internal error)
is a failure in every case.
"""

from __future__ import annotations

import json
import random
import sys
from fractions import Fraction
from pathlib import Path

import pytest

from verify.cli import _attach_signed_values, main
from verify.inputs.number_text import (
    approx_text,
    exact_text,
    float_or_none,
    short_text,
    unlimited_int_text,
)

MODELS = Path(__file__).resolve().parents[1] / "verify" / "data" / "models"
EXAMPLE = MODELS / "example_state_space.toml"


def _model(tmp_path: Path, body: str, name: str = "m") -> Path:
    path = tmp_path / f"{name}.toml"
    path.write_text(f'name = "{name}"\n[state_space]\n{body}\n')
    return path


# ------------------------------------------------------------------ the text of big numbers


def test_approx_text_is_float_formatting_inside_the_float_range():
    rng = random.Random(5)
    for _ in range(2000):
        x = Fraction(rng.randint(-10**30, 10**30), rng.randint(1, 10**rng.randint(1, 40)))
        for digits in (3, 6):
            assert approx_text(x, digits) == format(float(x), f".{digits}g")


@pytest.mark.parametrize("x, text", [
    (Fraction(10) ** 400, "1e+400"), (-Fraction(10) ** 4300, "-1e+4300"),
    (Fraction(1, 10**400), "1e-400"), (Fraction(999999999, 10**1000), "1e-991"),
    (Fraction(2, 3 * 10**5000), "6.66667e-5001"), (Fraction(0), "0"),
])
def test_approx_text_outside_the_float_range(x, text):
    assert approx_text(x, 6) == text


def test_exact_text_has_no_digit_limit_and_round_trips():
    x = Fraction(10**5000 + 1, 3)
    text = exact_text(x)
    assert len(text) > 4300 and text.endswith("/3")
    with unlimited_int_text():
        assert Fraction(text) == x


def test_float_or_none_refuses_what_a_float_cannot_hold():
    assert float_or_none(Fraction(10) ** 309) is None
    assert float_or_none(Fraction(1, 10**400)) is None
    assert float_or_none(Fraction(1, 10)) == 0.1 and float_or_none(0) == 0.0


def test_short_text_keeps_short_numbers_exact():
    assert short_text(Fraction(-1, 1000)) == "-1/1000"
    assert short_text(Fraction(10) ** 400) == "≈ 1e+400"


def test_unlimited_int_text_restores_the_limit():
    before = sys.get_int_max_str_digits()
    with unlimited_int_text():
        assert len(str(10**5000)) == 5001
    assert sys.get_int_max_str_digits() == before


# ------------------------------------------------------------------ models with huge entries


@pytest.mark.parametrize("body", [
    # witness mapped back from the rescaled model (alpha = 2^26569)
    "A = [[-1e-3999]]\nB = [[1.0]]\nC = [[-1e3999]]\nD = [[0.0]]",
    # witness frequency times beta: more than 4300 digits (21596 without the guard)
    "A = [[-1e-3999, 0.0], [0.0, -1e3999]]\nB = [[1.0], [1.0]]\nC = [[1.0, -1.0]]\n"
    "D = [[0.0]]",
])
def test_not_passive_model_with_entries_1e3999_apart_gets_a_witness(tmp_path, body, capsys):
    model = _model(tmp_path, body)
    out = tmp_path / "g.json"
    code = main(["gate", str(model), "--certificates", str(tmp_path / "c"),
                 "--json", str(out)])
    assert code == 1, capsys.readouterr().err
    (entry,) = json.loads(out.read_text())
    assert entry["verdict"] == "not passive" and entry["witness"]


def test_passive_model_with_entries_1e3999_apart_writes_a_checked_certificate(tmp_path):
    model = _model(tmp_path, "A = [[-1e-3999, 0.0], [0.0, -1e3999]]\nB = [[1.0], [1.0]]\n"
                   "C = [[1.0, 1.0]]\nD = [[0.0]]")
    certs = tmp_path / "c"
    assert main(["gate", str(model), "--certificates", str(certs)]) == 0
    assert main(["certificates", "check", str(certs)]) == 0


# ------------------------------------------------------------------ flags beyond the float range


@pytest.mark.parametrize("margin, name", [("-1e400", "margin-minus1e+400"),
                                          ("-1e3999", "margin-minus1e+3999")])
def test_margin_beyond_the_float_range_names_its_certificate(tmp_path, margin, name, capsys):
    certs = tmp_path / "c"
    assert main(["gate", str(EXAMPLE), f"--margin={margin}", "--certificates", str(certs),
                 "--json", str(tmp_path / "g.json")]) == 0
    (path,) = certs.glob("*.json")
    assert name in path.name
    assert f"with margin ≈ {margin.replace('e', 'e+')}" in capsys.readouterr().out
    assert main(["certificates", "check", str(certs)]) == 0


def test_margin_beyond_the_float_range_refutes_with_a_witness(tmp_path, capsys):
    assert main(["gate", str(EXAMPLE), "--margin=1e3999", "--certificates",
                 str(tmp_path), "--json", str(tmp_path / "g.json")]) == 1
    assert "not passive" in capsys.readouterr().out


@pytest.mark.parametrize("tolerance", ["1e309", "1e3999"])
def test_tolerance_beyond_the_float_range(tmp_path, tolerance, capsys):
    with unlimited_int_text():  # the JSON's exact fields have more than 4300 digits
        _tolerance_beyond_the_float_range(tmp_path, tolerance, capsys)


def _tolerance_beyond_the_float_range(tmp_path, tolerance, capsys):
    model = _model(tmp_path, "A = [[-1.0]]\nB = [[1.0]]\nC = [[-1.0]]\nD = [[0.0]]")
    out = tmp_path / "g.json"
    assert main(["gate", str(model), "--tolerance", tolerance, "--certificates",
                 str(tmp_path / "c"), "--json", str(out)]) == 0
    (entry,) = json.loads(out.read_text())
    perturbation = entry["tolerance"]["perturbation"]
    assert Fraction(perturbation["tolerance"]) == Fraction(tolerance)
    # the float view is there when a float holds the exact size, and null otherwise
    assert perturbation["relative_size_float"] == float_or_none(
        Fraction(perturbation["relative_size"]))
    out = capsys.readouterr().out
    assert f"<= {approx_text(Fraction(tolerance), 3)}" in out
    assert f"(1 within tolerance {tolerance})" in out


def test_band_beyond_the_float_range_at_the_bottom(tmp_path, capsys):
    certs = tmp_path / "c"
    assert main(["gate", str(EXAMPLE), "--band", "1e-3999:1e-3998",
                 "--certificates", str(certs)]) == 0
    (path,) = certs.glob("*.json")
    assert "band-1e-3999-1e-3998" in path.name
    assert main(["certificates", "check", str(certs)]) == 0


# ------------------------------------------------------------------ negative values, both spellings


@pytest.mark.parametrize("spelling", [["--margin", "-1e-3"], ["--margin=-1e-3"],
                                      ["--margin", "-1/1000"], ["--margin", "-.001"]])
def test_negative_margin_in_both_spellings(tmp_path, spelling, capsys):
    assert main(["gate", str(EXAMPLE), *spelling, "--certificates", str(tmp_path)]) == 0
    assert "with margin -1/1000" in capsys.readouterr().out


@pytest.mark.parametrize("spelling", [["--tolerance", "-1e-3"], ["--tolerance=-1e-3"]])
def test_negative_tolerance_reaches_the_number_check(tmp_path, spelling, capsys):
    assert main(["gate", str(EXAMPLE), *spelling, "--certificates", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "is negative" in err and err.count("\n") == 1


def test_signed_values_are_joined_only_for_numeric_options():
    assert _attach_signed_values(["gate", "m.toml", "--margin", "-1e-3", "--band", "-1:2"]) \
        == ["gate", "m.toml", "--margin=-1e-3", "--band=-1:2"]
    assert _attach_signed_values(["gate", "--margin", "--json", "x"]) \
        == ["gate", "--margin", "--json", "x"]  # a real option is left to argparse
    assert _attach_signed_values(["gate", "--", "--margin", "-1"]) \
        == ["gate", "--", "--margin", "-1"]


def test_the_gate_from_python_is_safe_for_any_size_too(tmp_path):
    """run_gate / write_json / GateResult.line, called without the command line."""
    from verify.passivity.gate import run_gate, write_json
    from verify.passivity.io.model_file import load_model

    model = _model(tmp_path, "A = [[-1e-3999, 0.0], [0.0, -1e3999]]\nB = [[1.0], [1.0]]\n"
                   "C = [[1.0, -1.0]]\nD = [[0.0]]")
    limit = sys.get_int_max_str_digits()
    for margin in (Fraction(0), -Fraction(10) ** 4300):
        (r,) = run_gate([load_model(model)], margin, tmp_path / "c")
        write_json([r], tmp_path / "g.json")
        assert r.line() and json.loads((tmp_path / "g.json").read_text())
    assert sys.get_int_max_str_digits() == limit  # restored after each call
