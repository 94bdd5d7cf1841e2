"""`verify gate --tolerance EPS`: rounded port-Hamiltonian and rounded lossless models pass
as *passive within tolerance* with the perturbation stated and the perturbed model's
certificate re-checked exactly; violations of 1e-9 relative fail at EPS = 1e-12; EPS = 0
changes nothing; bad EPS values exit 2 with one line.
"""

from __future__ import annotations

import json
import re
from fractions import Fraction

import numpy as np
import pytest

from verify.cli import main
from verify.passivity.check.certificate import check_kyp
from verify.passivity.decision import PASSIVE, decide
from verify.passivity.model import from_state_space
from verify.passivity.search.tolerance import PASSIVE_WITHIN, scales, within_tolerance

EPS = Fraction(1, 10**12)


def rounded_port_hamiltonian(n: int, m: int = 2, seed: int = 3):
    """x' = (J - R) Q x + G u, y = G^T Q x with a dense Q: C = G^T Q and A are rounded,
    so C B is not exactly symmetric (the exact model is not passive near w ~ 1e16)."""
    rng = np.random.default_rng([seed, n])
    J = rng.standard_normal((n, n))
    J = J - J.T
    L = rng.standard_normal((n, n))
    M = rng.standard_normal((n, n))
    Q = M @ M.T / n + 0.5 * np.eye(n)
    G = rng.standard_normal((n, m))
    return from_state_space((J - L @ L.T / n - 0.1 * np.eye(n)) @ Q, G, G.T @ Q,
                            np.zeros((m, m)), name=f"rounded pH {n}")


def rounded_lossless(drift: float = 1e-16):
    """2 + 5/(s + 4) + 5 s/(s^2 + 2) with the j-axis poles realised at drift +- 1.414j."""
    w, r = np.sqrt(2.0), np.sqrt(5.0)
    A = np.array([[-4.0, 0.0, 0.0], [0.0, drift, w], [0.0, -w, drift]])
    B = np.array([[r], [r], [0.0]])
    return from_state_space(A, B, B.T.copy(), [[2.0]], name=f"rounded lossless {drift:g}")


def violated_feedthrough(relative: float):
    """The rounded pH model with D + D^T indefinite by ``relative`` times the gain scale."""
    base = rounded_port_hamiltonian(6)
    _, gain = scales(base)
    D = np.diag([1.0, -relative * float(gain)])
    return from_state_space(base.A, base.B, base.C, D, name=f"violation {relative:g}")


def _passes_within(model):
    exact = decide(model)
    assert exact.verdict != PASSIVE  # not passive as written
    d = within_tolerance(model, EPS, Fraction(0), exact)
    assert d.verdict == PASSIVE_WITHIN, d.reason
    p = d.perturbation
    assert p.relative <= EPS
    cert = d.certificate
    assert check_kyp(cert.model, cert.P).ok
    # the certified model is the perturbed one: only the diagonals of A and D moved
    pm = d.perturbed_model
    assert cert.model == pm.exact
    assert np.array_equal(pm.B, model.B) and np.array_equal(pm.C, model.C)
    for X, Y in ((pm.A, model.A), (pm.D, model.D)):
        off = ~np.eye(X.shape[0], dtype=bool)
        assert np.array_equal(X[off], Y[off])
        assert np.all(np.diag(X) - np.diag(Y) <= 0) if X is pm.A else np.all(
            np.diag(X) - np.diag(Y) >= 0)
    return d


@pytest.mark.parametrize("n", [4, 12])
def test_rounded_port_hamiltonian_passes_within_tolerance(n):
    _passes_within(rounded_port_hamiltonian(n))


def test_rounded_lossless_passes_within_tolerance():
    d = _passes_within(rounded_lossless())
    assert d.perturbation.moved_a > 0  # the unstable drift had to be shifted away


@pytest.mark.parametrize("model", [violated_feedthrough(1e-9), rounded_lossless(2e-9)],
                         ids=["D + D^T short by 1e-9", "poles at +2e-9 +- 1.414j"])
def test_violations_of_1e_9_relative_fail(model):
    exact = decide(model)
    d = within_tolerance(model, EPS, Fraction(0), exact)
    assert d.verdict == exact.verdict != PASSIVE
    assert "within relative distance" in d.reason


def test_a_passive_model_is_untouched():
    model = from_state_space([[-1.0]], [[1.0]], [[1.0]], [[0.5]])
    exact = decide(model)
    assert within_tolerance(model, EPS, Fraction(0), exact) is exact


def _write(model, path):
    rows = lambda X: "[" + ", ".join(  # noqa: E731
        "[" + ", ".join(repr(float(x)) for x in row) + "]" for row in X) + "]"
    path.write_text(f'name = "{model.name}"\n[state_space]\nA = {rows(model.A)}\n'
                    f"B = {rows(model.B)}\nC = {rows(model.C)}\nD = {rows(model.D)}\n")
    return str(path)


def test_gate_command_with_tolerance(tmp_path, capsys):
    files = [_write(rounded_port_hamiltonian(4), tmp_path / "ph.toml"),
             _write(rounded_lossless(), tmp_path / "ll.toml"),
             _write(violated_feedthrough(1e-9), tmp_path / "v.toml")]
    certs = tmp_path / "certs"
    assert main(["gate", *files, "--tolerance", "1e-12", "--certificates", str(certs),
                 "--json", str(tmp_path / "g.json")]) == 1
    out = capsys.readouterr().out
    assert "2 of 3 model(s) passive (2 within tolerance 1e-12)" in out
    data = {d["name"]: d for d in json.loads((tmp_path / "g.json").read_text())}
    for name in ("rounded pH 4", "rounded lossless 1e-16"):
        entry = data[name]
        assert entry["verdict"] == PASSIVE_WITHIN and entry["passed"]
        t = entry["tolerance"]
        assert t["exact_verdict"] != PASSIVE
        assert Fraction(t["perturbation"]["relative_size"]) <= EPS
        assert "infinity norm" in t["perturbation"]["norm"]
        assert t["perturbed_certificate"]["P"]
    assert not data["violation 1e-09"]["passed"]
    # a perturbed model's certificate is bound to its file and (a, d), re-derived
    capsys.readouterr()
    assert main(["certificates", "check", str(certs)]) == 0
    out = capsys.readouterr().out
    assert out.count("the stored model is exactly the one it denotes perturbed by a = ") == 2


def test_tolerance_zero_changes_nothing(tmp_path, capsys):
    f = _write(rounded_lossless(), tmp_path / "ll.toml")
    strip = lambda text: re.sub(r"\d+\.\d+ s\)", "", text)  # noqa: E731
    assert main(["gate", f, "--certificates", str(tmp_path)]) == 1
    plain = strip(capsys.readouterr().out)
    assert main(["gate", f, "--tolerance", "0", "--certificates", str(tmp_path)]) == 1
    assert strip(capsys.readouterr().out) == plain


@pytest.mark.parametrize("value", ["-1e-12", "nan", "abc", "inf", "1/0", ""])
def test_bad_tolerance_exit_2_one_line(tmp_path, value, capsys):
    f = _write(rounded_lossless(), tmp_path / "ll.toml")
    assert main(["gate", f, f"--tolerance={value}"]) == 2
    err = capsys.readouterr().err
    assert "--tolerance" in err and len(err.strip().splitlines()) == 1
