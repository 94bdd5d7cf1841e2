"""The one rational type of model data and the one conversion into it.

Every number of a model denotes an exact rational (DESIGN, "The exact machinery must see
the input as written"):

* an integer (Python ``int``, a NumPy integer, a TOML integer) is that integer;
* a binary float (Python ``float``, a NumPy float: python-control, scipy and NumPy data)
  is the dyadic rational it stores, e.g. ``0.1`` is 3602879701896397 / 2^55;
* a decimal literal of a model file (TOML ``0.1``, ``2.5e-3``, ``1_000.5``) is the
  decimal value it spells, e.g. ``0.1`` is 1/10 (:func:`decimal_literal`, the
  ``parse_float`` hook of :func:`verify.toml_input.read_toml`);
* ``fractions.Fraction`` and ``gmpy2.mpq`` values are themselves.

The type is gmpy2's ``mpq`` (:data:`Rational`). Floating point appears only in the
other direction, as a *view* for numerical proposals (:func:`to_float`): it rounds to
nearest and saturates to +-inf outside the float range, so a view never raises.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction
from typing import Any

import numpy as np
from gmpy2 import mpq

from verify.errors import VerifyInputError

Rational = type(mpq(0))

#: Largest accepted |exponent| of a decimal literal: beyond it an exact value would have
#: thousands of digits (the same bound as Python's default limit on integer digits).
MAX_DECIMAL_EXPONENT = 4300

_DECIMAL = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def decimal_literal(text: str) -> Fraction | float:
    """The exact value of a TOML float literal (the ``tomllib`` ``parse_float`` hook).

    ``nan`` and ``inf`` come back as floats, so that the validation of the model refuses
    them by location; an exponent beyond +-``MAX_DECIMAL_EXPONENT`` raises ValueError.

    >>> decimal_literal("0.1"), decimal_literal("1_000.5e-3")
    (Fraction(1, 10), Fraction(2001, 2000))
    """
    plain = text.replace("_", "")  # TOML allows underscores only between digits
    if plain.lstrip("+-") in ("inf", "nan"):
        return float(plain)
    match = _DECIMAL.fullmatch(plain)
    if match is None:  # tomllib has checked the syntax; this is a guard
        raise ValueError(f"not a decimal number: {text!r}")
    if match.group(2) and abs(int(match.group(2)[1:])) > MAX_DECIMAL_EXPONENT:
        raise ValueError(
            f"decimal {text} has an exponent beyond +-{MAX_DECIMAL_EXPONENT}"
        )
    return Fraction(plain)


def rational(value: Any, where: str) -> Rational:
    """The exact rational a number denotes (module docstring); one-line error otherwise.

    Refused: bool, text, None, complex with a non-zero imaginary part, NaN and Inf.
    """
    if isinstance(value, Rational):
        return value
    if isinstance(value, complex | np.complexfloating) and value.imag == 0:
        value = value.real
    if isinstance(value, bool | np.bool_):
        raise VerifyInputError(f"{where}: expected a real number, got bool {_short(value)}")
    if isinstance(value, int | np.integer):
        return mpq(int(value))
    if isinstance(value, Fraction):
        return mpq(value.numerator, value.denominator)
    if isinstance(value, float | np.floating):
        if not np.isfinite(value):
            raise VerifyInputError(f"{where}: NaN or Inf is not allowed")
        p, q = value.as_integer_ratio()  # exact for every width, longdouble included
        return mpq(p, q)
    raise VerifyInputError(
        f"{where}: expected a real number, got {type(value).__name__} {_short(value)}"
    )


def to_float(q: Rational) -> float:
    """Nearest float to q (correctly rounded), +-inf beyond the float range; never raises."""
    try:
        return int(q.numerator) / int(q.denominator)
    except OverflowError:
        return math.inf if q > 0 else -math.inf


def float_view(M: list[list[Rational]], rows: int, cols: int) -> np.ndarray:
    """A float64 array of a rational matrix (shape given, so empty matrices keep it)."""
    out = np.empty((rows, cols), dtype=np.float64)
    for i, row in enumerate(M):
        for j, x in enumerate(row):
            out[i, j] = to_float(x)
    return out


__all__ = ["MAX_DECIMAL_EXPONENT", "Rational", "decimal_literal", "float_view", "rational",
           "to_float"]
