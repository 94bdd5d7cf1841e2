"""Experiment logs: round trips, and every defect the format names gives one line."""

import io
import zipfile

import numpy as np
import pytest

from verify.errors import VerifyInputError
from verify.inputs.experiment import ExperimentLog, Trial
from verify.inputs.experiment_log import read_log, read_logs, write_log

RATE = 120.0


def _log(trials=3, n=40, *, reference=True, valid=True, start=True, seed=0) -> ExperimentLog:
    rng = np.random.default_rng(seed)
    out = []
    for k in range(trials):
        t = (np.arange(n) + k * n) / RATE
        ref = rng.standard_normal((n, 3)) if reference else None
        ok = rng.random(n) > 0.1 if valid else None
        out.append(Trial(k, t, rng.standard_normal((n, 2)) * 1e-3 ** rng.random((n, 2)),
                         rng.standard_normal((n, 2)), ref, ok,
                         float(t[5 + k]) if start else None))
    return ExperimentLog(tuple(out), RATE, "test log")


def _same(a: ExperimentLog, b: ExperimentLog) -> None:
    assert a.rate == b.rate and len(a.trials) == len(b.trials)
    for x, y in zip(a.trials, b.trials, strict=True):
        assert x.trial == y.trial and x.start == y.start
        for name in ("t", "e", "u", "reference", "valid"):
            p, q = getattr(x, name), getattr(y, name)
            assert (p is None) == (q is None)
            if p is not None:
                assert p.dtype == q.dtype and np.array_equal(p, q)  # bit exact


@pytest.mark.parametrize("suffix", [".csv", ".npz"])
@pytest.mark.parametrize("full", [True, False])
def test_round_trip_is_bit_exact(tmp_path, suffix, full):
    log = _log(reference=full, valid=full, start=full)
    path = write_log(log, tmp_path / f"log{suffix}")
    back = read_log(path)
    _same(log, back)
    assert back.source == str(path)
    again = tmp_path / f"again{suffix}"
    write_log(back, again)
    if suffix == ".npz":  # fixed zip timestamps: equal logs give equal bytes
        assert path.read_bytes() == again.read_bytes()


def test_csv_round_trip_keeps_awkward_floats(tmp_path):
    # the extremes the limits allow: the smallest normal float, -0.0, MAX_VALUE
    values = np.array([[2.2250738585072014e-308, -0.0], [1e9, 0.1], [1 / 3, -2.5e-17]])
    tr = Trial(0, np.arange(3) / RATE, values, values[::-1].copy())
    path = write_log(ExperimentLog((tr,), RATE, ""), tmp_path / "x.csv")
    back = read_log(path).trials[0]
    assert np.array_equal(back.e, values) and np.signbit(back.e[0, 1])


def test_read_logs_combines_and_renumbers(tmp_path):
    a = write_log(_log(2, seed=1), tmp_path / "a.csv")
    b = write_log(_log(3, seed=2), tmp_path / "b.npz")
    both = read_logs([a, b])
    assert [tr.trial for tr in both.trials] == [0, 1, 2, 3, 4]  # ids collided: renumbered
    np.testing.assert_array_equal(both.trials[2].u, read_log(b).trials[0].u)
    log = _log(2, seed=3)
    shifted = ExperimentLog(tuple(Trial(tr.trial + 10, tr.t, tr.e, tr.u) for tr in log.trials),
                            RATE, "")
    c = write_log(shifted, tmp_path / "c.csv")
    assert [tr.trial for tr in read_logs([a, c]).trials] == [0, 1, 10, 11]  # kept
    slow = ExperimentLog(tuple(Trial(tr.trial, tr.t * 2, tr.e, tr.u) for tr in log.trials),
                         RATE / 2, "")
    d = write_log(slow, tmp_path / "d.csv")
    with pytest.raises(VerifyInputError, match=r"d\.csv: rate 60 Hz differs"):
        read_logs([a, d])
    with pytest.raises(VerifyInputError, match="no log files"):
        read_logs([])


# ------------------------------------------------------------------ hostile CSV

HEADER = "time,trial,e1,e2,u1,u2"


def _rows(n=5, trial=0, t0=0.0, step=0.01):
    return [f"{t0 + k * step!r},{trial},0.1,0.2,0.3,0.4" for k in range(n)]


def _csv(tmp_path, lines, name="bad.csv"):
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    return path


CSV_CASES = {
    "missing column": ([HEADER.replace(",u2", ""), *[r.rsplit(",", 1)[0] for r in _rows()]],
                       r"line 1 \(header\): missing column u2"),
    "unknown column": ([HEADER + ",speed", *[r + ",1" for r in _rows()]],
                       r"unknown column 'speed'"),
    "duplicate column": ([HEADER + ",e1", *[r + ",1" for r in _rows()]],
                         r"column 'e1' appears twice"),
    "partial reference": ([HEADER + ",r1", *[r + ",1" for r in _rows()]],
                          r"reference columns r1 without the others"),
    "nan": ([HEADER, *_rows(2), "0.02,0,nan,0.2,0.3,0.4"], r"line 4, column 'e1': NaN or Inf"),
    "inf": ([HEADER, *_rows(2), "0.02,0,0.1,0.2,-inf,0.4"], r"line 4, column 'u1': NaN or Inf"),
    "overflow": ([HEADER, *_rows(2), "0.02,0,0.1,1e999,0.3,0.4"],
                 r"line 4, column 'e2': '1e999' is beyond the float range"),
    "text": ([HEADER, *_rows(2), "0.02,0,0.1,abc,0.3,0.4"],
             r"line 4, column 'e2': 'abc' is not a number"),
    "underscore": ([HEADER, *_rows(2), "0.02,0,1_0,0.2,0.3,0.4"],
                   r"line 4, column 'e1': '1_0' is not a number"),
    "empty cell": ([HEADER, *_rows(2), "0.02,0,,0.2,0.3,0.4"], r"line 4, column 'e1': empty"),
    "row length": ([HEADER, *_rows(2), "0.02,0,0.1,0.2,0.3"], r"line 4: 5 cells, the header"),
    "time back": ([HEADER, "0.0,0,1,1,1,1", "0.02,0,1,1,1,1", "0.01,0,1,1,1,1"],
                  r"line 4, column 'time': time 0.01 goes back within trial 0"),
    "time repeats": ([HEADER, "0.0,0,1,1,1,1", "0.01,0,1,1,1,1", "0.01,0,1,1,1,1"],
                     r"line 4, column 'time': time 0.01 repeats within trial 0"),
    # 0.0201 would still lie on a grid within its written precision (1e-4: module doc)
    "unequal": ([HEADER, "0.0,0,1,1,1,1", "0.01,0,1,1,1,1", "0.0203,0,1,1,1,1",
                 "0.03,0,1,1,1,1"], r"column 'time': unequal sampling in trial 0.*relative 1e-06"),
    "steps differ": ([HEADER, *_rows(4), *_rows(4, trial=1, step=0.02)],
                     r"line 6, trial 1: trial 1 has step 0.02 s, the first trial 0.01 s"),
    "short trial": ([HEADER, *_rows(5), *_rows(1, trial=1, t0=1.0)],
                    r"line 7, trial 1: trial 1 has 1 sample; at least 2"),
    "header only": ([HEADER], r"header but no samples"),
    "comments only": (["# rate = 120", "# nothing"], r"empty log \(no header line\)"),
    "valid not 0/1": ([HEADER + ",valid", *[r + ",1" for r in _rows(2)], "0.02,0,1,1,1,1,2"],
                      r"line 4, column 'valid': 2 is not 0 or 1"),
    "start text": ([HEADER + ",start", *[r + ",0" for r in _rows(2)], "0.02,0,1,1,1,1,yes"],
                   r"line 4, column 'start': 'yes' is not an integer"),
    "trial float": ([HEADER, *_rows(2), "0.02,0.5,1,1,1,1"],
                    r"line 4, column 'trial': '0.5' is not an integer"),
    "trial 1.0": ([HEADER, *_rows(2), "0.02,1.0,1,1,1,1"],
                  r"line 4, column 'trial': '1.0' is not an integer.*decimal point"),
    "two starts": ([HEADER + ",start", "0.0,0,1,1,1,1,1", "0.01,0,1,1,1,1,0",
                    "0.02,0,1,1,1,1,1"], r"line 4, column 'start': a second start event"),
    "trial split": ([HEADER, *_rows(3), *_rows(3, trial=1, t0=1.0), *_rows(3, t0=2.0)],
                    r"line 8, trial 0: trial 0 appears again after other trials \(first at "
                    r"line 2\)"),
    "bad rate": (["# rate = fast", HEADER, *_rows(3)], r"line 1: rate 'fast' is not a positive"),
    # (times 0.0, 0.01, 0.02 would be 120 Hz rounded to 2 decimals: they cannot disagree)
    "rate disagrees": (["# rate = 120", HEADER, *_rows(3, step=0.0125)],
                       r"the rate metadata says 120 Hz but the time step is 0.0125"),
}


@pytest.mark.parametrize("case", sorted(CSV_CASES))
def test_bad_csv_is_one_line(tmp_path, case):
    lines, pattern = CSV_CASES[case]
    path = _csv(tmp_path, lines)
    with pytest.raises(VerifyInputError, match=pattern) as info:
        read_log(path)
    text = str(info.value)
    assert "\n" not in text and str(path) in text


def test_short_trial_against_min_samples(tmp_path):
    path = _csv(tmp_path, [HEADER, *_rows(5)])
    assert len(read_log(path, min_samples=5).trials[0].t) == 5
    with pytest.raises(VerifyInputError, match=r"trial 0 has 5 samples; at least 6 are needed"):
        read_log(path, min_samples=6)
    with pytest.raises(VerifyInputError, match="min_samples must be an integer >= 2"):
        read_log(path, min_samples=1)


def test_comments_and_spaces_are_allowed(tmp_path):
    lines = ["# a comment", "# rate = 100", " time , trial,e1,e2,u1,u2", "", *_rows(2),
             "  # between rows", *_rows(2, t0=0.02)]
    log = read_log(_csv(tmp_path, lines))
    assert log.rate == 100.0 and log.trials[0].t.shape == (4,)


def test_not_utf8_and_missing_file_and_suffix(tmp_path):
    path = tmp_path / "bin.csv"
    path.write_bytes(b"\xff\xfe\x00time")
    with pytest.raises(VerifyInputError, match="not UTF-8"):
        read_log(path)
    with pytest.raises(VerifyInputError, match="no such log file"):
        read_log(tmp_path / "none.csv")
    with pytest.raises(VerifyInputError, match=r"unknown log format '\.txt'"):
        read_log(tmp_path / "log.txt")
    empty = tmp_path / "empty.csv"
    empty.write_text("")
    with pytest.raises(VerifyInputError, match="empty log"):
        read_log(empty)


# ------------------------------------------------------------------ hostile NPZ


def _good_arrays(n=6):
    t = np.arange(n) * 0.01
    return dict(time=t, trial=np.zeros(n, np.int64), e1=t, e2=t, u1=t, u2=t)


def _npz(tmp_path, arrays, name="bad.npz"):
    path = tmp_path / name
    np.savez(path, **arrays)
    return path


NPZ_CASES = {
    "missing": (lambda a: {k: v for k, v in a.items() if k != "u1"}, r"missing column u1"),
    "unknown": (lambda a: {**a, "extra": a["time"]}, r"unknown column 'extra'"),
    "nan": (lambda a: {**a, "e2": np.where(a["time"] > 0.02, np.nan, 0.0)},
            r"array 'e2'\[3\]: NaN or Inf"),
    "2-d": (lambda a: {**a, "e1": np.zeros((6, 2))}, r"array 'e1': must be 1-D"),
    "lengths": (lambda a: {**a, "u2": np.zeros(5)}, r"arrays of different lengths"),
    "float trial": (lambda a: {**a, "trial": np.zeros(6)}, r"array 'trial': dtype float64 is not"),
    "text column": (lambda a: {**a, "e1": np.array(["a"] * 6)}, r"array 'e1': dtype <U1 is not"),
    "complex": (lambda a: {**a, "u1": np.zeros(6, complex)}, r"array 'u1': dtype complex128"),
    "valid 2": (lambda a: {**a, "valid": np.full(6, 2)}, r"entry 0, column 'valid': 2 is not 0"),
    "time back": (lambda a: {**a, "time": a["time"][[0, 1, 3, 2, 4, 5]]},
                  r"entry 3, column 'time': time 0.02 goes back"),
    "rate shape": (lambda a: {**a, "rate": np.array([120.0, 60.0])}, r"array 'rate': must be one"),
    "empty": (lambda a: {k: v[:0] for k, v in a.items()}, r"the log has no samples"),
    "no arrays": (lambda a: {}, r"empty archive"),
}


@pytest.mark.parametrize("case", sorted(NPZ_CASES))
def test_bad_npz_is_one_line(tmp_path, case):
    make, pattern = NPZ_CASES[case]
    path = _npz(tmp_path, make(_good_arrays()))
    with pytest.raises(VerifyInputError, match=pattern) as info:
        read_log(path)
    assert "\n" not in str(info.value) and str(path) in str(info.value)


def test_npz_with_object_arrays_is_refused_without_unpickling(tmp_path):
    arrays = {**_good_arrays(), "e1": np.array([object()] * 6, dtype=object)}
    path = tmp_path / "obj.npz"
    np.savez(path, **{k: v for k, v in arrays.items() if k != "e1"},
             e1=np.array([{"a": 1}] * 6, dtype=object))
    with pytest.raises(VerifyInputError, match=r"array 'e1' holds Python objects"):
        read_log(path)


def test_npz_bool_flags_and_not_a_zip(tmp_path):
    arrays = {**_good_arrays(), "valid": np.ones(6, bool), "start": np.arange(6) == 2}
    tr = read_log(_npz(tmp_path, arrays, "ok.npz")).trials[0]
    assert tr.valid.all() and tr.start == 0.02
    junk = tmp_path / "junk.npz"
    junk.write_bytes(b"not a zip at all")
    with pytest.raises(VerifyInputError, match=r"not a readable \.npz archive"):
        read_log(junk)
    one = tmp_path / "one.npz"
    with open(one, "wb") as handle:
        np.save(handle, np.zeros(3))
    with pytest.raises(VerifyInputError, match=r"a single \.npy array"):
        read_log(one)
    broken = tmp_path / "broken.npz"
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as z:
        z.writestr("time.npy", b"\x93NUMPY garbage")
    broken.write_bytes(buf.getvalue())
    with pytest.raises(VerifyInputError, match=r"broken\.npz"):
        read_log(broken)


# ------------------------------------------------------------------ writing


def test_failed_write_leaves_nothing(tmp_path):
    bad = ExperimentLog((Trial(0, np.arange(3) / RATE, np.full((3, 2), np.nan),
                               np.zeros((3, 2))),), RATE, "")
    for suffix in (".csv", ".npz"):
        with pytest.raises(VerifyInputError, match="column 'e1' has NaN or Inf"):
            write_log(bad, tmp_path / f"out{suffix}")
    off = ExperimentLog((Trial(0, np.arange(3) / RATE, np.zeros((3, 2)), np.zeros((3, 2)),
                               start=0.001),), RATE, "")
    with pytest.raises(VerifyInputError, match=r"start time 0\.001 is not a sample time"):
        write_log(off, tmp_path / "out.csv")
    with pytest.raises(VerifyInputError, match="unknown log format"):
        write_log(_log(1), tmp_path / "out.json")
    assert list(tmp_path.iterdir()) == []


def test_existing_file_survives_a_failed_write(tmp_path):
    path = write_log(_log(1), tmp_path / "keep.csv")
    before = path.read_bytes()
    bad = ExperimentLog((Trial(0, np.arange(3) / RATE, np.full((3, 2), np.inf),
                               np.zeros((3, 2))),), RATE, "")
    with pytest.raises(VerifyInputError):
        write_log(bad, path)
    assert path.read_bytes() == before and list(tmp_path.iterdir()) == [path]


# ------------------------------------------------------------------ hostile: sampling


def _fixed(n, decimals, rate=RATE, trial=0, t0=0.0):
    return [f"{t0 + k / rate:.{decimals}f},{trial},0.1,0.2,0.3,0.4" for k in range(n)]


def test_times_written_with_six_decimals_at_120_hz_are_equal_sampling(tmp_path):
    log = read_log(_csv(tmp_path, [HEADER, *_fixed(200, 6), *_fixed(150, 6, trial=1, t0=3.0)]))
    assert log.rate == 120.0  # the simplest rate the written step allows
    assert [len(tr.t) for tr in log.trials] == [200, 150]
    with_rate = read_log(_csv(tmp_path, ["# rate = 120", HEADER, *_fixed(40, 6)], "r.csv"))
    assert with_rate.rate == 120.0


def test_written_precision_does_not_hide_a_skipped_sample(tmp_path):
    rows = _fixed(60, 6)
    del rows[30]  # one sample missing: the grid is off by a whole step there
    with pytest.raises(VerifyInputError, match=r"line 32, column 'time': unequal sampling.*"
                       r"within 1e-06 s \(its written precision\)"):
        read_log(_csv(tmp_path, [HEADER, *rows]))
    jitter = _fixed(60, 6)
    jitter[20] = jitter[20].replace(jitter[20].split(",")[0],
                                    f"{20 / RATE + 3e-6:.6f}")  # 3 units of the last digit
    with pytest.raises(VerifyInputError, match=r"unequal sampling in trial 0"):
        read_log(_csv(tmp_path, [HEADER, *jitter], "j.csv"))


def test_a_byte_order_mark_is_ignored(tmp_path):
    path = tmp_path / "bom.csv"
    path.write_text("\n".join([HEADER, *_rows(4)]) + "\n", encoding="utf-8-sig")
    assert path.read_bytes().startswith(b"\xef\xbb\xbf")
    assert len(read_log(path).trials[0].t) == 4


# ------------------------------------------------------------------ hostile: sizes

SIZE_CASES = {
    "1e308 in a cell": ("0.02,0,1e308,0.2,0.3,0.4",
                        r"line 4, column 'e1': '1e308' exceeds the limit 1e\+09"),
    "max float in a cell": ("0.02,0,0.1,0.2,-1.7976931348623157e308,0.4",
                            r"line 4, column 'u1': .* exceeds the limit"),
    "trial id 1e20": ("0.02,100000000000000000000,1,1,1,1",
                      r"line 4, column 'trial': '100000000000000000000' has more than 18"),
    "trial id 1e20 written as a float": ("0.02,1e20,1,1,1,1",
                                         r"line 4, column 'trial': '1e20' is not an integer"),
    "trial id beyond the limit": ("0.02,900000000000000000,1,1,1,1",
                                  r"line 4, column 'trial': trial id 900000000000000000 "
                                  r"exceeds the limit"),
    "subnormal value": ("0.02,0,5e-324,1,1,1",
                        r"line 4, column 'e1': '5e-324' is below the normal float range"),
    "huge time": ("1e12,0,1,1,1,1", r"line 4, column 'time': '1e12' exceeds the limit 1e\+09s"),
    "many digits": ("0.02,0," + "1" * 50 + ",1,1,1",
                    r"line 4, column 'e1': '1111.*' has more digits than a log allows"),
    "long cell": ("0.02,0," + "1" * 70 + ",1,1,1",
                  r"line 4, column 'e1': a cell of 70 characters \(limit 64\)"),
    "long exponent": ("0.02,0,1e99999999,1,1,1",
                      r"line 4, column 'e1': '1e99999999' has more digits"),
}


@pytest.mark.parametrize("case", sorted(SIZE_CASES))
def test_huge_tiny_and_overflowing_values_are_one_line(tmp_path, case):
    row, pattern = SIZE_CASES[case]
    path = _csv(tmp_path, [HEADER, *_rows(2), row])
    with pytest.raises(VerifyInputError, match=pattern) as info:
        read_log(path)
    assert "\n" not in str(info.value)


@pytest.mark.parametrize(("times", "pattern"), [
    ([k * 5e-324 for k in range(1, 6)], r"'5e-324' is below the normal float range"),
    ([1.0 + k * 1e-12 for k in range(5)], r"time step of 1e-12 s, below 1e-06 s"),
    ([1e8 + k * 0.01 for k in range(5)], r"time step of 0\.01 s, below 0\.0931"),
])
def test_steps_too_small_to_resolve_are_one_line(tmp_path, times, pattern):
    path = _csv(tmp_path, [HEADER, *[f"{t!r},0,1,1,1,1" for t in times]])
    with pytest.raises(VerifyInputError, match=pattern):
        read_log(path)


def test_cli_exit_2_not_3_for_value_edges(tmp_path, capsys):
    from verify.cli import main

    for name, row in [("big", "0.02,0,1e308,0.2,0.3,0.4"), ("id", "0.02,10**20,1,1,1,1"),
                      ("sub", "1e-320,0,1,1,1,1")]:
        path = _csv(tmp_path, [HEADER, *_rows(2), row], f"{name}.csv")
        assert main(["identify", str(path), "--split", "1:1", "--out",
                     str(tmp_path / f"out-{name}")]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and str(path) in err and "Traceback" not in err
    assert not any(p.name.startswith("out-") for p in tmp_path.iterdir())


def test_a_trial_too_short_for_the_filter_is_exit_2(tmp_path, capsys):
    from verify.cli import main

    rows = [*_fixed(200, 9), *_fixed(3, 9, trial=1, t0=5.0), *_fixed(200, 9, trial=2, t0=9.0)]
    path = _csv(tmp_path, [HEADER, *rows])
    assert main(["identify", str(path), "--split", "2:1", "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "trial 1 has 3 samples; at least 28 are needed" in err and err.count("\n") == 1


def test_split_advice_is_a_split_the_command_accepts(tmp_path, capsys):
    import re

    from verify.cli import main
    from verify.identify.command import parse_split

    for count in (1, 2, 3, 5):
        rows = [r for k in range(count) for r in _fixed(40, 9, trial=k, t0=2.0 * k)]
        path = _csv(tmp_path, [HEADER, *rows], f"n{count}.csv")
        assert main(["identify", str(path), "--split", "6:6", "--out",
                     str(tmp_path / "o")]) == 2
        err = capsys.readouterr().err
        assert f"needs 12 trials but the log has {count}" in err
        advice = re.search(r"--split (\d+:\d+)\s*$", err.strip())
        if count == 1:
            assert advice is None and "at least 2 trials" in err
        else:
            a, b = parse_split(advice.group(1))  # accepted by the command's parser
            assert a + b == count


# ------------------------------------------------------------------ hostile: streaming


def test_csv_reading_stops_at_the_first_defect():
    from verify.inputs.experiment_log import read_csv_lines

    consumed = []

    def lines():
        yield HEADER
        for k in range(10**9):  # an endless log whose line 6 is bad
            consumed.append(k)
            yield "0.0x,0,1,1,1,1" if k == 4 else f"{k * 0.01!r},0,1,1,1,1"

    with pytest.raises(VerifyInputError, match=r"src: line 6, column 'time': '0\.0x' is not"):
        read_csv_lines(lines(), source="src")
    assert consumed == [0, 1, 2, 3, 4]  # nothing after the defect was read

    def trials():
        yield HEADER
        for k in range(3):
            yield f"{k * 0.01!r},0,1,1,1,1"
        yield "0.5,1,1,1,1,1"  # trial 1 starts: trial 0 (3 samples) is checked now
        raise AssertionError("read past the end of a short trial")

    with pytest.raises(VerifyInputError, match=r"trial 0 has 3 samples; at least 4"):
        read_csv_lines(trials(), source="src", min_samples=4)


def test_log_paths_that_are_not_regular_files(tmp_path):
    import os

    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    with pytest.raises(VerifyInputError, match=r"pipe\.csv: is a FIFO"):
        read_log(fifo)  # returns at once: opened without blocking
    zero = tmp_path / "zero.npz"
    zero.symlink_to("/dev/zero")
    with pytest.raises(VerifyInputError, match=r"zero\.npz: is a device"):
        read_log(zero)
    folder = tmp_path / "dir.csv"
    folder.mkdir()
    with pytest.raises(VerifyInputError, match=r"dir\.csv: is a directory"):
        read_log(folder)


# ------------------------------------------------------------------ hostile: NPZ sizes


def _zip(path, members: dict[str, bytes]):
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED) as z:
        for name, data in members.items():
            z.writestr(name, data)
    return path


def _npy(arr: np.ndarray) -> bytes:
    buf = io.BytesIO()
    np.lib.format.write_array(buf, arr, allow_pickle=False)
    return buf.getvalue()


def test_npz_header_promising_more_than_the_member_holds(tmp_path, monkeypatch):
    def no_data(*args, **kwargs):
        raise AssertionError("array data read before the headers were checked")

    monkeypatch.setattr(np.lib.format, "read_array", no_data)
    huge = io.BytesIO()
    np.lib.format.write_array_header_1_0(huge, {"descr": "<f8", "fortran_order": False,
                                                "shape": (2**40,)})
    members = {f"{k}.npy": _npy(v) for k, v in _good_arrays().items() if k != "e1"}
    path = _zip(tmp_path / "lie.npz", {**members, "e1.npy": huge.getvalue()})
    with pytest.raises(VerifyInputError, match=r"array 'e1': its header promises "
                       r"8796093022208 bytes, the member holds"):
        read_log(path)


def test_npz_uncompressed_size_is_bounded_before_decompressing(tmp_path, monkeypatch):
    import verify.inputs.log_npz as module

    path = _zip(tmp_path / "bomb.npz", {f"{k}.npy": _npy(np.resize(v, 20_000))
                                        for k, v in _good_arrays().items()})
    opened = []
    real_open = zipfile.ZipFile.open
    monkeypatch.setattr(zipfile.ZipFile, "open",
                        lambda self, *a, **k: opened.append(a) or real_open(self, *a, **k))
    monkeypatch.setattr(module, "MAX_NPZ_BYTES", 100_000)
    with pytest.raises(VerifyInputError, match=r"bomb\.npz: the archive holds 6 member\(s\) "
                       r"of 960\d+ bytes uncompressed, above the limit"):
        read_log(path)
    assert opened == []  # refused from the zip directory alone


def test_npz_trial_ids_and_values_beyond_the_limits(tmp_path):
    cases = {
        "uint64 ids": ({"trial": np.full(6, 2**63 + 5, np.uint64)},
                       r"array 'trial'\[0\]: 9223372036854775813 exceeds the limit"),
        "huge value": ({"u2": np.array([0, 0, 1e300, 0, 0, 0])},
                       r"array 'u2'\[2\]: '1e\+300' exceeds the limit 1e\+09"),
        "subnormal": ({"e1": np.array([0, 1e-310, 0, 0, 0, 0])},
                      r"array 'e1'\[1\]: '1e-310' is below the normal float range"),
        "subnormal step": ({"time": np.arange(6) * 5e-324},
                           r"array 'time'\[1\]: '5e-324' is below the normal float range"),
    }
    for name, (change, pattern) in cases.items():
        path = _npz(tmp_path, {**_good_arrays(), **change}, f"{name}.npz")
        with pytest.raises(VerifyInputError, match=pattern):
            read_log(path)


def test_a_log_without_line_breaks_is_refused_after_a_bounded_read(tmp_path):
    path = tmp_path / "one.csv"
    path.write_text(HEADER + "\n" + "0.0," * 200_000 + "\n")
    with pytest.raises(VerifyInputError, match=r"one\.csv: line 2 is longer than 10000"):
        read_log(path)


def test_quoted_cells_and_crlf_line_ends(tmp_path):
    path = tmp_path / "q.csv"
    rows = ['"time","trial","e1","e2","u1","u2"', *[f'"{k * 0.01!r}","0",1,2,3,4'
                                                      for k in range(5)]]
    path.write_bytes(("\r\n".join(rows) + "\r\n").encode())
    tr = read_log(path).trials[0]
    assert tr.t.shape == (5,) and tr.u[0, 1] == 4.0


def test_npz_member_stored_twice_is_ambiguous(tmp_path):
    members = {f"{k}.npy": _npy(v) for k, v in _good_arrays().items()}
    path = _zip(tmp_path / "twice.npz", members)
    with zipfile.ZipFile(path, "a") as z, pytest.warns(UserWarning, match="Duplicate name"):
        z.writestr("e1.npy", _npy(np.full(6, 7.0)))
    with pytest.raises(VerifyInputError, match=r"holds 'e1\.npy' twice"):
        read_log(path)


def test_a_trial_too_short_for_the_model_after_decimation_is_exit_2(tmp_path, capsys):
    from verify.cli import main

    rows = [*_fixed(200, 9), *_fixed(40, 9, trial=1, t0=5.0), *_fixed(200, 9, trial=2, t0=9.0)]
    path = _csv(tmp_path, [HEADER, *rows])
    assert main(["identify", str(path), "--split", "2:1", "--rate", "20",
                 "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "trial 1 has 40 samples; at least 43 are needed (8 after decimation by 6" in err
    assert err.count("\n") == 1


@pytest.mark.parametrize("rate", [100.0, 120.0, 250.0, 1000.0])
@pytest.mark.parametrize("decimals", [4, 5, 6, 7, 9])
def test_rounded_times_of_a_known_grid_read_back_as_that_grid(tmp_path, rate, decimals):
    """Data from a known truth: a uniform grid at ``rate`` (with an offset start), times
    rounded to ``decimals``; the reader must accept it and find the rate."""
    rows = [*_fixed(300, decimals, rate=rate, t0=1.2345678),
            *_fixed(250, decimals, rate=rate, trial=1, t0=7.7777777)]
    log = read_log(_csv(tmp_path, [HEADER, *rows]))
    assert log.rate == rate and [len(tr.t) for tr in log.trials] == [300, 250]
    # the same grid with one time moved by two units of its last digit is refused
    k = 150
    moved = rows.copy()
    t = float(rows[k].split(",")[0]) + 2 * 10.0 ** -decimals
    moved[k] = f"{t:.{decimals}f}" + rows[k][rows[k].index(","):]
    if 2 * 10.0 ** -decimals < 1e-6 / rate:  # within the relative 1e-6 tolerance anyway
        return
    with pytest.raises(VerifyInputError, match=rf"line {k + 2}, column 'time': unequal"):
        read_log(_csv(tmp_path, [HEADER, *moved], "moved.csv"))


def test_the_writer_refuses_what_the_reader_would_refuse(tmp_path):
    for values, pattern in [(np.full((3, 2), 1e300), r"column 'e1'\[0\]: '1e\+300' exceeds"),
                            (np.full((3, 2), 5e-324), r"column 'e1'\[0\]: '5e-324' is below")]:
        bad = ExperimentLog((Trial(0, np.arange(3) / RATE, values, np.zeros((3, 2))),), RATE, "")
        for suffix in (".csv", ".npz"):
            with pytest.raises(VerifyInputError, match=pattern):
                write_log(bad, tmp_path / f"out{suffix}")
    far = ExperimentLog((Trial(10**13, np.arange(3) / RATE, np.zeros((3, 2)),
                               np.zeros((3, 2))),), RATE, "")
    with pytest.raises(VerifyInputError, match="an id exceeds the limit"):
        write_log(far, tmp_path / "out.csv")
    assert list(tmp_path.iterdir()) == []


# ------------------------------------------------------------------ hostile: fuzzing

from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

_CELL = st.one_of(
    st.sampled_from(["0", "1", "-0.5", "1e308", "5e-324", "nan", "", " ", "1e99999999",
                     "9" * 30, "0x1", "1_0", '"2"', "١", "1.", ".5", "+3", "-0"]),
    st.text(alphabet="0123456789.eE+-, \"#\t\ufeff", max_size=12),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.integers(min_value=-10**20, max_value=10**20).map(str),
)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.lists(_CELL, min_size=5, max_size=7), min_size=1, max_size=8),
       st.sampled_from([HEADER, HEADER + ",valid", "# rate = 120\n" + HEADER]))
def test_random_rows_give_a_log_or_one_line(rows, header):
    """Whatever the cells, the reader ends in a log or a one-line VerifyInputError."""
    from verify.inputs.experiment_log import read_csv_lines

    lines = [*header.split("\n"), *(",".join(r) for r in rows)]
    try:
        log = read_csv_lines(iter(lines), source="fuzz")
    except VerifyInputError as exc:
        assert "\n" not in str(exc) and str(exc).startswith("fuzz")
        return
    for tr in log.trials:  # what is accepted respects the limits
        assert np.all(np.isfinite(tr.t)) and np.all(np.abs(tr.e) <= 1e9)
        assert np.all(np.diff(tr.t) > 0)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                 HealthCheck.function_scoped_fixture])
@given(st.data())
def test_corrupted_npz_bytes_give_a_log_or_one_line(tmp_path, data):
    good = tmp_path / "good.npz"
    if not good.exists():
        write_log(_log(2, n=30), good)
    raw = bytearray(good.read_bytes())
    for _ in range(data.draw(st.integers(1, 8))):
        k = data.draw(st.integers(0, len(raw) - 1))
        raw[k] = data.draw(st.integers(0, 255))
    cut = data.draw(st.integers(1, len(raw)))
    path = tmp_path / "bad.npz"
    path.write_bytes(bytes(raw[:cut]))
    try:
        read_log(path)
    except VerifyInputError as exc:
        assert "\n" not in str(exc)


def test_a_corrupt_deflate_stream_is_one_line(tmp_path):
    """Flipped bytes inside a compressed member: zlib's own error type, not exit 3."""
    rng = np.random.default_rng(1)
    tr = Trial(0, np.arange(2000) / RATE, rng.random((2000, 2)), rng.random((2000, 2)))
    path = write_log(ExperimentLog((tr,), RATE, ""), tmp_path / "z.npz")
    raw = path.read_bytes()
    with zipfile.ZipFile(path) as z:
        info = z.getinfo("e1.npy")
    start = info.header_offset + 30 + len(info.filename) + len(info.extra)
    refused = 0
    for k in range(200, info.compress_size, 97):
        bad = bytearray(raw)
        bad[start + k] ^= 0xFF
        (tmp_path / "c.npz").write_bytes(bytes(bad))
        with pytest.raises(VerifyInputError) as exc:
            read_log(tmp_path / "c.npz")
        assert "\n" not in str(exc.value)
        refused += 1
    assert refused > 50


@pytest.mark.parametrize(("lines", "pattern"), [
    ([HEADER, '0\r0,0,1,1,1,1'], r"s: line 2: not a CSV row"),
    ([HEADER, '"0\x00",0,1,1,1,1'], r"s: line 2, column 'time': '0\\x00' is not a number"),
    (["\x00" + HEADER, "0,0,1,1,1,1"], r"s: line 1 \(header\): unknown column '\\x00time'"),
])
def test_control_characters_in_lines_are_one_line(lines, pattern):
    from verify.inputs.experiment_log import read_csv_lines

    with pytest.raises(VerifyInputError, match=pattern):
        read_csv_lines(iter(lines), source="s")
