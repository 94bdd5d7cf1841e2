"""The paper's dynamic conclusions checked on one scenario with one pair of runs.

Every check of :mod:`verify.sim.properties` reads the same :class:`RunPair` (steps h and
h/2); stealthiness adds only the pair without the autonomous input. The pair is the
fixed-step one when h is inside CF4's stability bound for the loop
(:mod:`verify.sim.resolution`); when it is not, or when a check comes out unresolved on
it, the checks are repeated on an adaptive pair (error-controlled steps, Section 4's
loop rate kept for the held inputs), and the engine that produced the verdicts is
recorded. When neither resolves the loop, the checks are reported unresolved, never
held. Names are those of a campaign spec (:data:`verify.inputs.campaign_spec.PROPERTIES`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from verify.sim import properties as props
from verify.sim.resolution import stable_step, step_is_stable
from verify.sim.scenario import LOOP_RATE, Scenario

#: the checks by campaign name; LaSalle's convergence needs a constant reference
CHECKS: dict[str, Callable[[props.RunPair], props.PropertyResult]] = {
    "stealthiness": props.stealthiness,
    "quasi-average": props.quasi_average_axis,
    "lemma1": props.lemma1_invariance,
    "lyapunov": props.lyapunov_decrease,
    "lasalle": props.lasalle_convergence,
}


@dataclass
class CheckedRun:
    """The verdicts of one scenario and the pair they rest on (None: no engine resolved
    the loop within the step budget)."""

    pair: props.RunPair | None
    results: dict[str, props.PropertyResult | None]  # None: not applicable
    engine: str  # "fixed", "adaptive rtol=...", or "none"
    note: str = ""  # why the fixed step was not used

    @property
    def resolved(self) -> bool:
        return all(r is None or r.resolved for r in self.results.values())


def applicable(name: str, scenario: Scenario) -> bool:
    """LaSalle's convergence (Theorem 1) is stated for a constant reference only."""
    return name != "lasalle" or scenario.reference.is_constant


def _run(pair: props.RunPair, names: Sequence[str], scenario: Scenario
         ) -> dict[str, props.PropertyResult | None]:
    return {p: CHECKS[p](pair) if applicable(p, scenario) else None for p in names}


def _unresolved(names: Sequence[str], scenario: Scenario, why: str
                ) -> dict[str, props.PropertyResult | None]:
    nan = float("nan")
    return {p: props.PropertyResult(p, None, nan, nan, resolved=False, why_unresolved=why)
            if applicable(p, scenario) else None for p in names}


def check_scenario(scenario: Scenario, seconds: float, h: float = 1.0 / LOOP_RATE,
                   names: Sequence[str] = tuple(CHECKS), *,
                   rtol: float = props.ADAPTIVE_RTOL) -> CheckedRun:
    """Check ``names`` on ``scenario``: fixed step first, the adaptive engine when the
    fixed step is unstable or leaves a check unresolved (module docstring)."""
    fixed: CheckedRun | None = None
    if step_is_stable(scenario, h):
        pair = props.RunPair.of(scenario, seconds, h)
        fixed = CheckedRun(pair, _run(pair, names, scenario), pair.engine)
        if fixed.resolved:
            return fixed
        note = "the fixed step left a check unresolved"
    else:
        note = (f"step {h:.3g} s beyond CF4's stability bound {stable_step(scenario):.3g} s "
                f"for this loop (k_s = {scenario.k_s:g})")
    adaptive = props.adaptive_pair(scenario, seconds, h, rtol=rtol)
    if adaptive is None and fixed is not None:
        fixed.note = f"{note}; error-controlled steps exceed the step budget"
        return fixed
    if adaptive is None:
        why = (f"{note}; error-controlled steps would need more than "
               f"{props.ADAPTIVE_BUDGET} times the fixed steps")
        return CheckedRun(None, _unresolved(names, scenario, why), "none", note)
    return CheckedRun(adaptive, _run(adaptive, names, scenario), adaptive.engine, note)


__all__ = ["CHECKS", "CheckedRun", "applicable", "check_scenario"]
