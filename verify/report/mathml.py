"""MathML and Markdown from the report's LaTeX sources.

Every formula of the report has one LaTeX source (:mod:`verify.report.mathtex`, or a
claim's hand-written ``latex`` form); this module turns it into MathML for the HTML
report, which browsers render natively (MathML Core), and into the ``$...$`` spans of
the Markdown report. The conversion is done by ``latex2mathml`` (a maintained,
dependency-free converter) so that the two renderings cannot drift apart.

Text around formulas uses the LaTeX text escapes :func:`verify.report.mathtex.latex_text`
writes; :func:`untex` undoes exactly those.
"""

from __future__ import annotations

import html
import re
from functools import lru_cache

from latex2mathml.converter import convert

__all__ = ["markdown_prose", "mathml", "prose_html", "split_math", "untex"]

_NAMED_OPERATOR = re.compile(r"<mo>([A-Za-z]{2,})</mo>")
_MATH = re.compile(r"(?<!\\)\$(.+?)(?<!\\)\$")
_UNTEX = [(r"\textbackslash{}", "\\"), (r"\textasciitilde{}", "~"), (r"\textless{}", "<"),
          (r"\textgreater{}", ">"), (r"\textbar{}", "|"), (r"\^{}", "^"), ("---", "—"),
          ("--", "–"), (r"\_", "_"), (r"\{", "{"), (r"\}", "}"), (r"\%", "%"), (r"\#", "#"),
          (r"\&", "&"), (r"\$", "$"), ("~", "\u00a0")]


def untex(text: str) -> str:
    """Plain text of a LaTeX text-mode run written with the escapes of ``latex_text``."""
    out = []
    i = 0
    while i < len(text):
        for src, dst in _UNTEX:
            if text.startswith(src, i):
                out.append(dst)
                i += len(src)
                break
        else:
            out.append(text[i])
            i += 1
    return "".join(out)


def split_math(source: str) -> list[tuple[bool, str]]:
    """``(is_math, piece)`` pieces of a LaTeX text with ``$...$`` formulas."""
    out: list[tuple[bool, str]] = []
    pos = 0
    for m in _MATH.finditer(source):
        if m.start() > pos:
            out.append((False, source[pos:m.start()]))
        out.append((True, m.group(1)))
        pos = m.end()
    if pos < len(source):
        out.append((False, source[pos:]))
    return out


@lru_cache(maxsize=4096)
def mathml(latex: str, display: bool = False) -> str:
    """The ``<math>`` element of one LaTeX formula; a source the converter refuses is shown
    as its escaped LaTeX in ``<code>`` (visible, never a broken page)."""
    try:
        out = convert(latex, display="block" if display else "inline")
    except Exception:  # latex2mathml raises several types on malformed input
        return f"<code class='tex'>{html.escape(latex)}</code>"
    # operator names (tr, sym, cos, min) as identifiers: MathML Core renders a multi-letter
    # <mi> upright with no operator spacing, as LaTeX sets \operatorname
    return _NAMED_OPERATOR.sub(r"<mi>\1</mi>", out)


def prose_html(source: str) -> str:
    """HTML of a LaTeX text with ``$...$`` formulas (text escaped, formulas as MathML)."""
    return "".join(mathml(piece) if is_math else html.escape(untex(piece))
                   for is_math, piece in split_math(source))


def markdown_prose(source: str) -> str:
    """Markdown of the same text: formulas stay ``$...$``, text loses its LaTeX escapes
    and is made safe for a table cell."""
    parts = []
    for is_math, piece in split_math(source):
        if is_math:
            parts.append(f"${piece}$")
        else:
            parts.append(untex(piece).replace("|", "\\|").replace("\n", " "))
    return "".join(parts)
