"""Files written by ``verify simulate``: the trajectory (NPZ or CSV) and its plots.

Everything is rendered in memory first and then written file by file atomically, so a
failure leaves no half-written output (:mod:`verify.artefacts.atomic`).
"""

from __future__ import annotations

import io
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


def plots(traj: Trajectory, E: Energy, title: str) -> dict[str, bytes]:
    """PNG figures: V(t), tr(R-bar_r)(t), |dbar - d_r|(t), and d_i on the unit sphere."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    s = series(traj, E)
    t = s["t"]
    out: dict[str, bytes] = {}

    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.plot(t, s["V"], label="V = S_r + S_rl + S_h")
    ax.plot(t, s["S_r"], lw=0.8, label="S_r")
    ax.plot(t, s["S_rl"], lw=0.8, label="S_rl")
    ax.set(xlabel="t [s]", ylabel="energy", title=f"{title}: V(t) (Theorem 1)")
    ax.legend(fontsize=8)
    out["energy.png"] = _png(fig)

    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.plot(t, s["tr_Rbar_r"], label="tr(R-bar_r)")
    ax.plot(t, 1.0 + s["lambda_min_sym_R_rl"], lw=0.8, label="1 + lambda_min(sym R_rl)")
    ax.axhline(1.0, color="k", lw=0.6, ls="--")
    ax.set(xlabel="t [s]", title=f"{title}: Lemma 1 (tr >= 1 while sym(R_rl) > 0)")
    ax.legend(fontsize=8)
    out["lemma1.png"] = _png(fig)

    fig, ax = plt.subplots(figsize=(6, 3.2))
    ax.semilogy(t, np.maximum(s["dbar_error"], 1e-16))
    ax.set(xlabel="t [s]", ylabel="|dbar - d_r|", title=f"{title}: control objective (eq. 3)")
    out["dbar_error.png"] = _png(fig)

    fig = plt.figure(figsize=(5, 5))
    ax = fig.add_subplot(projection="3d")
    u, v = np.mgrid[0 : 2 * np.pi : 30j, 0 : np.pi : 15j]
    ax.plot_wireframe(np.cos(u) * np.sin(v), np.sin(u) * np.sin(v), np.cos(v), color="0.85",
                      lw=0.4)
    if traj.d is not None:
        for i in range(min(traj.d.shape[1], 50)):
            ax.plot(*traj.d[:, i].T, lw=0.8)
    ax.plot(*s["dbar"].T, color="k", lw=2, label="dbar")
    ax.scatter(*s["d_r"][-1], color="r", s=40, label="d_r")
    ax.set_box_aspect((1, 1, 1))
    ax.set_title(f"{title}: d_i on the sphere")
    ax.legend(fontsize=8)
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


def counterexample_figure(traj: Trajectory, E: Energy, title: str) -> bytes:
    """Two panels: Lemma 1's quantities, and |dbar - d_r| with the human's supply."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    s = series(traj, E)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8.4, 4.8), sharex=True)
    top.plot(s["t"], s["tr_Rbar_r"], label=r"$\mathrm{tr}\,\bar R_r$")
    top.plot(s["t"], 1.0 + s["lambda_min_sym_R_rl"], lw=0.8,
             label=r"$1 + \lambda_{\min}(\mathrm{sym}\,R_{rl})$")
    top.axhline(1.0, color="k", lw=0.6, ls="--")
    top.set_title(title, fontsize=10)
    bottom.plot(s["t"], s["dbar_error"], label=r"$\Vert\bar d - d_r\Vert$")
    bottom.plot(s["t"], traj.supply, lw=0.8, label=r"$\int e^{\top}\omega_h^b\,dt$")
    bottom.set_xlabel("t [s]")
    for ax in (top, bottom):  # legends beside the axes, never on the curves
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    fig.tight_layout()
    return _png(fig)
