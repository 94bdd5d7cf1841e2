"""The system calls a derivation file's process may not make (a seccomp filter).

A derivation file is the front end of the paper's Section 3 proof language: Python that
builds expressions and steps and hands them over as data. It needs no network, no
other process, no shared memory and no keys, so the sandbox's child
(:mod:`verify.proof.confine`) installs, last, a seccomp filter that refuses those
system calls with ``EPERM`` (``clone3`` with ``ENOSYS``, so that the C library falls
back to ``clone``, whose flags the filter can read):

* ``socket``/``socketpair`` of every family and ``connect``, ``bind``, ``listen``,
  ``accept``: no Unix socket under ``$HOME`` (an ssh ControlMaster, a container daemon),
  no netlink, nothing on the network namespace's loopback;
* a new process: ``fork``, ``vfork``, ``clone`` without ``CLONE_THREAD``, ``execve``.
  Threads share one address space, so the address-space limit of the memory budget
  (a hard limit the file cannot raise) bounds everything the file maps at once, a
  short burst included;
* memory outside that address space: ``memfd_create``, ``memfd_secret``, System V
  shared memory, ``io_uring``, ``userfaultfd``, larger pipe buffers
  (``fcntl(F_SETPIPE_SZ)``);
* keys (``keyctl``, ``add_key``, ``request_key``: keyrings are not namespaced; the child
  also joins a fresh session keyring first), new namespaces, mounts and ``chroot``,
  ``ptrace`` and reading or writing another process's memory, ``bpf``,
  ``perf_event_open``.

The filter is built with libseccomp through the ``pyseccomp`` binding (ctypes, the API
of libseccomp's own Python module); system calls of another architecture (the 32-bit
entry points of an x86-64 kernel) kill the process. Where the binding, libseccomp or
the kernel's seccomp is missing, :func:`unavailable` says why, and ``verify check
FILE.py`` refuses unless ``--unsandboxed`` (see ``verify/proof/TRUSTED.md``).
"""

from __future__ import annotations

import errno
import functools
import os

_CLONE_THREAD = 0x00010000
_F_SETPIPE_SZ = 1031
_PR_GET_SECCOMP = 21

#: Refused with EPERM, whatever the arguments.
DENIED = (
    # network and local sockets
    "socket", "socketpair", "connect", "bind", "listen", "accept", "accept4",
    # new processes and programs
    "fork", "vfork", "execve", "execveat",
    # memory the address-space limit does not see
    "memfd_create", "memfd_secret", "shmget", "shmat", "io_uring_setup",
    "userfaultfd",
    # keys, namespaces, mounts
    "keyctl", "add_key", "request_key", "unshare", "setns", "mount", "umount2",
    "pivot_root", "chroot", "open_tree", "move_mount", "fsopen", "fsmount", "fspick",
    "mount_setattr",
    # other processes and the kernel
    "ptrace", "process_vm_readv", "process_vm_writev", "pidfd_getfd", "bpf",
    "perf_event_open",
)
#: Those the filter must refuse on every kernel (the rest may be unknown to an old one).
ESSENTIAL = ("socket", "socketpair", "connect", "fork", "vfork", "execve",
             "memfd_create", "shmget", "keyctl", "add_key", "request_key")


class SyscallFilterError(Exception):
    """The filter could not be built or loaded (the file is then not run)."""


def _binding():
    import pyseccomp

    return pyseccomp


@functools.cache
def unavailable() -> str:
    """Why the filter cannot be installed here, or ""."""
    try:
        seccomp = _binding()
    except (ImportError, OSError, RuntimeError) as exc:
        return f"no seccomp binding (pyseccomp over libseccomp: {exc})"
    try:
        with open("/proc/self/status", encoding="ascii") as f:
            if not any(line.startswith("Seccomp:") for line in f):
                return "this kernel has no seccomp"
    except OSError:
        return "this system has no /proc/self/status"
    import ctypes

    libc = ctypes.CDLL(None, use_errno=True)
    if libc.prctl(_PR_GET_SECCOMP, 0, 0, 0, 0) < 0:
        return f"this kernel has no seccomp ({os.strerror(ctypes.get_errno())})"
    try:
        if seccomp.resolve_syscall(seccomp.Arch.NATIVE, "socket") < 0:
            return "libseccomp does not know this architecture's system calls"
    except (OSError, AttributeError) as exc:
        return f"libseccomp cannot be used ({exc})"
    return ""


def syscall_number(name: str) -> int:
    """The native number of a system call (negative if this architecture lacks it)."""
    seccomp = _binding()
    return int(seccomp.resolve_syscall(seccomp.Arch.NATIVE, name))


def install() -> None:
    """Load the filter into this process (and every thread and child it will have).
    Irreversible; needs no privilege (libseccomp sets ``no_new_privs``)."""
    why = unavailable()
    if why:
        raise SyscallFilterError(why)
    seccomp = _binding()
    try:
        flt = seccomp.SyscallFilter(seccomp.ALLOW)
        flt.set_attr(seccomp.Attr.ACT_BADARCH, seccomp.KILL_PROCESS)
        flt.set_attr(seccomp.Attr.CTL_TSYNC, 1)
        refuse = seccomp.ERRNO(errno.EPERM)
        for name in DENIED:
            if syscall_number(name) < 0 and name not in ESSENTIAL:
                continue  # not a system call of this architecture
            flt.add_rule(refuse, name)
        flt.add_rule(refuse, "clone", seccomp.Arg(0, seccomp.MASKED_EQ, _CLONE_THREAD, 0))
        flt.add_rule(seccomp.ERRNO(errno.ENOSYS), "clone3")
        flt.add_rule(refuse, "fcntl", seccomp.Arg(1, seccomp.EQ, _F_SETPIPE_SZ))
        flt.load()
    except (OSError, ValueError) as exc:
        raise SyscallFilterError(f"could not install the seccomp filter ({exc})") from None


__all__ = ["DENIED", "SyscallFilterError", "install", "syscall_number", "unavailable"]
