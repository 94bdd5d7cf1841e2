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

from math import comb

from verify.proof.expr import Expr, nodes, postorder, variables_of

MAX_DEGREE = 48  # polynomial degree in the variables' values
MAX_CONSTANT_BITS = 8192  # bits of a constant's numerator or denominator (~2466 digits)
MAX_NODES = 100_000  # distinct nodes of one step's expressions
MAX_TERMS = 2_000_000  # estimated terms of an expression's entries, expanded

#: Terms of one entry of a variable's value, and how many atoms (chart coordinates) it
#: has: a rotation's entries are quadratics in its quaternion (4 terms, 4 atoms).
_VALUE = {"rotation": (4, 4), "unit_vector": (1, 3), "vector": (1, 3), "matrix": (1, 9),
          "symmetric": (1, 6), "angle": (1, 2), "scalar": (1, 1)}
#: Factor on the terms of the argument(s) an entry of each operation sums over.
_FAN = {"matmul": 3, "dot": 3, "trace": 3, "sk": 2, "sym": 2, "vee": 2}

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


def terms(*exprs: Expr) -> int:
    """An upper bound on the number of terms of an entry of the expressions, expanded as
    polynomials in the variables' chart coordinates (each node once): the product rule
    on the shared tree, and never more than the monomials of that degree in that many
    coordinates. Computed before any expansion."""
    count: dict[int, int] = {}
    for e in postorder(*exprs):
        if e.op == "var":
            t = _VALUE.get(e.data.kind, (1, 1))[0]
        elif not e.args:
            t = 1
        elif e.op in ("cos", "sin", "lambda_min"):
            t = 1
        elif e.op in _SUM:
            t = count[id(e.args[0])] * count[id(e.args[1])] * _FAN.get(e.op, 1)
        elif e.op == "add":
            t = count[id(e.args[0])] + count[id(e.args[1])]
        else:
            t = max(count[id(a)] for a in e.args) * _FAN.get(e.op, 1)
        count[id(e)] = min(t, 10 ** 30)
    atoms = sum(_VALUE.get(v.kind, (1, 1))[1] for v in variables_of(*exprs))
    atoms += sum(1 for e in nodes(*exprs) if e.op == "lambda_min")
    d = degree(*exprs)
    bound = comb(atoms + d, d) if d <= 4096 else 10 ** 30
    return min(max((count[id(e)] for e in exprs), default=0), bound)


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


def over_term_limit(*exprs: Expr, limit: int = MAX_TERMS) -> str:
    """Why expanding the expressions' entries is too much work (:func:`terms` over
    ``limit``, or :func:`over_limits`), or "". Used before the tangency re-check of
    declared dynamics and before the Coq exporter expands a step."""
    why = over_limits(*exprs)
    if why:
        return why
    t = terms(*exprs)
    if t > limit:
        return f"about {t:.1e} terms when expanded, more than {limit:.0e}"
    return ""
