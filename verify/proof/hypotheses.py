"""Hypotheses of a claim: side conditions and sign assumptions.

A :class:`Condition` is an exact scalar equation ``lhs = rhs`` (e.g. "on the boundary
cos theta = 0"); an :class:`Assumption` is a sign assumption of the paper (sym(M) positive
(semi)definite, a scalar positive or non-negative, e.g. Assumption 1 item 2 of Section
3). Contexts make them (:meth:`verify.proof.derivation.Context.condition`,
``Context.assume``); derivations, non-negative terms (:func:`verify.proof.justify.assumed`)
and the exact questions of the checker (:mod:`verify.proof.problem`) use them. They hold
expressions only and import nothing above :mod:`verify.proof.expr`.
"""

from __future__ import annotations

from dataclasses import dataclass

from verify.proof.expr import MATRIX, SCALAR, Expr, ProofSyntaxError
from verify.validation import one_of


@dataclass(frozen=True)
class Condition:
    """An exact side condition ``lhs = rhs`` (scalar) under which steps are claimed."""

    label: str
    lhs: Expr
    rhs: Expr

    def __post_init__(self) -> None:
        if not isinstance(self.label, str):
            raise ProofSyntaxError("a condition's label is a string")
        for side in (self.lhs, self.rhs):
            if not isinstance(side, Expr) or side.shape != SCALAR:
                raise ProofSyntaxError(f"condition '{self.label}' must equate two scalars")

    @property
    def difference(self) -> Expr:
        return self.lhs - self.rhs


#: Sign assumptions: sym(M) positive (semi)definite, a scalar positive (non-negative).
ASSUMPTION_KINDS = ("pd", "psd", "pos", "nonneg")


@dataclass(frozen=True)
class Assumption:
    """A sign assumption of the paper: ``kind`` in pd, psd (of sym(M)), pos, nonneg."""

    label: str
    expr: Expr
    kind: str
    cite: str = ""

    def __post_init__(self) -> None:
        if not isinstance(self.label, str) or not isinstance(self.cite, str):
            raise ProofSyntaxError("an assumption's label and cite are strings")
        if not isinstance(self.expr, Expr):
            raise ProofSyntaxError(f"assumption '{self.label}' needs an expression")
        if self.kind in ("pd", "psd") and self.expr.shape != MATRIX:
            raise ProofSyntaxError(f"assumption '{self.label}': {self.kind} needs a matrix")
        if self.kind in ("pos", "nonneg") and self.expr.shape != SCALAR:
            raise ProofSyntaxError(f"assumption '{self.label}': {self.kind} needs a scalar")
        one_of("kind", self.kind, ASSUMPTION_KINDS, ProofSyntaxError)
