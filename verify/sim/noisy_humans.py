"""A known LTI operator with operator noise and a reaction time, for identification data.

Section 4 ("Human Modeling") identifies H(s) from a human-in-the-loop experiment: the
reference d_r changes every 15 s, the operator needs a moment to notice the change (a
cognitive dead time, ended by pressing a start button), and the operator's command is
not a noiseless function of what they see. :class:`ReactingNoisyHuman` reproduces these
features around a known model, so that an estimator can be checked against ground truth:

* between reactions it is the LTI model x' = A x + B e, u = C x + D e plus the operator
  noise v: u_h = C x + D e + v, where v is seeded white noise held over each loop period
  (it enters the loop through the leader, eq. (6b), so e depends on past v: the data are
  closed loop, as in the paper's experiment);
* for ``reaction[j]`` loop periods after the start of reference segment j the operator
  has not yet reacted: the model's input is zero (the state relaxes as x' = A x) and its
  output is C x + v; the first period after that is the "start" event of the segment.

Everything the human does in a loop period is a function of the period's index
k = round(t / h), so the run is reproducible and the command at any recorded sample can
be recomputed from a :class:`verify.sim.trajectory.Trajectory` (as
:func:`verify.sim.experiment_log.trajectory_trials` does).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from verify.errors import VerifyInputError
from verify.sim.humans import LTIHuman
from verify.sim.inputs import Reference
from verify.so3 import Array


@dataclass
class ReactingNoisyHuman(LTIHuman):
    """:class:`verify.sim.humans.LTIHuman` with held operator noise and reaction times.

    ``noise`` (K, ports) is the operator noise of loop periods 0..K-1 (period k covers
    [k h, (k + 1) h)); ``reaction`` holds, per reference segment, the number of loop
    periods before the operator reacts; ``reference`` the switching reference whose
    segments these are; ``h`` the loop period (s).

    The held value of a period is ``[v_1, ..., v_ports, reacting]``; :meth:`hold` also
    keeps it on the instance, because the state equation of a loop period needs to know
    whether the operator reacts (the simulator calls ``hold`` once at the start of each
    period, before the stages of that period, see :class:`verify.sim.humans.Human`).
    """

    noise: Array = field(default_factory=lambda: np.zeros((0, 2)))
    reaction: Sequence[int] = ()
    reference: Reference | None = None
    h: float = 1.0 / 120.0

    def __post_init__(self) -> None:
        super().__post_init__()
        self.noise = np.asarray(self.noise, dtype=float)
        if self.noise.ndim != 2 or self.noise.shape[1] != self.ports:
            raise VerifyInputError(f"the operator noise must have shape (K, {self.ports}), got "
                                   f"{self.noise.shape}")
        if not np.all(np.isfinite(self.noise)):
            raise VerifyInputError("the operator noise has non-finite entries")
        self.reaction = tuple(int(r) for r in self.reaction)
        if any(r < 0 for r in self.reaction):
            raise VerifyInputError(f"reaction times must be >= 0 periods, got {self.reaction}")
        if not (np.isfinite(self.h) and self.h > 0):
            raise VerifyInputError(f"the loop period must be positive, got {self.h}")
        self._held = np.zeros(self.ports + 1)

    @classmethod
    def of(cls, model, *, noise: Array, reaction: Sequence[int], reference: Reference,
           h: float) -> ReactingNoisyHuman:
        """From a :class:`verify.passivity.model.LTIModel` (its float view)."""
        return cls(model.A, model.B, model.C, model.D, name=model.name, noise=noise,
                   reaction=reaction, reference=reference, h=h)

    def period(self, t: float) -> int:
        """The loop period that starts at (or contains) time t."""
        return int(np.floor(t / self.h + 1e-6))

    def reacting(self, t: float) -> bool:
        """Whether at time t the operator has not yet reacted to the current reference."""
        if self.reference is None or not self.reaction:
            return False
        segment = self.reference.segment(t)
        if segment >= len(self.reaction):
            return False
        start = 0.0 if self.reference.period is None else segment * self.reference.period
        return self.period(t) - self.period(start) < self.reaction[segment]

    def hold(self, t: float, R_l: Array, R_r: Array) -> Array:
        k = self.period(t)
        if k >= self.noise.shape[0]:
            raise VerifyInputError(f"the operator noise covers {self.noise.shape[0]} loop "
                                   f"periods, the run asks for period {k} (t = {t:.4g} s)")
        held = np.empty(self.ports + 1)
        held[: self.ports] = self.noise[k]
        held[self.ports] = 1.0 if self.reacting(t) else 0.0
        self._held = held
        return held

    def command(self, t: float, x: Array, e: Array, R_l: Array, held: Array | None
                ) -> Array:
        k = self.ports
        held = self._held if held is None else held
        u = self.C @ x + held[:k]
        if not held[k]:
            u = u + self.D @ e[:k]
        out = np.zeros(3)
        out[:k] = u
        return out

    def state_rate(self, x: Array, e: Array) -> Array:
        if self._held[self.ports]:
            return self.A @ x
        return self.A @ x + self.B @ e[: self.ports]
