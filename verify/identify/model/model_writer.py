"""The identified model as a ``verify gate`` model file, and reading it back exactly.

:func:`model_text` writes the nominal model of an estimate (paper, Section 4: diagonal
num_i/den_i, constant off-diagonals c12, c21) as a ``[transfer_function]`` table whose
coefficients are short decimal literals: the exact model is what the file says (each
decimal denotes itself, :mod:`verify.inputs.numbers`), and the robust verdict's region is
centred on those written values, not on the estimator's floats. The ``[identification]``
table carries what the estimation found (method, structure, rate, trial split, fit ratios,
parameter names, values, standard errors, covariance, confidence level, χ² value,
residual tests). Every number is written to a canonical precision so that the same data
give the same bytes on any machine (float noise in the 10th digit, e.g. another BLAS
thread count, does not show): each coefficient to the decimal place its standard error
justifies (:func:`coefficient_text`, ``SE_DIGITS`` digits below the error's leading
one), the covariance to ``COVARIANCE_DIGITS`` significant digits, the other figures to
``FIGURE_DIGITS``; the region is the file's covariance as written.

:func:`read_identified` returns the model, its structure and the exact centre θc from a
file of this kind (used to bind robust certificates to their model file).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from decimal import ROUND_HALF_EVEN, Decimal
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np
from gmpy2 import mpq

from verify.errors import VerifyInputError
from verify.identify.estimate.structure import Structure
from verify.inputs.toml import read_toml
from verify.passivity.io.model_file import parse_model
from verify.passivity.model import LTIModel

#: Significant digits of a written coefficient whose standard error is unknown or zero.
DIGITS = 10
#: A coefficient with standard error s is written to the decimal place of s's leading
#: digit plus SE_DIGITS more (rounding error below s / 2000: nothing the data support is
#: lost, and float noise far below it, e.g. another BLAS, does not change the bytes).
SE_DIGITS = 3
#: Fewest decades below sqrt(C_ii C_jj) at which a covariance entry is written (more when
#: the correlation matrix is ill-conditioned: :func:`canonical_covariance`).
COVARIANCE_DIGITS = 4
#: Significant digits of the other descriptive floats (standard errors, noise levels,
#: test statistics).
FIGURE_DIGITS = 4


def canonical(x: float, digits: int = FIGURE_DIGITS) -> float:
    """x rounded to ``digits`` significant digits (the same float on every machine for
    inputs that differ only far below that precision)."""
    x = float(x)
    return float(f"{x:.{digits}g}") if math.isfinite(x) else x


def coefficient_text(x: float, standard_error: float | None) -> str:
    """The literal of a coefficient, to the precision its standard error justifies
    (``SE_DIGITS``); :func:`decimal_text` when the standard error is unknown or zero."""
    if standard_error is None or not (math.isfinite(standard_error) and standard_error > 0):
        return decimal_text(x)
    if not math.isfinite(x):
        raise VerifyInputError(f"parameter value {x} is not finite")
    d = _quantized(x, math.floor(math.log10(standard_error)) - SE_DIGITS)
    if d == 0:
        return "0"
    text = f"{d:f}"  # positional: a TOML float or integer literal
    return text.rstrip("0").rstrip(".") if "." in text else text


def decimal_text(x: float, digits: int = DIGITS) -> str:
    """A short decimal literal near x (TOML syntax, exact as read back)."""
    if not math.isfinite(x):
        raise VerifyInputError(f"parameter value {x} is not finite")
    text = f"{x:.{digits}g}"
    if "e" in text or "." in text:
        mantissa, _, exponent = text.partition("e")
        if "." not in mantissa:
            mantissa += ".0"
        return mantissa + (f"e{int(exponent)}" if exponent else "")
    return text  # an integer literal


def structure_text(structure: Structure) -> str:
    """The ``--structure`` spelling of a structure ("paper", "P:Z", "order:N")."""
    if structure.kind == "paper":
        return "paper"
    if structure.kind == "poles_zeros":
        return f"{structure.poles}:{structure.zeros}"
    return f"order:{structure.states}"


def parse_structure(text: str, where: str = "--structure") -> Structure:
    """``paper``, ``P:Z`` (poles:zeros) or ``order:N``; one-line error otherwise."""
    body = str(text).strip()
    if body == "paper":
        return Structure.paper()
    head, sep, tail = body.partition(":")
    try:
        if sep and head == "order":
            return Structure.order(int(tail))
        if sep:
            return Structure.poles_zeros(int(head), int(tail))
    except ValueError:
        pass
    raise VerifyInputError(f"{where} {text!r}: expected paper, P:Z (poles:zeros, e.g. 2:1) "
                           "or order:N (e.g. order:4)")


def _toml_value(value: Any, key: str) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=True)
    if isinstance(value, int | np.integer):
        return str(int(value))
    if isinstance(value, float | np.floating):
        x = float(value)
        if not math.isfinite(x):
            raise VerifyInputError(f"[identification] {key}: {x} is not finite")
        text = repr(x)
        return text if any(c in text for c in ".en") else text + ".0"
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_toml_value(v, key) for v in value) + "]"
    raise VerifyInputError(f"[identification] {key}: cannot write {type(value).__name__}")


def element_values(structure: Structure, theta: Sequence[str]) -> tuple[list, list]:
    """(num, den) tables of the model file from the written parameter literals."""
    num, den = structure.transfer_matrix(list(theta))
    return num, den


def model_text(name: str, structure: Structure, theta: Sequence[float],
               identification: Mapping[str, Any], description: str = "") -> tuple[str,
                                                                                    list[str]]:
    """The model file's text and the written parameter literals (structure order)."""
    if not structure.diagonal_with_constant_coupling:
        raise VerifyInputError("the model writer handles the structures with constant "
                               "off-diagonal elements (paper, P:Z)")
    errors = identification.get("standard_errors")
    errors = list(errors) if errors is not None and len(errors) == len(theta) else \
        [None] * len(theta)
    literals = [coefficient_text(float(x), None if e is None else float(e))
                for x, e in zip(theta, errors, strict=True)]
    num, den = element_values(structure, literals)

    def table(rows) -> str:
        return "[" + ", ".join(
            "[" + ", ".join("[" + ", ".join(str(c) for c in e) + "]" for e in row) + "]"
            for row in rows) + "]"

    lines = [
        "# Identified by `verify identify` (paper, Section 4): the coefficients below are",
        "# the exact model (each decimal denotes itself); [identification] is descriptive.",
        f"name = {json.dumps(name)}",
    ]
    if description:
        lines.append(f"description = {json.dumps(description)}")
    lines += ["", "[transfer_function]", f"num = {table(num)}", f"den = {table(den)}",
              "", "[identification]"]
    for key, value in identification.items():
        if not key.replace("_", "").isalnum():
            raise VerifyInputError(f"[identification] key {key!r} is not a bare TOML key")
        lines.append(f"{key} = {_toml_value(value, key)}")
    return "\n".join(lines) + "\n", literals


@dataclass(frozen=True)
class IdentifiedFile:
    """A model file written by :func:`model_text`, read back."""

    model: LTIModel
    structure: Structure
    center: tuple[mpq, ...]
    identification: dict[str, Any]

    def covariance(self) -> np.ndarray:
        """The covariance as floats (each decimal rounded to its nearest float)."""
        rows = self.identification.get("covariance")
        p = len(self.center)
        try:
            cov = np.array([[float(Fraction(v)) for v in row] for row in rows], dtype=float)
        except (TypeError, ValueError):
            raise VerifyInputError(f"{self.model.source}: [identification] covariance must "
                                   f"be a {p} x {p} array of numbers") from None
        if cov.shape != (p, p):
            raise VerifyInputError(f"{self.model.source}: [identification] covariance must "
                                   f"be {p} x {p}, got {cov.shape}")
        return cov

    def region(self):
        """The confidence region of the file: centre = the written coefficients, Σ = the
        covariance's floats, level and χ² as recorded (:mod:`verify.identify.model.region`)."""
        from verify.identify.model.region import make_region

        level = self.identification.get("confidence_level")
        if isinstance(level, bool) or not isinstance(level, Fraction | int | float):
            raise VerifyInputError(f"{self.model.source}: [identification] confidence_level "
                                   "must be a number")
        return make_region(self.center, self.covariance(), Fraction(level),
                           self.number("chi2"))

    def number(self, key: str) -> float:
        value = self.identification.get(key)
        if isinstance(value, bool) or not isinstance(value, int | float | Fraction):
            raise VerifyInputError(f"{self.model.source}: [identification] {key} must be a "
                                   "number")
        return float(Fraction(value))


def _quantized(x: float, place: int) -> Decimal:
    """x's exact decimal value rounded to the place 10^place (half to even)."""
    return Decimal(repr(float(x))).quantize(Decimal(1).scaleb(place), rounding=ROUND_HALF_EVEN)


def _on_grid(x: float, scale: float, digits: int) -> float:
    """x rounded to the decimal grid 10^(floor(log10 scale) - digits) (half to even)."""
    if not scale > 0:
        return 0.0
    return float(_quantized(x, math.floor(math.log10(scale)) - digits)) + 0.0  # no -0.0


def canonical_covariance(cov: np.ndarray) -> list[list[float]]:
    """The covariance as written: entry (i, j) on the decimal grid d decades below
    sqrt(C_ii C_jj), i.e. the correlations to d decimals. d is the smallest of at least
    ``COVARIANCE_DIGITS`` for which the rounding moves the correlation matrix's eigenvalues
    by at most 1 % of the smallest (Weyl: p 10^-d / 2 <= lambda_min / 100), so the region
    keeps its shape in its thinnest direction; a matrix that is then not exactly positive
    definite gets more digits. Float noise in the estimate (another BLAS, another
    summation order) moves entries by parts in 1e8 and leaves the written decimals."""
    from gmpy2 import mpq

    from verify.passivity.check.robust_band import is_positive_definite

    p = len(cov)
    scale = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    with np.errstate(divide="ignore", invalid="ignore"):
        corr = cov / np.outer(scale, scale)
    smallest = float(np.min(np.linalg.eigvalsh(corr))) if np.all(scale > 0) else 0.0
    need = math.ceil(math.log10(50 * p / smallest)) if smallest > 0 else 16
    rows: list[list[float]] = []
    for digits in range(max(COVARIANCE_DIGITS, need), 17):
        rows = [[_on_grid(cov[i, j], scale[i] * scale[j], digits) for j in range(p)]
                for i in range(p)]
        if is_positive_definite([[mpq(v) for v in row] for row in rows]):
            return rows
    return rows


def identification_table(structure: Structure, theta: Sequence[float], covariance: Any,
                         level: Fraction, extra: Mapping[str, Any] | None = None
                         ) -> dict[str, Any]:
    """The ``[identification]`` table: ``extra`` (method, rate, split, fit ratios, residual
    tests, ...) then the parameters, their standard errors, the covariance (symmetrised),
    the confidence level and its chi-square value."""
    from verify.identify.model.region import chi2_quantile

    cov = np.asarray(covariance, dtype=float)
    cov = (cov + cov.T) / 2
    p = len(theta)
    if cov.shape != (p, p) or not np.all(np.isfinite(cov)):
        raise VerifyInputError(f"covariance: expected a finite {p} x {p} matrix")
    errors = [float(math.sqrt(max(v, 0.0))) for v in np.diag(cov)]
    return {**dict(extra or {}), "structure": structure_text(structure),
            "parameter_names": list(structure.names()),
            "parameter_estimates": [float(coefficient_text(float(x), e))
                                    for x, e in zip(theta, errors, strict=True)],
            "standard_errors": [canonical(e) for e in errors],
            "covariance": canonical_covariance(cov),
            "confidence_level": float(level),
            "chi2": canonical(chi2_quantile(level, p), 12)}


def write_identified_model(path: str | Path, *, name: str, structure: Structure,
                           theta: Sequence[float], covariance: Any,
                           level: Fraction = Fraction(19, 20),
                           extra: Mapping[str, Any] | None = None,
                           description: str = "") -> IdentifiedFile:
    """Write the model file atomically and read it back (what the file says is the model)."""
    from verify.artefacts.atomic import write_atomic

    table = identification_table(structure, theta, covariance, level, extra)
    text, _ = model_text(name, structure, theta, table, description)
    write_atomic(Path(path), text)
    return read_identified(path)


def structure_coefficients(table: dict[str, Any], structure: Structure, source: str) -> list:
    """θc from the raw [transfer_function] table, in structure order; checks the layout."""
    num, den = table["num"], table["den"]
    try:
        theta = []
        for i in range(2):
            b, a = num[i][i], den[i][i]
            if len(b) != structure.zeros + 1 or len(a) != structure.poles + 1 or a[0] != 1:
                raise ValueError
            theta += list(b) + list(a[1:])
        c12, c21 = num[0][1], num[1][0]
        if den[0][1] != [1] or den[1][0] != [1] or len(c12) != 1 or len(c21) != 1:
            raise ValueError
        theta += [c12[0], c21[0]]
    except (ValueError, IndexError, TypeError, KeyError):
        raise VerifyInputError(f"{source}: [transfer_function] does not have the layout of "
                               "the identified structure (monic diagonal denominators, "
                               "constant off-diagonal elements)") from None
    return theta


def read_identified(path: str | Path) -> IdentifiedFile:
    """Read a model file with an ``[identification]`` table naming its structure."""
    path = Path(path)
    data = read_toml(path, exact=True)
    model = parse_model(data, str(path))
    ident = model.meta.get("identification")
    if not isinstance(ident, dict) or not isinstance(ident.get("structure"), str):
        raise VerifyInputError(f"{path}: no [identification] table with a structure")
    structure = parse_structure(ident["structure"], f"{path}: [identification] structure")
    if "transfer_function" not in data:
        raise VerifyInputError(f"{path}: an identified model is a [transfer_function]")
    theta = structure_coefficients(data["transfer_function"], structure, str(path))
    from verify.inputs.numbers import rational

    center = tuple(rational(x, f"{path}: coefficient") for x in theta)
    return IdentifiedFile(model, structure, center, ident)


__all__ = ["COVARIANCE_DIGITS", "DIGITS", "FIGURE_DIGITS", "SE_DIGITS", "IdentifiedFile",
           "canonical", "coefficient_text", "decimal_text", "identification_table", "model_text",
           "parse_structure", "read_identified", "structure_coefficients", "structure_text",
           "write_identified_model"]
