"""A constant offset on the logged u (an uncalibrated stick): estimated with the model as a
nuisance parameter, in the fits, the class test, the model file and the command line.

Data: the paper's closed loop (n = 2, 6 trials of 15 s at 120 Hz) with the known operator
THETA, the logged u shifted by a constant afterwards
(:func:`verify.identify.data.simulated_experiment.with_output_offset`).
"""

from __future__ import annotations

import numpy as np
import pytest
from identify_loop import THETA

from verify.identify.data.protocol import prepare
from verify.identify.data.simulated_experiment import simulate_experiment, with_output_offset
from verify.identify.estimate.estimation import OFFSET, estimate_model
from verify.identify.estimate.prediction import predict
from verify.identify.estimate.structure import Structure
from verify.identify.quality.coverage import true_model
from verify.identify.quality.fits import honest_fits

STICK = (0.1, -0.05)


@pytest.fixture(scope="module", params=[5, 6])
def loop(request):
    """(as logged, with the stick's offset) identification trials of one seeded loop."""
    log = simulate_experiment(true_model(THETA), trials=6, n=2, seed=request.param)
    return tuple(prepare(lg, rate="auto", split=(6, 0)).identification
                 for lg in (log, with_output_offset(log, STICK)))


def _z(est) -> np.ndarray:
    return np.abs(est.theta - THETA) / est.standard_errors()


def test_an_offset_on_u_is_estimated_and_leaves_the_parameters_in_place(loop):
    _, shifted = loop
    est = estimate_model(shifted, Structure.paper(), offset=True)
    assert np.all(np.abs(np.array(est.offsets) - STICK) <= 3 * np.array(est.offset_errors))
    assert np.max(_z(est)) < 4
    ignored = estimate_model(shifted, Structure.paper(), offset=False)
    assert ignored.offsets == () and np.max(_z(ignored)) > 10  # the stick pulls H(s)


def test_without_an_offset_in_the_data_the_term_costs_little(loop):
    plain, _ = loop
    on = estimate_model(plain, Structure.paper(), offset=True)
    off = estimate_model(plain, Structure.paper(), offset=False)
    assert np.all(np.abs(on.offsets) <= 3 * np.array(on.offset_errors))
    assert np.max(np.abs(on.theta - off.theta) / off.standard_errors()) < 0.5
    assert np.all(on.standard_errors() <= 1.2 * off.standard_errors())


def test_the_fits_add_the_offset_and_the_class_test_reports_it(loop):
    from verify.identify.quality.model_class import model_class_test

    _, shifted = loop
    est = estimate_model(shifted, Structure.paper(), offset=True)
    with_offset, _ = honest_fits(est, shifted)
    alone = predict(Structure.paper(), est.theta, shifted, initial="carry")
    for y, x in zip(with_offset, alone, strict=True):
        assert np.allclose(y - x, est.offsets, atol=1e-12)
    test = model_class_test(est, shifted)
    assert test.offsets == est.offsets and test.offsets_significant == (True, True)
    assert "u1 +0.1" in test.sentence() and "significant" in test.sentence()
    summary = test.to_json()
    assert summary["offsets_significant"] == [True, True]
    assert len(summary["offset_standard_errors"]) == 2
    assert not test.rejected


def test_the_command_line_turns_the_offset_off(tmp_path):
    from verify.cli import _build_parser
    from verify.identify.command import IdentifySettings, validate

    log = tmp_path / "log.csv"
    log.write_text("time,trial,e1,e2,u1,u2\n")
    parser = _build_parser()
    assert parser.parse_args(["identify", str(log)]).offset is None
    assert parser.parse_args(["identify", str(log), "--no-offset"]).offset is False
    out = tmp_path / "out"
    assert validate(IdentifySettings((log,), out=out)).offset is OFFSET
    assert validate(IdentifySettings((log,), out=out, offset=False)).offset is False
