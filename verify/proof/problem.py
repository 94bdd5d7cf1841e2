"""One decidable question about a step, in the exact and the numerical setting.

A :class:`StepProblem` gathers what both the exact check and the falsifiers need: the
variables and lambda_min atoms, the claimed slack (lhs - rhs for >=, rhs - lhs for <=,
the entries of lhs - rhs for =), the side conditions and the assumptions that restrict
where the claim is made.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from functools import cached_property

from verify.inputs.numbers import fraction
from verify.proof.algebras import ExactAlgebra, ExactSpace
from verify.proof.evaluate import evaluate
from verify.proof.exact import KnownFraction
from verify.proof.expr import (
    CHART_GAPS,
    Expr,
    Variable,
    chart_gap,
    nodes,
    replace_variables,
    structural_key,
    variables_of,
)
from verify.proof.hypotheses import Assumption, Condition


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
    pins: dict = field(default_factory=dict)  # variable uid -> its chart's missing point
    pinned_names: dict = field(default_factory=dict)  # variable name -> that point, as text

    def pinned(self, variables: list[Variable]) -> StepProblem:
        """The same question with each of ``variables`` at the point its chart misses.

        Together with this problem (every variable in its chart) the pinned problems
        for all subsets of the chart-gap variables cover every value of the variables.
        """
        pins = {v.uid: chart_gap(v) for v in variables}

        def sub(e: Expr) -> Expr:
            return replace_variables(e, pins)

        return StepProblem(
            self.relation,
            sub(self.lhs),
            sub(self.rhs),
            tuple(Condition(c.label, sub(c.lhs), sub(c.rhs)) for c in self.conditions),
            tuple(Assumption(a.label, sub(a.expr), a.kind, a.cite) for a in self.assumptions),
            tuple(sub(e) for e in self.extra),
            {**self.pins, **pins},
            {**self.pinned_names, **{v.name: CHART_GAPS[v.kind] for v in variables}},
        )

    @cached_property
    def gap_variables(self) -> list[Variable]:
        """Variables of the side conditions whose chart misses a point (angles, unit
        vectors). One absent from the conditions ranges freely over its whole space on
        the condition set, so continuity covers its missing point."""
        in_conditions = {v.uid for v in variables_of(*(c.difference for c in self.conditions))}
        return [v for v in self.variables if v.kind in CHART_GAPS and v.uid in in_conditions]

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
        if self.pins:
            e = replace_variables(e, self.pins)
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

    @cached_property
    def conditions_empty(self) -> bool:
        """The side conditions have no common real zero, decided exactly: their ideal
        contains 1, or one of them is definite (every monomial an even power product,
        every coefficient of one sign, a non-zero constant term: then it is bounded
        away from zero on real parameters)."""
        return any(p.is_ground for p in self.condition_basis) or any(
            _definite(p) for p in self.condition_polynomials
        )

    @cached_property
    def false_constant_assumptions(self) -> list[str]:
        """Labels of assumptions with no free parameter that are false (decided exactly)."""
        out = []
        for a in self.assumptions:
            values = self.exact(a.expr)
            if not all(v.num.is_ground and v.denominator().is_ground for v in values):
                continue
            x = [_fraction(v.num.LC if v.num else 0) / _fraction(v.denominator().LC)
                 for v in values]
            if not _constant_holds(a.kind, x):
                out.append(a.label)
        return out

    def vanishes(self, value: KnownFraction) -> bool:
        """Exactly zero, or in the ideal of the side conditions, or the conditions have no
        real solution here (each sufficient, not necessary, for zero on the condition set)."""
        if value.is_zero():
            return True
        if self.conditions and self.conditions_empty:
            return True
        basis = self.condition_basis
        if not basis:
            return False
        return not value.num.rem(basis)


def _definite(poly) -> bool:
    """poly > 0 or poly < 0 at every real point, by the shape of its terms (exact)."""
    terms = poly.terms()
    signs = {c > 0 for _, c in terms}
    return (len(signs) == 1 and all(e % 2 == 0 for m, _ in terms for e in m)
            and any(not any(m) for m, _ in terms))


def _fraction(c) -> Fraction:
    from sympy import QQ

    return fraction(QQ(c))


def _constant_holds(kind: str, x: list[Fraction]) -> bool:
    """Exact truth of an assumption about a constant: scalar, or a 3x3 matrix (row-major)."""
    if kind == "pos":
        return x[0] > 0
    if kind == "nonneg":
        return x[0] >= 0
    m = [[(x[3 * i + j] + x[3 * j + i]) / 2 for j in range(3)] for i in range(3)]
    minors = principal_minors(m)
    if kind == "pd":  # Sylvester's criterion: leading principal minors > 0
        return all(minors[k] > 0 for k in ((0,), (0, 1), (0, 1, 2)))
    return all(v >= 0 for v in minors.values())  # psd: every principal minor >= 0


def principal_minors(m) -> dict:
    """Principal minors of a 3x3 matrix (any scalar type with + - *), by index set."""
    out = {}
    for idx in ((0,), (1,), (2,), (0, 1), (0, 2), (1, 2), (0, 1, 2)):
        if len(idx) == 1:
            out[idx] = m[idx[0]][idx[0]]
        elif len(idx) == 2:
            i, j = idx
            out[idx] = m[i][i] * m[j][j] - m[i][j] * m[j][i]
        else:
            out[idx] = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    return out
