"""The time grid of a run: how many equal steps of at most ``h`` cover [0, seconds].

A run of ``seconds`` with step ``h`` (the loop period 1/120 s of Section 4 by default)
takes :func:`step_count` equal steps; the simulator integrates on that grid and a
campaign spec is refused when the grid would exceed what a run keeps in memory, so both
count the steps here.
"""

from __future__ import annotations

import numpy as np


def step_count(seconds: float, h: float) -> int:
    """Number of equal steps of at most ``h`` covering [0, seconds]."""
    return max(1, int(np.ceil(seconds / h - 1e-9)))


__all__ = ["step_count"]
