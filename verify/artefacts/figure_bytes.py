"""Figures rendered to bytes that depend only on what is drawn.

Matplotlib stamps its version into PNG files ("Software"), a date into SVG and PDF files,
and random ids into SVG elements unless ``svg.hashsalt`` is fixed. Each of these would
make two runs of ``verify all`` write different figures; :func:`figure_bytes` removes the
stamps and fixes the salt, so a figure is a function of its data and the drawing code.

The report's figures are set in the paper's font: :func:`paper_style` selects Computer
Modern (matplotlib's own ``cmr10`` text font and its ``cm`` mathtext), which matplotlib
ships, so no TeX installation is needed and the bytes do not depend on one.
:func:`vector_figures` writes a figure as SVG (for the HTML report) and PDF (for the
LaTeX appendix), both vector.
"""

from __future__ import annotations

import contextlib
import io
from collections.abc import Iterator
from typing import Any

_METADATA: dict[str, dict[str, None]] = {
    "png": {"Software": None},
    "svg": {"Date": None, "Creator": None},
    "pdf": {"CreationDate": None, "ModDate": None, "Creator": None, "Producer": None},
}


#: Computer Modern text and mathematics, as in the paper (matplotlib's own fonts)
PAPER_STYLE: dict[str, Any] = {
    "font.family": "serif",
    "font.serif": ["cmr10"],
    "mathtext.fontset": "cm",
    "axes.formatter.use_mathtext": True,  # cmr10 has no minus sign: tick labels as math
    "axes.unicode_minus": False,
    "svg.fonttype": "path",
}


@contextlib.contextmanager
def paper_style() -> Iterator[None]:
    """Draw (create and save) figures inside this block to set them in the paper's font."""
    import matplotlib

    with matplotlib.rc_context(PAPER_STYLE):
        yield


def vector_figures(fig: Any, **savefig: Any) -> dict[str, bytes]:
    """``fig`` as SVG and PDF bytes (``{"svg": ..., "pdf": ...}``), reproducible as
    :func:`figure_bytes` makes them; the figure is closed afterwards."""
    import matplotlib.pyplot as plt

    out = {}
    for fmt in ("svg", "pdf"):
        buffer = io.BytesIO()
        with _fixed_ids():
            fig.savefig(buffer, format=fmt, metadata=_METADATA[fmt], **savefig)
        out[fmt] = buffer.getvalue()
    plt.close(fig)
    return out


@contextlib.contextmanager
def _fixed_ids() -> Iterator[None]:
    import matplotlib

    with matplotlib.rc_context({"svg.hashsalt": "verify"}):
        yield


def figure_bytes(fig: Any, fmt: str = "png", **savefig: Any) -> bytes:
    """``fig`` saved as ``fmt`` (png, svg or pdf) without dates, versions or random ids;
    the figure is closed afterwards."""
    import matplotlib.pyplot as plt

    if fmt not in _METADATA:
        raise ValueError(f"figure format {fmt!r}: expected one of {', '.join(_METADATA)}")
    buffer = io.BytesIO()
    with _fixed_ids():
        fig.savefig(buffer, format=fmt, metadata=_METADATA[fmt], **savefig)
    plt.close(fig)
    return buffer.getvalue()


__all__ = ["PAPER_STYLE", "figure_bytes", "paper_style", "vector_figures"]
