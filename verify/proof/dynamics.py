"""Exact admissibility of declared dynamics: the derivative must be tangent to the manifold.

A rotation's derivative is R W with W skew-symmetric (the tangent space of SO(3) at R,
paper Section 3, eqs. (9), (11), (13)), equivalently R^T R-dot + R-dot^T R = 0; a unit
vector's derivative is orthogonal to it (u . u-dot = 0, tangent to the sphere); a
symmetric matrix's derivative is symmetric. Each test is a rational-function identity in
the variables' charts, decided exactly; holding on the chart's dense image, it holds
everywhere by continuity (the entries are polynomials in the variables' values).
Angles and scalars take a scalar rate, vectors and matrices a derivative of their shape.

The re-check is bounded before any expansion (:func:`verify.proof.size.over_term_limit`:
degree, constants, nodes and an estimate of the expanded terms), and, inside
:func:`tangency_budget` (``verify check`` reading a file), runs in a forked process
under the step budget like the rest of the checker's algebra
(:func:`verify.proof.budget.run_bounded`); past either, the declaration is refused.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from contextvars import ContextVar

from verify.proof.budget import Budget, BudgetExceededError, run_bounded
from verify.proof.expr import (
    ANGLE,
    SCALAR,
    Expr,
    ProofSyntaxError,
    Variable,
    dot,
    nodes,
    structural_key,
    validate_tree,
    var,
    variables_of,
)
from verify.proof.size import over_term_limit

_BUDGET: ContextVar[Budget | None] = ContextVar("tangency_budget", default=None)


@contextlib.contextmanager
def tangency_budget(budget: Budget | None) -> Iterator[None]:
    """Inside, every tangency re-check runs under ``budget`` in a forked process."""
    token = _BUDGET.set(budget)
    try:
        yield
    finally:
        _BUDGET.reset(token)


def _identically_zero(e: Expr, name: str) -> bool:
    too_large = over_term_limit(e)
    if too_large:
        raise ProofSyntaxError(f"dynamics of {name}: budget exceeded: the tangency re-check "
                               f"is too large ({too_large})")
    budget = _BUDGET.get()
    if budget is None:
        return _expand_to_zero(e)
    try:
        return bool(run_bounded(lambda: _expand_to_zero(e), budget))
    except (BudgetExceededError, RuntimeError) as exc:
        raise ProofSyntaxError(f"dynamics of {name}: budget exceeded: the tangency re-check "
                               f"did not finish ({exc})") from None


def _expand_to_zero(e: Expr) -> bool:
    from verify.proof.algebras import ExactSpace
    from verify.proof.evaluate import evaluate
    from verify.proof.problem import flatten

    atoms: dict = {}
    for n in nodes(e):
        if n.op == "lambda_min":
            atoms.setdefault(structural_key(n.args[0]), n)
    alg = ExactSpace(variables_of(e), list(atoms.values())).algebra()
    return all(x.is_zero() for x in flatten(evaluate(e, alg, alg.environment())))


def check_dynamics(variable: Variable, derivative: Expr) -> None:
    """Raise ProofSyntaxError unless ``derivative`` is an admissible d/dt of ``variable``."""
    validate_tree(derivative)
    name = variable.name
    want = SCALAR if variable.shape == ANGLE else variable.shape
    if derivative.shape != want:
        raise ProofSyntaxError(
            f"derivative of {name} has the wrong shape"
            + (" (an angle's rate is a scalar)" if variable.shape == ANGLE else "")
        )
    x = var(variable)
    if variable.kind == "rotation" and not _identically_zero(
            x.T * derivative + derivative.T * x, name):
        raise ProofSyntaxError(
            f"dynamics of {name}: a rotation's derivative must be {name}·W with W skew "
            f"({name}ᵀṘ + Ṙᵀ{name} = 0 fails exactly); did you mean {name} * hat(ω)?"
        )
    if variable.kind == "unit_vector" and not _identically_zero(dot(x, derivative), name):
        raise ProofSyntaxError(
            f"dynamics of {name}: a unit vector's derivative must be orthogonal to it "
            f"(<{name}, d{name}/dt> = 0 fails exactly)"
        )
    if variable.kind == "symmetric" and not _identically_zero(derivative - derivative.T,
                                                                          name):
        raise ProofSyntaxError(f"dynamics of {name}: a symmetric matrix's derivative "
                               "must be symmetric")
