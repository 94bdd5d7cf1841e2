"""Identified model files for the robust-verdict tests (synthetic estimates, no data)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from verify.identify.estimate.structure import Structure
from verify.identify.model.model_writer import IdentifiedFile, write_identified_model

#: The paper's structure with the shipped k_s = 3.0 reconstruction's diagonal and a small
#: non-skew off-diagonal pair (c12 + c21 = 0.02): passive up to about 12 rad/s.
PAPER_THETA = [1.2, 0.8, 2.0, 1.5, 1.1, 0.9, 2.1, 1.4, 0.06, -0.04]


def correlated_covariance(theta, relative: float = 0.02, coupling: float = 0.005,
                          seed: int = 1) -> np.ndarray:
    """A positive definite covariance with correlated parameters."""
    sig = relative * np.abs(np.asarray(theta, dtype=float))
    sig[-2:] = coupling
    rng = np.random.default_rng(seed)
    R = rng.normal(size=(len(theta), len(theta))) * 0.2 + np.eye(len(theta))
    G = R @ R.T
    d = np.sqrt(np.diag(G))
    cov = G / np.outer(d, d) * np.outer(sig, sig)
    return (cov + cov.T) / 2


def paper_model(directory: Path, name: str = "synthetic", theta=None, cov=None
                ) -> IdentifiedFile:
    theta = PAPER_THETA if theta is None else theta
    cov = correlated_covariance(theta) if cov is None else cov
    return write_identified_model(directory / "model.toml", name=name,
                                  structure=Structure.paper(), theta=theta, covariance=cov,
                                  extra={"method": "synthetic test estimate"})


def biproper_model(directory: Path) -> IdentifiedFile:
    """Structure 1:1, h_i = (b1 s + b0)/(s + a0) with Re h_i between b0/a0 and b1: the
    region is passive at every frequency (c12 + c21 small against 2 min Re h_i)."""
    theta = [1.0, 2.0, 1.0, 0.9, 1.6, 1.1, 0.1, 0.05]
    cov = np.diag((0.01 * np.abs(np.asarray(theta))) ** 2)
    return write_identified_model(directory / "model.toml", name="biproper",
                                  structure=Structure.poles_zeros(1, 1), theta=theta,
                                  covariance=cov, extra={"method": "synthetic test estimate"})


__all__ = ["PAPER_THETA", "biproper_model", "correlated_covariance", "open_loop_log",
           "paper_model"]


def open_loop_log(model, *, trials: int = 6, seconds: float = 15.0, rate: float = 120.0,
                  noise: float = 0.002, seed: int = 0):
    """A fast synthetic experiment log: u = H e + white noise for a multisine e
    (:func:`verify.identify.data.simulated_experiment.simulate_open_loop_experiment`).

    Not the closed loop of Section 4 (that is ``simulate_experiment``, slower): enough to
    exercise the command's files, verdicts and exit codes.
    """
    from verify.identify.data.simulated_experiment import simulate_open_loop_experiment

    return simulate_open_loop_experiment(model, trials=trials, seconds=seconds, rate=rate,
                                         noise=noise, seed=seed)
