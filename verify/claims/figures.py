"""Figures of Section 4 for the claims' evidence: nu(w) with its minimum, and Bode diagrams.

The paper shows Bode diagrams of the identified 2x2 models (Fig. "bode_diagram_2x2") and
nu(w) = lambda_min(H(jw) + H(jw)^H)/2 (Fig. "passivity_index_2x2"). These are drawn for
the shipped reconstructions: illustrations only, no verdict rests on a picture. The
minimum marked on the nu curve is the one located by Hamiltonian level crossings
(:mod:`verify.passivity.search.hamiltonian`), not the lowest grid point.

Matplotlib runs with the Agg backend in the paper's font (Computer Modern,
:func:`verify.artefacts.figure_bytes.paper_style`); a figure named ``x.svg`` is written as
``x.svg`` (for the HTML report) and ``x.pdf`` (for the LaTeX supplement), both vector, any
other name as PNG. Each file is rendered in memory and written with a temporary file and
a rename (:func:`verify.artefacts.atomic.write_atomic`), without the version and date
stamps that would make two runs differ (:mod:`verify.artefacts.figure_bytes`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from verify.artefacts.atomic import write_atomic
from verify.artefacts.figure_bytes import figure_bytes, paper_style, vector_figures
from verify.passivity.figure import passivity_figure
from verify.passivity.search.hamiltonian import NuMinimum, nu_values

if TYPE_CHECKING:
    from verify.passivity.model import LTIModel


def _pyplot():
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    return plt


def _math_name(name: str) -> str:
    """A model name for a legend, its gain written as mathtext (``$k_s$``)."""
    return name.replace("k_s", "$k_s$")


def _save(fig, path: Path) -> Path:
    """Write ``fig`` to ``path``: SVG plus a PDF beside it for ``.svg``, else PNG."""
    if path.suffix == ".svg":
        files = vector_figures(fig)
        write_atomic(path, files["svg"])
        write_atomic(path.with_suffix(".pdf"), files["pdf"])
    else:
        write_atomic(path, figure_bytes(fig, "png", dpi=110))
    return path


def frequency_grid(models: Sequence[LTIModel], lo: float = 1e-2, hi: float = 1e2) -> np.ndarray:
    """Log-spaced frequencies covering [lo, hi] and two decades around every pole."""
    mags = [abs(p) for m in models if m.n for p in np.linalg.eigvals(m.A) if abs(p) > 0]
    if mags:
        lo, hi = min(lo, min(mags) / 100), max(hi, max(mags) * 100)
    return np.logspace(math.log10(lo), math.log10(hi), 800)


def nu_figure(curves: Sequence[tuple[LTIModel, NuMinimum]], path: Path) -> Path:
    """nu(w) of each model on a log frequency axis, its minimum marked (paper, Section 4).

    The located minimum of each curve is named in the legend (below the axes), not in
    annotations that could cover each other, a curve or the zero line.
    """
    with paper_style():
        return _nu_figure(curves, path)


def _nu_figure(curves: Sequence[tuple[LTIModel, NuMinimum]], path: Path) -> Path:
    plt = _pyplot()
    w = frequency_grid([m for m, _ in curves])
    fig, ax = plt.subplots(figsize=(7, 4.6))
    for model, low in curves:
        values = nu_values(model.A, model.B, model.C, model.D, w)
        if math.isinf(low.omega):
            where = r"$\inf\,\nu$" + f" = {low.value:.3g} as " + r"$\omega\to\infty$"
        else:
            where = r"$\min\,\nu$" + f" = {low.value:.4g} at " + r"$\omega$" \
                + f" = {low.omega:.4g} rad/s"
        (line,) = ax.semilogx(w, values, label=f"{_math_name(model.name)}: {where}")
        if not math.isinf(low.omega):
            ax.plot([low.omega], [low.value], "o", color=line.get_color())
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xlabel(r"$\omega$ [rad/s]")
    ax.set_ylabel(r"$\nu(\omega) = \lambda_{\min}(H + H^{\mathsf{H}})/2$")
    ax.set_title(r"$\nu(\omega)$ of the reconstructions; minima by Hamiltonian crossings",
                 fontsize=10)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), fontsize=8, frameon=False)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    return _save(fig, path)


def gate_figure(decision, path: Path) -> Path:
    """The passivity gate's own figure of one decision (paper, Section 4): nu(w) with the
    exact witness frequency or the certified verdict named, and the relative index R(w),
    as ``verify gate --plot`` draws it (:func:`verify.passivity.figure.passivity_figure`),
    set in the paper's font and written as SVG and PDF like the other figures."""
    with paper_style():
        return _save(passivity_figure(decision), path)


def bode_figure(models: Sequence[LTIModel], path: Path) -> Path:
    """Magnitude (dB) and phase (deg) of every element H_ij(jw) of each model; the legend
    stands beside the axes, not on the curves."""
    with paper_style():
        return _bode_figure(models, path)


def _bode_figure(models: Sequence[LTIModel], path: Path) -> Path:
    plt = _pyplot()
    w = frequency_grid(models)
    fig, (mag, phase) = plt.subplots(2, 1, figsize=(8.5, 6), sharex=True)
    styles = ["-", "--", ":", "-."]
    for k, model in enumerate(models):
        H = model.frequency_response(w)
        for i in range(model.m):
            for j in range(model.m):
                h = H[:, i, j]
                if not np.any(np.abs(h) > 0):
                    continue
                label = f"{_math_name(model.name)}: " + f"$H_{{{i + 1}{j + 1}}}$"
                ls = styles[(i * model.m + j) % len(styles)]
                color = f"C{k}"
                mag.semilogx(w, 20 * np.log10(np.abs(h)), ls, color=color, label=label)
                phase.semilogx(w, np.degrees(np.unwrap(np.angle(h))), ls, color=color)
    mag.set_ylabel("magnitude [dB]")
    phase.set_ylabel("phase [deg]")
    phase.set_xlabel(r"$\omega$ [rad/s]")
    mag.set_title(r"Bode diagrams of the reconstructed $2\times 2$ human models", fontsize=10)
    mag.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False)
    for ax in (mag, phase):
        ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    return _save(fig, path)


__all__ = ["bode_figure", "frequency_grid", "nu_figure"]
