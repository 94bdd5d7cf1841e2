"""Hostile campaign specs: each is refused in one line (exit 2) before any run starts."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from verify.campaign.models import load_spec as load_campaign_spec
from verify.cli import main
from verify.errors import VerifyInputError

MODELS = Path(__file__).resolve().parents[1] / "verify" / "data" / "models"
GOOD_MODEL = (MODELS / "reconstructed_ks3p0.toml").as_posix()

SWEEP = """[sweep]
k_s = [2.0, 3.0]
n = 3
seeds = [0, 1]
seconds = 1
"""
HUMANS = f"""[[humans]]
model = "{GOOD_MODEL}"
"""


def write(tmp_path: Path, text: str, name: str = "spec.toml") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def refused(tmp_path: Path, text: str, *needles: str) -> str:
    """Load ``text`` as a spec; it must raise VerifyInputError naming each needle."""
    with pytest.raises(VerifyInputError) as info:
        load_campaign_spec(write(tmp_path, text))
    message = str(info.value)
    assert "\n" not in message
    for needle in needles:
        assert needle in message, (needle, message)
    return message


def test_a_good_spec_loads(tmp_path):
    spec = load_campaign_spec(write(tmp_path, SWEEP + HUMANS))
    assert spec.k_s == (2.0, 3.0) and spec.n == (3,) and spec.seeds == (0, 1)
    assert spec.step == (1 / 120,) and spec.autonomous == ("consensus",)
    assert spec.run_count == 4 and spec.humans[0].sha256


def test_ranges_are_exact(tmp_path):
    spec = load_campaign_spec(write(tmp_path, """[sweep]
k_s = {from = 1.5, to = 4, step = 0.5}
n = {from = 2, to = 8, count = 4}
seeds = {from = 10, count = 3}
step = "1/240"
seconds = {from = 0.1, step = 0.1, count = 3}
""" + HUMANS))
    assert spec.k_s == (1.5, 2.0, 2.5, 3.0, 3.5, 4.0)  # no 1.9999999 from float steps
    assert spec.n == (2, 4, 6, 8) and spec.seeds == (10, 11, 12)
    assert spec.step == (1 / 240,)
    assert spec.seconds == (0.1, 0.2, 0.3)  # exact 3/10, not 0.1 + 0.1 + 0.1


@pytest.mark.parametrize("text, needles", [
    ("colour = 3\n" + SWEEP + HUMANS, ["unknown key(s) colour", "valid keys: name"]),
    (SWEEP.replace("n = 3", "n = 3\nks = 2") + HUMANS,
     ["[sweep]: unknown key(s) ks", "valid keys: k_s, n, seeds"]),
    (SWEEP.replace("k_s = [2.0, 3.0]", "k_s = {from = 1, to = 2, stride = 1}") + HUMANS,
     ["sweep.k_s: unknown key(s) stride", "valid keys: from, to, step, count"]),
    (SWEEP + HUMANS.replace("model =", "gain = 1\nmodel ="),
     ["humans[0]: unknown key(s) gain", "valid keys: model, label"]),
    (SWEEP + HUMANS + "[checks]\nproperty = ['lemma1']\n",
     ["[checks]: unknown key(s) property", "valid keys: properties"]),
])
def test_unknown_keys_are_named_with_the_valid_ones(tmp_path, text, needles):
    refused(tmp_path, text, *needles)


@pytest.mark.parametrize("k_s, needle", [
    ("[]", "empty list"),
    ("{from = 3, to = 1, step = 0.5}", "empty range"),
    ("{from = 1, count = 0, step = 1}", "empty range"),
    ("{from = 1, to = 2, step = 0}", "step must be > 0"),
    ("{from = 1}", "two of 'to', 'step', 'count'"),
    ("0", "must be a positive number"),
    ("-1.5", "must be a positive number"),
    ("[1, -2]", "k_s[1] must be a positive number"),
    ("nan", "NaN or Inf is not allowed"),
    ("[2, inf]", "NaN or Inf is not allowed"),
    ('"2"', "expected a real number, got str"),
    ("true", "got bool"),
    ("[2, 2.0]", "listed twice"),
    ("{from = 1, to = 2, step = 1e-9}", "at most 100000 per axis"),
    ("1e400", "too large for a float"),
])
def test_bad_gains(tmp_path, k_s, needle):
    refused(tmp_path, SWEEP.replace("[2.0, 3.0]", k_s) + HUMANS, "sweep.k_s", needle)


@pytest.mark.parametrize("line, needle", [
    ("n = 8.0", "expected an integer"),
    ("n = 0", "1 <= n"),
    ("n = {from = 1, to = 5, step = 0.5}", "expected an integer"),
    ("n = {from = 1, to = 4, count = 3}", "do not fit"),
    ("seeds = [-1]", "seed -1"),
    ('seeds = ["0"]', "expected an integer"),
    ('autonomous = ["sideways"]', "choose from zero, random, consensus"),
    ('reference = "wobbly"', "choose from constant, switching"),
    ('reference = {from = 1, count = 2}', "not a table"),
    ("seconds = 0", "must be a positive number"),
    ('step = "1/0"', "not a finite number"),
    ('step = "__import__(\'os\').system(\'true\')"', "not a finite number"),
    ("seconds = 30\nstep = 1e-7", "at most 2000000 are kept"),
])
def test_bad_axes(tmp_path, line, needle):
    key = line.split(" =")[0]
    sweep = "\n".join(x for x in SWEEP.splitlines() if not x.startswith(key + " ")) + "\n"
    refused(tmp_path, sweep + line + "\n" + HUMANS, needle)


def test_too_many_runs(tmp_path):
    sweep = SWEEP.replace("seeds = [0, 1]", "seeds = {from = 0, count = 100000}").replace(
        "[2.0, 3.0]", "{from = 1, to = 20, step = 1}")
    refused(tmp_path, sweep + HUMANS, "2000000 runs", "at most 1000000")


@pytest.mark.parametrize("humans, needles", [
    ("", ["missing [[humans]]"]),
    ('[[humans]]\nmodel = "missing.toml"\n', ["humans[0].model", "cannot read"]),
    ('[[humans]]\nkind = "vr"\nmodel = "x.toml"\n', ["exactly one of", "model and kind"]),
    ('[[humans]]\nlabel = "nobody"\n', ["exactly one of"]),
    ('[[humans]]\nkind = "robot"\n', ["choose from vr, static"]),
    ('[[humans]]\nkind = "vr"\ngain = 2\n', ["'gain' applies to kind = \"static\" only"]),
    ('[[humans]]\nkind = "static"\n', ["needs 'gain'"]),
    ('[[humans]]\nkind = "static"\ngain = nan\n', ["NaN"]),
    ('[[humans]]\nfamily = "random-passive"\n', ["needs 'count'"]),
    ('[[humans]]\nfamily = "random-passive"\ncount = 0\n', ["1 <= count"]),
    ('[[humans]]\nfamily = "random-active"\ncount = 2\n', ["choose from random-passive"]),
    ('[[humans]]\nfamily = "random-passive"\ncount = 2\nseed = -3\n', ["seed -3"]),
])
def test_bad_humans(tmp_path, humans, needles):
    refused(tmp_path, SWEEP + humans, *needles)


def test_an_empty_list_of_humans(tmp_path):
    refused(tmp_path, "humans = []\n" + SWEEP, "non-empty array")


@pytest.mark.parametrize("model, needle", [
    ("this is not toml", "not valid TOML"),
    ("[transfer_function]\nnum = [[[1.0]]]\nden = [[[1.0, nan]]]\n", "NaN"),
    ("[state_space]\nA = []\nB = []\nC = []\nD = [[1.0]]\nwhat = 1\n", "unknown key(s) what"),
    ("[state_space]\nA = []\nB = []\nC = []\nD = [[1.0]]\n", "needs 2 or 3 ports"),
    ("[state_space]\nA = []\nB = []\nC = []\nD = [[1e400, 0], [0, 1]]\n", "float range"),
])
def test_a_model_file_that_fails_to_load(tmp_path, model, needle):
    write(tmp_path, model, "human.toml")
    message = refused(tmp_path, SWEEP + '[[humans]]\nmodel = "human.toml"\n', needle)
    assert "humans[0]" in message or "human.toml" in message


def test_model_paths_are_relative_to_the_spec(tmp_path):
    sub = tmp_path / "specs"
    sub.mkdir()
    (tmp_path / "h.toml").write_bytes((MODELS / "reconstructed_ks3p0.toml").read_bytes())
    spec = load_campaign_spec(write(sub, SWEEP + '[[humans]]\nmodel = "../h.toml"\n'))
    assert spec.humans[0].path == sub / "../h.toml"


@pytest.mark.parametrize("checks, needle", [
    ('properties = ["lemma2"]', "choose from stealthiness, quasi-average, lemma1"),
    ('properties = "lemma1"', "expected a list"),
    ("convergence_threshold = -0.1", "must be a positive number"),
    ("convergence_threshold = nan", "NaN"),
])
def test_bad_checks(tmp_path, checks, needle):
    refused(tmp_path, SWEEP + HUMANS + "[checks]\n" + checks + "\n", needle)


@pytest.mark.parametrize("text, needle", [
    ("k_s = [", "not valid TOML"),
    ("sweep = 3\n" + HUMANS, "expected a table"),
    (HUMANS, "missing the [sweep] table"),
    ("name = 3\n" + SWEEP + HUMANS, "expected a string"),
])
def test_malformed_files(tmp_path, text, needle):
    refused(tmp_path, text, needle)


def test_missing_spec_file(tmp_path):
    with pytest.raises(VerifyInputError, match="cannot read"):
        load_campaign_spec(tmp_path / "nope.toml")


def _cli(tmp_path, capsys, *args) -> tuple[int, str]:
    code = main(["campaign", *map(str, args)])
    err = capsys.readouterr().err.strip()
    return code, err


@pytest.mark.parametrize("tail", [
    f'[[humans]]\nmodel = "{GOOD_MODEL}"\n[[humans]]\nmodel = "broken.toml"\n',
    f'[[humans]]\nmodel = "{GOOD_MODEL}"\n[checks]\nproperties = ["all"]\n',
])
def test_the_command_refuses_before_any_run(tmp_path, capsys, tail):
    """A bad second human (or a bad check) stops the command before the first run: one
    line on stderr, exit 2, no output folder, no traceback."""
    write(tmp_path, "[state_space]\nA = [[\n", "broken.toml")
    spec = write(tmp_path, SWEEP + tail)
    out = tmp_path / "out"
    code, err = _cli(tmp_path, capsys, spec, "--out", out)
    assert code == 2
    assert err.startswith("verify: error: ") and len(err.splitlines()) == 1
    assert "Traceback" not in err
    assert not out.exists()


@pytest.mark.parametrize("flags, needle", [
    (["--workers", "0"], "--workers must be at least 1"),
    (["--scheduler", "nonsense"], "expected an address such as tcp://"),
    (["--scheduler", "tcp://127.0.0.1:8786", "--workers", "2"], "drop --workers"),
    (["--scheduler", "tcp://127.0.0.1:1"], "cannot connect"),
])
def test_bad_engine_flags(tmp_path, capsys, monkeypatch, flags, needle):
    monkeypatch.setattr("verify.campaign.engine.CONNECT_TIMEOUT", "1s")
    spec = write(tmp_path, SWEEP + HUMANS)
    code, err = _cli(tmp_path, capsys, spec, "--out", tmp_path / "out", *flags)
    assert code == 2 and needle in err and len(err.splitlines()) == 1
    assert not (tmp_path / "out" / "results").exists()


def test_an_existing_store_needs_resume(tmp_path, capsys):
    from verify.campaign.store import ResultStore

    spec = write(tmp_path, SWEEP + HUMANS)
    out = tmp_path / "out"
    ResultStore(out / "results").append([{"key": "earlier", "k_s": 1.0}])
    code, err = _cli(tmp_path, capsys, spec, "--out", out)
    assert code == 2 and "pass --resume" in err and "1 rows (0 of this campaign)" in err


def test_nothing_is_evaluated(tmp_path):
    """Text where a number belongs is refused, never run as code."""
    marker = tmp_path / "pwned"
    text = SWEEP.replace("seconds = 1", f'seconds = "__import__(\'pathlib\').Path(\'{marker}\')'
                                        '.touch()"') + HUMANS
    refused(tmp_path, text, "expected a real number, got str")
    assert not marker.exists()
    assert math.isfinite(load_campaign_spec(write(tmp_path, SWEEP + HUMANS)).seconds[0])


# ------------------------------------------------------------------ hostile: model paths


def _model_spec(tmp_path, target: str) -> Path:
    return write(tmp_path, SWEEP + f'[[humans]]\nmodel = "{GOOD_MODEL}"\n'
                 f'[[humans]]\nmodel = "{target}"\n')


def test_a_fifo_as_model_path_is_refused_at_once(tmp_path):
    import os

    os.mkfifo(tmp_path / "pipe.toml")  # opening it for reading would block forever
    refused(tmp_path, _model_spec(tmp_path, "pipe.toml").read_text(),
            "spec.toml: humans[1].model: model file", "pipe.toml: is a FIFO")


def test_dev_zero_as_model_path_is_refused_without_reading(tmp_path):
    refused(tmp_path, _model_spec(tmp_path, "/dev/zero").read_text(),
            "humans[1].model", "/dev/zero: is a device, not a regular file")
    (tmp_path / "zero.toml").symlink_to("/dev/zero")
    refused(tmp_path, _model_spec(tmp_path, "zero.toml").read_text(), "zero.toml: is a device")


def test_a_directory_and_a_huge_file_as_model_path(tmp_path):
    from verify.inputs.campaign_spec import MAX_MODEL_BYTES

    (tmp_path / "folder.toml").mkdir()
    refused(tmp_path, _model_spec(tmp_path, "folder.toml").read_text(), "is a directory")
    with open(tmp_path / "huge.toml", "wb") as handle:  # sparse: no disk, no memory
        handle.truncate(MAX_MODEL_BYTES + 1)
    refused(tmp_path, _model_spec(tmp_path, "huge.toml").read_text(), "humans[1].model",
            "huge.toml: the file has 16.0 MiB, above the limit of 16.0 MiB")


def test_the_command_refuses_a_fifo_before_any_run(tmp_path, capsys):
    import os

    os.mkfifo(tmp_path / "pipe.toml")
    out = tmp_path / "out"
    code, err = _cli(tmp_path, capsys, _model_spec(tmp_path, "pipe.toml"), "--out", out)
    assert code == 2 and len(err.splitlines()) == 1 and "is a FIFO" in err
    assert not out.exists()


@pytest.mark.parametrize("model, needle", [
    ("[state_space]\nA = [[\n", "not valid TOML"),
    ("[state_space]\nA = [[-1e99999999]]\nB = [[1]]\nC = [[1]]\nD = [[1]]\n",
     "exponent beyond +-4300"),
    ('[transfer_function]\nnum = [[[1]]]\nden = [[[1, 1]]]\n', "needs 2 or 3 ports"),
    ("nonsense = 1\n[state_space]\nA = []\nB = []\nC = []\nD = [[1, 0], [0, 1]]\n",
     "unknown"),
])
def test_model_errors_name_the_spec_and_the_entry(tmp_path, model, needle):
    write(tmp_path, model, "human.toml")
    message = refused(tmp_path, _model_spec(tmp_path, "human.toml").read_text(), needle)
    assert message.startswith(f"{tmp_path / 'spec.toml'}: humans[1].model: ")
    assert "human.toml" in message


# ------------------------------------------------------------------ hostile: numbers shown


@pytest.mark.parametrize("sweep, shown", [
    ("k_s = -1.0", "got -1.0;"),
    ("k_s = [2.0, -1.50]", "k_s[1] must be a positive number, got -1.50;"),
    ("k_s = 0.0", "got 0.0;"),
    ("k_s = {from = -1, to = 2, step = 0.5}", "k_s[0] must be a positive number, got -1;"),
    ("k_s = {from = -0.5, to = 2, step = 0.5}", "k_s[0] must be a positive number, got -0.5;"),
    ("k_s = {from = 1, to = 2, step = -1.0}", "step must be > 0, got -1.0"),
    ("k_s = {from = 1, to = 0.50, step = 0.5}", "to = 0.50 is below from = 1"),
    ("k_s = 2.0\nseconds = -2.5", "seconds must be a positive number, got -2.5;"),
])
def test_numbers_appear_as_written(tmp_path, sweep, shown):
    text = SWEEP.replace("k_s = [2.0, 3.0]", sweep)
    if "seconds = -2.5" in sweep:
        text = text.replace("seconds = 1\n", "")
    message = refused(tmp_path, text + HUMANS, shown)
    assert "Fraction(" not in message and "mpq(" not in message


@pytest.mark.parametrize("sweep, needles", [
    ("seconds = 1e300", ["seconds = 1e300 with step", "is 1.2e+302 steps; at most 2000000"]),
    ('seconds = 30\nstep = 1e-300', ["step = 1e-300 is 3e+301 steps"]),
])
def test_huge_step_counts_are_short(tmp_path, sweep, needles):
    message = refused(tmp_path, SWEEP.replace("seconds = 1\n", sweep + "\n") + HUMANS,
                      *needles)
    assert len(message) < 300 and not any(c * 30 in message for c in "0123456789")


def test_k_s_1e300_gets_the_real_reason(tmp_path):
    """1e300 is finite and positive; what is wrong is that no step can resolve the loop
    (not the directions cancelling, which a run at that gain reported before)."""
    message = refused(tmp_path, SWEEP.replace("k_s = [2.0, 3.0]", "k_s = [2.0, 1e300]")
                      + HUMANS, "k_s = 1e300 is a valid gain", "k_s * seconds = 1e+300 steps",
                      "lower k_s or the run length")
    assert "must be a positive number" not in message and "cancel" not in message
    # a large gain a run can resolve is accepted: 60 000 * 30 s = 1.8e6 steps of 1/k_s
    big = load_campaign_spec(write(tmp_path, SWEEP.replace("k_s = [2.0, 3.0]", "k_s = 60000")
                                   .replace("seconds = 1", "seconds = 30") + HUMANS, "ok.toml"))
    assert big.k_s == (60000.0,)


@pytest.mark.parametrize("sweep, needle", [
    ("k_s = {from = 1, to = 1e300, step = 1}", "the range has 1e+300 values; at most 100000"),
    ("k_s = {from = 1, to = 1e100, count = 2}\nseconds = 1", "k_s = 1e100 is a valid gain"),
])
def test_huge_counts_in_ranges_are_short(tmp_path, sweep, needle):
    text = SWEEP.replace("k_s = [2.0, 3.0]", sweep.split("\n")[0])
    message = refused(tmp_path, text + HUMANS, needle)
    assert len(message) < 400 and not any(c * 30 in message for c in "0123456789")


def test_a_huge_run_count_is_short(tmp_path):
    text = """[sweep]
k_s = {from = 1, to = 100, count = 1000}
n = {from = 1, count = 1000}
seeds = {from = 0, count = 1000}
reference = ["constant", "switching"]
seconds = 1
""" + HUMANS
    message = refused(tmp_path, text, "the sweep has 2e+09 runs; at most 1000000")
    assert "2000000000" not in message


def test_long_computed_values_are_shown_short(tmp_path):
    text = SWEEP.replace("k_s = [2.0, 3.0]", "k_s = {from = -1e100, to = 1, count = 2}")
    message = refused(tmp_path, text + HUMANS, "k_s[0] must be a positive number, got -1e+100")
    assert "0" * 30 not in message


@pytest.mark.parametrize("sweep, needle", [
    ("seconds = 1e308\nstep = 1e-10", "is more than 1.8e+308 steps"),
    ("seconds = 1e290\nstep = 1e-10", "is 1e+300 steps"),
])
def test_step_counts_beyond_the_float_range(tmp_path, sweep, needle):
    message = refused(tmp_path, SWEEP.replace("seconds = 1\n", sweep + "\n") + HUMANS, needle)
    assert "OverflowError" not in message


def test_a_positive_number_that_rounds_to_zero_is_called_what_it_is(tmp_path):
    text = SWEEP.replace("k_s = [2.0, 3.0]", "k_s = 1e-400")
    message = refused(tmp_path, text + HUMANS, "sweep.k_s: 1e-400 is too small for a float")
    assert "must be a positive number" not in message
