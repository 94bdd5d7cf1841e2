"""Run a scenario: CF4 on SO(3)^(n+2) x R^k, inputs held per loop period.

The loop period is the step (1/120 s by default, Section 4); the reference and a sampled
human command are read at the start of each step and held over it, so a switch of R_r
every 15 s falls on a step boundary. With ``adaptive=True`` the steps are chosen by error
control (:mod:`verify.sim.adaptive`) and the trajectory is still sampled every loop period.
"""

from __future__ import annotations

import numpy as np

from verify.errors import DbarUndefinedError, VerifyInputError
from verify.inputs.time_grid import step_count
from verify.sim import kernels
from verify.sim.fused import run_fixed
from verify.sim.fused import stepper as make_stepper
from verify.sim.scenario import LOOP_RATE, Scenario
from verify.sim.trajectory import Progress, Recorder, Trajectory, dbar_lost

ENGINES = ("auto", "compiled", "python")


def simulate(
    scenario: Scenario,
    seconds: float,
    h: float = 1.0 / LOOP_RATE,
    *,
    direction_every: int = 0,
    progress: Progress | None = None,
    engine: str = "auto",
    adaptive: bool = False,
    rtol: float = 1e-8,
    atol: float = 1e-10,
) -> Trajectory:
    """Integrate ``scenario`` over [0, seconds]; samples every ``h`` (rounded to divide it).

    By default the step is ``h``, the loop period (fixed-step CF4, inputs held per step).
    ``direction_every`` > 0 stores every body's direction d_i each that many samples
    (memory n * T / direction_every * 3 floats); 0 stores none.

    ``engine`` chooses how the CF4 stages are evaluated: ``"python"`` is the field of
    :class:`~verify.sim.scenario.ClosedLoop` (the definition), ``"compiled"`` the fused
    kernels of :mod:`verify.sim.kernels` (same method and stages, rounding-level
    differences; an error when the scenario has a part they do not model), ``"auto"``
    the kernels when they apply and the Python field otherwise.

    ``adaptive=True`` chooses the steps by error control instead
    (:mod:`verify.sim.adaptive`: step doubling of CF4 with tolerances ``rtol`` and
    ``atol``, steps ending exactly on reference switches and, for a human that holds
    its command, on every loop period); the samples every ``h`` then come from a dense
    output of order 5.
    """
    scenario.validate()
    if not (np.isfinite(seconds) and seconds > 0):
        raise VerifyInputError(f"the simulated time must be positive, got {seconds}")
    if not (np.isfinite(h) and h > 0):
        raise VerifyInputError(f"the step must be positive, got {h}")
    if engine not in ENGINES:
        raise VerifyInputError(f"unknown engine {engine!r}; choose from {', '.join(ENGINES)}")
    steps = step_count(seconds, h)
    dt = seconds / steps
    stepper = make_stepper(scenario, engine)
    Y, x = scenario.initial_state()
    rec = Recorder(scenario, steps, dt, x.shape[0], direction_every)
    if adaptive:
        # imported on use: a run with fixed steps never loads the error-controlled one
        from verify.sim.adaptive import integrate_adaptive

        return integrate_adaptive(stepper, rec, Y, x, seconds, rtol=rtol, atol=atol,
                                  progress=progress)

    # whole stretches of steps in one compiled call where the stepper allows it (the
    # same stages and samples as the loop below); one Python step where it does not
    chunk = steps if progress is None else max(1, steps // 200)
    k = 0
    while k < steps:
        Y, x, k_done, status = run_fixed(stepper, rec, Y, x, k, min(steps, k + chunk), dt)
        if k_done > k and progress is not None:
            progress(k_done, steps)
        k = k_done
        if status == kernels.OK or k >= steps:
            continue
        if status == kernels.DBAR_UNDEFINED:
            raise dbar_lost(k * dt, stepper._undefined())
        held = stepper.hold(k * dt, Y)
        rec.record(k, Y, x, held.R_r)
        try:
            Y, x = stepper.step(k * dt, Y, x, dt, held)
        except DbarUndefinedError as exc:
            raise dbar_lost(k * dt, exc) from None
        k += 1
        if progress is not None:
            progress(k, steps)
    rec.record(steps, Y, x, stepper.hold(steps * dt, Y).R_r)
    return rec.trajectory(Y[:scenario.n], steps=steps)
