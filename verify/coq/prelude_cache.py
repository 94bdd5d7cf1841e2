"""The compiled prelude, kept once per Coq version and prelude text in a user cache folder.

Compiling the prelude (``verify/coq/prelude/*.v``) takes most of a small development's
time (a minute on a loaded machine) and gives the same ``.vo`` files every time for the
same ``coqc`` and the same sources. So it is compiled once into

    $XDG_CACHE_HOME/verify/coq-prelude/<key>/      (default ~/.cache/verify/...)

with ``key`` the sha256 of ``coqc --print-version``, the logical root and every prelude
file's name and text, and its ``.vo`` files are copied beside a development's sources
before the units are compiled. A cache entry is written to a temporary folder and renamed
into place when complete (concurrent runs cannot see half of one); its manifest holds
the sha256 of each ``.vo``, checked on every reuse (a damaged entry is compiled again).
Only ``.vo`` files that ``coqc`` itself wrote are reused, so the kernel still checks
every unit against the prelude's definitions as compiled by this ``coqc``; nothing
about the proofs is trusted to the cache that ``coqc`` would not re-check when loading
a ``.vo`` (it checks the library's digest and name).
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import tempfile
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

MANIFEST = "manifest.json"


def cache_root() -> Path:
    """``$XDG_CACHE_HOME/verify/coq-prelude`` (``~/.cache`` when the variable is unset or
    not absolute, as the XDG base directory specification says)."""
    base = os.environ.get("XDG_CACHE_HOME", "")
    root = Path(base) if base and Path(base).is_absolute() else Path.home() / ".cache"
    return root / "verify" / "coq-prelude"


@lru_cache(maxsize=8)
def coq_version(coqc: str) -> str:
    """``coqc --print-version`` (Coq and OCaml versions), or "" when it cannot run."""
    try:
        done = subprocess.run([coqc, "--print-version"], capture_output=True, text=True,
                              timeout=60, check=False)
    except (OSError, subprocess.TimeoutExpired):
        return ""
    return done.stdout.strip() if done.returncode == 0 else ""


def prelude_key(version: str, root: str, sources: Mapping[str, str]) -> str:
    """The cache key of a prelude: its sources (in order), the logical root, the version."""
    h = hashlib.sha256()
    for part in (version, root, *(f"{name}\0{text}" for name, text in sources.items())):
        h.update(part.encode("utf-8"))
        h.update(b"\0\0")
    return h.hexdigest()


@dataclass(frozen=True)
class CachedPrelude:
    """Where the compiled prelude is, and what was compiled now to put it there."""

    folder: Path
    compiled: tuple[tuple[str, float], ...]  # (file, seconds); empty when reused

    def summary(self) -> str:
        if not self.compiled:
            return f"prelude reused from the cache {self.folder}"
        parts = ", ".join(f"{rel} {s:.1f} s" for rel, s in self.compiled)
        total = sum(s for _, s in self.compiled)
        return f"prelude compiled once into the cache {self.folder} ({parts}; {total:.1f} s)"


def _sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _valid(folder: Path, names: list[str]) -> bool:
    try:
        manifest = json.loads((folder / MANIFEST).read_text(encoding="utf-8"))
        return all(manifest.get(f"{n}.vo") == _sha(folder / f"{n}.vo") for n in names)
    except (OSError, ValueError, AttributeError):
        return False


def compiled_prelude(sources: Mapping[str, str], root: str, *, coqc: str = "coqc",
                     timeout_seconds: float = 600.0,
                     compile_one=None) -> CachedPrelude | None:
    """The cache folder holding the prelude ``sources`` (name -> text, in dependency
    order) compiled by ``coqc``, compiling it first when absent. None when it cannot be
    used (no version, a cache folder that cannot be written, or coqc refusing the
    prelude: the caller then compiles it beside the development and reports why).

    ``compile_one(folder, rel, coqc, timeout) -> (ok, output, seconds)`` runs coqc."""
    version = coq_version(coqc)
    if not version or compile_one is None:
        return None
    names = list(sources)
    folder = cache_root() / prelude_key(version, root, sources)
    if _valid(folder, names):
        return CachedPrelude(folder, ())
    try:
        folder.parent.mkdir(parents=True, exist_ok=True)
        work = Path(tempfile.mkdtemp(prefix="building-", dir=folder.parent))
    except OSError:
        return None
    try:
        timings = []
        for name, text in sources.items():
            (work / f"{name}.v").write_text(text, encoding="utf-8")
        for name in names:
            ok, _output, seconds = compile_one(work, f"{name}.v", coqc, timeout_seconds)
            timings.append((f"{name}.v", seconds))
            if not ok:
                return None
        manifest = {f"{n}.vo": _sha(work / f"{n}.vo") for n in names}
        manifest["coqc"] = version
        (work / MANIFEST).write_text(json.dumps(manifest, indent=1, sort_keys=True),
                                     encoding="utf-8")
        if folder.exists():  # another run finished first, or a damaged entry
            if _valid(folder, names):
                return CachedPrelude(folder, tuple(timings))
            shutil.rmtree(folder, ignore_errors=True)
        try:
            os.rename(work, folder)
        except OSError:
            if not _valid(folder, names):
                return None
        return CachedPrelude(folder, tuple(timings))
    except OSError:
        return None
    finally:
        shutil.rmtree(work, ignore_errors=True)


def install(cached: CachedPrelude, names: list[str], into: Path) -> bool:
    """Copy the compiled prelude's ``.vo`` files beside a development's sources (which
    must hold the same prelude ``.v`` files); False when a copy fails."""
    try:
        for name in names:
            shutil.copyfile(cached.folder / f"{name}.vo", Path(into) / f"{name}.vo")
    except OSError:
        return False
    return True


__all__ = ["CachedPrelude", "cache_root", "compiled_prelude", "coq_version", "install",
           "prelude_key"]
