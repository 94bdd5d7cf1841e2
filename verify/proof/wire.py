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
context index, ``args``: the differentiated node) is differentiated again here along the
context's dynamics, which are themselves re-checked to be tangent (``Context.dynamics``).

A term is ``{"make": constructor, "args": [...]}`` with the kernel's constructors of
:mod:`verify.proof.justify` (``square``, ``positive``, ``assumed``,
``trace_lower_bound``, ``trace_psd_product``) and ``add``, ``mul``, ``scale``; each
argument is tagged ``{"node": i}``, ``{"term": i}``, ``{"assumption": i}``,
``{"const": [num, den]}`` or null. Terms are issued again by those constructors, so their
grounds and premises are re-derived, never read. A justification is ``{"kind":
"algebra"|"citation"|"bound"|"sos", "note": str, "terms": [term], "assumptions": [asm],
"degree": int|null}`` (``terms`` for bound, ``assumptions`` and ``degree`` for sos; the
other two empty/null).

Limits (checked while reading, before any work): :data:`LIMITS`.
"""

from __future__ import annotations

import json
from fractions import Fraction
from typing import Any

from verify.errors import VerifyInputError
from verify.proof.derivation import RELATIONS, Assumption, Condition, Context, Derivation, Step
from verify.proof.expr import (
    ANGLE,
    CHART_GAPS,
    KINDS,
    MATRIX,
    MAX_DEPTH,
    SCALAR,
    VECTOR,
    Expr,
    ProofSyntaxError,
    Variable,
    _well_formed,
    var,
)
from verify.proof.justify import (
    ByAlgebra,
    ByBound,
    ByCitation,
    Justification,
    Nonneg,
    assumed,
    positive,
    recipe,
    square,
    trace_lower_bound,
    trace_psd_product,
)
from verify.proof.sos_step import BySos, by_sos

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
            made = self.derived.get(id(e))
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

    def _node(self, e: Expr, children: tuple, ddt_of: tuple | None) -> None:
        self.keep.append(e)
        if ddt_of is not None:
            entry = {"op": "ddt", "shape": _SHAPE_NAMES.get(e.shape), "value": ddt_of[0],
                     "args": [self.node_index[id(ddt_of[1])]], "label": None}
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


# -- the checker process: data -> its own objects -----------------------------------------
class WireError(ProofSyntaxError):
    """The data handed over by a derivation file is malformed or over a limit."""


def _fields(obj: Any, what: str, names: tuple[str, ...]) -> dict:
    if type(obj) is not dict or set(obj) != set(names):
        raise WireError(f"{what}: expected exactly the fields {', '.join(names)}")
    return obj


def _str(x: Any, what: str) -> str:
    if type(x) is not str or len(x) > LIMITS["text"]:
        raise WireError(f"{what}: expected a string of at most {LIMITS['text']} characters")
    return x


def _list(x: Any, what: str, limit: int) -> list:
    if type(x) is not list or len(x) > limit:
        raise WireError(f"{what}: expected a list of at most {limit} items")
    return x


def _index(x: Any, size: int, what: str) -> int:
    if type(x) is not int or not 0 <= x < size:
        raise WireError(f"{what}: expected an index below {size}")
    return x


def _int_hex(x: Any, what: str) -> int:
    bits = LIMITS["constant_bits"]
    if type(x) is not str or not 0 < len(x) <= bits // 4 + 2:
        raise WireError(f"{what}: a constant has more than {bits} bits")
    body = x[1:] if x.startswith("-") else x
    if not body or any(ch not in "0123456789abcdef" for ch in body):
        raise WireError(f"{what}: malformed constant")
    return int(x, 16)


def _fraction(x: Any, what: str) -> Fraction:
    if type(x) is not list or len(x) != 2:
        raise WireError(f"{what}: a constant is [numerator, denominator]")
    num, den = _int_hex(x[0], what), _int_hex(x[1], what)
    if den <= 0:
        raise WireError(f"{what}: a constant's denominator is positive")
    return Fraction(num, den)


class _Decoder:
    def __init__(self, data: Any):
        self.data = _fields(data, "derivations data", (
            "schema", "variables", "contexts", "nodes", "conditions", "assumptions", "terms",
            "derivations"))
        if data["schema"] != SCHEMA:
            raise WireError(f"schema is not {SCHEMA}")
        self.variables: list[Variable] = []
        for k, v in enumerate(_list(data["variables"], "variables", LIMITS["variables"])):
            v = _fields(v, f"variable {k}", ("name", "kind", "positive"))
            if v["kind"] not in KINDS or type(v["positive"]) is not bool:
                raise WireError(f"variable {k}: unknown kind or malformed 'positive'")
            self.variables.append(Variable(_str(v["name"], f"variable {k}"), v["kind"],
                                           v["positive"]))
        self.contexts: list[Context] = []
        self.dynamics: list[list] = []
        owner: dict[int, int] = {}
        for k, c in enumerate(_list(data["contexts"], "contexts", LIMITS["derivations"])):
            c = _fields(c, f"context {k}", ("name", "variables", "dynamics"))
            ctx = Context(_str(c["name"], f"context {k}"))
            for i in _list(c["variables"], f"context {k}", LIMITS["variables"]):
                i = _index(i, len(self.variables), f"context {k}")
                if i in owner:
                    raise WireError(f"context {k}: variable {i} belongs to another context")
                owner[i] = k
                v = self.variables[i]
                ctx.variables.append(v)
                if v.kind == "scalar":
                    ctx._dynamics[v.uid] = None
            self.contexts.append(ctx)
            self.dynamics.append(_list(c["dynamics"], f"context {k}", LIMITS["variables"]))
        self.declared = [False] * len(self.contexts)
        raw = _list(data["nodes"], "nodes", LIMITS["nodes"])
        self.nodes: list[Expr] = []
        self.depth: dict[int, int] = {}
        for k, n in enumerate(raw):
            e = self._node(k, n)
            if id(e) not in self.depth:  # a ddt result: its own nodes are ours already
                if not _well_formed(e):
                    raise WireError(f"node {k}: malformed {e.op!r} node")
                self.depth[id(e)] = 1 + max((self.depth.get(id(a), 0) for a in e.args),
                                            default=0)
                if self.depth[id(e)] > MAX_DEPTH:
                    raise WireError(f"an expression is nested more than {MAX_DEPTH} levels "
                                    "deep")
            self.nodes.append(e)

    def _declare(self, k: int) -> None:
        """Declare context k's dynamics (tangency re-checked) before its first ddt."""
        if self.declared[k]:
            return
        self.declared[k] = True
        ctx = self.contexts[k]
        seen: set[int] = set()
        for entry in self.dynamics[k]:
            if type(entry) is not list or len(entry) != 2:
                raise WireError(f"context {k}: a dynamics entry is [variable, node|null]")
            i = _index(entry[0], len(self.variables), f"context {k} dynamics")
            if i in seen:
                raise WireError(f"context {k}: dynamics of variable {i} given twice")
            seen.add(i)
            x = var(self.variables[i])
            if entry[1] is None:
                if self.variables[i].kind != "scalar":
                    ctx.constant(x)
                continue
            ctx.dynamics(x, self._node_ref(entry[1], f"context {k} dynamics"))

    def _node_ref(self, x: Any, what: str) -> Expr:
        return self.nodes[_index(x, len(self.nodes), what)]

    def _node(self, k: int, n: Any) -> Expr:
        what = f"node {k}"
        n = _fields(n, what, ("op", "shape", "value", "args", "label"))
        args = tuple(self.nodes[_index(a, k, what)] for a in _list(n["args"], what, 2))
        if n["shape"] not in _SHAPES:
            raise WireError(f"{what}: unknown shape")
        shape = _SHAPES[n["shape"]]
        label = None if n["label"] is None else _str(n["label"], what)
        op, value = n["op"], n["value"]
        if type(op) is not str:
            raise WireError(f"{what}: malformed op")
        if op == "ddt":
            ctx = _index(value, len(self.contexts), what)
            if len(args) != 1 or label is not None:
                raise WireError(f"{what}: ddt takes one expression")
            self._declare(ctx)
            out = self.contexts[ctx].ddt(args[0])
            if out.shape != shape:
                raise WireError(f"{what}: the derivative has another shape")
            return out
        if op == "const":
            data: Any = _fraction(value, what)
        elif op == "var":
            data = self.variables[_index(value, len(self.variables), what)]
        elif op == "chart_gap":
            if value not in CHART_GAPS:
                raise WireError(f"{what}: unknown chart")
            data = value
        elif value is not None:
            raise WireError(f"{what}: unexpected value")
        else:
            data = None
        return Expr(op, args, shape, data, label)  # checked by _well_formed (caller)

    def terms(self) -> list[Nonneg]:
        """Issue every term again with the kernel's constructors, in order (a term's
        arguments come before it, so nothing recurses)."""
        out: list[Nonneg] = []
        for k, t in enumerate(_list(self.data["terms"], "terms", LIMITS["terms"])):
            what = f"term {k}"
            t = _fields(t, what, ("make", "args"))
            args = [self._argument(a, out, what) for a in _list(t["args"], what, 6)]
            make = t["make"]
            if make not in _MAKERS or _MAKERS[make][0] != len(args):
                raise WireError(f"{what}: unknown constructor or wrong number of arguments")
            if make in ("add", "mul") and not all(type(a) is Nonneg for a in args):
                raise WireError(f"{what}: {make} combines two non-negative terms")
            term = _MAKERS[make][1](args)  # the kernel's own checks apply
            if type(term) is not Nonneg:
                raise WireError(f"{what}: {make} did not make a non-negative term")
            out.append(term)
        return out

    def _argument(self, a: Any, made: list[Nonneg], what: str) -> Any:
        if a is None:
            return None
        if type(a) is not dict or len(a) != 1:
            raise WireError(f"{what}: malformed argument")
        ((tag, x),) = a.items()
        if tag == "node":
            return self._node_ref(x, what)
        if tag == "term":
            return made[_index(x, len(made), what)]
        if tag == "assumption":
            return self.assumptions[_index(x, len(self.assumptions), what)]
        if tag == "const":
            value = _fraction(x, what)
            return value.numerator if value.denominator == 1 else value
        raise WireError(f"{what}: unknown argument tag")

    def objects(self) -> list[Derivation]:
        data = self.data
        self.conditions = []
        for k, c in enumerate(_list(data["conditions"], "conditions", LIMITS["nodes"])):
            c = _fields(c, f"condition {k}", ("label", "lhs", "rhs"))
            self.conditions.append(Condition(_str(c["label"], f"condition {k}"),
                                             self._node_ref(c["lhs"], f"condition {k}"),
                                             self._node_ref(c["rhs"], f"condition {k}")))
        self.assumptions = []
        for k, a in enumerate(_list(data["assumptions"], "assumptions", LIMITS["nodes"])):
            a = _fields(a, f"assumption {k}", ("label", "expr", "kind", "cite"))
            self.assumptions.append(Assumption(_str(a["label"], f"assumption {k}"),
                                               self._node_ref(a["expr"], f"assumption {k}"),
                                               _str(a["kind"], f"assumption {k}"),
                                               _str(a["cite"], f"assumption {k}")))
        cache = self.terms()
        out = []
        total = 0
        for k, d in enumerate(_list(data["derivations"], "derivations",
                                    LIMITS["derivations"])):
            what = f"derivation {k}"
            d = _fields(d, what, ("name", "statement", "cite", "context", "start", "where",
                                  "assumes", "steps"))
            steps = []
            for i, s in enumerate(_list(d["steps"], what, LIMITS["steps"]), 1):
                s = _fields(s, f"{what} step {i}", ("relation", "lhs", "rhs", "where", "note",
                                                    "because"))
                if s["relation"] not in RELATIONS:
                    raise WireError(f"{what} step {i}: unknown relation")
                steps.append(Step(s["relation"], self._node_ref(s["lhs"], what),
                                  self._node_ref(s["rhs"], what), self._because(
                                      s["because"], cache, f"{what} step {i}"),
                                  tuple(self._cond(c, what) for c in _list(
                                      s["where"], what, LIMITS["nodes"])),
                                  _str(s["note"], what)))
            total += len(steps)
            if total > LIMITS["steps"]:
                raise WireError(f"more than {LIMITS['steps']} steps")
            derivation = Derivation(
                _str(d["name"], what), self._node_ref(d["start"], what),
                self.contexts[_index(d["context"], len(self.contexts), what)],
                tuple(self._cond(c, what) for c in _list(d["where"], what, LIMITS["nodes"])),
                tuple(self.assumptions[_index(a, len(self.assumptions), what)]
                      for a in _list(d["assumes"], what, LIMITS["nodes"])),
                _str(d["statement"], what), _str(d["cite"], what))
            derivation.steps = steps
            out.append(derivation)
        return out

    def _cond(self, c: Any, what: str) -> Condition:
        return self.conditions[_index(c, len(self.conditions), what)]

    def _because(self, j: Any, cache: list[Nonneg], what: str) -> Justification:
        j = _fields(j, what, ("kind", "note", "terms", "assumptions", "degree"))
        kind, note = j["kind"], _str(j["note"], what)
        terms = _list(j["terms"], what, LIMITS["terms"])
        assumptions = _list(j["assumptions"], what, LIMITS["nodes"])
        if (kind != "bound" and terms) or (kind != "sos" and (assumptions
                                                             or j["degree"] is not None)):
            raise WireError(f"{what}: fields that a {kind} justification does not take")
        if kind == "algebra":
            return ByAlgebra(note)
        if kind == "citation":
            return ByCitation(note)
        if kind == "bound":
            return ByBound(tuple(cache[_index(t, len(cache), what)] for t in terms), note)
        if kind == "sos":
            degree = j["degree"]
            if degree is not None and type(degree) is not int:
                raise WireError(f"{what}: by_sos degree is an integer")
            return by_sos(*(self.assumptions[_index(a, len(self.assumptions), what)]
                            for a in assumptions), degree=degree, note=note)
        raise WireError(f"{what}: unknown justification kind")


_MAKERS = {
    "square": (1, lambda a: square(a[0])),
    "positive": (1, lambda a: positive(a[0])),
    "assumed": (1, lambda a: assumed(a[0])),
    "add": (2, lambda a: a[0] + a[1]),
    "mul": (2, lambda a: a[0] * a[1]),
    "scale": (2, lambda a: a[1] * a[0]),
    "trace_lower_bound": (4, lambda a: trace_lower_bound(a[0], a[1], gram=a[2],
                                                         gram_scale=a[3])),
    "trace_psd_product": (6, lambda a: trace_psd_product(
        a[0], a[1], a_psd=a[2], a_gram=a[3], b_gram=a[4], b_scale=a[5])),
}


def decode(data: Any) -> list[Derivation]:
    """Rebuild derivations from data with the checker's own classes.

    Raises ProofSyntaxError (with a one-line reason) for anything malformed, over a
    limit, or refused by the constructors (shapes, floats, kernel terms, dynamics).
    """
    try:
        out = _Decoder(data).objects()
    except ProofSyntaxError:
        raise
    except (ValueError, TypeError, KeyError, ArithmeticError, RecursionError,
            AttributeError, IndexError) as exc:  # anything the data can provoke
        raise WireError(f"malformed derivations data ({type(exc).__name__}: "
                        f"{str(exc)[:200]})") from None
    if not out:
        raise WireError("no derivation")
    return out


def loads(text: str) -> list[Derivation]:
    if len(text) > LIMITS["bytes"]:
        raise VerifyInputError(f"derivations data larger than {LIMITS['bytes']} bytes")

    def no_duplicates(pairs):
        keys = [k for k, _ in pairs]
        if len(set(keys)) != len(keys):
            raise WireError("duplicate field")
        return dict(pairs)

    try:
        data = json.loads(text, object_pairs_hook=no_duplicates,
                          parse_constant=_refuse_constant)
    except (ValueError, RecursionError) as exc:
        raise WireError(f"malformed derivations data ({type(exc).__name__})") from None
    return decode(data)


def _refuse_constant(name: str) -> Any:
    raise WireError(f"non-finite number {name}")


__all__ = ["LIMITS", "SCHEMA", "WireError", "decode", "dumps", "encode", "loads"]


