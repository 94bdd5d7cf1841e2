"""Cost of the Coq kernel check of certificates, against the Python exact checker.

SOS certificates (``--sos``, on by default): each of the paper's stored
``certificates/sos-*.json`` is exported (:mod:`verify.coq.sos`) and compiled, and the
CPU time is set beside the Python exact check of the same certificate against its step
(:func:`verify.sos.certificate.check_bound`, the step's program derived beforehand).

KYP certificates:
For the paper's k_s = 3.0 certificate and for gate certificates of random passive
port-Hamiltonian models (float data, the test suite's family; D = 0, so P B = C^T binds
exactly) of the sizes given, it exports the unit, compiles it with ``coqc`` (the prelude
compiled once, not counted), and prints coqc's CPU and wall time and peak memory beside
the Python exact check (:func:`verify.passivity.check.certificate.check_kyp`) on the same
certificate, and the ratio. The gate's P is the one ``verify gate`` stores (the decision's
P on the coarse grid, :func:`verify.passivity.search.canonical.coarse_kyp`); with
``--raw`` the decision's P as found, for comparison. A compile past ``--timeout``
seconds is reported as such.

Exact-band certificates: the paper's k_s = 2.5 one on [0, 3/2] and random passive models
of ``--band-sizes`` states on [0, 1], the same way.

The whole command (``--gate-sizes``, default 10): the same random model written to a
model file with each double's exact decimal expansion (so it stays passive: a shortest
``repr`` is another rational), then ``verify gate MODEL --coq DIR`` run twice in a
subprocess with a fresh ``XDG_CACHE_HOME``: the first run compiles the prelude into that
cache (cold), the second reuses it (warm). Wall and CPU (the command and its coqc
children) of both, with the load average, and the command's own "compiled by coqc" line.

The prelude is taken from the user's cache (:mod:`verify.coq.prelude_cache`), compiled
there first when absent.

    .venv/bin/python benchmarks/bench_coq.py [--sizes 4 10 60 200] [--band-sizes 4 6]
                                             [--gate-sizes 10] [--timeout 900] [--raw]
                                             [--no-sos] [--no-band]
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from fractions import Fraction
from pathlib import Path

import numpy as np

from verify.coq.band_fd import band_fd_unit_from_file, band_unit
from verify.coq.development import LOGICAL_ROOT, _compile_one, prelude_sources
from verify.coq.kyp import kyp_unit, kyp_unit_from_file
from verify.coq.positive_real import pr_unit_from_file
from verify.coq.prelude_cache import compiled_prelude, install
from verify.passivity.check.band_fd import BandFdCertificate, analyse_band, check_band_fd_data
from verify.passivity.check.certificate import check_kyp, exact_model
from verify.passivity.check.fd_certificate import check_pr_certificate_data
from verify.passivity.decision import decide
from verify.passivity.fd_decision import decide_positive_real
from verify.passivity.gate import store_pr_certificate
from verify.passivity.io import certificate_files as cf
from verify.passivity.io.strict_json import read_strict
from verify.passivity.model import from_state_space
from verify.passivity.port_hamiltonian import random_port_hamiltonian
from verify.passivity.search.canonical import coarse_kyp

ROOT = Path(__file__).resolve().parents[1]
KS3 = ROOT / "certificates" / "reconstructed-k_s-3.0-99babda880e6.json"
KS25 = ROOT / "certificates" / "reconstructed-k_s-2.5-band-0-1.5-f0739b7ae628.json"


def coqc(folder: Path, rel: str, timeout: float) -> tuple[float, float, float, bool]:
    """(wall seconds, CPU seconds, peak MB, ok) of one coqc run; ok False on failure or
    timeout. CPU time is the robust figure on a shared machine."""
    start = time.perf_counter()
    proc = subprocess.Popen(["coqc", "-R", ".", LOGICAL_ROOT, rel], cwd=folder,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = start + timeout
    while True:
        pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
        if pid:
            break
        if time.perf_counter() > deadline:
            proc.kill()
            _, status, usage = os.wait4(proc.pid, 0)
            return (time.perf_counter() - start, usage.ru_utime + usage.ru_stime,
                    usage.ru_maxrss / 1024, False)
        time.sleep(0.05)
    ok = os.waitstatus_to_exitcode(status) == 0
    return (time.perf_counter() - start, usage.ru_utime + usage.ru_stime,
            usage.ru_maxrss / 1024, ok)


def python_check_seconds(model, P, repeat: int = 3) -> float:
    """The best CPU time of the Python exact check (CPU, as for coqc)."""
    best = float("inf")
    for _ in range(repeat):
        t = time.process_time()
        assert check_kyp(model, P).ok
        best = min(best, time.process_time() - t)
    return best


def sos_rows(folder: Path, timeout: float) -> None:
    """Compile every paper SOS unit in ``folder`` (prelude already there) and print the
    CPU time beside the Python exact check of the same certificate."""
    import json

    from verify.coq.sos import certificate_for, paper_sos_steps, sos_unit
    from verify.proof.checker import step_problem
    from verify.proof.sos_step import step_program
    from verify.sos.certificate import check_bound

    print(f"{'SOS certificate':<44} {'coqc CPU':>8} {'peak MB':>8} {'python s':>9} "
          f"{'CPU ratio':>9}")
    total_cpu = total_py = 0.0
    for step in paper_sos_steps():
        path = certificate_for(step, ROOT / "certificates")
        if not path.is_file():
            continue
        data = json.loads(path.read_text(encoding="utf-8"))
        unit = sos_unit(step, data, file_label=path.name)
        (folder / f"{unit.name}.v").write_text(unit.text)
        _secs, cpu, mb, ok = coqc(folder, f"{unit.name}.v", timeout)
        d = step.derivation
        sp = step_program(step_problem(d, d.steps[0]), d.steps[0].because)
        best = float("inf")
        for _ in range(3):
            t = time.perf_counter()
            assert check_bound(data, sp).ok
            best = min(best, time.perf_counter() - t)
        total_cpu, total_py = total_cpu + cpu, total_py + best
        state = "" if ok else "  FAILED"
        label = f"{step.original} step {step.step}"
        print(f"{label:<44} {cpu:8.1f} {mb:8.0f} {best:9.3f} {cpu / best:9.0f}{state}",
              flush=True)
    print(f"{'all SOS units':<44} {total_cpu:8.1f} {'':>8} {total_py:9.3f} "
          f"{total_cpu / max(total_py, 1e-9):9.0f}")
def exact_decimal_toml(n: int, name: str) -> str:
    """The benchmark's random model of ``n`` states as a model file, every double written
    as its exact decimal expansion."""
    from decimal import Decimal

    A, B, C, D = random_port_hamiltonian(n, 2, np.random.default_rng([11, n]), False)

    def number(x: float) -> str:
        text = format(Decimal(float(x)), "f")
        return text if "." in text else text + ".0"

    def mat(M) -> str:
        return "[" + ", ".join("[" + ", ".join(number(x) for x in row) + "]"
                               for row in M) + "]"

    return (f'name = "{name}"\ndescription = "bench_coq.py"\n\n[state_space]\n'
            f"A = {mat(A)}\nB = {mat(B)}\nC = {mat(C)}\nD = {mat(D)}\n")


def children_cpu() -> float:
    """CPU seconds (user + system) of every child this process has waited for."""
    import resource

    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


def run_command(argv: list[str], env: dict, cwd: Path,
                timeout: float) -> tuple[float, float, int, str]:
    """(wall s, CPU s of the command and its coqc children, exit code, output)."""
    cpu0, start = children_cpu(), time.perf_counter()
    proc = subprocess.Popen(argv, cwd=cwd, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, _ = proc.communicate()
    return time.perf_counter() - start, children_cpu() - cpu0, proc.returncode, out


def gate_command_rows(sizes: list[int], timeout: float) -> None:
    """``verify gate MODEL --coq DIR`` on a passive random model: cold then warm cache."""
    verify = Path(sys.executable).with_name("verify")
    print(f"{'verify gate --coq':<26} {'cache':>5} {'wall s':>7} {'CPU s':>7} {'load':>5}  "
          "coqc line")
    for n in sizes:
        with tempfile.TemporaryDirectory() as tmp:
            work = Path(tmp)
            (work / "model.toml").write_text(exact_decimal_toml(n, f"pH {n}"))
            env = dict(os.environ, XDG_CACHE_HOME=str(work / "cache"))
            for cache in ("cold", "warm"):
                for old in ("coq", "certs"):
                    shutil.rmtree(work / old, ignore_errors=True)
                load = os.getloadavg()[0]
                wall, cpu, rc, out = run_command(
                    [str(verify), "gate", "model.toml", "--certificates", "certs",
                     "--coq", "coq"], env, work, timeout)
                line = next((ln for ln in out.splitlines()
                             if ln.startswith("coq: compiled by coqc")), f"exit {rc}")
                print(f"{f'{n} states':<26} {cache:>5} {wall:7.1f} {cpu:7.1f} {load:5.1f}  "
                      f"{line}", flush=True)


def entry_bits(P) -> int:
    """The longest numerator or denominator of P, in bits."""
    return max((max(int(x.numerator).bit_length(), int(x.denominator).bit_length())
                for row in P for x in row), default=0)


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", type=int, nargs="*", default=[4, 10, 60, 200])
    ap.add_argument("--gate-sizes", type=int, nargs="*", default=[10],
                    help="sizes of the whole 'verify gate --coq' command (cold, warm)")
    ap.add_argument("--no-band", action="store_true", help="skip the band certificates")
    ap.add_argument("--band-sizes", type=int, nargs="*", default=[4, 6])
    ap.add_argument("--timeout", type=float, default=900.0)
    ap.add_argument("--no-sos", action="store_true", help="skip the SOS certificates")
    ap.add_argument("--raw", action="store_true",
                    help="the decision's P as found, not the gate's coarse P")
    args = ap.parse_args()
    gate_command_rows(args.gate_sizes, args.timeout)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        sources = prelude_sources()
        for name, text in sources.items():
            (folder / f"{name}.v").write_text(text)
        cached = compiled_prelude(sources, LOGICAL_ROOT, timeout_seconds=args.timeout,
                                  compile_one=_compile_one)
        if cached is not None and install(cached, list(sources), folder):
            print(f"prelude: {cached.summary()}")
        else:
            for name in sources:
                secs, cpu, mb, ok = coqc(folder, f"{name}.v", args.timeout)
                print(f"prelude {name}.v: {secs:.1f} s wall, {cpu:.1f} s CPU, {mb:.0f} MB, "
                      f"ok={ok}")
        if not args.no_sos:
            sos_rows(folder, args.timeout)
        cases = []
        cert = cf.parse_kyp(read_strict(KS3))
        cases.append(("paper k_s=3.0 (4 states)", kyp_unit_from_file(KS3), cert.model, cert.P))
        for n in args.sizes:
            A, B, C, D = random_port_hamiltonian(n, 2, np.random.default_rng([11, n]), False)
            d = decide(from_state_space(A, B, C, D, name=f"pH n={n}"))
            c = d.certificate
            assert c is not None, d.reason
            P = c.P if args.raw else coarse_kyp(c.model, c.P)
            unit = kyp_unit(f"Gate{n}", model=c.model, P=P, margin=Fraction(0),
                            label=f"pH n={n}", source="(benchmark)",
                            fingerprint=c.model.fingerprint(), origin=f"gate n={n}")
            cases.append((f"gate pH {n} states", unit, c.model, P))
        print(f"{'certificate':<26} {'coqc wall':>9} {'coqc CPU':>9} {'peak MB':>8} "
              f"{'python s':>9} {'CPU ratio':>9}  unit size, longest entry of P")
        for label, unit, model, P in cases:
            (folder / f"{unit.name}.v").write_text(unit.text)
            secs, cpu, mb, ok = coqc(folder, f"{unit.name}.v", args.timeout)
            py = python_check_seconds(model, P)
            state = "" if ok else ("  TIMEOUT" if secs >= args.timeout else "  FAILED")
            print(f"{label:<26} {secs:9.1f} {cpu:9.1f} {mb:8.0f} {py:9.4f} {cpu / py:9.0f}  "
                  f"{len(unit.text) // 1024} KiB, {entry_bits(P)} bits{state}", flush=True)
        if not args.no_band:
            band_cases(folder, args)
    return 0


def band_python_seconds(data: dict, repeat: int = 3) -> float:
    """The Python exact checker of an exact-band or positive-real certificate (its
    binding aside)."""
    best = float("inf")
    for _ in range(repeat):
        t = time.perf_counter()
        if data["schema"] == "verify-pr-certificate/1":
            assert check_pr_certificate_data(data).ok
        else:
            assert check_band_fd_data(data)[0].ok
        best = min(best, time.perf_counter() - t)
    return best


def pr_case(folder: Path) -> tuple[str, object, dict]:
    """The positive-real certificate of the k_s = 3.0 model (frequency inequality)."""
    model = cf.parse_kyp(read_strict(KS3)).model
    _verdict, _reason, cert, _ = decide_positive_real(model, "k_s = 3.0", "")
    path, _ = store_pr_certificate(cert, Fraction(0), folder)
    return "paper k_s=3.0 PR (4 st.)", pr_unit_from_file(path), read_strict(path)


def band_cases(folder: Path, args: argparse.Namespace) -> None:
    """Exact-band certificates: the paper's k_s = 2.5 one, and random passive
    port-Hamiltonian models (2 ports) on the band [0, 1]."""
    cases = [("paper k_s=2.5 band (4 st.)", band_fd_unit_from_file(KS25),
              read_strict(KS25))]
    for n in args.band_sizes:
        A, B, C, D = random_port_hamiltonian(n, 2, np.random.default_rng([12, n]), False)
        model = exact_model(A, B, C, D)
        band = (Fraction(0), Fraction(1))
        analysis = analyse_band(model, band)
        assert analysis.passive
        data = BandFdCertificate(f"pH n={n}", "(benchmark)", model, band, Fraction(0),
                                 analysis).to_json()
        unit = band_unit(f"Band{n}", model=model, band=band, margin=Fraction(0),
                         label=f"pH n={n}", source="(benchmark)",
                         fingerprint=model.fingerprint(), origin=f"band n={n}")
        cases.append((f"band pH {n} states", unit, data))
    for label, unit, data in [*cases, pr_case(folder)]:
        (folder / f"{unit.name}.v").write_text(unit.text)
        secs, cpu, mb, ok = coqc(folder, f"{unit.name}.v", args.timeout)
        py = band_python_seconds(data)
        state = "" if ok else ("  TIMEOUT" if secs >= args.timeout else "  FAILED")
        print(f"{label:<26} {secs:9.1f} {cpu:9.1f} {mb:8.0f} {py:9.4f} {cpu / py:9.0f}  "
              f"{len(unit.text) // 1024} KiB{state}", flush=True)


if __name__ == "__main__":
    sys.exit(main())
