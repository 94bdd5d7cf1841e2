"""Decide every step of a derivation: exact check first, falsification beside it.

Verdict of a step:

- ``verified``: the exact check passed (lhs - rhs, or lhs - rhs minus the certificate's
  non-negative terms, is the zero rational function, or lies in the ideal of the side
  conditions) and every exact premise of the terms passed; under side conditions it
  passed also with each angle / unit vector at the point its chart misses; the
  conditions and assumptions are not vacuous (no exact contradiction, and some sampled
  point satisfies them); every numerical violation the falsifiers saw was rejected by
  exact evaluation at that point.
- ``refuted``: a counterexample was confirmed exactly (:mod:`verify.proof.confirm`)
  against every declaration, condition and assumption at once.
- ``inconclusive``: anything else, with the reason: a step the exact check cannot decide
  (a citation, a premise that fails, a certificate that does not match), vacuous or
  unwitnessed conditions, a numerical violation exact arithmetic could not decide.

A derivation is verified when every step is and the union of all its steps' conditions
and assumptions is witnessed by one sampled point; refuted when some step is. Its
conclusion states that union. ``verify/proof/TRUSTED.md`` lists what this rests on.
"""

from __future__ import annotations

import enum
import sys
import time
from dataclasses import dataclass, field

from verify.proof.budget import Budget, BudgetExceededError, run_bounded
from verify.proof.confirm import confirm, exact_witness
from verify.proof.derivation import RELATIONS, Derivation, Step
from verify.proof.expr import (
    MAX_DEPTH,
    SCALAR,
    Expr,
    ProofSyntaxError,
    structural_key,
    validate_tree,
)
from verify.proof.falsify import SearchReport, SearchSettings, random_search, search
from verify.proof.hypotheses import Assumption, Condition
from verify.proof.justify import (
    KERNEL,
    ByAlgebra,
    ByBound,
    ByCitation,
    BySos,
    Justification,
    issued,
)
from verify.proof.problem import StepProblem
from verify.proof.size import over_limits
from verify.proof.sos_step import exact_check as sos_exact_check


class ProofVerdict(enum.StrEnum):
    """Verdicts of a step and of a derivation (see the module docstring).

    A StrEnum, as :class:`verify.claims.model.Verdict`: a member equals, prints and
    serialises to JSON as its plain string, so reports are unchanged.
    """

    VERIFIED = "verified"
    REFUTED = "refuted"
    INCONCLUSIVE = "inconclusive"


VERIFIED, REFUTED, INCONCLUSIVE = ProofVerdict


@dataclass
class StepResult:
    index: int
    relation: str
    lhs: str
    rhs: str
    justification: str
    verdict: ProofVerdict
    exact: str  # what the exact check established, or why it could not
    conditions: list[str] = field(default_factory=list)
    assumptions: list[str] = field(default_factory=list)
    kernel: list[str] = field(default_factory=list)
    # signs the step may rest on without an assumption: scalars declared positive (a
    # kernel term ``positive``, or an SOS multiplier)
    declarations: list[str] = field(default_factory=list)
    counterexample: dict | None = None
    unconfirmed_violation: bool = False
    falsification: dict = field(default_factory=dict)
    note: str = ""
    seconds: float = 0.0

    def to_json(self) -> dict:
        return dict(self.__dict__)


@dataclass
class DerivationResult:
    name: str
    statement: str
    cite: str
    start: str
    relation: str
    end: str
    steps: list[StepResult]
    seconds: float
    conditions: list[str] = field(default_factory=list)  # union over the steps
    vacuous: str = ""  # why the steps' conditions and assumptions cannot hold together

    @property
    def verdict(self) -> ProofVerdict:
        verdicts = {s.verdict for s in self.steps}
        if REFUTED in verdicts:
            return REFUTED
        if verdicts <= {VERIFIED} and self.steps and not self.vacuous:
            return VERIFIED
        return INCONCLUSIVE

    @property
    def conclusion(self) -> str:
        """The statement proved, with every condition and assumption it rests on."""
        text = f"{self.start} {self.relation} {self.end}"
        if self.conditions:
            text += " where " + "; ".join(self.conditions)
        grounds = self.declarations + self.assumptions
        if grounds:
            text += " assuming " + "; ".join(grounds)
        return text

    @property
    def declarations(self) -> list[str]:
        return _unique(d for s in self.steps for d in s.declarations)

    @property
    def assumptions(self) -> list[str]:
        return _unique(a for s in self.steps for a in s.assumptions)

    def to_json(self) -> dict:
        return {
            "name": self.name,
            "statement": self.statement,
            "cite": self.cite,
            "start": self.start,
            "conclusion": self.conclusion,
            "verdict": self.verdict,
            "conditions": self.conditions,
            "assumptions": self.assumptions,
            "declarations": self.declarations,
            "vacuous": self.vacuous,
            "seconds": round(self.seconds, 3),
            "steps": [s.to_json() for s in self.steps],
        }


def _unique(items) -> list[str]:
    """The items once each, in first-appearance order (linear)."""
    out: list[str] = []
    seen: set[str] = set()
    for x in items:
        if x not in seen:
            seen.add(x)
            out.append(x)
    return out


def step_problem(d: Derivation, step: Step) -> StepProblem:
    """The exact question one step asks: its two sides, the derivation's and the step's
    conditions, and the assumptions and terms its justification brings."""
    conditions = tuple(d.where) + tuple(step.where)
    because = step.because
    extra: tuple = ()
    assumptions = list(d.assumes)
    if isinstance(because, ByBound):
        for t in because.terms:
            if not issued(t):
                continue  # refused by the exact check; nothing of it is evaluated
            extra += (t.value, *(p.expr for p in t.premises))
            assumptions += [a for a in t.assumptions if a not in assumptions]
    if isinstance(because, BySos):
        assumptions += [a for a in because.assumptions if a not in assumptions]
    return StepProblem(step.relation, step.lhs, step.rhs, conditions, tuple(assumptions),
                       extra)


def _exact_check(step: Step, problem: StepProblem) -> tuple[bool, str]:
    because = step.because
    if isinstance(because, ByCitation):
        return False, "not decidable: the step rests on a citation with no checkable premise"
    where = " modulo the side conditions" if problem.conditions else ""
    if isinstance(because, ByAlgebra):
        if step.relation != "=":
            return False, "an inequality cannot be justified by algebra alone; use by_bound"
        if all(problem.vanishes(v) for v in problem.exact_slack):
            return True, f"lhs - rhs = 0 exactly (rational functions of the parameters){where}"
        return False, "lhs - rhs is not identically zero" + where
    if isinstance(because, ByBound):
        if step.relation == "=":
            return False, "an equality is justified by algebra, not by a bound"
        if not because.terms or not all(issued(t) for t in because.terms):
            return False, "a non-negative term was not built by the kernel's constructors"
        total = because.terms[0].value
        for t in because.terms[1:]:
            total = total + t.value
        (rest,) = problem.exact(problem.slack_expr - total)
        if not problem.vanishes(rest):
            return False, (
                "the slack is not the sum of the stated non-negative terms" + where
            )
        for t in because.terms:
            for premise in t.premises:
                if not all(problem.vanishes(v) for v in problem.exact(premise.expr)):
                    return False, f"premise fails: {premise.label}"
        n = sum(len(t.premises) for t in because.terms)
        return True, (
            f"slack = sum of {len(because.terms)} non-negative term(s) exactly{where}; "
            f"{n} exact premise(s) hold"
        )
    if isinstance(because, BySos):
        return sos_exact_check(step, problem)
    return False, f"unknown justification {type(because).__name__}"


MAX_CHART_GAPS = 5  # 2^5 - 1 pinned copies of a step at most


def _pieces(problem: StepProblem) -> list[StepProblem] | None:
    """The step in every chart combination: each chart-gap variable in its chart or at the
    point the chart misses. None when there are too many gap variables to enumerate."""
    gaps = problem.gap_variables
    if len(gaps) > MAX_CHART_GAPS:
        return None
    out = []
    for mask in range(1, 2 ** len(gaps)):
        out.append(problem.pinned([v for k, v in enumerate(gaps) if mask >> k & 1]))
    return out


def _vacuity(problem: StepProblem, pieces: list[StepProblem]) -> str:
    """Why the conditions and assumptions can never hold, decided exactly (or "")."""
    false = problem.false_constant_assumptions
    if false:
        return f"assumption false as a constant: {false[0]}"
    if problem.conditions and all(p.conditions_empty for p in [problem, *pieces]):
        return ("the side conditions have no common real solution (decided exactly in "
                "every chart)")
    return ""


def _covered(step: Step, pieces: list[StepProblem]) -> tuple[bool, str, list[StepProblem]]:
    """Exact check of the step at the points the charts miss (all pinned pieces).

    A ``by_sos`` certificate uses neither the side conditions nor assumptions on angles or
    unit vectors, so it proves the slack >= 0 at every parameter value; the slack is
    continuous in the variables and the charts' images are dense, so it holds at the
    missed points as well, and no pinned copy needs (or gets) a certificate of its own.
    """
    if isinstance(step.because, BySos):
        return True, "", []
    failing = []
    for piece in pieces:
        ok, text = _exact_check(step, piece)
        if not ok:
            failing.append((piece, text))
    if not failing:
        return True, "", []
    piece, text = failing[0]
    where = ", ".join(f"{n} = {w}" for n, w in piece.pinned_names.items())
    return False, f"but at a point the charts miss ({where}): {text}", [p for p, _ in failing]


def check_step(d: Derivation, index: int, cfg: SearchSettings) -> StepResult:
    step = d.steps[index]
    start = time.perf_counter()
    problem = step_problem(d, step)
    settings = SearchSettings(cfg.samples, cfg.hypothesis_examples, cfg.ipopt_starts,
                              cfg.seed + 7919 * index)
    too_large = over_limits(*problem.all_exprs)
    try:
        if too_large:  # decided before any algebra is done
            raise _TooLargeError(too_large)
        ok, exact_text, report, counterexample, vacuous = _decide(step, problem, settings)
    except ProofSyntaxError:
        raise
    except _TooLargeError as exc:
        ok, vacuous, counterexample = False, "", None
        exact_text = f"not decided: budget exceeded before the work ({exc})"
        report = SearchReport()
    except Exception as exc:  # never an internal error as the answer: say what failed
        ok, vacuous, counterexample = False, "", None
        exact_text = f"not decided: {type(exc).__name__} while checking ({exc})"
        report = SearchReport()
    if counterexample is not None:
        verdict = REFUTED
        if ok:  # an exact proof and an exact counterexample cannot both stand
            exact_text += "; INTERNAL DISAGREEMENT with an exact counterexample"
            verdict = INCONCLUSIVE
    elif vacuous:
        verdict, exact_text = INCONCLUSIVE, f"{exact_text}; but vacuous: {vacuous}"
    elif not ok:
        verdict = INCONCLUSIVE
    elif report.feasible == 0:
        verdict = INCONCLUSIVE
        exact_text += ("; but no sampled point satisfies the side conditions and "
                       "assumptions exactly (they may be unsatisfiable)")
    elif report.undecided:
        verdict = INCONCLUSIVE
        exact_text += "; but a numerical violation was seen (not decided exactly)"
    else:
        verdict = VERIFIED
        if report.rejected:
            exact_text += (f"; {report.rejected} numerical violation(s) seen and rejected by "
                           "exact evaluation at the point (float rounding)")
    kernel: list[str] = []
    if isinstance(step.because, ByBound):
        for t in filter(issued, step.because.terms):
            kernel += [KERNEL[k] for k in sorted(t.kernel) if KERNEL[k] not in kernel]
    return StepResult(
        index=index + 1,
        relation=step.relation,
        lhs=str(step.lhs),
        rhs=str(step.rhs),
        justification=step.because.describe(),
        verdict=verdict,
        exact=exact_text,
        conditions=[c.label for c in problem.conditions],
        assumptions=[a.label + (f" ({a.cite})" if a.cite else "") for a in problem.assumptions],
        kernel=kernel,
        declarations=[f"{v.name} > 0 (declared)" for v in problem.variables
                      if v.kind == "scalar" and v.positive],
        counterexample=None if counterexample is None else counterexample.to_json(),
        unconfirmed_violation=bool(report.candidates) and counterexample is None,
        falsification=report.to_json(),
        note=step.note,
        seconds=time.perf_counter() - start,
    )


class _TooLargeError(Exception):
    """A step over the size limits of :mod:`verify.proof.size`."""


def _within(budget: Budget, deadline: float | None) -> Budget:
    """The budget, its time cut to what is left before ``deadline`` (time.monotonic)."""
    if deadline is None:
        return budget
    left = deadline - time.monotonic()
    if left <= 0:
        raise BudgetExceededError("the file's time budget is spent")
    return Budget(min(budget.seconds, left), budget.memory)


def bounded_step(d: Derivation, index: int, cfg: SearchSettings,
                 budget: Budget | None, deadline: float | None = None) -> StepResult:
    """:func:`check_step` within ``budget`` (in a forked process; None: in this one) and
    before ``deadline`` (time.monotonic; a file's whole budget).

    A step that runs out of time or memory is *inconclusive: budget exceeded*.
    """
    if budget is None:
        return check_step(d, index, cfg)
    start = time.perf_counter()
    try:
        return run_bounded(lambda: check_step(d, index, cfg), _within(budget, deadline))
    except (BudgetExceededError, RuntimeError) as exc:
        step = d.steps[index]
        exceeded = isinstance(exc, BudgetExceededError)
        return StepResult(
            index=index + 1, relation=step.relation, lhs=str(step.lhs), rhs=str(step.rhs),
            justification=step.because.describe(), verdict=INCONCLUSIVE,
            exact=(f"not decided: budget exceeded ({exc})" if exceeded
                   else f"not decided: {exc}"),
            conditions=[c.label for c in (*d.where, *step.where)],
            note=step.note, seconds=time.perf_counter() - start)


def _decide(step: Step, problem: StepProblem, settings: SearchSettings):
    """Exact check in every chart, vacuity, the searches, and an exact witness.

    Returns (exact ok, text, search report, counterexample, why vacuous). The premises
    count as satisfiable only if a sampled point, rounded to rationals with the
    conditions solved exactly, meets every declaration exactly (:func:`exact_witness`);
    otherwise ``report.feasible`` is set to 0.
    """
    pieces: list[StepProblem] = []
    if problem.conditions:
        found = _pieces(problem)
        if found is None:
            return (False, f"more than {MAX_CHART_GAPS} angle/unit-vector variables under side "
                    "conditions: the charts' missing points cannot be covered",
                    SearchReport(), None, "")
        pieces = found
    ok, exact_text = _exact_check(step, problem)
    failing: list[StepProblem] = list(pieces)
    if ok and pieces:
        ok, gap_text, failing = _covered(step, pieces)
        exact_text = ("in the charts: " + exact_text
                      + ("; also exactly at the points the charts miss" if ok
                         else "; " + gap_text))
    vacuous = _vacuity(problem, pieces)
    report, counterexample = search(problem, settings, confirm)
    runs = [(problem, report)]
    for piece in failing:  # a counterexample may sit only where a chart does not reach
        if counterexample is not None:
            break
        more, counterexample = search(piece, settings, confirm)
        runs.append((piece, more))
    if ok and not vacuous and counterexample is None:
        witnessed = _witnessed(runs)
        for piece in pieces:  # the conditions may hold only at a chart's missing point
            if witnessed or counterexample is not None:
                break
            if all(piece is not p for p, _ in runs) and not piece.conditions_empty:
                more, counterexample = search(piece, settings, confirm)
                runs.append((piece, more))
                witnessed = _witnessed(runs[-1:])
        if not witnessed:
            for _, r in runs:
                r.feasible = 0
    for _, more in runs[1:]:
        report.merge(more)
    return ok, exact_text, report, counterexample, vacuous


def _witnessed(runs: list) -> bool:
    """Some sampled point of some run meets every declaration exactly.

    With no condition and no assumption the only declarations are positive scalars,
    which any sampled point meets (its rounding to rationals stays positive).
    """
    return any(
        (r.feasible > 0 and not piece.conditions and not piece.assumptions)
        or any(exact_witness(piece, point) for point in r.feasible_points[:WITNESS_TRIES])
        for piece, r in runs
    )


WITNESS_TRIES = 4


def _snapshot(d: Derivation) -> Derivation:
    """A private copy of the chain, so that what is validated is what is checked."""
    if type(d) is not Derivation:
        raise ProofSyntaxError(f"check() takes a Derivation, got {type(d).__name__}")
    try:
        steps = [Step(s.relation, s.lhs, s.rhs, s.because, tuple(s.where), s.note)
                 if type(s) is Step else s for s in d.steps]
        copy = Derivation(d.name, d.start, d.context, tuple(d.where), tuple(d.assumes),
                          d.statement, d.cite)
    except ProofSyntaxError:
        raise
    except Exception as exc:
        raise ProofSyntaxError(f"malformed derivation: {type(exc).__name__}: {exc}") from None
    copy.steps = steps
    return copy


def validate_derivation(d: Derivation) -> None:
    """Refuse a derivation not built through the API: each step must start where the
    previous one ended (the first at ``start``), relations and shapes must be those the
    builders allow, and every tree must be well formed."""
    if type(d) is not Derivation:  # a subclass could answer differently on each read
        raise ProofSyntaxError(f"check() takes a Derivation, got {type(d).__name__}")
    if not all(isinstance(x, str) for x in (d.name, d.statement, d.cite)):
        raise ProofSyntaxError("a derivation's name, statement and cite are strings")
    if not isinstance(d.start, Expr):
        raise ProofSyntaxError(f"{d.name}: the start is not an expression")
    if not all(type(c) is Condition for c in d.where) or not all(
        type(a) is Assumption for a in d.assumes
    ):
        raise ProofSyntaxError(f"{d.name}: where= takes conditions, assumes= assumptions")
    validate_tree(*_every_expression(d))  # each shared node once, for all steps together
    previous, relations = d.start, set()
    for i, step in enumerate(d.steps, 1):
        if type(step) is not Step or step.relation not in RELATIONS:
            raise ProofSyntaxError(f"{d.name}: step {i} is not a step (use equals/le/ge)")
        if not isinstance(step.because, Justification) or not type(
            step.because
        ).__module__.startswith("verify."):
            raise ProofSyntaxError(f"{d.name}: step {i} needs a justification of "
                                   "verify.proof (by_algebra, by_bound, by_citation)")
        if not all(type(c) is Condition for c in step.where):
            raise ProofSyntaxError(f"{d.name}: step {i}: where= takes conditions")
        if isinstance(step.because, ByBound) and type(step.because.terms) is not tuple:
            raise ProofSyntaxError(f"{d.name}: step {i}: by_bound's terms were replaced")
        if step.lhs is not previous and structural_key(step.lhs) != structural_key(previous):
            raise ProofSyntaxError(
                f"{d.name}: step {i} does not start where "
                + ("the derivation starts" if i == 1 else f"step {i - 1} ended")
            )
        if step.rhs.shape != d.start.shape or (step.relation != "=" and
                                              step.rhs.shape != SCALAR):
            raise ProofSyntaxError(f"{d.name}: step {i} has the wrong shape")
        relations.add(step.relation)
        previous = step.rhs
    if {"<=", ">="} <= relations:
        raise ProofSyntaxError(f"{d.name}: a chain cannot mix <= and >=")


def _every_expression(d: Derivation) -> list:
    """The trees of every step's problem (sides, conditions, assumptions, terms and their
    premises), each derivation-wide part listed once (linear in the derivation's size)."""
    out: list = [d.start]
    for c in d.where:
        out += [c.lhs, c.rhs]
    out += [a.expr for a in d.assumes]
    for step in d.steps:
        if type(step) is not Step or not all(type(c) is Condition for c in step.where):
            continue  # refused with its reason by the caller
        out += [step.lhs, step.rhs]
        for c in step.where:
            out += [c.lhs, c.rhs]
        because = step.because
        if isinstance(because, ByBound) and type(because.terms) is tuple:
            for t in because.terms:
                if issued(t):
                    out += [t.value, *(p.expr for p in t.premises),
                            *(a.expr for a in t.assumptions)]
        if isinstance(because, BySos):
            out += [a.expr for a in because.assumptions]
    return out


def _joint(d: Derivation, problems: list[StepProblem], cfg: SearchSettings) -> str:
    """Why the union of every step's conditions and assumptions is vacuous, or ""."""
    conditions, assumptions = _union(problems)
    if any(
        len({id(c) for c in p.conditions}) == len(conditions)
        and len({id(a) for a in p.assumptions}) == len(assumptions)
        for p in problems  # each problem's own are a part of the union
    ):
        return ""  # one verified step carries all of them: its samples witnessed them
    joint = StepProblem("=", d.start, d.current, conditions, assumptions)
    pieces = (_pieces(joint) or []) if conditions else []
    vacuous = _vacuity(joint, pieces)
    if vacuous:
        return vacuous
    for piece in [joint, *pieces]:
        if piece.conditions and piece.conditions_empty:
            continue
        report = SearchReport()
        random_search(piece, cfg, report)
        if _witnessed([(piece, report)]):
            return ""
    return ("no sampled point satisfies the steps' conditions and assumptions together "
            "exactly (they may be jointly unsatisfiable)")


def _union(problems: list[StepProblem]) -> tuple[tuple, tuple]:
    """Every problem's conditions and assumptions, each object once, in first-appearance
    order (linear: identities in a set)."""
    conditions: list = []
    assumptions: list = []
    seen: set[int] = set()
    for p in problems:
        for c in p.conditions:
            if id(c) not in seen:
                seen.add(id(c))
                conditions.append(c)
        for a in p.assumptions:
            if id(a) not in seen:
                seen.add(id(a))
                assumptions.append(a)
    return tuple(conditions), tuple(assumptions)


def check(d: Derivation, cfg: SearchSettings | None = None, *,
          budget: Budget | None = None, deadline: float | None = None) -> DerivationResult:
    """Check every step of ``d``, then that its conditions and assumptions can hold together.

    Parameters
    ----------
    d : Derivation
        A derivation built with :class:`~verify.proof.derivation.Derivation` and the step
        builders of :mod:`verify.proof`; it is snapshotted before checking, so later
        changes to it do not affect the result.
    cfg : SearchSettings, optional
        Budget and seed of the falsification search beside the exact check (samples,
        hypothesis examples, IPOPT starts). Never decides a positive verdict.
    budget : Budget, optional
        Time and memory of each step and of the joint check, each run in a forked process
        (:mod:`verify.proof.budget`); past it the step is inconclusive: budget exceeded.
        None (the default, used for the paper's own derivations) runs in this process.
    deadline : float, optional
        With a budget: no step runs past this ``time.monotonic()`` value (a file's whole
        time budget); a step with no time left is inconclusive: budget exceeded.

    Returns
    -------
    DerivationResult
        One :class:`StepResult` per step and the derivation's :class:`ProofVerdict`:
        verified only when every step passed its exact check and the union of the
        conditions and assumptions is witnessed; refuted when a counterexample was
        confirmed exactly; inconclusive otherwise, with the reason.

    Raises
    ------
    ProofSyntaxError
        When ``d`` was not built through the API (a malformed tree, a step that does not
        start where the previous one ended, an unknown relation).

    References
    ----------
    The paper, Section 3 (Lemma 1, Theorem 1). Exact checks of polynomial identities
    modulo the side conditions' ideal: D. Cox, J. Little, D. O'Shea, *Ideals, Varieties,
    and Algorithms*, 4th ed., Springer 2015, Ch. 2.
    """
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 10 * MAX_DEPTH))  # trees are walked recursively
    try:
        return _check(d, cfg, budget, deadline)
    finally:
        sys.setrecursionlimit(limit)


def _check(d: Derivation, cfg: SearchSettings | None, budget: Budget | None,
           deadline: float | None = None) -> DerivationResult:
    cfg = cfg or SearchSettings()
    start = time.perf_counter()
    d = _snapshot(d)
    validate_derivation(d)
    steps = [bounded_step(d, i, cfg, budget, deadline) for i in range(len(d.steps))]
    problems = [step_problem(d, step) for step in d.steps]
    conditions, _ = _union(problems)
    joint = ""
    if steps and all(s.verdict == VERIFIED for s in steps):
        try:
            joint = (_joint(d, problems, cfg) if budget is None
                     else run_bounded(lambda: _joint(d, problems, cfg),
                                      _within(budget, deadline)))
        except ProofSyntaxError:
            raise
        except BudgetExceededError as exc:
            joint = f"joint satisfiability not decided: budget exceeded ({exc})"
        except Exception as exc:
            joint = f"joint satisfiability not decided: {type(exc).__name__} ({exc})"
    return DerivationResult(
        name=d.name,
        statement=d.statement,
        cite=d.cite,
        start=str(d.start),
        relation=d.conclusion_relation,
        end=str(d.current),
        steps=steps,
        seconds=time.perf_counter() - start,
        conditions=[c.label for c in conditions],
        vacuous=joint,
    )
