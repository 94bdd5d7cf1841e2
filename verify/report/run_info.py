"""When a report was generated, and whether its timings may be printed.

Everything a report says is a function of the code, the inputs and the seed, except the
time it was generated and how long each check took. Those two are kept in one block at
the end of each format ("Run"), so two runs' reports differ only there. With the
``SOURCE_DATE_EPOCH`` convention of reproducible builds
(https://reproducible-builds.org/specs/source-date-epoch/) set, the date is that value
and the timings are left out, so the reports are byte-identical between runs.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from datetime import UTC, datetime

from verify.errors import VerifyInputError


@dataclass(frozen=True)
class RunInfo:
    """The generation time of a report; ``reproducible`` omits the timings."""

    generated: datetime
    reproducible: bool = False

    @classmethod
    def from_environment(cls) -> RunInfo:
        """The current time, or SOURCE_DATE_EPOCH (seconds since 1970, UTC) when set."""
        text = os.environ.get("SOURCE_DATE_EPOCH")
        if text is None or not text.strip():
            return cls(datetime.now(UTC))
        try:
            seconds = int(text.strip())
            if seconds < 0:
                raise ValueError
            when = datetime.fromtimestamp(seconds, UTC)
        except (ValueError, OverflowError, OSError):
            raise VerifyInputError(f"SOURCE_DATE_EPOCH={text!r} is not a whole number of "
                                   "seconds since 1970-01-01 UTC") from None
        return cls(when, reproducible=True)

    @property
    def stamp(self) -> str:
        return self.generated.isoformat(timespec="seconds")


__all__ = ["RunInfo"]
