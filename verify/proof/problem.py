"""One decidable question about a step, in the exact and the numerical setting.

A :class:`StepProblem` gathers what both the exact check and the falsifiers need: the
variables and lambda_min atoms, the claimed slack (lhs - rhs for >=, rhs - lhs for <=,
the entries of lhs - rhs for =), the side conditions and the assumptions that restrict
where the claim is made.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

from verify.proof.algebras import ExactAlgebra, ExactSpace
from verify.proof.derivation import Assumption, Condition
from verify.proof.evaluate import evaluate
from verify.proof.exact import KnownFraction
from verify.proof.expr import Expr, Variable, nodes, structural_key, variables_of


def flatten(value) -> list:
    """Entries of a scalar, vector or matrix value as one list (scalars: one element)."""
    if isinstance(value, list):
        return [x for item in value for x in flatten(item)]
    return [value]


def lambda_min_nodes(*exprs: Expr) -> list[Expr]:
    """Structurally distinct lambda_min nodes in expressions."""
    found: dict[tuple, Expr] = {}
    for e in nodes(*exprs):
        if e.op == "lambda_min":
            found.setdefault(structural_key(e.args[0]), e)
    return list(found.values())


@dataclass
class StepProblem:
    relation: str
    lhs: Expr
    rhs: Expr
    conditions: tuple[Condition, ...] = ()
    assumptions: tuple[Assumption, ...] = ()
    extra: tuple[Expr, ...] = field(default_factory=tuple)  # premises, certificate terms

    @cached_property
    def slack_expr(self) -> Expr:
        if self.relation == "<=":
            return self.rhs - self.lhs
        return self.lhs - self.rhs

    @cached_property
    def all_exprs(self) -> tuple[Expr, ...]:
        conds = tuple(c.difference for c in self.conditions)
        assum = tuple(a.expr for a in self.assumptions)
        return (self.lhs, self.rhs, *conds, *assum, *self.extra)

    @cached_property
    def variables(self) -> list[Variable]:
        return variables_of(*self.all_exprs)

    @cached_property
    def space(self) -> ExactSpace:
        return ExactSpace(self.variables, lambda_min_nodes(*self.all_exprs))

    @cached_property
    def _algebra(self) -> tuple[ExactAlgebra, dict]:
        alg = self.space.algebra()
        return alg, alg.environment()

    def exact(self, e: Expr) -> list[KnownFraction]:
        """Exact entries of any expression (scalars give a one-element list)."""
        alg, env = self._algebra
        return flatten(evaluate(e, alg, env))

    @cached_property
    def exact_slack(self) -> list[KnownFraction]:
        return self.exact(self.slack_expr)

    @cached_property
    def condition_polynomials(self) -> list:
        """Numerators of the side conditions (the denominators never vanish)."""
        polys = []
        for c in self.conditions:
            (value,) = self.exact(c.difference)
            if value.num:
                polys.append(value.num)
        return polys

    @cached_property
    def condition_basis(self) -> list:
        """A Groebner basis of the side conditions' ideal (empty without conditions)."""
        polys = self.condition_polynomials
        if len(polys) <= 1:
            return polys
        from sympy.polys.groebnertools import groebner

        return groebner(polys, self.space.ring)

    def vanishes(self, value: KnownFraction) -> bool:
        """Exactly zero, or in the ideal of the side conditions (sufficient, not necessary)."""
        if value.is_zero():
            return True
        basis = self.condition_basis
        if not basis:
            return False
        return not value.num.rem(basis)
