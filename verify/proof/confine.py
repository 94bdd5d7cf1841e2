"""Inside the sandbox, before a derivation file runs: every mount read-only, private
scratch folders, no capabilities left.

The front end of ``verify check FILE.py`` runs the file as the first process of new
user, PID, mount, IPC and network namespaces (:mod:`verify.proof.sandbox`). That process
is root of its own user namespace until :func:`confine` ends: it remounts every mount it
inherited read-only (so the project, the checker's modules and every output path stay as
they are), mounts empty private file systems on ``/tmp``, ``/var/tmp``, ``/dev/shm``,
``/dev/pts`` and ``/run`` (no scratch, socket or terminal shared with the checker; 20 MB
together), hides ``/proc/keys``, joins a fresh session keyring, drops every capability
for good (bounding set emptied, no new privileges) and installs a seccomp filter
(:mod:`verify.proof.syscalls`: no sockets, no new process, no memfd or shared memory, no
keys), so the file cannot undo any of it. See ``verify/proof/TRUSTED.md``; the proof language this
serves is the paper's Section 3.
"""

from __future__ import annotations

import ctypes
import errno
import os
import resource
import sys

from verify.proof import syscalls

_MS_RDONLY = 1
_MS_NOSUID = 2
_MS_NODEV = 4
_MS_NOEXEC = 8
_MS_REMOUNT = 32
_MS_NOATIME = 1024
_MS_NODIRATIME = 2048
_MS_BIND = 4096
_MS_RELATIME = 1 << 21
_ST_FLAGS = (  # statvfs f_flag bit -> mount flag (locked flags must be kept on remount)
    (os.ST_NOSUID, _MS_NOSUID), (os.ST_NODEV, _MS_NODEV), (os.ST_NOEXEC, _MS_NOEXEC),
    (os.ST_NOATIME, _MS_NOATIME), (os.ST_NODIRATIME, _MS_NODIRATIME),
    (os.ST_RELATIME, _MS_RELATIME))
_PR_SET_NO_NEW_PRIVS = 38
_PR_CAPBSET_DROP = 24
_LINUX_CAPABILITY_VERSION_3 = 0x20080522
#: Empty file systems laid over shared scratch, socket and terminal folders.
PRIVATE = ("/tmp", "/var/tmp", "/dev/shm", "/dev/pts", "/run")
#: Their sizes: memory outside the file's address space, so kept small (20 MB together).
PRIVATE_BYTES = {"/tmp": 16 * 2**20, "/var/tmp": 2**20, "/dev/shm": 2**20,
                 "/dev/pts": 2**20, "/run": 2**20}
PRIVATE_INODES = 1024
#: Files of /proc the file sees empty (keyrings are not namespaced).
MASKED = ("/proc/keys", "/proc/key-users")
#: The only devices the file sees (in a fresh read-only /dev).
DEVICES = ("null", "zero", "full", "random", "urandom")
_MNT_DETACH = 2
_KEYCTL_JOIN_SESSION_KEYRING = 1


class ConfineError(Exception):
    """The sandbox could not be completed (the file is then not run)."""


def _libc() -> ctypes.CDLL:
    return ctypes.CDLL(None, use_errno=True)  # the interpreter's own libc symbols


def _unescape(field: str) -> str:
    """A mount point as /proc/self/mountinfo writes it (octal escapes for space etc.)."""
    out, i = [], 0
    while i < len(field):
        if field[i] == "\\" and field[i + 1:i + 4].isdigit() and len(field[i + 1:i + 4]) == 3:
            out.append(chr(int(field[i + 1:i + 4], 8)))
            i += 4
        else:
            out.append(field[i])
            i += 1
    return "".join(out)


def mount_points() -> list[str]:
    """Every mount point this process sees, parents before children."""
    with open("/proc/self/mountinfo", encoding="utf-8", errors="surrogateescape") as f:
        points = [_unescape(line.split()[4]) for line in f if len(line.split()) > 4]
    return sorted(set(points), key=lambda p: (p.count("/"), p))


def _remount_read_only(libc: ctypes.CDLL, point: str) -> None:
    try:
        flags = os.statvfs(point).f_flag
    except OSError:
        return  # not reachable from here (covered by a parent), so nothing to write
    if flags & os.ST_RDONLY:
        return
    keep = sum(ms for st, ms in _ST_FLAGS if flags & st)
    if libc.mount(None, point.encode("utf-8", "surrogateescape"), None,
                  _MS_REMOUNT | _MS_BIND | _MS_RDONLY | keep, None) != 0:
        err = ctypes.get_errno()
        raise ConfineError(f"could not make {point} read-only ({os.strerror(err)})")


def _private(libc: ctypes.CDLL, point: str) -> None:
    if not os.path.isdir(point):
        return
    size = PRIVATE_BYTES[point]
    options = f"size={size},nr_inodes={PRIVATE_INODES},mode=1777".encode()
    if libc.mount(b"none", point.encode(), b"tmpfs", _MS_NOSUID | _MS_NODEV, options) != 0:
        err = ctypes.get_errno()
        raise ConfineError(f"could not mount a private {point} ({os.strerror(err)})")


def _mount(libc: ctypes.CDLL, source: str | None, target: str, fstype: str | None,
           flags: int, data: str | None, what: str) -> None:
    def b(x: str | None) -> bytes | None:
        return None if x is None else x.encode("utf-8", "surrogateescape")

    if libc.mount(b(source), b(target), b(fstype), flags, b(data)) != 0:
        err = ctypes.get_errno()
        raise ConfineError(f"could not {what} ({os.strerror(err)})")


def _minimal_dev(libc: ctypes.CDLL) -> None:
    """Replace /dev by a read-only tmpfs holding only the harmless devices (no
    terminals, consoles, kernel log, loop or kvm devices), shared /dev/shm and /dev/pts
    included. Needs a private /tmp for staging."""
    stage = "/tmp/.verify-dev"
    os.mkdir(stage, 0o755)
    kept = [name for name in DEVICES if os.path.exists(f"/dev/{name}")]
    for name in kept:
        open(f"{stage}/{name}", "w").close()
        _mount(libc, f"/dev/{name}", f"{stage}/{name}", None, _MS_BIND, None,
               f"keep /dev/{name}")
    _mount(libc, "none", "/dev", "tmpfs", _MS_NOSUID, "size=1m,mode=755",
           "mount a private /dev")
    for name in kept:
        open(f"/dev/{name}", "w").close()
        _mount(libc, f"{stage}/{name}", f"/dev/{name}", None, _MS_BIND, None,
               f"restore /dev/{name}")
        libc.umount2(f"{stage}/{name}".encode(), _MNT_DETACH)
    for name in ("shm", "pts"):
        os.mkdir(f"/dev/{name}", 0o755)
    for k, name in enumerate(("stdin", "stdout", "stderr")):
        os.symlink(f"/proc/self/fd/{k}", f"/dev/{name}")
    os.symlink("/proc/self/fd", "/dev/fd")


def _drop_capabilities(libc: ctypes.CDLL) -> None:
    if libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        raise ConfineError("could not set no_new_privs")
    for cap in range(64):
        if libc.prctl(_PR_CAPBSET_DROP, cap, 0, 0, 0) != 0 and ctypes.get_errno() != 22:
            raise ConfineError(f"could not drop capability {cap} from the bounding set")

    class Header(ctypes.Structure):
        _fields_ = [("version", ctypes.c_uint32), ("pid", ctypes.c_int)]

    class Data(ctypes.Structure):
        _fields_ = [("effective", ctypes.c_uint32), ("permitted", ctypes.c_uint32),
                    ("inheritable", ctypes.c_uint32)]

    header = Header(_LINUX_CAPABILITY_VERSION_3, 0)
    data = (Data * 2)()
    if libc.capset(ctypes.byref(header), data) != 0:
        raise ConfineError("could not drop capabilities")
    with open("/proc/self/status", encoding="ascii") as f:
        caps = {k: v.strip() for k, v in (line.split(":", 1) for line in f if ":" in line)}
    if any(int(caps.get(k, "1"), 16) for k in ("CapEff", "CapPrm", "CapBnd", "CapAmb")):
        raise ConfineError("capabilities are left after dropping them")


def _needed_under_private() -> list[str]:
    """The folders the file's Python needs that lie below a private folder (a checkout
    or a virtual environment under /tmp, say): the interpreter's prefixes, the import
    path and the project holding this package. They are shown again, read-only, inside
    the private folder; nothing else of the shared folder is."""
    project = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
    candidates = {sys.prefix, sys.base_prefix, sys.exec_prefix, project,
                  os.path.dirname(os.path.dirname(os.path.realpath(sys.executable))),
                  os.path.dirname(sys.executable), *sys.path}
    below = sorted({os.path.realpath(c) for c in candidates if c and os.path.isdir(c)
                    and any(os.path.realpath(c).startswith(p + "/") for p in PRIVATE)})
    return [c for c in below if not any(c.startswith(k + "/") for k in below if k != c)]


def _show_again(libc: ctypes.CDLL, kept: list[tuple[str, int]]) -> None:
    """Bind each kept folder (opened before the private folders hid it) back to its own
    path, read-only."""
    for path, fd in kept:
        os.makedirs(path, exist_ok=True)
        _mount(libc, f"/proc/self/fd/{fd}", path, None, _MS_BIND, None,
               f"show {path} again")
        os.close(fd)
        _remount_read_only(libc, path)


def confine(max_processes: int) -> None:
    """Make this namespace's view of the file systems read-only, lay private empty
    folders over the shared ones, limit the namespace's processes and drop every
    capability. Raises ConfineError if any part fails (the file must then not run)."""
    libc = _libc()
    kept = [(path, os.open(path, os.O_PATH | os.O_DIRECTORY))
            for path in _needed_under_private()]
    for point in mount_points():
        if point in PRIVATE:
            continue
        _remount_read_only(libc, point)
    _private(libc, "/tmp")
    _minimal_dev(libc)
    for path in MASKED:  # the descriptions of the keys its user may view
        if os.path.exists(path):
            _mount(libc, "/dev/null", path, None, _MS_BIND, None, f"hide {path}")
    _remount_read_only(libc, "/dev")  # shm and pts below get their own tmpfs
    for point in PRIVATE:
        if point != "/tmp":
            _private(libc, point)
    _show_again(libc, kept)
    for point in mount_points():  # nothing writable is left but the private folders
        if point in PRIVATE or point.startswith("/proc"):
            continue
        try:
            if not os.statvfs(point).f_flag & os.ST_RDONLY:
                raise ConfineError(f"{point} is still writable")
        except OSError:
            continue
    resource.setrlimit(resource.RLIMIT_NPROC, (max_processes, max_processes))
    fresh_session_keyring()
    _drop_capabilities(libc)
    os.chdir("/tmp")
    try:
        syscalls.install()  # last: it refuses mount, keyctl and execve from here on
    except syscalls.SyscallFilterError as exc:
        raise ConfineError(str(exc)) from None


def fresh_session_keyring() -> None:
    """Join a new anonymous session keyring (``keyctl join_session_keyring``): keyrings
    are not namespaced, and the caller's session keyring (a token an agent or a CI put
    there) would otherwise be this process's too. A kernel without keys (ENOSYS) or an
    outer seccomp filter that refuses ``keyctl`` (EPERM, as container runtimes do) leaves
    no key to reach, since that filter binds the file too; any other failure is a
    ConfineError."""
    number = syscalls.syscall_number("keyctl")
    libc = _libc()
    libc.syscall.restype = ctypes.c_long
    serial = libc.syscall(ctypes.c_long(number), ctypes.c_long(_KEYCTL_JOIN_SESSION_KEYRING),
                          ctypes.c_void_p(None))
    if serial < 0:
        err = ctypes.get_errno()
        if err not in (errno.ENOSYS, errno.EPERM):
            raise ConfineError(f"could not join a fresh session keyring ({os.strerror(err)})")


__all__ = ["PRIVATE", "ConfineError", "confine", "fresh_session_keyring", "mount_points"]
