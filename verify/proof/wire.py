"""Derivations as plain data: the trust boundary of ``verify check FILE``.

A derivation file runs in a separate process (:mod:`verify.proof.isolate`), which only
builds the derivations of the paper's proof language (Section 3: rotations, unit vectors,
angles, the dynamics of eqs. (9), (11), (13), side conditions and assumptions) and hands
them to the checker as JSON in the schema ``verify-derivations/1`` below. The checker
process rebuilds every object from this data with its own classes and constructors, so
nothing the file made (a subclass, a mutated attribute, a patched function) reaches it.

Schema ``verify-derivations/1`` (every field required, no other field allowed)::

    {"schema": "verify-derivations/1",
     "variables": [{"name": str, "kind": "rotation"|..., "positive": bool}, ...],
     "contexts": [{"name": str, "variables": [var], "dynamics": [[var, node|null], ...]}],
     "nodes": [node, ...],            # children before parents (args < own index)
     "conditions": [{"label": str, "lhs": node, "rhs": node}],
     "assumptions": [{"label": str, "expr": node, "kind": "pd"|"psd"|"pos"|"nonneg",
                      "cite": str}],
     "terms": [term, ...],            # how each non-negative term was made (below)
     "derivations": [{"name", "statement", "cite": str, "context": ctx, "start": node,
                      "where": [cond], "assumes": [asm],
                      "steps": [{"relation": "="|"<="|">=", "lhs": node, "rhs": node,
                                 "where": [cond], "note": str, "because": justification}]}]}

A node is ``{"op", "shape", "args", "label", "value"}``: ``op`` one of the expression
operations; ``value`` is ``[numerator, denominator]`` as hexadecimal strings for
``const`` (no decimal conversion, so no integer-to-string limit), the variable index for
``var``, the chart kind for ``chart_gap``, else null. The op ``ddt`` (``value``: the
context index, ``args``: the differentiated node, ``label``: its label or null) is
differentiated again here along the context's dynamics, which are themselves re-checked
to be tangent (``Context.dynamics``).

A term is ``{"make": constructor, "args": [...]}`` with the kernel's constructors of
:mod:`verify.proof.justify` (``square``, ``positive``, ``assumed``,
``trace_lower_bound``, ``trace_psd_product``) and ``add``, ``mul``, ``scale``; each
argument is tagged ``{"node": i}``, ``{"term": i}``, ``{"assumption": i}``,
``{"const": [num, den]}`` or null. Terms are issued again by those constructors, so their
grounds and premises are re-derived, never read. A justification is ``{"kind":
"algebra"|"citation"|"bound"|"sos", "note": str, "terms": [term], "assumptions": [asm],
"degree": int|null}`` (``terms`` for bound, ``assumptions`` and ``degree`` for sos; the
other two empty/null).

This module is the building side (run in the file's process, not trusted); the
checker's side, which reads the data back, is :mod:`verify.proof.rebuild`. Limits
(checked while reading, before any work): :data:`LIMITS`.
"""

from __future__ import annotations

import json
from fractions import Fraction
from typing import Any

from verify.proof.derivation import Context, Derivation, Step
from verify.proof.expr import (
    ANGLE,
    MATRIX,
    SCALAR,
    VECTOR,
    Expr,
    ProofSyntaxError,
    Variable,
)
from verify.proof.hypotheses import Assumption, Condition
from verify.proof.justify import (
    ByAlgebra,
    ByBound,
    ByCitation,
    BySos,
    Nonneg,
    recipe,
)

SCHEMA = "verify-derivations/1"

#: Bounds on what a derivation file may hand over.
LIMITS = {
    "nodes": 200_000,        # expression nodes in all (shared subtrees count once)
    "variables": 500,
    "derivations": 500,
    "steps": 5_000,          # in all derivations
    "terms": 50_000,
    "text": 20_000,          # characters of one name, label, note or citation
    "constant_bits": 65_536,  # bits of a constant's numerator or denominator
    "bytes": 64 * 2**20,     # the whole JSON document
    "differentiated": 1_000_000,  # distinct nodes all ddt nodes differentiate together
    "term_size": 2**20,      # one term's reason, premises and assumptions (characters)
    "terms_size": 2**24,     # the same over all terms
}

_SHAPES = {"scalar": SCALAR, "vector": VECTOR, "matrix": MATRIX, "angle": ANGLE}
_SHAPE_NAMES = {v: k for k, v in _SHAPES.items()}
_JUSTIFICATIONS = {ByAlgebra: "algebra", ByCitation: "citation", ByBound: "bound",
                   BySos: "sos"}


# -- the building process: objects -> data ----------------------------------------------
class _Encoder:
    def __init__(self) -> None:
        self.variables: list[dict] = []
        self.var_index: dict[int, int] = {}
        self.contexts: list[dict] = []
        self.ctx_index: dict[int, int] = {}
        self.ctx_objects: list[Context] = []
        self.ctx_ready: set[int] = set()
        self.nodes: list[dict] = []
        self.node_index: dict[int, int] = {}
        self.keep: list[Any] = []  # keeps encoded objects alive (ids stay unique)
        self.derived: dict[int, tuple[int, Expr]] = {}
        self.derived_args: dict[int, tuple[int, Expr, Expr]] = {}
        self.conditions: list[dict] = []
        self.cond_index: dict[int, int] = {}
        self.assumptions: list[dict] = []
        self.asm_index: dict[int, int] = {}
        self.terms: list[dict] = []
        self.term_index: dict[int, int] = {}

    def variable(self, v: Variable) -> int:
        if type(v) is not Variable:
            raise ProofSyntaxError("a variable was not made by a context")
        if id(v) not in self.var_index:
            self.keep.append(v)
            self.var_index[id(v)] = len(self.variables)
            self.variables.append({"name": _text(v.name), "kind": str.__str__(v.kind),
                                   "positive": v.positive is True})
        return self.var_index[id(v)]

    def context(self, ctx: Context) -> int:
        if type(ctx) is not Context:
            raise ProofSyntaxError("a derivation's context must be a Context")
        if id(ctx) not in self.ctx_index:
            k = len(self.contexts)
            self.keep.append(ctx)
            self.ctx_index[id(ctx)] = k
            entry = {"name": _text(ctx.name), "variables": [], "dynamics": []}
            self.contexts.append(entry)
            self.ctx_objects.append(ctx)
            entry["variables"] = [self.variable(v) for v in list(ctx.variables)]
            for out, arg in list(ctx._derived):
                self.keep.append(out)
                self.derived[id(out)] = (k, arg)
                if out.args:  # a copy of it under another label (.named) shares its args
                    self.derived_args[id(out.args)] = (k, arg, out)
            for uid, d in list(ctx._dynamics.items()):
                v = next((w for w in ctx.variables if w.uid == uid), None)
                if v is None:
                    raise ProofSyntaxError(f"context {ctx.name!r}: dynamics of an unknown "
                                           "variable")
                entry["dynamics"].append([self.variable(v),
                                          None if d is None else self.expr(d)])
            self.ctx_ready.add(k)
        return self.ctx_index[id(ctx)]

    def expr(self, root: Any) -> int:
        if type(root) is not Expr:
            raise ProofSyntaxError(f"expected an expression, got {type(root).__name__}")
        stack: list[tuple[Expr, bool]] = [(root, False)]
        while stack:
            e, expanded = stack.pop()
            if id(e) in self.node_index:
                continue
            if type(e) is not Expr:
                raise ProofSyntaxError(f"expected an expression, got {type(e).__name__}")
            made = self.derived.get(id(e)) or self._named_derivative(e)
            ddt_of = made if made is not None and made[0] in self.ctx_ready else None
            children = (ddt_of[1],) if ddt_of is not None else tuple(e.args)
            if expanded:
                self._node(e, children, ddt_of)
                continue
            stack.append((e, True))
            stack.extend((a, False) for a in reversed(children) if id(a) not in self.node_index)
            if len(self.nodes) + len(stack) > 4 * LIMITS["nodes"]:
                raise ProofSyntaxError("an expression has too many nodes")
        return self.node_index[id(root)]

    def _named_derivative(self, e: Expr) -> tuple[int, Expr] | None:
        """(context, argument) when ``e`` is a derivative under a label of its own
        (``ctx.ddt(h).named("ḣ")``): it travels as ``ddt`` too, so the checker's
        process differentiates it again and knows it for a derivative."""
        found = self.derived_args.get(id(e.args)) if e.args else None
        if found is None:
            return None
        k, arg, out = found
        if e.op != out.op or e.shape != out.shape or e.data != out.data:
            return None
        return k, arg

    def _node(self, e: Expr, children: tuple, ddt_of: tuple | None) -> None:
        self.keep.append(e)
        if ddt_of is not None:
            entry = {"op": "ddt", "shape": _SHAPE_NAMES.get(e.shape), "value": ddt_of[0],
                     "args": [self.node_index[id(ddt_of[1])]],
                     "label": None if e.label is None else _text(e.label)}
        else:
            value: Any = None
            if e.op == "const":
                value = _const(e.data)
            elif e.op == "var":
                value = self.variable(e.data)
            elif e.op == "chart_gap":
                value = _text(e.data)
            entry = {"op": _text(e.op), "shape": _SHAPE_NAMES.get(e.shape),
                     "value": value, "args": [self.node_index[id(a)] for a in children],
                     "label": None if e.label is None else _text(e.label)}
        self.node_index[id(e)] = len(self.nodes)
        self.nodes.append(entry)

    def condition(self, c: Any) -> int:
        if type(c) is not Condition:
            raise ProofSyntaxError("where= takes conditions made by ctx.condition()")
        if id(c) not in self.cond_index:
            self.keep.append(c)
            entry = {"label": _text(c.label), "lhs": self.expr(c.lhs), "rhs": self.expr(c.rhs)}
            self.cond_index[id(c)] = len(self.conditions)
            self.conditions.append(entry)
        return self.cond_index[id(c)]

    def assumption(self, a: Any) -> int:
        if type(a) is not Assumption:
            raise ProofSyntaxError("an assumption must be made by ctx.assume()")
        if id(a) not in self.asm_index:
            self.keep.append(a)
            entry = {"label": _text(a.label), "expr": self.expr(a.expr),
                     "kind": _text(a.kind), "cite": _text(a.cite)}
            self.asm_index[id(a)] = len(self.assumptions)
            self.assumptions.append(entry)
        return self.asm_index[id(a)]

    def term(self, t: Any) -> int:
        if id(t) in self.term_index:
            return self.term_index[id(t)]
        how = recipe(t) if type(t) is Nonneg else None
        if how is None:
            raise ProofSyntaxError("a non-negative term must come from the kernel's "
                                   "constructors, unaltered")
        args = [self._argument(x) for x in how[1:]]
        self.keep.append(t)
        self.term_index[id(t)] = len(self.terms)
        self.terms.append({"make": how[0], "args": args})
        return self.term_index[id(t)]

    def _argument(self, x: Any) -> Any:
        if x is None:
            return None
        if type(x) is Expr:
            return {"node": self.expr(x)}
        if type(x) is Nonneg:
            return {"term": self.term(x)}
        if type(x) is Assumption:
            return {"assumption": self.assumption(x)}
        if type(x) in (int, Fraction):
            return {"const": _const(Fraction(x))}
        raise ProofSyntaxError(f"a kernel term was made from a {type(x).__name__}")

    def justification(self, j: Any) -> dict:
        kind = _JUSTIFICATIONS.get(type(j))
        if kind is None:
            raise ProofSyntaxError("a step needs a justification of verify.proof (by_algebra, "
                                   "by_bound, by_sos, by_citation)")
        out = {"kind": kind, "note": _text(j.note), "terms": [], "assumptions": [],
               "degree": None}
        if kind == "bound":
            terms = j.terms
            if type(terms) is not tuple:
                raise ProofSyntaxError("by_bound's terms were replaced")
            out["terms"] = [self.term(t) for t in terms]
        if kind == "sos":
            if type(j.assumptions) is not tuple:
                raise ProofSyntaxError("by_sos's assumptions were replaced")
            out["assumptions"] = [self.assumption(a) for a in j.assumptions]
            degree = j.degree
            if degree is not None and type(degree) is not int:
                raise ProofSyntaxError("by_sos(degree=...) must be an integer")
            out["degree"] = degree
        return out

    def derivation(self, d: Any) -> dict:
        if type(d) is not Derivation:
            raise ProofSyntaxError(f"expected a Derivation, got {type(d).__name__}")
        ctx = self.context(d.context)
        steps = []
        for i, s in enumerate(list(d.steps), 1):
            if type(s) is not Step:
                raise ProofSyntaxError(f"{_text(d.name)}: step {i} is not a step "
                                       "(use equals/le/ge)")
            steps.append({"relation": _text(s.relation), "lhs": self.expr(s.lhs),
                          "rhs": self.expr(s.rhs),
                          "where": [self.condition(c) for c in tuple(s.where)],
                          "note": _text(s.note), "because": self.justification(s.because)})
        return {"name": _text(d.name), "statement": _text(d.statement), "cite": _text(d.cite),
                "context": ctx, "start": self.expr(d.start),
                "where": [self.condition(c) for c in tuple(d.where)],
                "assumes": [self.assumption(a) for a in tuple(d.assumes)], "steps": steps}


def _text(x: Any) -> str:
    if not isinstance(x, str):
        raise ProofSyntaxError(f"expected a string, got {type(x).__name__}")
    return str.__str__(x)  # a plain copy of a str subclass, none of its methods


def _const(v: Any) -> list[str]:
    if type(v) is not Fraction:
        raise ProofSyntaxError("a constant is an int or a Fraction")
    return [_hex(v.numerator), _hex(v.denominator)]


def _hex(n: int) -> str:
    return ("-" if n < 0 else "") + format(abs(int(n)), "x")


def encode(derivations: list[Derivation]) -> dict:
    """The derivations as data (run in the process that loaded the file)."""
    enc = _Encoder()
    out = [enc.derivation(d) for d in derivations]
    return {"schema": SCHEMA, "variables": enc.variables, "contexts": enc.contexts,
            "nodes": enc.nodes, "conditions": enc.conditions,
            "assumptions": enc.assumptions, "terms": enc.terms, "derivations": out}


def dumps(data: dict) -> str:
    return json.dumps(data, ensure_ascii=True, separators=(",", ":"))


__all__ = ["LIMITS", "SCHEMA", "dumps", "encode"]
