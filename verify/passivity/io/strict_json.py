"""Strict reading of certificate JSON: one meaning per file, or a one-line refusal.

RFC 8259 leaves duplicate object keys to the parser; Python's :mod:`json` keeps the last
one, so ``{"P": good, "P": bad}`` would be read as whichever comes second, and a reader
with another parser could see the other. Certificates must mean one thing, so a duplicate
key anywhere is an error, as are the non-standard constants ``NaN`` and ``Infinity``, a
top level that is not an object, and (through :func:`fields`) unknown or missing fields.
Every error is a :class:`CertificateFormatError` whose text is one line.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from gmpy2 import mpq


class CertificateFormatError(ValueError):
    """A certificate file that cannot be read as its schema says (one-line message)."""


def _no_duplicates(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in pairs:
        if key in out:
            raise CertificateFormatError(f"duplicate key {key!r}")
        out[key] = value
    return out


def _no_constant(name: str) -> Any:
    raise CertificateFormatError(f"non-standard JSON constant {name}")


def loads_strict(text: str) -> dict[str, Any]:
    """Parse ``text`` as a JSON object; duplicate keys and NaN/Infinity are errors."""
    try:
        data = json.loads(text, object_pairs_hook=_no_duplicates, parse_constant=_no_constant)
    except json.JSONDecodeError as exc:
        raise CertificateFormatError(f"not valid JSON ({exc})") from None
    except RecursionError:
        raise CertificateFormatError("not valid JSON (nested too deeply)") from None
    if not isinstance(data, dict):
        raise CertificateFormatError(f"the top level is a JSON {type(data).__name__}, "
                                     "not an object")
    return data


MAX_CERTIFICATE_BYTES = 256 * 2**20  # far above any certificate written here


def read_strict(path: Path) -> dict[str, Any]:
    """Read and parse a certificate file strictly (see :func:`loads_strict`)."""
    from verify.errors import VerifyInputError
    from verify.inputs.files import read_bounded

    try:  # a regular file of bounded size: a FIFO or a device is refused unread
        text = read_bounded(path, where="", max_bytes=MAX_CERTIFICATE_BYTES).decode("utf-8")
    except VerifyInputError as exc:
        raise CertificateFormatError(str(exc).removeprefix(": ")) from None
    except UnicodeDecodeError:
        raise CertificateFormatError("not UTF-8 text") from None
    return loads_strict(text)


def fields(data: Mapping[str, Any], *, required: Iterable[str], optional: Iterable[str] = (),
           where: str = "") -> None:
    """Refuse unknown and missing fields of a JSON object, by name."""
    required, optional = set(required), set(optional)
    prefix = f"{where}: " if where else ""
    unknown = sorted(set(data) - required - optional)
    if unknown:
        raise CertificateFormatError(
            f"{prefix}unknown field(s) {', '.join(map(repr, unknown))}; allowed: "
            f"{', '.join(sorted(required | optional))}")
    missing = sorted(required - set(data))
    if missing:
        raise CertificateFormatError(f"{prefix}missing field(s) {', '.join(map(repr, missing))}")


def text_field(data: Mapping[str, Any], key: str) -> str:
    """A field that must be a JSON string."""
    value = data[key]
    if not isinstance(value, str):
        raise CertificateFormatError(f"field {key!r} must be a string, got "
                                     f"{type(value).__name__}")
    return value


MAX_DIGITS = 100_000  # far above any certificate written here; bounds the work per entry


def rational(value: Any, where: str) -> mpq:
    """An exact rational written canonically, "p" or "p/q" in lowest terms with q > 1.

    The input layer's one strict parser (:func:`verify.inputs.numbers.strict_rational`):
    one spelling per number keeps a certificate's bytes a function of its content, and
    refusing exponents ("1e999999999") bounds the work a hostile file can ask for.
    """
    from verify.errors import VerifyInputError
    from verify.inputs.numbers import strict_rational

    try:
        return strict_rational(value, where, max_chars=MAX_DIGITS)
    except VerifyInputError as exc:
        raise CertificateFormatError(str(exc)) from None


def rational_matrix(value: Any, where: str, rows: int | None = None,
                    cols: int | None = None) -> list[list[mpq]]:
    """A matrix of canonical rationals, list of rows; optional exact shape."""
    if not isinstance(value, list) or any(not isinstance(row, list) for row in value):
        raise CertificateFormatError(f"{where}: expected a list of rows")
    if rows is not None and len(value) != rows:
        raise CertificateFormatError(f"{where}: expected {rows} row(s), got {len(value)}")
    width = cols if cols is not None else (len(value[0]) if value else 0)
    for i, row in enumerate(value):
        if len(row) != width:
            raise CertificateFormatError(f"{where}: row {i} has {len(row)} entries, "
                                         f"expected {width}")
    return [[rational(x, f"{where}[{i}][{j}]") for j, x in enumerate(row)]
            for i, row in enumerate(value)]


__all__ = ["CertificateFormatError", "fields", "loads_strict", "rational", "rational_matrix",
           "read_strict", "text_field"]
