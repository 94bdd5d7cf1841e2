"""Running ``coqc`` in the tests: one compiled prelude per test process, and the small
helpers the Coq test modules share (compile a file, compile a unit's text, compile a
whole written development)."""

from __future__ import annotations

import shutil
import subprocess
from collections.abc import Sequence
from pathlib import Path

from verify.coq.development import LOGICAL_ROOT, prelude_sources, write_development
from verify.coq.unit import CoqUnit


def run_coqc(folder: Path, rel: str, check: bool = False) -> subprocess.CompletedProcess:
    """``coqc -R . VerifyCoq rel`` in ``folder``; with ``check``, assert that it passed."""
    done = subprocess.run([shutil.which("coqc") or "coqc", "-R", ".", LOGICAL_ROOT, rel],
                          cwd=folder, capture_output=True, text=True, timeout=600)
    if check:
        assert done.returncode == 0, done.stdout + done.stderr
    return done


def compile_prelude(folder: Path) -> Path:
    """Every prelude module written to ``folder`` and compiled, in dependency order."""
    for name, text in prelude_sources().items():
        (folder / f"{name}.v").write_text(text)
        run_coqc(folder, f"{name}.v", check=True)
    return folder


def compiles(folder: Path, text: str, name: str = "Attack") -> bool:
    """Does ``coqc`` accept ``text`` as module ``name`` beside the compiled prelude?"""
    (folder / f"{name}.v").write_text(text)
    return run_coqc(folder, f"{name}.v").returncode == 0


def compile_development(folder: Path, units: Sequence[CoqUnit]
                        ) -> tuple[bool, str | None, str]:
    """Write a development of ``units`` and compile it file by file (``All.v`` aside):
    ``(True, None, "")``, or ``(False, the failing file, coqc's output)``."""
    for f in write_development(folder, units):
        if f.name == "All.v":
            continue
        done = run_coqc(folder, f.name)
        if done.returncode != 0:
            return False, f.name, done.stdout + done.stderr
    return True, None, ""
