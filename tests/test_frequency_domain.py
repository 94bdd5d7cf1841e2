"""The exact frequency-domain decision of positive realness (certificates and witnesses).

Models are exact state-space realisations written by hand (rationals, no rounding).
Every passive verdict's certificate is re-checked by the JSON checker; every frequency
witness is re-evaluated exactly from the state-space data.
"""

from __future__ import annotations

import json
from fractions import Fraction

import numpy as np
import pytest
from gmpy2 import mpq
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.fd_certificate import (
    check_pr_certificate_data,
    check_pr_certificate_file,
    parse_json_text,
)
from verify.passivity.check.fd_witness import exact_negative_vector
from verify.passivity.check.frequency_domain import analyse, transfer_matrix
from verify.passivity.check.witness import hermitian_part_at
from verify.passivity.decision import NOT_PASSIVE, PASSIVE, decide, nu
from verify.passivity.fd_decision import decide_positive_real
from verify.passivity.model import from_state_space


def Q(rows) -> ex.RationalMatrix:
    return [[mpq(Fraction(x)) if isinstance(x, str | Fraction) else mpq(x) for x in row]
            for row in rows]


def em(A, B, C, D) -> ExactModel:
    m = len(D)
    if not A:
        return ExactModel([], [], [[] for _ in range(m)], Q(D))
    return ExactModel(Q(A), Q(B), Q(C), Q(D))


def block_diag(*blocks):
    n = sum(len(b) for b in blocks)
    out = [[0] * n for _ in range(n)]
    k = 0
    for b in blocks:
        for i, row in enumerate(b):
            for j, x in enumerate(row):
                out[k + i][k + j] = x
        k += len(b)
    return out


def circulant(first):
    m = len(first)
    return [[first[(j - i) % m] for j in range(m)] for i in range(m)]


def identity(m):
    return [[int(i == j) for j in range(m)] for i in range(m)]


def zeros(m):
    return [[0] * m for _ in range(m)]


EPS40 = Fraction(1, 2**40)

CASES = {
    # lossless: skew D, J-structured A, C = B^T
    "lossless MIMO": (em(block_diag([[0, 1], [-1, 0]], [[0, 2], [-2, 0]]),
                         [[1, 0], [0, 0], [0, 1], [1, 1]], [[1, 0, 0, 1], [0, 0, 1, 1]],
                         [[0, 3], [-3, 0]]), PASSIVE),
    # 2 + 5/(s+4) + 5s/(s^2+2): PSD residues at +-j sqrt(2)
    "2 + 5/(s+4) + 5s/(s^2+2)": (em(block_diag([[0, 1], [-2, 0]], [[-4]]),
                                    [[0], [1], [1]], [[0, 5, 5]], [[2]]), PASSIVE),
    "1 - s/(s^2+1)": (em([[0, 1], [-1, 0]], [[0], [1]], [[0, -1]], [[1]]), NOT_PASSIVE),
    "s/(s^2+1/10)": (em([[0, 1], ["-1/10", 0]], [[0], [1]], [[0, 1]], [[0]]), PASSIVE),
    "(s+2)/(s^2+2s+2)": (em([[0, 1], [-2, -2]], [[0], [1]], [[2, 1]], [[0]]), PASSIVE),
    "1/s": (em([[0]], [[1]], [[1]], [[0]]), PASSIVE),
    "-1/s": (em([[0]], [[1]], [[-1]], [[0]]), NOT_PASSIVE),
    "1/s^2": (em([[0, 1], [0, 0]], [[0], [1]], [[1, 0]], [[0]]), NOT_PASSIVE),
    "s/(s^2+1)^2 (double axis pole)": (
        em([[0, 1, 0, 0], [-1, 0, 1, 0], [0, 0, 0, 1], [0, 0, -1, 0]], [[0], [0], [0], [1]],
           [[0, 1, 0, 0]], [[0]]), NOT_PASSIVE),
    "1/(s^2+s+1)": (em([[0, 1], [-1, -1]], [[0], [1]], [[1, 0]], [[0]]), NOT_PASSIVE),
    # unstable pole with nu >= 0 on the axis
    "s/(s-1)": (em([[1]], [[1]], [[1]], [[1]]), NOT_PASSIVE),
    # near-cancellations of an unstable pole at several scales
    "(s-1-2^-40)/(s^2-1)": (em([[0, 1], [1, 0]], [[0], [1]], [[-1 - EPS40, 1]], [[0]]),
                            NOT_PASSIVE),
    "(s-1+2^-40)/(s^2-1)": (em([[0, 1], [1, 0]], [[0], [1]], [[-1 + EPS40, 1]], [[0]]),
                            NOT_PASSIVE),
    "(s-1-10^-30)/(s^2-1)": (em([[0, 1], [1, 0]], [[0], [1]],
                                [[str(-1 - Fraction(1, 10**30)), 1]], [[0]]), NOT_PASSIVE),
    # exact cancellation: (s-1)/(s^2-1) = 1/(s+1), a hidden unstable mode
    "(s-1)/(s^2-1)": (em([[0, 1], [1, 0]], [[0], [1]], [[-1, 1]], [[0]]), PASSIVE),
    # common factor (s^2+1)(s+2)/((s^2+s+1)(s+2)): realised in controller form
    "(s^2+1)(s+2)/((s^2+s+1)(s+2))": (
        em([[0, 1, 0], [0, 0, 1], [-2, -3, -3]], [[0], [0], [1]], [[0, -2, -1]], [[1]]),
        PASSIVE),
    "[[2,1],[1,2]]/(s+1)": (em([[-1, 0], [0, -1]], identity(2), [[2, 1], [1, 2]],
                               zeros(2)), PASSIVE),
    "[[2,1],[1,2]]/s": (em([[0, 0], [0, 0]], identity(2), [[2, 1], [1, 2]], zeros(2)),
                        PASSIVE),
    "[[1,1],[1,1]]/(s+1)": (em([[-1]], [[1, 1]], [[1], [1]], zeros(2)), PASSIVE),
    "circulant 3x3 / (s+1)": (em([[-1 if i == j else 0 for j in range(3)] for i in range(3)],
                                 identity(3), circulant([3, 1, 1]), zeros(3)), PASSIVE),
    "circulant 5x5 / (s+1)": (em([[-1 if i == j else 0 for j in range(5)] for i in range(5)],
                                 identity(5), circulant([4, 1, 0, 0, 1]), zeros(5)), PASSIVE),
    "non-symmetric circulant 3x3 / (s+1)": (
        em([[-1 if i == j else 0 for j in range(3)] for i in range(3)], identity(3),
           circulant([2, 1, 0]), zeros(3)), NOT_PASSIVE),
    # static gains on the boundary of the PSD cone
    "static [[1,1],[1,1]]": (em([], [], [], [[1, 1], [1, 1]]), PASSIVE),
    "static [[1,1+2^-60],[1,1]]": (em([], [], [], [[1, 1 + Fraction(1, 2**60)], [1, 1]]),
                                   NOT_PASSIVE),
    "static [[1, 2^31], [0, 2^60-1]]": (em([], [], [], [[1, 2**31], [0, 2**60 - 1]]),
                                        NOT_PASSIVE),
    "static [[1, 2^31], [0, 2^60]]": (em([], [], [], [[1, 2**31], [0, 2**60]]), PASSIVE),
}


def recheck_frequency_witness(model: ExactModel, data: dict) -> None:
    M = hermitian_part_at(model, Fraction(data["omega"]))
    v = [mpq(Fraction(x)) for x in data["a"] + data["b"]]
    value = sum((v[i] * M[i][j] * v[j] for i in range(len(v)) for j in range(len(v))),
                mpq(0))
    assert value < 0 and value == mpq(Fraction(data["value"]))


def recheck(model: ExactModel, verdict, cert, witness) -> None:
    if verdict == PASSIVE:
        data = parse_json_text(json.dumps(cert.to_json()))
        result = check_pr_certificate_data(data)
        assert result.ok, result.reason
    else:
        assert witness is not None
        if witness.kind == "frequency":
            recheck_frequency_witness(model, witness.data)


@pytest.mark.parametrize("name", sorted(CASES))
def test_known_verdicts(name):
    model, expected = CASES[name]
    verdict, reason, cert, witness = decide_positive_real(model)
    assert verdict == expected, reason
    recheck(model, verdict, cert, witness)


def test_witness_kinds():
    """Each failure carries the evidence of its own kind."""
    kinds = {name: decide_positive_real(CASES[name][0])[3].kind for name in (
        "1 - s/(s^2+1)", "1/s^2", "s/(s-1)", "(s-1-2^-40)/(s^2-1)", "1/(s^2+s+1)",
        "non-symmetric circulant 3x3 / (s+1)")}
    assert kinds == {"1 - s/(s^2+1)": "residue-not-psd", "1/s^2": "repeated-axis-pole",
                     "s/(s-1)": "unstable-pole", "(s-1-2^-40)/(s^2-1)": "unstable-pole",
                     "1/(s^2+s+1)": "frequency",
                     "non-symmetric circulant 3x3 / (s+1)": "frequency"}


def test_non_hermitian_residue_gives_a_frequency_witness():
    """[[0, 1/s], [0, 0]]: residue [[0,1],[0,0]] at 0 is not Hermitian."""
    model = em([[0]], [[0, 1]], [[1], [0]], zeros(2))
    verdict, reason, _cert, witness = decide_positive_real(model)
    assert verdict == NOT_PASSIVE and "not Hermitian" in reason
    assert witness.kind == "frequency"
    recheck_frequency_witness(model, witness.data)


def test_tiny_violation_found_exactly():
    """(s + 1 + 2^-40)/(s^2 + s + 1): Re H(jw) < 0 only for w above about 2^20."""
    model = em([[0, 1], [-1, -1]], [[0], [1]], [[1 + EPS40, 1]], [[0]])
    verdict, _reason, _cert, witness = decide_positive_real(model)
    assert verdict == NOT_PASSIVE and witness.kind == "frequency"
    recheck_frequency_witness(model, witness.data)
    assert decide_positive_real(em([[0, 1], [-1, -1]], [[0], [1]], [[1, 1]], [[0]]))[0] \
        == PASSIVE


def test_transfer_matrix_cancels_exactly():
    tm = transfer_matrix(CASES["(s-1)/(s^2-1)"][0])
    assert [str(c) for c in tm.dens[0][0].coeffs()] == ["1", "1"]
    assert [str(c) for c in tm.nums[0][0].coeffs()] == ["1"]


def test_exact_negative_vector():
    M = Q([[0, 1], [1, 0]])
    _v, value = exact_negative_vector(M)
    assert value < 0
    assert exact_negative_vector(Q([[1, 1], [1, 1]])) is None
    M = Q([[1, 2, 0], [2, 1, 0], [0, 0, 5]])
    assert exact_negative_vector(M)[1] < 0


# certificates: round trip and tampering ----------------------------------------------

def _passive_json(name="2 + 5/(s+4) + 5s/(s^2+2)"):
    _v, _r, cert, _w = decide_positive_real(CASES[name][0], "h", "h.toml", {"margin": "0"})
    return cert.to_json()


def test_certificate_bytes_are_deterministic():
    a = json.dumps(_passive_json(), indent=1)
    b = json.dumps(_passive_json(), indent=1)
    assert a == b


def test_certificate_file_round_trip(tmp_path):
    from verify.certificates.registry import check_stored_certificate
    from verify.passivity.io.binding import Claim, file_name

    data = _passive_json()
    path = tmp_path / "c.json"
    path.write_text(json.dumps(data, indent=1))
    assert check_pr_certificate_file(path).ok  # the exact facts alone
    # bound to its claim: a file name that does not match the content is refused
    assert not check_stored_certificate(path).ok
    named = tmp_path / file_name("h", Claim(), data["fingerprint"])
    named.write_text(json.dumps(data, indent=1))
    result = check_stored_certificate(named)  # its source is not found: unbound
    assert not result.ok and result.status == "unbound" and result.unchecked == ("name",)
    result = check_stored_certificate(named, allow_unbound=True)
    assert result.ok and "h.toml not found" in result.reason
    # a source file that denotes another model is refused
    (tmp_path / "h.toml").write_text("[transfer_function]\nnum = [[[1]]]\nden = [[[1, 1]]]\n")
    other = tmp_path / "certs"
    other.mkdir()
    moved = other / named.name
    moved.write_text(named.read_text())
    assert "another model" in check_stored_certificate(moved).reason
    # a margin other than the proven one (meta.margin shifts the model the name binds)
    data["meta"] = {"margin": "1"}
    named.write_text(json.dumps(data, indent=1))
    assert not check_stored_certificate(named).ok


def _tampered(edit):
    data = json.loads(json.dumps(_passive_json()))
    edit(data)
    return data


def _refit(data):
    data["fingerprint"] = ExactModel(*(ex.from_strings(data["model"][k])
                                       for k in "ABCD")).fingerprint()


@pytest.mark.parametrize("edit", [
    lambda d: d["model"]["D"][0].__setitem__(0, "1"),  # fingerprint no longer matches
    lambda d: (d["model"]["D"][0].__setitem__(0, "3"), _refit(d)),  # facts differ
    lambda d: (d["model"]["D"][0].__setitem__(0, "-1"), _refit(d)),  # not positive real
    lambda d: d["hermitian"]["minor_sums"][0]["nonnegativity"].__setitem__("content", "-1"),
    lambda d: d["hermitian"]["minor_sums"][0]["nonnegativity"]["factors"][0].__setitem__(
        "exponent", 3),
    lambda d: d["poles"]["axis_poles"][0].__setitem__("residue_signs", [0]),
    lambda d: d.__setitem__("statement", "strictly passive with margin 5"),
    lambda d: d["transfer"].__setitem__("pole_polynomial", ["1"]),
], ids=["model", "model+fingerprint", "non-PR model", "content", "exponent", "residue sign",
        "statement", "pole polynomial"])
def test_tampering_is_refused(edit):
    assert not check_pr_certificate_data(_tampered(edit)).ok


def test_tampered_sos_weight_is_refused():
    model = em(*_random_ph(np.random.default_rng(3), 5, 2))
    data = json.loads(json.dumps(decide_positive_real(model)[2].to_json()))
    assert check_pr_certificate_data(data).ok
    found = False
    for item in data["hermitian"]["minor_sums"]:
        for f in item["nonnegativity"]["factors"]:
            if isinstance(f["sos"], list) and f["sos"]:
                f["sos"][0]["weight"] = str(Fraction(f["sos"][0]["weight"]) * 2)
                found = True
    assert found
    assert not check_pr_certificate_data(data).ok


@pytest.mark.parametrize("text", [
    '{"schema": "verify-pr-certificate/1", "schema": "verify-pr-certificate/1"}',
    '{"schema": "verify-pr-certificate/1", "extra": 1}',
    '[1, 2]',
])
def test_malformed_certificates(text, tmp_path):
    path = tmp_path / "c.json"
    path.write_text(text)
    with pytest.raises(ValueError):
        check_pr_certificate_file(path)


def test_unknown_field_is_refused():
    data = _passive_json()
    data["P"] = [["1"]]
    with pytest.raises(ValueError, match="unknown fields"):
        check_pr_certificate_data(data)


# through decide(): the KYP route first, the frequency route for what it cannot -------

def _lti(model: ExactModel):
    f = [np.array([[float(x) for x in row] for row in M], dtype=float).reshape(r, c)
         for M, r, c in ((model.A, model.n, model.n), (model.B, model.n, model.m),
                         (model.C, model.m, model.n), (model.D, model.m, model.m))]
    return from_state_space(*f, name="m")


@pytest.mark.parametrize("name", ["(s-1)/(s^2-1)", "1 - s/(s^2+1)", "[[2,1],[1,2]]/s",
                                  "circulant 3x3 / (s+1)", "(s+2)/(s^2+2s+2)"])
def test_decide_never_inconclusive(name):
    model, expected = CASES[name]
    d = decide(_lti(model))
    assert d.verdict == expected, d.reason


def test_decide_hidden_unstable_mode_says_which_notion():
    d = decide(_lti(CASES["(s-1)/(s^2-1)"][0]))
    assert d.verdict == PASSIVE and "not minimal" in d.reason
    assert "storage" in d.reason


# random models: port-Hamiltonian (passive) and perturbed ones, cross-checked --------

def _random_ph(rng, n, m, scale=1):
    J = rng.integers(-3, 4, (n, n))
    J = J - J.T
    R = rng.integers(-2, 3, (n, n))
    R = R @ R.T
    Qm = rng.integers(-2, 3, (n, n))
    Qm = Qm @ Qm.T + np.eye(n, dtype=int)
    G = rng.integers(-2, 3, (n, m))
    A = (J - R) @ Qm
    C = G.T @ Qm
    S = rng.integers(-2, 3, (m, m))
    D = S @ S.T + (S - S.T)
    return [[int(x) for x in row] for row in A], [[int(x) for x in row] for row in G], \
        [[int(x) * scale for x in row] for row in C], [[int(x) for x in row] for row in D]


@pytest.mark.parametrize("seed, n, m", [(1, 2, 1), (2, 3, 2), (3, 5, 2), (4, 6, 3),
                                        (5, 8, 2), (6, 10, 2)])
def test_random_port_hamiltonian_models_are_passive(seed, n, m):
    model = em(*_random_ph(np.random.default_rng(seed), n, m))
    verdict, reason, cert, witness = decide_positive_real(model)
    assert verdict == PASSIVE, reason
    recheck(model, verdict, cert, witness)


@pytest.mark.parametrize("seed, n, m", [(11, 3, 1), (12, 4, 2), (13, 6, 2), (14, 8, 3)])
def test_random_perturbed_models_agree_with_the_float_grid(seed, n, m):
    """C -> -C flips the sign of H - D: not passive whenever H - D is not zero."""
    rng = np.random.default_rng(seed)
    A, B, C, _D = _random_ph(rng, n, m)
    model = em(A, B, [[-x for x in row] for row in C], [[0] * m for _ in range(m)])
    verdict, reason, cert, witness = decide_positive_real(model)
    assert verdict == NOT_PASSIVE, reason
    assert witness.kind == "frequency"
    recheck(model, verdict, cert, witness)


@pytest.mark.parametrize("seed, n, m, negate", [(31, 3, 1, False), (32, 4, 2, True),
                                                (33, 6, 2, False), (34, 5, 1, True)])
def test_random_models_agree_with_the_kyp_route(seed, n, m, negate):
    """decide() tries KYP first; where it decides, both routes give the same verdict."""
    from verify.passivity.search.kyp import find_certificate

    A, B, C, D = _random_ph(np.random.default_rng(seed), n, m)
    if negate:
        C, D = [[-x for x in row] for row in C], [[0] * m for _ in range(m)]
    model = em(A, B, C, D)
    lti = _lti(model)
    kyp = find_certificate(model, lti.A, lti.B, lti.C, lti.D)
    verdict = decide_positive_real(model)[0]
    if kyp.P is not None:
        assert verdict == PASSIVE
    assert decide(lti).verdict == verdict == (NOT_PASSIVE if negate else PASSIVE)


@pytest.mark.slow
@pytest.mark.parametrize("seed, n, m", [(21, 20, 2), (22, 30, 2), (23, 30, 3)])
def test_random_models_up_to_30_states(seed, n, m):
    rng = np.random.default_rng(seed)
    A, B, C, D = _random_ph(rng, n, m)
    passive = em(A, B, C, D)
    verdict, reason, cert, witness = decide_positive_real(passive)
    assert verdict == PASSIVE, reason
    recheck(passive, verdict, cert, witness)
    broken = em(A, B, C, [[x - (2 * max(abs(y) for r in D for y in r) + 1) * (i == j)
                           for j, x in enumerate(row)] for i, row in enumerate(D)])
    verdict, reason, cert, witness = decide_positive_real(broken)
    assert verdict == NOT_PASSIVE, reason


# property: agreement with a fine float nu grid where the grid is conclusive ----------

small = st.integers(-3, 3)


@st.composite
def small_models(draw):
    n = draw(st.integers(1, 3))
    m = draw(st.integers(1, 2))
    A = [[draw(small) for _ in range(n)] for _ in range(n)]
    B = [[draw(small) for _ in range(m)] for _ in range(n)]
    C = [[draw(small) for _ in range(n)] for _ in range(m)]
    D = [[draw(small) for _ in range(m)] for _ in range(m)]
    return A, B, C, D


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(small_models())
def test_verdict_agrees_with_a_float_grid(data):
    A, B, C, D = data
    model = em(A, B, C, D)
    verdict, reason, cert, witness = decide_positive_real(model)
    recheck(model, verdict, cert, witness)
    Af, Bf, Cf, Df = (np.array(x, dtype=float) for x in (A, B, C, D))
    grid = np.concatenate([[0.0], np.logspace(-3, 3, 2000)])
    with np.errstate(all="ignore"):
        values = nu(Af, Bf, Cf, Df, grid)
    values = values[np.isfinite(values)]
    if values.size and values.min() < -1e-6:
        assert verdict == NOT_PASSIVE, reason
    if verdict == PASSIVE:
        assert not values.size or values.min() > -1e-9
        # no pole of H in the open right half-plane (transfer matrix, float roots)
        an = analyse(model, certify=False)
        roots = np.roots([float(c) for c in reversed(an.tm.d.coeffs())]) \
            if an.tm.d.degree() > 0 else np.array([])
        assert np.all(roots.real < 1e-6)


# hostile inputs ------------------------------------------------------------------------

@pytest.mark.parametrize("model, expected", [
    (em([[-1, 0], [0, 2]], [[1], [1]], [[0, 0]], [[0]]), PASSIVE),  # H = 0
    (em([], [], [], [[0, 0], [0, 0]]), PASSIVE),  # static zero
    (em([[-(2**200)]], [[2**200]], [[2**200]], [[0]]), PASSIVE),  # 2^400/(s + 2^200)
    (em([[-(2**200)]], [[2**200]], [[-(2**200)]], [[2**-1]]), NOT_PASSIVE),
    (em([[-1, 0], [0, 2]], [[1], [0]], [[1, 0]], [[0]]), PASSIVE),  # hidden unstable mode
    # unobservable imaginary-axis modes: jw = +-j is an eigenvalue of A but no pole of H
    (em([[0, 1, 0], [-1, 0, 0], [0, 0, -1]], [[1], [0], [1]], [[0, 0, -1]], [[0]]),
     NOT_PASSIVE),
    (em([[0, 1, 0], [-1, 0, 0], [0, 0, -1]], [[1], [0], [1]], [[0, 0, 1]], [[0]]), PASSIVE),
], ids=["H = 0", "static zero", "2^400/(s+2^200)", "1/2 - 2^400/(s+2^200)",
        "hidden unstable", "unobservable axis modes, -1/(s+1)",
        "unobservable axis modes, 1/(s+1)"])
def test_hostile_models(model, expected):
    verdict, reason, cert, witness = decide_positive_real(model)
    assert verdict == expected, reason
    recheck(model, verdict, cert, witness)


def test_hermitian_part_from_the_transfer_matrix_matches_the_state_space():
    from flint import fmpq

    from verify.passivity.check.fd_witness import hermitian_part_from

    model = em(*_random_ph(np.random.default_rng(7), 4, 2))
    tm = transfer_matrix(model)
    for w in (fmpq(0), fmpq(3, 2), fmpq(1000)):
        assert hermitian_part_from(tm, w) == hermitian_part_at(
            model, Fraction(int(w.p), int(w.q)))


@pytest.mark.parametrize("margin, expected", [(Fraction(1), PASSIVE),
                                              (Fraction(1) + Fraction(1, 2**50), NOT_PASSIVE)])
def test_margin_is_decided_exactly(margin, expected):
    """1 + s/(s^2+1): nu(w) = 1 exactly, with a lossless pole pair at +-j."""
    lti = _lti(em([[0, 1], [-1, 0]], [[0], [1]], [[0, 1]], [[1]]))
    d = decide(lti, margin)
    assert d.verdict == expected, d.reason


def test_a_sturm_count_certificate_round_trips_as_the_string_sturm(monkeypatch):
    """Above the SOS degree limit an odd factor is certified by a Sturm count: JSON
    "sturm", parsed back to a SturmCount that the checker re-decides."""
    from flint import fmpq_poly

    from verify.passivity.check import univariate_sos as us

    monkeypatch.setattr(us, "SOS_DEGREE_LIMIT", -1)
    f = fmpq_poly([1, 0, 1]) * fmpq_poly([2, 1]) ** 2  # (x^2 + 1)(x + 2)^2 >= 0
    cert = us.nonnegativity_certificate(f)
    assert any(isinstance(s, us.SturmCount) for _, _, s in cert.factors)
    data = cert.to_json()
    assert [item["sos"] for item in data["factors"] if item["exponent"] % 2] == ["sturm"]
    back = us.nonnegativity_from_json(data)
    assert back == cert and us.check_nonnegativity(f, back) is None
    bad = us.Nonnegativity(cert.content, [(fmpq_poly([-1, 0, 1]), 1, us.SturmCount()),
                                          *[x for x in cert.factors if x[1] % 2 == 0]])
    assert us.check_nonnegativity(fmpq_poly([-1, 0, 1]) * fmpq_poly([2, 1]) ** 2, bad)
