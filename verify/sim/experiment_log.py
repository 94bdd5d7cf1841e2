"""A simulated run as the trials of an experiment log (Section 4, "Human Modeling").

The paper's experiment logs, per trial (one reference segment), the operator's input
e = the first two components of sk(R_l^T R_r)^vee and output u_h = the first two
components of omega_h^b at the loop rate. :func:`trajectory_trials` reads those signals
off a simulator :class:`verify.sim.run.Trajectory`, as the human saw and produced them,
into :class:`verify.inputs.experiment.Trial` records: what ``verify simulate --log``
writes and what the simulated identification experiments start from.
"""

from __future__ import annotations

import numpy as np

from verify.errors import VerifyInputError
from verify.inputs.experiment import Trial
from verify.sim.trajectory import Trajectory
from verify.so3 import vee

__all__ = ["trajectory_trials"]


def trajectory_trials(traj: Trajectory, *, until: float | None = None) -> tuple[Trial, ...]:
    """The trials of a run: one per reference segment, with the signals the human saw.

    Sample k (time t_k, the start of loop period k) carries e_k = the first two
    components of vee(sk(R_l(t_k)^T R_r(t_k))), with R_r the reference held over the
    period (as :class:`verify.sim.scenario.ClosedLoop` computes it), and u_k = the first
    two components of omega_h^b, recomputed from the recorded human state x_k through
    the human's own ``hold`` and ``command`` (the value the simulator used at the first
    stage of that period). A trial is a maximal run of samples in one reference segment
    (:meth:`verify.sim.inputs.Reference.segment`); ``reference`` is d_r = R_r e3. When
    the human is a :class:`verify.sim.noisy_humans.ReactingNoisyHuman`, ``start`` is the
    time of the first sample after its reaction time. Samples at t >= ``until`` are left out.
    """
    scenario = traj.scenario
    human = scenario.human
    t = traj.t
    keep = np.ones(t.shape[0], bool) if until is None else t < until - 1e-9 * max(1.0, until)
    idx = np.flatnonzero(keep)
    if idx.size == 0:
        raise VerifyInputError(f"no samples before t = {until} s")
    m = human.state_size
    e3 = np.empty((idx.size, 3))
    u3 = np.empty_like(e3)
    for row, k in enumerate(idx):  # as ClosedLoop.signals computes them, bit for bit
        e3[row] = vee(traj.R_l[k].T @ traj.R_r[k])  # sk(R_l^T R_r)^vee
        held = human.hold(float(t[k]), traj.R_l[k], traj.R_r[k])
        u3[row] = human.command(float(t[k]), traj.x[k, :m], e3[row], traj.R_l[k], held)
    segments = np.array([scenario.reference.segment(float(t[k])) for k in idx])
    d_r = traj.R_r[idx][:, :, 2]
    reacting = getattr(human, "reacting", None)
    trials = []
    for seg in np.unique(segments):
        rows = np.flatnonzero(segments == seg)
        start = None
        if reacting is not None:
            ready = [r for r in rows if not reacting(float(t[idx[r]]))]
            start = float(t[idx[ready[0]]]) if ready else None
        trials.append(Trial(int(seg), t[idx[rows]].copy(), e3[rows, :2].copy(),
                            u3[rows, :2].copy(), reference=d_r[rows].copy(), start=start))
    return tuple(trials)
