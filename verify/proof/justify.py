"""Justifications of steps, and the small trusted kernel behind inequalities.

An equality step is justified ``by_algebra``: the checker decides lhs - rhs = 0 exactly.

An inequality step ``lhs >= rhs`` is justified ``by_bound(t1, t2, ...)``: the checker
decides exactly that lhs - rhs - (t1 + t2 + ...) = 0, where every t_k is a
:class:`Nonneg` term, a quantity known to be >= 0 for a stated reason. Terms are built
from a short list of facts (the trusted kernel, listed in :data:`KERNEL`) whose side
premises (a matrix is symmetric, a matrix is c G^T G for a given G) are themselves
checked exactly, and from assumptions of the paper, which are reported as such. A
term's reason never rests on a solver or on floating point.

``by_sos(...)`` justifies an inequality step by an exact sum-of-squares certificate
that the checker finds and checks itself (:mod:`verify.proof.sos_step`).

``by_citation(source)`` records a step the paper takes from elsewhere without a
premise the checker can decide; such a step is never verified, only falsified or left
inconclusive.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass, field
from fractions import Fraction

from verify.proof.expr import (
    MATRIX,
    SCALAR,
    VECTOR,
    Expr,
    ProofSyntaxError,
    as_expr,
    dot,
    fro2,
    lambda_min,
    sym,
    tr,
)
from verify.proof.hypotheses import Assumption
from verify.proof.printing import integer_text
from verify.validation import message

KERNEL = {
    "squares": "a sum of squares (tr(G^T G), |v|^2, s^2) is >= 0",
    "positive": "a variable declared positive is > 0; a non-negative constant is >= 0",
    "products": "sums and products of non-negative numbers are >= 0",
    "spectral": "for symmetric A, A - lambda_min(A) I is positive semidefinite",
    "congruence": "for P positive semidefinite, tr(G P G^T) >= 0",
}


@dataclass(frozen=True)
class ExactPremise:
    """A premise decided exactly: ``expr`` is identically zero (any shape)."""

    label: str
    expr: Expr


# Terms issued by the kernel's constructors, each with a fingerprint of its fields taken
# when it was issued: the checker accepts a term only if it is here, unchanged.
_ISSUED: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_issuing = [0]
# How each issued term was made (constructor name and arguments): the serialisation of a
# derivation file (:mod:`verify.proof.wire`) hands over this recipe, and the checker
# process issues the term again with its own constructors.
_RECIPES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def recipe(term: Nonneg) -> tuple | None:
    """(constructor, arguments...) of an issued, unaltered term; None otherwise."""
    return _RECIPES.get(term) if issued(term) else None


def _made(term: Nonneg, *how: object) -> Nonneg:
    _RECIPES[term] = how
    return term


def _fingerprint(t: Nonneg) -> tuple:
    return (id(t.value), t.reason, tuple((id(p), p.label, id(p.expr)) for p in t.premises),
            tuple(id(a) for a in t.assumptions), t.kernel)


def _issue(*args, **kwargs) -> Nonneg:
    _issuing[0] += 1
    try:
        return Nonneg(*args, **kwargs)
    finally:
        _issuing[0] -= 1


def issued(term: object) -> bool:
    """``term`` came from a kernel constructor and has not been altered since."""
    return type(term) is Nonneg and _ISSUED.get(term) == _fingerprint(term)


def _require_issued(*terms: object) -> None:
    for t in terms:
        if not issued(t):
            raise ProofSyntaxError("a non-negative term must come from the kernel's "
                                   "constructors, unaltered")


@dataclass(frozen=True, eq=False)
class Nonneg:
    """A scalar quantity ``value`` that is >= 0, with the grounds for it.

    Only the kernel's constructors make these (:func:`square`, :func:`positive`,
    :func:`assumed`, :func:`trace_lower_bound`, :func:`trace_psd_product`, and sums,
    products and non-negative multiples of such terms); ``Nonneg(...)`` written in a
    user's file is refused, and a term altered after it was made is not accepted.
    """

    value: Expr
    reason: str
    premises: tuple[ExactPremise, ...] = ()
    assumptions: tuple[Assumption, ...] = ()
    kernel: frozenset[str] = field(default_factory=frozenset)

    def __post_init__(self) -> None:
        if not _issuing[0]:
            raise ProofSyntaxError(
                "Nonneg terms come only from the kernel (square, positive, assumed, "
                "trace_lower_bound, trace_psd_product and their sums and products); "
                "they cannot be constructed directly"
            )
        if not isinstance(self.value, Expr) or self.value.shape != SCALAR:
            raise ProofSyntaxError("a non-negative term is a scalar expression")
        _ISSUED[self] = _fingerprint(self)

    def _merge(self, other: Nonneg, value: Expr, reason: str) -> Nonneg:
        _require_issued(self, other)
        return _issue(
            value,
            reason,
            self.premises + other.premises,
            self.assumptions + tuple(a for a in other.assumptions if a not in self.assumptions),
            self.kernel | other.kernel | {"products"},
        )

    def __add__(self, other: Nonneg) -> Nonneg:
        if not isinstance(other, Nonneg):
            raise ProofSyntaxError("only non-negative terms can be added to a non-negative term")
        return _made(self._merge(other, self.value + other.value,
                                 f"({self.reason}) + ({other.reason})"), "add", self, other)

    def __mul__(self, other) -> Nonneg:
        if isinstance(other, Nonneg):
            return _made(self._merge(
                other, self.value * other.value, f"({self.reason}) * ({other.reason})"
            ), "mul", self, other)
        c = Fraction(other) if isinstance(other, int | Fraction) else None
        if c is None or isinstance(other, bool) or c < 0:
            raise ProofSyntaxError("a non-negative term can be scaled by a constant >= 0 only")
        _require_issued(self)
        return _made(_issue(
            as_expr(c) * self.value,
            f"{_number(c)} * ({self.reason})",
            self.premises,
            self.assumptions,
            self.kernel | {"products"},
        ), "scale", c, self)

    __rmul__ = __mul__


def _number(c: Fraction) -> str:
    if c.denominator == 1:
        return integer_text(c.numerator)
    return f"{integer_text(c.numerator)}/{integer_text(c.denominator)}"


def square(g: Expr) -> Nonneg:
    """tr(G^T G), |v|^2 or s^2 (kernel: squares)."""
    if not isinstance(g, Expr):
        raise ProofSyntaxError(message(
            "an expression of the context (matrix, vector or scalar)", "g", g,
            "did you mean the square of a variable from ctx.scalar(), ctx.vector() or "
            "ctx.matrix()? A constant c >= 0 scales a term instead: c * square(x)"))
    if g.shape == MATRIX:
        value = fro2(g)
    elif g.shape == VECTOR:
        value = dot(g, g)
    elif g.shape == SCALAR:
        value = g * g
    else:
        raise ProofSyntaxError("square() needs a matrix, vector or scalar")
    return _made(_issue(value, f"square of {g}", kernel=frozenset({"squares"})), "square", g)


def positive(k: Expr) -> Nonneg:
    """A scalar variable declared positive, e.g. the gain k_s (kernel: positive)."""
    if not isinstance(k, Expr) or k.op != "var" or k.data.kind != "scalar" or not k.data.positive:
        raise ProofSyntaxError(message(
            "a scalar variable declared positive", "k", k,
            "declare it with ctx.scalar(name, positive=True); a constant c >= 0 scales a "
            "term instead (c * term)",
            detail=f"{k} is not a variable declared positive" if isinstance(k, Expr) else ""))
    return _made(_issue(k, f"{k} > 0 (declared)", kernel=frozenset({"positive"})),
                 "positive", k)


def assumed(assumption: Assumption) -> Nonneg:
    """A scalar assumption (kind pos or nonneg) used as a non-negative term."""
    _require_assumption(assumption)
    if assumption.kind not in ("pos", "nonneg"):
        raise ProofSyntaxError("assumed() takes a scalar assumption (pos or nonneg)")
    return _made(_issue(assumption.expr, f"assumed: {assumption.label}",
                        assumptions=(assumption,)), "assumed", assumption)


def _require_assumption(a: object) -> None:
    if type(a) is not Assumption:
        raise ProofSyntaxError(message(
            "an assumption made by ctx.assume()", "assumption", a,
            "did you mean assumed(ctx.assume(label, expr, 'nonneg'))?",
            detail=f"of type {type(a).__name__}"))


def _psd_by_gram(label: str, b: Expr, gram: Expr, scale: Nonneg | int | Fraction):
    """Premise sym(B) = c G^T G, returning (premise, scale term)."""
    if isinstance(scale, Nonneg):
        _require_issued(scale)
        c_term = scale
    else:
        c_term = _issue(as_expr(Fraction(scale)), f"{_number(Fraction(scale))} >= 0",
                        kernel=frozenset({"positive"}))
        if Fraction(scale) < 0:
            raise ProofSyntaxError("a Gram scale must be >= 0")
    premise = ExactPremise(f"{label}: sym({b}) = c G^T G", sym(b) - c_term.value * (gram.T * gram))
    return premise, c_term


def trace_lower_bound(
    a: Expr, b: Expr, *, gram: Expr | None, gram_scale: Nonneg | int | Fraction = 1
) -> Nonneg:
    """tr(A B) - lambda_min(A) tr(B) >= 0 for A symmetric and sym(B) positive semidefinite.

    The trace inequality quoted in Lemma 1 (from Hatanaka et al. 2015) with the premise
    it needs: sym(B) = c G^T G for a given G and c >= 0. Then
    tr(AB) - lambda tr B = tr((A - lambda I) sym B) = c tr(G (A - lambda I) G^T) >= 0
    (kernel: spectral, congruence). Without ``gram`` the premise cannot be decided.
    """
    value = tr(a * b) - lambda_min(a) * tr(b)
    premises = [ExactPremise(f"{a} is symmetric", a - a.T)]
    if gram is None:
        raise ProofSyntaxError(
            "trace_lower_bound needs gram=G with sym(B) = c G^T G; as quoted, without a "
            "premise on B, the inequality is false (see lemma1.trace-inequality-as-quoted)"
        )
    premise, c_term = _psd_by_gram("B", b, gram, gram_scale)
    premises.append(premise)
    return _made(_issue(
        value,
        f"trace inequality tr(AB) >= lambda_min(A) tr(B), A = {a}, B = {b}",
        tuple(premises) + c_term.premises,
        c_term.assumptions,
        frozenset({"spectral", "congruence"}) | c_term.kernel,
    ), "trace_lower_bound", a, b, gram, gram_scale)


def trace_psd_product(
    a: Expr,
    b: Expr,
    *,
    a_psd: Assumption | None = None,
    a_gram: Expr | None = None,
    b_gram: Expr,
    b_scale: Nonneg | int | Fraction = 1,
) -> Nonneg:
    """tr(A B) >= 0 for A symmetric PSD (assumed, or A = G^T G) and sym(B) = c H^T H."""
    premises = [ExactPremise(f"{a} is symmetric", a - a.T)]
    assumptions: tuple = ()
    if a_psd is not None:
        _require_assumption(a_psd)
        if a_psd.kind not in ("pd", "psd"):
            raise ProofSyntaxError("a_psd must be a pd or psd assumption")
        premises.append(ExactPremise(f"{a} = sym of the assumed matrix", a - sym(a_psd.expr)))
        assumptions = (a_psd,)
    elif a_gram is not None:
        premises.append(ExactPremise(f"{a} = G^T G", a - a_gram.T * a_gram))
    else:
        raise ProofSyntaxError("trace_psd_product needs a_psd= or a_gram=")
    premise, c_term = _psd_by_gram("B", b, b_gram, b_scale)
    premises.append(premise)
    return _made(_issue(
        tr(a * b),
        f"trace of a product of PSD matrices, A = {a}, B = {b}",
        tuple(premises) + c_term.premises,
        assumptions + c_term.assumptions,
        frozenset({"congruence"}) | c_term.kernel,
    ), "trace_psd_product", a, b, a_psd, a_gram, b_gram, b_scale)


class Justification:
    """Grounds of one step."""

    kind = "justification"

    def __init__(self, note: str = ""):
        self.note = note

    def describe(self) -> str:
        return self.note


class ByAlgebra(Justification):
    """An equality decided exactly (under the step's side conditions)."""

    kind = "algebra"

    def describe(self) -> str:
        return f"algebra ({self.note})" if self.note else "algebra"


class ByBound(Justification):
    """lhs - rhs (or rhs - lhs for <=) is exactly a sum of non-negative terms."""

    kind = "bound"

    def __init__(self, terms: tuple[Nonneg, ...], note: str = ""):
        super().__init__(note)
        if not terms or not all(isinstance(t, Nonneg) for t in terms):
            raise ProofSyntaxError("by_bound needs at least one non-negative term")
        self.terms = terms

    def describe(self) -> str:
        reasons = "; ".join(t.reason if issued(t) else "(a term not from the kernel)"
                            for t in self.terms)
        return f"{self.note}: {reasons}" if self.note else reasons


class ByCitation(Justification):
    """A step taken from elsewhere; cannot be decided, only falsified."""

    kind = "citation"

    def describe(self) -> str:
        return f"cited: {self.note}"


def by_algebra(note: str = "") -> ByAlgebra:
    return ByAlgebra(note)


def by_bound(*terms: Nonneg, note: str = "") -> ByBound:
    return ByBound(tuple(terms), note)


def by_citation(source: str) -> ByCitation:
    return ByCitation(source)


class BySos(Justification):
    """lhs - rhs (rhs - lhs for <=) is proved >= 0 by an exact SOS certificate."""

    kind = "sos"

    def __init__(self, assumptions: tuple[Assumption, ...], degree: int | None, note: str):
        super().__init__(note)
        self.assumptions = assumptions
        self.degree = degree

    def describe(self) -> str:
        used = ", ".join(a.label for a in self.assumptions)
        text = "SOS certificate" + (f" using {used}" if used else "")
        return f"{self.note}: {text}" if self.note else text


def by_sos(*assumptions: Assumption, degree: int | None = None, note: str = "") -> BySos:
    """Prove an inequality step by a sum-of-squares certificate found and checked here.

    Parameters
    ----------
    *assumptions
        Assumptions of the context (``ctx.assume``) the certificate may use as
        multipliers: kind ``pos``/``nonneg`` (scalar) or ``pd``/``psd`` (matrix).
        Scalars declared positive and lambda_min atoms are used without being named.
    degree
        Cap on the total degree of each term multiplier x SOS (default: the degree of
        the slack's numerator, the most a certificate without cancellation needs);
        a lower cap keeps the search small.

    Examples
    --------
    >>> from verify.proof import Context, Derivation, tr, I3
    >>> ctx = Context("trace")
    >>> R = ctx.rotation("R")
    >>> d = Derivation("tr R <= 3", tr(R), ctx).le(3, by_sos())
    """
    for a in assumptions:
        if type(a) is not Assumption:  # a subclass could answer == and hash as it likes
            raise ProofSyntaxError(
                f"by_sos() takes assumptions made with ctx.assume(...), got "
                f"{type(a).__name__}; did you mean by_sos(ctx.assume(...))?")
    if degree is not None and (isinstance(degree, bool) or not isinstance(degree, int)
                               or not 1 <= degree <= 24):
        raise ProofSyntaxError(f"by_sos(degree=...) must be an integer in [1, 24], "
                               f"got degree={degree!r}")
    return BySos(tuple(assumptions), degree, note)
