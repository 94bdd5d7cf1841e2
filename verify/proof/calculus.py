"""Time derivatives of expressions along declared dynamics (product rule on the tree).

A derivation about a closed loop states ``h-dot`` as ``ddt(h)``; the derivative is
formed here from the dynamics the user declared for each variable (for the paper:
R-bar-dot = hat(tilde-omega) R-bar, eq. (9); R_l-dot = R_l hat(omega_l), eq. (11);
R_r constant, Assumption 1). Nothing is simplified: the checker decides afterwards,
exactly, whether the derivative equals what the proof writes.
"""

from __future__ import annotations

from collections.abc import Mapping

from verify.proof.expr import (
    ANGLE,
    Expr,
    ProofSyntaxError,
    cos,
    dot,
    hat,
    outer,
    sin,
    sk,
    sym,
    tr,
    vee,
    zero,
)


def ddt(e: Expr, dynamics: Mapping[int, Expr | None],
        cache: dict[int, Expr | None] | None = None) -> Expr:
    """d/dt of ``e``; ``dynamics`` maps a variable uid to its derivative (None: constant).

    ``cache`` (node id -> derivative) may be shared by calls with the same dynamics, so
    that differentiating many trees with common subtrees visits each node once; the
    caller keeps those trees alive while the cache is in use."""
    cache = {} if cache is None else cache
    result = _ddt(e, dynamics, cache)
    return result if result is not None else zero(e.shape)


def _ddt(e: Expr, dyn: Mapping[int, Expr | None], cache: dict[int, Expr | None]) -> Expr | None:
    """Derivative, or None when it is identically zero (keeps trees small)."""
    key = id(e)
    if key in cache:
        return cache[key]
    out = _rule(e, dyn, cache)
    cache[key] = out
    return out


def _rule(e: Expr, dyn, cache) -> Expr | None:
    op = e.op
    if op in ("const", "identity", "zero", "chart_gap"):
        return None
    if op == "var":
        v = e.data
        if v.uid not in dyn:
            raise ProofSyntaxError(
                f"no dynamics declared for {v.name}; declare it (or declare it constant)"
            )
        return dyn[v.uid]
    if op == "lambda_min":
        raise ProofSyntaxError("lambda_min is not differentiable in this language")
    if e.shape == ANGLE:
        raise ProofSyntaxError("differentiate cos/sin of an angle, not the angle itself")
    d = [_ddt(a, dyn, cache) for a in e.args]
    a = e.args
    if op == "add":
        return _sum(d[0], d[1])
    if op == "neg":
        return None if d[0] is None else -d[0]
    if op in ("scale", "matmul"):
        left = None if d[0] is None else _mul(op, d[0], a[1])
        right = None if d[1] is None else _mul(op, a[0], d[1])
        return _sum(left, right)
    if op in ("transpose", "trace", "sk", "sym", "hat", "vee"):
        if d[0] is None:
            return None
        return {
            "transpose": lambda x: x.T,
            "trace": tr,
            "sk": sk,
            "sym": sym,
            "hat": hat,
            "vee": vee,
        }[op](d[0])
    if op in ("dot", "outer"):
        f = dot if op == "dot" else outer
        left = None if d[0] is None else f(d[0], a[1])
        right = None if d[1] is None else f(a[0], d[1])
        return _sum(left, right)
    if op in ("cos", "sin"):
        theta = e.args[0].data
        if theta.uid not in dyn:
            raise ProofSyntaxError(f"no dynamics declared for angle {theta.name}")
        rate = dyn[theta.uid]
        if rate is None:
            return None

        if op == "cos":
            return -(sin(e.args[0]) * rate)
        return cos(e.args[0]) * rate
    raise ProofSyntaxError(f"cannot differentiate operation {op}")


def _sum(x: Expr | None, y: Expr | None) -> Expr | None:
    if x is None:
        return y
    if y is None:
        return x
    return x + y


def _mul(op: str, x: Expr, y: Expr) -> Expr:
    """A product node like the original: scale(s, X) and matmul(M, X) have X's shape."""
    return Expr(op, (x, y), y.shape)
