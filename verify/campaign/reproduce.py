"""The ``verify simulate`` command that rebuilds one run of a campaign.

``verify simulate`` builds its scenario with :func:`verify.sim.command.build_scenario`
from n, k_s, the seed, the autonomous input, the reference, the run length and the step,
exactly as a campaign run does (:mod:`verify.campaign.execute`); its human is the same
model file (gated the same way), the VR operator, or the same static gain. Numbers are
written with ``repr``, which reads back as the same float, so the command's trajectory
is the campaign's h-run sample for sample, and ``--check`` repeats the property checks.
"""

from __future__ import annotations

import os
import shlex
from pathlib import Path

from verify.campaign.runs import Run


def shown_path(path: Path, cwd: Path | None = None) -> str:
    """``path`` relative to ``cwd`` (default the current folder) when it lies below it,
    else absolute."""
    base = Path(os.path.abspath(Path.cwd() if cwd is None else cwd))
    full = Path(os.path.abspath(path))
    return str(full.relative_to(base)) if full.is_relative_to(base) else str(full)


def simulate_arguments(run: Run, *, cwd: Path | None = None,
                       out: str | None = None) -> list[str]:
    """The arguments after ``verify`` (``simulate ...``) for ``run``."""
    args = ["simulate", "--n", str(run.n), "--ks", repr(float(run.k_s))]
    human = run.human
    if human.kind == "model":
        if human.path is None:
            raise ValueError(f"run {run.key}: the human's model file has no path")
        args += ["--model", shown_path(human.path, cwd)]
    elif human.kind == "static":
        args += ["--human", "static", "--gain", repr(float(human.gain or 0.0))]
    else:
        args += ["--human", human.kind]
    args += ["--seed", str(run.seed), "--autonomous", run.autonomous, "--reference",
             run.reference, "--seconds", repr(float(run.seconds)), "--step",
             repr(float(run.step))]
    if run.properties:
        args.append("--check")
    args += ["--no-plots", "--out", out or f"build/simulation/{run.key}"]
    return args


def simulate_command(run: Run, *, cwd: Path | None = None) -> str:
    """``verify simulate ...`` as one shell line."""
    return "verify " + " ".join(shlex.quote(a) for a in simulate_arguments(run, cwd=cwd))


__all__ = ["shown_path", "simulate_arguments", "simulate_command"]
