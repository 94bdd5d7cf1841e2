"""The paper's dynamic conclusions as checks on simulated trajectories (Lemma 1, Theorem 1).

Each check runs a scenario twice, with steps h and h/2; the difference of a quantity
between the two runs, times 16/15 (Richardson, order 4), estimates the integration error
of the h-run. A check passes when its violation is at most twice that estimate plus a
rounding floor of 16 eps per step on the quantity's scale; the tolerance is therefore
derived from the integrator, not chosen per test.

The paper's assumptions are evaluated along every trajectory and returned with the
verdict; a check whose assumptions fail says so (``holds`` is None) instead of passing.

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

import numpy as np

from verify.sim.energy import Energy, energy
from verify.sim.inputs import Autonomous
from verify.sim.run import Trajectory, simulate
from verify.sim.scenario import LOOP_RATE, Scenario
from verify.so3 import E3, Array

EPS = float(np.finfo(float).eps)
SAFETY = 2.0  # multiple of the Richardson error estimate allowed
COHERENCE_MIN = 1e-3  # |sum d_i|/n below this: dbar (and A(d)) are ill-conditioned


@dataclass
class PropertyResult:
    """Outcome of one property on one scenario."""

    name: str
    holds: bool | None  # None: an assumption failed along the trajectory
    violation: float  # how far the conclusion is from failing (<= tolerance: holds)
    tolerance: float
    assumptions: dict[str, bool] = field(default_factory=dict)
    detail: str = ""

    def line(self) -> str:
        state = {True: "holds", False: "FAILS", None: "assumption failed"}[self.holds]
        failed = [k for k, ok in self.assumptions.items() if not ok]
        why = f" ({', '.join(failed)})" if failed else ""
        return (f"{self.name}: {state}{why}; violation {self.violation:.3g} vs tolerance "
                f"{self.tolerance:.3g}. {self.detail}").strip()


@dataclass
class RunPair:
    """A scenario run with steps h and h/2 (the error estimate's two runs)."""

    coarse: Trajectory
    fine: Trajectory
    _energies: dict[bool, tuple[Energy, Energy]] = field(default_factory=dict, repr=False)

    def energies(self, use_storage: bool) -> tuple[Energy, Energy]:
        """The Lyapunov terms of both runs, computed once per choice of S_h."""
        if use_storage not in self._energies:
            self._energies[use_storage] = (energy(self.coarse, use_storage),
                                           energy(self.fine, use_storage))
        return self._energies[use_storage]

    @classmethod
    def of(cls, scenario: Scenario, seconds: float, h: float = 1.0 / LOOP_RATE) -> RunPair:
        return cls(simulate(scenario, seconds, h), simulate(scenario, seconds, h / 2))

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


def _coherent(traj: Trajectory) -> bool:
    return bool(traj.weakest_coherence > COHERENCE_MIN)


def stealthiness(scenario: Scenario, seconds: float, h: float = 1.0 / LOOP_RATE
                 ) -> PropertyResult:
    """max_t |dbar_with(t) - dbar_without(t)| within the error of the two pairs of runs."""
    with_a = RunPair.of(scenario, seconds, h)
    without = RunPair.of(replace(scenario, autonomous=Autonomous()), seconds, h)
    violation = float(np.max(np.linalg.norm(with_a.coarse.dbar - without.coarse.dbar, axis=1)))
    tol = (with_a.tolerance(with_a.coarse.dbar, with_a.fine.dbar)
           + without.tolerance(without.coarse.dbar, without.fine.dbar))
    ok = {"dbar defined (|sum d_i|/n > 1e-3)": _coherent(with_a.coarse)}
    return _result("stealthiness", violation, tol, ok,
                   f"autonomous input {scenario.autonomous.name}, n = {scenario.n}")


def quasi_average_axis(pair: RunPair) -> PropertyResult:
    """max_t |R-bar(t) e3 - dbar(t)| (Section 3: R-bar e3 stays equal to dbar)."""
    c, f = pair.coarse, pair.fine
    violation = float(np.max(np.linalg.norm(c.R_bar @ E3 - c.dbar, axis=1)))
    tol = pair.tolerance(c.dbar, f.dbar) + pair.tolerance(c.R_bar @ E3, f.R_bar @ E3)
    ok = {"dbar defined (|sum d_i|/n > 1e-3)": _coherent(c)}
    return _result("R-bar e3 = dbar", violation, tol, ok)


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
    Ec, Ef = pair.energies(False)
    segs = _segments(pair.coarse)
    kept = [_while(Ec.lmin_rl > 0, s) for s in segs]
    starts = all(Ec.h[s.start] >= 0 for s in segs)
    violation = max((float(-np.min(Ec.h[k])) for k in kept if k.stop > k.start),
                    default=-np.inf)
    tol = pair.tolerance(Ec.h, Ef.h)
    ok = {"sym(R_rl) > 0 at each start": all(k.stop > k.start for k in kept),
          "tr(R-bar_r) >= 1 at each start": starts}
    return _result("Lemma 1 invariance", violation, tol, ok,
                   f"min tr(R-bar_r) - 1 = {-violation:.3g}"
                   + _prefix_note(kept, segs, pair.coarse.t))


def lyapunov_decrease(pair: RunPair, use_storage: bool = True) -> PropertyResult:
    """V' <= the bound of eq. (9) at every sample, and V non-increasing while it applies.

    The bound holds at every state; V' <= 0 needs sym(R_rl) > 0 and tr(R-bar_r) >= 1, so
    monotonicity is checked on the prefix of each segment (constant R_r) where both hold.
    With ``use_storage`` and a human carrying a KYP storage x^T P x / 2, S_h is that
    storage (passivity is then used); otherwise S_h is the running supply integral.
    """
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
    holds = None if not all(ok.values()) else bool(rise <= tol_rise and slack <= tol_slack)
    detail = (f"S_h = {'human storage' if Ec.uses_storage else 'running supply'}; "
              f"largest (V' - bound)/scale = {slack:.3g} (tolerance {tol_slack:.3g})"
              + _prefix_note(kept, segs, pair.coarse.t))
    return PropertyResult("Lyapunov decrease", holds, rise, tol_rise, ok, detail)


def lasalle_convergence(pair: RunPair, fraction: float = 0.1) -> PropertyResult:
    """|dbar(T) - d_r| <= fraction * max_t |dbar(t) - d_r| (constant reference, Theorem 1).

    Relative to the peak, not the start: a run may start at dbar = d_r with the leader
    elsewhere, so that dbar first moves away (found by the deep hypothesis profile).
    """
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
                   f"{err_c[-1]:.3g} in {c.t[-1]:.3g} s")


def _result(name: str, violation: float, tol: float, ok: dict[str, bool], detail: str = ""
            ) -> PropertyResult:
    holds = None if not all(ok.values()) else bool(violation <= tol)
    return PropertyResult(name, holds, violation, tol, ok, detail)
