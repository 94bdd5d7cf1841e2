"""The sandbox's last doors, each attack with its sound outcome (verify/proof/TRUSTED.md).

A derivation file's process may not open a socket of any family nor connect to a Unix
socket it can see through the read-only mounts; it cannot hold more memory than
``--budget-memory`` through memfd, shared memory, a burst or a raised limit; it cannot
read a key of the caller's session keyring; and ``/dev/stdout``-style output paths are
refused, never replaced by a regular file.

Each attack runs as root (the file then runs as ``nobody``) and as a normal user (the
whole check run as ``nobody`` through ``setpriv``: the file runs as that user mapped to
root of its own user namespace), where the machine allows it.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import socket
import stat
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

import verify
from verify.proof import sandbox

pytestmark = pytest.mark.skipif(bool(sandbox.unavailable()),
                                reason=f"no sandbox here: {sandbox.unavailable()}")

PROJECT = Path(verify.__file__).resolve().parents[1]
NOBODY = 65534
HEADER = """
import ctypes, os, sys
from verify.proof import Context, Derivation, by_bound, square
ctx = Context("user")
x = ctx.scalar("x")
seen = []
"""
REPORT = ("d = Derivation('|'.join(seen), x * x + 1, ctx).ge(1, by_bound(square(x)))\n"
          "DERIVATIONS = [d]\n")
WHO = ("root", "user")


def attempt(label: str, code: str) -> str:
    """Lines of the file that record whether ``code`` ran (``label:done``) or raised."""
    body = "\n".join("    " + line for line in code.splitlines())
    return (f"try:\n{body}\n    seen.append('{label}:done')\n"
            f"except BaseException as e:\n    seen.append('{label}:' + type(e).__name__)\n")


def _as(who: str, *, sandboxed: bool = True) -> list[str]:
    """The command prefix that runs the check as ``who``, or skips with the reason."""
    if who == "root":
        if os.geteuid() != 0:
            pytest.skip("the root case needs root")
        return []
    if os.geteuid() != 0:
        return []  # already a normal user
    setpriv = [shutil.which("setpriv") or "setpriv", f"--reuid={NOBODY}", f"--regid={NOBODY}",
               "--clear-groups"]
    if sandboxed and not sandbox.as_nobody():
        pytest.skip("nobody cannot run this interpreter in its own namespaces here (it lives "
                    "where nobody may not go), so no check can run as a normal user")
    if not sandboxed:
        probe = subprocess.run([*setpriv, sys.executable, "-c", "import verify"],
                               capture_output=True, timeout=120, cwd="/")
        if probe.returncode != 0:
            pytest.skip("nobody cannot run this interpreter here")
    return setpriv


@contextlib.contextmanager
def workdir():
    """A folder any user can use, outside the sandbox's private /tmp (so that what is
    placed there is visible to the file through the read-only mounts)."""
    path = Path(tempfile.mkdtemp(prefix=".verify-doors-", dir=PROJECT))
    try:
        path.chmod(0o777)
        yield path
    finally:
        shutil.rmtree(path, ignore_errors=True)


def check_command(work: Path, body: str, *extra: str) -> list[str]:
    path = work / "attack.py"
    path.write_text(HEADER + body)
    path.chmod(0o644)
    return [sys.executable, "-m", "verify.cli", "check", str(path), "--quick",
            "--certificates", str(work / "c"), "--json", str(work / "out.json"), *extra]


def environment(home: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k in ("PATH", "LANG", "LC_ALL")}
    env.update(HOME=str(home), PYTHONDONTWRITEBYTECODE="1")
    return env


def run_check(who: str, work: Path, body: str, *extra: str) -> tuple[int, str, str]:
    """Exit code, the --json report and standard error of ``verify check``."""
    done = subprocess.run([*_as(who), *check_command(work, body, *extra)],
                          capture_output=True, text=True, timeout=600, cwd=work,
                          env=environment(work))
    out = work / "out.json"
    return done.returncode, out.read_text() if out.exists() else "", done.stderr


# -- sockets ---------------------------------------------------------------------------------
@pytest.mark.parametrize("who", WHO)
def test_no_socket_of_any_family_and_no_unix_socket_under_home(who):
    """An ssh ControlMaster or a container daemon listening under $HOME answered a
    connect() through the read-only mount; now socket() itself is refused."""
    with workdir() as home:
        place = home / ".ssh"
        place.mkdir(mode=0o755)
        path = place / "control-master.sock"
        listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        try:
            listener.bind(str(path))
            path.chmod(0o777)
            listener.listen(4)
            listener.setblocking(False)
            body = (attempt("see", f"os.stat({str(path)!r})")
                    + attempt("unix", "import socket\ns = socket.socket(socket.AF_UNIX)\n"
                              f"s.connect({str(path)!r})")
                    + "".join(attempt(family.lower(),
                                      f"import socket\nsocket.socket(socket.{family})")
                              for family in ("AF_INET", "AF_INET6", "AF_UNIX", "AF_NETLINK",
                                             "AF_PACKET"))
                    + attempt("pair", "import socket\nsocket.socketpair()")
                    + attempt("raw", "libc = ctypes.CDLL(None, use_errno=True)\n"
                              "assert libc.socket(1, 1, 0) >= 0, ctypes.get_errno()")
                    + REPORT)
            code, report, err = run_check(who, home, body)
            assert code == 0, err
            assert "see:done" in report  # the socket was there to be found
            for label in ("unix", "af_inet", "af_inet6", "af_unix", "af_netlink",
                          "af_packet", "pair"):
                assert f"{label}:PermissionError" in report, (label, report)
            assert "raw:AssertionError" in report
            with pytest.raises(BlockingIOError):
                listener.accept()  # nobody connected
        finally:
            listener.close()


# -- memory ----------------------------------------------------------------------------------
MEMORY_ATTACKS = {
    # 1.4 GB in a memfd with little resident: refused at memfd_create
    "memfd": "fd = os.memfd_create('hoard')\nos.ftruncate(fd, 1400 * 2**20)\n"
             "os.write(fd, b'x' * 2**20)",
    # a 1.5 GB burst, freed at once: past the address-space limit of the budget
    "burst": "b = bytearray(1536 * 2**20)\ndel b",
    "shared": "import mmap\nm = mmap.mmap(-1, 1536 * 2**20, flags=mmap.MAP_SHARED)\n"
              "m[::4096] = b'x' * (1536 * 2**20 // 4096)",
    "sysv": "libc = ctypes.CDLL(None, use_errno=True)\n"
            "assert libc.shmget(0, ctypes.c_size_t(1536 * 2**20), 0o1600) >= 0",
    "devshm": "with open('/dev/shm/hoard', 'wb') as f:\n"
              "    for _ in range(1536):\n        f.write(b'x' * 2**20)",
    "raise": "import resource\ninf = resource.RLIM_INFINITY\n"
             "resource.setrlimit(resource.RLIMIT_AS, (inf, inf))",
    "prlimit": "import resource\ninf = resource.RLIM_INFINITY\n"
               "resource.prlimit(0, resource.RLIMIT_AS, (inf, inf))",
    "fork": "pid = os.fork()\nif pid == 0:\n    os._exit(0)",
    "cap": "line = [l for l in open('/proc/self/status') if l.startswith('CapEff')][0]\n"
           "assert int(line.split()[1], 16) != 0",
    # threads are allowed (they share the one address space and its limit)
    "thread": "import threading\nt = threading.Thread(target=lambda: None)\nt.start()\n"
              "t.join()",
}
MEMORY_OUTCOMES = {"memfd": "PermissionError", "burst": "MemoryError", "shared": "OSError",
                   "sysv": "AssertionError", "devshm": "OSError", "raise": "ValueError",
                   "prlimit": "PermissionError", "fork": "PermissionError",
                   "cap": "AssertionError", "thread": "done"}


@pytest.mark.parametrize("who", WHO)
def test_memory_the_budget_does_not_see_cannot_be_held(who):
    with workdir() as work:
        body = "".join(attempt(k, v) for k, v in MEMORY_ATTACKS.items()) + REPORT
        code, report, err = run_check(who, work, body, "--budget-memory", "1")
        assert code == 0, err
        for label, outcome in MEMORY_OUTCOMES.items():
            assert f"{label}:{outcome}" in report, (label, report)


def test_without_seccomp_the_sandbox_is_unavailable(monkeypatch):
    """No binding, no libseccomp or no kernel support: the sandbox counts as unavailable
    (``verify check FILE.py`` then refuses unless --unsandboxed)."""
    from verify.proof import syscalls

    def missing():
        raise ImportError("No module named 'pyseccomp'")

    monkeypatch.setattr(syscalls, "_binding", missing)
    syscalls.unavailable.cache_clear()
    try:
        why = syscalls.unavailable()
        assert why.startswith("no seccomp binding")
        mode, reason = sandbox._mode.__wrapped__()
        assert mode == "" and "no seccomp filter can be installed here" in reason
        with pytest.raises(syscalls.SyscallFilterError, match="no seccomp binding"):
            syscalls.install()
    finally:
        monkeypatch.undo()
        syscalls.unavailable.cache_clear()
    assert syscalls.unavailable() == ""


# -- keys ------------------------------------------------------------------------------------
READ_KEY = """
from verify.proof.syscalls import syscall_number
libc = ctypes.CDLL(None, use_errno=True)
libc.syscall.restype = ctypes.c_long
buf = ctypes.create_string_buffer(256)
n = libc.syscall(ctypes.c_long(syscall_number('keyctl')), ctypes.c_long(11),
                 ctypes.c_long(KEYID), buf, ctypes.c_long(256))
assert n >= 0, ctypes.get_errno()
seen.append(buf.raw[:n].decode())
"""
LIST_KEYS = "listed = open('/proc/keys').read()\nassert 'verify-token' in listed"


def _keyctl() -> str:
    tool = shutil.which("keyctl")
    if tool is None:
        pytest.skip("keyutils (keyctl) is not installed")
    probe = subprocess.run([tool, "session", "-", "true"], capture_output=True, timeout=30)
    if probe.returncode != 0:
        pytest.skip("this system refuses a new session keyring "
                    f"({probe.stderr.decode(errors='replace').strip()})")
    return tool


@pytest.mark.parametrize("readable_by_all", [False, True])
@pytest.mark.parametrize("who", WHO)
def test_a_key_of_the_caller_s_session_keyring_is_not_readable(who, readable_by_all):
    """The caller (and, without the sandbox, any process of its session) reads the
    token; the file does not, even when the key's permissions let every user read it."""
    keyctl = _keyctl()
    prefix = " ".join(_as(who))
    with workdir() as work:
        command = " ".join(f"'{a}'" for a in check_command(
            work, attempt("read", READ_KEY.strip()) + attempt("list", LIST_KEYS) + REPORT))
        template = work / "attack.py"
        script = work / "run.sh"
        script.write_text(
            "set -e\n"
            f"id=$({keyctl} add user verify-token S3CRET-TOKEN @s)\n"
            + (f"{keyctl} setperm \"$id\" 0x3f3f3f3f\n" if readable_by_all else "")
            + f"{prefix} {keyctl} print \"$id\" > {work}/control\n"  # same user, no sandbox
            + f"sed -i \"s/KEYID/$id/\" {template}\n"
            + f"{prefix} {command}\n")
        done = subprocess.run([keyctl, "session", "-", "sh", str(script)], capture_output=True,
                              text=True, timeout=600, cwd=work, env=environment(work))
        assert done.returncode == 0, done.stderr
        assert (work / "control").read_text().strip() == "S3CRET-TOKEN"
        report = (work / "out.json").read_text()
        assert "S3CRET-TOKEN" not in report
        assert "read:AssertionError" in report and "list:AssertionError" in report


def test_the_child_s_fresh_session_keyring_alone_loses_the_caller_s_keys():
    """The keyring step by itself (no seccomp filter): before it the process possesses
    the caller's token, after it not."""
    keyctl = _keyctl()
    program = ("import ctypes, sys\n"
               "from verify.proof.confine import fresh_session_keyring\n"
               + READ_KEY.replace("seen.append(buf.raw[:n].decode())",
                                  "print(buf.raw[:n].decode())")
                         .replace("assert n >= 0, ctypes.get_errno()",
                                  "print(n >= 0, flush=True)")
                         .replace("KEYID", "int(sys.argv[1])")
               + "fresh_session_keyring()\n"
               + "buf = ctypes.create_string_buffer(256)\n"
               + "n = libc.syscall(ctypes.c_long(syscall_number('keyctl')), ctypes.c_long(11),"
                 " ctypes.c_long(int(sys.argv[1])), buf, ctypes.c_long(256))\n"
               + "print(n >= 0, ctypes.get_errno())\n")
    script = (f"id=$({keyctl} add user verify-token S3CRET-TOKEN @s) && "
              f"{sys.executable} -c \"$PROGRAM\" \"$id\"")
    done = subprocess.run([keyctl, "session", "-", "sh", "-c", script], capture_output=True,
                          text=True, timeout=120, env={**os.environ, "PROGRAM": program})
    lines = done.stdout.split("\n")
    assert done.returncode == 0, done.stderr
    assert lines[:2] == ["True", "S3CRET-TOKEN"]  # possessed through the session keyring
    assert lines[2] in ("False 13", "False 126")  # EACCES, or ENOKEY: no longer possessed


# -- output paths that name a process's open file --------------------------------------------
DATA = PROJECT / "verify" / "data" / "derivations" / "lemma1.h_dot.json"


@pytest.mark.parametrize("who", WHO)
def test_dev_stdout_style_outputs_are_refused_never_replaced(who):
    with workdir() as work:
        fifo = work / "pipe"
        os.mkfifo(fifo, 0o666)
        links = {"stdout": "/proc/self/fd/1", "fd": "/dev/fd/1", "dev-stdout": "/dev/stdout",
                 "null": "/dev/null", "fifo": str(fifo)}
        for name, target in links.items():
            (work / name).symlink_to(target)
        for name in links:
            for flag in ("--emit", "--json"):
                out = work / "stdout.txt"
                with open(out, "w") as sink:
                    done = subprocess.run(
                        [*_as(who, sandboxed=False), sys.executable, "-m", "verify.cli",
                         "check", str(DATA),
                         flag, str(work / name), "--certificates", str(work / "c")],
                        stdout=sink, stderr=subprocess.PIPE, text=True, timeout=300,
                        cwd=work, env=environment(work))
                assert done.returncode == 2, (name, flag, done.stderr)
                assert len(done.stderr.strip().splitlines()) == 1, done.stderr
                assert (work / name).is_symlink()
                assert os.readlink(work / name) == links[name]
        assert stat.S_ISFIFO(os.lstat(fifo).st_mode)


def test_dev_stdout_in_a_private_mount_namespace_is_not_replaced(tmp_path):
    """The reported case: a scratch /dev (writable, as root of a private mount namespace),
    standard output redirected to a file, ``--emit /dev/stdout`` and ``--json
    /dev/stdout``: refused in one line, the link kept."""
    unshare = shutil.which("unshare")
    if unshare is None:
        pytest.skip("util-linux unshare is not installed")
    how = ["--mount"] if os.geteuid() == 0 else ["--user", "--map-root-user", "--mount"]
    out = tmp_path / "redirected.txt"
    script = (
        "set -e\nmount --make-rprivate / 2>/dev/null || true\n"
        "mount -t tmpfs none /dev\nln -s /proc/self/fd/1 /dev/stdout\n"
        "ln -s /proc/self/fd /dev/fd\ntouch /dev/null\n"
        f"for flag in --emit --json; do\n"
        f"  set +e; {sys.executable} -m verify.cli check {DATA} $flag /dev/stdout "
        f"--certificates {tmp_path}/c > {out} 2>> {tmp_path}/err; echo $? >> {tmp_path}/codes\n"
        "  set -e\ndone\n"
        f"stat -c %F /dev/stdout > {tmp_path}/kind\n")
    done = subprocess.run([unshare, *how, "sh", "-c", script], capture_output=True, text=True,
                          timeout=300)
    if done.returncode != 0 and not (tmp_path / "kind").exists():
        pytest.skip(f"no private mount namespace with a scratch /dev here: {done.stderr[:200]}")
    assert (tmp_path / "codes").read_text().split() == ["2", "2"]
    assert len((tmp_path / "err").read_text().strip().splitlines()) == 2
    assert "/proc" in (tmp_path / "err").read_text()
    assert (tmp_path / "kind").read_text().strip() == "symbolic link"
    assert out.read_text() == ""


def test_a_link_to_a_file_is_followed_and_kept(tmp_path):
    from verify.artefacts.atomic import write_atomic

    (tmp_path / "real").mkdir()
    target = tmp_path / "real" / "out.json"
    target.write_text("old")
    link = tmp_path / "out.json"
    link.symlink_to("real/out.json")
    write_atomic(link, "new")
    assert link.is_symlink() and os.readlink(link) == "real/out.json"
    assert target.read_text() == "new"
    loop = tmp_path / "loop"
    loop.symlink_to("loop")
    from verify.artefacts.atomic import OutputError

    with pytest.raises(OutputError, match="symbolic links"):
        write_atomic(loop, "x")
    assert loop.is_symlink()


def test_dot_dot_after_a_link_is_taken_from_where_the_link_leads(tmp_path, monkeypatch):
    """``link/../out.json`` is beside the link's target, as the kernel resolves it, not
    beside the link (a lexical ``abspath`` would say the latter)."""
    from verify.artefacts.links import resolve_output

    (tmp_path / "a" / "b").mkdir(parents=True)
    (tmp_path / "link").symlink_to(tmp_path / "a" / "b")
    monkeypatch.chdir(tmp_path)
    assert resolve_output("link/../out.json") == tmp_path / "a" / "out.json"
    (tmp_path / "fd").symlink_to("/proc/self/fd")
    from verify.artefacts.links import LinkError

    with pytest.raises(LinkError, match="/proc"):
        resolve_output("fd/../fd/1")
