"""Reading TOML input files (network and model files): numbers-only data, never evaluated."""

from __future__ import annotations

import tomllib
from pathlib import Path

from verify.errors import VerifyInputError


def read_toml(path: str | Path) -> dict:
    """Parse a TOML input file; unreadable or invalid files are one-line VerifyInputErrors."""
    path = Path(path)
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise VerifyInputError(f"{path}: cannot read ({exc.strerror})") from None
    try:
        return tomllib.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        message = " ".join(str(exc).split())
        raise VerifyInputError(f"{path}: not valid TOML ({message})") from None
