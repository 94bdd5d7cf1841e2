"""Exact admissibility of declared dynamics: the derivative must be tangent to the manifold.

A rotation's derivative is R W with W skew-symmetric (the tangent space of SO(3) at R,
paper Section 3, eqs. (9), (11), (13)), equivalently R^T R-dot + R-dot^T R = 0; a unit
vector's derivative is orthogonal to it (u . u-dot = 0, tangent to the sphere); a
symmetric matrix's derivative is symmetric. Each test is a rational-function identity in
the variables' charts, decided exactly; holding on the chart's dense image, it holds
everywhere by continuity (the entries are polynomials in the variables' values).
Angles and scalars take a scalar rate, vectors and matrices a derivative of their shape.
"""

from __future__ import annotations

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


def _identically_zero(e: Expr) -> bool:
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
    if variable.kind == "rotation" and not _identically_zero(x.T * derivative
                                                              + derivative.T * x):
        raise ProofSyntaxError(
            f"dynamics of {name}: a rotation's derivative must be {name}·W with W skew "
            f"({name}ᵀṘ + Ṙᵀ{name} = 0 fails exactly); did you mean {name} * hat(ω)?"
        )
    if variable.kind == "unit_vector" and not _identically_zero(dot(x, derivative)):
        raise ProofSyntaxError(
            f"dynamics of {name}: a unit vector's derivative must be orthogonal to it "
            f"(<{name}, d{name}/dt> = 0 fails exactly)"
        )
    if variable.kind == "symmetric" and not _identically_zero(derivative - derivative.T):
        raise ProofSyntaxError(f"dynamics of {name}: a symmetric matrix's derivative "
                               "must be symmetric")
