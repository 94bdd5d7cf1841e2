"""Can the data reject passivity: the passive class, the constrained fit and the test."""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from verify.identify.estimate.structure import Structure
from verify.identify.robust.passive_fit import (
    passive_constraints,
    passive_literals,
    passive_model_text,
    passivity_test,
)
from verify.passivity.decision import decide
from verify.passivity.model import from_transfer_function

LOGS = Path(__file__).resolve().parents[1] / "verify" / "data" / "logs"


def _gate(theta) -> str:
    num, den = Structure.paper().transfer_matrix([Fraction(x) for x in theta])
    return str(decide(from_transfer_function(num, den)).verdict)


def _passive_instance(rng) -> list[Fraction]:
    """A random model meeting every constraint (some exactly on a boundary)."""
    out = []
    for _ in range(2):
        a1, a0 = (Fraction(int(rng.integers(1, 40)), 10) for _ in range(2))
        b0 = Fraction(int(rng.integers(0, 30)), 10)
        slack = Fraction(int(rng.integers(0, 3)) * int(rng.integers(0, 20)), 10)
        out += [(b0 + slack) / a1, b0, a1, a0]
    c = Fraction(int(rng.integers(-20, 21)), 100)
    return [*out, c, -c]


VIOLATIONS = {
    "c12 = -c21": lambda t: [*t[:9], -t[8] + Fraction(1, 50)],
    "a1_1 > 0": lambda t: [t[0], t[1], -t[2], *t[3:]],
    "a0_2 > 0": lambda t: [*t[:7], -t[7] - 1, *t[8:]],
    "b0_1 >= 0": lambda t: [t[0], -t[1] - Fraction(1, 10), *t[2:]],
    "a1_2 b1_2 >= b0_2": lambda t: [*t[:4], (t[5] + 1) / t[6] / 2, t[5] + 1, *t[6:]],
}


def test_the_passive_class_agrees_with_the_exact_gate_on_random_instances():
    """Constraints met: the gate certifies passivity; one violated (with margin): the gate
    finds an exact witness. 24 instances on each side."""
    rng = np.random.default_rng(11)
    for _ in range(24):
        theta = _passive_instance(rng)
        assert passive_constraints(theta) == []
        assert _gate(theta) == "passive", theta
    for k in range(24):
        name = list(VIOLATIONS)[k % len(VIOLATIONS)]
        theta = VIOLATIONS[name](_passive_instance(rng))
        assert name in passive_constraints(theta), (name, theta)
        assert _gate(theta) == "not passive", (name, theta)


def test_written_literals_meet_the_constraints_exactly_on_the_boundary():
    """a1 b1 = b0 in floats (rounded down by one ulp): the decimals are raised until the
    constraint holds exactly; c21 is written as -c12."""
    a1, b0 = 3.0, 1.0
    b1 = np.nextafter(b0 / a1, 0)
    theta = [b1, b0, a1, 2.0, b1, b0, a1, 2.0, 0.1 + 1e-17, -0.1]
    lits = passive_literals(theta)
    assert passive_constraints(lits) == []
    assert lits[9] == -lits[8] and lits[2] * lits[0] >= lits[1]
    assert abs(float(lits[0]) - b1) < 1e-8


@pytest.fixture(scope="module")
def shipped():
    """The passivity test on the shipped closed-loop logs (the paper's protocol, known
    operators: verify.identify.data.example_logs)."""
    from verify.identify.data.protocol import prepare
    from verify.identify.estimate.estimation import estimate_model
    from verify.inputs.experiment_log import read_logs

    out = {}
    for name in ("passive_human", "nonpassive_human"):
        prepared = prepare(read_logs([LOGS / f"{name}.npz"]), rate=None, split=(6, 6))
        est = estimate_model(prepared.identification, Structure.paper())
        out[name] = (est, passivity_test(prepared.identification, est.theta,
                                         offset=bool(est.offsets)))
    return out


def test_a_passive_operator_is_not_rejected_and_its_passive_fit_is_certified(shipped,
                                                                             tmp_path):
    from verify.passivity.io.model_file import load_model

    est, test = shipped["passive_human"]
    assert test.informative and not test.rejected and test.p_value > 0.05
    assert "a passive model explains the data as well (p = " in test.sentence()
    theta = test.theta_passive
    assert passive_constraints([*theta[:9], -theta[8]]) == []
    # nested fits: the free one is at least as good on every output
    assert all(f <= p * (1 + 1e-9) for f, p in zip(test.cost_free, test.cost_passive,
                                                   strict=True))
    # the free fit is the estimator's (the same criterion, recomputed)
    assert np.allclose(test.theta_free, est.theta, rtol=1e-3, atol=1e-4)
    path = tmp_path / "passive.toml"
    path.write_text(passive_model_text("passive fit", test))
    model = load_model(path)
    assert str(decide(model).verdict) == "passive"


def test_a_non_passive_operator_inside_the_excited_band_is_rejected(shipped, tmp_path):
    """Truth: Re h(jw) < 0 above 2 rad/s, inside the band the reference excites."""
    from verify.passivity.io.model_file import load_model

    _, test = shipped["nonpassive_human"]
    assert test.rejected and test.p_value < 1e-6
    assert "the data reject passivity (p = " in test.sentence()
    path = tmp_path / "passive.toml"
    path.write_text(passive_model_text("passive fit", test))
    assert str(decide(load_model(path)).verdict) == "passive"  # still written
    assert json.dumps(test.to_json())


def test_correlated_residuals_lower_the_effective_sample_size(shipped):
    """The protocol's filtering colours the residuals: fewer effective samples than
    samples, which makes the test more conservative, never less."""
    _, test = shipped["passive_human"]
    assert all(1 <= e <= n for e, n in zip(test.effective_samples, test.samples,
                                           strict=True))
    assert min(e / n for e, n in zip(test.effective_samples, test.samples,
                                     strict=True)) < 0.95


def test_other_structures_are_refused_with_one_line():
    from verify.errors import VerifyInputError

    with pytest.raises(VerifyInputError, match="paper's structure"):
        passivity_test([], [0.0] * 8, structure=Structure.poles_zeros(1, 1))


def test_the_effective_sample_size_counts_one_second_at_any_rate():
    """The test's effective samples use the covariance's noise window in seconds (1 s),
    not a fixed number of samples: at 250 Hz, 20 samples would be 0.08 s, and a residual
    correlated over 0.3 s would count several times as many independent samples."""
    from types import SimpleNamespace

    from verify.identify.estimate.pem import covariance_lags
    from verify.identify.estimate.residual_tests import effective_samples
    from verify.identify.robust.passive_fit import _effective

    h, n = 1 / 250, 5000
    rng = np.random.default_rng(3)
    phi = np.exp(-h / 0.3)  # AR(1) with a 0.3 s correlation time
    e = rng.standard_normal(n)
    r = np.empty(n)
    r[0] = e[0]
    for k in range(1, n):
        r[k] = phi * r[k - 1] + e[k]
    data = SimpleNamespace(h=h, skip=0, own=[np.zeros(n)])
    got = _effective(r, data)
    assert covariance_lags(h, [n]) == 250
    assert got == pytest.approx(effective_samples(r, [n], lags=250))
    assert got < 0.5 * effective_samples(r, [n], lags=20)
