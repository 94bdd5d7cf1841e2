"""Experiment data as the identification sees it: trials of sampled (e, u_h).

The protocol of Section 4 ("Human Modeling") records, per trial, the operator's input
e = the first two components of sk(R_l^T R_r)^vee and output u_h = the first two
components of omega_h^b, at the simulator's loop rate (120 Hz), while the reference d_r
is held for the trial. These classes hold validated arrays only; reading files is
:mod:`verify.inputs.experiment_log`, the protocol's preprocessing is
:mod:`verify.identify.data.protocol`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Trial:
    """One trial, uniformly sampled.

    ``t`` (N,) seconds, strictly increasing with a constant step; ``e`` and ``u`` (N, 2);
    ``reference`` (N, 3) the reference direction d_r when logged; ``valid`` (N,) a mask of
    usable samples when logged; ``start`` the time of the operator's "start" event after
    the reference change, when logged; ``end`` the time until which the last sample's
    input acts (the next sample time of the log the trial was taken from; after
    decimation later than t[-1] + step would say), None for one step after t[-1];
    ``resumed`` True when the log was paused before this trial (its first raw sample
    comes more than one step after the previous trial's last): the operator's state at
    its start is not what the previous trial left.
    """

    trial: int
    t: np.ndarray
    e: np.ndarray
    u: np.ndarray
    reference: np.ndarray | None = None
    valid: np.ndarray | None = None
    start: float | None = None
    end: float | None = None
    resumed: bool = False

    @property
    def step(self) -> float:
        """The sampling period (s)."""
        return float(self.t[1] - self.t[0])


@dataclass(frozen=True)
class ExperimentLog:
    """The trials of one or more log files, in trial order, with a common rate (Hz)."""

    trials: tuple[Trial, ...]
    rate: float
    source: str
