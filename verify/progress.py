"""When and how the commands show progress: stage lines on stderr.

A command that can run longer than about 2 s tells a person at a terminal what it is
doing: on stderr (stdout stays the result, safe to pipe or capture), only when stderr
is a terminal or when asked (``--progress``), never when asked to be quiet. Each line
names the command, the seconds since it started and the stage, e.g.
``verify identify: [  3.1 s] estimating the model (continuous-time IV, then output error)``.
The times are for the person watching; nothing written to a file carries them.
"""

from __future__ import annotations

import sys
import time
from typing import TextIO


def is_terminal(stream: TextIO) -> bool:
    """Whether ``stream`` is an interactive terminal (False when it cannot say)."""
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError, OSError):
        return False


def progress_wanted(stream: TextIO, *, forced: bool = False, quiet: bool = False) -> bool:
    """Show progress on ``stream``: never when ``quiet``; on a terminal; else if ``forced``."""
    return not quiet and (forced or is_terminal(stream))


class Stages:
    """Stage lines of one command (module docstring); call it with the stage's text.

    Disabled, a call does nothing, so library code can take a ``Stages`` (or any
    callable of one string) and report unconditionally.
    """

    def __init__(self, command: str, *, enabled: bool, stream: TextIO | None = None) -> None:
        self.command = command
        self.enabled = enabled
        self.stream = stream
        self.start = time.perf_counter()

    @classmethod
    def for_command(cls, command: str, *, forced: bool = False, quiet: bool = False,
                    stream: TextIO | None = None) -> Stages:
        """Stages shown on ``stream`` (default stderr) by :func:`progress_wanted`'s rule."""
        out = sys.stderr if stream is None else stream
        return cls(command, enabled=progress_wanted(out, forced=forced, quiet=quiet),
                   stream=out)

    def __call__(self, text: str) -> None:
        if not self.enabled:
            return
        seconds = time.perf_counter() - self.start
        print(f"{self.command}: [{seconds:6.1f} s] {text}",
              file=sys.stderr if self.stream is None else self.stream, flush=True)


def silent(_text: str) -> None:
    """A stage callback that shows nothing (the default of library functions)."""


__all__ = ["Stages", "is_terminal", "progress_wanted", "silent"]
