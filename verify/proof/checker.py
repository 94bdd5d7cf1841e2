"""Decide every step of a derivation: exact check first, falsification beside it.

Verdict of a step:

- ``verified``: the exact check passed (lhs - rhs, or lhs - rhs minus the certificate's
  non-negative terms, is the zero rational function, or lies in the ideal of the side
  conditions) and every exact premise of the terms passed; the falsifiers found nothing.
- ``refuted``: a counterexample was confirmed exactly (:mod:`verify.proof.confirm`).
- ``inconclusive``: anything else, including a step the exact check cannot decide
  (a citation, a premise that fails, a certificate that does not match) when no exact
  counterexample was found. A numerical violation that exact arithmetic cannot confirm
  is reported but does not refute.

A derivation is verified when every step is; refuted when some step is.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

from verify.proof.confirm import confirm
from verify.proof.derivation import Derivation, Step
from verify.proof.falsify import SearchSettings, search
from verify.proof.justify import KERNEL, ByAlgebra, ByBound, ByCitation
from verify.proof.problem import StepProblem
from verify.proof.sos_step import BySos
from verify.proof.sos_step import exact_check as sos_exact_check

VERIFIED, REFUTED, INCONCLUSIVE = "verified", "refuted", "inconclusive"


@dataclass
class StepResult:
    index: int
    relation: str
    lhs: str
    rhs: str
    justification: str
    verdict: str
    exact: str  # what the exact check established, or why it could not
    conditions: list[str] = field(default_factory=list)
    assumptions: list[str] = field(default_factory=list)
    kernel: list[str] = field(default_factory=list)
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

    @property
    def verdict(self) -> str:
        verdicts = {s.verdict for s in self.steps}
        if REFUTED in verdicts:
            return REFUTED
        if verdicts <= {VERIFIED}:
            return VERIFIED
        return INCONCLUSIVE

    @property
    def assumptions(self) -> list[str]:
        out: list[str] = []
        for s in self.steps:
            out += [a for a in s.assumptions if a not in out]
        return out

    def to_json(self) -> dict:
        return {
            "name": self.name,
            "statement": self.statement,
            "cite": self.cite,
            "start": self.start,
            "conclusion": f"{self.start} {self.relation} {self.end}",
            "verdict": self.verdict,
            "assumptions": self.assumptions,
            "seconds": round(self.seconds, 3),
            "steps": [s.to_json() for s in self.steps],
        }


def _problem(d: Derivation, step: Step) -> StepProblem:
    conditions = tuple(d.where) + tuple(step.where)
    because = step.because
    extra: tuple = ()
    assumptions = list(d.assumes)
    if isinstance(because, ByBound):
        for t in because.terms:
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


def check_step(d: Derivation, index: int, cfg: SearchSettings) -> StepResult:
    step = d.steps[index]
    start = time.perf_counter()
    problem = _problem(d, step)
    ok, exact_text = _exact_check(step, problem)
    settings = SearchSettings(cfg.samples, cfg.hypothesis_examples, cfg.ipopt_starts,
                              cfg.seed + 7919 * index)
    report, counterexample = search(problem, settings, confirm)
    if counterexample is not None:
        verdict = REFUTED
        if ok:  # an exact proof and an exact counterexample cannot both stand
            exact_text += "; INTERNAL DISAGREEMENT with an exact counterexample"
            verdict = INCONCLUSIVE
    elif ok and not report.candidates:
        verdict = VERIFIED
    else:
        verdict = INCONCLUSIVE
        if ok:
            exact_text += "; but a numerical violation was seen (not confirmed exactly)"
    kernel: list[str] = []
    if isinstance(step.because, ByBound):
        for t in step.because.terms:
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
        counterexample=None if counterexample is None else counterexample.to_json(),
        unconfirmed_violation=bool(report.candidates) and counterexample is None,
        falsification=report.to_json(),
        note=step.note,
        seconds=time.perf_counter() - start,
    )


def check(d: Derivation, cfg: SearchSettings | None = None) -> DerivationResult:
    """Check every step of ``d``."""
    cfg = cfg or SearchSettings()
    start = time.perf_counter()
    steps = [check_step(d, i, cfg) for i in range(len(d.steps))]
    return DerivationResult(
        name=d.name,
        statement=d.statement,
        cite=d.cite,
        start=str(d.start),
        relation=d.conclusion_relation,
        end=str(d.current),
        steps=steps,
        seconds=time.perf_counter() - start,
    )
