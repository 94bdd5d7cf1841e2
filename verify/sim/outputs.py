"""Files written by ``verify simulate``: the trajectory (NPZ or CSV) and its plots.

Everything is rendered in memory first and then written file by file atomically, so a
failure leaves no half-written output (:mod:`verify.artefacts.atomic`).
"""

from __future__ import annotations

import io
import math
from pathlib import Path

import numpy as np

from verify.artefacts.atomic import write_all_atomic
from verify.sim.energy import Energy
from verify.sim.trajectory import Trajectory
from verify.so3 import E3

CSV_COLUMNS = (
    "t", "dbar_x", "dbar_y", "dbar_z", "d_r_x", "d_r_y", "d_r_z", "dbar_error",
    "d_l_x", "d_l_y", "d_l_z", "tr_Rbar_r", "lambda_min_sym_R_rl", "S_r", "S_rl", "S_h", "V",
    "V_dot", "V_dot_bound", "coherence",
)


#: The figures :func:`plots` writes (checked as outputs before a run).
PLOT_NAMES = ("energy.png", "lemma1.png", "dbar_error.png", "sphere.png")


def series(traj: Trajectory, E: Energy) -> dict[str, np.ndarray]:
    """Named time series of a run (each of length T, or (T, 3) for vectors)."""
    d_r = traj.R_r @ E3
    return {
        "t": traj.t,
        "dbar": traj.dbar,
        "d_r": d_r,
        "dbar_error": np.linalg.norm(traj.dbar - d_r, axis=1),
        "d_l": traj.R_l @ E3,
        "tr_Rbar_r": E.h + 1.0,
        "lambda_min_sym_R_rl": 0.5 * E.lmin_rl,
        "S_r": E.S_r,
        "S_rl": E.S_rl,
        "S_h": E.S_h_storage if E.uses_storage else E.S_h_integral,
        "V": E.V,
        "V_dot": E.V_dot,
        "V_dot_bound": E.V_dot_bound,
        "coherence": traj.coherence,
    }


def trajectory_npz(traj: Trajectory, E: Energy) -> bytes:
    arrays = dict(series(traj, E))
    arrays.update(R_bar=traj.R_bar, R_l=traj.R_l, R_r=traj.R_r, human_state=traj.human_state,
                  supply=traj.supply, final_bodies=traj.final_bodies,
                  direction_times=traj.direction_times)
    if traj.d is not None:
        arrays["d"] = traj.d
    buffer = io.BytesIO()
    np.savez_compressed(buffer, **arrays)
    return buffer.getvalue()


def trajectory_csv(traj: Trajectory, E: Energy) -> str:
    s = series(traj, E)
    columns = [s["t"][:, None], s["dbar"], s["d_r"], s["dbar_error"][:, None], s["d_l"]]
    columns += [s[k][:, None] for k in ("tr_Rbar_r", "lambda_min_sym_R_rl", "S_r", "S_rl",
                                        "S_h", "V", "V_dot", "V_dot_bound", "coherence")]
    table = np.hstack(columns)
    buffer = io.StringIO()
    np.savetxt(buffer, table, delimiter=",", header=",".join(CSV_COLUMNS), comments="",
               fmt="%.12g")
    return buffer.getvalue()


def _png(fig) -> bytes:
    from verify.artefacts.figure_bytes import figure_bytes

    return figure_bytes(fig, "png", dpi=110, bbox_inches="tight")


def _plain_title(title: str) -> str:
    """A run's title for a figure: ``k_s`` as math, Matplotlib's ``$`` otherwise literal."""
    return title.replace("$", r"\$").replace("k_s", "$k_s$")


def _finish(ax, *, legend: bool = True) -> None:
    """Few enough ticks that their labels never touch; a legend beside the curves."""
    from matplotlib.ticker import MaxNLocator

    ax.xaxis.set_major_locator(MaxNLocator(nbins=6))
    ax.grid(True, alpha=0.3)
    if legend:
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)


def plots(traj: Trajectory, E: Energy, title: str) -> dict[str, bytes]:
    """PNG figures of a run (paper, Sections 2-3): the storage V(t) = S_r + S_rl + S_h of
    Theorem 1 with its three terms, tr(R-bar_r)(t) of Lemma 1, |dbar - d_r|(t) (the
    control objective) and the directions d_i on the unit sphere; labels in math."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    s = series(traj, E)
    t = s["t"]
    head = _plain_title(title)
    out: dict[str, bytes] = {}

    fig, ax = plt.subplots(figsize=(7.2, 3.4))
    ax.plot(t, s["V"], lw=1.8, label=r"$V = S_r + S_{rl} + S_h$")
    ax.plot(t, s["S_r"], lw=0.9, label=r"$S_r$")
    ax.plot(t, s["S_rl"], lw=0.9, label=r"$S_{rl}$")
    human = (r"$S_h = x^{\top} P x / 2$ (KYP storage)" if E.uses_storage
             else r"$S_h$: $\int_0^t e^{\top} \omega_h^b \, d\tau$ (up to a constant)")
    ax.plot(t, s["S_h"], lw=0.9, label=human)
    ax.set_xlabel(r"$t$ [s]")
    ax.set_ylabel("storage")
    ax.set_title(f"{head}: $V(t)$ (Theorem 1)", fontsize=10)
    _finish(ax)
    out["energy.png"] = _png(fig)

    fig, ax = plt.subplots(figsize=(7.2, 3.4))
    ax.plot(t, s["tr_Rbar_r"], label=r"$\mathrm{tr}\,\bar R_r$")
    ax.plot(t, 1.0 + s["lambda_min_sym_R_rl"], lw=0.9,
            label=r"$1 + \lambda_{\min}(\mathrm{sym}\,R_{rl})$")
    ax.axhline(1.0, color="k", lw=0.6, ls="--", label="1")
    ax.set_xlabel(r"$t$ [s]")
    ax.set_title(f"{head}: Lemma 1 "
                 r"($\mathrm{tr}\,\bar R_r \geq 1$ while $\mathrm{sym}\,R_{rl} \succ 0$)",
                 fontsize=10)
    _finish(ax)
    out["lemma1.png"] = _png(fig)

    fig, ax = plt.subplots(figsize=(7.2, 3.4))
    ax.semilogy(t, np.maximum(s["dbar_error"], 1e-16))
    from matplotlib.ticker import FuncFormatter

    lo, hi = ax.get_ylim()
    few = math.log10(hi / lo) < 2  # under two decades: label the minor ticks too
    ax.yaxis.set_major_formatter(FuncFormatter(lambda y, _: f"{y:g}"))
    ax.yaxis.set_minor_formatter(FuncFormatter(
        lambda y, _: f"{y:g}" if few and str(f"{y:.0e}")[0] in "2345" else ""))
    ax.set_xlabel(r"$t$ [s]")
    ax.set_ylabel(r"$\Vert \bar d - d_r \Vert$")
    ax.set_title(f"{head}: control objective (eq. 3)", fontsize=10)
    _finish(ax, legend=False)
    out["dbar_error.png"] = _png(fig)

    fig = plt.figure(figsize=(5.4, 5.4))
    ax = fig.add_subplot(projection="3d")
    u, v = np.mgrid[0 : 2 * np.pi : 30j, 0 : np.pi : 15j]
    ax.plot_wireframe(np.cos(u) * np.sin(v), np.sin(u) * np.sin(v), np.cos(v), color="0.85",
                      lw=0.4)
    if traj.d is not None:
        for i in range(min(traj.d.shape[1], 50)):
            ax.plot(*traj.d[:, i].T, lw=0.8)
    ax.plot(*s["dbar"].T, color="k", lw=2, label=r"$\bar d(t)$")
    ax.scatter(*s["d_r"][-1], color="r", s=40, label=r"$d_r$")
    ax.set_box_aspect((1, 1, 1))
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):  # three ticks per axis: none overlap
        axis.set_ticks([-1.0, 0.0, 1.0])
    ax.tick_params(labelsize=7)
    ax.set_title(f"{head}: $d_i(t)$ on the sphere", fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    out["sphere.png"] = _png(fig)
    return out


def write_outputs(out_dir: Path, traj: Trajectory, E: Energy, fmt: str, title: str,
                  with_plots: bool = True) -> list[Path]:
    """Render and write the trajectory and plots into ``out_dir``; returns the paths."""
    files: dict[Path, bytes | str] = {}
    if fmt == "npz":
        files[out_dir / "trajectory.npz"] = trajectory_npz(traj, E)
    else:
        files[out_dir / "trajectory.csv"] = trajectory_csv(traj, E)
    if with_plots:
        files.update({out_dir / name: data for name, data in plots(traj, E, title).items()})
    write_all_atomic(files)
    return list(files)


def counterexample_figure(traj: Trajectory, E: Energy, title: str) -> dict[str, bytes]:
    """Two panels: Lemma 1's quantities, and |dbar - d_r| with the human's supply; SVG and
    PDF bytes (``{"svg": ..., "pdf": ...}``) in the paper's font. ``title`` may hold
    mathtext (``$\\mathrm{tr}\\,\\bar R_r$``)."""
    from verify.artefacts.figure_bytes import paper_style

    with paper_style():
        return _counterexample_figure(traj, E, title)


def _counterexample_figure(traj: Trajectory, E: Energy, title: str) -> dict[str, bytes]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from verify.artefacts.figure_bytes import vector_figures

    s = series(traj, E)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8.4, 4.8), sharex=True)
    top.plot(s["t"], s["tr_Rbar_r"], label=r"$\mathrm{tr}\,\bar R_r$")
    top.plot(s["t"], 1.0 + s["lambda_min_sym_R_rl"], lw=0.8,
             label=r"$1 + \lambda_{\min}(\mathrm{sym}\,R_{rl})$")
    top.axhline(1.0, color="k", lw=0.6, ls="--")
    top.set_title(title, fontsize=10)
    bottom.plot(s["t"], s["dbar_error"], label=r"$\Vert\bar d - d_r\Vert$")
    bottom.plot(s["t"], traj.supply, lw=0.8, label=r"$\int e^{\top}\omega_h^b\,dt$")
    bottom.set_xlabel(r"$t$ [s]")
    top.set_ylabel(r"$\mathrm{tr}\,\bar R_r$ (Lemma 1)")
    bottom.set_ylabel(r"$\Vert\bar d - d_r\Vert$ and supply")
    for ax in (top, bottom):  # legends beside the axes, never on the curves
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    fig.tight_layout()
    return vector_figures(fig)
