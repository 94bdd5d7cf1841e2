"""Attacks on `verify check` once a derivation file runs in its sandbox, and on the data
the checker reads, printed output and exit codes.

1. processes of the file outliving the check, or acting on the checker and its outputs;
2. handover and data files that block, flood or explode while decoded;
3. what is printed is what was checked (escaping, exact counterexamples).

Each case of the hostile round against the earlier child-process isolation is kept here.
"""

from __future__ import annotations

import hashlib
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

import verify
from verify.cli import main
from verify.proof import sandbox

pytestmark = pytest.mark.skipif(bool(sandbox.unavailable()),
                                reason=f"no namespaces here: {sandbox.unavailable()}")

HEADER = """
import os, sys, subprocess, time
from verify.proof import Context, Derivation, by_bound, square
ctx = Context("user")
x = ctx.scalar("x")
"""
FALSE = "d = Derivation('false', x * x, ctx).ge(1, by_bound(square(x)))\nDERIVATIONS = [d]\n"
REPORT = ("d = Derivation('|'.join(seen), x * x + 1, ctx).ge(1, by_bound(square(x)))\n"
          "DERIVATIONS = [d]\n")


def attempt(label: str, code: str) -> str:
    """A line of the file's body that records whether ``code`` raised."""
    return (f"try:\n    {code}\n    seen.append('{label}:done')\n"
            f"except BaseException as e:\n    seen.append('{label}:' + type(e).__name__)\n")


def run(tmp_path: Path, body: str, *extra: str) -> int:
    path = tmp_path / "attack.py"
    path.write_text(HEADER + body)
    return main(["check", str(path), "--quick", "--certificates", str(tmp_path / "c"),
                 "--json", str(tmp_path / "out.json"), *extra])


def survivors(marker: str) -> list[int]:
    """Processes whose command line holds ``marker``."""
    out = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit() or int(pid) == os.getpid():
            continue
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                if marker.encode() in f.read():
                    out.append(int(pid))
        except OSError:
            continue
    return out


# -- 1. processes that outlive the check, or act on the checker ------------------------------
def test_a_setsid_grandchild_cannot_rewrite_the_outputs_after_the_exit(tmp_path, capsys):
    out, certs = tmp_path / "out.json", tmp_path / "c"
    marker = "verify-attack-marker-forger"
    forger = (f"import time\nfor _ in range(100):\n"
              f"    try:\n        open({str(out)!r}, 'w').write('verified')\n"
              f"    except OSError:\n        pass\n"
              f"    try:\n        open({str(certs / 'forged.json')!r}, 'w').write('x')\n"
              f"    except OSError:\n        pass\n"
              f"    time.sleep(0.05)\n# {marker}\n")
    spawn = (f"subprocess.Popen([sys.executable, '-c', {forger!r}], start_new_session=True, "
             "stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)")
    body = ("seen = []\n" + attempt("spawn", spawn) + attempt("fork", "os.fork()")
            + "time.sleep(1)\n" + REPORT.replace("x * x + 1", "x * x"))
    assert run(tmp_path, body) == 1
    written = out.read_text()
    time.sleep(1.5)
    assert out.read_text() == written and '"refuted"' in written
    # the seccomp filter refuses a new process (verify.proof.syscalls)
    assert "spawn:PermissionError|fork:PermissionError" in written
    assert not (certs / "forged.json").exists()
    assert survivors(marker) == []
    assert "0 of 1 derivation(s) verified" in capsys.readouterr().out


def test_no_process_of_the_file_survives_and_their_number_is_bounded(tmp_path, capsys):
    marker = "verify-attack-marker-many"
    sleeper = f"import time\ntime.sleep(1000)\n# {marker}\n"
    body = ("for _ in range(32):\n    try:\n"
            f"        subprocess.Popen([sys.executable, '-c', {sleeper!r}],"
            " start_new_session=True)\n"
            "    except OSError:\n        break\n"
            "time.sleep(1)\n" + FALSE)
    code = run(tmp_path, body)
    assert code in (1, 2)
    if code == 2:
        assert "processes" in capsys.readouterr().err
    assert survivors(marker) == []


def test_the_memory_budget_covers_the_file_s_processes_together(tmp_path, capsys):
    """Three hogs of 400 MB under a 1 GB budget: no process can be started to hold one,
    and the file's one process (its threads share it) cannot map all three."""
    marker = "verify-attack-marker-memory"
    hog = f"b = bytearray(b'x') * (400 * 2**20)\nimport time\ntime.sleep(60)\n# {marker}\n"
    body = ("seen = []\n"
            + attempt("spawn", f"subprocess.Popen([sys.executable, '-c', {hog!r}])")
            + "hogs = []\n"
            + attempt("hog", "for _ in range(3): hogs.append(bytearray(b'x') * (400 * 2**20))")
            + "del hogs\n" + REPORT)
    assert run(tmp_path, body, "--budget-memory", "1", "--budget-seconds", "40") == 0
    report = (tmp_path / "out.json").read_text()
    assert "spawn:PermissionError" in report and "hog:MemoryError" in report
    assert survivors(marker) == []


def test_the_file_cannot_signal_ptrace_or_write_to_another_process(tmp_path):
    victim = subprocess.Popen(["sleep", "60"])
    try:
        body = ("import ctypes, signal\nseen = []\nlibc = ctypes.CDLL(None, use_errno=True)\n"
                + attempt("stop", f"os.kill({victim.pid}, signal.SIGSTOP)")
                + attempt("kill", f"os.kill({victim.pid}, signal.SIGKILL)")
                + attempt("ptrace", f"assert libc.ptrace(16, {victim.pid}, 0, 0) == 0")
                + attempt("checker", f"os.kill({os.getpid()}, 0)")
                + attempt("fd1", f"open('/proc/{os.getpid()}/fd/1', 'w').write('forged')")
                + REPORT)
        assert run(tmp_path, body) == 0
        report = (tmp_path / "out.json").read_text()
        for what in ("stop", "kill", "ptrace", "checker", "fd1"):
            assert f"{what}:done" not in report
        with open(f"/proc/{victim.pid}/stat") as f:
            state = f.read().rsplit(")", 1)[1].split()[0]
        assert victim.poll() is None and state != "T"
    finally:
        victim.kill()
        victim.wait()


def test_the_file_cannot_change_the_checker_s_modules_or_outputs(tmp_path):
    module = Path(verify.__file__).parent / "sos" / "search.py"
    before = hashlib.sha256(module.read_bytes()).hexdigest()
    certs = tmp_path / "c"
    certs.mkdir()
    body = ("seen = []\n"
            + attempt("module", f"open({str(module)!r}, 'a').write('# forged')")
            + attempt("certs", f"open({str(certs / 'forged.json')!r}, 'w')")
            + attempt("json", f"open({str(tmp_path / 'out.json')!r}, 'w')")
            + attempt("tmp", "open('/tmp/scratch', 'w').write('private')")
            + REPORT)
    assert run(tmp_path, body) == 0
    report = (tmp_path / "out.json").read_text()
    assert "module:done" not in report and "certs:done" not in report
    assert "json:done" not in report and "tmp:done" in report  # /tmp is its own
    assert hashlib.sha256(module.read_bytes()).hexdigest() == before
    assert not (certs / "forged.json").exists() and not Path("/tmp/scratch").exists()


def test_the_file_has_no_network_and_no_capabilities(tmp_path):
    body = ("import socket\nseen = []\n"
            + attempt("net", "socket.create_connection(('10.0.0.1', 80), timeout=1)")
            + attempt("remount", "assert os.system('mount -o remount,rw / 2>/dev/null') == 0")
            + attempt("caps", "assert [l for l in open('/proc/self/status') "
                              "if l.startswith('CapEff')][0].split()[1].strip('0') != ''")
            + REPORT)
    assert run(tmp_path, body) == 0
    report = (tmp_path / "out.json").read_text()
    assert "net:done" not in report and "remount:done" not in report
    assert "caps:done" not in report


def test_without_namespaces_the_check_refuses_unless_unsandboxed(tmp_path, capsys,
                                                                  monkeypatch):
    monkeypatch.setattr(sandbox, "_mode", lambda: ("", "namespaces are switched off"))
    path = tmp_path / "ok.py"
    path.write_text(HEADER + "d = Derivation('ok', x * x + 1, ctx).ge(1, by_bound(square(x)))\n")
    assert main(["check", str(path), "--quick", "--certificates", str(tmp_path / "c")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--unsandboxed" in err
    assert main(["check", str(path), "--quick", "--certificates", str(tmp_path / "c"),
                 "--unsandboxed"]) == 0


# -- 2. handovers and data files ------------------------------------------------------------
def test_a_fifo_or_device_as_data_file_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "fifo.json"
    os.mkfifo(fifo)
    zero = tmp_path / "zero.json"
    zero.symlink_to("/dev/zero")
    for path in (fifo, zero, tmp_path):
        done = subprocess.run([sys.executable, "-m", "verify.cli", "check", str(path)],
                              capture_output=True, text=True, timeout=120)
        assert done.returncode == 2, done.stderr
        assert len(done.stderr.strip().splitlines()) == 1


def test_the_data_file_s_size_is_bounded(tmp_path, capsys):
    from verify.proof.wire import LIMITS

    big = tmp_path / "big.json"
    with open(big, "wb") as f:
        f.truncate(LIMITS["bytes"] + 10)
    assert main(["check", str(big)]) == 2
    assert "larger than" in capsys.readouterr().err


def test_the_file_sees_no_terminal_console_or_kernel_device(tmp_path):
    body = ("seen = []\n"
            + "".join(attempt(name, f"open('/dev/{name}', 'w').write('x')")
                      for name in ("console", "tty1", "kmsg", "tty", "loop0", "kvm"))
            + attempt("null", "open('/dev/null', 'w').write('x')")
            + REPORT)
    assert run(tmp_path, body) == 0
    report = (tmp_path / "out.json").read_text()
    for name in ("console", "tty1", "kmsg", "tty", "loop0", "kvm"):
        assert f"{name}:done" not in report
    assert "null:done" in report


def test_a_nested_user_namespace_cannot_make_a_mount_writable(tmp_path):
    target = Path(verify.__file__).parent / "nested-forgery"
    body = ("seen = []\n"
            + attempt("nested", "subprocess.run(['unshare', '-Urm', 'sh', '-c', "
                      f"'mount -o remount,rw / ; echo x > {target}'], check=True, "
                      "capture_output=True)")
            + REPORT)
    assert run(tmp_path, body) == 0
    assert not target.exists()


def test_filling_its_scratch_space_hurts_only_the_file(tmp_path):
    """The earlier handover folder could be kept full until the checker failed with exit
    3; now the handover is a pipe and /tmp is the file's own bounded tmpfs."""
    body = ("seen = []\nk = 0\n"
            "try:\n    while True:\n"
            "        open(f'/tmp/f{k}', 'wb').write(b'x' * 2**20)\n        k += 1\n"
            "except OSError as e:\n    seen.append('full:' + type(e).__name__)\n"
            + REPORT)
    assert run(tmp_path, body) == 0
    assert "full:OSError" in (tmp_path / "out.json").read_text()


def test_the_checker_is_not_dumpable_after_running_a_file(tmp_path):
    import ctypes

    assert run(tmp_path, "seen = []\n" + REPORT) == 0
    libc = ctypes.CDLL(None)
    assert libc.prctl(3, 0, 0, 0, 0) == 0  # PR_GET_DUMPABLE


def test_the_checker_s_lazy_modules_are_loaded_before_the_file_runs(tmp_path, monkeypatch):
    """Unsandboxed a file could rewrite on disk a module the checker imports later; every
    such module is imported before the child starts."""
    import verify.proof.isolate as isolate

    events = []
    monkeypatch.setattr(isolate, "preload", lambda: events.append("preload"))
    real = isolate.subprocess.Popen

    def popen(argv, *args, **kwargs):
        if "verify.proof.child" in argv:  # not, e.g., ctypes looking for libc
            events.append("child")
        return real(argv, *args, **kwargs)

    monkeypatch.setattr(isolate.subprocess, "Popen", popen)
    assert run(tmp_path, "seen = []\n" + REPORT) == 0
    assert events == ["preload", "child"]
    monkeypatch.undo()  # the real preload imports every one of them
    isolate.preload()
    assert set(isolate.LAZY_MODULES) <= set(sys.modules)


def test_an_exception_text_reaches_the_terminal_escaped(tmp_path, capsys):
    body = "raise ValueError('\\x1b[2J\\x1b[H1 of 1 derivation(s) verified\\r\\u202e')\n"
    assert run(tmp_path, body) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1
    assert "\x1b" not in err and "\r" not in err and "\u202e" not in err
    assert "\\x1b[2J" in err
