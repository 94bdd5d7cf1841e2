"""Load a researcher's own derivation file for ``verify check FILE``.

The file is Python the user wrote (it is run as a module, like a test file; no text is
evaluated from anywhere else). ``verify check`` calls this only in a child process
(:mod:`verify.proof.child`), never in the checker's (see :mod:`verify.proof.isolate`).
It lists its derivations in ``DERIVATIONS``; without that name, every
:class:`~verify.proof.Derivation` bound at module level (alone, or in a list or tuple)
is checked, in order of appearance.
"""

from __future__ import annotations

import os
import runpy
import sys
import traceback
import types
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from verify.errors import VerifyInputError
from verify.proof.derivation import Derivation
from verify.proof.expr import ProofSyntaxError


@contextmanager
def contained(path: Path, stage: str) -> Iterator[None]:
    """Run the user's code (loading, or checking objects it made) as a malformed-file
    risk: an exit (``sys.exit``, ``exit()``, ``os._exit``, ``posix._exit``,
    ``raise SystemExit``) or an
    exception raised from the file's own code becomes one VerifyInputError line.

    Used in the child process that loads the file: it turns a file that stops early into
    a one-line message; the process boundary (``verify/proof/TRUSTED.md``) is what keeps
    the file away from the checker.
    """
    modules = [os] + [m for m in (sys.modules.get("posix"), sys.modules.get("nt")) if m]
    saved = [(m, m._exit) for m in modules]

    def refuse_exit(code: int = 0) -> None:
        raise SystemExit(code)

    for m in modules:
        m._exit = refuse_exit
    try:
        yield
    except VerifyInputError:
        raise
    except SystemExit as exc:
        raise VerifyInputError(
            f"{path}: the file exited while {stage} (exit code {exc.code!r}); a derivation "
            "file only defines derivations"
        ) from None
    except ProofSyntaxError as exc:
        frames = [f for f in traceback.extract_tb(exc.__traceback__)
                  if Path(f.filename).resolve() == path.resolve()]
        where = f"{path}:{frames[-1].lineno}" if frames else f"{path}: {stage}"
        raise VerifyInputError(f"{where}: {exc}") from None
    except Exception as exc:
        frames = [f for f in traceback.extract_tb(exc.__traceback__)
                  if Path(f.filename).resolve() == path.resolve()]
        if not frames and stage != "loading":
            raise  # ours, not the file's: an internal error
        where = f"{path}:{frames[-1].lineno}" if frames else str(path)
        raise VerifyInputError(f"{where}: {type(exc).__name__}: {exc}") from None
    finally:
        for m, f in saved:
            m._exit = f


def load_derivations(path: Path) -> list[Derivation]:
    """Run ``path`` and return its derivations; any failure is one VerifyInputError line."""
    with contained(path, "loading"):
        return _load(path)


def _load(path: Path) -> list[Derivation]:
    if not path.is_file():
        raise VerifyInputError(f"{path}: no such file")
    if path.suffix != ".py":
        raise VerifyInputError(f"{path}: a derivation file is a Python file (.py)")
    try:
        namespace = runpy.run_path(str(path), run_name="__verify_check__")
    except SyntaxError as exc:
        raise VerifyInputError(f"{path}:{exc.lineno}: syntax error: {exc.msg}") from None
    return _collect(path, namespace)


def run_source(name: str, source: bytes) -> list[Derivation]:
    """Run a derivation file's text (read by the checker and handed to the sandboxed
    child, which may not see the file itself) as module ``__verify_check__`` with
    ``name`` as its file name; its derivations, or one VerifyInputError line."""
    path = Path(name)
    with contained(path, "loading"):
        try:
            code = compile(source, name, "exec", dont_inherit=True)
        except SyntaxError as exc:
            raise VerifyInputError(f"{path}:{exc.lineno}: syntax error: {exc.msg}") from None
        except ValueError as exc:  # e.g. a NUL byte
            raise VerifyInputError(f"{path}: not Python text ({exc})") from None
        module = types.ModuleType("__verify_check__")
        module.__file__ = name
        sys.modules["__verify_check__"] = module
        if str(path.parent) not in sys.path:
            sys.path.insert(0, str(path.parent))  # its own helper modules, where readable
        exec(code, module.__dict__)
        return _collect(path, dict(module.__dict__))


def _collect(path: Path, namespace: dict) -> list[Derivation]:
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
