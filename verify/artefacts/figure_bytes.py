"""Figures rendered to bytes that depend only on what is drawn.

Matplotlib stamps its version into PNG files ("Software"), a date into SVG and PDF files,
and random ids into SVG elements unless ``svg.hashsalt`` is fixed. Each of these would
make two runs of ``verify all`` write different figures; :func:`figure_bytes` removes the
stamps and fixes the salt, so a figure is a function of its data and the drawing code.
"""

from __future__ import annotations

import io
from typing import Any

_METADATA: dict[str, dict[str, None]] = {
    "png": {"Software": None},
    "svg": {"Date": None, "Creator": None},
    "pdf": {"CreationDate": None, "ModDate": None, "Creator": None, "Producer": None},
}


def figure_bytes(fig: Any, fmt: str = "png", **savefig: Any) -> bytes:
    """``fig`` saved as ``fmt`` (png, svg or pdf) without dates, versions or random ids;
    the figure is closed afterwards."""
    import matplotlib
    import matplotlib.pyplot as plt

    if fmt not in _METADATA:
        raise ValueError(f"figure format {fmt!r}: expected one of {', '.join(_METADATA)}")
    buffer = io.BytesIO()
    with matplotlib.rc_context({"svg.hashsalt": "verify"}):
        fig.savefig(buffer, format=fmt, metadata=_METADATA[fmt], **savefig)
    plt.close(fig)
    return buffer.getvalue()


__all__ = ["figure_bytes"]
