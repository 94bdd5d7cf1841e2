"""Derivations for ``verify check``: read from data, or made by a Python file run in a
sandbox, and taken over as data.

``verify check FILE.json`` reads derivations data (:func:`read_data_file`: opened without
blocking, a regular file only, size-bounded) and rebuilds it with the checker's own
classes; nothing of the user runs. ``verify check FILE.py`` is the front end that makes
that data: the file's text is handed on a memfd to a child process
(:mod:`verify.proof.child`) that is the first process of its own namespaces
(:mod:`verify.proof.sandbox`) and confines itself before the file runs
(:mod:`verify.proof.confine`); the child writes the derivations (schema of
:mod:`verify.proof.wire`) on a pipe that the checker reads with a size and time bound,
while it watches the memory and the number of the file's processes together; at the end
the whole PID namespace is killed and the checker continues only once every process of
the file is gone. The child's output and exit code are discarded; an early exit, a
crash, a timeout or missing data is a malformed file (one line, exit 2). Without
namespaces the front end refuses unless asked to run unsandboxed. See
``verify/proof/TRUSTED.md``; the language is that of the paper's Section 3.
"""

from __future__ import annotations

import json
import os
import select
import signal
import subprocess
import sys
import time
from pathlib import Path

import verify
from verify.errors import VerifyInputError
from verify.inputs.files import open_regular
from verify.proof import sandbox
from verify.proof.budget import DEFAULT_BUDGET, Budget
from verify.proof.derivation import Derivation
from verify.proof.expr import ProofSyntaxError
from verify.proof.rebuild import loads
from verify.proof.wire import LIMITS
from verify.stopping import child_processes


def _limits(budget: Budget):
    def apply() -> None:
        import resource

        from verify.process_tree import die_with_parent

        die_with_parent()  # a checker that ends takes the file's processes with it

        cpu = max(1, int(budget.seconds + 0.999))
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 5))
        resource.setrlimit(resource.RLIMIT_AS, (budget.memory, budget.memory))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        written = 2 * LIMITS["bytes"]  # no file the child writes grows past this
        resource.setrlimit(resource.RLIMIT_FSIZE, (written, written))
        # pipe buffers are kernel memory outside the address space (64 KB each)
        hard = resource.getrlimit(resource.RLIMIT_NOFILE)[1]
        files = MAX_OPEN_FILES if hard == resource.RLIM_INFINITY else min(hard, MAX_OPEN_FILES)
        resource.setrlimit(resource.RLIMIT_NOFILE, (files, files))

    return apply


#: Files the child may have open at once (hard limit).
MAX_OPEN_FILES = 256

#: Bytes of a derivation file's own text the checker reads and hands to the child.
MAX_SOURCE_BYTES = 16 * 2**20


def dumpable_off() -> None:
    """PR_SET_DUMPABLE 0 for the checker: no process of the same user may ptrace it or
    read its memory (the file's processes run in other namespaces as well)."""
    import ctypes

    ctypes.CDLL(None, use_errno=True).prctl(4, 0, 0, 0, 0)  # PR_SET_DUMPABLE, libc's


def _read_bounded(path: Path, limit: int) -> bytes:
    """At most ``limit + 1`` bytes of a regular file (opened without blocking, so a FIFO
    or a device is refused at once: :func:`verify.inputs.files.open_regular`)."""
    with open_regular(path) as f:
        try:
            return f.read(limit + 1)
        except OSError as exc:
            raise VerifyInputError(f"{path}: cannot be read ({exc.strerror})") from None


def _read_source(path: Path) -> bytes:
    source = _read_bounded(path, MAX_SOURCE_BYTES)
    if len(source) > MAX_SOURCE_BYTES:
        raise VerifyInputError(f"{path}: a derivation file has at most {MAX_SOURCE_BYTES} "
                               "bytes")
    return source


def load_isolated(path: Path, *, budget: Budget = DEFAULT_BUDGET,
                  sandboxed: bool = True) -> list[Derivation]:
    """Run ``path`` in a child process (in its own namespaces unless ``sandboxed`` is
    False) and return the derivations rebuilt from the data it hands over."""
    text = run_front_end(path, budget=budget, sandboxed=sandboxed)
    try:
        return loads(text)
    except ProofSyntaxError as exc:
        raise VerifyInputError(f"{path}: {exc}") from None


def run_front_end(path: Path, *, budget: Budget = DEFAULT_BUDGET,
                  sandboxed: bool = True) -> str:
    """The derivations data (``verify-derivations/1`` text) the file hands over."""
    if path.suffix != ".py":
        raise VerifyInputError(f"{path}: a derivation file is a Python file (.py) or its "
                               "data (.json)")
    if not path.exists():  # what else it is (a FIFO, a device) the bounded read says
        raise VerifyInputError(f"{path}: no such file")
    if sandboxed:
        why = sandbox.unavailable()
        if why:
            raise VerifyInputError(f"{path}: not run: {why}; --unsandboxed runs it without "
                                   "a sandbox (only for a file you trust)")
    source = _read_source(path)
    dumpable_off()
    preload()  # before the file runs (unsandboxed, it could rewrite a module on disk)
    name = str(path.resolve())
    root = str(Path(verify.__file__).resolve().parents[1])
    env = {k: v for k, v in os.environ.items() if k in _KEPT_ENVIRONMENT}
    env["PYTHONPATH"] = root
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    env["HOME"] = "/tmp"
    for name_ in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        env.setdefault(name_, "1")
    memfd = os.memfd_create("verify-derivation-source", 0)
    argv = [sys.executable, "-m", "verify.proof.child", name, str(memfd)]
    if sandboxed:
        argv = [*sandbox.prefix(), *argv, str(sandbox.MAX_PROCESSES)]
    try:
        os.write(memfd, source)
        os.lseek(memfd, 0, os.SEEK_SET)
        try:
            proc = subprocess.Popen(
                argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                stderr=subprocess.DEVNULL, env=env, preexec_fn=_limits(budget),
                start_new_session=True, pass_fds=(memfd,), cwd="/")
        except (OSError, subprocess.SubprocessError) as exc:
            raise VerifyInputError(f"{path}: no process to load the file in ({exc})") from None
    finally:
        os.close(memfd)
    return _collect(path, proc, budget, sandboxed)


#: Modules the checker imports only when a step needs them (SOS steps, Groebner bases).
LAZY_MODULES = ("sympy.polys.groebnertools", "scipy.sparse", "cvxpy", "verify.sos.search",
                "verify.sos.prove", "verify.sos.certificate", "verify.proof.sos_step",
                "verify.proof.sos_rebuild", "verify.proof.confirm", "verify.proof.falsify")


def preload() -> None:
    """Import every module the checker may need later in the run, so none is read from
    disk after a derivation file ran."""
    import importlib

    for name in LAZY_MODULES:
        importlib.import_module(name)


def read_data_file(path: Path) -> list[Derivation]:
    """Derivations from a data file (``verify-derivations/1``, as ``--emit`` writes it):
    read with a size bound, never executed. A FIFO, a device or a file past the bound
    is refused without blocking."""
    raw = _read_bounded(path, LIMITS["bytes"])
    if len(raw) > LIMITS["bytes"]:
        raise VerifyInputError(f"{path}: derivations data larger than {LIMITS['bytes']} "
                               "bytes")
    try:
        text = raw.decode("ascii")
    except UnicodeDecodeError:
        raise VerifyInputError(f"{path}: derivations data is ASCII JSON (non-ASCII "
                               "characters are written as \\u escapes)") from None
    try:
        return loads(text)
    except ProofSyntaxError as exc:
        raise VerifyInputError(f"{path}: {exc}") from None


def data_text(derivations: list[Derivation]) -> str:
    """The derivations as a data file: the checker's own objects encoded again, so the
    text is canonical (what was checked, not what a file wrote)."""
    from verify.proof.wire import encode

    data = encode(derivations)
    lines = []
    for key, value in data.items():
        head = json.dumps(key) + ": "
        if isinstance(value, list) and value:
            items = ",\n  ".join(json.dumps(v, ensure_ascii=True, separators=(",", ":"))
                                 for v in value)
            lines.append(f"{head}[\n  {items}]")
        else:
            lines.append(head + json.dumps(value, ensure_ascii=True))
    return "{" + ",\n ".join(lines) + "}\n"


#: Environment variables the child keeps (locale and thread settings; no tokens).
_KEPT_ENVIRONMENT = ("PATH", "LANG", "LC_ALL", "LC_CTYPE", "OPENBLAS_NUM_THREADS",
                     "OMP_NUM_THREADS", "MKL_NUM_THREADS", "VIRTUAL_ENV")


def _collect(path: Path, proc: subprocess.Popen, budget: Budget, sandboxed: bool) -> str:
    """Read the child's handover within the size and time budgets, watching the total
    memory of its process tree; kill everything of the file at the end."""
    assert proc.stdout is not None
    fd = proc.stdout.fileno()
    limit = LIMITS["bytes"] + 64
    chunks: list[bytes] = []
    size = 0
    deadline = time.monotonic() + budget.seconds
    why = ""
    try:
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                why = (f"loading the file exceeded its budget of {budget.seconds:g} s "
                       "(raise it with --budget-seconds)")
                break
            ready, _, _ = select.select([fd], [], [], min(left, 0.05))
            if ready:
                chunk = os.read(fd, 1 << 20)
                if not chunk:
                    break  # every process of the file has closed the pipe (or ended)
                chunks.append(chunk)
                size += len(chunk)
                if size > limit:
                    why = f"the file's derivations exceed {LIMITS['bytes']} bytes of data"
                    break
            elif proc.poll() is not None and not sandboxed:
                break  # the child ended; its stray processes are killed below
            pids = sandbox.tree(proc.pid)
            if len(pids) > sandbox.MAX_PROCESSES + 3:
                why = f"the file started more than {sandbox.MAX_PROCESSES} processes"
                break
            if sandbox.resident_bytes(pids) > budget.memory:
                why = (f"the file's processes exceeded the memory budget of "
                       f"{budget.memory / 2**30:g} GB together")
                break
    finally:
        _kill(proc, sandboxed)
    if why:
        raise VerifyInputError(f"{path}: {why}")
    data = b"".join(chunks)
    if data[:1] == b"F":
        reason = data[1:200].decode("ascii", "replace")
        raise VerifyInputError(f"{path}: not run: the sandbox could not be completed "
                               f"({reason}); --unsandboxed runs it without one")
    if data[:1] != b"C":
        raise VerifyInputError(f"{path}: no process could load the file (exit code "
                               f"{proc.returncode})")
    try:
        text = data[1:].decode("ascii")
    except UnicodeDecodeError:
        raise VerifyInputError(f"{path}: malformed derivations data") from None
    payload = None
    if text.startswith('{"error"'):
        try:
            payload = json.loads(text)
        except ValueError:
            payload = None
    if not text:
        code = proc.returncode
        how = (f"was killed by signal {-code}" if code < 0 else f"exited (exit code {code})")
        hint = " or exceeded its memory budget" if code < 0 or code == 1 else ""
        raise VerifyInputError(f"{path}: the file {how}{hint} while loading, before "
                               "handing its derivations over; a derivation file only "
                               "defines derivations")
    if isinstance(payload, dict) and set(payload) == {"error"}:
        message = payload["error"] if isinstance(payload["error"], str) else "malformed"
        raise VerifyInputError(" ".join(message.split())[:2000] or f"{path}: malformed")
    prefix = '{"derivations":'
    if not (text.startswith(prefix) and text.endswith("}")):
        raise VerifyInputError(f"{path}: malformed derivations data")
    return text[len(prefix):-1]


def _kill(proc: subprocess.Popen, sandboxed: bool) -> None:
    """End every process of the file: in the sandbox, the namespace's first process
    (the kernel then kills the rest of its PID namespace); unsandboxed, its session."""
    if sandboxed:  # unshare ends only after its child, the namespace's first process,
        # was reaped, which the kernel does only once every process of the namespace died
        give_up = time.monotonic() + 10
        while proc.poll() is None and time.monotonic() < give_up:
            for pid in child_processes(proc.pid):
                try:
                    os.kill(pid, signal.SIGKILL)
                except (ProcessLookupError, PermissionError):
                    pass
            try:
                proc.wait(timeout=0.01)
            except subprocess.TimeoutExpired:
                pass
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    proc.wait()
    if proc.stdout is not None:
        proc.stdout.close()
