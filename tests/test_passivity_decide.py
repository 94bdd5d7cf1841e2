"""Passivity verdicts with known answers (paper, Section 4), certificates and witnesses.

Every passive verdict must come with a certificate that the exact checker accepts; every
not-passive verdict with a witness; the tests re-check both independently.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import check_kyp
from verify.passivity.decision import NOT_PASSIVE, PASSIVE, decide, nu
from verify.passivity.model import from_state_space


def ss(A, B, C, D, name="m"):
    D = np.atleast_2d(np.array(D, dtype=float))
    m = D.shape[0]
    if np.size(A) == 0:
        return from_state_space(np.zeros((0, 0)), np.zeros((0, m)), np.zeros((m, 0)), D,
                                name=name)
    return from_state_space(*(np.atleast_2d(np.array(x, dtype=float)) for x in (A, B, C)), D,
                            name=name)


CASES = {
    # strictly proper, D + D^T = 0: P B = C^T must hold exactly
    "1/(s+1)": (ss([[-1]], [[1]], [[1]], [[0]]), PASSIVE),
    "2x2 strictly proper": (ss([[-1, 0], [0, -2]], [[1, 0], [0, 1]], [[1, 0], [0, 1]],
                               [[0, 0], [0, 0]]), PASSIVE),
    # poles on the imaginary axis
    "1/s": (ss([[0]], [[1]], [[1]], [[0]]), PASSIVE),
    "s/(s^2+1) lossless": (ss([[0, 1], [-1, 0]], [[0], [1]], [[0, 1]], [[0]]), PASSIVE),
    "1/s^2": (ss([[0, 1], [0, 0]], [[0], [1]], [[1, 0]], [[0]]), NOT_PASSIVE),
    "-1/s": (ss([[0]], [[1]], [[-1]], [[0]]), NOT_PASSIVE),
    # unstable with nu(w) >= 0 everywhere
    "s/(s-1)": (ss([[1]], [[1]], [[1]], [[1]]), NOT_PASSIVE),
    # static gains
    "static passive": (ss([], [], [], [[1, 0.5], [-0.5, 0]]), PASSIVE),
    "static not passive": (ss([], [], [], [[1, 2], [0, 0]]), NOT_PASSIVE),
    # badly scaled: poles near 1e12 and 1e-4
    "1/(s+1e-4) + 1e12/(s+1e12)": (
        ss([[-1e-4, 0], [0, -1e12]], [[1], [1e6]], [[1, 1e6]], [[0]]), PASSIVE),
    "badly scaled, not passive": (
        ss([[-1e-4, 0], [0, -1e12]], [[1], [1e6]], [[1, -2e6]], [[0]]), NOT_PASSIVE),
    # on the boundary: nu(w) > 0 but ~ 1/w^4, and the KYP LMI pins P[0][0] = 2 exactly
    "(s+1)/(s^2+s+1)": (ss([[0, 1], [-1, -1]], [[0], [1]], [[1, 1]], [[0]]), PASSIVE),
    # a frequency-domain violation at a finite frequency
    "1/(s^2+s+1)": (ss([[0, 1], [-1, -1]], [[0], [1]], [[1, 0]], [[0]]), NOT_PASSIVE),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_known_verdicts_with_checked_evidence(name):
    model, expected = CASES[name]
    d = decide(model)
    assert d.verdict == expected, d.reason
    if expected == PASSIVE:
        cert = d.certificate
        assert cert is not None and check_kyp(cert.model, cert.P).ok
    else:
        assert d.witness is not None
        if d.witness.kind == "frequency":
            w = float(Fraction(d.witness.data["omega"]))
            assert nu(model.A, model.B, model.C, model.D, np.array([w]))[0] < 0


@pytest.mark.parametrize("z, expected", [(1 - 1e-8, PASSIVE), (1 + 1e-8, NOT_PASSIVE)])
def test_near_boundary_in_frequency(z, expected):
    """(s + z)/(s^2 + s + 1) is passive iff z <= 1; at z = 1 + 1e-8 nu < 0 only above 1e4."""
    d = decide(ss([[0, 1], [-1, -1]], [[0], [1]], [[z, 1]], [[0]]))
    assert d.verdict == expected, d.reason


@pytest.mark.parametrize(
    "feedthrough, expected",
    [
        (2e-8, PASSIVE),
        (1e-8, PASSIVE),  # exactly on the boundary: nu(w) > 1e-8, inf nu = 1e-8
        (float(np.nextafter(1e-8, 0)), NOT_PASSIVE),  # one ulp short
        (0.5e-8, NOT_PASSIVE),
        (-1e-8, NOT_PASSIVE),
    ],
)
def test_margin_of_1e_minus_8(feedthrough, expected):
    """nu(w) of 1/(s+1) + d decreases to d as w grows: nu >= 1e-8 iff d >= 1e-8 (both the
    float 1e-8, compared exactly)."""
    model = ss([[-1]], [[1]], [[1]], [[feedthrough]])
    d = decide(model, margin=Fraction(1e-8))
    assert d.verdict == expected, d.reason


def test_a_tampered_certificate_is_rejected():
    d = decide(CASES["1/(s+1)"][0])
    P = [row[:] for row in d.certificate.P]
    P[0][0] = P[0][0] * 3  # P B = C^T no longer holds
    assert not check_kyp(d.certificate.model, P).ok
    assert check_kyp(d.certificate.model, d.certificate.P).ok


def test_exact_ldl_decides_semidefinite_matrices():
    q = ex.to_rational
    assert ex.psd_ldl(q([[1, 1], [1, 1]])).ok
    assert not ex.pd_ldl(q([[1, 1], [1, 1]])).ok
    assert not ex.psd_ldl(q([[0, 1], [1, 0]])).ok
    assert not ex.psd_ldl(q([[1, 0], [0, -1e-300]])).ok
    assert ex.psd_ldl(q([[0, 0], [0, 0]])).ok


def test_a_hidden_unstable_mode_is_decided_for_the_transfer_function():
    """1/(s+1) with an extra uncontrollable, unobservable unstable state: no P > 0 solves
    the KYP LMI for this non-minimal realisation, but H(s) = 1/(s+1) is positive real;
    the verdict says it is about H(s), not a storage function on the given state."""
    from verify.passivity.check.fd_certificate import PrCertificate, check_pr_certificate_data

    model = ss([[-1, 0], [0, 1]], [[1], [0]], [[1, 0]], [[0]])
    d = decide(model)
    assert d.verdict == PASSIVE
    assert "not minimal" in d.reason and "1 in Re s > 0" in d.reason
    assert "positive realness of the transfer function" in d.reason
    assert d.certificate is not None and d.certificate.model.n == 1
    if not isinstance(d.certificate, PrCertificate):  # the KYP route, on the minimal part
        return
    assert check_pr_certificate_data(d.certificate.to_json()).ok


def test_verdicts_are_a_closed_set_that_serialises_as_before():
    """GateVerdict members are the old strings: equal, formatted and JSON-encoded alike."""
    import json

    from verify.passivity import GateVerdict
    from verify.passivity.search.tolerance import PASSIVE_WITHIN

    assert [str(v) for v in GateVerdict] == [
        "passive", "not passive", "inconclusive", "passive within tolerance"]
    assert PASSIVE is GateVerdict.PASSIVE and PASSIVE_WITHIN is GateVerdict.PASSIVE_WITHIN
    d = decide(ss([[-1.0]], [[1.0]], [[1.0]], [[0.0]]))
    assert d.verdict is GateVerdict.PASSIVE
    assert json.dumps(d.to_json()["verdict"]) == '"passive"' and f"{d.verdict}" == "passive"
    d = decide(ss([[-1.0]], [[1.0]], [[-1.0]], [[0.0]]))
    assert d.verdict is NOT_PASSIVE and d.witness is not None
