"""Running ``coqc`` in the tests: a prelude compiled once per test session, module by
module and only as far as the tests need it, and the small helpers the Coq test modules
share (compile a file, compile a unit's text, compile a whole written development).

The prelude is compiled lazily into one folder shared by the session's worker processes
(:data:`SHARED_ENV`, set by ``conftest.py`` before ``pytest -n`` starts its workers); each
module is compiled there once, under a file lock, and its ``.vo`` copied beside the
files that need it. A worker that needs only ``QCert`` never waits for the trajectory
files, and two workers never compile the same module twice."""

from __future__ import annotations

import fcntl
import os
import shutil
import subprocess
import tempfile
from collections.abc import Sequence
from pathlib import Path

from verify.coq.development import (
    LOGICAL_ROOT,
    prelude_sources,
    required_prelude,
    write_development,
)
from verify.coq.unit import CoqUnit

#: The environment variable naming the session's shared prelude folder.
SHARED_ENV = "VERIFY_TEST_COQ_PRELUDE"

#: Folders whose prelude ``.vo`` files are filled in on demand (see :func:`run_coqc`).
_LAZY: set[Path] = set()


def _coqc(folder: Path, rel: str) -> subprocess.CompletedProcess:
    return subprocess.run([shutil.which("coqc") or "coqc", "-R", ".", LOGICAL_ROOT, rel],
                          cwd=folder, capture_output=True, text=True, timeout=600)


def _shared_folder() -> Path:
    where = os.environ.get(SHARED_ENV)
    if not where:  # a lone process (no conftest): a folder of its own
        where = tempfile.mkdtemp(prefix="verify-coq-prelude-")
        os.environ[SHARED_ENV] = where
    folder = Path(where)
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def _shared_module(name: str, sources: dict[str, str]) -> Path:
    """``name.vo`` compiled once in the shared folder (its prelude dependencies first)."""
    shared = _shared_folder()
    for dep in required_prelude(sources, [sources[name]]):
        if dep != name:
            _shared_module(dep, sources)
    target = shared / f"{name}.vo"
    with open(shared / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not target.exists():
            (shared / f"{name}.v").write_text(sources[name])
            done = _coqc(shared, f"{name}.v")
            assert done.returncode == 0, f"prelude {name}.v: " + done.stdout + done.stderr
    return target


def _install_prelude_for(folder: Path, text: str) -> None:
    """Copy into ``folder`` the compiled prelude modules ``text`` requires."""
    sources = prelude_sources()
    for name in required_prelude(sources, [text]):
        if not (folder / f"{name}.vo").exists():
            shutil.copyfile(_shared_module(name, sources), folder / f"{name}.vo")


def run_coqc(folder: Path, rel: str, check: bool = False) -> subprocess.CompletedProcess:
    """``coqc -R . VerifyCoq rel`` in ``folder``; with ``check``, assert that it passed.
    In a folder from :func:`compile_prelude`, the prelude modules ``rel`` needs are
    compiled (once per session) and copied in first."""
    if Path(folder).resolve() in _LAZY:
        _install_prelude_for(Path(folder), (Path(folder) / rel).read_text())
    done = _coqc(folder, rel)
    if check:
        assert done.returncode == 0, done.stdout + done.stderr
    return done


def compile_prelude(folder: Path) -> Path:
    """``folder`` with every prelude module's source; each is compiled when a file
    compiled there first needs it (:func:`run_coqc`)."""
    for name, text in prelude_sources().items():
        (folder / f"{name}.v").write_text(text)
    _LAZY.add(Path(folder).resolve())
    return folder


def compiles(folder: Path, text: str, name: str = "Attack") -> bool:
    """Does ``coqc`` accept ``text`` as module ``name`` beside the compiled prelude?"""
    (folder / f"{name}.v").write_text(text)
    return run_coqc(folder, f"{name}.v").returncode == 0


def compile_development(folder: Path, units: Sequence[CoqUnit]
                        ) -> tuple[bool, str | None, str]:
    """Write a development of ``units`` and compile it file by file (``All.v`` aside):
    ``(True, None, "")``, or ``(False, the failing file, coqc's output)``. A prelude file
    written unchanged is taken from the session's compiled prelude."""
    sources = prelude_sources()
    for f in write_development(folder, units):
        if f.name == "All.v":
            continue
        if sources.get(f.stem) == f.read_text():
            shutil.copyfile(_shared_module(f.stem, sources), f.with_suffix(".vo"))
            continue
        done = run_coqc(folder, f.name)
        if done.returncode != 0:
            return False, f.name, done.stdout + done.stderr
    return True, None, ""
