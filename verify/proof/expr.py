"""Expressions of the proof language: matrices, vectors and scalars over SO(3).

An expression is an immutable tree (:class:`Expr`) built with Python operators and the
functions of this module (``tr``, ``sk``, ``sym``, ``hat``, ``vee``, ...). The tree is
not evaluated when it is built; the checker evaluates the same tree in three algebras
(:mod:`verify.proof.evaluate`): exact rational functions of the parameters, batched
floating point (numpy) and CasADi symbols for optimisation-based falsification.

Shapes are checked when a tree is built, so a derivation with a shape error fails where
it is written, not later in the checker. Exact constants only: ints and
:class:`fractions.Fraction` are accepted, floats are refused (a proof step written with
0.5 would silently become inexact).
"""

from __future__ import annotations

import enum
import itertools
import weakref
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

from verify.proof.printing import to_text

SCALAR: tuple[int, ...] = ()
VECTOR: tuple[int, ...] = (3,)
MATRIX: tuple[int, ...] = (3, 3)
ANGLE: tuple[str, ...] = ("angle",)

_ids = itertools.count()



class VariableKind(enum.StrEnum):
    """The kinds of free variable, each with its own exact chart (see :class:`Variable`).

    A StrEnum: each member equals, prints and serialises as its plain string.
    """

    ROTATION = "rotation"
    UNIT_VECTOR = "unit_vector"
    ANGLE = "angle"
    VECTOR = "vector"
    MATRIX = "matrix"
    SYMMETRIC = "symmetric"
    SCALAR = "scalar"


KINDS = tuple(VariableKind)

#: The one point each chart misses (kinds whose chart reaches every value are absent).
CHART_GAPS = {"angle": "π", "unit_vector": "(0, 0, 1)"}


class ProofSyntaxError(TypeError):
    """An expression or derivation is malformed (wrong shapes, floats, unknown names)."""


@dataclass(frozen=True, eq=False)
class Variable:
    """A free variable of a derivation; ``kind`` fixes its parametrisation.

    Kinds and their exact parametrisations (``verify/proof/TRUSTED.md`` says which
    points each chart misses and how the checker covers them):

    - ``rotation``: quaternion (w, x, y, z) != 0, R = I + 2(w q^ + q^ q^)/|q|^2
      (every rotation is reached);
    - ``unit_vector``: stereographic (a, b), u = (2a, 2b, a^2 + b^2 - 1)/(a^2 + b^2 + 1)
      (misses u = (0, 0, 1));
    - ``angle``: t = tan(theta/2), cos = (1 - t^2)/(1 + t^2), sin = 2t/(1 + t^2)
      (misses theta = pi);
    - ``vector``, ``matrix``, ``symmetric``: free real entries;
    - ``scalar``: a real number, ``positive=True`` for a gain such as k_s > 0.
    """

    name: str
    kind: VariableKind
    positive: bool = False
    uid: int = field(default_factory=lambda: next(_ids), init=False)

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ProofSyntaxError(
                f"unknown variable kind {self.kind!r}; expected one of {', '.join(KINDS)}"
            )
        object.__setattr__(self, "kind", VariableKind(self.kind))
        if not isinstance(self.name, str):
            raise ProofSyntaxError("a variable's name is a string")
        if self.positive is not False and (self.kind != "scalar" or self.positive is not True):
            raise ProofSyntaxError("only a scalar can be declared positive (positive=True)")

    @property
    def parameter_count(self) -> int:
        return {
            "rotation": 4,
            "unit_vector": 2,
            "angle": 1,
            "vector": 3,
            "matrix": 9,
            "symmetric": 6,
            "scalar": 1,
        }[self.kind]

    @property
    def shape(self) -> tuple:
        return {
            "rotation": MATRIX,
            "unit_vector": VECTOR,
            "angle": ANGLE,
            "vector": VECTOR,
            "matrix": MATRIX,
            "symmetric": MATRIX,
            "scalar": SCALAR,
        }[self.kind]


def _shape_name(shape: tuple) -> str:
    return {SCALAR: "scalar", VECTOR: "3-vector", MATRIX: "3x3 matrix", ANGLE: "angle"}[shape]


class Expr:
    """A node of an expression tree. Build with operators and the module functions."""

    __slots__ = ("__weakref__", "args", "data", "label", "op", "shape")
    __array_priority__ = 1000  # keep numpy from broadcasting over an Expr

    def __init__(self, op: str, args: tuple[Expr, ...], shape: tuple, data: Any = None,
                 label: str | None = None):
        set_ = object.__setattr__
        set_(self, "op", op)
        set_(self, "args", tuple(args))
        set_(self, "shape", shape)
        set_(self, "data", data)
        set_(self, "label", label)

    def __setattr__(self, name: str, value: Any) -> None:
        raise ProofSyntaxError(
            "expressions are immutable; build a new one (use .named() for a new label)"
        )

    __delattr__ = __setattr__

    # -- naming -----------------------------------------------------------------------
    def named(self, label: str) -> Expr:
        """A copy printed as ``label`` (evaluation is unchanged)."""
        if not isinstance(label, str):
            raise ProofSyntaxError("a label is a string")
        return Expr(self.op, self.args, self.shape, self.data, label)

    # -- arithmetic -------------------------------------------------------------------
    def __add__(self, other: Any) -> Expr:
        other = as_expr(other)
        _same_shape("+", self, other)
        return Expr("add", (self, other), self.shape)

    def __radd__(self, other: Any) -> Expr:
        return as_expr(other) + self

    def __neg__(self) -> Expr:
        _not_angle("-", self)
        return Expr("neg", (self,), self.shape)

    def __sub__(self, other: Any) -> Expr:
        return self + (-as_expr(other))

    def __rsub__(self, other: Any) -> Expr:
        return as_expr(other) - self

    def __mul__(self, other: Any) -> Expr:
        return _product(self, as_expr(other))

    def __rmul__(self, other: Any) -> Expr:
        return _product(as_expr(other), self)

    def __matmul__(self, other: Any) -> Expr:
        return _product(self, as_expr(other))

    def __truediv__(self, other: Any) -> Expr:
        if isinstance(other, Expr):
            raise ProofSyntaxError("division is only by an exact constant (int or Fraction)")
        return _product(as_expr(Fraction(1) / _exact(other)), self)

    def __pow__(self, power: int) -> Expr:
        if not isinstance(power, int) or isinstance(power, bool) or power < 1:
            raise ProofSyntaxError("only positive integer powers are supported")
        if power > MAX_POWER:
            raise ProofSyntaxError(f"powers are at most {MAX_POWER} (the checker's degree "
                                   "limit is 48)")
        if self.shape not in (SCALAR, MATRIX):
            raise ProofSyntaxError(f"cannot raise a {_shape_name(self.shape)} to a power")
        result = self
        for _ in range(power - 1):
            result = _product(result, self)
        return result

    @property
    def T(self) -> Expr:
        if self.shape == MATRIX:
            return Expr("transpose", (self,), MATRIX)
        if self.shape == SCALAR:
            return self
        raise ProofSyntaxError(f"cannot transpose a {_shape_name(self.shape)}")

    def __bool__(self) -> bool:
        raise ProofSyntaxError("an expression has no truth value; state relations as steps")

    def __repr__(self) -> str:
        return f"Expr({to_text(self)})"

    def __str__(self) -> str:
        return to_text(self)


def _exact(value: Any) -> Fraction:
    if isinstance(value, bool) or not isinstance(value, int | Fraction):
        raise ProofSyntaxError(
            f"constants in a derivation must be int or Fraction, not {type(value).__name__}"
            " (a float would make the check inexact)"
        )
    return Fraction(value)


def as_expr(value: Any) -> Expr:
    """An Expr as is, or an exact scalar constant."""
    if isinstance(value, Expr):
        return value
    return Expr("const", (), SCALAR, _exact(value))


def _not_angle(op: str, *exprs: Expr) -> None:
    for e in exprs:
        if e.shape == ANGLE:
            raise ProofSyntaxError(f"an angle can only be used inside cos() or sin(), not in {op}")


def _same_shape(op: str, a: Expr, b: Expr) -> None:
    _not_angle(op, a, b)
    if a.shape != b.shape:
        raise ProofSyntaxError(
            f"'{op}' needs equal shapes, got {_shape_name(a.shape)} and {_shape_name(b.shape)}"
        )


def _product(a: Expr, b: Expr) -> Expr:
    _not_angle("*", a, b)
    if a.shape == SCALAR or b.shape == SCALAR:
        scalar, other = (a, b) if a.shape == SCALAR else (b, a)
        return Expr("scale", (scalar, other), other.shape)
    if a.shape == MATRIX and b.shape == MATRIX:
        return Expr("matmul", (a, b), MATRIX)
    if a.shape == MATRIX and b.shape == VECTOR:
        return Expr("matmul", (a, b), VECTOR)
    raise ProofSyntaxError(
        f"no product of a {_shape_name(a.shape)} and a {_shape_name(b.shape)}"
        " (use dot(u, v) or outer(u, v) for vectors)"
    )


# -- constructors ---------------------------------------------------------------------
def var(variable: Variable) -> Expr:
    return Expr("var", (), variable.shape, variable, variable.name)


def chart_gap(variable: Variable) -> Expr:
    """The value a variable's chart misses, as a constant of the variable's shape.

    theta = pi for an angle (t = tan(theta/2) is infinite there) and (0, 0, 1) for a
    unit vector (the pole of the stereographic projection). The checker substitutes it
    for the variable to decide a conditioned step at the missing point exactly.
    """
    if variable.kind not in CHART_GAPS:
        raise ProofSyntaxError(f"the chart of a {variable.kind} misses no point")
    label = "π" if variable.kind == "angle" else "(0, 0, 1)"
    return Expr("chart_gap", (), variable.shape, variable.kind, label)


def identity() -> Expr:
    """The 3x3 identity I_3."""
    return Expr("identity", (), MATRIX, None, "I")


I3 = identity()


def zero(shape: tuple = MATRIX) -> Expr:
    return Expr("zero", (), shape)


def tr(m: Expr) -> Expr:
    """Trace of a 3x3 matrix."""
    _require(m, MATRIX, "tr")
    return Expr("trace", (m,), SCALAR)


def sk(m: Expr) -> Expr:
    """Skew-symmetric part (M - M^T)/2 (paper, Section 3)."""
    _require(m, MATRIX, "sk")
    return Expr("sk", (m,), MATRIX)


def sym(m: Expr) -> Expr:
    """Symmetric part (M + M^T)/2 (paper, Lemma 1)."""
    _require(m, MATRIX, "sym")
    return Expr("sym", (m,), MATRIX)


def hat(v: Expr) -> Expr:
    """hat(v) w = v x w."""
    _require(v, VECTOR, "hat")
    return Expr("hat", (v,), MATRIX)


def vee(m: Expr) -> Expr:
    """vee of the skew part of M, so vee(hat(v)) = v and vee(M) = vee(sk(M))."""
    _require(m, MATRIX, "vee")
    return Expr("vee", (m,), VECTOR)


def dot(u: Expr, v: Expr) -> Expr:
    _require(u, VECTOR, "dot")
    _require(v, VECTOR, "dot")
    return Expr("dot", (u, v), SCALAR)


def outer(u: Expr, v: Expr) -> Expr:
    """u v^T."""
    _require(u, VECTOR, "outer")
    _require(v, VECTOR, "outer")
    return Expr("outer", (u, v), MATRIX)


def cos(theta: Expr) -> Expr:
    _require(theta, ANGLE, "cos")
    return Expr("cos", (theta,), SCALAR)


def sin(theta: Expr) -> Expr:
    _require(theta, ANGLE, "sin")
    return Expr("sin", (theta,), SCALAR)


def lambda_min(m: Expr) -> Expr:
    """Smallest eigenvalue of a symmetric matrix.

    Exactly, lambda_min is an algebraic function, not a rational one; the checker treats
    each distinct lambda_min(M) as an opaque real number, so an identity is verified
    only if it holds whatever that number is. Inequalities about it enter through the
    kernel fact "spectral" of :mod:`verify.proof.justify` (A - lambda_min(A) I is PSD).
    """
    _require(m, MATRIX, "lambda_min")
    return Expr("lambda_min", (m,), SCALAR)


def fro2(m: Expr) -> Expr:
    """Squared Frobenius norm tr(M^T M)."""
    _require(m, MATRIX, "fro2")
    return tr(m.T * m)


def phi(r: Expr) -> Expr:
    """The energy function phi(R) = tr(I - R)/2 of Theorem 1's proof."""
    return (Fraction(1, 2) * tr(I3 - r)).named(f"φ({r})")


def rodrigues(axis: Expr, angle: Expr) -> Expr:
    """exp(theta hat(xi)) = I + sin(theta) hat(xi) + (1 - cos(theta)) hat(xi)^2 (Lemma 1)."""
    k = hat(axis)
    return I3 + sin(angle) * k + (1 - cos(angle)) * (k * k)


def _require(e: Expr, shape: tuple, op: str) -> None:
    if not isinstance(e, Expr):
        raise ProofSyntaxError(f"{op}() needs an expression, got {type(e).__name__}")
    if e.shape != shape:
        raise ProofSyntaxError(
            f"{op}() needs a {_shape_name(shape)}, got a {_shape_name(e.shape)}"
        )


def nodes(*exprs: Expr):
    """Every node of the trees once (shared subtrees once), depth first, left to right."""
    stack = list(reversed(exprs))
    visited: set[int] = set()
    while stack:
        e = stack.pop()
        if id(e) in visited:
            continue
        visited.add(id(e))
        yield e
        stack.extend(reversed(e.args))


def postorder(*exprs: Expr) -> list[Expr]:
    """Every node of the trees once, each after all of its children (no recursion)."""
    out: list[Expr] = []
    done: set[int] = set()
    stack: list[tuple[Expr, bool]] = [(e, False) for e in reversed(exprs)]
    while stack:
        e, expanded = stack.pop()
        if id(e) in done:
            continue
        if expanded:
            done.add(id(e))
            out.append(e)
            continue
        stack.append((e, True))
        stack.extend((a, False) for a in reversed(e.args)
                     if type(a) is Expr and id(a) not in done)
    return out


def variables_of(*exprs: Expr) -> list[Variable]:
    """The free variables of expressions, in first-appearance order."""
    seen: dict[int, Variable] = {}
    for e in nodes(*exprs):
        if e.op == "var":
            seen.setdefault(e.data.uid, e.data)
    return list(seen.values())


# Structural keys are interned: each distinct structure gets one small integer, computed
# once per node (a shared subtree is not walked again, so a tree that doubles at every
# level costs its number of nodes, not its printed size).
_INTERN: dict[tuple, int] = {}
_KEYS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def structural_key(e: Expr) -> tuple:
    """A hashable key equal for structurally equal trees (labels ignored)."""
    if e in _KEYS:
        return ("tree", _KEYS[e])
    for node in postorder(e):
        if node in _KEYS:
            continue
        if node.op == "var":
            raw: tuple = ("var", node.data.uid)
        elif node.op == "const":
            raw = ("const", node.data)
        else:
            raw = (node.op, node.shape, node.data if node.op == "chart_gap" else None,
                   *(_KEYS[a] for a in node.args))
        _KEYS[node] = _INTERN.setdefault(raw, len(_INTERN))
    return ("tree", _KEYS[e])


def substitute(e: Expr, mapping: dict) -> Expr:
    """Replace variables: ``mapping`` sends a variable expression to an expression of its shape."""
    table: dict[int, Expr] = {}
    for k, v in mapping.items():
        if not isinstance(k, Expr) or k.op != "var":
            raise ProofSyntaxError("substitute() maps variables to expressions")
        v = as_expr(v)
        if v.shape != k.shape:
            raise ProofSyntaxError(f"substitute(): {k.data.name} and its value differ in shape")
        table[k.data.uid] = v
    return replace_variables(e, table)


def replace_variables(e: Expr, table: dict[int, Expr]) -> Expr:
    """``e`` with each variable whose uid is in ``table`` replaced (shapes already match)."""
    cache: dict[int, Expr] = {}

    def walk(node: Expr) -> Expr:
        if id(node) in cache:
            return cache[id(node)]
        if node.op == "var":
            out = table.get(node.data.uid, node)
        elif not node.args:
            out = node
        else:
            args = tuple(walk(a) for a in node.args)
            if all(a is b for a, b in zip(args, node.args, strict=True)):
                out = node
            else:
                out = Expr(node.op, args, node.shape, node.data)
        cache[id(node)] = out
        return out

    return walk(e)


_UNARY = {  # op -> (argument shape, result shape)
    "neg": (None, None),
    "transpose": (MATRIX, MATRIX),
    "trace": (MATRIX, SCALAR),
    "sk": (MATRIX, MATRIX),
    "sym": (MATRIX, MATRIX),
    "hat": (VECTOR, MATRIX),
    "vee": (MATRIX, VECTOR),
    "cos": (ANGLE, SCALAR),
    "sin": (ANGLE, SCALAR),
    "lambda_min": (MATRIX, SCALAR),
}


def validate_tree(*exprs: Any) -> None:
    """Refuse a tree not built by this module's constructors (shapes re-derived per node).

    The checker calls this on everything it evaluates, so a hand-assembled ``Expr`` with
    a shape that does not match its operation is a ProofSyntaxError, not a silent
    mis-evaluation.
    """
    for e in exprs:
        if type(e) is not Expr:
            raise ProofSyntaxError(f"expected an expression, got {type(e).__name__}")
    depth: dict[int, int] = {}
    for e in postorder(*exprs):
        if not all(type(a) is Expr for a in e.args) or not _well_formed(e):
            raise ProofSyntaxError(f"malformed expression node {e.op!r} (build expressions "
                                   "with operators and the functions of verify.proof)")
        depth[id(e)] = 1 + max((depth.get(id(a), 0) for a in e.args), default=0)
        if depth[id(e)] > MAX_DEPTH:
            raise ProofSyntaxError(f"an expression is nested more than {MAX_DEPTH} levels "
                                   "deep; split it into named parts or balance long sums")


MAX_DEPTH = 1000
MAX_POWER = 64  # e ** k: a larger power would exceed every step's degree limit


def _well_formed(e: Expr) -> bool:
    op, args, shape = e.op, e.args, e.shape
    shapes = [a.shape for a in args]
    if op == "var":
        return not args and type(e.data) is Variable and shape == e.data.shape
    if op == "const":
        return not args and shape == SCALAR and type(e.data) is Fraction
    if op in ("identity", "zero"):
        return not args and shape in (SCALAR, VECTOR, MATRIX) and (op == "zero"
                                                                   or shape == MATRIX)
    if op == "chart_gap":
        return not args and e.data in CHART_GAPS and shape == (
            ANGLE if e.data == "angle" else VECTOR)
    if op in _UNARY:
        if len(args) != 1:
            return False
        a, r = _UNARY[op]
        if op == "neg":
            return shapes[0] == shape and shape != ANGLE
        return shapes[0] == a and shape == r
    if len(args) != 2 or ANGLE in shapes:
        return False
    if op == "add":
        return shapes[0] == shapes[1] == shape
    if op == "scale":
        return shapes[0] == SCALAR and shapes[1] == shape
    if op == "matmul":
        return shapes[0] == MATRIX and shapes[1] in (MATRIX, VECTOR) and shape == shapes[1]
    if op == "dot":
        return shapes == [VECTOR, VECTOR] and shape == SCALAR
    if op == "outer":
        return shapes == [VECTOR, VECTOR] and shape == MATRIX
    return False
