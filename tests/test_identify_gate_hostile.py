"""Hostile logs for `verify identify`'s identifiability gate (Section 4, "Human Modeling"):
data that do not identify an operator must give *cannot identify* (exit 1, the reason,
no model file, no certificate), never a model with a verdict.

Grouped by attack: data with no operator in them, wiring mistakes, a loop that is not in
the steady operation the paper models, and estimates the search cannot trust.
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from identify_loop import THETA, diverging, loop_log, pure_noise, swapped

from verify.cli import main
from verify.identify.command import REFUSAL_FILE
from verify.identify.estimate.pem import denominator_bounds
from verify.identify.estimate.result import Estimate
from verify.identify.estimate.structure import Structure
from verify.identify.quality import identifiability as gate
from verify.inputs.experiment import Trial
from verify.inputs.experiment_log import read_logs, write_log


def _refused(log: Path, tmp_path: Path, capsys) -> tuple[dict, str]:
    out = tmp_path / "out"
    code = main(["identify", str(log), "--split", "6:2", "--out", str(out), "--json",
                 str(tmp_path / "s.json"), "--junit", str(tmp_path / "j.xml")])
    printed = capsys.readouterr().out
    assert code == 1
    assert sorted(p.name for p in out.iterdir()) == [REFUSAL_FILE]  # no model, no certificate
    summary = json.loads((tmp_path / "s.json").read_text())
    assert summary["verdict"] == "cannot identify" and summary["passed"] is False
    assert summary["model"] is None
    assert summary["identifiability"]["identifiable"] is False
    case = ET.parse(tmp_path / "j.xml").getroot().find(".//testcase")
    assert case.find("failure") is not None
    assert printed.startswith("cannot identify ")
    return summary, " ".join(summary["identifiability"]["reasons"])


# --- no operator in the data ------------------------------------------------------------

def test_pure_noise_cannot_be_identified(tmp_path, capsys):
    log = write_log(pure_noise(), tmp_path / "noise.npz")
    _, reasons = _refused(log, tmp_path, capsys)
    assert "no better than predicting" in reasons


@pytest.mark.parametrize("column", ["e", "u"])
def test_a_constant_signal_cannot_be_identified(tmp_path, capsys, column):
    """A log whose input or output never moves is valid but carries no information: the
    answer is "cannot identify" with that reason, not an error about the fit ratio."""
    noise = pure_noise()
    trials = tuple(Trial(tr.trial, tr.t, *(
        (np.zeros_like(tr.e), tr.u) if column == "e" else (tr.e, np.full_like(tr.u, 0.25))),
        start=tr.start) for tr in noise.trials)
    log = write_log(type(noise)(trials, noise.rate, "constant"), tmp_path / "constant.npz")
    _, reasons = _refused(log, tmp_path, capsys)
    assert f"{column}_1 is constant" in reasons


# --- wiring mistakes ---------------------------------------------------------------------

@pytest.fixture(scope="module")
def loop(tmp_path_factory) -> Path:
    return loop_log(tmp_path_factory.mktemp("loop") / "noisy.npz")


def test_swapped_e_and_u_cannot_be_identified(loop, tmp_path, capsys):
    log = write_log(swapped(read_logs([loop])), tmp_path / "swapped.npz")
    _, reasons = _refused(log, tmp_path, capsys)
    assert "rougher" in reasons and "swapped" in reasons


def test_the_loop_log_itself_passes_the_roughness_question(loop):
    trials = read_logs([loop]).trials
    assert np.all(gate.roughness(trials, "e") * 4 < gate.roughness(trials, "u"))


# --- a loop outside steady operation -----------------------------------------------------

def test_a_diverging_loop_cannot_be_identified(tmp_path, capsys):
    log = write_log(diverging(), tmp_path / "diverging.npz")
    with np.errstate(over="ignore", invalid="ignore"):
        _, reasons = _refused(log, tmp_path, capsys)
    assert "diverged" in reasons


def test_growth_of_a_settling_trial_is_small_and_of_a_growing_one_large():
    t = np.arange(400) * 0.05
    settle = np.column_stack([np.exp(-t), np.exp(-t)])
    grow = np.column_stack([np.exp(0.3 * t), np.exp(0.3 * t)])
    assert gate.growth([Trial(0, t, settle, settle)]) < 1
    assert gate.growth([Trial(0, t, grow, settle)]) > gate.MAX_GROWTH
    bad = grow.copy()
    bad[5, 0] = np.inf
    assert gate.growth([Trial(0, t, settle, bad)]) == np.inf


# --- estimates the search cannot trust ----------------------------------------------------

def _estimate(theta, cov=None) -> Estimate:
    s = Structure.paper()
    cov = np.diag((0.01 * np.abs(np.asarray(theta)) + 1e-3) ** 2) if cov is None else cov
    return Estimate(s, np.asarray(theta, float), cov, s.names(), "test", np.ones(2), 1000)


def test_an_estimate_on_the_upper_search_bound_is_refused():
    h = 0.05
    upper = denominator_bounds(2, h)
    theta = THETA.copy()
    theta[2] = upper[0]  # a1_1 on its bound
    reasons = gate.interior(_estimate(theta), h)
    assert len(reasons) == 1 and "a1_1" in reasons[0] and "search bound" in reasons[0]
    assert gate.interior(_estimate(THETA), h) == []


def test_an_estimate_on_the_lower_bound_or_unstable_is_refused():
    theta = THETA.copy()
    theta[6] = 1e-40  # a1_2 = 0: no damping, on the box's lower edge
    assert any("a1_2" in r and "bound 0" in r for r in gate.interior(_estimate(theta), 0.05))
    theta = THETA.copy()
    theta[3] = -0.5  # a0_1 < 0: an unstable pole
    assert any("not stable" in r for r in gate.interior(_estimate(theta), 0.05))


def test_the_lower_edge_is_judged_on_the_model_own_scale_not_the_box():
    """A 3-pole model at 120 Hz: the box's bound on a0 is (pi/2h)^3 = 6.6e6, so a0 = 1.8
    is 3e-7 of it, yet it is an ordinary pole product; a0 = 1e-9 is a pole at zero."""
    s = Structure.poles_zeros(3, 2)
    theta = np.array([1.0, 2.0, 1.8, 1.9, 2.9, 1.8, 1.0, 2.3, 2.6, 2.3, 3.5, 2.6, 0.04, -0.05])
    est = Estimate(s, theta, np.eye(14) * 1e-4, s.names(), "test", np.ones(2), 1000)
    assert gate.interior(est, 1 / 120) == []
    theta[5] = 1e-9
    est = Estimate(s, theta, np.eye(14) * 1e-4, s.names(), "test", np.ones(2), 1000)
    reasons = gate.interior(est, 1 / 120)
    assert len(reasons) == 1 and "a0_1" in reasons[0] and "bound 0" in reasons[0]


def test_an_ill_conditioned_information_matrix_is_refused():
    rng = np.random.default_rng(1)
    v = rng.standard_normal((10, 9))
    singular = v @ v.T * 1e-4  # rank 9
    assert gate.condition_number(singular) > gate.MAX_CONDITION
    result = gate.check(_estimate(THETA, singular), [50.0, 50.0], [], 0.05)
    assert not result.identifiable and "ill-conditioned" in result.reasons[0]
    assert gate.condition_number(np.full((2, 2), np.nan)) == np.inf
    assert gate.condition_number(np.diag([1.0, 0.0])) == np.inf


def test_the_estimator_giving_up_on_the_bound_is_cannot_identify(loop, tmp_path, capsys,
                                                                  monkeypatch):
    """When every refinement ends on the search bound the estimator raises
    CannotIdentifyError; the command turns it into *cannot identify*, exit 1."""
    import verify.identify.estimate.estimation as estimation
    from verify.identify.estimate.result import CannotIdentifyError

    def on_bound(*args, **kwargs):
        raise CannotIdentifyError("output 1: every refinement ran to the bound")

    monkeypatch.setattr(estimation, "estimate_model", on_bound)
    _, reasons = _refused(loop, tmp_path, capsys)
    assert "bound" in reasons


def test_a_refusal_replaces_a_previous_output_and_can_be_replaced(loop, tmp_path, capsys):
    """No stale model file or certificate of an earlier run survives a refusal, and the
    refusal's folder counts as ours for the next run."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "model.toml").write_text("stale")
    code = main(["identify", str(write_log(pure_noise(), tmp_path / "n.npz")), "--split",
                 "6:2", "--out", str(out)])
    # a foreign (unreadable) model.toml: refused before any work, nothing replaced
    assert code == 2 and (out / "model.toml").read_text() == "stale"
    (out / "model.toml").unlink()
    assert main(["identify", str(tmp_path / "n.npz"), "--split", "6:2", "--out",
                 str(out)]) == 1
    assert [p.name for p in out.iterdir()] == [REFUSAL_FILE]
    assert main(["identify", str(tmp_path / "n.npz"), "--split", "6:2", "--out",
                 str(out)]) == 1
    capsys.readouterr()


def test_a_validation_fit_below_the_minimum_cannot_identify(loop):
    """The gate's first question with the threshold: a 2.8 % fit (what a short noisy
    session gave, with b1 = -410) is refused with the minimum named; a fit at the
    minimum passes that question."""
    trials = read_logs([loop]).trials
    est = _estimate(THETA)
    low = gate.check(est, [2.8, 55.0], trials, 1 / 120)
    assert not low.identifiable
    assert any("output 1" in r and "2.80 %" in r and f"{gate.MIN_FIT:g} %" in r
               for r in low.reasons)
    assert not any("output 2" in r for r in low.reasons)
    ok = gate.check(est, [gate.MIN_FIT, 55.0], trials, 1 / 120)
    assert not any("validation input fits" in r for r in ok.reasons)
    negative = gate.check(est, [-3.0, 55.0], trials, 1 / 120)
    assert any("no better than predicting" in r for r in negative.reasons)
    labelled = gate.check(est, [2.8, 55.0], trials, 1 / 120, basis="the estimator's")
    assert any("validation input (the estimator's) fits 2.80 %" in r
               for r in labelled.reasons)
