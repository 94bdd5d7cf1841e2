"""Load a researcher's own derivation file for ``verify check FILE``.

The file is Python the user wrote (it is run as a module, like a test file; no text is
evaluated from anywhere else). It lists its derivations in ``DERIVATIONS``; without
that name, every :class:`~verify.proof.Derivation` bound at module level (alone, or in
a list or tuple) is checked, in order of appearance.
"""

from __future__ import annotations

import runpy
import traceback
from pathlib import Path

from verify.errors import VerifyInputError
from verify.proof.derivation import Derivation


def load_derivations(path: Path) -> list[Derivation]:
    """Run ``path`` and return its derivations; any failure is one VerifyInputError line."""
    if not path.is_file():
        raise VerifyInputError(f"{path}: no such file")
    if path.suffix != ".py":
        raise VerifyInputError(f"{path}: a derivation file is a Python file (.py)")
    try:
        namespace = runpy.run_path(str(path), run_name="__verify_check__")
    except SyntaxError as exc:
        raise VerifyInputError(f"{path}:{exc.lineno}: syntax error: {exc.msg}") from None
    except Exception as exc:  # the user's code failed: say where, in one line
        frames = [f for f in traceback.extract_tb(exc.__traceback__)
                  if Path(f.filename).resolve() == path.resolve()]
        where = f"{path}:{frames[-1].lineno}" if frames else str(path)
        raise VerifyInputError(f"{where}: {type(exc).__name__}: {exc}") from None
    if "DERIVATIONS" in namespace:
        found = namespace["DERIVATIONS"]
        if not isinstance(found, list | tuple) or not all(
            isinstance(d, Derivation) for d in found
        ):
            raise VerifyInputError(f"{path}: DERIVATIONS must be a list of Derivation objects")
        derivations = list(found)
    else:
        derivations, seen = [], set()
        for value in namespace.values():
            items = value if isinstance(value, list | tuple) else [value]
            for d in items:
                if isinstance(d, Derivation) and id(d) not in seen:
                    seen.add(id(d))
                    derivations.append(d)
    if not derivations:
        raise VerifyInputError(f"{path}: defines no derivation (set DERIVATIONS = [...])")
    empty = [d.name for d in derivations if not d.steps]
    if empty:
        raise VerifyInputError(f"{path}: derivation {empty[0]!r} has no steps")
    return derivations
