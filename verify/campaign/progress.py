"""A one-line progress display for a campaign: runs done of the total and the time left.

Written on stderr and redrawn in place on a terminal (at most a few times a second);
elsewhere only when asked (``--progress``), as a new line every tenth of the runs, and
never when asked to be quiet (:func:`verify.progress.progress_wanted`, the rule of
``verify simulate`` too). The time left is
the mean wall time per run finished in this session times the runs still to do (runs
found in the store from an earlier session are counted as done but not timed).
"""

from __future__ import annotations

import sys
import time
from typing import TextIO

from verify.progress import is_terminal, progress_wanted


def clock(seconds: float) -> str:
    """``1h02m03s`` / ``2m03s`` / ``7s``."""
    s = round(seconds)
    h, rest = divmod(s, 3600)
    m, s = divmod(rest, 60)
    if h:
        return f"{h}h{m:02d}m{s:02d}s"
    return f"{m}m{s:02d}s" if m else f"{s}s"


class CampaignProgress:
    """Call :meth:`update` as rows arrive and :meth:`close` at the end."""

    def __init__(self, total: int, already: int, *, stream: TextIO | None = None,
                 enabled: bool = True, forced: bool = False) -> None:
        self.total, self.already = total, already
        self.stream = stream if stream is not None else sys.stderr
        self.tty = is_terminal(self.stream)
        self.enabled = progress_wanted(self.stream, forced=forced, quiet=not enabled)
        self.tenth = -1
        self.start = time.perf_counter()
        self.last = -1.0
        self.done = 0
        self.raised = 0
        self.width = 0

    def line(self, now: float | None = None) -> str:
        elapsed = (time.perf_counter() if now is None else now) - self.start
        finished = self.already + self.done
        left = self.total - finished
        if self.done:
            eta = f"~{clock(elapsed / self.done * left)} left"
        else:
            eta = "estimating time left"
        parts = [f"campaign: {finished}/{self.total} runs"]
        if self.already:
            parts.append(f"{self.already} stored earlier")
        if self.raised:
            parts.append(f"{self.raised} raised")
        parts.append(f"{clock(elapsed)} elapsed")
        if left:
            parts.append(eta)
        return ", ".join(parts)

    def update(self, done: int = 0, raised: int = 0, *, force: bool = False) -> None:
        self.done += done
        self.raised += raised
        if not self.enabled:
            return
        now = time.perf_counter()
        if not self.tty:  # a log: one line per tenth of the runs
            tenth = 10 * (self.already + self.done) // max(1, self.total)
            if tenth > self.tenth:
                self.tenth = tenth
                print(self.line(now), file=self.stream, flush=True)
            return
        if not force and now - self.last < 0.2:
            return
        self.last = now
        text = self.line(now)
        pad = max(0, self.width - len(text))
        self.width = len(text)
        print("\r" + text + " " * pad, end="", file=self.stream, flush=True)

    def close(self) -> None:
        if self.enabled and self.tty:
            self.update(force=True)
            print(file=self.stream, flush=True)


__all__ = ["CampaignProgress", "clock"]
