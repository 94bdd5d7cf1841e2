"""Messages for arguments of the public API that are of the wrong kind.

One wording everywhere, in the style of hypothesis' ``InvalidArgument``: what was
expected, the argument's name and value as given, and the likely fix, e.g.
``Expected a justification such as by_algebra(), but got because=by_algebra (the
function itself); did you mean by_algebra()?``. Each caller keeps its own exception
class (``ProofSyntaxError`` in proofs, ``VerifyInputError`` for numbers and arrays).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from numbers import Real

_MAX_REPR = 60


def shown(value: object) -> str:
    """A short one-line repr of ``value`` (long ones cut in the middle)."""
    text = getattr(value, "__name__", None) if callable(value) else None
    text = text if isinstance(text, str) else repr(value)
    text = " ".join(text.split())  # one line: a NumPy array's repr spans several
    if len(text) > _MAX_REPR:
        text = text[: _MAX_REPR // 2 - 2] + " ... " + text[-_MAX_REPR // 2 + 3:]
    return text


def message(expected: str, name: str, value: object, fix: str = "", *,
            detail: str = "") -> str:
    """``Expected <expected>, but got <name>=<value> [(detail)][; fix]``."""
    got = f"{name}={shown(value)}"
    if detail:
        got += f" ({detail})"
    return f"Expected {expected}, but got {got}" + (f"; {fix}" if fix else "")


def one_of(name: str, value: object, choices: Iterable[object],
           error: type[Exception] = ValueError) -> object:
    """``value`` if it is one of ``choices``, else ``error`` listing the valid ones."""
    choices = tuple(choices)
    if value not in choices:
        valid = ", ".join(repr(c) for c in choices)
        raise error(message(f"one of {valid}", name, value))
    return value


def real_in(name: str, value: object, low: float, high: float, *, fix: str = "",
            error: type[Exception] = ValueError) -> float:
    """``value`` as a float if it is a finite real number (not a bool) in [low, high]."""
    if isinstance(value, bool) or not isinstance(value, Real) or not math.isfinite(value):
        raise error(message(f"a finite real number in [{low:g}, {high:g}]", name, value, fix))
    if not low <= value <= high:
        raise error(message(f"a number in [{low:g}, {high:g}]", name, value, fix))
    return float(value)


def integer_at_least(name: str, value: object, low: int, *,
                     error: type[Exception] = ValueError) -> int:
    """``value`` if it is an int (not a bool) >= ``low``."""
    if isinstance(value, bool) or not isinstance(value, int):
        raise error(message(f"an integer >= {low}", name, value))
    if value < low:
        raise error(message(f"an integer >= {low}", name, value))
    return value
