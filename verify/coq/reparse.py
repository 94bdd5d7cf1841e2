"""The round trip of a written statement: the Coq text of a theorem read back into a
term tree and compared with the tree the exporter meant to state.

:func:`intended` builds the tree from the step's own expressions (the paper's language,
Section 3) with a table of its own (operation and shape to the prelude's name), not from
the text the exporter wrote; :func:`parse_statement` reads the text a ``.v`` file holds.
Both are iterative (no recursion), so a deep expression is no limit. A statement that
reads back as another tree than intended is refused by the audit
(:func:`verify.coq.audit.statement_problems`).

A tree is written as one flat string in prefix form (``name``, ``#p/q``,
``head(a,b)``, ``+(a,b)``, ``*(a,b)``, ``-(a)``), so comparing, storing and pickling it
never recurses, however deep the expression.
"""

from __future__ import annotations

import re
from fractions import Fraction

from verify.proof.expr import MATRIX, SCALAR, VECTOR, Expr, postorder

#: The prelude's name of each operation on vectors and matrices (``SO3.v``).
_HEADS = {("add", VECTOR): "vadd", ("add", MATRIX): "madd", ("neg", VECTOR): "vneg",
          ("neg", MATRIX): "mneg", ("scale", VECTOR): "vscale", ("scale", MATRIX): "mscale",
          ("matmul", VECTOR): "mvmul", ("matmul", MATRIX): "mmul"}
_UNARY = {"transpose": "mT", "trace": "tr", "sk": "sk", "sym": "sym", "hat": "hat",
          "vee": "vee", "cos": "cos", "sin": "sin", "dot": "vdot", "outer": "outer"}
_ZEROS = {VECTOR: "vzero", MATRIX: "Z3"}
RELATIONS = ("=", "<=", ">=")
#: The prelude's derivative predicates (Coquelicot's ``is_derive``; ``Traj.v``).
DERIVATIVES = ("is_derive", "is_mderiv", "is_vderiv")


class ReparseError(ValueError):
    """Text that is not a statement the exporter's grammar writes."""


def _num(c: Fraction) -> str:
    return f"#{c.numerator}/{c.denominator}"


def _app(head: str, args) -> str:
    return f"{head}({','.join(args)})"


def intended(e: Expr, naming, *, use_phi: bool = True) -> str:
    """The tree of ``e`` as the statement means it (``naming``: the section's names)."""
    from verify.coq.terms import _is_phi

    tree: dict[int, str] = {}
    for node in postorder(e):
        op, a, shape = node.op, [tree.get(id(x), "") for x in node.args], node.shape
        if op == "var":
            t = naming.variable(node.data)
        elif op == "const":
            t = _num(Fraction(node.data))
        elif op == "identity":
            t = "I3"
        elif op == "zero":
            t = _ZEROS.get(shape, _num(Fraction(0)))
        elif op == "lambda_min":
            t = naming.lambda_atom(node)
        elif use_phi and (r := _is_phi(node)) is not None:
            t = _app("phi", [tree[id(r)]])
        elif op in ("add", "scale") and shape == SCALAR:
            t = _app("+" if op == "add" else "*", a)
        elif op == "neg" and shape == SCALAR:
            t = _app("-", a)
        elif (op, shape) in _HEADS:
            t = _app(_HEADS[(op, shape)], a)
        elif op in _UNARY:
            t = _app(_UNARY[op], a)
        else:
            raise ReparseError(f"no Coq term for the operation {op!r}")
        tree[id(node)] = t
    return tree[id(e)]


def intended_statement(lhs: Expr, relation: str, rhs: Expr, naming) -> str:
    return f"{intended(lhs, naming)} {relation} {intended(rhs, naming)}"


_TOKEN = re.compile(r"\s*(?:(<=|>=|:=|=>|->)|(-?\d+)|([A-Za-z_][A-Za-z0-9_']*)|([()+*/=-]))")


class _Term(str):
    """A parsed term (its flat string), told apart from a symbol token."""


class _Num(_Term):
    """A parsed number, with its value."""

    value: Fraction


def _number(value: Fraction) -> _Num:
    n = _Num(_num(value))
    n.value = value
    return n


def _tokens(text: str) -> list:
    out: list = []
    i, n = 0, len(text)
    while i < n:
        if text[i:].isspace():
            break
        m = _TOKEN.match(text, i)
        if not m:
            raise ReparseError(f"unexpected text at {text[i:i + 20]!r}")
        rel, num, ident, sym = m.groups()
        if rel or sym:
            out.append(rel or sym)
        elif num:
            out.append(_number(Fraction(int(num))))
        else:
            out.append(_Term(ident))
        i = m.end()
    return out


def _close(items: list) -> _Term:
    """The term of one parenthesised group of items."""
    if len(items) == 3 and items[1] == "/" and all(
            isinstance(x, _Num) for x in (items[0], items[2])):
        return _number(items[0].value / items[2].value)
    if len(items) == 1 and isinstance(items[0], _Num):
        return items[0]
    if len(items) == 3 and items[1] in ("+", "*") and all(isinstance(x, _Term)
                                                          for x in (items[0], items[2])):
        return _Term(_app(items[1], [items[0], items[2]]))
    if len(items) == 2 and items[0] == "-" and isinstance(items[1], _Term):
        return _Term(_app("-", [items[1]]))
    if (len(items) == 4 and items[0] == "fun" and items[2] == "=>"
            and isinstance(items[1], _Term) and isinstance(items[3], _Term)):
        return _Term(_app("fun", [items[1], items[3]]))
    if (len(items) >= 2 and isinstance(items[0], _Term) and not isinstance(items[0], _Num)
            and re.match(r"[A-Za-z_]", items[0]) and "(" not in items[0]
            and all(isinstance(x, _Term) for x in items[1:])):
        return _Term(_app(items[0], items[1:]))
    raise ReparseError("a group the exporter's grammar does not write")


def parse_statement(text: str) -> str:
    """The flat tree ``lhs REL rhs`` of a statement as written, its leading
    ``let NAME := TERM in`` bindings substituted (each name stands for its term)."""
    stack: list[list] = [[]]
    env: dict[str, _Term] = {}
    for tok in _tokens(text):
        if isinstance(tok, _Term) and not isinstance(tok, _Num) and tok in env:
            tok = env[tok]
        if len(stack) == 1 and isinstance(tok, _Term) and tok == "in":
            top = stack[0]
            if (len(top) != 4 or top[0] != "let" or top[2] != ":="
                    or not isinstance(top[3], _Term) or top[1] in env
                    or not re.fullmatch(r"s_[0-9]+", top[1])):
                raise ReparseError("a let binding the exporter does not write")
            env[str(top[1])] = top[3]
            stack[0] = []
            continue
        if tok == "(" and not isinstance(tok, _Term):
            stack.append([])
        elif tok == ")" and not isinstance(tok, _Term):
            if len(stack) == 1:
                raise ReparseError("unbalanced parentheses")
            group = stack.pop()
            stack[-1].append(_close(group))
        else:
            stack[-1].append(tok)
    if len(stack) != 1:
        raise ReparseError("unbalanced parentheses")
    top = stack[0]
    if any(x == "->" and not isinstance(x, _Term) for x in top) or (
            top and top[0] in DERIVATIVES):
        return _implications(top)
    if (len(top) != 3 or isinstance(top[1], _Term) or top[1] not in RELATIONS
            or not all(isinstance(x, _Term) for x in (top[0], top[2]))):
        raise ReparseError("not a statement 'lhs REL rhs'")
    return f"{top[0]} {top[1]} {top[2]}"


def _implications(top: list) -> str:
    """A derivative theorem's statement (:mod:`verify.coq.ddt`): premises and conclusion
    separated by ``->``, each ``PRED f t d`` or ``a = b``; the conclusion a ``PRED``."""
    parts: list[list] = [[]]
    for x in top:
        if x == "->" and not isinstance(x, _Term):
            parts.append([])
        else:
            parts[-1].append(x)
    out = []
    for part in parts:
        if (len(part) == 4 and part[0] in DERIVATIVES
                and all(isinstance(x, _Term) for x in part[1:])):
            out.append(_app(str(part[0]), [str(x) for x in part[1:]]))
        elif (len(part) == 3 and part[1] == "=" and not isinstance(part[1], _Term)
                and isinstance(part[0], _Term) and isinstance(part[2], _Term)):
            out.append(f"{part[0]} = {part[2]}")
        else:
            raise ReparseError("a premise or conclusion the exporter does not write")
    if not out[-1].startswith(DERIVATIVES):
        raise ReparseError("a derivative theorem concludes with a derivative")
    return " -> ".join(out)
