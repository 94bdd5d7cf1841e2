"""Figures of Section 4 for the report: nu(w) with its located minimum, and Bode diagrams.

The paper shows Bode diagrams of the identified 2x2 models (Fig. "bode_diagram_2x2") and
nu(w) = lambda_min(H(jw) + H(jw)^H)/2 (Fig. "passivity_index_2x2"). These are drawn for
the shipped reconstructions: illustrations only, no verdict rests on a picture. The
minimum marked on the nu curve is the one located by Hamiltonian level crossings
(:mod:`verify.passivity.search.hamiltonian`), not the lowest grid point.

Matplotlib runs with the Agg backend; each PNG is rendered in memory and written with a
temporary file and a rename (:func:`verify.report.atomic.write_atomic`), without the
version and date stamps that would make two runs differ
(:func:`verify.report.figure_bytes.figure_bytes`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from verify.passivity.search.hamiltonian import NuMinimum, nu_values
from verify.report.atomic import write_atomic
from verify.report.figure_bytes import figure_bytes

if TYPE_CHECKING:
    from verify.passivity.model import LTIModel


def _pyplot():
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    return plt


def _save(fig, path: Path) -> Path:
    write_atomic(path, figure_bytes(fig, "png", dpi=110))
    return path


def frequency_grid(models: Sequence[LTIModel], lo: float = 1e-2, hi: float = 1e2) -> np.ndarray:
    """Log-spaced frequencies covering [lo, hi] and two decades around every pole."""
    mags = [abs(p) for m in models if m.n for p in np.linalg.eigvals(m.A) if abs(p) > 0]
    if mags:
        lo, hi = min(lo, min(mags) / 100), max(hi, max(mags) * 100)
    return np.logspace(math.log10(lo), math.log10(hi), 800)


def nu_figure(curves: Sequence[tuple[LTIModel, NuMinimum]], path: Path) -> Path:
    """nu(w) of each model on a log frequency axis, its minimum marked (paper, Section 4)."""
    plt = _pyplot()
    w = frequency_grid([m for m, _ in curves])
    fig, ax = plt.subplots(figsize=(7, 4))
    for model, low in curves:
        values = nu_values(model.A, model.B, model.C, model.D, w)
        (line,) = ax.semilogx(w, values, label=model.name)
        if math.isinf(low.omega):
            ax.annotate(f"inf ν = {low.value:.3g} as ω → ∞", xy=(w[-1], low.value),
                        xytext=(-150, 18), textcoords="offset points", color=line.get_color(),
                        arrowprops={"arrowstyle": "->", "color": line.get_color()})
        else:
            ax.plot([low.omega], [low.value], "o", color=line.get_color())
            ax.annotate(f"min ν = {low.value:.4g} at ω = {low.omega:.4g}",
                        xy=(low.omega, low.value), xytext=(12, 14), textcoords="offset points",
                        color=line.get_color())
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xlabel("ω [rad/s]")
    ax.set_ylabel("ν(ω) = λ_min(H + Hᴴ)/2")
    ax.set_title("ν(ω) of the reconstructions; minima by Hamiltonian crossings")
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    return _save(fig, path)


def bode_figure(models: Sequence[LTIModel], path: Path) -> Path:
    """Magnitude (dB) and phase (deg) of every element H_ij(jw) of each model."""
    plt = _pyplot()
    w = frequency_grid(models)
    fig, (mag, phase) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    styles = ["-", "--", ":", "-."]
    for k, model in enumerate(models):
        H = model.frequency_response(w)
        for i in range(model.m):
            for j in range(model.m):
                h = H[:, i, j]
                if not np.any(np.abs(h) > 0):
                    continue
                label = f"{model.name}: H[{i + 1},{j + 1}]"
                ls = styles[(i * model.m + j) % len(styles)]
                color = f"C{k}"
                mag.semilogx(w, 20 * np.log10(np.abs(h)), ls, color=color, label=label)
                phase.semilogx(w, np.degrees(np.unwrap(np.angle(h))), ls, color=color)
    mag.set_ylabel("magnitude [dB]")
    phase.set_ylabel("phase [deg]")
    phase.set_xlabel("ω [rad/s]")
    mag.set_title("Bode diagrams of the reconstructed 2x2 human models")
    mag.legend(fontsize=7, ncol=2)
    for ax in (mag, phase):
        ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    return _save(fig, path)


__all__ = ["bode_figure", "frequency_grid", "nu_figure"]
