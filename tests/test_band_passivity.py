"""Finite-band passivity (generalized KYP, Iwasaki-Hara 2005): gate, certificates, witnesses.

The reconstructed k_s = 2.5 model has nu(w) = Re h(jw) with Re h |den|^2 = 2 - w^2/2, so
it is passive exactly on bands inside [0, 2] rad/s (paper, Section 4: "not satisfied for
k_s = 2.5 at frequencies above approximately 2 rad/s").
"""

from __future__ import annotations

import json
from fractions import Fraction

import numpy as np
import pytest
from gmpy2 import mpq

from verify.cli import main
from verify.passivity.band import decide_band, parse_band
from verify.passivity.check.gkyp import check_gkyp
from verify.passivity.check.witness import hermitian_part_at
from verify.passivity.decision import NOT_PASSIVE, PASSIVE
from verify.passivity.io.model_file import load_model
from verify.passivity.model import from_state_space
from verify.passivity.search.hamiltonian import nu_values

KS25 = "verify/data/models/reconstructed_ks2p5.toml"
F = Fraction


@pytest.fixture(scope="module")
def ks25():
    return load_model(KS25)


def test_gate_band_passes_below_two_and_fails_above(tmp_path, capsys):
    certs = tmp_path / "certs"
    assert main(["gate", KS25, "--band", "0:1.5", "--certificates", str(certs)]) == 0
    out = capsys.readouterr().out
    assert "PASS" in out and "on [0, 3/2] rad/s" in out
    (path,) = certs.glob("*.json")
    # the exact route first: a certificate with no floating point in it
    assert json.loads(path.read_text())["schema"] == "verify-band-fd-certificate/1"
    assert main(["certificates", "check", str(certs)]) == 0
    capsys.readouterr()
    assert main(["gate", KS25, "--band", "1:10", "--certificates", str(certs),
                 "--json", str(tmp_path / "g.json")]) == 1
    line = capsys.readouterr().out.splitlines()[0]
    assert line.startswith("FAIL") and "not passive on [1, 10]" in line
    (data,) = json.loads((tmp_path / "g.json").read_text())
    omega = Fraction(data["witness"]["omega"])
    assert 2 < omega <= 10 and data["band"] == ["1", "10"]


def test_band_witness_lies_inside_the_band_and_is_exact(ks25):
    d = decide_band(ks25, (F(1), F(10)))
    assert d.verdict == NOT_PASSIVE
    w = Fraction(d.witness.data["omega"])
    assert F(1) <= w <= F(10)
    a = [mpq(Fraction(x)) for x in d.witness.data["a"]]
    b = [mpq(Fraction(x)) for x in d.witness.data["b"]]
    v = a + b  # real form of a + jb
    d_cert = decide_band(ks25, (F(0), F(3, 2)))
    M = hermitian_part_at(d_cert.certificate.model, w)
    value = sum(v[i] * M[i][j] * v[j] for i in range(len(v)) for j in range(len(v)))
    assert value < 0


def test_narrow_bands_near_the_boundary(ks25):
    assert decide_band(ks25, (F(0), F(199, 100))).verdict == PASSIVE
    assert decide_band(ks25, (F(201, 100), F(3))).verdict == NOT_PASSIVE
    # nu(2) = 0 exactly at the band's edge: no strict GKYP certificate exists, the exact
    # route decides it (a tangency at the edge is allowed); one step past 2 it fails
    d = decide_band(ks25, (F(0), F(2)))
    assert d.verdict == PASSIVE and d.certificate.to_json()["schema"] == \
        "verify-band-fd-certificate/1"
    d = decide_band(ks25, (F(0), F(2) + F(1, 10**30)))
    assert d.verdict == NOT_PASSIVE
    assert F(2) < Fraction(d.witness.data["omega"]) <= F(2) + F(1, 10**30)


def test_certificate_does_not_transfer_to_another_band(ks25):
    """Soundness: the certificate for [0, 3/2] fails the exact check on [1, 10]."""
    cert = decide_band(ks25, (F(0), F(3, 2)), exact_first=False).certificate
    assert check_gkyp(cert.model, cert.P, cert.Q, cert.band).ok
    assert not check_gkyp(cert.model, cert.P, cert.Q, (F(1), F(10))).ok


def test_tampered_band_certificate_is_rejected(tmp_path, capsys):
    main(["gate", KS25, "--band", "0:1.5", "--certificates", str(tmp_path)])
    (path,) = tmp_path.glob("*.json")
    original = path.read_text()
    for edit in ("band", "model"):
        data = json.loads(original)
        if edit == "band":
            data["band"] = ["0", "5"]  # the model is not passive at 2 < w <= 5
        else:
            data["model"]["D"][0][1] = "1"  # fingerprint no longer matches
        path.write_text(json.dumps(data))
        assert main(["certificates", "check", str(path)]) == 1
        assert "INVALID" in capsys.readouterr().out
    path.write_text("{\"schema\": \"verify-gkyp-certificate/1\", \"model\": 3}")
    assert main(["certificates", "check", str(path)]) == 1
    (line, _) = capsys.readouterr().out.strip().splitlines()
    assert line.startswith(f"INVALID {path}: malformed: missing field(s)")


def test_tampered_gkyp_certificate_is_rejected(ks25, tmp_path):
    """The generalized KYP route's certificate (second route) refuses edits of Q."""
    cert = decide_band(ks25, (F(0), F(3, 2)), exact_first=False).certificate
    assert cert is not None and check_gkyp(cert.model, cert.P, cert.Q, cert.band).ok
    re, im = ([row[:] for row in part] for part in cert.Q)
    re[0][0] = -1 - re[0][0]  # Q no longer PSD
    assert not check_gkyp(cert.model, cert.P, (re, im), cert.band).ok


def test_band_verdict_agrees_with_nu_on_random_bands(ks25):
    """Cross-check against floating-point nu on a fine grid (never a proof, a falsifier)."""
    rng = np.random.default_rng(4)
    for _ in range(6):
        w1, w2 = sorted(rng.uniform(0, 4, 2))
        band = (F(w1).limit_denominator(100), F(w2).limit_denominator(100))
        if band[0] >= band[1]:
            continue
        d = decide_band(ks25, band)
        grid = np.linspace(float(band[0]), float(band[1]), 2001)
        lowest = nu_values(ks25.A, ks25.B, ks25.C, ks25.D, grid).min()
        if d.verdict == PASSIVE:
            assert lowest > -1e-12
        elif d.verdict == NOT_PASSIVE:
            assert lowest < 0


def test_static_and_unstable_models_on_a_band():
    static = from_state_space(np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)),
                              np.array([[-1.0]]), name="static")
    assert decide_band(static, (F(0), F(1))).verdict == NOT_PASSIVE
    # s/(s-1): unstable, yet Re H(jw) = w^2/(1 + w^2) >= 0, so passive on every band
    unstable = from_state_space(np.array([[1.0]]), np.array([[1.0]]), np.array([[1.0]]),
                                np.array([[1.0]]), name="s/(s-1)")
    assert decide_band(unstable, (F(1), F(3))).verdict == PASSIVE


@pytest.mark.parametrize("text", ["0:1.5", " 1/2 : 3 ", "1e-3:2"])
def test_parse_band_is_exact(text):
    w1, w2 = parse_band(text)
    assert isinstance(w1, Fraction) and w1 < w2


def _random_band_checks(seed: int, count: int) -> set:
    """Falsification: a certified band has nu >= 0 on a fine grid; a witness lies in the band
    and nu is negative there. Returns the verdicts seen."""
    rng = np.random.default_rng(seed)
    seen = set()
    for _ in range(count):
        n, m = int(rng.integers(1, 4)), int(rng.integers(1, 3))
        A = rng.normal(size=(n, n))
        A -= (np.max(np.linalg.eigvals(A).real) + 0.3) * np.eye(n)
        B, C = rng.normal(size=(n, m)), rng.normal(size=(m, n))
        D = 1.5 * np.eye(m) + 0.2 * rng.normal(size=(m, m))
        model = from_state_space(A, B, C, D, name="random")
        w1 = F(float(rng.uniform(0, 2))).limit_denominator(100)
        band = (w1, w1 + F(float(rng.uniform(0.1, 3))).limit_denominator(100))
        d = decide_band(model, band)
        seen.add(d.verdict)
        grid = np.linspace(float(band[0]), float(band[1]), 4001)
        lowest = nu_values(A, B, C, D, grid).min()
        if d.verdict == PASSIVE:
            assert lowest > -1e-12
        elif d.verdict == NOT_PASSIVE:
            w = Fraction(d.witness.data["omega"])
            assert band[0] <= w <= band[1]
            assert nu_values(A, B, C, D, np.array([float(w)]))[0] < 0
    return seen


def test_random_models_band_verdicts_are_consistent_with_nu():
    assert PASSIVE in _random_band_checks(seed=11, count=8)


@pytest.mark.slow
def test_random_models_band_verdicts_deep():
    seen = _random_band_checks(seed=12, count=150)
    assert {PASSIVE, NOT_PASSIVE} <= seen


def test_a_pole_inside_the_band_is_named_in_the_verdict():
    """1/s: Re H(jw) = 0 for w != 0, so nu >= 0 on the band where H is defined; the pole
    at w = 0 is stated, not hidden."""
    integrator = from_state_space(np.array([[0.0]]), np.array([[1.0]]), np.array([[1.0]]),
                                  np.array([[0.0]]), name="1/s")
    d = decide_band(integrator, (F(0), F(1)))
    assert d.verdict == PASSIVE and "poles at ω ≈ 0" in d.reason
    # 1/s^2 has nu -> -infinity at its pole: the witness comes from another band point
    double = from_state_space(np.array([[0.0, 1.0], [0.0, 0.0]]), np.array([[0.0], [1.0]]),
                              np.array([[1.0, 0.0]]), np.array([[0.0]]), name="1/s^2")
    d = decide_band(double, (F(0), F(1)))
    assert d.verdict == NOT_PASSIVE and F(0) < Fraction(d.witness.data["omega"]) <= F(1)


def test_gkyp_matrix_with_q_zero_is_the_kyp_matrix(ks25):
    """Sign conventions: with Q = 0 the generalized KYP matrix is the ordinary one."""
    from verify.passivity.check import exact as ex
    from verify.passivity.check.certificate import exact_model, kyp_matrix
    from verify.passivity.check.gkyp import gkyp_matrix

    em = exact_model(ks25.A, ks25.B, ks25.C, ks25.D)
    rng = np.random.default_rng(3)
    X = rng.integers(-5, 6, size=(em.n, em.n)).astype(float)
    P = ex.to_rational(X + X.T)
    zero = ex.zeros(em.n, em.n)
    Lr, Li = gkyp_matrix(em, (P, zero), (zero, zero), (F(1, 3), F(7, 2)))
    assert Lr == kyp_matrix(em, P) and all(x == 0 for row in Li for x in row)


def test_gkyp_quadratic_form_identity(ks25):
    """z^H L(P, Q) z = psi(w) x^H Q x - u^H (H + H^H) u for z = ((jw - A)^-1 B u, u), any
    Hermitian P, Q, with psi(w) = -(w - w1)(w - w2): the identity behind the certificate."""
    from verify.passivity.check import exact as ex
    from verify.passivity.check.certificate import exact_model
    from verify.passivity.check.gkyp import gkyp_matrix

    em = exact_model(ks25.A, ks25.B, ks25.C, ks25.D)
    n, m = em.n, em.m
    rng = np.random.default_rng(5)

    def hermitian():
        X = rng.normal(size=(n, n)) + 1j * rng.normal(size=(n, n))
        X = X + X.conj().T
        return (ex.to_rational(X.real), ex.to_rational(X.imag)), X

    (P, _), (Q, Qf) = hermitian(), hermitian()
    band = (F(1, 2), F(3))
    Lr, Li = gkyp_matrix(em, P, Q, band)
    L = np.array(Lr, dtype=float) + 1j * np.array(Li, dtype=float)
    for w in (0.1, 0.5, 1.7, 3.0, 4.2):
        u = rng.normal(size=m) + 1j * rng.normal(size=m)
        x = np.linalg.solve(1j * w * np.eye(n) - ks25.A, ks25.B @ u)
        z = np.concatenate([x, u])
        H = ks25.frequency_response(np.array([w]))[0]
        psi = -(w - 0.5) * (w - 3.0)
        rhs = psi * (x.conj() @ Qf @ x) - u.conj() @ (H + H.conj().T) @ u
        assert z.conj() @ L @ z == pytest.approx(rhs, rel=1e-9, abs=1e-9)
