"""One writer per result store: an advisory lock taken before a campaign plans its runs.

Two ``verify campaign`` on one output folder (two CI jobs, a second terminal) would each
plan the runs not yet stored and run them all: the work twice, and every key twice in
the Parquet parts for any reader that does not deduplicate. So a campaign holds an
exclusive ``flock`` on ``.campaign.lock`` inside its store folder from before it reads
the stored keys until its last row is appended; a second campaign waits for it (one
progress line) or, with ``--no-wait``, stops with one line naming the holder.

The file's text names the holder (PID, host, start time in UTC); it is for people: the
lock itself is the kernel's, released when the holder's process ends however it ends,
so a holder that was killed leaves a lock the next campaign simply takes (it says so,
since the holder's text is still there). A clean release deletes the file first; a
waiter that then gets the lock on the deleted file notices that the path no longer
names it and opens the new one, so two holders never share a store.

Network file systems: on NFSv4 (and NFSv3 with a lock manager), Linux turns ``flock``
into a byte-range lock the server arbitrates, so campaigns on different hosts exclude
each other; a holder's host that crashes keeps the lock until the server's lease ends
(about 90 s). On file systems without working locks (some FUSE and SMB mounts, NFS
mounted with ``nolock``/``local_lock``) the lock excludes only processes of one host.
"""

from __future__ import annotations

import contextlib
import errno
import fcntl
import json
import os
import socket
import sys
import time
from datetime import UTC, datetime
from pathlib import Path
from typing import TextIO

from verify.errors import VerifyInputError

LOCK_NAME = ".campaign.lock"  # a dot name: Parquet dataset readers skip it


def _holder_text(path: Path) -> str:
    """Who holds (or last held) the lock, as its file says: "PID 12 on host h since t"."""
    try:
        found = json.loads(path.read_text(encoding="utf-8"))
        return f"PID {int(found['pid'])} on host {str(found['host'])[:100]} since " \
               f"{str(found['started'])[:40]}"
    except (OSError, ValueError, KeyError, TypeError, UnicodeDecodeError):
        return "a process that has not yet written its name"


class StoreLock:
    """The exclusive lock of the store in ``folder`` (created if missing)."""

    def __init__(self, folder: Path, *, wait: bool = True, stream: TextIO | None = None,
                 poll_seconds: float = 0.25) -> None:
        self.folder = Path(folder)
        self.path = self.folder / LOCK_NAME
        self.wait = wait
        self.stream = stream if stream is not None else sys.stderr
        self.poll_seconds = poll_seconds
        self.fd: int | None = None
        #: the holder this lock was taken over from (it ended without releasing), or "".
        self.taken_over = ""

    def _try(self) -> int | None:
        """The descriptor of the lock file, locked, or None when another holds it."""
        fd = os.open(self.path, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as exc:
            os.close(fd)
            if exc.errno in (errno.EWOULDBLOCK, errno.EAGAIN, errno.EACCES):
                return None
            raise
        try:  # the path must still name the file locked (a holder deletes it on release)
            same = os.path.samestat(os.fstat(fd), os.stat(self.path))
        except FileNotFoundError:
            same = False
        if not same:
            os.close(fd)
            return self._try()
        return fd

    def acquire(self) -> StoreLock:
        self.folder.mkdir(parents=True, exist_ok=True)
        fd = self._try()
        if fd is None:
            holder = _holder_text(self.path)
            if not self.wait:
                raise VerifyInputError(f"{self.folder}: another verify campaign is writing "
                                       f"this store ({holder}); wait for it, drop "
                                       "--no-wait to wait, or choose another --out")
            print(f"verify campaign: {self.folder} is in use by {holder}; waiting for it "
                  "to finish (--no-wait would exit instead)", file=self.stream, flush=True)
            while fd is None:
                time.sleep(self.poll_seconds)
                fd = self._try()
        previous = os.read(fd, 4096)
        if previous.strip():  # its holder ended without releasing it (killed)
            self.taken_over = _holder_text(self.path)
        record = {"pid": os.getpid(), "host": socket.gethostname(),
                  "started": datetime.now(UTC).strftime("%Y-%m-%dT%H:%M:%SZ")}
        os.ftruncate(fd, 0)
        os.pwrite(fd, (json.dumps(record) + "\n").encode(), 0)
        os.fsync(fd)
        self.fd = fd
        return self

    def release(self) -> None:
        if self.fd is None:
            return
        with contextlib.suppress(OSError):
            os.unlink(self.path)  # before the unlock: a waiter then sees the path moved
        os.close(self.fd)  # (closing releases the lock)
        self.fd = None

    def __enter__(self) -> StoreLock:
        return self.acquire()

    def __exit__(self, *exc: object) -> None:
        self.release()


__all__ = ["LOCK_NAME", "StoreLock"]
