"""One run of a campaign: build the scenario, simulate, check the properties, make a row.

The scenario is the one ``verify simulate`` builds for the same settings
(:func:`verify.sim.command.build_scenario`: bodies within 45 degrees of the identity,
R_r within 60 degrees, drawn from the run's seed), so the command that a report prints
for a row rebuilds it exactly. The properties are those of :mod:`verify.sim.properties`
with their step-doubling tolerances, all read from one pair of runs (h and h/2) by
:func:`verify.sim.checks.check_scenario`, the same checks as ``verify simulate --check``:
a run the fixed step cannot resolve is repeated with error-controlled steps, and a
property no engine resolved is ``unresolved``, never held. The row records the engine
and, per property, whether its conclusion held whatever the assumptions (``*_conclusion``:
where the system behaved well outside the paper's premises). Figures come from the
coarse run of that pair, as ``verify simulate`` prints them (none when unresolved):

* convergence time: the first sample time t* after which |dbar(t) - d_r(t)| stays below
  the spec's threshold up to the end of the run (null if it is above it at the end);
* min tr(R-bar_r) (Lemma 1 keeps it >= 1 while sym(R_rl) > 0);
* max V rise: max over t of V(t) - min_{s<t} V(s), with S_h the human's KYP storage
  when it has one, else the running supply (Theorem 1: V does not increase);
* the human's supply w(T) = int_0^T e^T omega_h^b dt (eq. (7)) at the end.

A run that raises becomes a row with its error text and no figures: a campaign records
it and goes on.
"""

from __future__ import annotations

import os
import socket
import time
from typing import Any

import numpy as np

from verify.campaign.runs import Human, Run
from verify.inputs.campaign_spec import PROPERTIES
from verify.sim.properties import Status

HELD, FAILED, ASSUMPTION, UNRESOLVED = (str(Status.HELD), str(Status.FAILED),
                                       str(Status.ASSUMPTION_FAILED), str(Status.UNRESOLVED))
NOT_CHECKED, NOT_APPLICABLE = "not-checked", "n/a"

#: Columns of a row besides the parameters (None until known; a run that raised keeps them so).
OUTCOME_COLUMNS = ("human_gate", "engine", "engine_note", *[c for p in PROPERTIES for c in (
    p.replace("-", "_"), f"{p.replace('-', '_')}_violation",
    f"{p.replace('-', '_')}_tolerance", f"{p.replace('-', '_')}_conclusion")],
    "convergence_time", "dbar_error_end", "min_tr_Rbar_r", "max_V_rise", "supply_end",
    "uses_storage", "error", "wall_time", "worker")

_HUMANS: dict[tuple[object, ...], tuple[Any, str]] = {}  # per process: gating costs ~1 s


def column(prop: str) -> str:
    """The store's column of a property's outcome (``lemma1`` -> ``lemma1``)."""
    return prop.replace("-", "_")


def build_human(human: Human) -> tuple[Any, str]:
    """The simulator's human and its gate verdict (``passive``, ``not passive``, ...).

    As ``verify simulate --model``: an LTI model is gated exactly and, when passive with
    a KYP certificate, carries the storage x^T P x / 2 (:meth:`LTIHuman.gated`).
    """
    cache_key = tuple(human.identity().items())
    if cache_key in _HUMANS:
        return _HUMANS[cache_key]
    from verify.sim.command import SimulateSettings
    from verify.sim.command import build_human as simulate_human

    if human.kind == "model":
        from verify.passivity.io.model_file import model_from_bytes
        from verify.sim.humans import LTIHuman

        model = model_from_bytes(human.text or b"", human.label)
        made, decision = LTIHuman.gated(model)
        built = (made, str(decision.verdict))
    elif human.kind == "static":
        made, _ = simulate_human(SimulateSettings(human="static", gain=human.gain))
        built = (made, "passive" if (human.gain or 0.0) >= 0 else "not passive")
    else:
        made, _ = simulate_human(SimulateSettings(human=human.kind))
        built = (made, "not established")
    _HUMANS[cache_key] = built
    return built


def convergence_time(t: np.ndarray, error: np.ndarray, threshold: float) -> float | None:
    """First sample time after which ``error`` stays below ``threshold`` (None: never)."""
    below = error < threshold  # NaN (dbar undefined) counts as above
    if not below[-1]:
        return None
    above = np.flatnonzero(~below)
    return float(t[above[-1] + 1]) if above.size else float(t[0])


def parameters(run: Run) -> dict[str, Any]:
    """The row's parameter columns."""
    h = run.human
    return {
        "key": run.key, "human": h.label, "human_kind": h.kind, "human_sha256": h.sha256,
        "human_gain": h.gain, "k_s": run.k_s, "n": run.n, "seed": run.seed,
        "autonomous": run.autonomous, "reference": run.reference, "seconds": run.seconds,
        "step": run.step, "convergence_threshold": run.convergence_threshold,
    }


def _figures(run: Run, traj, E) -> dict[str, Any]:
    from verify.sim.properties import largest_rise

    error = np.linalg.norm(traj.dbar - traj.R_r[:, :, 2], axis=1)
    return {
        "convergence_time": convergence_time(traj.t, error, run.convergence_threshold),
        "dbar_error_end": float(error[-1]),
        "min_tr_Rbar_r": float(np.min(E.h) + 1.0),
        "max_V_rise": max(0.0, largest_rise(E.V)),
        "supply_end": float(traj.supply[-1]),
        "uses_storage": bool(E.uses_storage),
    }


def _finite(x: float) -> float | None:
    return float(x) if np.isfinite(x) else None


def simulate_run(run: Run) -> dict[str, Any]:
    """Simulate and check one run; returns the outcome columns (raises on a bad run)."""
    from verify.sim.checks import check_scenario
    from verify.sim.command import SimulateSettings, build_scenario
    from verify.sim.energy import energy
    from verify.sim.resolution import step_is_stable
    from verify.sim.run import simulate

    made, gate = build_human(run.human)
    settings = SimulateSettings(n=run.n, k_s=run.k_s, seed=run.seed, seconds=run.seconds,
                                step=run.step, autonomous=run.autonomous,
                                reference=run.reference)
    scenario = build_scenario(settings, made)
    out: dict[str, Any] = {"human_gate": gate}
    for p in PROPERTIES:
        out[column(p)] = NOT_CHECKED
        out[f"{column(p)}_violation"] = None
        out[f"{column(p)}_tolerance"] = None
        out[f"{column(p)}_conclusion"] = None
    if not run.properties:
        if step_is_stable(scenario, run.step):
            traj, out["engine"] = simulate(scenario, run.seconds, run.step), "fixed"
            out.update(_figures(run, traj, energy(traj)))
        else:
            out["engine"] = "none"
            out["engine_note"] = "step beyond CF4's stability bound; no property asked"
        return out
    checked = check_scenario(scenario, run.seconds, run.step, run.properties)
    out["engine"], out["engine_note"] = checked.engine, checked.note or None
    for p, result in checked.results.items():
        if result is None:
            out[column(p)] = NOT_APPLICABLE  # Theorem 1's convergence needs a constant R_r
            continue
        out[column(p)] = str(result.status)
        out[f"{column(p)}_violation"] = _finite(result.violation)
        out[f"{column(p)}_tolerance"] = _finite(result.tolerance)
        if result.conclusion is not None:
            out[f"{column(p)}_conclusion"] = HELD if result.conclusion else FAILED
    if checked.pair is not None and checked.pair.finite:
        out.update(_figures(run, checked.pair.coarse, checked.pair.energies(True)[0]))
    return out


def execute_run(run: Run) -> dict[str, Any]:
    """The row of one run: parameters, outcomes, figures, wall time, worker, error text.

    Never raises for a failure of the run itself (the row carries the error text).
    """
    start = time.perf_counter()
    row = parameters(run)
    row.update(dict.fromkeys(OUTCOME_COLUMNS))
    try:
        row.update(simulate_run(run))
        row["error"] = None
    except Exception as exc:  # a run's failure is data, not a crash of the campaign
        row["error"] = f"{type(exc).__name__}: {' '.join(str(exc).split())}"[:2000]
    row["wall_time"] = time.perf_counter() - start
    row["worker"] = f"{socket.gethostname()}:{os.getpid()}"
    return row


__all__ = ["ASSUMPTION", "FAILED", "HELD", "NOT_APPLICABLE", "NOT_CHECKED", "OUTCOME_COLUMNS",
           "UNRESOLVED",
           "build_human",
           "column", "convergence_time", "execute_run", "parameters", "simulate_run"]
