"""Rebuild derivations from the data a derivation file handed over (the checker's side).

The data is in the schema ``verify-derivations/1`` documented in :mod:`verify.proof.wire`.
This module is part of what a verdict of ``verify check`` rests on: it reads the JSON
strictly (exact fields, no duplicate keys, indices in range and pointing backwards, sizes
within :data:`verify.proof.wire.LIMITS`) and rebuilds every object with the checker's own
classes and constructors: variables get fresh identities, nodes are checked for their
shapes as they are built (the language of the paper's Section 3), ``ddt`` nodes are
differentiated again along dynamics declared again (and so re-checked to be tangent,
eqs. (9), (11), (13)), and non-negative terms are issued again by the kernel from their
recipes. See ``verify/proof/TRUSTED.md``.
"""

from __future__ import annotations

import json
from fractions import Fraction
from typing import Any

from verify.errors import VerifyInputError
from verify.proof import calculus
from verify.proof.derivation import RELATIONS, Context, Derivation, Step
from verify.proof.expr import (
    CHART_GAPS,
    KINDS,
    MAX_DEPTH,
    Expr,
    ProofSyntaxError,
    Variable,
    _well_formed,
    var,
)
from verify.proof.hypotheses import Assumption, Condition
from verify.proof.justify import (
    ByAlgebra,
    ByBound,
    ByCitation,
    Justification,
    Nonneg,
    assumed,
    by_sos,
    positive,
    square,
    trace_lower_bound,
    trace_psd_product,
)
from verify.proof.size import over_limits
from verify.proof.wire import _SHAPES, LIMITS, SCHEMA


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
        # one derivative cache per context (its dynamics are fixed once declared), so
        # every node is differentiated once however many ddt nodes reach it
        self.ddt_cache: list[dict] = [{} for _ in self.contexts]
        self.differentiated = 0
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
            rate = self._node_ref(entry[1], f"context {k} dynamics")
            too_large = over_limits(rate)
            if too_large:  # the tangency check is exact algebra on this expression
                raise WireError(f"context {k}: budget exceeded: the declared derivative of "
                                f"variable {i}: {too_large}")
            ctx.dynamics(x, rate)

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
            if len(args) != 1:
                raise WireError(f"{what}: ddt takes one expression")
            self._declare(ctx)
            cache = self.ddt_cache[ctx]
            before = len(cache)
            out = calculus.ddt(args[0], self.contexts[ctx]._dynamics, cache)
            self.contexts[ctx]._derived.append((out, args[0]))
            self.differentiated += len(cache) - before
            if self.differentiated > LIMITS["differentiated"]:
                raise WireError(f"budget exceeded: the ddt nodes differentiate more than "
                                f"{LIMITS['differentiated']} distinct nodes")
            if out.shape != shape:
                raise WireError(f"{what}: the derivative has another shape")
            return out if label is None else out.named(label)
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
        sizes: list[int] = []  # characters of reason plus premises and assumptions
        total = 0
        for k, t in enumerate(_list(self.data["terms"], "terms", LIMITS["terms"])):
            what = f"term {k}"
            t = _fields(t, what, ("make", "args"))
            raw = _list(t["args"], what, 6)
            args = [self._argument(a, out, what) for a in raw]
            make = t["make"]
            if make not in _MAKERS or _MAKERS[make][0] != len(args):
                raise WireError(f"{what}: unknown constructor or wrong number of arguments")
            if make in ("add", "mul") and not all(type(a) is Nonneg for a in args):
                raise WireError(f"{what}: {make} combines two non-negative terms")
            # a combination's reason, premises and assumptions are those of its parts
            # together: measured before it is made (t(k+1) = t(k) + t(k) doubles)
            parts = [sizes[a["term"]] for a in raw if type(a) is dict and "term" in a]
            size = _COMBINED + sum(parts) if parts else 0
            total += size
            if size > LIMITS["term_size"] or total > LIMITS["terms_size"]:
                raise WireError(f"{what}: budget exceeded: the non-negative terms' reasons "
                                "and premises grow past "
                                f"{min(LIMITS['term_size'], LIMITS['terms_size'])} units")
            sizes.append(size)
            term = _MAKERS[make][1](args)  # the kernel's own checks apply
            if type(term) is not Nonneg:
                raise WireError(f"{what}: {make} did not make a non-negative term")
            if not parts:  # a kernel term made from expressions: its printed size
                sizes[-1] = len(term.reason) + len(term.premises) + len(term.assumptions)
                total += sizes[-1]
                if total > LIMITS["terms_size"]:
                    raise WireError(f"{what}: budget exceeded: the non-negative terms' "
                                    f"reasons and premises grow past {LIMITS['terms_size']} "
                                    "units")
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


#: Characters a combination adds to its parts' reasons (brackets, an operator and a
#: constant printed with at most 4000 digits in numerator and denominator).
_COMBINED = 8200

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


__all__ = ["WireError", "decode", "loads"]
