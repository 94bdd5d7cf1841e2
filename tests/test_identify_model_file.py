"""Model files with an [identification] table: written exactly, read strictly."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from identify_models import PAPER_THETA, correlated_covariance

from verify.errors import VerifyInputError
from verify.identify.estimate.structure import Structure
from verify.identify.model.model_writer import (
    COVARIANCE_DIGITS,
    decimal_text,
    parse_structure,
    read_identified,
    write_identified_model,
)
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
    # standard error 0.0247: written to 1e-5 (3 digits below the error's leading one)
    assert f.center[0] == Fraction("1.23457")
    assert f.identification["parameter_estimates"][0] == Fraction("1.23457")
    # the covariance on a grid at least COVARIANCE_DIGITS decades below sqrt(C_ii C_jj),
    # fine enough that the correlation's smallest eigenvalue moves by at most 1 %
    sym = (cov + cov.T) / 2
    scale = np.sqrt(np.outer(np.diag(sym), np.diag(sym)))
    assert np.all(np.abs(f.covariance() - sym) <= 0.5 * 10.0**-COVARIANCE_DIGITS * scale)
    s = np.sqrt(np.diag(sym))
    before = np.linalg.eigvalsh(sym / np.outer(s, s))
    after = np.linalg.eigvalsh(f.covariance() / np.outer(s, s))
    assert np.max(np.abs(after - before)) <= 0.011 * before[0]
    assert f.identification["method"] == "riv"
    assert f.identification["whiteness_ok"] is True
    region = f.region()
    assert region.center == f.center and region.level == Fraction(19, 20)
    assert abs(float(region.chi2) - 18.307038053275146) < 1e-10  # 12 digits written


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


# --- canonical digits ------------------------------------------------------------------

def test_coefficients_are_written_to_the_precision_their_standard_errors_justify():
    from verify.identify.model.model_writer import coefficient_text

    assert coefficient_text(1.23456789, 0.051) == "1.23457"  # SE 5e-2: to 1e-5
    assert coefficient_text(-0.0404232538, 0.0058) == "-0.040423"
    assert coefficient_text(1500.4, 30.0) == "1500.4"
    assert coefficient_text(0.8000020845, 6.4e-08) == "0.8000020845"
    assert coefficient_text(2.5, 0.0) == decimal_text(2.5)  # no error: 10 digits
    assert coefficient_text(1e-7, 1.0) == "0"
    for x, se in ((1.2345, 0.01), (-3.0e-5, 1e-7), (12.5, 0.5)):
        text = coefficient_text(x, se)
        assert abs(float(Fraction(text)) - x) <= se / 2000 + 1e-15


def test_float_noise_far_below_the_standard_errors_does_not_change_the_bytes():
    """A rerun on another machine (other BLAS thread count) moves the estimate and its
    covariance in the 12th digit: the model file is byte-identical."""
    from identify_models import PAPER_THETA, correlated_covariance

    from verify.identify.estimate.structure import Structure
    from verify.identify.model.model_writer import identification_table, model_text

    structure = Structure.paper()
    theta = np.array(PAPER_THETA) * (1 + 1e-3 * np.arange(10))  # not round numbers
    cov = correlated_covariance(theta)
    extra = {"method": "riv+pem", "fit_validation": [67.29189512816725, 79.8450594281873]}

    def text(th, cv):
        from verify.identify.model.model_writer import canonical

        ex = {**extra, "fit_validation": [canonical(x) for x in extra["fit_validation"]]}
        table = identification_table(structure, th, cv, Fraction(19, 20), ex)
        return model_text("m", structure, th, table)[0]

    reference = text(theta, cov)
    rng = np.random.default_rng(0)
    for _ in range(20):
        d = 1 + 1e-12 * rng.choice([-1.0, 1.0], size=theta.shape)
        D = 1 + 1e-12 * rng.choice([-1.0, 1.0], size=cov.shape)
        assert text(theta * d, (cov * D + (cov * D).T) / 2) == reference
    # and the file is still the exact model it says, with a positive definite covariance
    assert "1.2" in reference
    table = identification_table(structure, theta, cov, Fraction(19, 20), extra)
    written = np.array(table["covariance"])
    assert np.linalg.eigvalsh(written).min() > 0
