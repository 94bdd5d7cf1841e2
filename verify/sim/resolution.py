"""Whether a fixed-step run can resolve the closed loop of Sections 2-3 at all.

The CF4 method reduces to the classical RK4 on a linear constant-coefficient problem, so
a step h is stable only while h |lambda| stays inside RK4's stability interval on the
negative real axis, |lambda h| <= 2.785, for the fastest rate lambda of the linearised
loop. Near synchronisation the relative attitude R-bar^T R_l of eqs. (6a)-(6b) decays at
rate 2 k_s (R-bar and R_l each turn towards the other at k_s); the consensus input of
Section 2 adds at most 4 times its gain on a ring, and an LTI human adds the rates of its
state matrix and of its feedthrough. :func:`stiffness` bounds their sum from above
(spectral norms), so :func:`step_is_stable` errs on the side of calling a step unstable.

A run beyond the bound is not an approximation of the paper's loop: its samples may
stay bounded (rotations cannot blow up) and even agree between the h and h/2 runs by
chance, so the property checks call such a run *unresolved* whatever its error estimate.
"""

from __future__ import annotations

import numpy as np

from verify.sim.humans import LTIHuman, StaticGainHuman
from verify.sim.inputs import Synchronisation
from verify.sim.scenario import Scenario

#: RK4's stability interval on the negative real axis: |lambda h| <= 2.7853
RK4_REAL_STABILITY = 2.785


def _norm(M: object) -> float:
    A = np.atleast_2d(np.asarray(M, dtype=float))
    return float(np.linalg.norm(A, 2)) if A.size else 0.0


def stiffness(scenario: Scenario) -> float:
    """An upper estimate (1/s) of the fastest decay rate of the linearised closed loop."""
    rate = 2.0 * float(scenario.k_s)
    auto = scenario.autonomous
    if isinstance(auto, Synchronisation):
        rate += 4.0 * abs(float(auto.gain))
    human = scenario.human
    if isinstance(human, LTIHuman):
        rate += _norm(human.A) + _norm(human.D) + np.sqrt(_norm(human.B) * _norm(human.C))
    elif isinstance(human, StaticGainHuman):
        rate += _norm(human.K)
    return float(rate)


def step_is_stable(scenario: Scenario, h: float) -> bool:
    """Whether the fixed step ``h`` lies inside CF4's stability bound for this loop."""
    return bool(stiffness(scenario) * float(h) <= RK4_REAL_STABILITY)


def stable_step(scenario: Scenario) -> float:
    """The largest fixed step inside the stability bound (s)."""
    return RK4_REAL_STABILITY / stiffness(scenario)


__all__ = ["RK4_REAL_STABILITY", "stable_step", "step_is_stable", "stiffness"]
