"""`verify identify` on closed-loop logs of a known operator (Section 4, "Human Modeling"):
honest fits, exact data, per-trial clocks, the decimation rate.

The logs are the paper's loop (2 bodies, 8 trials of 15 s at 120 Hz, split 6:2) simulated
with the known operator :data:`identify_loop.THETA`; the reported fit is checked against
an independent simulation (scipy's ``lsim``) of the model file as written.
"""

from __future__ import annotations

import json
import tomllib
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from identify_loop import THETA, loop_log, per_trial_clocks
from scipy import linalg, signal

from verify.cli import main
from verify.identify.command import REFUSAL_FILE
from verify.identify.data.protocol import chosen_rate, prepare
from verify.identify.estimate.structure import Structure
from verify.identify.model.model_writer import read_identified
from verify.identify.quality.fits import assess
from verify.inputs.experiment import Trial
from verify.inputs.experiment_log import read_logs, write_log


@pytest.fixture(scope="module")
def logs(tmp_path_factory) -> dict[str, Path]:
    d = tmp_path_factory.mktemp("loop")
    exact = loop_log(d / "exact.npz", exact=True)
    return {"noisy": loop_log(d / "noisy.npz"), "exact": exact,
            "clocks": write_log(per_trial_clocks(read_logs([exact])), d / "clocks.npz")}


def _identify(log: Path, out: Path, *extra: str) -> tuple[int, dict]:
    code = main(["identify", str(log), "--split", "6:2", "--band", "0:2", "--out", str(out),
                 "--json", str(out.parent / f"{out.name}.json"), *extra])
    return code, json.loads((out.parent / f"{out.name}.json").read_text())


@pytest.fixture(scope="module")
def noisy_run(logs, tmp_path_factory):
    out = tmp_path_factory.mktemp("noisy") / "out"
    code, summary = _identify(logs["noisy"], out)
    return code, summary, out


@pytest.fixture(scope="module")
def exact_run(logs, tmp_path_factory):
    out = tmp_path_factory.mktemp("exact") / "out"
    code, summary = _identify(logs["exact"], out)
    return code, summary, out


def _written_fits(model: Path, trials: list[Trial], split: int) -> tuple[list, list]:
    """Section 4's fit of the written model, simulated by scipy's lsim: each data set's
    first trial from rest, each later one from the state the previous one ended in,
    coasted with zero input over the time between them (the clock must move forward),
    no offset."""
    tf = tomllib.loads(model.read_text())["transfer_function"]
    fits: tuple[list, list] = ([], [])
    for i in (0, 1):
        j = 1 - i
        A, B, C, D = signal.tf2ss(tf["num"][i][i], tf["den"][i][i])
        c = tf["num"][i][j][0]
        x_end, prev = None, None
        yhat = []
        for tr in trials:
            x0 = np.zeros(A.shape[0])
            if len(yhat) == split:  # the validation data: from rest again
                prev = None
            if prev is not None and tr.trial != prev.trial and tr.t[0] > prev.t[-1]:
                x0 = linalg.expm(A * (tr.t[0] - prev.t[-1])) @ x_end
            _, y, xs = signal.lsim((A, B, C, D), tr.e[:, i], tr.t - tr.t[0], X0=x0)
            x_end, prev = xs[-1], tr
            yhat.append(y + c * tr.e[:, j])
        for part, (lo, hi) in enumerate(((0, split), (split, len(trials)))):
            u = np.concatenate([tr.u[:, i] for tr in trials[lo:hi]])
            y = np.concatenate(yhat[lo:hi])
            fits[part].append(100 * (1 - np.linalg.norm(u - y) / np.linalg.norm(u - u.mean())))
    return fits


# --- honest fits -------------------------------------------------------------------------

def test_reported_fit_is_the_written_model_simulated_on_the_logged_input(logs, noisy_run):
    code, summary, out = noisy_run
    assert code == 0
    prepared = prepare(read_logs([logs["noisy"]]), rate=summary["rate"], split=(6, 2))
    trials = [*prepared.identification, *prepared.validation]
    ident, val = _written_fits(out / "model.toml", trials, len(prepared.identification))
    assert np.allclose(summary["fit"]["identification"], ident, atol=1.0), (summary["fit"], ident)
    assert np.allclose(summary["fit"]["validation"], val, atol=1.0), (summary["fit"], val)
    table = read_identified(out / "model.toml").identification
    assert [float(x) for x in table["fit_validation"]] == pytest.approx(
        summary["fit"]["validation"], abs=0.01)
    assert "paper's" in table["fit_basis"] and "no offset" in table["fit_basis"]
    assert summary["fit"]["basis"] == table["fit_basis"]
    # the default estimates offsets: the estimator's fit is a second, labelled figure
    second = summary["fit"]["second"]
    assert "offsets added" in second["basis"]
    assert second["basis"] == table["fit_second_basis"]
    assert [float(x) for x in table["fit_second_validation"]] == second["validation"]
    assert summary["identifiability"]["identifiable"] is True


def test_truth_inside_the_region_of_the_noisy_default_run(noisy_run):
    """One seeded experiment: at the default (auto: the logged 120 Hz) the true operator
    is inside the 95 % region (coverage over seeds is the benchmark's)."""
    _, summary, out = noisy_run
    assert summary["rate"] == 120.0
    assert _inside(out)


def _inside(out: Path) -> bool:
    """The true parameters inside the written 95 % region (exact quadratic form)."""
    from verify.passivity.check import robust_band as rb

    region = read_identified(out / "model.toml").region()
    truth = [Fraction(str(x)) for x in THETA]
    return rb.quadratic_form(rb.inverse(region.covariance), region.center, truth) <= region.chi2


@pytest.mark.parametrize("rate", ["60", "40", "20"])
def test_forced_rates_estimate_the_truth_inside_the_region(logs, rate):
    """Estimate level (no verdict, seconds): at --rate 20, 40 and 60 the estimator's 95 %
    region holds the true operator, and the gate passes."""
    from scipy.stats import chi2

    from verify.identify.estimate.estimation import estimate_model
    from verify.identify.quality.fits import honest_fits
    from verify.identify.quality.identifiability import check

    prepared = prepare(read_logs([logs["noisy"]]), rate=float(rate), split=(6, 2))
    est = estimate_model(prepared.identification, Structure.paper())
    d = est.theta - THETA
    assert d @ np.linalg.solve(est.covariance, d) <= chi2.ppf(0.95, 10)
    _, y_val = honest_fits(est, prepared.identification, prepared.validation)
    fit = assess(est, prepared.validation, yhat=y_val).fit
    gate = check(est, fit, [*prepared.identification, *prepared.validation],
                 1.0 / prepared.rate)
    assert gate.identifiable, gate.reasons


@pytest.mark.slow
@pytest.mark.parametrize("rate", ["60", "40"])
def test_higher_rates_never_give_a_confident_wrong_model(logs, tmp_path, rate):
    """--rate 40, 60 on a passive operator's log: the truth is inside the 95 % region, or
    the outcome is *cannot identify* (exit 1, nothing certified)."""
    out = tmp_path / "out"
    code, summary = _identify(logs["noisy"], out, "--rate", rate)
    if summary.get("verdict") == "cannot identify":
        assert code == 1 and (out / REFUSAL_FILE).exists()
        assert not (out / "model.toml").exists()
    else:
        assert summary["rate"] == float(rate)
        assert _inside(out)
        assert summary["robust"]["verdict"] != "not passive"


# --- exact data ----------------------------------------------------------------------------

def test_exact_closed_loop_data_recover_the_operator_to_1e_4(exact_run):
    """Noise-free closed-loop logs: kept at the logged 120 Hz (auto rate), parameters
    within 1e-4 relative, and the residual tests are reported, never a reason to stop."""
    code, summary, out = exact_run
    assert code == 0
    assert summary["rate"] == 120.0
    written = np.array([float(x) for x in read_identified(out / "model.toml").center])
    assert np.max(np.abs(written - THETA) / np.abs(THETA)) < 1e-4, written - THETA
    assert "residual_tests_passed" in summary["residual_tests"]


def test_the_class_test_on_in_class_logs(noisy_run, exact_run):
    """The operator is in the paper's class: noisy logs do not reject the class; the
    noise-free log may (the sampled loop is not exactly the class) but its answers are
    confirmed by the larger model, so none is withdrawn."""
    noisy = noisy_run[1]["model_class"]
    assert noisy["rejected"] is False and max(noisy["likelihood_ratio"]) < 15.2
    assert noisy["answers"] == ""
    exact = exact_run[1]
    assert exact["robust"]["withdrawn"] is False and exact["passed"] is True
    if exact["model_class"]["rejected"]:
        assert "agrees" in exact["model_class"]["answers"]


def test_residual_tests_that_cannot_be_computed_are_listed_not_raised():
    """A constant second input: the cross-correlation test with it is undefined."""
    from verify.identify.estimate.result import Estimate

    structure = Structure.paper()
    rng = np.random.default_rng(0)
    N = 200
    t = np.arange(N) * 0.05
    e = np.column_stack([np.sin(t), np.zeros(N)])
    u = np.column_stack([0.1 * rng.standard_normal(N), 0.1 * rng.standard_normal(N)])
    est = Estimate(structure, THETA.copy(), np.eye(10) * 1e-4, structure.names(), "test",
                   np.ones(2), N)
    q = assess(est, [Trial(0, t, e, u)])
    assert q.not_computed and any("input 2" in s for s in q.not_computed)
    assert not q.residuals_pass
    assert len(q.whiteness) == 2


# --- per-trial clocks ---------------------------------------------------------------------

def test_per_trial_clocks_are_joined_back_to_back_and_said(logs, exact_run, tmp_path):
    """The same log with each trial's time restarting at 0: detected, said in the output
    and the JSON, and the trials joined as in the protocol, so the estimate is the one
    of the log on one clock."""
    out = tmp_path / "out"
    code, summary = _identify(logs["clocks"], out)
    assert code == 0
    assert any("clock restarts in 7 trial(s)" in n for n in summary["protocol"])
    assert any("continue from the state" in j for j in summary["trial_joins"])
    one_clock = np.array(exact_run[1]["estimate"]["theta"])
    assert np.allclose(summary["estimate"]["theta"], one_clock, rtol=1e-6)


# --- the decimation rate ------------------------------------------------------------------

def test_auto_rate_keeps_the_logged_rate_and_bounds_fast_logs(logs):
    """Auto keeps a 120 Hz log, noisy or exact (decimation costs accuracy: the methods
    benchmark), and decimates a faster log only down to the bound."""
    from dataclasses import replace

    from verify.identify.data.protocol import AUTO_MAX_RATE

    noisy, why_noisy = chosen_rate(read_logs([logs["noisy"]]))
    exact, _ = chosen_rate(read_logs([logs["exact"]]))
    assert noisy == exact == 120.0 and "kept at the logged 120 Hz" in why_noisy
    fast = replace(read_logs([logs["noisy"]]), rate=1000.0)
    rate, why = chosen_rate(fast)
    assert rate == 250.0 <= AUTO_MAX_RATE and "decimated to 250 Hz" in why


def test_rate_off_decimates_nothing(logs):
    prepared = prepare(read_logs([logs["exact"]]), rate="off", split=(6, 2))
    assert prepared.rate == 120.0 and prepared.decimation == 1
    assert any("--rate off" in n for n in prepared.notes)


def test_rate_help_states_the_auto_rule_the_protocol_uses(capsys):
    """`verify identify --help` names the protocol's own ceiling of the automatic rate."""
    from verify.identify.data.protocol import AUTO_MAX_RATE

    with pytest.raises(SystemExit):
        main(["identify", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert f"up to {AUTO_MAX_RATE:g} Hz" in text and "20 Hz for noisy" not in text
