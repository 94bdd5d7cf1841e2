"""Figures of an identification (Section 4): validation fit, Bode with bands, nu(w).

Pictures, not evidence: the bands of the Bode plot come from parameter vectors sampled in
the confidence ellipsoid (seeded, so the bytes are reproducible), and nu(w) is evaluated
in floating point. The verdicts rest on :mod:`verify.identify.robust.verdict` alone. Bytes depend
only on the data drawn (:func:`verify.artefacts.figure_bytes.figure_bytes`).
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction

import numpy as np

from verify.artefacts.figure_bytes import figure_bytes
from verify.identify.estimate.structure import Structure

#: Parameter vectors sampled in the ellipsoid for the Bode bands.
SAMPLES = 200


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _in_paper_style(draw):
    """``draw`` run in the paper's font (Computer Modern, as the report's other figures)."""
    import functools

    from verify.artefacts.figure_bytes import paper_style

    @functools.wraps(draw)
    def drawn(*args, **kwargs):
        with paper_style():
            return draw(*args, **kwargs)

    return drawn


@_in_paper_style
def validation_figure(times: Sequence[np.ndarray], measured: Sequence[np.ndarray],
                      predicted: Sequence[np.ndarray], fits: Sequence[float]) -> bytes:
    """Measured and simulated u_h (two outputs) over the validation trials, end to end."""
    plt = _pyplot()
    fig, axes = plt.subplots(2, 1, figsize=(9, 5), sharex=True)
    offset = 0.0
    for k, (t, y, yhat) in enumerate(zip(times, measured, predicted, strict=True)):
        tt = np.asarray(t) - t[0] + offset
        for i, ax in enumerate(axes):
            ax.plot(tt, y[:, i], color="0.3", lw=0.8, label="data" if k == 0 else None)
            ax.plot(tt, yhat[:, i], color="C1", lw=1.0,
                    label="model (from rest, no offset)" if k == 0 else None)
        offset = tt[-1] + (t[1] - t[0])
        for ax in axes:
            ax.axvline(offset, color="0.85", lw=0.5)
    for i, ax in enumerate(axes):
        ax.set_ylabel(rf"$u_{{h,{i + 1}}}$ [rad/s]")
        ax.set_title(f"output {i + 1}: validation fit {fits[i]:.2f} % (the paper's basis)",
                     fontsize=9)
        ax.legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel(r"time over the validation trials, $t$ [s]")
    fig.tight_layout()
    return figure_bytes(fig)


def _response(structure: Structure, theta: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """(2, len(omega)) complex responses of the diagonal elements at θ."""
    per = structure.zeros + 1 + structure.poles
    out = []
    for i in range(2):
        block = theta[i * per:(i + 1) * per]
        num, den = block[: structure.zeros + 1], np.r_[1.0, block[structure.zeros + 1:]]
        out.append(np.polyval(num, 1j * omega) / np.polyval(den, 1j * omega))
    return np.array(out)


def ellipsoid_samples(center: np.ndarray, covariance: np.ndarray, chi2: float,
                      count: int = SAMPLES, seed: int = 0) -> np.ndarray:
    """Points uniform in {θ : (θ - c)^T Σ^-1 (θ - c) <= chi2} (seeded)."""
    rng = np.random.default_rng(seed)
    p = len(center)
    L = np.linalg.cholesky(covariance)
    z = rng.normal(size=(count, p))
    z /= np.linalg.norm(z, axis=1, keepdims=True)
    z *= rng.uniform(size=(count, 1)) ** (1 / p)
    return center + np.sqrt(chi2) * z @ L.T


@_in_paper_style
def bode_figure(structure: Structure, center: np.ndarray, covariance: np.ndarray | None,
                chi2: float, omega: np.ndarray, level: Fraction) -> bytes:
    """Magnitude and phase of h_1, h_2 at the centre, with the envelope over sampled θ
    (no envelope when ``covariance`` is None: no region)."""
    plt = _pyplot()
    thetas = center[None, :] if covariance is None else \
        ellipsoid_samples(center, covariance, chi2)
    nominal = _response(structure, center, omega)
    sampled = np.array([_response(structure, th, omega) for th in thetas])
    fig, axes = plt.subplots(2, 2, figsize=(9, 5.5), sharex=True)
    for i in range(2):
        mag = 20 * np.log10(np.abs(sampled[:, i]))
        ph = np.degrees(np.unwrap(np.angle(sampled[:, i]), axis=1))
        for row, (values, nom) in enumerate(((mag, 20 * np.log10(np.abs(nominal[i]))),
                                             (ph, np.degrees(np.unwrap(np.angle(
                                                 nominal[i]))))),):
            ax = axes[row, i]
            ax.fill_between(omega, values.min(axis=0), values.max(axis=0), color="C0",
                            alpha=0.25, lw=0,
                            label=f"{float(level):.0%} region ({len(thetas)} samples)")
            ax.semilogx(omega, nom, color="C0", lw=1.2, label="identified")
            ax.grid(True, which="both", lw=0.3)
        axes[0, i].set_title(rf"$h_{{{i + 1}}}(j\omega)$", fontsize=9)
        axes[1, i].set_xlabel(r"$\omega$ [rad/s]")
    axes[0, 0].set_ylabel("magnitude (dB)")
    axes[1, 0].set_ylabel("phase (deg)")
    axes[0, 0].legend(fontsize=7, loc="lower left")
    c12, c21 = center[-2], center[-1]
    fig.suptitle(rf"diagonal elements; off-diagonal constants $c_{{12}} = {c12:.4g}$, "
                 rf"$c_{{21}} = {c21:.4g}$", fontsize=9)
    fig.tight_layout()
    return figure_bytes(fig)


def nu_figure(structure: Structure, center: np.ndarray, omega: np.ndarray,
              proved: tuple[float, float] | None, requested: tuple[float, float] | None
              ) -> bytes:
    """nu(w) of the nominal model, with the robustly proved band shaded.

    When the curve dips below zero by a small fraction of its range (the passive human's
    tail of about -1.4e-4 beside values near 1), a second panel zooms on zero so the
    negative part, which decides "not passive", is seen rather than drawn as the axis.
    """
    from verify.artefacts.figure_bytes import paper_style

    with paper_style():
        return _nu_figure(structure, center, omega, proved, requested)


def _nu_figure(structure: Structure, center: np.ndarray, omega: np.ndarray,
               proved: tuple[float, float] | None, requested: tuple[float, float] | None
               ) -> bytes:
    from verify.identify.robust.verdict import float_nu

    plt = _pyplot()
    values = float_nu(structure, center, omega)
    low = int(np.argmin(values))
    span = float(np.max(values) - np.min(values)) or 1.0
    hidden = values[low] < 0 and -values[low] < 0.02 * span  # invisible at full scale
    fig, axes = plt.subplots(2 if hidden else 1, 1, figsize=(7, 5.2 if hidden else 3.5),
                             sharex=True, squeeze=False)
    axes = axes[:, 0]
    for k, ax in enumerate(axes):
        ax.semilogx(omega, values, color="C0", lw=1.2,
                    label=r"$\nu(\omega)$ of the identified model" if k == 0 else None)
        ax.axhline(0, color="0.4", lw=0.6)
        if proved is not None:
            ax.axvspan(max(proved[0], omega[0]), proved[1], color="C2", alpha=0.2,
                       label=f"robustly passive (proved) up to {proved[1]:.4g} rad/s"
                       if k == 0 else None)
        if requested is not None:
            ax.axvline(requested[1], color="C3", lw=0.8, ls="--",
                       label="requested band end" if k == 0 else None)
        ax.grid(True, which="both", lw=0.3)
    if values[low] < 0:
        where = axes[-1]
        where.fill_between(omega, values, 0, where=values < 0, color="C3", alpha=0.35,
                           lw=0, label=r"$\nu < 0$: not passive there")
        where.plot([omega[low]], [values[low]], "o", color="C3", ms=4,
                   label=rf"lowest drawn: $\nu = {values[low]:.2g}$ at $\omega = {omega[low]:.3g}$"
                   " rad/s")
    if hidden:
        axes[1].set_ylim(3 * values[low], -3 * values[low])
        axes[1].set_ylabel(r"$\nu(\omega)$ near 0")
        axes[1].legend(fontsize=8, loc="upper left")
    axes[-1].set_xlabel(r"$\omega$ [rad/s]")
    axes[0].set_ylabel(r"$\nu(\omega)$")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    return figure_bytes(fig)


__all__ = ["SAMPLES", "bode_figure", "ellipsoid_samples", "nu_figure", "validation_figure"]
