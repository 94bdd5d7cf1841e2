"""Estimation of H(s) from trials (Section 4, "Human Modeling"): recovery, consistency in
closed loop, covariance, fit ratio, residual tests, hostile inputs.

The data here are small scipy simulations, independent of the estimator's own filters:
open loop with piecewise-linear inputs (exact under first-order hold, simulated by
``scipy.signal.lsim``), and a linear closed loop theta' = u_h, e = r - theta,
u_h = H e + v (the leader's small-angle kinematics: the loop from u_h to e is strictly
proper and the operator noise v, held per sample, acts inside it).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from scipy import signal

from verify.errors import VerifyInputError
from verify.identify.estimate.bootstrap import bootstrap, bootstrap_draws
from verify.identify.estimate.ct_filters import filtered, free_responses
from verify.identify.estimate.estimation import estimate_model
from verify.identify.estimate.prediction import predict
from verify.identify.estimate.residual_tests import cross_correlation, whiteness
from verify.identify.estimate.structure import Structure
from verify.identify.quality.fits import assess, fit_ratio
from verify.inputs.experiment import Trial

#: A known operator in the paper's class: (b1, b0, a1, a0) per diagonal element, c12, c21.
THETA = np.array([1.2, 0.8, 2.0, 1.5, 0.9, 1.1, 1.6, 2.0, 0.05, -0.08])


def _human(theta: np.ndarray) -> tuple[np.ndarray, ...]:
    A = np.zeros((4, 4))
    B = np.zeros((4, 2))
    C = np.zeros((2, 4))
    for i in range(2):
        b1, b0, a1, a0 = theta[4 * i:4 * i + 4]
        s = slice(2 * i, 2 * i + 2)
        A[s, s] = [[0.0, 1.0], [-a0, -a1]]
        B[2 * i + 1, i] = 1.0
        C[i, s] = [b0, b1]
    D = np.array([[0.0, theta[8]], [theta[9], 0.0]])
    return A, B, C, D


def closed_loop(seed: int, *, trials: int = 6, seconds: float = 15.0, rate: float = 20.0,
                noise: float = 0.05, theta: np.ndarray = THETA, human_state: float = 0.0
                ) -> list[Trial]:
    """theta' = u, e = r - theta, u = H e + v; r constant per trial, random leader start;
    the operator starts each trial at rest (as after the protocol's reaction time) unless
    ``human_state`` gives the scale of a random initial state."""
    rng = np.random.default_rng(seed)
    A, B, C, D = _human(theta)
    Acl = np.zeros((6, 6))
    Bcl = np.zeros((6, 4))
    Acl[:4, :4], Acl[:4, 4:], Bcl[:4, :2] = A, -B, B
    Acl[4:, :4], Acl[4:, 4:], Bcl[4:, :2], Bcl[4:, 2:] = C, -D, D, np.eye(2)
    h = 1.0 / rate
    Ad, Bd, *_ = signal.cont2discrete((Acl, Bcl, np.eye(6), np.zeros((6, 4))), h,
                                      method="zoh")  # exact: r and v are held
    N = round(seconds * rate)
    out = []
    for k in range(trials):
        r = rng.uniform(-0.6, 0.6, 2)
        X = np.concatenate([human_state * rng.standard_normal(4), rng.uniform(-0.3, 0.3, 2)])
        v = noise * rng.standard_normal((N, 2))
        e = np.empty((N, 2))
        u = np.empty((N, 2))
        for n in range(N):
            e[n] = r - X[4:]
            u[n] = C @ X[:4] + D @ e[n] + v[n]
            X = Ad @ X + Bd @ np.concatenate([r, v[n]])
        out.append(Trial(k, np.arange(N) * h, e, u))
    return out


def open_loop(seed: int, structure: Structure, theta: np.ndarray, *, trials: int = 3,
              seconds: float = 10.0, rate: float = 20.0) -> list[Trial]:
    """Noise-free: e piecewise linear (exact under first-order hold), u = H e from a
    random initial state of each diagonal element, simulated by scipy's lsim."""
    rng = np.random.default_rng(seed)
    per = structure.zeros + 1 + structure.poles
    h = 1.0 / rate
    N = round(seconds * rate)
    t = np.arange(N) * h
    out = []
    for k in range(trials):
        e = 0.06 * np.cumsum(rng.standard_normal((N, 2)), axis=0)
        u = np.empty((N, 2))
        for i in range(2):
            block = theta[i * per:(i + 1) * per]
            num, den = block[: structure.zeros + 1], [1.0, *block[structure.zeros + 1:]]
            x0 = 0.3 * rng.standard_normal(structure.poles)
            _, y, _ = signal.lsim((num, den), e[:, i], t, X0=x0)
            u[:, i] = y + theta[-2 + i] * e[:, 1 - i]
        out.append(Trial(k, t, e, u))
    return out


# --- filters -------------------------------------------------------------------------

def test_state_variable_filters_match_scipy_lsim():
    rng = np.random.default_rng(3)
    h, N = 0.05, 300
    t = np.arange(N) * h
    x = rng.standard_normal(N)
    a = np.array([1.3, 2.0, 0.7])
    Z = filtered(a, x, h)
    for k in range(4):
        num = np.zeros(k + 1)
        num[0] = 1.0
        _, y, _ = signal.lsim((num, [1.0, *a]), x, t)
        assert np.max(np.abs(y - Z[:, k])) < 1e-10
    F = free_responses(a, h, N)
    sys = signal.StateSpace(*signal.tf2ss([1.0], [1.0, *a]))
    for j in range(3):  # w = first companion state from the unit initial state e_j
        w0 = np.zeros(3)
        w0[j] = 1.0
        Ac = np.array([[0, 1, 0], [0, 0, 1], [-0.7, -2.0, -1.3]])
        _, _, xs = signal.lsim((Ac, np.zeros((3, 1)), np.eye(3), np.zeros((3, 1))),
                               np.zeros(N), t, X0=w0)
        assert np.max(np.abs(xs[:, 0] - F[:, j])) < 1e-10
    del sys


# --- recovery and consistency ----------------------------------------------------------

def test_exact_recovery_from_noise_free_open_loop_data():
    structure = Structure.paper()
    trials = open_loop(0, structure, THETA)
    est = estimate_model(trials, structure, initial="estimate", burn_in=0.0)
    assert est.names == structure.names()
    assert np.max(np.abs(est.theta - THETA) / np.abs(THETA)) < 1e-6
    # open-loop trials from random states: the re-initialised figure (each trial's free
    # response fitted) is the one that can be 100 % here
    fits = assess(est, trials, initial="estimate").fit
    assert np.all(fits > 100 - 1e-4)


def test_exact_recovery_general_poles_zeros_structure():
    structure = Structure.poles_zeros(3, 2)
    theta = np.array([0.5, 1.0, 2.0, 3.0, 4.0, 2.0, 1.0, 0.2, 1.5, 2.5, 3.5, 1.5, 0.1, -0.3])
    est = estimate_model(open_loop(1, structure, theta), structure, initial="estimate",
                         burn_in=0.0)
    assert np.max(np.abs(est.theta - theta) / np.abs(theta)) < 1e-6


def test_closed_loop_noisy_estimate_within_a_few_standard_errors():
    trials = closed_loop(11)
    est = estimate_model(trials, Structure.paper())
    se = est.standard_errors()
    assert est.covariance_kind == "asymptotic"
    assert np.all(se > 0) and np.all(np.isfinite(se))
    assert np.all(np.abs(est.theta - THETA) <= 4 * se), (est.theta - THETA) / se
    # the covariance is symmetric positive semidefinite
    assert np.allclose(est.covariance, est.covariance.T)
    assert np.linalg.eigvalsh(est.covariance).min() > -1e-12
    # white operator noise at the sampling rate: the residual tests pass on this data
    quality = assess(est, trials)
    assert all(w.passed for w in quality.whiteness), [w.statistic for w in quality.whiteness]


def test_estimated_initial_states_handle_an_operator_not_at_rest_in_open_loop():
    """Zero initial states misfit trials that start away from rest; estimated ones fit."""
    structure = Structure.paper()
    trials = open_loop(4, structure, THETA)
    at_rest = estimate_model(trials, structure, initial="zero", burn_in=0.0)
    assert np.max(np.abs(at_rest.theta - THETA) / np.abs(THETA)) > 1e-3


def test_plain_arx_started_output_error_is_misled_by_the_loop():
    """The baseline lands near the leader's inverse (fast poles), the method does not."""
    trials = closed_loop(12)
    ours = estimate_model(trials, Structure.paper())
    base = estimate_model(trials, Structure.paper(), method="arx+oe")
    assert base.method == "arx+oe"
    assert np.max(np.abs(ours.theta - THETA)) < 1.0
    assert np.max(np.abs(base.theta - THETA)) > 10.0


def test_bootstrap_over_trials_is_seeded_and_has_the_parameter_shape():
    trials = closed_loop(13, trials=3, seconds=8.0, rate=10.0)
    result = bootstrap_draws(trials, Structure.paper(), 2, 7)
    assert result.thetas.shape == (2, 10) and result.used == 2
    assert np.allclose(result.covariance, bootstrap(trials, Structure.paper(), 2, 7))
    assert np.all(np.diag(result.covariance) >= 0)


# --- quality -------------------------------------------------------------------------

def test_fit_ratio_hand_example():
    y = np.array([1.0, 2.0, 3.0, 4.0])
    yhat = np.array([1.0, 2.0, 3.0, 3.0])
    # ||y - yhat|| = 1, ||y - mean y|| = sqrt(5)
    assert fit_ratio(y, yhat) == pytest.approx(100 * (1 - 1 / np.sqrt(5)), abs=1e-12)
    assert fit_ratio(y, y) == 100.0
    assert fit_ratio(y, np.full(4, 2.5)) == pytest.approx(0.0, abs=1e-12)
    with pytest.raises(VerifyInputError, match="constant output"):
        fit_ratio(np.ones(5), np.zeros(5))


def test_whiteness_accepts_white_and_rejects_coloured_residuals():
    rng = np.random.default_rng(5)
    # a 95 % test: white residuals are rejected in about 5 % of the data sets
    rejected = np.mean([not whiteness([rng.standard_normal(300) for _ in range(3)]).passed
                        for _ in range(300)])
    assert 0.02 <= rejected <= 0.09, rejected
    white = [rng.standard_normal(500) for _ in range(4)]
    test = whiteness(white)
    assert test.lags == 20
    # the statistic is the Ljung-Box formula over within-trial products
    N = 2000
    r0 = sum(float(r @ r) for r in white)
    rho = [sum(float(r[:-k] @ r[k:]) for r in white) / r0 for k in range(1, 21)]
    Q = N * (N + 2) * sum(rho[k - 1] ** 2 / (N - k) for k in range(1, 21))
    assert test.statistic == pytest.approx(Q, rel=1e-12)
    coloured = [signal.lfilter([1.0], [1.0, -0.5], r) for r in white]
    assert not whiteness(coloured).passed
    moving = [signal.lfilter([1.0, 0.3], [1.0], r) for r in white]
    assert not whiteness(moving).passed


def test_cross_correlation_detects_residual_driven_by_past_input():
    rng = np.random.default_rng(6)
    inputs = [signal.lfilter([1.0], [1.0, -0.8], rng.standard_normal(600)) for _ in range(3)]
    independent = [rng.standard_normal(600) for _ in range(3)]
    assert cross_correlation(independent, inputs).passed
    driven = [n + 0.2 * np.concatenate([[0, 0], x[:-2]])
              for n, x in zip(independent, inputs, strict=True)]
    assert not cross_correlation(driven, inputs).passed


def test_predict_with_zero_initial_state_misfits_the_start_of_trials():
    structure = Structure.paper()
    trials = open_loop(2, structure, THETA)
    estimated = np.concatenate(predict(structure, THETA, trials))
    zero = np.concatenate(predict(structure, THETA, trials, initial="zero"))
    u = np.concatenate([tr.u for tr in trials])
    assert np.max(np.abs(estimated - u)) < 1e-8
    assert np.max(np.abs(zero - u)) > 1e-3


# --- hostile inputs ------------------------------------------------------------------

def _one_line(excinfo) -> str:
    text = str(excinfo.value)
    assert "\n" not in text and text
    return text


def test_state_space_structure_is_refused_in_one_line():
    trials = closed_loop(1, trials=2, seconds=5.0)
    with pytest.raises(VerifyInputError) as err:
        estimate_model(trials, Structure.order(4))
    assert "not yet support" in _one_line(err)


@pytest.mark.parametrize("bad, pattern", [
    ("nan", "non-finite"),
    ("short", "samples"),
    ("nonuniform", "not uniformly sampled"),
    ("two_rates", "one sampling rate"),
    ("shape", "must be"),
    ("invalid", "marked invalid"),
    ("none", "at least one trial"),
    ("too_few", "too few"),
])
def test_bad_trials_give_one_line_errors(bad, pattern):
    trials = closed_loop(2, trials=3, seconds=5.0)
    tr = trials[0]
    if bad == "nan":
        e = tr.e.copy()
        e[5, 1] = np.nan
        trials[0] = Trial(0, tr.t, e, tr.u)
    elif bad == "short":
        trials[0] = Trial(0, tr.t[:4], tr.e[:4], tr.u[:4])
    elif bad == "nonuniform":
        t = tr.t.copy()
        t[10:] += 0.01
        trials[0] = Trial(0, t, tr.e, tr.u)
    elif bad == "two_rates":
        trials[1] = Trial(1, trials[1].t * 2, trials[1].e, trials[1].u)
    elif bad == "shape":
        trials[0] = Trial(0, tr.t, tr.e[:, :1], tr.u)
    elif bad == "invalid":
        valid = np.ones(tr.t.shape[0], bool)
        valid[3] = False
        trials[0] = Trial(0, tr.t, tr.e, tr.u, valid=valid)
    elif bad == "none":
        trials = []
    elif bad == "too_few":
        trials = [Trial(0, tr.t[:7], tr.e[:7], tr.u[:7])]
    with pytest.raises(VerifyInputError) as err:
        estimate_model(trials, Structure.paper())
    assert pattern in _one_line(err)


def test_unknown_method_and_non_structure_are_refused():
    trials = closed_loop(3, trials=2, seconds=5.0)
    with pytest.raises(VerifyInputError) as err:
        estimate_model(trials, Structure.paper(), method="magic")
    assert "riv+pem" in _one_line(err)
    with pytest.raises(VerifyInputError) as err:
        estimate_model(trials, "paper")  # type: ignore[arg-type]
    assert "Structure.paper()" in _one_line(err)


@pytest.mark.parametrize("kwargs, pattern", [
    ({"initial": "guess"}, "initial must be"),
    ({"burn_in": -1.0}, "burn_in"),
    ({"burn_in": float("nan")}, "burn_in"),
    ({"burn_in": 100.0}, "burn_in"),
    ({"burn_in": "1"}, "burn_in"),
])
def test_bad_trial_start_options_are_refused(kwargs, pattern):
    trials = closed_loop(4, trials=2, seconds=5.0)
    with pytest.raises(VerifyInputError) as err:
        estimate_model(trials, Structure.paper(), **kwargs)
    assert pattern in _one_line(err)


def test_residual_tests_refuse_trials_shorter_than_the_lags():
    with pytest.raises(VerifyInputError) as err:
        whiteness([np.ones(10)], lags=20)
    assert "longer than" in _one_line(err)


# --- covariance calibration (deep) ---------------------------------------------------

@pytest.mark.slow
def test_asymptotic_intervals_cover_on_the_linear_closed_loop():
    """30 seeded closed-loop data sets (operator at rest at each trial's start, white
    operator noise at the sampling rate): each parameter's 95 % interval holds the true
    value in at least 80 % of them."""
    hits = []
    for seed in range(100, 130):
        est = estimate_model(closed_loop(seed), Structure.paper())
        hits.append(np.abs(est.theta - THETA) <= 1.96 * est.standard_errors())
    coverage = np.mean(hits, axis=0)
    print("coverage per parameter:", np.round(coverage, 2))
    assert np.all(coverage >= 0.8), coverage


@pytest.mark.slow
def test_coverage_study_on_simulated_so3_experiments_prints_its_numbers():
    """A short run of the study of benchmarks/bench_identify_coverage.py (3 seeds, n = 3):
    every repetition is estimated, and the fit ratios are printed."""
    from verify.identify.quality.coverage import run_study

    theta = (1.2, 0.8, 2.0, 1.5, 1.2, 0.8, 2.0, 1.5, 0.05, -0.05)
    study = run_study(theta, range(2000, 2003), n=3)
    est = study.estimates("riv+pem")
    assert est.shape == (3, 10) and np.all(np.isfinite(est))
    print("coverage:", np.round(study.coverage("riv+pem"), 2))
    print("fit on clean data:", [np.round(r.fit_clean["riv+pem"], 2) for r in study.repetitions])


def test_refinements_on_the_search_bound_are_set_aside(monkeypatch):
    """A refinement that ends on the box of denominators (poles at half the Nyquist
    frequency) is never returned; when all do, the error says so in one line."""
    import verify.identify.estimate.estimation as estimation
    from verify.identify.estimate.pem import denominator_bounds

    trials = closed_loop(5, trials=2, seconds=6.0)
    real_refine = estimation.refine
    calls = []

    def on_bound(data, a0, zeros, d0=None):
        fit = real_refine(data, a0, zeros, d0)
        calls.append(1)
        return replace(fit, a=denominator_bounds(len(fit.a), data.h))

    monkeypatch.setattr(estimation, "refine", on_bound)
    with pytest.raises(VerifyInputError) as err:
        estimate_model(trials, Structure.paper())
    assert "bound" in _one_line(err)
    assert len(calls) == estimation.MAX_STARTS  # it looked further before giving up
    h = trials[0].step
    assert np.allclose(denominator_bounds(2, h), [2 * 0.5 * np.pi / h, (0.5 * np.pi / h) ** 2])


def test_the_covariance_is_widened_for_few_trials():
    """The few-trials factor T / (T - 2) (3 below 4 trials) multiplies the asymptotic
    covariance and nothing else; it tends to 1 as trials are added."""
    from verify.identify.estimate.estimation import few_trials_factor

    assert few_trials_factor(6) == 1.5 and few_trials_factor(12) == 1.2
    assert few_trials_factor(1) == few_trials_factor(3) == 3.0
    assert few_trials_factor(1000) == pytest.approx(1.0, abs=3e-3)
    with pytest.raises(VerifyInputError):
        few_trials_factor(0)
    trials = closed_loop(11)
    wide = estimate_model(trials, Structure.paper())
    plain = estimate_model(trials, Structure.paper(), inflate=False)
    assert wide.inflation == 1.5 and plain.inflation == 1.0
    assert np.array_equal(wide.theta, plain.theta)
    assert np.allclose(wide.covariance, 1.5 * plain.covariance, rtol=1e-12, atol=0)
