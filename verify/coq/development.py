"""Writing a Coq development to a folder and compiling it with ``coqc``.

A development is the prelude (``verify/coq/prelude/*.v``, copied as is), one file per
:class:`~verify.coq.unit.CoqUnit`, a ``_CoqProject`` mapping the folder to the logical
root :data:`LOGICAL_ROOT`, and ``All.v`` that ``Require``s every unit and prints the
assumptions of every top theorem. ``coqc`` on the files in order is the whole check.
"""

from __future__ import annotations

import shutil
import subprocess
from collections.abc import Sequence
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from verify.artefacts.atomic import write_all_atomic
from verify.coq.unit import CoqUnit

LOGICAL_ROOT = "VerifyCoq"

# Prelude modules in dependency order (each may Require the ones before it).
PRELUDE_ORDER: tuple[str, ...] = ("SO3",)


def prelude_sources() -> dict[str, str]:
    """The prelude's ``.v`` files by module name, in :data:`PRELUDE_ORDER` then by name."""
    folder = resources.files("verify.coq") / "prelude"
    found = {
        entry.name[:-2]: entry.read_text(encoding="utf-8")
        for entry in folder.iterdir()
        if entry.name.endswith(".v")
    }
    ordered = [name for name in PRELUDE_ORDER if name in found]
    ordered += sorted(name for name in found if name not in PRELUDE_ORDER)
    return {name: found[name] for name in ordered}


def render_development(units: Sequence[CoqUnit]) -> dict[str, str]:
    """Every file of the development by relative path (no I/O; bytes depend only on units)."""
    names = [unit.name for unit in units]
    if len(set(names)) != len(names):
        raise ValueError("two Coq units share a module name")
    prelude = prelude_sources()
    clash = set(names) & set(prelude) | ({"All"} & set(names))
    if clash:
        raise ValueError(f"Coq unit names clash with the prelude: {sorted(clash)}")
    files: dict[str, str] = {f"{name}.v": text for name, text in prelude.items()}
    files.update({f"{unit.name}.v": unit.text for unit in units})
    order = [*prelude, *names]
    files["_CoqProject"] = f"-R . {LOGICAL_ROOT}\n" + "".join(f"{name}.v\n" for name in order)
    lines = [f"From {LOGICAL_ROOT} Require {name}." for name in names]
    for unit in units:
        lines += [f"Print Assumptions {unit.name}.{theorem}." for theorem in unit.theorems]
    files["All.v"] = "\n".join(lines) + "\n"
    files["_CoqProject"] += "All.v\n"
    return files


def write_development(folder: Path, units: Sequence[CoqUnit]) -> list[Path]:
    """Write the development into ``folder``; return the ``.v`` files in compile order."""
    files = render_development(units)
    folder = Path(folder)
    write_all_atomic({folder / rel: text for rel, text in files.items()})
    order = files["_CoqProject"].splitlines()[1:]
    return [folder / rel for rel in order]


@dataclass(frozen=True)
class CompileResult:
    """What ``coqc`` said: success, the file that failed (if any) and its output."""

    ok: bool
    failed_file: str | None
    output: str


def coqc_available(coqc: str = "coqc") -> bool:
    """True when a ``coqc`` executable is on the PATH."""
    return shutil.which(coqc) is not None


def compile_development(folder: Path, *, coqc: str = "coqc",
                        timeout_seconds: float = 600.0) -> CompileResult:
    """Compile every file of the development in ``_CoqProject`` order with ``coqc``."""
    folder = Path(folder)
    project = (folder / "_CoqProject").read_text(encoding="utf-8").splitlines()
    outputs: list[str] = []
    for rel in project[1:]:
        done = subprocess.run(
            [coqc, "-R", ".", LOGICAL_ROOT, rel], cwd=folder, capture_output=True,
            text=True, timeout=timeout_seconds, check=False,
        )
        outputs.append(done.stdout + done.stderr)
        if done.returncode != 0:
            return CompileResult(False, rel, "".join(outputs))
    return CompileResult(True, None, "".join(outputs))
