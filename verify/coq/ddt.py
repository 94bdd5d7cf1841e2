"""Derivative theorems of derivations that start from a time derivative (``ctx.ddt``).

A derivation such as Lemma 1's ḣ chain (eq. (15)) or Theorem 1's V̇ chain (eq. (17))
starts from ``ctx.ddt(e)``: the tree :mod:`verify.proof.calculus` formed from ``e``
and the declared dynamics (eqs. (9), (12b), (13)). Its steps are Coq theorems at one
instant; this module adds the theorem that the first expression *is* the derivative:
for every trajectory of the context's variables that satisfies the declared dynamics
at ``t`` (a variable with declared dynamics is a function ``R -> M3``, ``R -> V3`` or
``R -> R``; a constant, and a variable no dynamics mention, is a value),

    ``is_derive (fun s => e(s)) t (D(t))``  (``is_mderiv``/``is_vderiv`` entry by entry)

where ``D`` is the derivation's first expression. The dynamics are premises of the
statement itself, so the audit's round trip reads them back too. The proof is
``traj_deriv`` (prelude ``Traj.v``): the rules of Coquelicot's ``is_derive`` applied
along the structure of ``e``, then ``ring`` entry by entry; Coq, not the Python
checker, takes the derivative.

A derivation that starts from a derivative with variables substituted (Theorem 1's
"V̇ at R_l = R̄", the LaSalle step's d/dt(R_lᵀR̄) at R̄ = R_l) gets the same theorem
with the substitution at ``t`` as premises (``R_l t = R̄ t``).
"""

from __future__ import annotations

from dataclasses import dataclass

from verify.coq.reparse import intended
from verify.coq.terms import CoqExportError, Naming, coq_text
from verify.coq.unit import comment_text
from verify.proof.derivation import Derivation
from verify.proof.expr import (
    MATRIX,
    SCALAR,
    VECTOR,
    Expr,
    Variable,
    postorder,
    replace_variables,
    structural_key,
    variables_of,
)
from verify.proof.printing import to_text

#: The theorem's name in a derivation unit.
THEOREM = "ddt"
#: The prelude's derivative predicate of each shape.
PREDICATES = {SCALAR: "is_derive", VECTOR: "is_vderiv", MATRIX: "is_mderiv"}
#: Imports the derivative theorem needs (after the instant section, so the instant
#: proofs are unchanged).
IMPORTS = ("From Coquelicot Require Import Hierarchy Derive.",
           "From VerifyCoq Require Import Traj.")
_TYPES = {"rotation": "M3", "matrix": "M3", "symmetric": "M3", "vector": "V3",
          "unit_vector": "V3", "scalar": "R", "angle": "R"}


@dataclass(frozen=True)
class DdtStart:
    """A derivation's first expression as a derivative: ``start`` is d/dt of
    ``argument`` along the context's dynamics, with ``substitution`` (variable uid ->
    expression) applied afterwards (empty for a plain ``ctx.ddt``)."""

    argument: Expr
    derivative: Expr
    substitution: tuple[tuple[Variable, Expr], ...]


def ddt_start(d: Derivation) -> DdtStart | None:
    """How ``d.start`` is a derivative of its context (None when it is not)."""
    key = structural_key(d.start)
    derived = list(getattr(d.context, "_derived", ()))
    for out, arg in derived:
        if structural_key(out) == key:
            return DdtStart(arg, out, ())
    for out, arg in derived:
        table = _substitution(out, d.start)
        if table and structural_key(replace_variables(out, {v.uid: x for v, x in table})) == key:
            return DdtStart(arg, out, tuple(table))
    return None


def _substitution(before: Expr, after: Expr) -> list[tuple[Variable, Expr]] | None:
    """The variables of ``before`` replaced to make ``after`` (walked side by side), or
    None when the trees differ otherwise."""
    table: dict[int, tuple[Variable, Expr]] = {}
    stack = [(before, after)]
    seen: set[tuple[int, int]] = set()
    while stack:
        a, b = stack.pop()
        if (id(a), id(b)) in seen:
            continue
        seen.add((id(a), id(b)))
        if a.op == "var":
            if b.op == "var" and b.data.uid == a.data.uid:
                continue
            if a.shape == b.shape and a.data.uid not in table:
                table[a.data.uid] = (a.data, b)
                continue
            if a.data.uid in table and structural_key(table[a.data.uid][1]) == structural_key(b):
                continue
            return None
        if a.op != b.op or a.shape != b.shape or len(a.args) != len(b.args) or (
                not a.args and a.data != b.data):
            return None
        stack.extend(zip(a.args, b.args, strict=True))
    return list(table.values())


class _AtTime:
    """The section's names with trajectories applied to a time (``(x t)``); the same
    naming for :func:`verify.coq.terms.coq_text` and, with ``tree``, for
    :func:`verify.coq.reparse.intended`."""

    def __init__(self, naming: Naming, moving: set[int], time: str, tree: bool = False):
        self.naming, self.moving, self.time, self.tree = naming, moving, time, tree

    def variable(self, v: Variable) -> str:
        n = self.naming.variable(v)
        if v.uid not in self.moving:
            return n
        return f"{n}({self.time})" if self.tree else f"({n} {self.time})"

    def lambda_atom(self, node: Expr) -> str:
        raise CoqExportError("lambda_min is not differentiable: no derivative theorem")


def _said(e: Expr) -> str:
    return comment_text(to_text(e, labels=False))


def ddt_theorem(d: Derivation, naming: Naming) -> tuple[str, str, str] | None:
    """The trajectory section of ``d`` (Coq text), its theorem's statement and its
    intended tree (:func:`verify.coq.reparse.intended`), or None when ``d`` does not
    start from a derivative. Raises :class:`CoqExportError` when it cannot be stated."""
    found = ddt_start(d)
    if found is None:
        return None
    dynamics = d.context._dynamics
    arg, start = found.argument, d.start
    if arg.shape not in PREDICATES:
        raise CoqExportError("only scalars, vectors and matrices are differentiated")
    if any(n.op == "lambda_min" for n in postorder(arg, start)):
        raise CoqExportError("lambda_min is not differentiable: no derivative theorem")
    rates = {v.uid: dynamics[v.uid] for v in variables_of(arg)
             if dynamics.get(v.uid) is not None}
    subst = list(found.substitution)
    mentioned = variables_of(arg, start, *rates.values(), *(x for _, x in subst))
    mentioned += [v for v, _ in subst if v.uid not in {w.uid for w in mentioned}]
    moving = {v.uid for v in mentioned if dynamics.get(v.uid) is not None}
    order = {v.uid: k for k, v in enumerate(d.context.variables)}
    mentioned.sort(key=lambda v: order.get(v.uid, len(order)))
    at_s, at_t = _AtTime(naming, moving, "s"), _AtTime(naming, moving, "t")
    tree_s, tree_t = _AtTime(naming, moving, "s", True), _AtTime(naming, moving, "t", True)
    premises, trees = [], []
    for v in mentioned:
        if v.uid in rates and v.uid in {w.uid for w in variables_of(arg)}:
            rate = rates[v.uid]
            pred = PREDICATES[SCALAR if v.kind == "angle" else rate.shape]
            n = naming.variable(v)
            premises.append(f"{pred} {n} t {coq_text(rate, at_t)}")
            trees.append(f"{pred}({n},t,{intended(rate, tree_t)})")
    for v, x in subst:
        lhs = at_t.variable(v)
        premises.append(f"{lhs} = {coq_text(x, at_t)}")
        trees.append(f"{tree_t.variable(v)} = {intended(x, tree_t)}")
    pred = PREDICATES[arg.shape]
    conclusion = f"{pred} (fun s => {coq_text(arg, at_s)}) t {coq_text(start, at_t)}"
    statement = " -> ".join([*premises, conclusion])
    tree = " -> ".join([*trees, f"{pred}(fun(s,{intended(arg, tree_s)}),t,"
                                f"{intended(start, tree_t)})"])
    lines = ["", *IMPORTS, "", f"Section {THEOREM}_trajectories.", ""]
    for v in mentioned:
        n, typ, label = naming.variable(v), _TYPES[v.kind], comment_text(v.name)
        if v.uid in moving:
            lines.append(f"(** {label}: a trajectory (its derivative at t is a premise "
                         "when it is differentiated) *)")
            lines.append(f"Variable {n} : R -> {typ}.")
        elif dynamics.get(v.uid, 0) is None:
            lines += [f"(** {label}: constant *)", f"Variable {n} : {typ}."]
        else:
            lines += [f"(** {label}: its value at t *)", f"Variable {n} : {typ}."]
    lines += ["Variable t : R.", ""]
    names = [f"E{k}" for k in range(1, len(subst) + 1)]
    intros = " ".join([f"D{k}" for k in range(1, len(premises) - len(subst) + 1)] + names)
    lemma = {"is_derive": "deriv_unique_eq", "is_mderiv": "mderiv_unique_eq",
             "is_vderiv": "vderiv_unique_eq"}[pred]
    rewrites = "".join(f" try rewrite {e};" for e in names)
    how = "the declared dynamics" + (" and the substitution" if subst else "")
    lines += [f"(** The first expression is the derivative: d/dt {_said(arg)} along {how},",
              f"    at every t, is {_said(start)} *)",
              f"Theorem {THEOREM} : {statement}.",
              "Proof.",
              f"  intros {intros}." if intros else "  intros.",
              f"  eapply {lemma}; [ d_mirror | cbv beta;{rewrites} traj_same ].",
              "Qed.", "", f"End {THEOREM}_trajectories.", ""]
    return "\n".join(lines), statement, tree


__all__ = ["PREDICATES", "THEOREM", "DdtStart", "ddt_start", "ddt_theorem"]
