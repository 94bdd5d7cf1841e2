"""The gate at scale and at extreme scales: frequency witnesses from one exact FLINT solve,
bounded memory at 200 states, the KYP route on rank-deficient B N, exact power-of-two
rescaling of models with entries near the float limits, and no internal error on hostile
finite inputs. Timing is measured by benchmarks/, not here.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from verify.passivity.check.certificate import check_kyp, exact_model
from verify.passivity.check.fd_certificate import check_pr_certificate_data
from verify.passivity.check.witness import response_at
from verify.passivity.decision import NOT_PASSIVE, PASSIVE, decide
from verify.passivity.model import from_state_space
from verify.passivity.port_hamiltonian import random_port_hamiltonian, with_negative_resonance
from verify.passivity.search.scaling import rescale

ROOT = Path(__file__).resolve().parents[1]


def resonant(n: int, m: int, seed: int = 1, depth: float = 0.3):
    """A stable non-passive model that needs a frequency witness (a passive
    port-Hamiltonian part of n - 2 states with D = 0.05 I, minus a resonance at w0 = 3)."""
    rng = np.random.default_rng([seed, n, m])
    A0, G, C0, _ = random_port_hamiltonian(n - 2, m, rng)
    A, B, C, D = with_negative_resonance(A0, G, C0, 0.05, rng, depth=depth)
    return from_state_space(A, B, C, D, name=f"resonant {n}x{m}")


def _float_form(model, w):
    H = model.C @ np.linalg.solve(1j * w * np.eye(model.n) - model.A, model.B) + model.D
    return H + H.conj().T


# ----------------------------------------------------------------- exact H(jw) by FLINT


@pytest.mark.parametrize("omega", [Fraction(0), Fraction(3, 4), Fraction(7)])
def test_response_is_the_exact_transfer_matrix(omega):
    """(Re H(jw), Im H(jw)) agree with sympy's exact solve over Q(i) entry by entry."""
    rng = np.random.default_rng(4)
    A = rng.standard_normal((3, 3)) - 3 * np.eye(3)
    B, C, D = rng.standard_normal((3, 2)), rng.standard_normal((2, 3)), np.eye(2) / 3
    em = exact_model(A, B, C, D)
    Hr, Hi = response_at(em, omega)
    S = lambda M: sp.Matrix([[sp.Rational(int(x.numerator), int(x.denominator))  # noqa: E731
                              for x in row] for row in M])
    w = sp.Rational(omega.numerator, omega.denominator)
    H = S(em.C) * (sp.I * w * sp.eye(3) - S(em.A)).LUsolve(S(em.B)) + S(em.D)
    for i in range(2):
        for j in range(2):
            re, im = sp.expand(H[i, j]).as_real_imag()
            assert sp.Rational(int(Hr[i][j].numerator), int(Hr[i][j].denominator)) == re
            assert sp.Rational(int(Hi[i][j].numerator), int(Hi[i][j].denominator)) == im


def test_response_at_an_imaginary_eigenvalue_is_none():
    em = exact_model(np.array([[0.0, 2.0], [-2.0, 0.0]]), np.eye(2), np.eye(2), np.eye(2))
    assert response_at(em, Fraction(2)) is None
    assert response_at(em, Fraction(3)) is not None


@pytest.mark.parametrize("n, m", [(12, 3), (60, 5)])
def test_frequency_witness_of_a_resonant_model(n, m):
    model = resonant(n, m)
    d = decide(model)
    assert d.verdict == NOT_PASSIVE, d.reason
    w = d.witness
    assert w.kind == "frequency"
    omega = Fraction(w.data["omega"])
    assert abs(float(omega) - 3.0) < 0.1  # at the resonance
    v = np.array([float(Fraction(a)) + 1j * float(Fraction(b))
                  for a, b in zip(w.data["a"], w.data["b"], strict=True)])
    assert float(np.real(v.conj() @ _float_form(model, float(omega)) @ v)) < 0
    assert Fraction(w.data["value"]) < 0


@pytest.mark.slow
def test_two_hundred_states_five_ports_within_two_gigabytes():
    """The 200 x 5 case that used to be killed at 24 GB: a fresh process, peak RSS measured."""
    code = (
        "import json, resource, sys; sys.path.insert(0, 'tests')\n"
        "from test_passivity_scale import resonant\n"
        "from verify.passivity.decision import decide\n"
        "d = decide(resonant(200, 5))\n"
        "print(json.dumps([d.verdict, d.witness.kind if d.witness else None,\n"
        "    resource.getrusage(resource.RUSAGE_SELF).ru_maxrss]))\n")
    env = {**os.environ, "PYTHONPATH": str(ROOT), "OPENBLAS_NUM_THREADS": "1"}
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True,
                         text=True, timeout=600, check=True)
    verdict, kind, peak_kb = json.loads(out.stdout.strip().splitlines()[-1])
    assert verdict == NOT_PASSIVE and kind == "frequency"
    assert peak_kb < 2 * 1024 * 1024


# ----------------------------------------------------------------- the KYP route, robust


def _certified(d):
    assert d.verdict == PASSIVE, d.reason
    cert = d.certificate
    assert cert is not None and check_kyp(cert.model, cert.P).ok
    return cert


def test_rank_deficient_b_n_is_decided_passive():
    """One state, two identical input columns: B N = [1, 1] has rank 1; P = 1 works."""
    model = from_state_space([[-1.0]], [[1.0, 1.0]], [[1.0], [1.0]], np.zeros((2, 2)))
    cert = _certified(decide(model))
    assert cert.P == [[1]]  # forced: P B = C^T


def test_rank_deficient_b_n_with_partial_feedthrough_kernel():
    """ker(D + D^T) is two of three inputs, B on it rank one; the third input is strict."""
    B = np.array([[1.0, 2.0, 0.5], [0.0, 0.0, 1.0]])
    model = from_state_space([[-1.0, 0.0], [0.0, -2.0]], B, B.T, np.diag([0.0, 0.0, 1.0]))
    _certified(decide(model))


def test_rank_deficient_b_n_with_output_on_the_dropped_direction_is_not_passive():
    """B u = 0 but C u != 0 for u = (1, -1): H = [[1, 1], [2, 2]]/(s + 1) is not passive."""
    model = from_state_space([[-1.0]], [[1.0, 1.0]], [[1.0], [2.0]], np.zeros((2, 2)))
    d = decide(model)
    assert d.verdict == NOT_PASSIVE, d.reason
    assert d.witness is not None and d.witness.kind == "rhp-point"


@pytest.mark.parametrize("A, B, C, D", [
    ([[-1e150]], [[1e150]], [[1e150]], [[0.0]]),
    ([[-1e-150]], [[1e-150]], [[1e-150]], [[0.0]]),
    ([[-5e-324]], [[5e-324]], [[5e-324]], [[0.0]]),
    ([[-1.0]], [[1.0]], [[1.0]], [[1e300]]),
    ([[-1e150, 0.0], [0.0, -1e-150]], [[1e150], [1e-150]], [[1e150, 1e-150]], [[0.0]]),
], ids=["1e150", "1e-150", "subnormal", "D=1e300", "1e150 and 1e-150"])
def test_badly_scaled_passive_models_get_certificates_on_the_model_as_written(A, B, C, D):
    model = from_state_space(A, B, C, D)
    assert rescale(model.exact) is not None
    cert = _certified(decide(model))
    assert cert.model == model.exact  # on the model as written


def test_well_scaled_models_are_not_rescaled():
    assert rescale(from_state_space([[-2.0]], [[3.0]], [[1e3]], [[1e-3]]).exact) is None


def test_badly_scaled_non_passive_model_has_a_witness_for_the_model_as_written():
    """H = -1e300/(s + 1e150): the witness point s* and value are mapped back exactly."""
    model = from_state_space([[-1e150]], [[1e150]], [[-1e150]], [[0.0]])
    d = decide(model)
    assert d.verdict == NOT_PASSIVE, d.reason
    w = d.witness
    assert w.kind == "rhp-point" and "rescaled" in w.data
    s = Fraction(w.data["s"])
    a, b, c = (Fraction(float(x[0][0])) for x in (model.A, model.B, model.C))
    H = c * b / (s - a)  # exact value of the 1 x 1 transfer function at s*
    assert s > 0 and H < 0


def test_hostile_finite_models_never_raise():
    """Entries across the whole float range (subnormal to 1e300), zeros, unstable and
    singular A: every model gets a verdict with its evidence, never an exception."""
    rng = np.random.default_rng(20261123)
    for _ in range(12):
        n, m = int(rng.integers(1, 3)), int(rng.integers(1, 3))

        def mat(r, c):
            e = rng.choice([0, int(rng.integers(-1074, 1000))], size=(r, c)).astype(int)
            x = np.ldexp(rng.standard_normal((r, c)), e)
            x[rng.random((r, c)) < 0.3] = 0.0
            return x

        A = mat(n, n)
        if rng.random() < 0.5:
            A = A - np.abs(A).max() * np.eye(n)
        model = from_state_space(A, mat(n, m), mat(m, n), mat(m, m))
        with np.errstate(all="ignore"):
            d = decide(model)
        if d.verdict == PASSIVE and hasattr(d.certificate, "P"):
            assert check_kyp(d.certificate.model, d.certificate.P).ok
        elif d.verdict == PASSIVE:  # the frequency-domain route
            assert check_pr_certificate_data(d.certificate.to_json()).ok
        elif d.verdict == NOT_PASSIVE:
            assert d.witness is not None


@pytest.mark.parametrize("margin, verdict", [
    (Fraction(10) ** 400, NOT_PASSIVE), (-Fraction(10) ** 400, PASSIVE),
    (-Fraction(10) ** 300, PASSIVE), (Fraction(1, 10**400), NOT_PASSIVE),
])
def test_margins_beyond_the_float_range(margin, verdict):
    """H - nu0 I for nu0 = +-1e400: decided on the rescaled problem, no overflow."""
    model = from_state_space([[-1.0, 0.0], [0.0, -2.0]], [[1.0], [1.0]], [[1.0, 1.0]],
                             [[0.0]])
    d = decide(model, margin)
    assert d.verdict == verdict, d.reason
    if verdict == PASSIVE:
        assert check_kyp(d.certificate.model, d.certificate.P).ok
        assert d.certificate.model.D[0][0] == -margin  # the certificate is for H - nu0 I
    else:
        assert d.witness is not None


def test_verified_solve_bound_is_above_the_exact_value_and_close():
    """The bound of witness_bound for v from the float eigenvector: exact q <= bound, and
    the bound is tight (the Neumann error term is tiny for a well-conditioned K)."""
    from verify.passivity.check.witness_bound import bounded_form, float_direction

    model = resonant(24, 3)
    em = exact_model(model.A, model.B, model.C, model.D)
    w = Fraction(3)
    a, b = float_direction(model.A, model.B, model.C, model.D, 3.0)
    bound = bounded_form(em, w, a, b)
    Hr, Hi = response_at(em, w)
    m = model.m
    # v^H (H + H^H) v with H = Hr + j Hi, v = a + j b, exactly
    re = sum(a[i] * (Hr[i][j] + Hr[j][i]) * a[j] + b[i] * (Hr[i][j] + Hr[j][i]) * b[j]
             for i in range(m) for j in range(m))
    im = sum(2 * (a[i] * (Hi[i][j] - Hi[j][i]) * b[j]) for i in range(m) for j in range(m))
    exact_q = re - im
    assert exact_q < 0
    assert exact_q <= bound < 0
    assert bound - exact_q < Fraction(1, 10**6) * abs(exact_q)


def test_large_resonant_model_uses_the_verified_solve():
    model = resonant(80, 3)
    d = decide(model)
    assert d.verdict == NOT_PASSIVE, d.reason
    w = d.witness
    assert w.kind == "frequency" and Fraction(w.data["value_bound"]) < 0
    v = np.array([float(Fraction(x)) + 1j * float(Fraction(y))
                  for x, y in zip(w.data["a"], w.data["b"], strict=True)])
    assert float(np.real(v.conj() @ _float_form(model, float(Fraction(w.data["omega"]))) @ v)) < 0


# the complete route on the families of benchmarks/bench_passivity_complete.py -----------

def complete_family(family: str, n: int, seed: int = 5):
    """lossless (J Q, G, G^T Q, 0); tangent: a dissipative port-Hamiltonian 1-port beside
    H_t = (s^2/2 + s/2 + 1)/(s + 1)^3, whose nu touches 0 at w = 1; nonpassive: port 2
    H_t - 2^-40/(s + 1) (nu < 0 only within ~1e-6 of w = 1, at least -2^-41)."""
    rng = np.random.default_rng([seed, n])
    if family == "lossless":
        J = rng.standard_normal((n, n))
        J = J - J.T
        Q = np.diag(2.0 ** rng.integers(-2, 3, n))
        G = rng.standard_normal((n, 2))
        return from_state_space(J @ Q, G, G.T @ Q, np.zeros((2, 2)), name=f"lossless {n}")
    A1, B1, C1, _ = random_port_hamiltonian(n - 3, 1, rng)
    At = np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [-1.0, -3.0, -3.0]])
    A = np.block([[A1, np.zeros((n - 3, 3))], [np.zeros((3, n - 3)), At]])
    B = np.block([[B1, np.zeros((n - 3, 1))], [np.zeros((3, 1)), np.array([[0], [0], [1.0]])]])
    eps = 2.0**-40 if family == "nonpassive" else 0.0  # H_t - eps / (s + 1)
    Ct = np.array([[1.0 - eps, 0.5 - 2 * eps, 0.5 - eps]])
    C = np.block([[C1, np.zeros((1, 3))], [np.zeros((1, n - 3)), Ct]])
    return from_state_space(A, B, C, np.zeros((2, 2)), name=f"{family} {n}")


EXPECTED_FAMILY = {"lossless": PASSIVE, "tangent": PASSIVE, "nonpassive": NOT_PASSIVE}


@pytest.mark.parametrize("family", sorted(EXPECTED_FAMILY))
def test_complete_route_families_small(family):
    from verify.passivity.band import decide_band
    from verify.passivity.check.fd_certificate import PrCertificate

    model = complete_family(family, 12)
    d = decide(model)
    assert d.verdict == EXPECTED_FAMILY[family], d.reason
    if isinstance(d.certificate, PrCertificate):  # the complete route's certificate
        assert check_pr_certificate_data(d.certificate.to_json()).ok
    band = decide_band(model, (Fraction(0), Fraction(3, 2)))
    assert band.verdict == EXPECTED_FAMILY[family], band.reason


@pytest.mark.slow
@pytest.mark.parametrize("n", [60, 120])
@pytest.mark.parametrize("family", sorted(EXPECTED_FAMILY))
def test_complete_route_families_at_scale(family, n):
    """Decided, never inconclusive, up to the complete route's limit (timings:
    benchmarks/bench_passivity_complete.py)."""
    assert decide(complete_family(family, n)).verdict == EXPECTED_FAMILY[family]
