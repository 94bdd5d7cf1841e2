"""The compiled step of a scenario, when its parts are ones the kernels know.

:func:`stepper` returns the held values and the CF4 step of one loop period, either
through the Python field of :class:`verify.sim.scenario.ClosedLoop` (the definition) or
through the compiled field of :mod:`verify.sim.kernels`. The compiled one is used only for
parts the kernels model; a human class or an autonomous input defined elsewhere, or a
closed-loop law replaced at run time (as mutation tests do), gets the Python field.

Supported: humans :class:`LTIHuman`, :class:`StaticGainHuman`, :class:`VROperator`,
:class:`SignalHuman` (exact types), and with ``engine="compiled"`` only,
:class:`ReactingNoisyHuman` (its held noise added to the output, B e and D e left out
before the operator reacts); autonomous inputs zero, :class:`Synchronisation`
and :class:`SignalInput` (a function of time only, e.g. :class:`SmoothRandom`).
"""

from __future__ import annotations

import numpy as np

import verify.sim.scenario as scenario_module
from verify.errors import DbarUndefinedError, VerifyInputError
from verify.sim import kernels
from verify.sim.humans import Human, LTIHuman, SignalHuman, StaticGainHuman, VROperator
from verify.sim.inputs import Autonomous, SignalInput, Synchronisation
from verify.sim.lie_group import cf4_mixed_step
from verify.sim.noisy_humans import ReactingNoisyHuman
from verify.sim.scenario import ClosedLoop, Held, Scenario
from verify.so3 import Array
from verify.system import laws, stealthy

_EMPTY2 = np.zeros((0, 0))


def laws_unmodified() -> bool:
    """True while ClosedLoop evaluates the paper's laws (nothing patched at run time)."""
    cl = ClosedLoop
    return (scenario_module.stealthy_input is stealthy.stealthy_input
            and scenario_module.interface_velocity is laws.interface_velocity
            and scenario_module.leader_velocity is laws.leader_velocity
            and all(getattr(cl, name).__qualname__ == f"ClosedLoop.{name}"
                    and getattr(cl, name).__module__ == scenario_module.__name__
                    for name in ("field", "signals", "leader_velocity", "hold")))


def human_form(human: Human) -> tuple[Array, Array, Array, Array, str] | None:
    """(A, B, C, D, command kind) of omega_h^b = pad(C x + D e[:k]) + R_l^T c_s."""
    t = type(human)
    if t is LTIHuman:
        return human.A, human.B, human.C, human.D, "none"
    if t is StaticGainHuman:
        k = human.K.shape[0]
        return _EMPTY2, np.zeros((0, k)), np.zeros((k, 0)), human.K, "none"
    if t is VROperator:
        return _EMPTY2, _EMPTY2, _EMPTY2, _EMPTY2, "held"
    if t is SignalHuman:
        return _EMPTY2, _EMPTY2, _EMPTY2, _EMPTY2, "signal"
    if t is ReactingNoisyHuman:
        return human.A, human.B, human.C, human.D, "noisy"
    return None


def _autonomous_form(a: Autonomous) -> tuple[int, float] | None:
    t = type(a)
    if t is Autonomous:
        return kernels.AUTO_ZERO, 0.0
    if t is Synchronisation:
        return kernels.AUTO_CONSENSUS, float(a.gain)
    if isinstance(a, SignalInput) and t.__call__ is SignalInput.__call__:
        return kernels.AUTO_GIVEN, 0.0
    return None


def _c(M: Array) -> Array:
    return np.ascontiguousarray(M, dtype=float)


class Stepper:
    """One loop period of a scenario: its held values and one CF4 step over it."""

    def __init__(self, loop: ClosedLoop) -> None:
        self.loop = loop

    def hold(self, t: float, Y: Array) -> Held:
        """The reference and the human's held command for the period starting at t."""
        return self.loop.hold(t, Y)

    @property
    def holds_commands(self) -> bool:
        """Whether the human samples and holds its command each loop period."""
        return type(self.loop.s.human).hold is not Human.hold

    def step(self, t: float, Y: Array, x: Array, h: float, held: Held) -> tuple[Array, Array]:
        """(Y, x) after one CF4 step of ``ClosedLoop.field`` (the definition)."""
        return cf4_mixed_step(self.loop.field(held), t, Y, x, h)

    def field(self, t: float, Y: Array, x: Array, held: Held) -> tuple[Array, Array]:
        """(F, g) of the closed loop at one state."""
        return self.loop.field(held)(t, Y, x)


class CompiledStepper(Stepper):
    """The same step through :func:`verify.sim.kernels.cf4_step` (see the module)."""

    def __init__(self, loop: ClosedLoop, h_form: tuple, auto_form: tuple[int, float]
                 ) -> None:
        super().__init__(loop)
        s = loop.s
        self.hA, self.hB, self.hC, self.hD = (_c(M) for M in h_form[:4])
        self.command = h_form[4]
        self.auto, self.gain = auto_form
        self.n, self.k_s = s.n, float(s.k_s)
        self.human, self.autonomous, self.reference = s.human, s.autonomous, s.reference
        self.tol = float(stealthy.DBAR_RELATIVE_TOLERANCE)
        self.no_input = np.zeros((4, 0, 3))
        self.zero_command = np.zeros((4, 3))
        self.rotations = [_c(R) for R in s.reference.rotations]
        self.workspace = kernels.workspace(s.n, s.human.state_size + 1)
        self.no_add = np.zeros(0)
        self.zero_B, self.zero_D = np.zeros_like(self.hB), np.zeros_like(self.hD)

    def _human_terms(self, held: Held) -> tuple[Array, Array, Array]:
        """(B, D, added output) of the period: the noisy operator's held noise, and no
        B e or D e while it has not reacted (:class:`ReactingNoisyHuman`)."""
        if self.command != "noisy":
            return self.hB, self.hD, self.no_add
        k = self.hD.shape[0]
        u_add = np.ascontiguousarray(held.human[:k], dtype=float)
        if held.human[k]:
            return self.zero_B, self.zero_D, u_add
        return self.hB, self.hD, u_add

    def hold(self, t: float, Y: Array) -> Held:
        R_r = self.rotations[self.reference.segment(t)]
        if self.command != "held":
            return Held(R_r, self.human.hold(t, Y[self.n + 1], R_r))
        h = self.human
        out = np.empty(3)
        if kernels.vr_command(Y[self.n + 1], R_r, float(h.k_omega), float(h.saturation),
                              float(h.tilt), out):
            return Held(R_r, out)
        return Held(R_r, h.hold(t, Y[self.n + 1], R_r))

    def _inputs(self, times: tuple[float, ...], held: Held) -> tuple[Array, Array]:
        """The human's spatial command and the given autonomous input at stage times."""
        c_stage = self.zero_command
        if self.command == "held":
            c_stage = np.empty((4, 3))
            c_stage[:] = held.human
        elif self.command == "signal":
            c_stage = np.empty((4, 3))
            for j, s in enumerate(times):
                c_stage[j + (j > 1)] = self.human.signal(s)
            c_stage[2] = c_stage[1]
        Oa = self.no_input
        if self.auto == kernels.AUTO_GIVEN:
            Oa = np.empty((4, self.n, 3))
            for j, s in enumerate(times):
                Oa[j + (j > 1)] = self.autonomous(s, None)
            Oa[2] = Oa[1]
        return c_stage, Oa

    def _undefined(self) -> DbarUndefinedError:
        return DbarUndefinedError(
            f"dbar is undefined: |sum d_i| <= {self.tol:g} * n (n = {self.n}); the bodies' "
            "directions cancel out")

    def field(self, t: float, Y: Array, x: Array, held: Held) -> tuple[Array, Array]:
        c_stage, Oa = self._inputs((t,), held)
        F, g = np.empty((Y.shape[0], 3)), np.empty(x.shape[0])
        Om, work = self.workspace[3], self.workspace[4]
        B, D, u_add = self._human_terms(held)
        if kernels.closed_loop_field(Y, x, self.k_s, held.R_r, c_stage[0], self.hA, B,
                                     self.hC, D, self.auto, self.gain, Oa[0], self.tol,
                                     F, g, Om, work, u_add) != kernels.OK:
            raise self._undefined()
        return F, g

    def step(self, t: float, Y: Array, x: Array, h: float, held: Held) -> tuple[Array, Array]:
        c_stage, Oa = self._inputs((t, t + 0.5 * h, t + h), held)
        Y_out, x_out = np.empty_like(Y), np.empty_like(x)
        B, D, u_add = self._human_terms(held)
        status = kernels.cf4_step(Y, x, h, self.k_s, held.R_r, c_stage, self.hA, B,
                                  self.hC, D, self.auto, self.gain, Oa, self.tol,
                                  Y_out, x_out, *self.workspace, u_add)
        if status != kernels.OK:
            raise self._undefined()
        return Y_out, x_out


def run_fixed(stepper: Stepper, rec, Y: Array, x: Array, k0: int, k1: int, dt: float
              ) -> tuple[Array, Array, int, int]:
    """Steps k0 .. k1 - 1 in one compiled call when the stepper allows it
    (:func:`verify.sim.kernels.cf4_run`), recording into ``rec`` (a
    :class:`verify.sim.trajectory.Recorder`). Returns (Y, x, k, status) with k where it stopped;
    status -1 when the stepper has no whole-run kernel (nothing done)."""
    if not (isinstance(stepper, CompiledStepper) and stepper.command in ("none", "held")
            and stepper.auto != kernels.AUTO_GIVEN):
        return Y, x, k0, -1
    h = stepper.human
    held = stepper.command == "held"
    if not hasattr(stepper, "_segments"):
        ref = stepper.reference
        times = np.arange(rec.t.shape[0]) * dt  # k * dt, as the per-step loop forms it
        stepper._segments = (np.zeros(times.shape[0], dtype=np.int64) if ref.period is None
                             else np.minimum(np.floor(times / ref.period + 1e-9),
                                             len(ref.rotations) - 1).astype(np.int64))
        stepper._rotations = np.ascontiguousarray(np.stack(stepper.rotations))
    Y, x = np.array(Y, dtype=float), np.array(x, dtype=float)
    Y_out, x_out = np.empty_like(Y), np.empty_like(x)
    s = np.empty((rec.t.shape[0], 3))
    dirs = rec.d if rec.d is not None else np.empty((0, rec.n, 3))
    k, status = kernels.cf4_run(
        Y, x, k0, k1, dt, stepper.k_s, stepper._rotations, stepper._segments, int(held),
        float(h.k_omega) if held else 0.0, float(h.saturation) if held else 0.0,
        float(h.tilt) if held else 0.0, stepper.hA, stepper.hB, stepper.hC, stepper.hD,
        stepper.auto, stepper.gain, stepper.tol, rec.R_bar, rec.R_l, rec.R_r, rec.x, s,
        dirs, rec.every if rec.d is not None else 0, Y_out, x_out, *stepper.workspace)
    if k > k0:
        norm = np.linalg.norm(s[k0:k], axis=1)
        rec.coherence[k0:k] = norm / rec.n
        with np.errstate(invalid="ignore", divide="ignore"):
            rec.dbar[k0:k] = np.where(norm[:, None] > 0, s[k0:k] / norm[:, None], np.nan)
    return Y, x, k, int(status)


def stepper(scenario: Scenario, engine: str = "auto") -> Stepper:
    """The stepper of ``engine``: "python" (ClosedLoop's field), "compiled" (the kernels;
    VerifyInputError when they do not model the scenario) or "auto" (kernels if they do)."""
    loop = ClosedLoop(scenario)
    if engine == "python":
        return Stepper(loop)
    h_form = human_form(scenario.human)
    auto_form = _autonomous_form(scenario.autonomous)
    if h_form is not None and h_form[4] == "noisy" and engine != "compiled":
        # opt-in only: the shipped experiment logs were generated by the Python field,
        # and "auto" must keep regenerating them byte for byte
        h_form = None
    if laws_unmodified() and h_form is not None and auto_form is not None:
        return CompiledStepper(loop, h_form, auto_form)
    if engine == "compiled":
        raise VerifyInputError(
            "the compiled engine does not model this scenario's human or autonomous input "
            "(or a closed-loop law was replaced); use engine='auto' or 'python'")
    return Stepper(loop)
