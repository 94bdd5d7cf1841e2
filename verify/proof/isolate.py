"""Run a derivation file in its own process and take its derivations over as data.

``verify check FILE`` never runs FILE's code in the checker process: a child process
(:mod:`verify.proof.child`, a fresh interpreter) loads the file under resource limits
(CPU time, address space and file size by ``resource.setrlimit``, a wall-clock timeout,
its own process group killed at the end) and writes the derivations in the schema of
:mod:`verify.proof.wire`. The checker rebuilds them with its own classes. The child's
output and exit code are discarded; an early exit, a crash, a timeout or missing data is
a malformed file (one line, exit 2). See ``verify/proof/TRUSTED.md``.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

import verify
from verify.errors import VerifyInputError
from verify.proof.budget import DEFAULT_BUDGET, Budget
from verify.proof.derivation import Derivation
from verify.proof.expr import ProofSyntaxError
from verify.proof.rebuild import loads
from verify.proof.wire import LIMITS


def _limits(budget: Budget):
    def apply() -> None:
        import resource

        cpu = max(1, int(budget.seconds + 0.999))
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 5))
        resource.setrlimit(resource.RLIMIT_AS, (budget.memory, budget.memory))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        written = 2 * LIMITS["bytes"]  # no file the child writes grows past this
        resource.setrlimit(resource.RLIMIT_FSIZE, (written, written))

    return apply


def load_isolated(path: Path, *, budget: Budget = DEFAULT_BUDGET) -> list[Derivation]:
    """Load ``path`` in a child process and return the derivations rebuilt from its data."""
    if not path.is_file():
        raise VerifyInputError(f"{path}: no such file")
    if path.suffix != ".py":
        raise VerifyInputError(f"{path}: a derivation file is a Python file (.py)")
    root = str(Path(verify.__file__).resolve().parents[1])
    env = dict(os.environ)
    env["PYTHONPATH"] = root + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    for name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        env.setdefault(name, "1")
    with tempfile.TemporaryDirectory(prefix="verify-check-") as tmp:
        out = Path(tmp) / "derivations.json"
        try:
            proc = subprocess.Popen(
                [sys.executable, "-m", "verify.proof.child", str(path), str(out)],
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL, env=env, preexec_fn=_limits(budget),
                start_new_session=True)
        except (OSError, subprocess.SubprocessError) as exc:
            raise VerifyInputError(f"{path}: no process to load the file in ({exc})") from None
        try:
            code = proc.wait(timeout=budget.seconds)
        except subprocess.TimeoutExpired:
            code = None
        finally:
            try:
                os.killpg(proc.pid, signal.SIGKILL)  # the file's own subprocesses too
            except (ProcessLookupError, PermissionError):
                pass
            proc.wait()
        if code is None:
            raise VerifyInputError(f"{path}: loading the file exceeded its budget of "
                                   f"{budget.seconds:g} s (raise it with --budget-seconds)")
        try:
            size = out.stat().st_size
        except OSError:
            size = 0
        if size > LIMITS["bytes"]:
            raise VerifyInputError(f"{path}: the file's derivations exceed "
                                   f"{LIMITS['bytes']} bytes of data")
        try:
            text = out.read_text(encoding="ascii")
            payload = json.loads(text) if text.startswith('{"error"') else None
        except (OSError, UnicodeDecodeError, ValueError):
            text, payload = None, None
        if text is None:
            why = (f"was killed by signal {-code}" if code < 0 else f"exited (exit code {code})")
            hint = (" or exceeded its memory budget" if code < 0 or code == 1 else "")
            raise VerifyInputError(f"{path}: the file {why}{hint} while loading, before "
                                   "handing its derivations over; a derivation file only "
                                   "defines derivations")
        if isinstance(payload, dict) and set(payload) == {"error"}:
            message = payload["error"] if isinstance(payload["error"], str) else "malformed"
            raise VerifyInputError(" ".join(message.split())[:2000] or f"{path}: malformed")
        prefix = '{"derivations":'
        if not (text.startswith(prefix) and text.endswith("}")):
            raise VerifyInputError(f"{path}: malformed derivations data")
        try:
            return loads(text[len(prefix):-1])
        except ProofSyntaxError as exc:
            raise VerifyInputError(f"{path}: {exc}") from None
