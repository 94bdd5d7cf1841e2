"""Passive LTI models by construction: port-Hamiltonian systems x' = (J - R) Q x + G u.

With J skew, R >= 0 and Q > 0, the output y = G^T Q x + D u with D + D^T >= 0 makes
V = x^T Q x / 2 a storage: dV/dt = -x^T Q R Q x + y^T u - u^T D u <= u^T y, so P = Q
solves the KYP inequality (A. van der Schaft, *L2-Gain and Passivity Techniques in
Nonlinear Control*, 3rd ed., Springer 2017, Ch. 6; H. K. Khalil, *Nonlinear Systems*,
3rd ed., Lemma 6.2). Negating C gives models that are not passive in general.

Two builders, both in floating point (the gate then reads every entry as the exact
rational it denotes, so rounding can break the storage; a strictly passive feedthrough
keeps the KYP LMI strictly feasible):

* :func:`port_hamiltonian`: from free matrices (random scenarios of ``verify all`` and
  the hypothesis strategy :func:`verify.strategies.passive_lti_models`);
* :func:`random_port_hamiltonian`: a seeded random family of any size (benchmarks and
  tests of the gate at scale).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from verify.passivity.model import LTIModel


def port_hamiltonian(J: np.ndarray, L: np.ndarray, M: np.ndarray, G: np.ndarray,
                     N: np.ndarray, s: float) -> LTIModel:
    """A passive LTI model built from free matrices (port-Hamiltonian, strict feedthrough).

    x' = (J - J^T - R) Q x + G u, y = G^T Q x + (s I + (N - N^T)/2) u with
    R = L L^T + 0.3 I > 0 and Q = M M^T + 0.5 I > 0: x^T Q x / 2 is a storage, and
    D + D^T = 2 s I > 0 (s > 0) keeps the KYP LMI strictly feasible after rounding.
    """
    from verify.passivity.model import from_state_space

    n, ports = G.shape
    Q = M @ M.T + 0.5 * np.eye(n)
    A = (J - J.T - (L @ L.T + 0.3 * np.eye(n))) @ Q
    D = s * np.eye(ports) + 0.5 * (N - N.T)
    return from_state_space(A, G, G.T @ Q, D, name="random port-Hamiltonian")


def random_port_hamiltonian(n: int, m: int, rng: np.random.Generator, flip: bool = False
                            ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(A, B, C, D) of x' = (J - R) Q x + G u, y = G^T Q x (or -G^T Q x when ``flip``).

    J skew and R = L L^T / n + 0.1 I from standard normal draws, Q diagonal with powers
    of two from 1/4 to 4 (exact in binary), G standard normal, D = 0; drawn from ``rng``
    in that order.
    """
    J = rng.standard_normal((n, n))
    J = J - J.T
    L = rng.standard_normal((n, n))
    R = L @ L.T / n + 0.1 * np.eye(n)
    Q = np.diag(2.0 ** rng.integers(-2, 3, n))
    G = rng.standard_normal((n, m))
    C = G.T @ Q
    return (J - R) @ Q, G, -C if flip else C, np.zeros((m, m))


def with_negative_resonance(A0: np.ndarray, G: np.ndarray, C0: np.ndarray, d: float,
                            rng: np.random.Generator, *, w0: float = 3.0,
                            zeta: float = 0.01, depth: float = 0.3
                            ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(A, B, C, D) of the passive part (A0, G, C0, d I) minus a lightly damped resonance
    at ``w0`` deep enough that nu(w0) < 0, along a direction v drawn from ``rng``.

    D = d I > 0 leaves no witness at infinity or on the real axis, so the model is not
    passive only near w0: a test of frequency witnesses (Section 4's nu(w) dips below 0).
    """
    m, p = G.shape[1], A0.shape[0]
    H0 = C0 @ np.linalg.solve(1j * w0 * np.eye(p) - A0, G) + d * np.eye(m)
    k = float(np.linalg.eigvalsh((H0 + H0.conj().T) / 2)[-1]) + depth
    v = rng.standard_normal(m)
    v /= np.linalg.norm(v)
    Ar = np.array([[0.0, 1.0], [-w0 * w0, -2 * zeta * w0]])
    A = np.block([[A0, np.zeros((p, 2))], [np.zeros((2, p)), Ar]])
    B = np.vstack([G, np.outer([0.0, 1.0], v)])
    C = np.hstack([C0, -k * 2 * zeta * w0 * np.outer(v, [0.0, 1.0])])
    return A, B, C, d * np.eye(m)


__all__ = ["port_hamiltonian", "random_port_hamiltonian", "with_negative_resonance"]
