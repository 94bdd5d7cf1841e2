"""Where an output path really leads: its symbolic links followed one by one.

An output named through a symbolic link is the file the link names, never the link:
``results.json -> ../out/results.json`` writes ``../out/results.json`` and leaves the
link in place. A path that leads into ``/proc`` is refused: ``/dev/stdout``,
``/dev/fd/1`` and ``/proc/self/fd/1`` name whatever a process has open (a terminal, a
pipe, a file its shell redirected to), and a temporary file renamed over them would
replace the ``/dev/stdout`` link itself (as root) with a regular file. The links are
resolved here component by component (``os.path.realpath`` would read the target of a
``/proc`` link as the name of the open file and hide that it went through ``/proc``).
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

#: Symbolic links followed at most while resolving one path (the kernel's own limit).
MAX_LINKS = 40


class LinkError(Exception):
    """An output path that leads into /proc or through too many links; the message is
    the reason (the writers prefix the path and report it in one line, exit 2)."""


def _proc_device() -> int | None:
    try:
        return os.lstat("/proc/self").st_dev
    except OSError:
        return None


def _in_proc(path: str, proc_dev: int | None) -> bool:
    if path == "/proc" or path.startswith("/proc/"):
        return True
    if proc_dev is None:
        return False
    try:
        return os.lstat(path).st_dev == proc_dev
    except OSError:
        return False


def resolve_output(path: str | Path) -> Path:
    """The absolute path ``path`` leads to, every symbolic link followed (the part that
    does not exist yet kept as written). Raises :class:`LinkError` if the way passes
    through ``/proc`` (``/dev/stdout``, ``/dev/fd/N``) or a loop of links."""
    proc_dev = _proc_device()
    # not os.path.abspath: it would fold "link/.." before the link is followed
    todo = list((Path(os.getcwd()) / path).parts[1:])
    done = "/"
    links = 0
    while todo:
        name = todo.pop(0)
        if name in ("", "."):
            continue
        if name == "..":
            done = os.path.dirname(done) or "/"
            continue
        here = os.path.join(done, name)
        if _in_proc(here, proc_dev):
            where = os.path.join(here, *todo)
            raise LinkError(f"leads into /proc ({where}: what a process has open, standard "
                            "output perhaps), not to a file; it is not written")
        try:
            mode = os.lstat(here).st_mode
        except (FileNotFoundError, NotADirectoryError):
            return Path(os.path.join(here, *todo))  # the rest does not exist yet
        except OSError:
            return Path(os.path.join(here, *todo))  # the writer reports what it cannot do
        if not stat.S_ISLNK(mode):
            done = here
            continue
        links += 1
        if links > MAX_LINKS:
            raise LinkError(f"more than {MAX_LINKS} symbolic links on the way (a loop?); "
                            "it is not written")
        target = os.readlink(here)
        if os.path.isabs(target):
            done = "/"
        todo = [*Path(target).parts[1 if os.path.isabs(target) else 0:], *todo]
    return Path(done)


__all__ = ["MAX_LINKS", "LinkError", "resolve_output"]
