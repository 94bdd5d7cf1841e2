"""One run of a campaign: build the scenario, simulate, check the properties, make a row.

The scenario is the one ``verify simulate`` builds for the same settings
(:func:`verify.sim.command.build_scenario`: bodies within 45 degrees of the identity,
R_r within 60 degrees, drawn from the run's seed), so the command that a report prints
for a row rebuilds it exactly. The properties are those of :mod:`verify.sim.properties`
with their step-doubling tolerances (runs with h and h/2; the same checks as
``verify simulate --check``). Figures come from the h-run, as ``verify simulate`` prints
them:

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

HELD, FAILED, ASSUMPTION, NOT_CHECKED, NOT_APPLICABLE = (
    "held", "failed", "assumption-failed", "not-checked", "n/a")

#: Columns of a row besides the parameters (None until known; a run that raised keeps them so).
OUTCOME_COLUMNS = ("human_gate", *[c for p in PROPERTIES for c in (
    p.replace("-", "_"), f"{p.replace('-', '_')}_violation",
    f"{p.replace('-', '_')}_tolerance")], "convergence_time", "dbar_error_end",
    "min_tr_Rbar_r", "max_V_rise", "supply_end", "uses_storage", "error", "wall_time",
    "worker")

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
        from verify.inputs.campaign_spec import parse_model_bytes
        from verify.sim.humans import LTIHuman

        model = parse_model_bytes(human.text or b"", human.label)
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


def _status(holds: bool | None) -> str:
    return {True: HELD, False: FAILED, None: ASSUMPTION}[holds]


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


def simulate_run(run: Run) -> dict[str, Any]:
    """Simulate and check one run; returns the outcome columns (raises on a bad run)."""
    from verify.sim import properties as props
    from verify.sim.command import SimulateSettings, build_scenario
    from verify.sim.energy import energy
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
    if not run.properties:
        traj = simulate(scenario, run.seconds, run.step)
        out.update(_figures(run, traj, energy(traj)))
        return out
    pair = props.RunPair.of(scenario, run.seconds, run.step)
    checks = {
        "stealthiness": lambda: props.stealthiness(scenario, run.seconds, run.step),
        "quasi-average": lambda: props.quasi_average_axis(pair),
        "lemma1": lambda: props.lemma1_invariance(pair),
        "lyapunov": lambda: props.lyapunov_decrease(pair),
        "lasalle": lambda: props.lasalle_convergence(pair),
    }
    for p in run.properties:
        if p == "lasalle" and not scenario.reference.is_constant:
            out[column(p)] = NOT_APPLICABLE  # Theorem 1's convergence needs a constant R_r
            continue
        result = checks[p]()
        out[column(p)] = _status(result.holds)
        out[f"{column(p)}_violation"] = float(result.violation)
        out[f"{column(p)}_tolerance"] = float(result.tolerance)
    out.update(_figures(run, pair.coarse, pair.energies(True)[0]))
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
           "build_human",
           "column", "convergence_time", "execute_run", "parameters", "simulate_run"]
