"""Plain-text rendering of expressions for reports and error messages."""

from __future__ import annotations

from fractions import Fraction

from verify.proof.expr import Expr

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


def to_text(e: Expr) -> str:
    return _text(e, 0)


def _wrap(s: str, inner: int, outer: int) -> str:
    return f"({s})" if inner < outer else s


def _text(e: Expr, prec: int) -> str:
    if e.label is not None:
        return e.label
    op = e.op
    if op == "const":
        v: Fraction = e.data
        s = str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"
        return _wrap(s, 2 if v.denominator == 1 and v >= 0 else 1, prec)
    if op == "zero":
        return "0"
    if op == "add":
        a, b = e.args
        if b.op == "neg":
            return _wrap(f"{_text(a, 1)} - {_text(b.args[0], 2)}", 1, prec)
        return _wrap(f"{_text(a, 1)} + {_text(b, 1)}", 1, prec)
    if op == "neg":
        return _wrap(f"-{_text(e.args[0], 2)}", 1, prec)
    if op in ("scale", "matmul"):
        a, b = e.args
        return _wrap(f"{_text(a, 2)} {_text(b, 2)}", 2, prec)
    if op == "transpose":
        return f"{_text(e.args[0], 3)}ᵀ"
    if op in _FUNCS:
        return f"{_FUNCS[op]}({_text(e.args[0], 0)})"
    if op == "dot":
        return f"<{_text(e.args[0], 0)}, {_text(e.args[1], 0)}>"
    if op == "outer":
        return f"{_text(e.args[0], 3)} {_text(e.args[1], 3)}ᵀ"
    return op
