"""Data built to fool the passivity test: each must get the answer its truth supports.

Classes: passive operators the test must not reject (noise, a constraint active at the
truth, coloured residuals), non-passive operators it must reject (through the coupling
alone, through one diagonal element), data with no information (pure noise).
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from identify_models import open_loop_log

from verify.identify.data.protocol import prepare
from verify.identify.estimate.estimation import estimate_model
from verify.identify.estimate.structure import Structure
from verify.identify.robust.passive_fit import passive_constraints, passivity_test
from verify.inputs.experiment import ExperimentLog, Trial
from verify.passivity.model import from_transfer_function


def _model(theta):
    num, den = Structure.paper().transfer_matrix([Fraction(str(x)) for x in theta])
    return from_transfer_function(num, den)


def _test(theta, *, seed: int, noise: float = 0.01, trials: int = 4):
    log = open_loop_log(_model(theta), trials=trials, noise=noise, seed=seed)
    prepared = prepare(log, rate=None, split=(trials - 1, 1))
    est = estimate_model(prepared.identification, Structure.paper())
    return passivity_test(prepared.identification, est.theta)


# ------------------------------------------------------------------ passive truths


@pytest.mark.parametrize("seed", [3, 4])
def test_a_passive_operator_is_not_rejected_over_seeds(seed):
    theta = [1.2, 0.8, 2.0, 1.5, 1.2, 0.8, 2.0, 1.5, 0.05, -0.05]
    assert passive_constraints([Fraction(str(x)) for x in theta]) == []
    test = _test(theta, seed=seed)
    assert not test.rejected, test.sentence()


def test_a_passive_operator_on_the_constraint_boundary_is_not_rejected():
    """a1 b1 = b0 exactly (Re h_i(jw) constant at high frequency): the constraint is
    active at the truth, where the chi-square approximation is weakest."""
    theta = [0.4, 0.8, 2.0, 1.5, 0.5, 1.0, 2.0, 2.0, 0.1, -0.1]
    assert passive_constraints([Fraction(str(x)) for x in theta]) == []
    test = _test(theta, seed=5)
    assert not test.rejected, test.sentence()


# ------------------------------------------------------------------ non-passive truths


def test_skew_violated_only_through_the_coupling_is_rejected():
    """Passive diagonal, c12 + c21 = 0.4: only c12 = -c21 fails."""
    theta = [1.2, 0.8, 2.0, 1.5, 1.2, 0.8, 2.0, 1.5, 0.3, 0.1]
    assert passive_constraints([Fraction(str(x)) for x in theta]) == ["c12 = -c21"]
    test = _test(theta, seed=6)
    assert test.rejected, test.sentence()


def test_one_lossy_diagonal_element_is_rejected():
    """Element 2 has a1 b1 = 0.5 < b0 = 1 (Re h_2 < 0 above 2 rad/s, inside the band the
    inputs excite); element 1 and the coupling are passive."""
    theta = [1.2, 0.8, 2.0, 1.5, 0.5, 1.0, 1.0, 2.0, 0.05, -0.05]
    assert passive_constraints([Fraction(str(x)) for x in theta]) == ["a1_2 b1_2 >= b0_2"]
    test = _test(theta, seed=7)
    assert test.rejected, test.sentence()


# ------------------------------------------------------------------ no information


def test_pure_noise_outputs_never_reject_passivity():
    """u independent of e: nothing to reject with (the free fit explains nothing, so the
    passive one is as good); the test must not invent evidence."""
    rng = np.random.default_rng(8)
    log = open_loop_log(_model([1.2, 0.8, 2.0, 1.5, 1.2, 0.8, 2.0, 1.5, 0.05, -0.05]),
                        trials=4, seed=8)
    trials = tuple(Trial(tr.trial, tr.t, tr.e, 0.05 * rng.standard_normal(tr.u.shape),
                         start=tr.start) for tr in log.trials)
    prepared = prepare(ExperimentLog(trials, log.rate, "noise"), rate=None, split=(3, 1))
    est = estimate_model(prepared.identification, Structure.paper())
    test = passivity_test(prepared.identification, est.theta)
    assert not test.rejected and not test.informative, test.sentence()
    assert "cannot test passivity" in test.sentence()
    assert max(test.fit_free) < 20  # and the fit says there is nothing to explain
