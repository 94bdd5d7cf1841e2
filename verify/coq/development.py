"""Writing a Coq development to a folder and compiling it with ``coqc``.

A development is the prelude modules its units need (``verify/coq/prelude/*.v``, copied
as is: those a unit ``Require``s, and what they ``Require`` in turn), one file per
:class:`~verify.coq.unit.CoqUnit`, a ``_CoqProject`` mapping the folder to the logical
root :data:`LOGICAL_ROOT`, and ``All.v`` that ``Require``s every unit, names every top
theorem in one tuple and prints its assumptions (those of all the theorems). ``coqc``
on the files in order is the whole check.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import subprocess
import tempfile
import threading
import time
from collections.abc import Mapping, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from verify.artefacts.atomic import write_all_atomic
from verify.coq.audit import (
    forbidden_commands,
    stated_theorems,
    statement_problems,
    template_problems,
)
from verify.coq.unit import CoqExportError, CoqUnit
from verify.process_tree import die_with_parent

LOGICAL_ROOT = "VerifyCoq"
#: The tuple of the top theorems of ``machine_words`` units in ``All.v``.
WORD_THEOREMS = "word_theorems"

# Prelude modules in dependency order (each may Require the ones before it).
PRELUDE_ORDER: tuple[str, ...] = ("SO3", "QCert", "SOSCert", "BandCert", "WitnessCert",
                                  "RobustCert", "PoleCert", "RotSurj", "Traj", "Lemma1Inv",
                                  "Thm1Energy", "Barbalat", "Converge", "LTIHuman", "Thm1LTI")


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


_REQUIRE = re.compile(
    rf"From\s+{LOGICAL_ROOT}\s+Require(?:\s+(?:Import|Export))?\s+([^.]*)\.")


def required_prelude(prelude: Mapping[str, str], texts: Sequence[str]) -> dict[str, str]:
    """The prelude modules ``texts`` require, directly or through another prelude module,
    in the prelude's order: a gate's or a user's development does not carry (or
    compile) the trajectory files only the paper's conclusions need."""
    needed: set[str] = set()
    pending = [name for text in texts for match in _REQUIRE.finditer(text)
               for name in match.group(1).split()]
    while pending:
        name = pending.pop()
        if name in prelude and name not in needed:
            needed.add(name)
            pending += [dep for match in _REQUIRE.finditer(prelude[name])
                        for dep in match.group(1).split()]
    return {name: text for name, text in prelude.items() if name in needed}


def prelude_digest() -> str:
    """SHA-256 (hex) of the prelude: each module's name and text in :data:`PRELUDE_ORDER`,
    so two installations that print the same digest export against the same definitions."""
    import hashlib

    digest = hashlib.sha256()
    for name, text in prelude_sources().items():
        digest.update(f"{name}.v\0{len(text.encode())}\0".encode())
        digest.update(text.encode())
    return digest.hexdigest()


def _files_of_units(units: Sequence[CoqUnit]) -> dict[str, list[CoqUnit]]:
    """The units by the file (stem) they are written into, in order of first use: a
    bundle's units together (:mod:`verify.coq.bundle`), every other unit alone."""
    groups: dict[str, list[CoqUnit]] = {}
    for unit in units:
        groups.setdefault(unit.bundle or unit.name, []).append(unit)
    bundled = {unit.name for unit in units if unit.bundle}
    for stem, group in groups.items():
        if len(group) > 1 and any(not unit.bundle for unit in group):
            raise ValueError(f"Coq bundle name clashes with a unit's name: {stem}")
        for unit in group:
            if unit.bundle:
                continue
            used = {name for match in _REQUIRE.finditer(unit.text)
                    for name in match.group(1).split()}
            if used & bundled:
                raise ValueError(f"Coq unit {unit.name} requires a unit written into a "
                                 f"bundle: {sorted(used & bundled)[0]}")
    return groups


def _naming_all(name: str, theorems: Sequence[str]) -> list[str]:
    """``Definition name : unit := let _ := t1 in … tt.``: a term that names every
    theorem (so its ``Print Assumptions`` are theirs), typed without building the
    product of their statements that a tuple's type needs (a second per hundred
    theorems)."""
    return [f"Definition {name} : unit :=", *(f"  let _ := {t} in" for t in theorems),
            "  tt."]


def render_development(units: Sequence[CoqUnit], *,
                       extra: Mapping[str, str] | None = None) -> dict[str, str]:
    """Every file of the development by relative path (no I/O; bytes depend only on units).

    A unit with a :attr:`~verify.coq.unit.CoqUnit.bundle` is a module of that file
    (:func:`verify.coq.bundle.bundle_text`), which ``All.v`` imports so that its
    theorems keep their names ``<unit>.<theorem>``.
    ``extra``: further files (not Coq sources, e.g. the list of certificates not exported).
    """
    from verify.coq.bundle import bundle_text

    names = [unit.name for unit in units]
    if len(set(names)) != len(names):
        raise ValueError("two Coq units share a module name")
    groups = _files_of_units(units)
    prelude = prelude_sources()
    clash = (set(names) | set(groups)) & {*prelude, "All"}
    if clash:
        raise ValueError(f"Coq unit names clash with the prelude: {sorted(clash)}")
    if units:
        prelude = required_prelude(prelude, [unit.text for unit in units])
    files: dict[str, str] = {f"{name}.v": text for name, text in prelude.items()}
    for stem, group in groups.items():
        files[f"{stem}.v"] = bundle_text(stem, group) if group[0].bundle else group[0].text
    order = [*prelude, *groups]
    files["_CoqProject"] = f"-R . {LOGICAL_ROOT}\n" + "".join(f"{name}.v\n" for name in order)
    lines = [f"From {LOGICAL_ROOT} Require {'Import ' if group[0].bundle else ''}{stem}."
             for stem, group in groups.items()]
    tops = [f"{unit.name}.{theorem}" for unit in units if not unit.machine_words
            for theorem in unit.theorems]
    words = [f"{unit.name}.{theorem}" for unit in units if unit.machine_words
             for theorem in unit.theorems]
    if tops:
        # One Print Assumptions of a term naming every top theorem: Coq walks the
        # theorems' common dependencies (the real numbers' library) once, where a
        # Print Assumptions per theorem walked them once per theorem (most of All.v's
        # time). An axiom of any one theorem is an axiom of the term.
        lines += ["", "(** Every top theorem of the development. *)",
                  *_naming_all("top_theorems", tops),
                  "Print Assumptions top_theorems."]
    if words:
        # Printed last and apart: these theorems may also rest on Coq's primitive
        # integers (verify.coq.audit.MACHINE_INTEGER_AXIOMS), the others may not.
        lines += ["", "(** The top theorems checked on machine integers. *)",
                  *_naming_all(WORD_THEOREMS, words),
                  f"Print Assumptions {WORD_THEOREMS}."]
    files["All.v"] = "\n".join(lines) + "\n"
    files["_CoqProject"] += "All.v\n"
    for rel, text in (extra or {}).items():
        if rel in files or rel.endswith(".v") or "/" in rel:
            raise ValueError(f"extra file name clashes or is not a plain name: {rel!r}")
        files[rel] = text
    return files


class CoqAuditError(CoqExportError):
    """A development the audit refuses (a command outside the templates, a forbidden
    command, a statement that is not the one exported): nothing is written."""


def audit_problems(files: Mapping[str, str], units: Sequence[CoqUnit]) -> list[str]:
    """What the audit refuses in rendered (or re-read) files: forbidden commands,
    commands outside the templates (units and ``All.v``; the prelude is ours), and
    statements that differ from those the exporter made (the round trip)."""
    from verify.coq.bundle import module_texts

    prelude = [f"{name}.v" for name in prelude_sources()]
    problems = forbidden_commands(files) + template_problems(files, skip=prelude)
    for stem, group in _files_of_units(units).items():
        rel = f"{stem}.v"
        text = files.get(rel, "")
        if not group[0].bundle:
            texts = {group[0].name: text}
        else:
            header, texts = module_texts(text)
            extra = [name for name in texts if name not in {u.name for u in group}]
            problems += [f"{rel}: module {name} is not a unit the exporter wrote"
                         for name in extra]
            problems += [f"{rel}: {name} stated before the first module"
                         for name in stated_theorems(header)]
        for unit in group:
            if unit.name not in texts:
                problems.append(f"{rel}: unit {unit.name} is missing")
            elif unit.statements:
                problems += statement_problems(rel, texts[unit.name], dict(unit.statements),
                                               dict(unit.terms))
    return problems


def _refuse(problems: list[str]) -> None:
    if problems:
        more = f" (and {len(problems) - 1} more)" if len(problems) > 1 else ""
        raise CoqAuditError(f"Coq audit refused the development: {problems[0]}{more}")


def _read_back(folder: Path, files: Mapping[str, str]) -> dict[str, str]:
    """The files as read from ``folder`` (the round trip reads what was written)."""
    return {rel: (folder / rel).read_text(encoding="utf-8") for rel in files}


def write_development(folder: Path, units: Sequence[CoqUnit], *,
                      extra: Mapping[str, str] | None = None) -> list[Path]:
    """Write the development into ``folder``; return the ``.v`` files in compile order.

    The files are rendered and audited (:func:`audit_problems`) before anything is
    written, written to a temporary folder beside ``folder``, read back and audited
    again (the round trip), then moved into place: a new folder by one rename; in an
    existing one, each file atomically, and files an earlier development listed in its
    ``_CoqProject`` and this one does not are removed (nothing else is touched). A
    refusal raises :class:`CoqAuditError` with nothing written.
    """
    files = render_development(units, extra=extra)
    _refuse(audit_problems(files, units))
    for rel, text in files.items():
        try:
            text.encode("utf-8")
        except UnicodeEncodeError:
            raise CoqAuditError(f"Coq development: {rel} is not writable as UTF-8") from None
    folder = Path(folder)
    folder.parent.mkdir(parents=True, exist_ok=True)
    stage = Path(tempfile.mkdtemp(prefix=f".{folder.name}.partial-", dir=folder.parent))
    try:
        for rel, text in files.items():
            (stage / rel).write_text(text, encoding="utf-8")
        back = _read_back(stage, files)
        if back != dict(files):
            raise CoqAuditError("Coq development: a file read back differs from the one "
                                "written")
        _refuse(audit_problems(back, units))
        if not os.path.lexists(folder):
            os.rename(stage, folder)
        else:
            stale = [rel for rel in _listed(folder) if rel not in files]
            write_all_atomic({folder / rel: text for rel, text in files.items()})
            for rel in stale:
                (folder / rel).unlink(missing_ok=True)
            if _read_back(folder, files) != dict(files):
                raise CoqAuditError(f"Coq development: a file read back from {folder} "
                                    "differs from the one written")
    finally:
        shutil.rmtree(stage, ignore_errors=True)
    order = files["_CoqProject"].splitlines()[1:]
    return [folder / rel for rel in order]


def _listed(folder: Path) -> list[str]:
    """The ``.v`` files of an earlier development of ours in ``folder`` (plain names)."""
    try:
        lines = (folder / "_CoqProject").read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError):
        return []
    if not lines or lines[0] != f"-R . {LOGICAL_ROOT}":
        return []
    return [ln for ln in lines[1:] if ln.endswith(".v") and "/" not in ln and ln != ".v"]


@dataclass(frozen=True)
class CompileResult:
    """What ``coqc`` said: success, the file that failed (if any) and its output."""

    ok: bool
    failed_file: str | None
    output: str
    #: (file, seconds) for every file compiled, in order (the failed one last).
    timings: tuple[tuple[str, float], ...] = ()
    #: how the prelude was had (compiled here, compiled into the cache, reused from it)
    prelude: str = ""


def coqc_available(coqc: str = "coqc") -> bool:
    """True when a ``coqc`` executable is on the PATH."""
    return shutil.which(coqc) is not None


#: ``coqc`` processes running now (from any thread), ended at once by a stop.
_RUNNING: set[subprocess.Popen] = set()
_RUNNING_LOCK = threading.Lock()


def _compile_one(folder: Path, rel: str, coqc: str,
                 timeout_seconds: float) -> tuple[bool, str, float]:
    start = time.perf_counter()
    # coqc dies with the thread that started it (and so with this process)
    with _RUNNING_LOCK:
        proc = subprocess.Popen([coqc, "-R", ".", LOGICAL_ROOT, rel], cwd=folder,
                                stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True,
                                preexec_fn=die_with_parent)
        _RUNNING.add(proc)
    try:
        out, err = proc.communicate(timeout=timeout_seconds)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        return False, f"coqc: {rel} not done within {timeout_seconds:g} s\n", \
            time.perf_counter() - start
    except BaseException:  # a stop: coqc ends with the compilation, not after it
        proc.kill()
        proc.wait()
        raise
    finally:
        with _RUNNING_LOCK:
            _RUNNING.discard(proc)
    return proc.returncode == 0, out + err, time.perf_counter() - start


def _stop_running() -> None:
    """Kill every ``coqc`` still running (a stop, or an error, ends the compilation)."""
    with _RUNNING_LOCK:
        running = list(_RUNNING)
    for proc in running:
        with contextlib.suppress(OSError):
            proc.kill()


def unit_levels(folder: Path, units: list[str]) -> list[list[str]]:
    """The units in rounds: each unit after every unit it ``Require``s (a gate's
    ``Thm1_`` unit after its certificate's unit); the units of one round are independent
    of each other, so they may be compiled at once. A cycle (not written by us) puts the
    rest in one last round, compiled in order."""
    names = {rel[:-2]: rel for rel in units}
    needs = {}
    for rel in units:
        text = (folder / rel).read_text(encoding="utf-8")
        needs[rel] = {names[name] for match in _REQUIRE.finditer(text)
                      for name in match.group(1).split()
                      if name in names and name != rel[:-2]}
    levels: list[list[str]] = []
    done: set[str] = set()
    left = list(units)
    while left:
        ready = [rel for rel in left if needs[rel] <= done]
        if not ready:
            levels.append(left)
            break
        levels.append(ready)
        done.update(ready)
        left = [rel for rel in left if rel not in done]
    return levels


def compile_development(folder: Path, *, coqc: str = "coqc",
                        timeout_seconds: float = 600.0, jobs: int = 1,
                        prelude_cache: bool = True) -> CompileResult:
    """Compile every file of the development with ``coqc``: the prelude in
    ``_CoqProject`` order, then the units (with ``jobs`` > 1, in rounds of units that
    require none of each other, ``jobs`` at a time: :func:`unit_levels`), then
    ``All.v``. Stops at the first file ``coqc`` refuses.

    With ``prelude_cache`` the prelude's ``.vo`` files come from the user's cache
    (:mod:`verify.coq.prelude_cache`: compiled there once per Coq version and prelude
    text). A development without units compiles nothing."""
    folder = Path(folder)
    project = (folder / "_CoqProject").read_text(encoding="utf-8").splitlines()[1:]
    prelude = [rel for rel in project if rel[:-2] in PRELUDE_ORDER]
    last = [rel for rel in project if rel == "All.v"]
    units = [rel for rel in project if rel not in prelude and rel not in last]
    outputs: list[str] = []
    timings: list[tuple[str, float]] = []
    if not units:
        return CompileResult(True, None, "", (), "no unit: nothing compiled")
    how = "prelude compiled beside the development"
    if prelude_cache and prelude:
        from verify.coq.prelude_cache import compiled_prelude, install

        names = [rel[:-2] for rel in prelude]
        sources = {n: (folder / f"{n}.v").read_text(encoding="utf-8") for n in names}
        cached = compiled_prelude(sources, LOGICAL_ROOT, coqc=coqc,
                                  timeout_seconds=timeout_seconds, compile_one=_compile_one)
        if cached is not None and install(cached, names, folder):
            prelude, how = [], cached.summary()

    def run_in_order(files: list[str]) -> str | None:
        for rel in files:
            ok, text, seconds = _compile_one(folder, rel, coqc, timeout_seconds)
            outputs.append(text)
            timings.append((rel, seconds))
            if not ok:
                return rel
        return None

    def run_at_once(files: list[str]) -> str | None:
        pool = ThreadPoolExecutor(max_workers=jobs)
        try:
            done = list(pool.map(
                lambda rel: _compile_one(folder, rel, coqc, timeout_seconds), files))
        except BaseException:  # a stop: no thread waits for its coqc to finish
            pool.shutdown(wait=False, cancel_futures=True)
            _stop_running()
            pool.shutdown(wait=True)
            raise
        pool.shutdown(wait=True)
        first = None
        for rel, (ok, text, seconds) in zip(files, done, strict=True):
            outputs.append(text)
            timings.append((rel, seconds))
            if not ok and first is None:
                first = rel
        return first

    failed = run_in_order(prelude)
    if failed is None and units:
        levels = unit_levels(folder, units) if jobs > 1 else [units]
        for level in levels:
            failed = run_at_once(level) if jobs > 1 and len(level) > 1 \
                else run_in_order(level)
            if failed is not None:
                break
    if failed is None:
        failed = run_in_order(last)
    return CompileResult(failed is None, failed, "".join(outputs), tuple(timings), how)


def check_files(files: Mapping[str, str], *, coqc: str = "coqc",
                timeout_seconds: float = 600.0, jobs: int = 1,
                prelude_cache: bool = True) -> CompileResult:
    """Compile rendered files in a temporary folder (leaves no ``.vo`` beside the sources)."""
    with tempfile.TemporaryDirectory(prefix="verify-coq-") as tmp:
        for rel, text in files.items():
            (Path(tmp) / rel).write_text(text, encoding="utf-8")
        return compile_development(Path(tmp), coqc=coqc, timeout_seconds=timeout_seconds,
                                   jobs=jobs, prelude_cache=prelude_cache)
