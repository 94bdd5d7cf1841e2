"""Evidence data in ``report.html`` as small tables and typeset values, not JSON text.

A claim's evidence carries data (a certificate's margin, a confidence region's χ², a
derivation's steps); ``report.json`` keeps it as JSON, and the HTML report shows the same
values for a reader: a mapping as a two-column table (its keys typeset as prose, so
``min tr(R-bar_r) - 1`` reads as a formula), a list of mappings with the same keys as a
table with those columns, a matrix of numbers as a MathML matrix, text in the checks'
plain notation typeset as the report's prose is, and an exact rational
``p/q`` as a MathML fraction with its decimal value beside it. A rational too long to set
(more than :data:`SHORT_DIGITS` digits above or below) is shown by its decimal value and
its size, the exact value being in ``report.json``. Long lists show their first
:data:`LIST_ROWS` items and say how many more there are. Every text is escaped.
"""

from __future__ import annotations

import html
import re
from fractions import Fraction
from typing import Any

from verify.report.mathml import mathml, prose_html
from verify.report.mathtex import prose_to_latex

#: A rational is set as a fraction when neither its numerator nor denominator is longer.
SHORT_DIGITS = 12
#: Items of a list shown before "... and N more".
LIST_ROWS = 12
#: Nesting shown as tables; deeper values are summarised.
DEPTH = 4

_RATIONAL = re.compile(r"-?\d+/\d+")
_NUMBER = (int, float)


def _decimal(value: Fraction) -> str:
    return f"{float(value):.6g}" if value else "0"


def rational_html(text: str) -> str:
    """``"p/q"`` as a typeset fraction and its decimal value (or, for a long one, the
    decimal value and its digit counts)."""
    value = Fraction(text)
    num, den = text.lstrip("-").split("/")
    if len(num) > SHORT_DIGITS or len(den) > SHORT_DIGITS:
        return (f"≈ {html.escape(_decimal(value))} <span class='exact'>(exact rational of "
                f"{len(num)}/{len(den)} digits, in report.json)</span>")
    sign = "-" if text.startswith("-") else ""
    return (mathml(f"{sign}\\frac{{{num}}}{{{den}}}") +
            f" <span class='approx'>≈ {html.escape(_decimal(value))}</span>")


def _scalar_html(value: Any) -> str:
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, _NUMBER):
        return html.escape(f"{value:.6g}" if isinstance(value, float) else str(value))
    text = str(value)
    if _RATIONAL.fullmatch(text):
        return rational_html(text)
    return prose_html(prose_to_latex(text))  # the checks' plain notation, typeset


def _is_matrix(value: Any) -> bool:
    return (isinstance(value, list) and 0 < len(value) <= LIST_ROWS
            and all(isinstance(row, list) and row and len(row) == len(value[0])
                    and len(row) <= LIST_ROWS for row in value)
            and all((isinstance(x, _NUMBER) and not isinstance(x, bool))
                    or (isinstance(x, str) and (_RATIONAL.fullmatch(x) or
                                               re.fullmatch(r"-?\d+", x)))
                    for row in value for x in row))


def _entry_latex(x: Any) -> str:
    text = str(x)
    if _RATIONAL.fullmatch(text):
        num, den = text.lstrip("-").split("/")
        if len(num) <= SHORT_DIGITS and len(den) <= SHORT_DIGITS:
            return ("-" if text.startswith("-") else "") + f"\\frac{{{num}}}{{{den}}}"
        return f"{float(Fraction(text)):.6g}"
    return f"{x:.6g}" if isinstance(x, float) else text


def _matrix_html(value: list[list[Any]]) -> str:
    rows = r" \\ ".join(" & ".join(_entry_latex(x) for x in row) for row in value)
    return mathml(r"\begin{bmatrix}" + rows + r"\end{bmatrix}")


def _key_html(key: str) -> str:
    return prose_html(prose_to_latex(str(key).replace("_", " ")))


def _more(count: int) -> str:
    return f"<p class='more'>… and {count} more (all in report.json)</p>" if count else ""


def value_html(value: Any, depth: int = 0) -> str:
    """HTML of one evidence value (module docstring)."""
    if isinstance(value, dict):
        if not value:
            return "—"
        if depth >= DEPTH:
            return f"<span class='more'>{len(value)} fields (in report.json)</span>"
        rows = "".join(f"<tr><th>{_key_html(k)}</th><td>{value_html(v, depth + 1)}</td></tr>"
                       for k, v in value.items())
        return f"<table class='evidence'>{rows}</table>"
    if isinstance(value, list):
        if not value:
            return "—"
        if _is_matrix(value):
            return _matrix_html(value)
        if depth >= DEPTH:
            return f"<span class='more'>{len(value)} items (in report.json)</span>"
        shown, rest = value[:LIST_ROWS], max(0, len(value) - LIST_ROWS)
        if all(isinstance(v, dict) for v in shown) and len({tuple(v) for v in shown}) == 1:
            keys = list(shown[0])
            head = "".join(f"<th>{_key_html(k)}</th>" for k in keys)
            body = "".join("<tr>" + "".join(f"<td>{value_html(v[k], depth + 1)}</td>"
                                            for k in keys) + "</tr>" for v in shown)
            return (f"<table class='evidence'><tr>{head}</tr>{body}</table>" + _more(rest))
        if all(not isinstance(v, (dict, list)) for v in shown):
            return ", ".join(_scalar_html(v) for v in shown) + (
                f" … and {rest} more (in report.json)" if rest else "")
        items = "".join(f"<li>{value_html(v, depth + 1)}</li>" for v in shown)
        return f"<ul class='evidence'>{items}</ul>" + _more(rest)
    return _scalar_html(value)


__all__ = ["LIST_ROWS", "SHORT_DIGITS", "rational_html", "value_html"]
