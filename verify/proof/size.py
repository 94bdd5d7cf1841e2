"""Size limits a step must meet before exact algebra starts on it.

A derivation chooses the size of the exact work: ``(s + 1)`` squared sixteen times is a
16-node tree of degree 65536, ``s^4096 = 2`` a condition whose real roots are costly at
every sample. Before a step of the paper's language (Section 3) is decided, a bound on
the polynomial degree of every expression in the values of its variables (entries of
R and u, cos and sin of angles, free entries, lambda_min atoms) and the size of its
constants are computed over the shared tree (each node once); a step over a limit is
*inconclusive* with the reason, and no algebra is done. The limits leave ample room for
the paper's proofs (their largest degree is printed by ``verify.proof.size.degree``).
"""

from __future__ import annotations

from verify.proof.expr import Expr, nodes, postorder

MAX_DEGREE = 48  # polynomial degree in the variables' values
MAX_CONSTANT_BITS = 8192  # bits of a constant's numerator or denominator (~2466 digits)
MAX_NODES = 100_000  # distinct nodes of one step's expressions

_SUM = {"scale", "matmul", "dot", "outer"}
_ZERO = {"const", "identity", "zero", "chart_gap"}


def degree(*exprs: Expr) -> int:
    """An upper bound on the polynomial degree of the expressions in the values of their
    variables (each node once, children before parents)."""
    deg: dict[int, int] = {}
    for e in postorder(*exprs):
        if e.op in _ZERO:
            d = 0
        elif e.op in ("var", "cos", "sin", "lambda_min"):
            d = 1
        elif e.op in _SUM:
            d = deg[id(e.args[0])] + deg[id(e.args[1])]
        else:
            d = max(deg[id(a)] for a in e.args)
        deg[id(e)] = d
    return max((deg[id(e)] for e in exprs), default=0)


def over_limits(*exprs: Expr) -> str:
    """Why the expressions are too large to decide exactly, or ""."""
    count = 0
    for e in nodes(*exprs):
        count += 1
        if count > MAX_NODES:
            return f"more than {MAX_NODES} distinct expression nodes"
        if e.op == "const" and max(e.data.numerator.bit_length(),
                                   e.data.denominator.bit_length()) > MAX_CONSTANT_BITS:
            return f"a constant has more than {MAX_CONSTANT_BITS} bits"
    d = degree(*exprs)
    if d > MAX_DEGREE:
        return f"degree {d} exceeds {MAX_DEGREE} in the variables' values"
    return ""
