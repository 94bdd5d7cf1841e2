"""The Section 4 data preparation: dead time, invalid samples, decimation, split."""

import numpy as np
import pytest

from verify.errors import VerifyInputError
from verify.identify.data.protocol import MIN_FILTER_SAMPLES, decimation_factor, prepare
from verify.identify.data.simulated_experiment import simulate_experiment
from verify.inputs.experiment import ExperimentLog, Trial
from verify.passivity.model import from_transfer_function

RATE = 120.0


def _log(trials=12, seconds=3.0, *, start=None, valid=None, signal=None) -> ExperimentLog:
    n = round(seconds * RATE)
    out = []
    for k in range(trials):
        t = k * seconds + np.arange(n) / RATE
        x = np.zeros((n, 2)) if signal is None else signal(t)
        s = None if start is None else float(t[start[k] if isinstance(start, list) else start])
        out.append(Trial(k, t, x, x.copy(), start=s,
                         valid=None if valid is None else valid(k, n)))
    return ExperimentLog(tuple(out), RATE, "synthetic")


def test_dead_time_is_removed_exactly_at_the_event():
    starts = [37 + k for k in range(12)]
    log = _log(start=starts)
    for rate in (120.0, 20.0):
        prep = prepare(log, rate=rate, dead_time="event")
        assert prep.rule == "event"
        for k, tr in enumerate(prep.identification + prep.validation):
            source = log.trials[k]
            assert tr.t[0] == source.t[starts[k]]  # the start sample is the first one kept
            assert prep.dead_time[k] == pytest.approx(starts[k] / RATE)
            np.testing.assert_allclose(np.diff(tr.t), 1 / rate, rtol=1e-9)
            assert tr.t[-1] <= source.t[-1]
            assert tr.start is None and tr.valid is None


def test_event_rule_needs_every_event_and_auto_falls_back():
    log = _log()
    with pytest.raises(VerifyInputError, match="trial 0 has no start event") as info:
        prepare(log, dead_time="event")
    assert "\n" not in str(info.value)
    assert prepare(log).rule == "threshold"
    assert prepare(_log(start=5)).rule == "event"
    with pytest.raises(VerifyInputError, match="dead-time rule 'button' is unknown"):
        prepare(log, dead_time="button")


def test_decimation_keeps_slow_and_suppresses_fast_sinusoids():
    def slow(t):
        return np.stack([np.sin(2 * np.pi * 0.5 * t), np.cos(2 * np.pi * 0.3 * t)], 1)

    def fast(t):
        return np.stack([np.sin(2 * np.pi * 15 * t), np.sin(2 * np.pi * 25 * t)], 1)

    def both(t):
        return slow(t) + fast(t)

    prep = prepare(_log(seconds=5.0, start=0, signal=slow), rate=20.0)
    assert prep.rate == 20.0 and prep.decimation == 6
    for tr in prep.identification:  # 0.5 and 0.3 Hz pass, to the ends of the segment
        assert tr.t.shape == (100,)
        np.testing.assert_allclose(tr.e, slow(tr.t), atol=1e-3)
        np.testing.assert_array_equal(tr.u, tr.e)  # the same filter on e and u
    prep = prepare(_log(seconds=5.0, start=0, signal=both), rate=20.0)
    for tr in prep.identification:
        # 15 and 25 Hz, above the new Nyquist frequency of 10 Hz (so they would alias),
        # are removed; within 1 s of the ends the filter's edge transient is allowed
        inner = slice(20, -20)
        np.testing.assert_allclose(tr.u[inner], slow(tr.t)[inner], atol=1e-3)
        assert np.max(np.abs(tr.u - slow(tr.t))) < 0.3
    plain = [tr.e for tr in prepare(_log(seconds=5.0, start=0, signal=fast),
                                    rate=20.0).identification]
    assert max(np.max(np.abs(e[20:-20])) for e in plain) < 1e-3
    # without the filter the 15 Hz tone would alias to 5 Hz at full amplitude
    t = np.arange(600) / RATE
    assert np.max(np.abs(np.sin(2 * np.pi * 15 * t)[::6])) > 0.8


@pytest.mark.parametrize(("rate", "pattern"), [
    (25.0, r"120 Hz / 25 Hz = 4\.8 is not an integer; choose a rate that divides 120 Hz, "
           r"e\.g\. 60, 40, 30, 24, 20"),
    (240.0, r"above the log's 120 Hz"),
    (0.0, r"must be a positive number"),
    (float("nan"), r"NaN or Inf"),
])
def test_bad_rates_are_one_line(rate, pattern):
    with pytest.raises(VerifyInputError, match=pattern) as info:
        prepare(_log(start=0), rate=rate)
    assert "\n" not in str(info.value)
    assert decimation_factor(120.0, 40.0) == 3


def test_split_counts():
    log = _log(start=0)
    prep = prepare(log)
    assert [tr.trial for tr in prep.identification] == [0, 1, 2, 3, 4, 5]
    assert [tr.trial for tr in prep.validation] == [6, 7, 8, 9, 10, 11]
    prep = prepare(log, split=(4, 3))
    assert len(prep.identification) == 4 and len(prep.validation) == 3
    assert len(prep.dead_time) == 7
    assert any("trials 7, 8, 9, 10, 11 unused" in note for note in prep.notes)


@pytest.mark.parametrize(("split", "pattern"), [
    ((7, 6), r"--split 7:6 needs 13 trials .* but the log has 12; e\.g\. --split 6:6"),
    ((0, 6), r"--split 0:6 needs 6 trials \(at least 1 for identification\)"),
    ((6, -1), r"--split 6:-1"),
    ((6.5, 6), r"--split must be two whole numbers"),
    (("a", 6), r"--split must be two whole numbers"),
    ((6,), r"--split must be two whole numbers"),
    ((True, 6), r"--split must be two whole numbers"),
])
def test_bad_split_is_one_line(split, pattern):
    with pytest.raises(VerifyInputError, match=pattern) as info:
        prepare(_log(start=0), split=split)
    assert "\n" not in str(info.value)


def test_invalid_samples_split_a_trial_and_short_pieces_are_dropped():
    def valid(k, n):
        ok = np.ones(n, bool)
        if k == 0:
            ok[100:110] = False  # a gap: two segments
            ok[300:] = False  # and a short piece [110, 300) stays, the rest is invalid
        if k == 1:
            ok[MIN_FILTER_SAMPLES - 1:] = False  # too short for the filter
        return ok

    prep = prepare(_log(trials=3, start=0, valid=valid), split=(2, 1))
    first = [tr for tr in prep.identification if tr.trial == 0]
    assert len(first) == 2
    assert first[0].t[0] == 0.0 and first[0].t[-1] < 100 / RATE
    assert first[1].t[0] == pytest.approx(110 / RATE) and first[1].t[-1] < 300 / RATE
    assert not any(tr.trial == 1 for tr in prep.identification)
    assert any("trial 1: segment of 27 samples" in n for n in prep.notes)
    assert any("trial 0: split into 2 segments" in n for n in prep.notes)
    with pytest.raises(VerifyInputError, match="no identification data left"):
        prepare(_log(trials=2, start=0, valid=lambda k, n: np.zeros(n, bool)), split=(1, 1))


def test_threshold_rule_errs_late_on_simulated_operators():
    model = from_transfer_function([[[1.2, 0.8], [0.05]], [[-0.05], [1.2, 0.8]]],
                                   [[[1, 2, 1.5], [1]], [[1], [1, 2, 1.5]]])
    log = simulate_experiment(model, n=3, trials=4, trial_seconds=4.0, seed=11)
    prep = prepare(log, split=(2, 2), dead_time="threshold", rate=120.0)
    assert prep.rule == "threshold"
    for tr, removed in zip(log.trials, prep.dead_time, strict=True):
        late = removed - (tr.start - tr.t[0])
        assert 0 <= late < 0.5  # never before the operator reacted, not much after
