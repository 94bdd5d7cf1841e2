"""When the commands show progress: on a terminal, or when asked (``--progress``).

``verify simulate`` and ``verify campaign`` share this rule and the two display modes:
on a terminal one line redrawn in place; on anything else (a log file, a pipe, CI) only
when asked, as a new line every tenth of the work, so captured output stays readable.
"""

from __future__ import annotations

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


__all__ = ["is_terminal", "progress_wanted"]
