"""Model files with an [identification] table: written exactly, read strictly."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from identify_models import PAPER_THETA, correlated_covariance

from verify.errors import VerifyInputError
from verify.identify.model_writer import (
    decimal_text,
    parse_structure,
    read_identified,
    write_identified_model,
)
from verify.identify.structure import Structure
from verify.passivity.decision import decide
from verify.passivity.io.model_file import load_model

GOOD = """
name = "m"
[transfer_function]
num = [[[1.2, 0.8], [0.06]], [[-0.04], [1.1, 0.9]]]
den = [[[1, 2, 1.5], [1]], [[1], [1, 2.1, 1.4]]]
[identification]
"""


def _load(tmp_path, table: str):
    path = tmp_path / "m.toml"
    path.write_text(GOOD + table)
    return load_model(path)


def test_written_model_is_the_written_decimals_and_round_trips(tmp_path):
    theta = [1.23456789012345, 0.8, 2.0, 1.5, 1.1, 0.9, 2.1, 1.4, 0.06, -0.04]
    cov = correlated_covariance(theta)
    f = write_identified_model(tmp_path / "m.toml", name="m", structure=Structure.paper(),
                               theta=theta, covariance=cov,
                               extra={"method": "riv", "fit_validation": [70.5, 66.25],
                                      "whiteness_ok": True})
    assert f.center[0] == Fraction("1.234567890")  # 10 significant digits, exactly
    assert np.array_equal(f.covariance(), (cov + cov.T) / 2)  # floats round-trip exactly
    assert f.identification["method"] == "riv"
    assert f.identification["whiteness_ok"] is True
    region = f.region()
    assert region.center == f.center and region.level == Fraction(19, 20)
    assert abs(float(region.chi2) - 18.307038053275146) < 1e-12


def test_identification_table_does_not_change_the_gate(tmp_path):
    plain = tmp_path / "plain.toml"
    plain.write_text(GOOD.replace("[identification]\n", ""))
    with_table = _load(tmp_path, 'method = "x"\ncovariance = [[1.0, 0.0], [0.0, 1.0]]\n')
    a, b = decide(load_model(plain)), decide(with_table)
    assert a.verdict == b.verdict and a.witness.data == b.witness.data
    assert with_table.meta["identification"]["method"] == "x"


@pytest.mark.parametrize("table,needle", [
    ("x = nan\n", "NaN"),
    ("x = [1.0, inf]\n", "NaN"),
    ("x = [[1.0, 2.0], [3.0]]\n", "rectangular"),
    ("x = [[[1.0]]]\n", "expected a number"),
    ("x = [1.0, \"a\"]\n", "expected a number"),
    ("[identification.sub]\ny = 1\n", "expected a string, bool, number"),
    ("x = 1979-05-27\n", "expected a string, bool, number"),
    ("x = [{a = 1}]\n", "expected a number"),
])
def test_hostile_identification_tables_are_refused_in_one_line(tmp_path, table, needle):
    with pytest.raises(VerifyInputError) as err:
        _load(tmp_path, table)
    assert needle in str(err.value) and "\n" not in str(err.value)


def test_identification_must_be_a_table(tmp_path):
    path = tmp_path / "m.toml"
    path.write_text('identification = "riv"\n' + GOOD.replace("[identification]\n", ""))
    with pytest.raises(VerifyInputError, match="must be a table"):
        load_model(path)


def test_read_identified_refuses_other_layouts(tmp_path):
    path = tmp_path / "m.toml"
    path.write_text(GOOD.replace("[1, 2, 1.5]", "[2, 2, 1.5]") + 'structure = "paper"\n')
    with pytest.raises(VerifyInputError, match="layout"):
        read_identified(path)
    path.write_text(GOOD + "method = 'x'\n")
    with pytest.raises(VerifyInputError, match="structure"):
        read_identified(path)


def test_structure_and_decimal_spellings():
    assert parse_structure("paper") == Structure.paper()
    assert parse_structure("3:1") == Structure.poles_zeros(3, 1)
    assert parse_structure("order:4") == Structure.order(4)
    for bad in ("", "2", "a:b", "1:2", "order:0", "order:x"):
        with pytest.raises(VerifyInputError):
            parse_structure(bad)
    assert decimal_text(2.0) == "2" and decimal_text(1e-7) == "1.0e-7"
    assert Fraction(decimal_text(0.1)) == Fraction(1, 10)
    with pytest.raises(VerifyInputError):
        decimal_text(float("nan"))
    assert PAPER_THETA
