"""Text of exact numbers of any size: the output side of :mod:`verify.inputs.numbers`.

A model file may hold decimals up to 10^+-4300 and the gate's exact rescaling multiplies
them by powers of two, so an exact number written to a certificate, a file name, JSON or
a message can exceed both Python's int-to-str digit limit (4300 digits) and the float
range (about 1.8e308). These two functions never raise on any rational:

* :func:`exact_text`: "p" or "p/q" in lowest terms, any number of digits (gmpy2 prints
  integers without Python's digit limit);
* :func:`approx_text`: a short decimal for people and file names, at any exponent;
  inside the float range it is the text ``format(float(x), spec)`` gives.

Where exact numbers are written by code that uses ``str`` (Fractions in messages and
JSON), :func:`unlimited_int_text` lifts the digit limit around work on numbers that the
input layer has already validated (the gate's decisions, a certificate's re-check after
its strict parse).
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from fractions import Fraction
from typing import Any

from gmpy2 import mpq


def exact_text(x: Any) -> str:
    """``x`` (int, Fraction, mpq) as "p" or "p/q" in lowest terms, of any size."""
    return str(mpq(x))


def approx_text(x: Any, digits: int = 6) -> str:
    """``x`` rounded to ``digits`` significant digits in ``g`` style ("1e-08", "-1e+400").

    Inside the float range (normal floats) this is ``format(float(x), f".{digits}g")``;
    outside it the exact value is rounded to ``digits`` digits with integers only, so
    10^400 is "1e+400" rather than an OverflowError and 10^-400 is "1e-400" rather
    than "0".
    """
    q = _fraction(x)
    f = float_or_none(q)
    if f is not None and (f == 0.0 or abs(f) >= _SMALLEST_NORMAL):
        return format(f, f".{digits}g")
    num, den = abs(q.numerator), q.denominator
    e = int((num.bit_length() - den.bit_length()) * _LOG10_2)  # within 1 of log10|x|
    while _scaled(num, den, -e) >= 1:
        e += 1
    while _scaled(num, den, -e) < Fraction(1, 10):
        e -= 1
    e -= 1  # now 10^e <= |x| < 10^(e + 1)
    m = round(_scaled(num, den, digits - 1 - e))  # half to even
    if m == 10**digits:
        m, e = m // 10, e + 1
    text = str(m)
    mantissa = (text[0] + "." + text[1:]).rstrip("0").rstrip(".")
    return f"{'-' if q < 0 else ''}{mantissa}e{'+' if e >= 0 else '-'}{abs(e):02d}"


_SMALLEST_NORMAL = 2.2250738585072014e-308
_LOG10_2 = 0.30102999566398120


def _fraction(x: Any) -> Fraction:
    if isinstance(x, Fraction):
        return x
    if hasattr(x, "p") and hasattr(x, "q"):  # python-flint's fmpq
        return Fraction(int(x.p), int(x.q))
    r = mpq(x)
    return Fraction(int(r.numerator), int(r.denominator))


def _scaled(num: int, den: int, k: int) -> Fraction:
    """num/den * 10^k, exactly."""
    return Fraction(num * 10**k, den) if k >= 0 else Fraction(num, den * 10**-k)


def short_text(x: Any, limit: int = 24) -> str:
    """The exact text of ``x`` when it has at most ``limit`` characters, else "≈ " and
    its :func:`approx_text` (for one-line summaries)."""
    text = exact_text(x)
    return text if len(text) <= limit else f"≈ {approx_text(x, 6)}"


@contextmanager
def unlimited_int_text() -> Iterator[None]:
    """Lift Python's int-to-str digit limit for a block of work on validated numbers.

    The limit guards *parsing* untrusted text (quadratic int(str)); inside this block no
    untrusted text is parsed, only numbers the input layer has already bounded (decimal
    exponents up to 4300) and their exact products, which may exceed 4300 digits when
    written (str of a Fraction, JSON). The previous limit is restored on exit.
    """
    old = sys.get_int_max_str_digits()
    sys.set_int_max_str_digits(0)
    try:
        yield
    finally:
        sys.set_int_max_str_digits(old)


def float_or_none(x: Any) -> float | None:
    """``float(x)`` when it is finite and, for x != 0, not rounded to 0; else None (JSON
    keeps the exact text beside it)."""
    q = _fraction(x)
    try:
        f = float(q)
    except OverflowError:
        return None
    if q != 0 and f == 0.0:
        return None
    return f


__all__ = ["approx_text", "exact_text", "float_or_none", "short_text", "unlimited_int_text"]
