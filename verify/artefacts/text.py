"""One way to show text that came from a user's file: inert on any terminal or page.

Names, labels, notes, citations, variable names, exception texts and certificate
statements come from files a user (or a hostile submission) wrote. Printed raw, they can
drive a terminal (ANSI escape sequences clearing the screen and drawing a fake report),
overwrite a verdict (a carriage return), reorder a line (bidirectional overrides and
isolates) or stop the program (a lone surrogate cannot be encoded). :func:`shown` maps
every such character to a visible escape, so what is printed is the text's content and
nothing else; the other renderers (Markdown, HTML, LaTeX) escape their own syntax after
this.
"""

from __future__ import annotations

import unicodedata

#: Formatting characters that reorder or hide text (bidi embeddings, overrides,
#: isolates and marks; zero-width characters; the BOM; interlinear annotation).
_INVISIBLE = frozenset(
    [0x061C, 0x200B, 0x200C, 0x200D, 0x200E, 0x200F, 0x2028, 0x2029, 0x2060, 0xFEFF,
     *range(0x202A, 0x202F), *range(0x2066, 0x206A), *range(0xFFF9, 0xFFFC)])


def _needs_escape(ch: str) -> bool:
    code = ord(ch)
    if code < 0x20 or 0x7F <= code < 0xA0:  # C0 and C1 controls, DEL (ESC, CR, BS, ...)
        return True
    if 0xD800 <= code < 0xE000:  # a lone surrogate (not encodable as UTF-8)
        return True
    if code in _INVISIBLE:
        return True
    category = unicodedata.category(ch)
    return category in ("Cc", "Cf", "Cs", "Co", "Cn", "Zl", "Zp")


def shown(text: object, limit: int | None = None) -> str:
    """``text`` with every control, formatting, bidi, surrogate, private-use or
    unassigned character written as a visible escape (``\\x1b``, ``\\u202e``,
    ``\\ud800``); other characters unchanged (a backslash too: the escapes are for
    reading, the text stays inert either way). A non-string is shown as its type's name
    only, so none of its methods run. ``limit`` cuts the result (marked with ``…``)."""
    if not isinstance(text, str):
        text = f"<{type(text).__name__}>"
    text = str.__str__(text)  # a plain copy: no method of a str subclass runs
    if text.isprintable():  # no control, format, surrogate or separator but the space
        return text if limit is None or len(text) <= limit else text[:limit] + "…"
    out = []
    for ch in text:
        if _needs_escape(ch):
            code = ord(ch)
            out.append(f"\\x{code:02x}" if code < 0x100 else
                       f"\\u{code:04x}" if code < 0x10000 else f"\\U{code:08x}")
        else:
            out.append(ch)
    result = "".join(out)
    if limit is not None and len(result) > limit:
        result = result[:limit] + "…"
    return result


__all__ = ["shown"]
