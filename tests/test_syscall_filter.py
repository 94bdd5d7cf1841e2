"""The seccomp filter of the sandbox (verify.proof.syscalls) on its own, in a plain child
process: what it refuses and what it leaves (threads, pipes, files)."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from verify.proof import syscalls

pytestmark = pytest.mark.skipif(bool(syscalls.unavailable()),
                                reason=f"no seccomp filter here: {syscalls.unavailable()}")

PROGRAM = r"""
import ctypes, errno, fcntl, json, os, socket, threading
from verify.proof import syscalls
libc = ctypes.CDLL(None, use_errno=True)
libc.syscall.restype = ctypes.c_long
out = {}

def attempt(name, f):
    try:
        f()
        out[name] = "done"
    except OSError as e:
        out[name] = errno.errorcode.get(e.errno, str(e.errno))

def raw(name, *args):
    n = libc.syscall(ctypes.c_long(syscalls.syscall_number(name)),
                     *(ctypes.c_long(a) for a in args))
    if n < 0:
        raise OSError(ctypes.get_errno(), name)

attempt("before", lambda: socket.socket(socket.AF_UNIX).close())
syscalls.install()
for family in ("AF_INET", "AF_INET6", "AF_UNIX", "AF_NETLINK", "AF_PACKET"):
    attempt(family, lambda: socket.socket(getattr(socket, family)))
attempt("socketpair", socket.socketpair)
attempt("connect", lambda: raw("connect", 0, 0, 0))
attempt("fork", os.fork)
attempt("exec", lambda: os.execv("/bin/true", ["true"]))
attempt("clone3", lambda: raw("clone3", 0, 0))
attempt("memfd", lambda: os.memfd_create("x"))
attempt("shmget", lambda: raw("shmget", 0, 4096, 0o1600))
attempt("keyctl", lambda: raw("keyctl", 0, -3, 0))
attempt("unshare", lambda: raw("unshare", 0x10000000))
attempt("ptrace", lambda: raw("ptrace", 0, 0, 0, 0))
r, w = os.pipe()
attempt("pipe_size", lambda: fcntl.fcntl(w, 1031, 1 << 20))
attempt("pipe", lambda: os.write(w, b"x"))
attempt("file", lambda: open("/dev/null", "w").write("x"))
t = threading.Thread(target=lambda: out.__setitem__("thread", "done"))
t.start()
t.join()
print(json.dumps(out))
"""


def test_the_filter_refuses_the_doors_and_leaves_threads_pipes_and_files():
    done = subprocess.run([sys.executable, "-c", PROGRAM], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout)
    assert out.pop("before") == "done"  # sockets work before the filter
    assert out.pop("clone3") == "ENOSYS"  # so that the C library falls back to clone
    for name in ("thread", "pipe", "file"):
        assert out.pop(name) == "done", name
    assert out == dict.fromkeys(out, "EPERM") and len(out) == 15
