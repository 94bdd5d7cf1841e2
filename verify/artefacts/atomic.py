"""Writing files so that a reader never sees a half-written one (temp file, then rename).

Each file is written to a temporary file in the same directory and moved into place
with ``os.replace``; a set of files is rendered fully in memory before the first move.
The rename only ever replaces a regular file: a symbolic link is followed to the file
it names (:func:`verify.artefacts.links.resolve_output`; the link stays), a path that
leads into ``/proc`` (``/dev/stdout``, ``/dev/fd/1``) is refused, and a device, FIFO,
socket or directory at the target is refused, never replaced.
An operating-system error (a full disk, a read-only or immutable folder, a parent that
cannot exist) becomes a one-line :class:`OutputError` naming the path; the temporary
file and any folder created for the write are removed, so nothing half-written and no
empty folder is left behind.
"""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from collections.abc import Iterator, Mapping
from pathlib import Path

from verify.artefacts.links import LinkError, resolve_output
from verify.errors import VerifyInputError


class OutputError(VerifyInputError):
    """An output that cannot be written: one line on stderr, exit 2 (like bad input)."""


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def kind_of(mode: int) -> str:
    """What a file of this ``st_mode`` is, in words ("a directory", "a device", ...)."""
    if stat.S_ISDIR(mode):
        return "a directory"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISSOCK(mode):
        return "a socket"
    if stat.S_ISLNK(mode):
        return "a symbolic link"
    return "a regular file" if stat.S_ISREG(mode) else "not a regular file"


def os_error_text(exc: OSError) -> str:
    """The reason of an OS error in words ("No space left on device")."""
    if exc.strerror:
        return exc.strerror
    return os.strerror(exc.errno) if exc.errno else str(exc) or type(exc).__name__


@contextlib.contextmanager
def os_errors_as_output_errors(path: str | Path, what: str = "cannot write") -> Iterator[None]:
    """Inside, an ``OSError`` becomes ``OutputError("<path>: <what> (<reason>)")``."""
    try:
        yield
    except OutputError:
        raise
    except OSError as exc:
        raise OutputError(f"{path}: {what} ({os_error_text(exc)})") from None


def make_parents(folder: Path) -> list[Path]:
    """Create ``folder`` and its missing parents; return those created, outermost first
    (for :func:`remove_empty`). A parent that exists and is not a folder is refused."""
    missing: list[Path] = []
    p = Path(folder)
    while not os.path.lexists(p):
        missing.append(p)
        if p.parent == p:
            break
        p = p.parent
    if os.path.lexists(p) and not p.is_dir():
        raise OutputError(f"{folder}: cannot create the folder ({p} is not a folder)")
    created: list[Path] = []
    try:
        for q in reversed(missing):
            os.mkdir(q)
            created.append(q)
    except OSError as exc:
        remove_empty(created)
        raise OutputError(f"{folder}: cannot create the folder "
                          f"({os_error_text(exc)})") from None
    return created


def remove_empty(folders: list[Path]) -> None:
    """Remove the given folders, innermost first, where they are empty (errors ignored)."""
    for q in reversed(folders):
        with contextlib.suppress(OSError):
            os.rmdir(q)


def resolved(path: str | Path) -> Path:
    """The file ``path`` names, its symbolic links followed; a way through ``/proc``
    (``/dev/stdout``) or a loop of links is an :class:`OutputError`."""
    try:
        return resolve_output(path)
    except LinkError as exc:
        raise OutputError(f"{path}: {exc}") from None
    except OSError as exc:
        raise OutputError(f"{path}: cannot write ({os_error_text(exc)})") from None


def refuse_non_regular(path: Path) -> None:
    """Refuse an existing ``path`` that a rename must not replace: anything but a regular
    file once its symbolic links are followed (a link to a device is the device; a link
    into ``/proc``, such as ``/dev/stdout``, is refused whatever it names)."""
    try:
        mode = os.lstat(resolved(path)).st_mode
    except (FileNotFoundError, NotADirectoryError):  # the parents are checked next
        return
    except OSError as exc:
        raise OutputError(f"{path}: cannot write ({os_error_text(exc)})") from None
    if not stat.S_ISREG(mode):
        raise OutputError(f"{path}: is {kind_of(mode)}, not a regular file; it is not "
                          "replaced: give the path of a file")


def write_atomic(path: Path, data: bytes | str) -> None:
    """Write ``data`` to ``path`` atomically (temporary file + rename).

    A symbolic link is followed to the file it names, as ``open(path, "w")`` would
    (``/dev/stdout`` and other ways into ``/proc`` are refused). The file gets the mode an
    ordinary ``open(path, "w")`` would give (0666 less the
    umask), not the private 0600 of a temporary file. Missing parent folders are created
    (and removed again if the write fails); a failure is an :class:`OutputError`.
    """
    path = resolved(path)  # through its symbolic links: the link itself is never replaced
    payload = data.encode("utf-8") if isinstance(data, str) else data
    refuse_non_regular(path)
    created = make_parents(path.parent)
    tmp: str | None = None
    try:
        with os_errors_as_output_errors(path):
            fd, tmp = tempfile.mkstemp(prefix=f".{path.name[:64]}.", suffix=".tmp",
                                       dir=path.parent)
            with os.fdopen(fd, "wb") as handle:
                handle.write(payload)
                handle.flush()
                os.fsync(handle.fileno())
            os.chmod(tmp, 0o666 & ~_umask())
            refuse_non_regular(path)  # the target may have changed during the write
            os.replace(tmp, path)
            tmp = None
    except BaseException:
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
        remove_empty(created)
        raise


def write_all_atomic(files: Mapping[Path, bytes | str]) -> None:
    """Write several already-rendered files, each atomically."""
    for path, data in files.items():
        write_atomic(path, data)
