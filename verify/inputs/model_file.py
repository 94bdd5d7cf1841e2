"""Model files: a human model H(s) as TOML, numbers only, read as a document.

The input layer's half of a model file: the bytes are read (bounded), parsed as TOML with
exact numbers, and every key, table and descriptive field is validated here, giving a
:class:`ModelDocument`. The matrices it holds are then realised as an LTI model by
:mod:`verify.passivity.io.model_file` (shapes and exact values checked there, with
:mod:`verify.passivity.model`).

```toml
name = "optional label"            # default: the file name without suffix
description = "optional text"
k_s = 2.5                          # optional, a number > 0 (the gain of Section 4)
units = "optional text"
reconstructed = true               # optional bool: the model was reconstructed, not measured

[identification]                   # optional: how the model was identified (descriptive)
method = "refined instrumental variables"
fit_validation = [69.4, 66.15]
covariance = [[1e-4, 0.0], [0.0, 2e-4]]

# exactly one of the two tables:
[state_space]                      # continuous time; A = [] (then B = C = []) for n = 0
A = [[-1.0, 0.0], [0.0, -2.0]]
B = [[1.0], [1.0]]
C = [[1.0, 1.0]]
D = [[0.0]]

[transfer_function]                # element (i, j): coefficients, descending powers of s
num = [[[1.2, 0.8], [0.05]], [[-0.05], [1.2, 0.8]]]
den = [[[1.0, 2.0, 1.5], [1.0]], [[1.0], [1.0, 2.0, 1.5]]]
```

Every number denotes its exact value: an integer is that integer (any size), a decimal
is the exact decimal it spells (``0.1`` is 1/10, ``2.5e-3`` is 1/400; underscores as
TOML allows; the exponent at most 4300 in size), never a rounded binary float
(:mod:`verify.inputs.numbers`). The optional ``[identification]`` table (written by
``verify identify``, :mod:`verify.identify.model.model_writer`) holds strings, booleans, finite
numbers and arrays of numbers (one or two levels) or of strings, nothing else; it is kept in
``meta["identification"]`` and no verdict of the gate depends on it. TOML's ``nan`` and
``inf`` are refused; nothing is evaluated. The path must name a regular file of at most
16 MiB (a FIFO, a device such as ``/dev/zero`` or a directory is refused unread).
Unknown keys, at the top level or inside a table, are refused by name. A transfer function
is realised exactly over Q and minimally (:mod:`verify.passivity.check.realization`).
Every problem is a one-line :class:`~verify.errors.VerifyInputError` starting with the file
path.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Any

from verify.errors import VerifyInputError
from verify.inputs.files import MAX_FILE_BYTES
from verify.inputs.numbers import decimal_literal, rational, real
from verify.inputs.toml import read_toml

TABLES = {"state_space": ("A", "B", "C", "D"), "transfer_function": ("num", "den")}
TEXT_KEYS = ("name", "description", "units")
ALLOWED_KEYS = {*TABLES, *TEXT_KEYS, "k_s", "reconstructed", "identification"}
MAX_IDENTIFICATION_KEYS = 200
MAX_ARRAY_LENGTH = 10_000
MAX_MODEL_FILE_BYTES = MAX_FILE_BYTES  # 16 MiB; a model file written by verify is a few KB


def _identification_value(value: Any, where: str) -> Any:
    """A string, bool, finite number, array of numbers (1 or 2 levels) or of strings."""
    if isinstance(value, str | bool):
        return value
    if isinstance(value, int | Fraction | float):
        rational(value, where)  # refuses nan and inf by location
        return value
    if isinstance(value, list):
        if len(value) > MAX_ARRAY_LENGTH:
            raise VerifyInputError(f"{where}: more than {MAX_ARRAY_LENGTH} entries")
        if value and all(isinstance(v, str) for v in value):
            return list(value)
        rows = value if value and all(isinstance(v, list) for v in value) else [value]
        width = {len(r) for r in rows}
        if len(width) > 1:
            raise VerifyInputError(f"{where}: rows of different lengths; give a rectangular "
                                   "array")
        for i, row in enumerate(rows):
            if len(row) > MAX_ARRAY_LENGTH:
                raise VerifyInputError(f"{where}[{i}]: more than {MAX_ARRAY_LENGTH} entries")
            for j, v in enumerate(row):
                label = f"{where}[{j}]" if rows is not value else f"{where}[{i}][{j}]"
                if isinstance(v, list | dict | str) or not isinstance(
                        v, int | Fraction | float):
                    raise VerifyInputError(f"{label}: expected a number, got "
                                           f"{type(v).__name__}; arrays hold numbers (one or "
                                           "two levels) or strings only")
                rational(v, label)
        return value
    raise VerifyInputError(f"{where}: expected a string, bool, number or array of numbers or "
                           f"strings, got {type(value).__name__}")


def _identification(data: dict[str, Any], source: str) -> dict[str, Any]:
    """The validated ``[identification]`` table (descriptive: no verdict reads it)."""
    table = data["identification"]
    if not isinstance(table, dict):
        raise VerifyInputError(f"{source}: 'identification' must be a table [identification]")
    if len(table) > MAX_IDENTIFICATION_KEYS:
        raise VerifyInputError(f"{source}: [identification] has more than "
                               f"{MAX_IDENTIFICATION_KEYS} keys")
    return {key: _identification_value(value, f"{source}: [identification] {key}")
            for key, value in table.items()}


def _table(data: dict[str, Any], key: str, source: str) -> dict[str, Any]:
    table = data[key]
    if not isinstance(table, dict):
        raise VerifyInputError(f"{source}: '{key}' must be a table [{key}]")
    allowed = TABLES[key]
    unknown = sorted(set(table) - set(allowed))
    if unknown:
        raise VerifyInputError(
            f"{source}: unknown key(s) {', '.join(unknown)} in [{key}]; allowed: "
            f"{', '.join(allowed)}"
        )
    missing = [k for k in allowed if k not in table]
    if missing:
        raise VerifyInputError(f"{source}: [{key}] is missing key(s) {', '.join(missing)}")
    return table


def _meta(data: dict[str, Any], source: str) -> dict[str, Any]:
    meta: dict[str, Any] = {}
    for key in TEXT_KEYS:
        if key in data and not isinstance(data[key], str):
            raise VerifyInputError(
                f"{source}: '{key}' must be a string, got {type(data[key]).__name__}"
            )
    for key in ("description", "units"):
        if key in data:
            meta[key] = data[key]
    if "k_s" in data:
        where = f"{source}: 'k_s'"
        if rational(data["k_s"], where) <= 0:
            raise VerifyInputError(f"{where} must be a number > 0, got {data['k_s']}; give the "
                                   "coupling gain of Section 4, e.g. k_s = 2.5")
        meta["k_s"] = real(data["k_s"], where)  # descriptive only (no verdict depends on it)
    if "reconstructed" in data:
        if not isinstance(data["reconstructed"], bool):
            raise VerifyInputError(
                f"{source}: 'reconstructed' must be true or false, got "
                f"{type(data['reconstructed']).__name__}"
            )
        meta["reconstructed"] = data["reconstructed"]
    if "identification" in data:
        meta["identification"] = _identification(data, source)
    return meta



@dataclass(frozen=True)
class ModelDocument:
    """A model file's validated content: its label, descriptive fields and one table.

    ``kind`` is ``state_space`` (``table`` holds A, B, C, D) or ``transfer_function``
    (``num``, ``den``), each value as TOML gave it with exact numbers; ``context`` is the
    prefix of every later error about the table (``"<source> [<kind>]"``).
    """

    name: str
    source: str
    kind: str
    table: dict[str, Any]
    meta: dict[str, Any] = field(default_factory=dict)

    @property
    def context(self) -> str:
        return f"{self.source} [{self.kind}]"


def read_model_document(data: dict[str, Any], source: str) -> ModelDocument:
    """Validate a parsed TOML document (``source`` names the file)."""
    unknown = sorted(set(data) - ALLOWED_KEYS)
    if unknown:
        raise VerifyInputError(
            f"{source}: unknown key(s) {', '.join(unknown)}; "
            f"allowed: {', '.join(sorted(ALLOWED_KEYS))}"
        )
    present = [key for key in TABLES if key in data]
    if len(present) != 1:
        raise VerifyInputError(
            f"{source}: give exactly one of the tables [state_space] or [transfer_function]"
            + (" (both are present)" if present else " (neither is present)")
        )
    meta = _meta(data, source)
    name = data.get("name", Path(source).stem)
    kind = present[0]
    return ModelDocument(name, source, kind, _table(data, kind, source), meta)


def load_model_document(path: str | Path) -> ModelDocument:
    """Read and validate a model file as a document (a regular file of at most
    ``MAX_MODEL_FILE_BYTES``; a FIFO or /dev/zero is one line, exit 2)."""
    path = Path(path)
    return read_model_document(read_toml(path, exact=True, max_bytes=MAX_MODEL_FILE_BYTES),
                               str(path))


def model_document_from_bytes(raw: bytes, source: str) -> ModelDocument:
    """A model file's bytes as a document, read as :func:`load_model_document` reads a
    file (numbers exact)."""
    try:
        data = tomllib.loads(raw.decode("utf-8"), parse_float=decimal_literal)
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise VerifyInputError(f"{source}: not valid TOML ({' '.join(str(exc).split())})"
                               ) from None
    except ValueError as exc:
        raise VerifyInputError(f"{source}: number out of range ({' '.join(str(exc).split())})"
                               ) from None
    return read_model_document(data, source)


__all__ = ["ALLOWED_KEYS", "MAX_MODEL_FILE_BYTES", "TABLES", "TEXT_KEYS", "ModelDocument",
           "load_model_document", "model_document_from_bytes", "read_model_document"]
