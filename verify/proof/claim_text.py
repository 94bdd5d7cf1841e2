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

from dataclasses import dataclass

from verify.artefacts.text import shown
from verify.proof.expr import Variable, nodes, variables_of
from verify.proof.printing import name_text, to_text
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
    another variable of the claim already prints the same."""
    names: dict[int, str] = {}
    used: set[str] = set()
    for v in claim_variables(problem):
        base = text = name_text(v.name)
        k = 1
        while text in used:
            k += 1
            text = f"{base}#{k}"
        used.add(text)
        names[v.uid] = text
    return names


def claim_text(problem: StepProblem) -> ClaimText:
    """The claim of ``problem`` as its tree says, with its declarations and assumptions."""
    names = display_names(problem)
    inequality = (f"{to_text(problem.lhs, labels=False, names=names)} {problem.relation} "
                  f"{to_text(problem.rhs, labels=False, names=names)}")
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
    assumptions: list[str] = []
    for a in problem.assumptions:
        value = to_text(a.expr, labels=False, names=names)
        if a.kind in ("pd", "psd") and a.expr.op != "sym":
            value = f"sym({value})"  # what a definiteness assumption is about
        text = _ASSUMED[a.kind].format(value)
        if text not in assumptions:
            assumptions.append(text)
    return ClaimText(inequality, tuple(declarations), tuple(assumptions),
                     label_definitions(problem, names))


#: Leaves whose label is their own name or symbol, never an abbreviation.
_LEAVES = ("var", "const", "zero", "identity", "chart_gap")


def label_definitions(problem: StepProblem, names: dict[int, str]) -> tuple[str, ...]:
    """``label = tree`` for every labelled node of the two sides whose label is not its
    tree's text, spaces aside (each once, in first-seen order)."""
    out: list[str] = []
    for e in nodes(problem.lhs, problem.rhs):
        if e.label is None or e.op in _LEAVES:
            continue
        tree = to_text(e, labels=False, names=names)
        label = shown(e.label)
        text = f"{label} = {tree}"
        # spaces only separate factors: a label that differs from its tree by them
        # alone (ξξᵀ for ξ ξᵀ) abbreviates nothing
        if label.replace(" ", "") != tree.replace(" ", "") and text not in out:
            out.append(text)
    return tuple(out)


__all__ = ["ClaimText", "claim_text", "claim_variables", "display_names", "label_definitions"]
