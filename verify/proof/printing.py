"""Plain-text rendering of expressions for reports and error messages.

Rendering is memoised over shared subtrees (each node's text is made once) and bounded:
a subexpression whose text would exceed :data:`MAX_TEXT` characters is shown as
``…``, so a tree that doubles at every level (``x = x + x`` sixty-four
times) prints in linear time. Integers too long for a decimal string are shown by
their size (``⟨integer of 5001 digits⟩``), never converted.

Printed as the tree says (``labels=False``, what a checked certificate is reported as),
a variable's name is shown as it is only when it cannot be read as anything else
(:func:`is_plain_name`): ASCII or Greek letters that look like no other, digits,
subscript digits, ``_``, primes and a few accents, not the printer's own words (``I``,
``tr``, ``π``, ...); any other name is quoted (:func:`name_text`), so a rotation named
``R)+tr(R`` prints as ``tr("R)+tr(R") <= 3``, never ``tr(R)+tr(R) <= 3``.

The printer reads a tree's fields only (``op``, ``args``, ``data``, ``label``) and
imports nothing of :mod:`verify.proof.expr`, which uses it for ``str`` and ``repr``.
"""

from __future__ import annotations

import json
import unicodedata
from collections.abc import Callable, Mapping
from fractions import Fraction
from typing import TYPE_CHECKING

from verify.artefacts.text import shown

if TYPE_CHECKING:
    from verify.proof.expr import Expr

MAX_TEXT = 4000  # characters of one rendered expression before it is abbreviated
MAX_DIGITS = 4000  # digits of an integer printed in full (Python converts up to 4300)

_FUNCS = {
    "trace": "tr",
    "sk": "sk",
    "sym": "sym",
    "hat": "hat",
    "vee": "vee",
    "cos": "cos",
    "sin": "sin",
    "lambda_min": "λmin",
}


def to_text(e: Expr, labels: bool = True, names: Mapping[int, str] | None = None) -> str:
    """The expression as text; with ``labels=False`` every author's label is ignored and
    the tree itself is printed (variables by their names, quoted by :func:`name_text`
    when they could be misread, or as ``names`` maps their ``uid``), so the text says
    what is evaluated. Labels and names are user text: shown escaped
    (:func:`verify.artefacts.text.shown`)."""
    return _Printer(labels, names).text(e, 0)


def tree_text(names: Mapping[int, str] | None = None) -> Callable[[Expr], str]:
    """``to_text(e, labels=False, names=names)`` for many expressions with one memo, so
    shared subtrees are printed once over all of them (linear in the nodes)."""
    printer = _Printer(False, names)
    return lambda e: printer.text(e, 0)


#: Words of the printed language a bare name must not be (functions, constants, gaps).
RESERVED = frozenset({*_FUNCS.values(), "I", "π", "gap"})
#: Letters a bare name may hold: ASCII, and the Greek letters that do not look like a
#: Latin one (omicron and the capitals Α, Β, Ε, ... are quoted, so ``Α`` and ``A``
#: never print alike).
_LETTERS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                     "αβγδεζηθικλμνξπρςστυφχψω" "ΓΔΘΛΞΠΣΦΨΩ")
#: After the first letter, also: digits, subscript digits, ``_``, primes, and a few
#: combining accents (bar, hat, tilde, dot, vector arrow; not the overline, which looks
#: like the bar).
_FOLLOWING = frozenset("0123456789₀₁₂₃₄₅₆₇₈₉_′'"
                       "\u0300\u0301\u0302\u0303\u0304\u0306\u0307\u0308\u030c\u20d7")


def is_plain_name(name: str) -> bool:
    """True when ``name`` prints bare without being misread: a letter (ASCII, or Greek
    unlike any Latin one) or ``_``, then letters, digits, subscript digits, ``_``,
    primes or a few combining accents; in NFC (so no two spellings of one look), and
    not a word of the printed language (``tr``, ``I``, ``λmin``, ``π``, ...)."""
    if not name or name in RESERVED or unicodedata.normalize("NFC", name) != name:
        return False
    first, rest = name[0], name[1:]
    return ((first in _LETTERS or first == "_")
            and all(ch in _LETTERS or ch in _FOLLOWING for ch in rest))


def name_text(name: str) -> str:
    """A variable's name as printed in a claim: bare when :func:`is_plain_name`, else
    in double quotes with ``"`` and ``\\`` escaped (JSON string syntax), which the
    printer never uses otherwise; control and bidi characters shown escaped."""
    if is_plain_name(name):
        return name
    return shown(json.dumps(name, ensure_ascii=False))


_CHART_GAPS = {"angle": "π", "unit_vector": "(0, 0, 1)"}


def integer_text(n: int) -> str:
    """Decimal digits of ``n``, or its size when it has more than MAX_DIGITS digits."""
    if n.bit_length() <= MAX_DIGITS * 3:  # below 10^(0.9 MAX_DIGITS): safe to convert
        return str(n)
    digits = _digits(abs(n))
    if digits <= MAX_DIGITS:
        return str(n)
    return f"{'-' if n < 0 else ''}⟨integer of {digits} digits⟩"


def _digits(n: int) -> int:
    k = max(1, int(n.bit_length() * 0.30102999566398120) - 1)
    while 10**k <= n:
        k += 1
    return k


def _wrap(s: str, inner: int, outer: int) -> str:
    return f"({s})" if inner < outer else s


class _Printer:
    def __init__(self, labels: bool = True, names: Mapping[int, str] | None = None) -> None:
        self.memo: dict[tuple[int, int], str] = {}
        self.labels = labels
        self.names = names or {}

    def text(self, e: Expr, prec: int) -> str:
        key = (id(e), prec)
        if key not in self.memo:
            s = self._text(e, prec)
            if len(s) > MAX_TEXT:
                s = "…"
            self.memo[key] = s
        return self.memo[key]

    def _text(self, e: Expr, prec: int) -> str:
        op, t = e.op, self.text
        if not self.labels:  # the tree, whatever its labels say
            if op == "var":
                given = self.names.get(e.data.uid)
                return given if given is not None else name_text(e.data.name)
            if op == "identity":
                return "I"
            if op == "chart_gap":
                return _CHART_GAPS.get(e.data, "gap")
        elif e.label is not None:
            return shown(e.label)
        if op == "const":
            v: Fraction = e.data
            s = (integer_text(v.numerator) if v.denominator == 1
                 else f"{integer_text(v.numerator)}/{integer_text(v.denominator)}")
            return _wrap(s, 2 if v.denominator == 1 and v >= 0 else 1, prec)
        if op == "zero":
            return "0"
        if op == "add":
            a, b = e.args
            if b.op == "neg":
                return _wrap(f"{t(a, 1)} - {t(b.args[0], 2)}", 1, prec)
            return _wrap(f"{t(a, 1)} + {t(b, 1)}", 1, prec)
        if op == "neg":
            return _wrap(f"-{t(e.args[0], 2)}", 1, prec)
        if op in ("scale", "matmul"):
            a, b = e.args
            return _wrap(f"{t(a, 2)} {t(b, 2)}", 2, prec)
        if op == "transpose":
            return f"{t(e.args[0], 3)}ᵀ"
        if op in _FUNCS:
            return f"{_FUNCS[op]}({t(e.args[0], 0)})"
        if op == "dot":
            return f"<{t(e.args[0], 0)}, {t(e.args[1], 0)}>"
        if op == "outer":
            return f"{t(e.args[0], 3)} {t(e.args[1], 3)}ᵀ"
        return op
