"""Derivations as data: a context of variables and a chain of justified steps.

A :class:`Context` declares the variables of an argument (rotations, unit vectors,
angles, vectors, gains), the dynamics used to differentiate (``ctx.ddt``), equality
side conditions (``ctx.condition``, e.g. "on the boundary cos theta = 0") and the
assumptions of the paper (``ctx.assume``, e.g. "sym(R_rl) is positive definite").

A :class:`Derivation` starts from an expression and adds steps ``equals``, ``le`` and
``ge``, each relating the previous expression to a new one and carrying its
justification (:mod:`verify.proof.justify`). Building a derivation checks shapes only;
:func:`verify.proof.checker.check` decides every step.

Example (the first equality of Lemma 1's h-dot chain, eq. (14))::

    ctx = Context("Lemma 1")
    Rr, Rb, Rl = ctx.rotation("R_r"), ctx.rotation("Rbar"), ctx.rotation("R_l")
    ks = ctx.scalar("k_s", positive=True)
    ctx.constant(Rr)
    ctx.dynamics(Rb, ks * Rb * sk(Rb.T * Rl))          # eq. (13)
    h = tr(Rr.T * Rb) - 1
    d = Derivation("h-dot", ctx.ddt(h), ctx)
    d.equals(ks * tr(Rr.T * Rb * sk(Rb.T * Rl)), by_algebra("eq. (13)"))
"""

from __future__ import annotations

from dataclasses import dataclass, field

from verify.proof.calculus import ddt
from verify.proof.dynamics import check_dynamics
from verify.proof.expr import (
    SCALAR,
    Expr,
    ProofSyntaxError,
    Variable,
    as_expr,
    var,
    variables_of,
    zero,
)
from verify.proof.hypotheses import Assumption, Condition
from verify.proof.justify import Justification
from verify.validation import message

RELATIONS = ("=", "<=", ">=")


class Context:
    """Variables, dynamics, side conditions and assumptions of one argument."""

    def __init__(self, name: str):
        self.name = name
        self._dynamics: dict[int, Expr | None] = {}
        self._declared: set[int] = set()
        self.variables: list[Variable] = []
        # (result, argument) of every ddt call: a derivation file hands over "ddt of this
        # expression", and the checker process differentiates again (verify.proof.wire)
        self._derived: list[tuple[Expr, Expr]] = []

    # -- variables ----------------------------------------------------------------------
    def _new(self, name: str, kind: str, positive: bool = False) -> Expr:
        v = Variable(name, kind, positive)
        self.variables.append(v)
        if kind == "scalar":
            self._dynamics[v.uid] = None  # gains are constant unless declared otherwise
        return var(v)

    def rotation(self, name: str) -> Expr:
        return self._new(name, "rotation")

    def unit_vector(self, name: str) -> Expr:
        return self._new(name, "unit_vector")

    def angle(self, name: str) -> Expr:
        return self._new(name, "angle")

    def vector(self, name: str) -> Expr:
        return self._new(name, "vector")

    def matrix(self, name: str) -> Expr:
        return self._new(name, "matrix")

    def symmetric(self, name: str) -> Expr:
        return self._new(name, "symmetric")

    def scalar(self, name: str, positive: bool = False) -> Expr:
        return self._new(name, "scalar", positive)

    # -- dynamics -----------------------------------------------------------------------
    def dynamics(self, variable: Expr, derivative: Expr) -> None:
        """Declare d/dt of a variable (for ``ddt``), once.

        The derivative is checked exactly to be tangent: R·W with W skew for a rotation,
        orthogonal to u for a unit vector, symmetric for a symmetric matrix; an angle
        takes a scalar rate ω (then d/dt cos θ = -ω sin θ).
        """
        v = self._own(variable)
        check_dynamics(v, as_expr(derivative))
        self._dynamics[v.uid] = as_expr(derivative)
        self._declared.add(v.uid)

    def constant(self, *variables: Expr) -> None:
        """Declare variables constant in time (once each)."""
        for variable in variables:
            v = self._own(variable)
            self._dynamics[v.uid] = None
            self._declared.add(v.uid)

    def _own(self, variable: Expr) -> Variable:
        v = _variable(variable)
        if all(v is not w for w in self.variables):
            raise ProofSyntaxError(f"{v.name} is not a variable of context {self.name!r}")
        if v.uid in self._declared:
            raise ProofSyntaxError(
                f"the dynamics of {v.name} are already declared (or used by ddt); each "
                "variable's dynamics (or constancy) is declared once, before ddt uses it"
            )
        return v

    def ddt(self, e: Expr) -> Expr:
        """Time derivative of ``e`` along the declared dynamics (product rule).

        Every variable of ``e`` counts as declared from then on (a gain used as a
        constant cannot be given dynamics later), so all derivatives of a context
        use the same dynamics.
        """
        out = ddt(e, self._dynamics)
        self._declared.update(v.uid for v in variables_of(e))
        self._derived.append((out, e))
        return out

    # -- side conditions and assumptions ---------------------------------------------------
    def condition(self, label: str, lhs: Expr, rhs: Expr | int = 0) -> Condition:
        lhs, rhs = as_expr(lhs), as_expr(rhs)
        if lhs.shape != SCALAR or rhs.shape != SCALAR:
            raise ProofSyntaxError(f"condition '{label}' must equate two scalars")
        return Condition(label, lhs, rhs)

    def assume(self, label: str, expr: Expr, kind: str, cite: str = "") -> Assumption:
        return Assumption(label, as_expr(expr), kind, cite)


def _justification_error(name: str, index: int, because: object) -> str:
    factory = getattr(because, "__name__", "")
    if callable(because) and factory.startswith("by_"):
        return f"{name}: step {index} needs a justification: " + message(
            f"a justification such as {factory}()", "because", because,
            f"did you mean {factory}()?", detail="the function itself")
    return f"{name}: step {index} needs a justification: " + message(
        "a justification (by_algebra(), by_bound(...), by_sos(...), by_citation(...))",
        "because", because)


def _variable(e: Expr) -> Variable:
    if not isinstance(e, Expr) or e.op != "var":
        raise ProofSyntaxError("expected a variable created by the context")
    return e.data


@dataclass
class Step:
    """``previous relation expr``, on the grounds of ``because``."""

    relation: str
    lhs: Expr
    rhs: Expr
    because: Justification
    where: tuple[Condition, ...] = ()
    note: str = ""


@dataclass
class Derivation:
    """A chain start = e1 <= e2 = e3 ... with one justification per step."""

    name: str
    start: Expr
    context: Context
    where: tuple[Condition, ...] = ()
    assumes: tuple[Assumption, ...] = ()
    statement: str = ""
    cite: str = ""
    steps: list[Step] = field(default_factory=list)

    def __post_init__(self) -> None:
        self.start = as_expr(self.start)
        self.where = tuple(self.where)
        self.assumes = tuple(self.assumes)

    @property
    def current(self) -> Expr:
        return self.steps[-1].rhs if self.steps else self.start

    def _add(self, relation: str, expr, because: Justification, where, note) -> Derivation:
        if isinstance(expr, int) and expr == 0 and self.start.shape != SCALAR:
            expr = zero(self.start.shape)  # ".equals(0)" for a matrix or vector chain
        expr = as_expr(expr)
        if expr.shape != self.start.shape:
            raise ProofSyntaxError(
                f"{self.name}: step {len(self.steps) + 1} changes the shape of the expression"
            )
        if relation != "=" and expr.shape != SCALAR:
            raise ProofSyntaxError(f"{self.name}: inequalities relate scalars")
        if not isinstance(because, Justification):
            raise ProofSyntaxError(_justification_error(self.name, len(self.steps) + 1, because))
        used = {s.relation for s in self.steps if s.relation != "="} | (
            {relation} - {"="}
        )
        if len(used) > 1:
            raise ProofSyntaxError(f"{self.name}: a chain cannot mix <= and >=")
        self.steps.append(Step(relation, self.current, expr, because, tuple(where), note))
        return self

    def equals(self, expr, because: Justification, where=(), note: str = "") -> Derivation:
        return self._add("=", expr, because, where, note)

    def le(self, expr, because: Justification, where=(), note: str = "") -> Derivation:
        return self._add("<=", expr, because, where, note)

    def ge(self, expr, because: Justification, where=(), note: str = "") -> Derivation:
        return self._add(">=", expr, because, where, note)

    @property
    def conclusion_relation(self) -> str:
        rels = {s.relation for s in self.steps} - {"="}
        return rels.pop() if rels else "="
