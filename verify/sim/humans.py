"""Human operator models for the closed loop (Section 3, Assumption 1; Section 4).

Every model maps the error e = sk(R_l^T R_r)^vee (the input of eq. (7), the passivity
inequality) to the body velocity command omega_h^b = R_l^T omega_h^s. Models with two
ports see the first two components of e and leave the third output at zero, as in the
identification of Section 4 ("Human Modeling"); three-port models see all of e.

* :class:`LTIHuman`: x' = A x + B e, omega_h^b = C x + D e, from a passivity-module model,
  with the storage x^T P x / 2 of its KYP certificate when one is given;
* :class:`StaticGainHuman`: omega_h^b = K e (passive iff K + K^T >= 0), no state;
* :class:`SignalHuman`: a given spatial command omega_h^s(t) (open loop, no feedback);
* :class:`VROperator`: the VR interface of Section 4, omega_h^s = k_omega log(R_t R_0^T)^vee
  saturated at 1 rad/s and held over each 1/120 s loop period, driven by a simple
  operator policy (below).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from verify.errors import VerifyInputError
from verify.inputs.numbers import real_array
from verify.so3 import E3, Array, exp, log, transpose

if TYPE_CHECKING:
    from verify.passivity.decision import Decision

_EMPTY = np.zeros(0)


def _ports(m: int, what: str) -> int:
    if m not in (2, 3):
        raise VerifyInputError(
            f"{what} must have 2 ports (first two components of the error, Section 4) or 3, "
            f"got {m}"
        )
    return m


def _pad(u: Array) -> Array:
    """The three-component body command from a 2- or 3-port output (third set to 0)."""
    out = np.zeros(3)
    out[: u.shape[0]] = u
    return out


class Human:
    """Interface of a human model in the simulator.

    ``state_size`` Euclidean states are integrated with the rotations; ``hold`` is called
    once at the start of every loop period and may return a value that stays fixed over
    the period (a sampled-and-held command); ``command`` and ``state_rate`` are evaluated
    at every integrator stage.
    """

    state_size: int = 0
    name: str = "human"

    def initial_state(self) -> Array:
        return np.zeros(self.state_size)

    def hold(self, t: float, R_l: Array, R_r: Array) -> Array | None:
        return None

    def command(self, t: float, x: Array, e: Array, R_l: Array, held: Array | None
                ) -> Array:
        """omega_h^b (3,) at time t from the state x, the error e = sk(R_l^T R_r)^vee, R_l."""
        raise NotImplementedError

    def state_rate(self, x: Array, e: Array) -> Array:
        return _EMPTY

    def storage(self, x: Array) -> float | None:
        """A storage function of the state (x^T P x / 2) when the model carries one."""
        return None

    def storage_rate(self, x: Array, e: Array) -> float:
        """The storage's rate along the human's dynamics (at most e^T omega_h^b if passive)."""
        raise NotImplementedError(f"{self.name} has no storage function")


@dataclass
class LTIHuman(Human):
    """An LTI model H(s) as the human (Section 4): x' = A x + B e, omega_h^b = C x + D e.

    ``P`` is the KYP matrix of a certificate for exactly these (A, B, C, D) (the KYP
    lemma); with it, x^T P x / 2 is a storage function: its rate is at most e^T omega_h^b.
    """

    A: Array
    B: Array
    C: Array
    D: Array
    P: Array | None = None
    name: str = "LTI model"
    x0: Array | None = None

    def __post_init__(self) -> None:
        self.A, self.B, self.C, self.D = (
            real_array(M, f"the human model's {label}")
            for label, M in (("A", self.A), ("B", self.B), ("C", self.C), ("D", self.D)))
        p, m = self.D.shape
        if p != m:
            raise VerifyInputError(f"the human model must be square, got {p} outputs and "
                                   f"{m} inputs")
        self.ports = _ports(m, "the human model")
        self.state_size = self.A.shape[0]

    @classmethod
    def from_model(cls, model, P: Array | None = None, x0: Array | None = None) -> LTIHuman:
        """From a :class:`verify.passivity.model.LTIModel` (and its certificate's P)."""
        return cls(model.A, model.B, model.C, model.D, P=P, name=model.name, x0=x0)

    @classmethod
    def gated(cls, model) -> tuple[LTIHuman, Decision]:
        """The model with the passivity gate's verdict; a passive model gets the storage
        x^T P x / 2 from its exactly checked KYP certificate, any other none (a
        frequency-domain certificate proves H(s) positive real but holds no P)."""
        from verify.passivity.decision import PASSIVE, decide

        decision = decide(model)
        if decision.verdict != PASSIVE or not hasattr(decision.certificate, "P"):
            return cls.from_model(model), decision
        cert = decision.certificate
        if cert.model.n != model.n:  # not minimal: the storage is on the minimal part
            from verify.passivity.model import LTIModel

            model = LTIModel(model.name, source=model.source, meta=model.meta,
                             exact=cert.model, realization="exact minimal part")
        P = np.array([[float(v) for v in row] for row in cert.P]).reshape(model.n, model.n)
        return cls.from_model(model, P=P), decision

    def initial_state(self) -> Array:
        return np.zeros(self.state_size) if self.x0 is None else np.array(self.x0, float)

    def command(self, t: float, x: Array, e: Array, R_l: Array, held: Array | None
                ) -> Array:
        k = self.ports
        return _pad(self.C @ x + self.D @ e[:k])

    def state_rate(self, x: Array, e: Array) -> Array:
        return self.A @ x + self.B @ e[: self.ports]

    def storage(self, x: Array) -> float | None:
        return None if self.P is None else 0.5 * float(x @ self.P @ x)

    def storage_rate(self, x: Array, e: Array) -> float:
        return float(x @ self.P @ self.state_rate(x, e))


@dataclass
class StaticGainHuman(Human):
    """omega_h^b = K e: a memoryless operator (passive iff K + K^T >= 0, with no storage)."""

    K: Array = field(default_factory=lambda: np.eye(2))
    name: str = "static gain"

    def __post_init__(self) -> None:
        K = np.atleast_2d(real_array(self.K, "the static gain K"))
        if K.ndim != 2 or K.shape[0] != K.shape[1]:
            raise VerifyInputError(f"the static gain must be square, got shape {K.shape}")
        self.K = K
        self.ports = _ports(K.shape[0], "the static gain")
        self.passive = bool(np.linalg.eigvalsh(K + K.T)[0] >= 0)

    def command(self, t: float, x: Array, e: Array, R_l: Array, held: Array | None
                ) -> Array:
        return _pad(self.K @ e[: self.ports])

    def storage(self, x: Array) -> float | None:
        """0 (a memoryless passive map stores nothing); None when K + K^T is not PSD."""
        return 0.0 if self.passive else None

    def storage_rate(self, x: Array, e: Array) -> float:
        return 0.0


@dataclass
class VROperator(Human):
    """The VR-controller interface of Section 4 with a simple operator policy.

    Policy: the operator sees d_l = R_l e3 and the reference d_r = R_r e3 and tilts the
    controller from its grip attitude R_0 by a fraction ``tilt`` of the rotation that
    would carry d_l onto d_r, i.e. R_t R_0^T = exp(tilt * angle(d_l, d_r) * axis) with
    axis along d_l x d_r. The interface sends omega_h^s = k_omega log(R_t R_0^T)^vee with
    its norm saturated at ``saturation`` (k_omega = 0.8, 1 rad/s in the paper), held over
    each loop period (120 Hz). The body command is omega_h^b = R_l^T omega_h^s.
    """

    k_omega: float = 0.8
    saturation: float = 1.0
    tilt: float = 1.0
    name: str = "VR operator"

    def hold(self, t: float, R_l: Array, R_r: Array) -> Array:
        d_l, d_r = R_l @ E3, R_r @ E3
        axis = np.cross(d_l, d_r)
        s, c = float(np.linalg.norm(axis)), float(d_l @ d_r)
        if s < 1e-15:
            tilt_vector = np.zeros(3)
        else:
            tilt_vector = self.tilt * np.arctan2(s, c) * axis / s
        R_grip = np.eye(3)  # R_0: the grip attitude; only R_t R_0^T matters
        R_t = exp(tilt_vector) @ R_grip
        omega_s = self.k_omega * log(R_t @ transpose(R_grip))
        norm = float(np.linalg.norm(omega_s))
        if norm > self.saturation:
            omega_s *= self.saturation / norm
        return omega_s

    def command(self, t: float, x: Array, e: Array, R_l: Array, held: Array | None
                ) -> Array:
        return transpose(R_l) @ held


@dataclass
class SignalHuman(Human):
    """An open-loop operator: omega_h^s(t) is a given signal (shape (3,)), whatever e is.

    Used where a claim must hold for every human command (Section 2's stealthiness,
    Section 3's R-bar e3 = dbar), not only for feedback laws.
    """

    signal: Callable[[float], Array] = field(default=lambda t: np.zeros(3))
    name: str = "given command signal"

    def command(self, t: float, x: Array, e: Array, R_l: Array, held: Array | None
                ) -> Array:
        return transpose(R_l) @ self.signal(t)
