"""The paper's dynamic conclusions as checks on simulated trajectories (Lemma 1, Theorem 1).

Each check runs a scenario twice, with steps h and h/2; the difference of a quantity
between the two runs, times 16/15 (Richardson, order 4), estimates the integration error
of the h-run. A check passes when its violation is at most twice that estimate plus a
rounding floor of 16 eps per step on the quantity's scale; the tolerance is therefore
derived from the integrator, not chosen per test.

The paper's assumptions are evaluated along every trajectory and returned with the
verdict; a check whose assumptions fail says so (``holds`` is None) instead of passing,
and records separately whether the conclusion held anyway (``conclusion``), which is
where a sweep finds the system behaving well outside the theorem's premises.

A check is *unresolved*, never held, when its run cannot support a verdict: the coarse
step is beyond CF4's stability for the loop's rates (:mod:`verify.sim.resolution`), or
the error estimate exceeds :data:`RESOLUTION` of the checked quantity's scale, so that
the tolerance would swallow any violation. An unresolved check can often be resolved
by error-controlled steps: :meth:`RunPair.of` with ``rtol`` makes the pair with the
adaptive engine (the fine run at rtol / :data:`REFINE` and half the sample spacing), and
:func:`resolved_pair` tries the fixed step first and falls back to it.

* stealthiness (Section 2, eq. (3)): dbar is the same with and without Omega~_a;
* quasi-average (Section 3): R-bar e3 = dbar;
* Lemma 1: tr(R-bar_r) >= 1 while lambda_min(R_rl + R_rl^T) > 0 (checked on that prefix);
* Theorem 1: V' below eq. (9) everywhere; V non-increasing (per segment of constant R_r)
  while the premises of V' <= 0 hold;
* LaSalle (Theorem 1), a finite-horizon proxy: |dbar - d_r| at the end is at most a
  fraction of its largest value along the run.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field, replace
from enum import StrEnum

import numpy as np

from verify.sim.energy import Energy, energy
from verify.sim.inputs import Autonomous
from verify.sim.resolution import step_is_stable
from verify.sim.run import simulate
from verify.sim.scenario import LOOP_RATE, Scenario
from verify.sim.trajectory import Trajectory
from verify.so3 import E3, Array

EPS = float(np.finfo(float).eps)
SAFETY = 2.0  # multiple of the Richardson error estimate allowed
COHERENCE_MIN = 1e-3  # |sum d_i|/n below this: dbar (and A(d)) are ill-conditioned
#: a check is resolved while its tolerance is at most this fraction of the quantity's
#: scale (1 for unit vectors and tr(R-bar_r) - 1; the range of V for the Lyapunov check)
RESOLUTION = 1e-2
#: adaptive pairs: the fine run's tolerances are the coarse run's divided by this
REFINE = 32.0
#: adaptive pairs: rtol of the coarse run, and atol = rtol * ATOL_RATIO
ADAPTIVE_RTOL, ATOL_RATIO = 1e-7, 1e-2
#: an adaptive pair is not attempted when the stable step would need more than this many
#: times the fixed run's steps (the run is then reported unresolved)
ADAPTIVE_BUDGET = 64


class Status(StrEnum):
    """A property's outcome on one run."""

    HELD = "held"
    FAILED = "failed"
    ASSUMPTION_FAILED = "assumption-failed"
    UNRESOLVED = "unresolved"


@dataclass
class PropertyResult:
    """Outcome of one property on one scenario."""

    name: str
    holds: bool | None  # None: an assumption failed, or the run did not resolve the loop
    violation: float  # how far the conclusion is from failing (<= tolerance: holds)
    tolerance: float
    assumptions: dict[str, bool] = field(default_factory=dict)
    detail: str = ""
    resolved: bool = True  # False: the integration error or step forbids any verdict
    conclusion: bool | None = None  # violation <= tolerance, assumptions aside (None: unresolved)
    why_unresolved: str = ""

    @property
    def status(self) -> Status:
        if not self.resolved:
            return Status.UNRESOLVED
        if self.holds is None:
            return Status.ASSUMPTION_FAILED
        return Status.HELD if self.holds else Status.FAILED

    def line(self) -> str:
        failed = [k for k, ok in self.assumptions.items() if not ok]
        why = f" ({', '.join(failed)})" if failed else ""
        state = {Status.HELD: "holds", Status.FAILED: "FAILS",
                 Status.ASSUMPTION_FAILED: f"assumption failed{why}",
                 Status.UNRESOLVED: f"UNRESOLVED ({self.why_unresolved})"}[self.status]
        if self.status is Status.ASSUMPTION_FAILED:
            state += ("; the conclusion held anyway" if self.conclusion
                      else "; the conclusion failed too")
        if not (np.isfinite(self.violation) or np.isfinite(self.tolerance)):
            return f"{self.name}: {state}. {self.detail}".strip()
        return (f"{self.name}: {state}; violation {self.violation:.3g} vs tolerance "
                f"{self.tolerance:.3g}. {self.detail}").strip()


@dataclass
class RunPair:
    """A scenario run with steps h and h/2 (the error estimate's two runs).

    With ``rtol`` set, both runs are adaptive (:func:`verify.sim.run.simulate` with
    ``adaptive=True``): the coarse one sampled every h at ``rtol``, the fine one every
    h/2 at ``rtol / REFINE``; their difference then estimates the coarse run's error.
    """

    coarse: Trajectory
    fine: Trajectory
    rtol: float | None = None
    stable: bool = True  # the coarse step is inside CF4's stability bound for the loop
    _energies: dict[bool, tuple[Energy, Energy]] = field(default_factory=dict, repr=False)

    def energies(self, use_storage: bool) -> tuple[Energy, Energy]:
        """The Lyapunov terms of both runs, computed once per choice of S_h."""
        if use_storage not in self._energies:
            self._energies[use_storage] = (energy(self.coarse, use_storage),
                                           energy(self.fine, use_storage))
            human, x0 = self.coarse.scenario.human, self.coarse.human_state[0]
            if human.storage(x0) is None:  # no storage: both choices are the supply
                self._energies[not use_storage] = self._energies[use_storage]
        return self._energies[use_storage]

    @classmethod
    def of(cls, scenario: Scenario, seconds: float, h: float = 1.0 / LOOP_RATE, *,
           rtol: float | None = None) -> RunPair:
        if rtol is None:
            return cls(simulate(scenario, seconds, h), simulate(scenario, seconds, h / 2),
                       stable=step_is_stable(scenario, h))
        fine_rtol = rtol / REFINE
        coarse = simulate(scenario, seconds, h, adaptive=True, rtol=rtol,
                          atol=rtol * ATOL_RATIO)
        fine = simulate(scenario, seconds, h / 2, adaptive=True, rtol=fine_rtol,
                        atol=fine_rtol * ATOL_RATIO)
        return cls(coarse, fine, rtol=rtol)

    @property
    def seconds(self) -> float:
        return float(self.coarse.t[-1])

    @property
    def engine(self) -> str:
        """How the pair was integrated: ``fixed`` or ``adaptive rtol=...``."""
        return "fixed" if self.rtol is None else f"adaptive rtol={self.rtol:g}"

    def like(self, scenario: Scenario) -> RunPair:
        """The pair of another scenario, integrated the same way (same T, h, engine)."""
        return RunPair.of(scenario, self.seconds, self.coarse.h, rtol=self.rtol)

    @property
    def finite(self) -> bool:
        """Whether both runs stayed finite (an unstable step can overflow)."""
        return all(bool(np.all(np.isfinite(a))) for t in (self.coarse, self.fine)
                   for a in (t.R_bar, t.R_l, t.x))

    def unresolved(self, tolerance: float, scale: float) -> str:
        """Why a check with this tolerance on a quantity of this scale cannot decide
        (empty when it can)."""
        if not self.stable:
            return (f"step {self.coarse.h:.3g} s beyond CF4's stability for k_s = "
                    f"{self.coarse.scenario.k_s:g}")
        if not tolerance <= RESOLUTION * scale:  # NaN is unresolved too
            return (f"integration error estimate {tolerance:.3g} above {RESOLUTION:g} of "
                    f"the quantity's scale {scale:.3g}")
        return ""

    def error(self, coarse: Array, fine: Array) -> Array:
        """Per-sample error estimate of a quantity of the coarse run (leading axis time)."""
        diff = np.abs(np.asarray(coarse) - np.asarray(fine)[::2])
        diff = diff.reshape(diff.shape[0], -1).max(axis=1)
        return diff * 16.0 / 15.0

    def floor(self, scale: float) -> float:
        return 16.0 * EPS * self.fine.t.shape[0] * max(1.0, scale)

    def tolerance(self, coarse: Array, fine: Array) -> float:
        scale = float(np.max(np.abs(coarse)))
        return SAFETY * float(self.error(coarse, fine).max()) + self.floor(scale)


def _overflowed(name: str, pair: RunPair) -> PropertyResult | None:
    """An unresolved result when a run of the pair left the finite numbers."""
    if pair.finite:
        return None
    nan = float("nan")
    return PropertyResult(name, None, nan, nan, resolved=False,
                          why_unresolved="a run of the pair overflowed (non-finite state)")


def _coherent(traj: Trajectory) -> bool:
    return bool(traj.weakest_coherence > COHERENCE_MIN)


def stealthiness(scenario: Scenario | RunPair, seconds: float | None = None,
                 h: float = 1.0 / LOOP_RATE) -> PropertyResult:
    """max_t |dbar_with(t) - dbar_without(t)| within the error of the two pairs of runs.

    Given the scenario's :class:`RunPair` (the run every other check uses), only the pair
    without the autonomous input is simulated, the same way; with no autonomous input
    the two pairs are one and nothing more is simulated.
    """
    if isinstance(scenario, RunPair):
        with_a = scenario
        scenario = with_a.coarse.scenario
    else:
        if seconds is None:
            raise TypeError("stealthiness(scenario, seconds, h) needs the run length")
        with_a = RunPair.of(scenario, seconds, h)
    if (bad := _overflowed("stealthiness", with_a)) is not None:
        return bad
    plain = type(scenario.autonomous) is Autonomous
    without = with_a if plain else with_a.like(replace(scenario, autonomous=Autonomous()))
    violation = float(np.max(np.linalg.norm(with_a.coarse.dbar - without.coarse.dbar, axis=1)))
    tol = (with_a.tolerance(with_a.coarse.dbar, with_a.fine.dbar)
           + without.tolerance(without.coarse.dbar, without.fine.dbar))
    ok = {"dbar defined (|sum d_i|/n > 1e-3)": _coherent(with_a.coarse)}
    why = with_a.unresolved(tol, 1.0) or (without.unresolved(tol, 1.0) if not plain else "")
    return _result("stealthiness", violation, tol, ok,
                   f"autonomous input {scenario.autonomous.name}, n = {scenario.n}", why)


def quasi_average_axis(pair: RunPair) -> PropertyResult:
    """max_t |R-bar(t) e3 - dbar(t)| (Section 3: R-bar e3 stays equal to dbar)."""
    if (bad := _overflowed("R-bar e3 = dbar", pair)) is not None:
        return bad
    c, f = pair.coarse, pair.fine
    violation = float(np.max(np.linalg.norm(c.R_bar @ E3 - c.dbar, axis=1)))
    tol = pair.tolerance(c.dbar, f.dbar) + pair.tolerance(c.R_bar @ E3, f.R_bar @ E3)
    ok = {"dbar defined (|sum d_i|/n > 1e-3)": _coherent(c)}
    return _result("R-bar e3 = dbar", violation, tol, ok, "", pair.unresolved(tol, 1.0))


def _segments(traj: Trajectory) -> list[slice]:
    """Index ranges of constant reference (the energy functions jump at a switch)."""
    switches = [round(ts / traj.h) for ts in traj.scenario.reference.switch_times(
        float(traj.t[-1]))]
    bounds = [0, *switches, traj.t.shape[0]]
    return [slice(a, b) for a, b in itertools.pairwise(bounds)]


def largest_rise(v: Array) -> float:
    """max over k of v_k - min_{j<k} v_j: how far a series climbs above an earlier value."""
    if v.shape[0] < 2:
        return 0.0
    return float(np.max(v[1:] - np.minimum.accumulate(v)[:-1]))


def _while(condition: Array, seg: slice) -> slice:
    """The longest prefix of ``seg`` on which ``condition`` holds at every sample."""
    bad = np.flatnonzero(~condition[seg])
    return slice(seg.start, seg.start + (int(bad[0]) if bad.size else seg.stop - seg.start))


def _prefix_note(kept: list[slice], segs: list[slice], t: Array) -> str:
    cut = [k for k, s in zip(kept, segs, strict=True) if k.stop < s.stop]
    return "" if not cut else f" (premise lost at t = {t[cut[0].stop]:.3g} s; checked before)"


def lemma1_invariance(pair: RunPair) -> PropertyResult:
    """tr(R-bar_r) >= 1 while sym(R_rl) > 0, on each segment that starts with it (Lemma 1).

    The samples after the first loss of sym(R_rl) > 0 in a segment are not checked: the
    lemma says nothing about them.
    """
    if (bad := _overflowed("Lemma 1 invariance", pair)) is not None:
        return bad
    Ec, Ef = pair.energies(False)
    segs = _segments(pair.coarse)
    kept = [_while(Ec.lmin_rl > 0, s) for s in segs]
    starts = all(Ec.h[s.start] >= 0 for s in segs)
    violation = max((float(-np.min(Ec.h[k])) for k in kept if k.stop > k.start),
                    default=-np.inf)
    tol = pair.tolerance(Ec.h, Ef.h)
    ok = {"sym(R_rl) > 0 at each start": all(k.stop > k.start for k in kept),
          "tr(R-bar_r) >= 1 at each start": starts}
    if not all(ok.values()):  # the conclusion on the whole run, for the map of findings
        violation = float(-np.min(Ec.h))
    return _result("Lemma 1 invariance", violation, tol, ok,
                   f"min tr(R-bar_r) - 1 = {-violation:.3g}"
                   + _prefix_note(kept, segs, pair.coarse.t), pair.unresolved(tol, 1.0))


def lyapunov_decrease(pair: RunPair, use_storage: bool = True) -> PropertyResult:
    """V' <= the bound of eq. (9) at every sample, and V non-increasing while it applies.

    The bound holds at every state; V' <= 0 needs sym(R_rl) > 0 and tr(R-bar_r) >= 1, so
    monotonicity is checked on the prefix of each segment (constant R_r) where both hold.
    With ``use_storage`` and a human carrying a KYP storage x^T P x / 2, S_h is that
    storage (passivity is then used); otherwise S_h is the running supply integral.
    """
    if (bad := _overflowed("Lyapunov decrease", pair)) is not None:
        return bad
    Ec, Ef = pair.energies(use_storage)
    V_c, V_f = Ec.V, Ef.V
    segs = _segments(pair.coarse)
    tol_rise = pair.tolerance(V_c, V_f)
    premise = (Ec.lmin_rl > 0) & (Ec.h >= -pair.tolerance(Ec.h, Ef.h))
    kept = [_while(premise, s) for s in segs]
    rise = max([0.0, *(largest_rise(V_c[k]) for k in kept)])
    # V' and its bound come from the vector field at the same state: only rounding apart
    scale = np.abs(Ec.V_dot) + np.abs(Ec.V_dot_bound) + pair.coarse.scenario.k_s
    slack = float(np.max((Ec.V_dot - Ec.V_dot_bound) / scale))
    tol_slack = 1e3 * EPS
    ok = {"sym(R_rl) > 0 and sym(R-bar_r) >= 0 at each start":
          all(k.stop > k.start for k in kept)}
    if use_storage:
        ok["human has a storage function (KYP certificate)"] = Ec.uses_storage
    # the rise is judged on the premise's prefix; the conclusion without the premise
    # (for a map of where V decreased anyway) on whole segments
    judged = kept if all(ok.values()) else segs
    rise_all = max([0.0, *(largest_rise(V_c[s]) for s in judged)])
    conclusion = bool(rise_all <= tol_rise and slack <= tol_slack)
    why = pair.unresolved(tol_rise, max(1.0, float(np.ptp(V_c))))
    detail = (f"S_h = {'human storage' if Ec.uses_storage else 'running supply'}; "
              f"largest (V' - bound)/scale = {slack:.3g} (tolerance {tol_slack:.3g})"
              + _prefix_note(kept, segs, pair.coarse.t))
    return _result("Lyapunov decrease", rise if all(ok.values()) else rise_all, tol_rise, ok,
                   detail, why, conclusion=conclusion)


def lasalle_convergence(pair: RunPair, fraction: float = 0.1) -> PropertyResult:
    """|dbar(T) - d_r| <= fraction * max_t |dbar(t) - d_r| (constant reference, Theorem 1).

    Relative to the peak, not the start: a run may start at dbar = d_r with the leader
    elsewhere, so that dbar first moves away (found by the deep hypothesis profile).
    """
    if (bad := _overflowed("LaSalle convergence", pair)) is not None:
        return bad
    c, f = pair.coarse, pair.fine
    d_r = c.R_r[:, :, 2]
    err_c = np.linalg.norm(c.dbar - d_r, axis=1)
    err_f = np.linalg.norm(f.dbar - f.R_r[:, :, 2], axis=1)
    target = fraction * float(np.max(err_c))
    violation = float(err_c[-1] - target)
    tol = pair.tolerance(err_c, err_f)
    Ec, _ = pair.energies(True)
    ok = {
        "R_r constant": c.scenario.reference.is_constant,
        "sym(R_rl) > 0 along the trajectory": bool(np.min(Ec.lmin_rl) > 0),
        "human has a storage function (KYP certificate)": Ec.uses_storage,
        "dbar defined (|sum d_i|/n > 1e-3)": _coherent(c),
    }
    return _result(f"LaSalle convergence (finite-horizon proxy: to {fraction:g} of its peak "
                   f"by T)", violation, tol, ok,
                   f"|dbar - d_r| from {err_c[0]:.3g} (peak {np.max(err_c):.3g}) to "
                   f"{err_c[-1]:.3g} in {c.t[-1]:.3g} s", pair.unresolved(tol, 1.0))


def _result(name: str, violation: float, tol: float, ok: dict[str, bool], detail: str = "",
            why_unresolved: str = "", *, conclusion: bool | None = None) -> PropertyResult:
    """The result: unresolved when ``why_unresolved`` says so (never held), else the
    conclusion (violation within tolerance) when every assumption held."""
    if why_unresolved:
        return PropertyResult(name, None, violation, tol, ok, detail, resolved=False,
                              conclusion=None, why_unresolved=why_unresolved)
    if conclusion is None:
        conclusion = bool(violation <= tol)
    holds = conclusion if all(ok.values()) else None
    return PropertyResult(name, holds, violation, tol, ok, detail, conclusion=conclusion)


def resolved_pair(scenario: Scenario, seconds: float, h: float = 1.0 / LOOP_RATE, *,
                  rtol: float = ADAPTIVE_RTOL) -> RunPair | None:
    """The fixed-step pair when h is stable for this loop, else an adaptive pair, or None
    when even that would exceed :data:`ADAPTIVE_BUDGET` times the fixed run's steps.

    Callers check the properties on the pair and, when a check comes out unresolved on
    the fixed pair, may call :func:`adaptive_pair` for a second try.
    """
    if step_is_stable(scenario, h):
        return RunPair.of(scenario, seconds, h)
    return adaptive_pair(scenario, seconds, h, rtol=rtol)


def adaptive_pair(scenario: Scenario, seconds: float, h: float = 1.0 / LOOP_RATE, *,
                  rtol: float = ADAPTIVE_RTOL) -> RunPair | None:
    """An adaptive pair, or None when its stable step would exceed the step budget
    (:data:`ADAPTIVE_BUDGET` times the fixed run's steps) or its step control fails."""
    from verify.sim.resolution import stable_step

    if h / stable_step(scenario) > ADAPTIVE_BUDGET:
        return None
    try:
        return RunPair.of(scenario, seconds, h, rtol=rtol)
    except RuntimeError:  # the step size control gave up (a stiff or singular stretch)
        return None
