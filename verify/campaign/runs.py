"""A campaign spec expanded into runs, each keyed by a hash of what determines its result.

A run is one closed-loop scenario of Sections 2-3 (the ``verify simulate`` scenario for
its n, k_s, seed, autonomous input and reference) with one human operator, integrated
for ``seconds`` with ``step`` and checked for the chosen properties. Its key is a
SHA-256 of every parameter that can change its row: the numbers (by their exact float
value), the names, the property list, the convergence threshold, and for a model-file
human the hash of the file's bytes (not its path: a renamed file keeps its runs, an
edited one gets new ones). Runs with equal keys are merged.

Members of a human family are drawn here (seeded) and turned into model files whose
numbers are the exact decimal expansions of the drawn floats, so that a member's file
denotes exactly the model that was drawn and ``verify simulate --model`` rebuilds it.
"""

from __future__ import annotations

import functools
import hashlib
import itertools
import json
from collections.abc import Iterator
from dataclasses import dataclass
from decimal import Decimal
from pathlib import Path

import numpy as np

from verify.inputs.campaign_spec import CampaignSpec, HumanEntry
from verify.so3 import Array

KEY_VERSION = 2  # bump when the meaning of a row's columns changes

#: The code a row's figures depend on: the simulator (with its time grid), the paper's
#: system, SO(3) maps and the per-run checks. Their bytes enter every run key, so
#: ``--resume`` after a change of this code runs everything again instead of mixing rows
#: of two versions in one store.
_CODE = ("verify/inputs/time_grid.py", "verify/sim", "verify/system", "verify/so3.py",
         "verify/campaign/execute.py")


@functools.cache
def code_fingerprint() -> str:
    """SHA-256 (24 hex digits) of the source files in :data:`_CODE`, in path order."""
    root = Path(__file__).resolve().parents[2]
    digest = hashlib.sha256()
    for entry in _CODE:
        path = root / entry
        files = sorted(path.rglob("*.py")) if path.is_dir() else [path]
        for f in files:
            digest.update(f.relative_to(root).as_posix().encode() + b"\0")
            digest.update(f.read_bytes() + b"\0")
    return digest.hexdigest()[:24]


@dataclass(frozen=True)
class Human:
    """The human of a run: ``kind`` model (``text`` a model file's bytes), vr or static."""

    kind: str
    label: str
    text: bytes | None = None
    sha256: str = ""
    gain: float | None = None
    path: Path | None = None  # where the model file lives (for the reproducing command)

    def identity(self) -> dict[str, object]:
        """What of the human enters the run key (never the path or the label)."""
        if self.kind == "model":
            return {"kind": "model", "sha256": self.sha256}
        if self.kind == "static":
            return {"kind": "static", "gain": float(self.gain).hex()}
        return {"kind": self.kind}


@dataclass(frozen=True)
class Run:
    """One run of a campaign; :attr:`key` identifies its row in the store."""

    key: str
    human: Human
    k_s: float
    n: int
    seed: int
    autonomous: str
    reference: str
    seconds: float
    step: float
    properties: tuple[str, ...]
    convergence_threshold: float


def run_key(human: Human, k_s: float, n: int, seed: int, autonomous: str, reference: str,
            seconds: float, step: float, properties: tuple[str, ...], threshold: float) -> str:
    """A stable hash of the run's parameters (floats by their exact binary value)."""
    payload = {
        "version": KEY_VERSION, "code": code_fingerprint(), "human": human.identity(),
        "k_s": float(k_s).hex(), "n": n,
        "seed": seed, "autonomous": autonomous, "reference": reference,
        "seconds": float(seconds).hex(), "step": float(step).hex(),
        "properties": list(properties), "convergence_threshold": float(threshold).hex(),
    }
    text = json.dumps(payload, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:24]


def spec_fingerprint(spec: CampaignSpec) -> str:
    """SHA-256 (24 hex digits) of what a spec sweeps: its name, every axis (floats by
    their exact value), the humans (model files by content) and the checks. Comments,
    layout and the spec's path do not enter it; the simulator's code does not either
    (a code change re-runs rows, it does not make the store another campaign's)."""
    humans = [{"kind": h.kind, "sha256": h.sha256 or "",
               "gain": None if h.gain is None else float(h.gain).hex(),
               "family": h.family or "", "count": h.count, "seed": h.seed}
              for h in spec.humans]
    payload = {
        "name": spec.name, "k_s": [float(k).hex() for k in spec.k_s], "n": list(spec.n),
        "seeds": list(spec.seeds), "autonomous": list(spec.autonomous),
        "reference": list(spec.reference), "seconds": [float(t).hex() for t in spec.seconds],
        "step": [float(h).hex() for h in spec.step], "humans": humans,
        "properties": list(spec.properties),
        "convergence_threshold": float(spec.convergence_threshold).hex(),
    }
    text = json.dumps(payload, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:24]


def exact_decimal(x: float) -> str:
    """The exact decimal expansion of a float, as a TOML number (it reads back exactly)."""
    if not np.isfinite(x):
        raise ValueError(f"not a finite number: {x}")
    text = format(Decimal(float(x)), "f")
    return text if "." in text else text + ".0"


def _matrix(M: Array) -> str:
    M = np.atleast_2d(np.asarray(M, dtype=float))
    if M.size == 0:
        return "[]"
    rows = (", ".join(exact_decimal(v) for v in row) for row in M)
    return "[" + ", ".join(f"[{r}]" for r in rows) + "]"


def model_file_text(name: str, A: Array, B: Array, C: Array, D: Array, note: str) -> bytes:
    """A state-space model file (``verify gate`` format) holding exactly these floats."""
    A = np.asarray(A, dtype=float)
    lines = [f"# {note}", f"name = {json.dumps(name)}", "", "[state_space]"]
    if A.size == 0:
        lines += ["A = []", "B = []", "C = []"]
    else:
        lines += [f"A = {_matrix(A)}", f"B = {_matrix(B)}", f"C = {_matrix(C)}"]
    lines.append(f"D = {_matrix(D)}")
    return ("\n".join(lines) + "\n").encode()


def family_member(family: str, seed: int) -> Human:
    """Member ``seed`` of a human family, as a model file (module docstring)."""
    from verify.sim.humans import StaticGainHuman
    from verify.sim.random_scenarios import random_passive_human

    if family != "random-passive":
        raise ValueError(f"unknown family {family!r}")
    drawn = random_passive_human(np.random.default_rng(seed))
    name = f"random-passive seed {seed}"
    note = ("drawn by verify.sim.random_scenarios.random_passive_human(default_rng("
            f"{seed})); numbers are the exact values of the drawn floats")
    if isinstance(drawn, StaticGainHuman):
        text = model_file_text(name, np.zeros((0, 0)), None, None, drawn.K, note)
    else:
        text = model_file_text(name, drawn.A, drawn.B, drawn.C, drawn.D, note)
    return Human("model", name, text=text, sha256=hashlib.sha256(text).hexdigest())


def _humans(entry: HumanEntry) -> list[Human]:
    if entry.kind == "model":
        return [Human("model", entry.label, text=entry.text, sha256=entry.sha256 or "",
                      path=entry.path)]
    if entry.kind == "family":
        return [family_member(entry.family or "", entry.seed + i) for i in range(entry.count)]
    return [Human(entry.kind, entry.label, gain=entry.gain)]


def _distinct_labels(humans: list[Human]) -> list[Human]:
    """Humans with one label per identity (two files named alike get their hash added)."""
    from dataclasses import replace

    identities: dict[str, set[tuple[object, ...]]] = {}
    for h in humans:
        identities.setdefault(h.label, set()).add(tuple(h.identity().items()))
    return [replace(h, label=f"{h.label} [{h.sha256[:8]}]")
            if len(identities[h.label]) > 1 and h.sha256 else h for h in humans]


def _distinct(values: tuple) -> list:
    """The values in order, repeats dropped (floats by exact value, as in the key)."""
    seen: dict[object, object] = {}
    for v in values:
        seen.setdefault(float(v).hex() if isinstance(v, float) else v, v)
    return list(seen.values())


def distinct_humans(spec: CampaignSpec) -> list[Human]:
    """The spec's humans, one per identity (equal model files are one human)."""
    humans = _distinct_labels([h for entry in spec.humans for h in _humans(entry)])
    seen: dict[tuple[object, ...], Human] = {}
    for h in humans:
        seen.setdefault(tuple(h.identity().items()), h)
    return list(seen.values())


def _axes(spec: CampaignSpec) -> list[list]:
    return [_distinct(a) for a in (spec.k_s, spec.n, spec.autonomous, spec.reference,
                                   spec.seconds, spec.step, spec.seeds)]


def run_total(spec: CampaignSpec, humans: list[Human] | None = None) -> int:
    """How many runs :func:`iter_runs` yields (without expanding them)."""
    count = len(distinct_humans(spec) if humans is None else humans)
    for axis in _axes(spec):
        count *= len(axis)
    return count


def iter_runs(spec: CampaignSpec, humans: list[Human] | None = None) -> Iterator[Run]:
    """Every run of ``spec``, lazily, in a fixed order (humans, k_s, n, autonomous,
    reference, seconds, step, seeds). Humans and axis values are made distinct first, so
    the runs' keys are distinct with no set of keys held. ``humans`` (from
    :func:`distinct_humans`, e.g. with file paths set) replaces the spec's."""
    humans = distinct_humans(spec) if humans is None else humans
    for human, k_s, n, auto, ref, T, h, seed in itertools.product(humans, *_axes(spec)):
        key = run_key(human, k_s, n, seed, auto, ref, T, h, spec.properties,
                      spec.convergence_threshold)
        yield Run(key, human, k_s, n, seed, auto, ref, T, h, spec.properties,
                  spec.convergence_threshold)


def expand(spec: CampaignSpec) -> list[Run]:
    """Every run of ``spec`` as a list (:func:`iter_runs`)."""
    return list(iter_runs(spec))


def place_family_files(humans: list[Human], folder: Path) -> list[Human]:
    """Write the model files of drawn humans into ``folder`` (atomically) and return the
    humans with those paths set, so that their reproducing commands can name a file."""
    from dataclasses import replace

    from verify.artefacts.atomic import write_atomic

    out = []
    for human in humans:
        if human.kind == "model" and human.path is None and human.text is not None:
            stem = human.label.replace(" ", "-")
            path = folder / f"{stem}-{human.sha256[:12]}.toml"
            if not (path.is_file() and path.read_bytes() == human.text):
                write_atomic(path, human.text)
            human = replace(human, path=path)
        out.append(human)
    return out


def write_family_files(runs: list[Run], folder: Path) -> list[Run]:
    """The runs with their drawn humans' model files written (:func:`place_family_files`)."""
    from dataclasses import replace

    placed: dict[tuple[object, ...], Human] = {}
    out = []
    for run in runs:
        ident = tuple(run.human.identity().items())
        if ident not in placed:
            placed[ident] = place_family_files([run.human], folder)[0]
        out.append(replace(run, human=placed[ident]))
    return out


__all__ = ["Human", "Run", "distinct_humans", "exact_decimal", "expand", "family_member",
           "iter_runs", "model_file_text", "place_family_files", "run_key", "run_total",
           "spec_fingerprint", "write_family_files"]
