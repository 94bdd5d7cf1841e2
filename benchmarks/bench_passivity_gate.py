"""Passivity gate: decision times against python-control, a plain SDP and a float test.

Run: ``python benchmarks/bench_passivity_gate.py [--sizes 2,10,30,100,200,400]
[--control-max 100] [--sdp-max 100] [--kinds passive,flipped,resonant]
[--frequency-route MODULE:FUNCTION]`` (``pip install -e '.[bench]'`` for cvxopt, which
python-control's ``ispassive`` uses; at n = 100 it takes minutes, so beyond n = 30 it runs
on the passive family only, up to ``--control-max``; the plain SDP likewise). All tools
see the same models in the same process. Columns:

- ``kyp``: our gate, :func:`verify.passivity.decision.decide` (KYP certificate checked
  exactly, or an exactly checked witness); ``ok`` says the verdict is the known truth and
  its evidence re-checks (a certificate once more with :func:`check_kyp`, untimed);
- ``freq``: the exact frequency-domain route, when a module providing it is importable
  (``--frequency-route``, by default verify.passivity.fd_decision; up to 100 states);
- ``ispassive``: python-control's ``ispassive`` (an SDP in cvxopt, floating point);
- ``sdp``: a plain KYP LMI in cvxpy + Clarabel (P >= eps I, M(P) <= 0; feasibility only, no
  exact check): what an SDP costs before any rounding;
- ``ham``: a float Hamiltonian-eigenvalue test (stable A and no imaginary-axis eigenvalue
  of the Hamiltonian of H + eps I, eps = 1e-9 of the gain scale; a yes/no with no
  evidence, the speed limit of any exact method).
- ratios: ``ctl/kyp`` (python-control's time over ours), ``kyp/sdp`` and ``kyp/ham``
  (our time over each).

Models (m = 2 ports unless ``--ports``): ``passive``: x' = (J - R) Q x + G u,
y = G^T Q x, with J skew, R = L L^T/n + 0.1 I > 0 and Q = diag(2^k), k in {-2..2} (exact in
floats, so the exact model is passive; the gate is not told Q); ``flipped``: y = -G^T Q x
(not passive, caught on the real axis); ``resonant``: a passive port-Hamiltonian part with
D = 0.05 I plus a negative lightly damped resonance at 3 rad/s (not passive only near
3 rad/s: needs a frequency witness, the exact H(jw*) of the whole model). Each size has
its own seed, so any subset of sizes gives the same models. The peak RSS of the process
is printed at the end.

BLAS threads are pinned to 1 for every tool unless OPENBLAS_NUM_THREADS / OMP_NUM_THREADS
are set: on a loaded machine threaded BLAS makes timings erratic (a 10x spread).
"""

from __future__ import annotations

from verify.cli import single_threaded_blas

single_threaded_blas()  # before numpy is imported (verify.cli does not import it)

import argparse  # noqa: E402
import importlib  # noqa: E402
import resource  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402

from verify.passivity.check.certificate import check_kyp  # noqa: E402
from verify.passivity.check.fd_certificate import (  # noqa: E402
    PrCertificate,
    check_pr_certificate_data,
)
from verify.passivity.decision import NOT_PASSIVE, PASSIVE, decide  # noqa: E402
from verify.passivity.model import from_state_space  # noqa: E402
from verify.passivity.port_hamiltonian import (  # noqa: E402
    random_port_hamiltonian,
    with_negative_resonance,
)

SIZES = (2, 10, 30, 100, 200, 400)
KINDS = ("passive", "flipped", "resonant")
SEED = 20261121
FREQUENCY_ROUTE = "verify.passivity.fd_decision:decide_positive_real"
FREQUENCY_MAX = 100  # the exact frequency-domain route alone, up to this many states
#: python-control and the plain SDP run on every family up to this n, beyond it (up to
#: --control-max / --sdp-max) on the passive family only: each takes minutes there
ALL_KINDS_UP_TO = 30


def resonant(n: int, m: int, rng: np.random.Generator):
    """Passive port-Hamiltonian (n - 2 states, D = 0.05 I) minus a resonance at w0 = 3."""
    A0, G, C0, _ = random_port_hamiltonian(max(n - 2, 1), m, rng)
    return with_negative_resonance(A0, G, C0, 0.05, rng)


def build(kind: str, n: int, m: int):
    rng = np.random.default_rng([SEED, n, KINDS.index(kind)])
    if kind == "resonant":
        return resonant(n, m, rng), NOT_PASSIVE
    return random_port_hamiltonian(n, m, rng, flip=kind == "flipped"), (
        NOT_PASSIVE if kind == "flipped" else PASSIVE)


def timed(f):
    start = time.perf_counter()
    try:
        value = f()
    except Exception as exc:  # a tool failing is a result, not a crash of the benchmark
        value = f"error: {type(exc).__name__}"
    return value, time.perf_counter() - start


def ours(A, B, C, D, n: int) -> tuple[str, float, bool]:
    """Verdict, seconds, and whether the evidence re-checks exactly."""
    model = from_state_space(A, B, C, D, name=f"n={n}")
    d, seconds = timed(lambda: decide(model))
    if isinstance(d, str):
        return d, seconds, False
    if d.verdict == PASSIVE and isinstance(d.certificate, PrCertificate):
        evidence = check_pr_certificate_data(d.certificate.to_json()).ok
    elif d.verdict == PASSIVE:
        evidence = d.certificate is not None and check_kyp(d.certificate.model,
                                                           d.certificate.P).ok
    else:
        evidence = d.witness is not None
    return d.verdict, seconds, evidence


def frequency_route(spec: str):
    """The frequency-domain decision function, or None when it is not importable."""
    module, _, name = spec.partition(":")
    try:
        return getattr(importlib.import_module(module), name)
    except (ImportError, AttributeError):
        return None


def theirs(A, B, C, D) -> tuple[str, float]:
    import control

    value, seconds = timed(lambda: control.ispassive(control.ss(A, B, C, D)))
    text = value if isinstance(value, str) else (PASSIVE if value else NOT_PASSIVE)
    return text, seconds


def plain_sdp(A, B, C, D) -> tuple[str, float]:
    """Feasibility of P >= eps I, M(P) <= 0 in cvxpy + Clarabel (floating point only)."""
    import cvxpy as cp

    def run():
        n = A.shape[0]
        P = cp.Variable((n, n), symmetric=True)
        M = cp.bmat([[A.T @ P + P @ A, P @ B - C.T], [B.T @ P - C, -(D + D.T)]])
        prob = cp.Problem(cp.Minimize(0), [P >> 1e-6 * np.eye(n), -(M + M.T) / 2 >> 0])
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            prob.solve(solver=cp.CLARABEL)
        return PASSIVE if prob.status == cp.OPTIMAL else NOT_PASSIVE

    return timed(run)


def hamiltonian_test(A, B, C, D) -> tuple[str, float]:
    """Stable A and no imaginary eigenvalue of the Hamiltonian of H + eps I (float)."""
    def run():
        if np.max(np.linalg.eigvals(A).real) >= 0:
            return NOT_PASSIVE
        m = D.shape[0]
        gain = max(float(np.abs(D).max()), float(np.abs(C @ B).max()), 1e-300)
        R = D + D.T + 2e-9 * gain * np.eye(m)
        if np.min(np.linalg.eigvalsh(R)) <= 0:
            return NOT_PASSIVE
        Ri = np.linalg.inv(R)
        H = np.block([[A - B @ Ri @ C, -B @ Ri @ B.T], [C.T @ Ri @ C, -A.T + C.T @ Ri @ B.T]])
        eig = np.linalg.eigvals(H)
        on_axis = np.abs(eig.real) <= 1e-8 * np.abs(eig)  # relative to each eigenvalue
        return NOT_PASSIVE if np.any(on_axis) else PASSIVE

    return timed(run)


def _cell(result, truth) -> str:
    verdict, seconds = result
    mark = "" if verdict == truth else "!"
    return f"{seconds:8.3f}{mark:1}"


def main(sizes, kinds, ports: int, control_max: int, sdp_max: int, freq_spec: str) -> None:
    freq = frequency_route(freq_spec)
    print(f"frequency route {freq_spec}: {'importable' if freq else 'not available'}; "
          f"'!' marks a wrong verdict; times in seconds")
    head = (f"{'n':>4} {'model':>9} {'truth':>11} {'kyp':>9} {'ok':>3} {'freq':>9} "
            f"{'ispassive':>10} {'sdp':>9} {'ham':>9} {'ctl/kyp':>8} {'kyp/sdp':>8} "
            f"{'kyp/ham':>8}")
    print(head)
    for n in sizes:
        for kind in kinds:
            (A, B, C, D), truth = build(kind, n, ports)
            verdict, t_ours, evidence = ours(A, B, C, D, n)
            ok = "yes" if verdict == truth and evidence else "NO"
            f_cell = "-"
            if freq is not None and n <= FREQUENCY_MAX:
                em = from_state_space(A, B, C, D, name=f"n={n}").exact
                d, t_f = timed(lambda em=em, n=n: freq(em, f"n={n}", "python", {"margin": "0"}))
                f_verdict = d if isinstance(d, str) else d[0]
                f_cell = _cell((f_verdict, t_f), truth)
            every = n <= ALL_KINDS_UP_TO or kind == "passive"  # minutes each beyond
            c = theirs(A, B, C, D) if n <= control_max and every else None
            s = plain_sdp(A, B, C, D) if n <= sdp_max and every else None
            h = hamiltonian_test(A, B, C, D)
            ratio = lambda num, den: f"{num / den:8.3g}" if den > 0 else "inf"  # noqa: E731
            print(f"{n:>4} {kind:>9} {truth:>11} {t_ours:8.3f}{'':1} {ok:>3} {f_cell:>9} "
                  f"{_cell(c, truth) if c else '-':>10} {_cell(s, truth) if s else '-':>9} "
                  f"{_cell(h, truth):>9} "
                  f"{ratio(c[1], t_ours) if c else '-':>8} "
                  f"{ratio(t_ours, s[1]) if s else '-':>8} {ratio(t_ours, h[1]):>8}",
                  flush=True)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"peak RSS of the benchmark process: {peak:.0f} MB")


def _sizes(text: str) -> list[int]:
    try:
        sizes = [int(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"--sizes {text!r}: comma-separated integers") from None
    if not sizes or min(sizes) < 2:
        raise argparse.ArgumentTypeError("--sizes needs integers >= 2")
    return sizes


def _kinds(text: str) -> list[str]:
    kinds = [k.strip() for k in text.split(",") if k.strip()]
    unknown = [k for k in kinds if k not in KINDS]
    if not kinds or unknown:
        raise argparse.ArgumentTypeError(f"--kinds: choose from {', '.join(KINDS)}")
    return kinds


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=_sizes, default=list(SIZES),
                        help="comma-separated state dimensions (default 2,10,30,100,200,400)")
    parser.add_argument("--kinds", type=_kinds, default=list(KINDS),
                        help="model families (default passive,flipped,resonant)")
    parser.add_argument("--ports", type=int, default=2, help="inputs = outputs (default 2)")
    parser.add_argument("--control-max", type=int, default=100,
                        help="largest n for python-control's ispassive (default 100)")
    parser.add_argument("--sdp-max", type=int, default=100,
                        help="largest n for the plain cvxpy + Clarabel LMI (default 100)")
    parser.add_argument("--frequency-route", default=FREQUENCY_ROUTE,
                        help=f"MODULE:FUNCTION of the exact frequency-domain decision "
                        f"(default {FREQUENCY_ROUTE})")
    parser.add_argument("--no-control", action="store_true",
                        help="skip python-control's ispassive")
    args = parser.parse_args()
    main(args.sizes, args.kinds, args.ports, -1 if args.no_control else args.control_max,
         args.sdp_max, args.frequency_route)
