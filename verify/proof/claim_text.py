"""A step's claim as its tree says, with every premise it rests on (what a checked SOS
certificate is reported as).

In: a :class:`~verify.proof.problem.StepProblem`. Out: a :class:`ClaimText`, the
inequality printed from the tree (every label ignored: a label is the author's word and
binds nothing), then ``for all`` each variable with its kind or its declared sign
(``R ∈ SO(3)``, ``k > 0``) and ``with`` each sign assumption, also printed from its tree
(``c >= 0``). Names are quoted when they could be misread
(:func:`verify.proof.printing.name_text`), and two distinct variables that would print
alike are told apart (``R``, ``R#2``).

Side conditions (``where=``) are not premises of an SOS certificate: its identity holds
for every value of the parameters (Section 3's inequalities, proved as in
:mod:`verify.proof.sos_step`), so the claim is printed without them, which is the
stronger statement the certificate proves.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from verify.artefacts.text import shown
from verify.proof.expr import Expr, Variable, nodes, variables_of
from verify.proof.printing import MAX_TEXT, name_text, tree_text
from verify.proof.problem import StepProblem

#: How each kind of variable is declared in a printed claim (``scalar`` by its sign).
_KIND_TEXT = {
    "rotation": "∈ SO(3)",
    "unit_vector": "∈ S² (unit vectors)",
    "angle": "∈ ℝ (angles)",
    "vector": "∈ ℝ³",
    "matrix": "∈ ℝ³ˣ³",
    "symmetric": "∈ ℝ³ˣ³ symmetric",
    "scalar": "∈ ℝ",
}
#: An assumption of each kind, as a relation (pd/psd: of the symmetric part, printed
#: ``sym(M) ≻ 0`` so that it is not read as entrywise positivity).
_ASSUMED = {"pos": "{} > 0", "nonneg": "{} >= 0", "pd": "{} ≻ 0", "psd": "{} ⪰ 0"}


@dataclass(frozen=True)
class ClaimText:
    """The inequality as its tree says, the variables' declarations and the assumptions."""

    inequality: str
    declarations: tuple[str, ...]
    assumptions: tuple[str, ...]
    #: ``label = tree`` for each label of the two sides that reads otherwise than its
    #: tree (what a statement written with labels abbreviates)
    definitions: tuple[str, ...] = ()

    @property
    def premises(self) -> tuple[str, ...]:
        """Every premise: declarations, then assumptions."""
        return self.declarations + self.assumptions


def claim_variables(problem: StepProblem) -> list[Variable]:
    """The variables of the claim: of its two sides and its assumptions (a variable of
    the side conditions only is no part of what an SOS certificate proves)."""
    return variables_of(problem.lhs, problem.rhs, *(a.expr for a in problem.assumptions))


def display_names(problem: StepProblem) -> dict[int, str]:
    """Each variable's printed name by uid: :func:`name_text`, with ``#k`` added when
    another variable of the claim already prints the same (``#`` is not in a bare name,
    so ``R#2`` is no other variable's text)."""
    names: dict[int, str] = {}
    seen: dict[str, int] = {}
    for v in claim_variables(problem):
        base = name_text(v.name)
        k = seen[base] = seen.get(base, 0) + 1
        names[v.uid] = base if k == 1 else f"{base}#{k}"
    return names


def claim_text(problem: StepProblem) -> ClaimText:
    """The claim of ``problem`` as its tree says, with its declarations and assumptions."""
    names = display_names(problem)
    text_of = tree_text(names)
    inequality = f"{text_of(problem.lhs)} {problem.relation} {text_of(problem.rhs)}"
    # in first-seen order: a declared sign alone, variables of one kind together
    entries: list[tuple[str, list[str]]] = []
    by_kind: dict[str, list[str]] = {}
    for v in claim_variables(problem):
        if v.kind == "scalar" and v.positive:
            entries.append(("> 0", [names[v.uid]]))
        elif str(v.kind) in by_kind:
            by_kind[str(v.kind)].append(names[v.uid])
        else:
            by_kind[str(v.kind)] = [names[v.uid]]
            entries.append((_KIND_TEXT[v.kind], by_kind[str(v.kind)]))
    declarations = [f"{', '.join(listed)} {what}" for what, listed in entries]
    assumptions: dict[str, None] = {}  # in order, once each
    for a in problem.assumptions:
        value = text_of(a.expr)
        if a.kind in ("pd", "psd") and a.expr.op != "sym":
            value = f"sym({value})"  # what a definiteness assumption is about
        assumptions[_ASSUMED[a.kind].format(value)] = None
    return ClaimText(inequality, tuple(declarations), tuple(assumptions),
                     label_definitions(problem, text_of))


#: Leaves whose label is their own name or symbol, never an abbreviation.
_LEAVES = ("var", "const", "zero", "identity", "chart_gap")
MAX_DEFINITIONS = 64  # labels defined in one claim before the rest are counted


def label_definitions(problem: StepProblem, text_of: Callable[[Expr], str]
                      ) -> tuple[str, ...]:
    """``label = tree`` for every labelled node of the two sides whose label is not its
    tree's text, spaces aside (each once, in first-seen order; past
    :data:`MAX_DEFINITIONS`, how many more)."""
    out: dict[str, None] = {}
    more = 0
    for e in nodes(problem.lhs, problem.rhs):
        if e.label is None or e.op in _LEAVES:
            continue
        tree = text_of(e)
        label = shown(e.label, limit=MAX_TEXT)
        # spaces only separate factors: a label that differs from its tree by them
        # alone (ξξᵀ for ξ ξᵀ) abbreviates nothing
        if label.replace(" ", "") == tree.replace(" ", ""):
            continue
        if len(out) < MAX_DEFINITIONS:
            out[f"{label} = {tree}"] = None
        else:
            more += 1
    return tuple(out) + ((f"… ({more} more labels)",) if more else ())


__all__ = ["ClaimText", "claim_text", "claim_variables", "display_names", "label_definitions"]
