"""The lossless storage from P K = L: found, re-checked independently, and never forced.

A lossless model x' = J Q x + G u, y = Gᵀ Q x + D u (J skew, Q > 0, D skew) has the
storage P = Q with M(P) = 0 exactly. The route solves it modulo primes and lifts it;
the certificate is then re-checked by the certificate-file checker and, independently,
by the rational KYP matrix and rational LDLᵀ. A perturbed twin with energy growth (not
passive) and a non-minimal copy must not yield a certificate, nor an error.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from gmpy2 import mpq

from verify.cli import main
from verify.coq.development import coqc_available
from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel, check_kyp, kyp_matrix
from verify.passivity.decision import decide
from verify.passivity.model import from_state_space
from verify.passivity.search.lossless import lossless_certificate
from verify.passivity.verdicts import PASSIVE

SEED = 20261129


def _exact_lossless(n: int = 6, m: int = 2, long_q: bool = True, sign: int = 1
                    ) -> tuple[ExactModel, ex.RationalMatrix]:
    """(model, Q) with a dense Q of long rationals (so several primes are needed);
    ``sign`` = -1 makes Q indefinite."""
    rng = np.random.default_rng(SEED + n)
    J = [[mpq(0)] * n for _ in range(n)]
    for i in range(n):
        for j in range(i):
            v = mpq(int(rng.integers(-5, 6)))
            J[i][j], J[j][i] = v, -v
    G = [[mpq(int(rng.integers(-4, 5)), int(rng.choice([1, 3, 7]))) for _ in range(n)]
         for _ in range(n)]
    top = mpq(2**90 + 1, 3**40) if long_q else mpq(1)
    Q = ex.add(ex.matmul(G, ex.transpose(G)),
               [[top if i == j else mpq(0) for j in range(n)] for i in range(n)], sign)
    B = [[mpq(int(rng.integers(-3, 4))) for _ in range(m)] for _ in range(n)]
    D = [[mpq(0), mpq(1, 3)], [mpq(-1, 3), mpq(0)]]
    return ExactModel(ex.matmul(J, Q), B, ex.transpose(ex.matmul(Q, B)), D), Q


def test_a_lossless_model_gets_its_storage_and_the_independent_checks_accept_it():
    model, Q = _exact_lossless()
    found = lossless_certificate(model)
    assert found.P is not None, found.reason
    assert found.P == Q  # the storage of a minimal lossless model is unique
    assert found.primes > 1  # Q's long entries need more than one prime
    assert check_kyp(model, found.P).ok
    # independent of the integer routes: rational M(P) and rational LDLᵀ
    assert all(x == 0 for row in kyp_matrix(model, found.P) for x in row)
    assert ex.pd_ldl(found.P).ok


def test_a_perturbed_non_passive_twin_gets_no_certificate():
    model, Q = _exact_lossless()
    eps = mpq(1, 2**30)  # A + eps I: energy grows, every pole moves into Re s > 0
    A = [[x + (eps if i == j else 0) for j, x in enumerate(row)]
         for i, row in enumerate(model.A)]
    twin = ExactModel(A, model.B, model.C, model.D)
    found = lossless_certificate(twin)
    assert found.P is None and "no lossless storage" in found.reason
    assert not check_kyp(twin, Q).ok  # the original storage fails on the twin
    C = [row[:] for row in model.C]
    C[0][0] += eps  # an output that no longer matches the storage
    assert lossless_certificate(ExactModel(model.A, model.B, C, model.D)).P is None


def test_an_indefinite_lossless_storage_is_found_but_not_accepted():
    """M(P) = 0 with P indefinite (energy-conserving, not passive): the exact check says
    why, and no certificate comes out."""
    model, _Q = _exact_lossless(sign=-1)
    found = lossless_certificate(model)
    assert found.P is None and "not positive definite" in found.reason, found.reason


def test_a_non_minimal_lossless_model_is_refused_with_the_reason():
    model, _Q = _exact_lossless(n=4, long_q=False)
    n, m = model.n, model.m
    zero = mpq(0)
    # a fifth state x5' = 0, not driven by u and not seen at y: uncontrollable
    A = [[*row, zero] for row in model.A] + [[zero] * (n + 1)]
    B = [*model.B, [zero] * m]
    C = [[*row, zero] for row in model.C]
    found = lossless_certificate(ExactModel(A, B, C, model.D))
    assert found.P is None and "not controllable" in found.reason


def test_the_gate_decides_a_lossless_port_hamiltonian_model_by_this_route(tmp_path):
    """The benchmark's lossless family at 24 states (with integer J and G, so that the
    file's decimals are the model's exact values): ``verify gate`` writes the certificate
    and ``verify certificates check`` accepts it."""
    rng = np.random.default_rng([SEED, 24])
    n = 24
    J = rng.integers(-9, 10, (n, n)).astype(float)
    J = J - J.T
    Q = np.diag(2.0 ** rng.integers(-2, 3, n))
    G = rng.integers(-9, 10, (n, 2)).astype(float)
    A, B, C, D = J @ Q, G, G.T @ Q, np.zeros((2, 2))
    d = decide(from_state_space(A, B, C, D, name="lossless 24"))
    assert d.verdict == PASSIVE and "lossless storage" in d.reason, d.reason
    model = tmp_path / "ll24.toml"
    model.write_text("[state_space]\n" + "".join(
        f"{k} = {json.dumps(v.tolist())}\n" for k, v in zip("ABCD", (A, B, C, D),
                                                              strict=True)))
    certs = tmp_path / "certs"
    assert main(["gate", str(model), "--certificates", str(certs)]) == 0
    written = list(certs.glob("*.json"))
    assert len(written) == 1
    P = ex.from_strings(json.loads(written[0].read_text())["P"])
    assert P == ex.to_rational(Q)
    assert main(["certificates", "check", str(certs)]) == 0


def _float_lossless(n: int, rng: np.random.Generator):
    J = rng.integers(-9, 10, (n, n)).astype(float)
    J = J - J.T
    Q = np.diag(2.0 ** rng.integers(-2, 3, n))
    G = rng.integers(-9, 10, (n, 2)).astype(float)
    return J @ Q, G, G.T @ Q, np.zeros((2, 2))


def test_the_gate_on_a_non_minimal_lossless_model_decides_its_minimal_part():
    """A hidden state (x' = 0, unseen and undriven): no error; the route itself refuses
    the non-minimal realisation, and the verdict is about the minimal part."""
    A0, B0, C0, D = _float_lossless(6, np.random.default_rng(SEED))
    A = np.block([[A0, np.zeros((6, 1))], [np.zeros((1, 7))]])
    B = np.vstack([B0, np.zeros((1, 2))])
    C = np.hstack([C0, np.zeros((2, 1))])
    model = from_state_space(A, B, C, D, name="non-minimal")
    found = lossless_certificate(model.exact)
    assert found.P is None and "not controllable" in found.reason
    d = decide(model)
    assert d.verdict == PASSIVE and "minimal" in d.reason, d.reason


@pytest.mark.slow
@pytest.mark.skipif(not coqc_available(), reason="coqc not installed")
def test_coq_accepts_the_lossless_certificate(tmp_path, capsys):
    """The KYP unit with M(P) = 0 (its -M(P) witness: the zero matrix) compiles."""
    A, B, C, D = _float_lossless(6, np.random.default_rng([SEED, 6]))
    model = tmp_path / "ll6.toml"
    model.write_text("[state_space]\n" + "".join(
        f"{k} = {json.dumps(v.tolist())}\n" for k, v in zip("ABCD", (A, B, C, D),
                                                              strict=True)))
    d = decide(from_state_space(A, B, C, D, name="ll6"))
    assert "lossless storage" in d.reason, d.reason
    rc = main(["gate", str(model), "--certificates", str(tmp_path / "c"),
               "--coq", str(tmp_path / "coq")])
    out = capsys.readouterr().out
    assert rc == 0, out
    assert "coq: compiled by coqc, accepted" in out
    assert "(P: exact LDLᵀ; -M(P): zero matrix)" in next(
        (tmp_path / "coq").glob("Cert_*.v")).read_text()
