"""The baseline estimator of the method benchmark: output error started from ARX.

What a plain workflow does (e.g. ``arx`` -> ``d2c`` -> ``oe`` in a toolbox): per output
i, the discrete ARX model A(q) u_i = B_i(q) e_i + C_j(q) e_j + noise of orders
(n, n, n + 1) by linear least squares over all trials; its element B_i/A converted to
continuous time through the matrix logarithm of the zero-order-hold discretisation
(poles reflected into Re s < 0 if the conversion leaves any outside); then the plain
output-error least-squares fit of (b, a, c) with zero initial states, by
``scipy.optimize.least_squares`` from that start. The covariance is sigma^2 (J^T J)^-1.
It is the comparison point of ``benchmarks/bench_identify_methods.py``, not a method to
use: ARX is biased when the noise is not an equation error, and zero initial states
misfit the start of every trial.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from scipy import linalg, signal
from scipy.optimize import least_squares

from verify.identify.estimate.pem import OutputFit
from verify.identify.estimate.prediction import predict_output
from verify.identify.estimate.result import Estimate, assemble
from verify.identify.estimate.riv import stable
from verify.identify.estimate.structure import Structure
from verify.identify.estimate.trial_data import OutputData, output_data
from verify.inputs.experiment import Trial

__all__ = ["arx_start", "oe_from_arx"]


def arx_start(data: OutputData, poles: int, zeros: int) -> tuple[np.ndarray, np.ndarray,
                                                                  float]:
    """(b, a, c) of the continuous-time element converted from a discrete ARX fit."""
    n = poles
    rows, target = [], []
    for own, other, y in zip(data.own, data.other, data.y, strict=True):
        for k in range(n, len(y)):
            rows.append(np.concatenate([-y[k - n:k][::-1], own[k - n:k][::-1],
                                        other[k - n:k + 1][::-1]]))
            target.append(y[k])
    theta = np.linalg.lstsq(np.array(rows), np.array(target), rcond=None)[0]
    ad = np.concatenate([[1.0], theta[:n]])
    bd = np.concatenate([[0.0], theta[n:2 * n]])
    c = float(theta[2 * n])  # the feedthrough of e_j
    A, B, C, D = signal.tf2ss(bd, ad)
    m = A.shape[0]
    big = np.zeros((m + 1, m + 1))
    big[:m, :m], big[:m, m:] = A, B
    big[m, m] = 1.0
    cont = np.real(linalg.logm(big)) / data.h
    Ac, Bc = cont[:m, :m], cont[:m, m:]
    num, den = signal.ss2tf(Ac, Bc, C, D)
    a = stable(den[1:] / den[0]) if den[0] != 0 else np.ones(n)
    b = np.real(num[0][-(zeros + 1):]) / den[0]
    return b, a, c


def _fit(data: OutputData, poles: int, zeros: int) -> OutputFit:
    b0, a0, c0 = arx_start(data, poles, zeros)
    y = np.concatenate(data.y)
    p = zeros + 1

    def residual(x: np.ndarray) -> np.ndarray:
        r = y - predict_output(x[:p], x[p:p + poles], x[-1], data, initial="zero")
        return r if np.all(np.isfinite(r)) else np.full(r.shape, 1e6)

    sol = least_squares(residual, np.concatenate([b0, a0, [c0]]), method="lm")
    r = sol.fun
    J = sol.jac
    sigma2 = float(r @ r) / max(len(r) - len(sol.x), 1)
    cov = sigma2 * np.linalg.pinv(J.T @ J)
    return OutputFit(sol.x[:p], sol.x[p:p + poles], float(sol.x[-1]),
                     np.zeros((len(data.y), poles)), r, float(r @ r), cov, float(np.sqrt(sigma2)))


def oe_from_arx(trials: Sequence[Trial], structure: Structure, h: float) -> Estimate:
    """The baseline estimate (module docstring) of checked ``trials`` with step ``h``."""
    fits = [_fit(output_data(trials, i, h), structure.poles, structure.zeros) for i in (0, 1)]
    samples = sum(np.asarray(tr.t).shape[0] for tr in trials)
    return assemble(structure, fits, "arx+oe", samples)
