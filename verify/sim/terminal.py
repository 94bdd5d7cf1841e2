"""When the commands show progress: on a terminal, or when asked (``--progress``).

The rule itself is :mod:`verify.progress` (shared with every command); re-exported here.

``verify simulate`` and ``verify campaign`` share this rule and the two display modes:
on a terminal one line redrawn in place; on anything else (a log file, a pipe, CI) only
when asked, as a new line every tenth of the work, so captured output stays readable.
"""

from __future__ import annotations

from verify.progress import is_terminal, progress_wanted

__all__ = ["is_terminal", "progress_wanted"]
