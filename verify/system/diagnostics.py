"""Numerical diagnostics of Section 2 on one given network (``verify network FILE``).

These are floating-point checks with rounding bounds (not proofs): they tell a user
whether the repaired stealthy projector behaves on their network and how well
conditioned it is. The exact checks of the claims live in :mod:`verify.claims.section2`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from verify.so3 import Array
from verify.system import stealthy as st

DENSE_LIMIT = 2000  # bodies; the dense 3n x 3n reference is skipped above this


@dataclass(frozen=True)
class NetworkDiagnostics:
    n: int
    abs_sum: float
    dbar: Array
    singular_values: Array  # of W~ (unscaled W), descending
    kappa: float
    rounding_bound: float  # per unit input, for applying A
    stealth_residual: float  # max |P S A x| / |x| over probe vectors
    idempotence_residual: float  # max |A A x - A x| / |x|
    dense_vs_structured: float | None  # max difference / |x|, None when skipped

    @property
    def ok(self) -> bool:
        checks = [self.stealth_residual, self.idempotence_residual]
        if self.dense_vs_structured is not None:
            checks.append(self.dense_vs_structured)
        return all(c <= self.rounding_bound for c in checks)


def diagnose(R: Array, probes: int = 8, seed: int = 0) -> NetworkDiagnostics:
    """Measure the repaired projector on ``R`` with random probe vectors."""
    n = R.shape[0]
    u = st.dbar(R)
    sv = np.linalg.svd(st.w_matrix(R, scaled=False), compute_uv=False)
    bound, kappa = st.projector_rounding_bound(R)
    rng = np.random.default_rng(seed)
    X = rng.standard_normal((3 * n, probes))
    X /= np.linalg.norm(X, axis=0)
    AX = st.apply_projector(R, X)
    JS_AX = st.dbar_rate_unscaled(R, AX.reshape(n, 3, probes))
    stealth = float(np.linalg.norm(JS_AX, axis=0).max())
    idem = float(np.linalg.norm(st.apply_projector(R, AX) - AX, axis=0).max())
    dense = None
    if n <= DENSE_LIMIT:
        dense = float(np.linalg.norm(st.projector_dense(R) @ X - AX, axis=0).max())
    return NetworkDiagnostics(
        n=n,
        abs_sum=float(np.linalg.norm(st.direction_sum(R))),
        dbar=u,
        singular_values=sv,
        kappa=kappa,
        rounding_bound=bound,
        stealth_residual=stealth,
        idempotence_residual=idem,
        dense_vs_structured=dense,
    )
