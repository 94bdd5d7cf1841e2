"""The namespaces a derivation file runs in, and the process tree the checker watches.

``verify check FILE.py`` runs the file's Python (the front end that turns it into the
data of the paper's Section 3 proof language) as the first process of new user, PID,
mount, IPC, UTS and network namespaces, made by util-linux ``unshare`` (Python 3.11 has
no ``os.unshare``). Run by root, the namespaces are made as the unprivileged user
``nobody`` (``setpriv``) where ``nobody`` can run the interpreter, so the file's
processes count against a process limit (``RLIMIT_NPROC`` does not bind root) and own
nothing of the checker's; otherwise as the checker's user, mapped to root of the new
user namespace, which the child leaves without capabilities. In its PID namespace the
file cannot name, signal or ptrace the checker; when the namespace's first process
ends, the kernel kills every other process in it, so nothing the file starts outlives
the check. Inside, the child confines itself before the file runs
(:mod:`verify.proof.confine`), last with a seccomp filter
(:mod:`verify.proof.syscalls`: no sockets, no new process, no memfd or shared memory,
no keys); where that filter cannot be installed the sandbox counts as unavailable.

The checker also watches the tree from outside: :func:`tree` lists the namespace's
processes (through the ``children`` lists of ``/proc``), :func:`resident_bytes` adds up
their memory, and the caller kills the namespace when the total passes the budget. This
is a second line: the filter allows the file one process, whose hard address-space limit
is the budget, so no burst passes between two looks.
"""

from __future__ import annotations

import functools
import os
import shutil
import subprocess
import sys
from pathlib import Path

import verify
from verify.proof import syscalls
from verify.stopping import child_processes

#: The file's processes at most (its first process included).
MAX_PROCESSES = 16
NOBODY = 65534

_NAMESPACES = ("--user", "--map-root-user", "--pid", "--fork", "--kill-child", "--mount",
               "--mount-proc", "--net", "--ipc", "--uts")


def prefix() -> list[str]:
    """The command that puts what follows it in new namespaces (as ``nobody`` when run
    by root and ``nobody`` can run this interpreter and read the package)."""
    unshare = shutil.which("unshare") or "unshare"
    out = [unshare, *_NAMESPACES, "--"]
    if os.geteuid() == 0 and _mode()[0] == "nobody":
        setpriv = shutil.which("setpriv") or "setpriv"
        out = [setpriv, f"--reuid={NOBODY}", f"--regid={NOBODY}", "--clear-groups", *out]
    return out


def unavailable() -> str:
    """Why namespaces cannot be made here, or "" (tried once per process)."""
    return _mode()[1]


def as_nobody() -> bool:
    """Whether the file's processes run as ``nobody`` (else as the checker's user,
    mapped to root of their own user namespace, without any capability after
    :func:`verify.proof.confine.confine`)."""
    return _mode()[0] == "nobody"


@functools.cache
def _mode() -> tuple[str, str]:
    if not os.path.isdir("/proc/self/ns"):
        return "", "this system has no Linux namespaces"
    for tool in ("unshare", *(("setpriv",) if os.geteuid() == 0 else ())):
        if shutil.which(tool) is None:
            return "", f"the util-linux tool {tool!r} is not installed"
    why = syscalls.unavailable()
    if why:
        return "", f"no seccomp filter can be installed here: {why}"
    unshare = [shutil.which("unshare") or "unshare", *_NAMESPACES, "--"]
    child = Path(verify.__file__).resolve().parent / "proof" / "child.py"
    # the interpreter runs, and the package and the libraries it needs can be read
    probe = [sys.executable, "-I", "-c",
             "import os, sys, importlib.util as u; sys.exit(0 if os.access("
             f"{str(child)!r}, os.R_OK) and all(u.find_spec(m) for m in "
             "('numpy', 'sympy')) else 1)"]
    env = {"PYTHONDONTWRITEBYTECODE": "1"}
    tries = [("user", unshare)]
    if os.geteuid() == 0:
        setpriv = shutil.which("setpriv") or "setpriv"
        tries.insert(0, ("nobody", [setpriv, f"--reuid={NOBODY}", f"--regid={NOBODY}",
                                    "--clear-groups", *unshare]))
    why = ""
    for mode, command in tries:
        try:
            done = subprocess.run([*command, *probe], stdin=subprocess.DEVNULL,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                  timeout=30, start_new_session=True, env=env, cwd="/")
        except (OSError, subprocess.SubprocessError) as exc:
            why = f"unshare could not run ({exc})"
            continue
        if done.returncode == 0:
            return mode, ""
        why = " ".join(done.stderr.decode("ascii", "replace").split())[:200]
        why = f"unshare cannot make user, PID, mount and network namespaces ({why})"
    return "", why


def tree(root: int) -> list[int]:
    """``root`` and every process below it (a process that moved out of the tree, by
    dying or being re-parented, is not counted; in a PID namespace orphans are
    re-parented to its first process, so they stay in the tree)."""
    seen, todo = [], [root]
    while todo and len(seen) < 10 * MAX_PROCESSES:
        pid = todo.pop()
        if pid in seen:
            continue
        seen.append(pid)
        todo.extend(child_processes(pid))
    return seen


def resident_bytes(pids: list[int]) -> int:
    """Resident memory of the processes, in bytes (a process gone meanwhile counts 0)."""
    page = os.sysconf("SC_PAGE_SIZE")
    total = 0
    for pid in pids:
        try:
            with open(f"/proc/{pid}/statm", encoding="ascii") as f:
                total += int(f.read().split()[1]) * page
        except (OSError, ValueError, IndexError):
            continue
    return total


__all__ = ["MAX_PROCESSES", "as_nobody", "prefix", "resident_bytes", "tree",
           "unavailable"]
