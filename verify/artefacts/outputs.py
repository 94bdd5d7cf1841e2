"""Every output of a command, checked before the work and written whole after it.

A command names its inputs and each of its outputs in an :class:`OutputPlan` before it
does any work; a path it must not write is refused at once, in one line (an
:class:`~verify.artefacts.atomic.OutputError`, exit 2), so no output is discovered to be
unwritable after minutes of computation. Refused are:

* an output that is one of the call's inputs (the same file, by device and inode, so a
  hard link or a symbolic link to the input is caught too), or the same file as another
  output of the call;
* a directory where a file is expected, and a device, FIFO or socket (the atomic rename
  would replace it), also through a symbolic link; a path that leads into ``/proc``
  (``/dev/stdout``, ``/dev/fd/1``: whatever a process has open; the rename would replace
  the link itself, as root); ``-`` names standard output instead where the command allows a
  stream (``stream=True``);
* a folder output that exists as a file, and a folder ``replaced`` whole that holds an
  input of the call;
* a place that cannot be written: the nearest existing folder is probed by creating,
  writing, syncing and removing a small file in it, so a read-only, immutable, full or
  forbidden folder is found before the work (the probe leaves nothing behind).

Files are then written with :meth:`OutputPlan.write` (or
:func:`~verify.artefacts.atomic.write_atomic`, which every writer of the package uses):
through a temporary file and a rename, an OS error as one line, no folder left empty.

Usage, for a command with an input file and a ``--json`` output::

    plan = OutputPlan(inputs=[model_path])
    plan.file("--json", json_path, stream=True)  # before the work
    ...
    plan.write(json_path, text)                  # after it
"""

from __future__ import annotations

import contextlib
import os
import stat
import sys
import tempfile
from collections.abc import Iterable
from pathlib import Path

from verify.artefacts.atomic import (
    OutputError,
    kind_of,
    os_error_text,
    write_atomic,
)
from verify.artefacts.links import LinkError, resolve_output

#: The path that names standard output for an output that allows a stream.
STREAM = "-"


def is_stream(path: str | Path | None) -> bool:
    """True for ``-``, the name of standard output."""
    return path is not None and str(path) == STREAM


def _identity(path: Path) -> tuple[int, int] | None:
    try:
        info = os.stat(path)
    except OSError:
        return None
    return info.st_dev, info.st_ino


def _real(path: Path) -> str:
    return os.path.realpath(path)


def nearest_existing(path: Path) -> Path:
    """``path`` itself if it exists, else its nearest existing ancestor."""
    p = Path(os.path.abspath(path))
    while not os.path.lexists(p) and p.parent != p:
        p = p.parent
    return p


def probe_folder(folder: Path, label: str) -> None:
    """Refuse unless a file can be created and written where ``folder`` is (or would be
    created): a small file is written, synced and removed in its nearest existing folder."""
    base = nearest_existing(folder)
    if not base.is_dir():
        raise OutputError(f"{label}: {base} is not a folder, so {folder} cannot be created")
    name: str | None = None
    try:
        fd, name = tempfile.mkstemp(prefix=".verify-probe.", dir=base)
        try:
            os.write(fd, b"verify: probe of a writable folder\n")
            os.fsync(fd)
        finally:
            os.close(fd)
    except OSError as exc:
        raise OutputError(f"{label}: cannot write in {base} ({os_error_text(exc)}); "
                          "choose another place") from None
    finally:
        if name is not None:
            with contextlib.suppress(OSError):
                os.unlink(name)


class OutputPlan:
    """The inputs and outputs of one call, checked before the work (see the module)."""

    def __init__(self, inputs: Iterable[str | Path] = ()) -> None:
        self._inputs: list[tuple[Path, tuple[int, int] | None]] = []
        self._outputs: dict[tuple[int, int] | str, str] = {}
        self._probed: set[str] = set()
        for p in inputs:
            self.add_input(p)

    def add_input(self, path: str | Path) -> None:
        """Name one more input of the call (a file or a folder)."""
        p = Path(path)
        self._inputs.append((p, _identity(p)))

    def _input_named(self, identity: tuple[int, int] | None) -> Path | None:
        if identity is None:
            return None
        return next((p for p, i in self._inputs if i == identity), None)

    def _probe(self, folder: Path, label: str) -> None:
        key = _real(nearest_existing(folder))
        if key not in self._probed:
            probe_folder(folder, label)
            self._probed.add(key)

    def file(self, flag: str, path: str | Path | None, *, stream: bool = False) -> None:
        """Check a file output named by ``flag`` (``None``: no such output asked for).

        With ``stream``, ``-`` means standard output (nothing is checked)."""
        if path is None or (stream and is_stream(path)):
            return
        path = Path(path)
        label = f"{flag} {path}" if flag else str(path)
        try:
            resolve_output(path)
        except LinkError as exc:
            hint = "; use - for standard output" if stream else ""
            raise OutputError(f"{label}: {exc}{hint}") from None
        except OSError:
            pass  # the stat and the probe below say what is wrong
        try:
            info = os.stat(path)
        except (FileNotFoundError, NotADirectoryError):  # the probe says what is wrong
            info = None
        except OSError as exc:
            raise OutputError(f"{label}: cannot use this path ({os_error_text(exc)})") from None
        if info is not None:
            if stat.S_ISDIR(info.st_mode):
                raise OutputError(f"{label}: is a directory; give a file name")
            if not stat.S_ISREG(info.st_mode):
                hint = " (use - for standard output)" if stream else ""
                raise OutputError(f"{label}: is {kind_of(info.st_mode)}, not a regular "
                                  f"file; it is not written{hint}")
            source = self._input_named((info.st_dev, info.st_ino))
            if source is not None:
                raise OutputError(f"{label}: is an input of this call ({source}); writing "
                                  "it would destroy the input: choose another file")
        key: tuple[int, int] | str = (info.st_dev, info.st_ino) if info is not None \
            else _real(path)
        if key in self._outputs:
            raise OutputError(f"{label}: is also written as {self._outputs[key]}; give "
                              "each output its own file")
        self._outputs[key] = label
        self._probe(path.parent, label)

    def folder(self, flag: str, path: str | Path, *, replaced: bool = False) -> None:
        """Check a folder output; with ``replaced`` (the command replaces it whole), an
        input inside it is refused too."""
        path = Path(path)
        label = f"{flag} {path}" if flag else str(path)
        if os.path.lexists(path) and not path.is_dir():
            try:
                kind = kind_of(os.stat(path).st_mode)
            except OSError:
                kind = "not a folder"
            raise OutputError(f"{label}: exists and is {kind}, not a folder; name a folder "
                              "(it is created if missing)")
        where = _real(path)
        for p, _ in self._inputs:
            inside = _real(p) == where or _real(p).startswith(where.rstrip(os.sep) + os.sep)
            if inside and (replaced or _real(p) == where):
                raise OutputError(f"{label}: holds an input of this call ({p}), and the "
                                  "folder is replaced whole; choose another folder")
        self._outputs.setdefault(where, label)
        self._probe(path, label)

    def write(self, path: str | Path, data: bytes | str) -> None:
        """Write one output whole: ``-`` to standard output, else atomically."""
        if is_stream(path):
            write_stream(data)
        else:
            write_atomic(Path(path), data)


def write_stream(data: bytes | str) -> None:
    """Write ``data`` to standard output (a closed pipe is one line, exit 2)."""
    try:
        if isinstance(data, bytes):
            sys.stdout.flush()
            sys.stdout.buffer.write(data)
        else:
            sys.stdout.write(data)
        sys.stdout.flush()
    except OSError as exc:
        raise OutputError(f"standard output: cannot write ({os_error_text(exc)})") from None


__all__ = ["STREAM", "OutputError", "OutputPlan", "is_stream", "nearest_existing",
           "probe_folder", "write_stream"]
