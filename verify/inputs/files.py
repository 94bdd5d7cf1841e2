"""Opening a user's file without trusting what the path names.

A path can name a FIFO (opening it for reading blocks until a writer appears), a character
device such as ``/dev/zero`` (reading never ends) or a file of any size. Every reader of
the input layer opens through :func:`open_regular`, which refuses anything but a regular
file before reading a byte, and, with ``max_bytes``, a file larger than that bound.
:func:`read_bounded` reads such a file whole. Refusals are one-line
:class:`~verify.errors.VerifyInputError` messages starting with ``where``.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path
from typing import BinaryIO

from verify.artefacts.atomic import kind_of
from verify.errors import VerifyInputError

#: Default bound on a file read whole (model files, specs, certificates): 16 MiB, far
#: above any file ``verify`` writes (a model file is a few KB).
MAX_FILE_BYTES = 16 * 2**20


def _size_text(n: int) -> str:
    return f"{n / 2**20:.1f} MiB" if n >= 2**20 else f"{n} bytes"


def open_regular(path: str | Path, *, where: str | None = None,
                 max_bytes: int | None = None) -> BinaryIO:
    """``path`` opened for binary reading, refused unless it is a regular file.

    The file is opened with ``O_NONBLOCK`` (so a FIFO cannot block the open) and its type
    is read from the open descriptor (so the check and the read see the same file). With
    ``max_bytes``, a larger file is refused before any read.
    """
    path = Path(path)
    where = str(path) if where is None else where
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        raise VerifyInputError(f"{where}: cannot read ({exc.strerror})") from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise VerifyInputError(f"{where}: is {kind_of(info.st_mode)}, not a regular "
                                   "file; give the path of a file on disk")
        if max_bytes is not None and info.st_size > max_bytes:
            raise VerifyInputError(f"{where}: the file has {_size_text(info.st_size)}, above "
                                   f"the limit of {_size_text(max_bytes)} for this kind of "
                                   "file; check the path")
        if hasattr(os, "set_blocking"):
            os.set_blocking(fd, True)
        handle = os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise
    return handle


def read_bounded(path: str | Path, *, where: str | None = None,
                 max_bytes: int = MAX_FILE_BYTES) -> bytes:
    """The bytes of a regular file of at most ``max_bytes`` bytes (:func:`open_regular`).

    The read itself stops after ``max_bytes + 1`` bytes, so a file that grows while it is
    read is refused too.
    """
    where = str(path) if where is None else where
    with open_regular(path, where=where, max_bytes=max_bytes) as handle:
        try:
            data = handle.read(max_bytes + 1)
        except OSError as exc:
            raise VerifyInputError(f"{where}: cannot read ({exc.strerror})") from None
    if len(data) > max_bytes:
        raise VerifyInputError(f"{where}: the file has more than {_size_text(max_bytes)}, the "
                               "limit for this kind of file; check the path")
    return data


__all__ = ["MAX_FILE_BYTES", "open_regular", "read_bounded"]
