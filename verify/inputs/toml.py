"""Reading TOML input files (network and model files): numbers-only data, never evaluated."""

from __future__ import annotations

import tomllib
from pathlib import Path

from verify.errors import VerifyInputError
from verify.inputs.numbers import decimal_literal


def read_toml(path: str | Path, *, exact: bool = False) -> dict:
    """Parse a TOML input file; unreadable or invalid files are one-line VerifyInputErrors.

    With ``exact``, a decimal literal becomes the exact ``Fraction`` it spells
    (:func:`verify.inputs.numbers.decimal_literal`; ``nan``/``inf`` stay floats for the
    caller to refuse by location); TOML integers are Python ints either way.
    """
    path = Path(path)
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise VerifyInputError(f"{path}: cannot read ({exc.strerror})") from None
    parse_float = decimal_literal if exact else float
    try:
        return tomllib.loads(raw.decode("utf-8"), parse_float=parse_float)
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        message = " ".join(str(exc).split())
        raise VerifyInputError(f"{path}: not valid TOML ({message})") from None
    except ValueError as exc:  # an integer beyond Python's digit limit, a huge exponent
        message = " ".join(str(exc).split())
        raise VerifyInputError(f"{path}: number out of range ({message})") from None
