"""Numbers and numeric arrays: the one rational type, and the exact and float conversions.

Every number of a model denotes an exact rational (DESIGN, "The exact machinery must see
the input as written"):

* an integer (Python ``int``, a NumPy integer, a TOML integer) is that integer;
* a binary float (Python ``float``, a NumPy float: python-control, scipy and NumPy data)
  is the dyadic rational it stores, e.g. ``0.1`` is 3602879701896397 / 2^55;
* a decimal literal of a model file (TOML ``0.1``, ``2.5e-3``, ``1_000.5``) is the
  decimal value it spells, e.g. ``0.1`` is 1/10 (:func:`decimal_literal`, the
  ``parse_float`` hook of :func:`verify.inputs.toml.read_toml`);
* ``fractions.Fraction`` and ``gmpy2.mpq`` values are themselves.

The type is gmpy2's ``mpq`` (:data:`Rational`). Floating point appears only in the
other direction, as a *view* for numerical proposals (:func:`to_float`): it rounds to
nearest and saturates to +-inf outside the float range, so a view never raises.

Two flavours validate an input: the exact one (:func:`rational`, :func:`exact_array`)
for data the exact machinery decides on, and the float one (:func:`real`,
:func:`positive_real`, :func:`real_array`) for data that only simulations and
numerical proposals read. Both refuse bool, text, NaN and Inf with one line naming the
argument, the value and the fix; :func:`parse_number` reads a command-line number;
:func:`strict_rational` reads a certificate's number (one spelling per value).

Limits, checked on the text before any conversion: a decimal literal has at most
``MAX_DECIMAL_DIGITS`` = 4000 digits counting the size of its exponent, and an exponent
of at most ``MAX_DECIMAL_EXPONENT`` = 4300 in size (so ``1e99999999`` is refused at
once); a strict rational has at most ``MAX_STRICT_CHARS`` = 100 000 characters.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction
from typing import Any

import numpy as np
from gmpy2 import mpq

from verify.errors import VerifyInputError
from verify.validation import shown

Rational = type(mpq(0))

#: Largest accepted |exponent| of a decimal literal: beyond it an exact value would have
#: thousands of digits (the same bound as Python's default limit on integer digits).
MAX_DECIMAL_EXPONENT = 4300
#: Most digits of a decimal literal's exact value: the mantissa's digits plus the size of
#: its exponent (so numerator and denominator stay printable, below Python's 4300).
MAX_DECIMAL_DIGITS = 4000
#: Most characters of a strict rational "p" or "p/q" (:func:`strict_rational`).
MAX_STRICT_CHARS = 100_000

_STRICT = re.compile(r"-?(0|[1-9][0-9]*)(/[1-9][0-9]*)?")
_EXPONENT_DIGITS = 12  # an exponent written with more digits is beyond any bound above

_DECIMAL = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


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
    exponent = (match.group(2) or "e0")[1:].lstrip("+-").lstrip("0") or "0"
    if len(exponent) > _EXPONENT_DIGITS or int(exponent) > MAX_DECIMAL_EXPONENT:
        raise ValueError(f"decimal {_brief(text)} has an exponent beyond "
                         f"+-{MAX_DECIMAL_EXPONENT}")
    digits = len(match.group(1)) - ("." in match.group(1)) + int(exponent)
    if digits > MAX_DECIMAL_DIGITS:
        raise ValueError(f"decimal {_brief(text)} would have {digits} digits, more than "
                         f"{MAX_DECIMAL_DIGITS}")
    power = -int(exponent) if (match.group(2) or "e")[1:2] == "-" else int(exponent)
    mantissa = Fraction(("-" if plain.startswith("-") else "") + match.group(1))
    return mantissa * Fraction(10) ** power


class WrittenDecimal(Fraction):
    """The exact value of a decimal literal that prints as it was written.

    ``WrittenDecimal("-1.0")`` equals ``Fraction(-1)`` in every comparison and operation
    (results of arithmetic are plain Fractions), but ``str`` and ``repr`` give ``-1.0``,
    so a message quotes the user's number, not ``Fraction(-1, 1)``. Made by
    :func:`written_decimal`, the ``parse_float`` hook for specs.
    """

    _text: str

    def __new__(cls, value: Fraction, text: str) -> WrittenDecimal:
        self = super().__new__(cls, value.numerator, value.denominator)
        self._text = text
        return self

    def __repr__(self) -> str:
        return self._text

    __str__ = __repr__

    def __reduce__(self):  # pickles (and copies) as the plain value
        return (Fraction, (self.numerator, self.denominator))


def written_decimal(text: str) -> WrittenDecimal | float:
    """:func:`decimal_literal`, keeping the text for messages (:class:`WrittenDecimal`)."""
    value = decimal_literal(text)
    return WrittenDecimal(value, _brief(text)) if isinstance(value, Fraction) else value


def _brief(text: str, width: int = 40) -> str:
    return text if len(text) <= width else f"{text[:20]}...{text[-10:]} ({len(text)} chars)"


def strict_rational(text: Any, where: str, *, max_chars: int = MAX_STRICT_CHARS) -> Rational:
    """A certificate number: an integer "p" or a reduced fraction "p/q" with q > 1.

    The one spelling of each rational (Python's ``str`` of a Fraction): no sign but a
    leading "-", no leading zeros, no whitespace, no decimal point or exponent, no "-0",
    "3/1", "2/4" or "-2/2". One spelling per value keeps a certificate's bytes a function
    of its content, and refusing exponents bounds the work a file can ask for: the text
    is at most ``max_chars`` characters, checked before it is converted. Anything else is
    a one-line :class:`VerifyInputError` naming ``where``.

    >>> strict_rational("-3/4", "x"), strict_rational("12", "x")
    (mpq(-3,4), mpq(12,1))
    """
    if not isinstance(text, str):
        raise VerifyInputError(f"{where}: expected a rational as a string 'p' or 'p/q', got "
                               f"{type(text).__name__}")
    if len(text) > max_chars:
        raise VerifyInputError(f"{where}: a number of {len(text)} characters is not a "
                               f"rational this reader accepts (at most {max_chars})")
    if not _STRICT.fullmatch(text):
        raise VerifyInputError(f"{where}: {_brief(text)!r} is not a rational 'p' or 'p/q' "
                               "(an integer or a fraction of integers, no spaces, decimals "
                               "or exponents)")
    value = mpq(text)
    if str(value) != text:
        raise VerifyInputError(f"{where}: {_brief(text)!r} is not in lowest terms with a "
                               f"positive denominator > 1; write {_brief(str(value))}")
    return value


def rational(value: Any, where: str) -> Rational:
    """The exact rational a number denotes (module docstring); one-line error otherwise.

    Refused: bool, text, None, complex with a non-zero imaginary part, NaN and Inf.
    ``where`` names the argument (a flag, or a file and the entry's index).
    """
    if isinstance(value, Rational):
        return value
    if isinstance(value, complex | np.complexfloating) and value.imag == 0:
        value = value.real
    if isinstance(value, bool | np.bool_):
        raise VerifyInputError(f"{where}: expected a real number, got bool {shown(value)}; write a "
                               "number such as 1 or 0.5 (true/false are not numbers)")
    if isinstance(value, int | np.integer):
        return mpq(int(value))
    if isinstance(value, Fraction):
        return mpq(value.numerator, value.denominator)
    if isinstance(value, float | np.floating):
        if not np.isfinite(value):
            raise VerifyInputError(f"{where}: NaN or Inf is not allowed (got {value}); give a "
                                   "finite number")
        p, q = value.as_integer_ratio()  # exact for every width, longdouble included
        return mpq(p, q)
    raise VerifyInputError(
        f"{where}: expected a real number, got {type(value).__name__} {shown(value)}; write a "
        "number such as 1 or 0.5, without quotes"
    )


def real(value: Any, where: str) -> float:
    """The float flavour of :func:`rational`: the nearest float, refusing what overflows."""
    q = rational(value, where)
    x = to_float(q)
    if not math.isfinite(x):
        raise VerifyInputError(f"{where}: {shown(value)} is too large for a float; give a "
                               "number below 1.8e308 in size")
    if x == 0 and q != 0:
        raise VerifyInputError(f"{where}: {shown(value)} is too small for a float (it rounds "
                               "to 0); give 0 or a number of at least 2.2e-308 in size")
    return x


def positive_real(value: Any, where: str, fix: str = "give a number > 0") -> float:
    """A finite float > 0 (gains, durations, steps); ``fix`` ends the error message."""
    x = real(value, where)
    if not x > 0:
        raise VerifyInputError(f"{where} must be a positive number, got {shown(value)}; {fix}")
    return x


def parse_number(text: str, where: str, example: str) -> Fraction:
    """A command-line number as the exact rational it spells ("0.01", "1e-8", "1/100").

    A decimal denotes the decimal it spells, as in model files; NaN, Inf, text and
    exponents beyond +-``MAX_DECIMAL_EXPONENT`` are one-line errors naming ``where`` and
    suggesting ``example``.
    """
    body = str(text).strip()
    try:
        if "/" in body:
            value = Fraction(body)
        else:
            value = decimal_literal(body)
            if not isinstance(value, Fraction):
                raise ValueError
    except (ValueError, ZeroDivisionError):
        raise VerifyInputError(
            f"{where} {text!r} is not a finite number (or its exponent is beyond "
            f"+-{MAX_DECIMAL_EXPONENT}); write e.g. {example}"
        ) from None
    return value


def fraction(q: Any) -> Fraction:
    """``q`` as a ``fractions.Fraction``, exactly: the one conversion to the standard type.

    Accepts any rational with integer ``numerator`` and ``denominator`` (gmpy2 ``mpq``,
    python-flint ``fmpq``, sympy ``Rational`` and its polynomial domain ``QQ``), ints,
    Fractions, and a binary float as the dyadic rational it stores. For code that needs
    ``Fraction``'s methods (``limit_denominator``) or hands values to sympy.
    """
    if isinstance(q, Fraction):
        return q
    if isinstance(q, float):
        return Fraction(q)
    return Fraction(int(q.numerator), int(q.denominator))


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


def _nan_index(arr: np.ndarray, where: str) -> None:
    """Refuse NaN and Inf in a float array, naming the first bad entry by index."""
    bad = np.argwhere(~np.isfinite(arr))
    if bad.size:
        index = "".join(f"[{k}]" for k in bad[0])
        raise VerifyInputError(f"{where}{index}: NaN or Inf is not allowed (got "
                               f"{arr[tuple(bad[0])]}); give a finite number")


def _map(nested: Any, f) -> Any:
    return [_map(v, f) for v in nested] if isinstance(nested, list) else f(nested)


def exact_array(value: Any, where: str) -> tuple[Any, tuple[int, ...]]:
    """Nested lists of exact rationals and their shape (ragged nesting refused).

    Every number is converted by :func:`rational`: integers exactly, binary floats as
    the dyadic rationals they store, Fractions as they are; an entry's error names it
    by index (``where[i][j]``).
    """
    if isinstance(value, np.ndarray):
        shape = value.shape
        if value.dtype.kind in "iuf":
            if value.dtype.kind == "f":
                _nan_index(value, where)
            if value.dtype.itemsize <= 8:  # to Python int / float, exactly
                return _map(value.tolist(), mpq), shape
            return _map(value.tolist(), lambda x: rational(x, where)), shape
        nested, inner = exact_array(value.tolist(), where)
        return nested, shape if value.size else inner
    if isinstance(value, list | tuple):
        parts = [exact_array(v, f"{where}[{i}]") for i, v in enumerate(value)]
        shapes = {s for _, s in parts}
        if len(shapes) > 1:
            raise VerifyInputError(f"{where}: ragged nesting (rows of different lengths); "
                                   "give every row the same length")
        inner = shapes.pop() if shapes else ()
        return [x for x, _ in parts], (len(parts), *inner)
    return rational(value, where), ()


def _shape_text(shape: tuple[int | None, ...]) -> str:
    names = ["n" if k is None else str(k) for k in shape]
    return "(" + ", ".join(names) + ("," if len(names) == 1 else "") + ")"


def real_array(value: Any, where: str, shape: tuple[int | None, ...] | None = None
               ) -> np.ndarray:
    """The float flavour of :func:`exact_array`: a finite float64 array of any rank.

    ``shape``, if given, is the expected shape (``None`` for a free length).
    """
    if isinstance(value, np.ndarray) and value.dtype.kind in "iuf":
        arr = np.array(value, dtype=float)
        _nan_index(arr, where)
    else:
        nested, got = exact_array(value, where)
        arr = np.array(_map(nested, lambda q: real(q, where)), dtype=float).reshape(got)
    if shape is not None and (arr.ndim != len(shape) or any(
            k is not None and k != g for k, g in zip(shape, arr.shape, strict=True))):
        raise VerifyInputError(f"{where}: expected shape {_shape_text(shape)}, got "
                               f"{arr.shape}; give one entry of that shape per item")
    return arr


__all__ = ["MAX_DECIMAL_DIGITS", "MAX_DECIMAL_EXPONENT", "MAX_STRICT_CHARS", "Rational",
           "decimal_literal", "exact_array", "float_view", "fraction", "parse_number",
           "positive_real", "rational", "real", "real_array", "strict_rational", "to_float",
           "written_decimal"]
