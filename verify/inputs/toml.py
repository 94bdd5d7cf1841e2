"""Reading TOML input files (network and model files): numbers-only data, never evaluated."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

from verify.errors import VerifyInputError
from verify.inputs.files import MAX_FILE_BYTES, read_bounded
from verify.inputs.number_text import unlimited_int_text
from verify.inputs.numbers import decimal_literal, written_decimal

#: The most digits (underscores included) in one run of a TOML file: an integer of up
#: to this many digits is read exactly, beyond Python's default limit of 4300 (reading
#: an integer takes time quadratic in its digits, so the bound keeps a 16 MiB file of
#: digits from taking hours).
MAX_DIGIT_RUN = 20_000
_DIGIT_RUN = re.compile(rf"[0-9_]{{{MAX_DIGIT_RUN + 1},}}")


def _check_digit_runs(text: str, where: str) -> None:
    found = _DIGIT_RUN.search(text)
    if found is not None:
        line = text.count("\n", 0, found.start()) + 1
        raise VerifyInputError(f"{where}: line {line}: a number with more than "
                               f"{MAX_DIGIT_RUN} digits; integers of up to {MAX_DIGIT_RUN} "
                               "digits are read exactly")


def read_toml(path: str | Path, *, exact: bool = False, written: bool = False,
              max_bytes: int = MAX_FILE_BYTES, where: str | None = None) -> dict:
    """Parse a TOML input file; unreadable or invalid files are one-line VerifyInputErrors.

    With ``exact``, a decimal literal becomes the exact ``Fraction`` it spells
    (:func:`verify.inputs.numbers.decimal_literal`; ``nan``/``inf`` stay floats for the
    caller to refuse by location); with ``written`` as well, it prints as written
    (:class:`~verify.inputs.numbers.WrittenDecimal`, for messages). TOML integers are
    Python ints either way. The path must name a regular file of at most ``max_bytes``
    bytes (:func:`verify.inputs.files.read_bounded`: a FIFO or ``/dev/zero`` is refused,
    not read); ``where`` prefixes messages (default: the path).
    """
    path = Path(path)
    where = str(path) if where is None else where
    raw = read_bounded(path, where=where, max_bytes=max_bytes)
    return parse_toml_bytes(raw, where, exact=exact, written=written)


def parse_toml_bytes(raw: bytes, where: str, *, exact: bool = False,
                     written: bool = False) -> dict:
    """:func:`read_toml` on bytes already read; messages start with ``where``."""
    parse_float = (written_decimal if written else decimal_literal) if exact else float
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise VerifyInputError(f"{where}: not valid TOML ({exc})") from None
    _check_digit_runs(text, where)
    try:
        with unlimited_int_text():  # integers of any size up to the bound just checked
            return tomllib.loads(text, parse_float=parse_float)
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        message = " ".join(str(exc).split())
        raise VerifyInputError(f"{where}: not valid TOML ({message})") from None
    except ValueError as exc:  # an integer beyond Python's digit limit, a huge exponent
        message = " ".join(str(exc).split())
        raise VerifyInputError(f"{where}: number out of range ({message})") from None
