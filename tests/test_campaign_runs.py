"""Run keys, expansion and drawn humans of a campaign (no simulation)."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from verify.campaign.execute import convergence_time
from verify.campaign.runs import exact_decimal, expand, family_member
from verify.campaign.store import SCHEMA, ResultStore
from verify.inputs.campaign_spec import load_campaign_spec
from verify.passivity.io.model_file import model_from_bytes

MODELS = Path(__file__).resolve().parents[1] / "verify" / "data" / "models"

SPEC = """[sweep]
k_s = [2.0, 3.0]
n = 3
seeds = [0, 1]
seconds = 1
{extra}
[[humans]]
model = "a.toml"
[[humans]]
model = "b.toml"
[[humans]]
kind = "static"
gain = 1.5
{checks}
"""


def spec_at(folder: Path, a: bytes, b: bytes, extra: str = "", checks: str = ""):
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "a.toml").write_bytes(a)
    (folder / "b.toml").write_bytes(b)
    (folder / "spec.toml").write_text(SPEC.format(extra=extra, checks=checks))
    return load_campaign_spec(folder / "spec.toml")


KS3 = (MODELS / "reconstructed_ks3p0.toml").read_bytes()
KS25 = (MODELS / "reconstructed_ks2p5.toml").read_bytes()


def keys(spec) -> list[str]:
    return [r.key for r in expand(spec)]


def test_keys_depend_on_file_contents_not_paths(tmp_path):
    one = keys(spec_at(tmp_path / "one", KS3, KS25))
    moved = keys(spec_at(tmp_path / "elsewhere" / "deeper", KS3, KS25))
    assert one == moved and len(set(one)) == len(one) == 12
    edited = keys(spec_at(tmp_path / "edited", KS3, KS25.replace(b"0.5, 1.0", b"0.5, 1.01")))
    assert edited[:4] == one[:4] and not set(edited[4:8]) & set(one)
    assert edited[8:] == one[8:]


def test_equal_files_are_one_human(tmp_path):
    runs = expand(spec_at(tmp_path, KS3, KS3))
    assert len(runs) == 8  # the second file is the first one again


@pytest.mark.parametrize("extra, checks", [
    ("step = 0.01", ""),
    ("", "[checks]\nproperties = ['lemma1']"),
    ("", "[checks]\nconvergence_threshold = 0.1"),
    ("reference = 'switching'", ""),
])
def test_every_parameter_enters_the_key(tmp_path, extra, checks):
    base = set(keys(spec_at(tmp_path / "base", KS3, KS25)))
    other = set(keys(spec_at(tmp_path / "other", KS3, KS25, extra, checks)))
    assert not base & other


def test_the_simulator_code_enters_the_key(tmp_path, monkeypatch):
    """Rows computed by other simulator code are not resumed as if they were this code's."""
    import verify.campaign.runs as runs

    before = keys(spec_at(tmp_path / "a", KS3, KS25))
    assert runs.code_fingerprint() == runs.code_fingerprint.__wrapped__()
    monkeypatch.setattr(runs, "code_fingerprint", lambda: "another version")
    after = keys(spec_at(tmp_path / "b", KS3, KS25))
    assert not set(before) & set(after)


def test_family_members_are_exact_model_files():
    from verify.sim.random_scenarios import random_passive_human

    for seed in range(6):
        human = family_member("random-passive", seed)
        drawn = random_passive_human(np.random.default_rng(seed))
        model = model_from_bytes(human.text, "member")
        D = getattr(drawn, "D", getattr(drawn, "K", None))
        # the file denotes exactly the drawn floats: exact entries are their dyadic values
        for row_file, row_drawn in zip(model.exact.D, np.atleast_2d(D), strict=True):
            for q, x in zip(row_file, row_drawn, strict=True):
                assert Fraction(int(q.numerator), int(q.denominator)) == Fraction(float(x))
        assert np.array_equal(model.D, D)
        if hasattr(drawn, "A") and drawn.A.size:
            assert np.array_equal(model.A, drawn.A) and np.array_equal(model.C, drawn.C)
        assert family_member("random-passive", seed).sha256 == human.sha256  # same draw


@pytest.mark.parametrize("x", [0.1, -2.5e-300, 1e300, 3.0, -0.0, 5e-324])
def test_exact_decimal_reads_back_exactly(x):
    text = exact_decimal(x)
    assert Fraction(text) == Fraction(x)


def test_convergence_time_definition():
    t = np.arange(6.0)
    assert convergence_time(t, np.array([1, 0.01, 1, 0.01, 0.01, 0.01]), 0.05) == 3.0
    assert convergence_time(t, np.array([0.01] * 6), 0.05) == 0.0
    assert convergence_time(t, np.array([1, 0.01, 0.01, 0.01, 0.01, 1]), 0.05) is None
    assert convergence_time(t, np.array([1, 0.01, np.nan, 0.01, 0.01, 0.01]), 0.05) == 3.0


def test_store_is_idempotent_per_key(tmp_path):
    store = ResultStore(tmp_path / "results")
    assert store.append([{"key": "a", "k_s": 1.0}, {"key": "b", "k_s": 2.0},
                         {"key": "a", "k_s": 9.0}]) == 2
    assert store.append([{"key": "b", "k_s": 3.0}]) == 0
    assert ResultStore(store.folder).append([{"key": "a"}, {"key": "c"}]) == 1
    rows = ResultStore(store.folder).rows()
    assert sorted(r["key"] for r in rows) == ["a", "b", "c"] and store.count() == 3
    assert {r["key"]: r["k_s"] for r in rows}["a"] == 1.0
    assert len(store.parts()) == 2 and not list(store.folder.glob(".*"))  # no temp left
    assert ResultStore(store.folder).rows(["c", "a"])[0]["key"] == "c"
    assert set(rows[0]) == set(SCHEMA.names)


def test_rows_have_the_store_schema():
    from verify.campaign.execute import OUTCOME_COLUMNS, parameters
    from verify.campaign.runs import Human, Run

    run = Run("k", Human("vr", "VR operator"), 2.0, 3, 0, "zero", "constant", 1.0, 0.1,
              ("lemma1",), 0.05)
    columns = [*parameters(run), *OUTCOME_COLUMNS]
    assert sorted(columns) == sorted(SCHEMA.names) and len(set(columns)) == len(columns)


class _Stream:
    def __init__(self, tty: bool) -> None:
        self.tty, self.text = tty, ""

    def isatty(self) -> bool:
        return self.tty

    def write(self, s: str) -> int:
        self.text += s
        return len(s)

    def flush(self) -> None:
        pass


def test_progress_line():
    from verify.campaign.progress import CampaignProgress, clock

    assert (clock(7.4), clock(123), clock(3723)) == ("7s", "2m03s", "1h02m03s")
    tty = _Stream(True)
    bar = CampaignProgress(48, 8, stream=tty)
    assert "estimating" in bar.line(bar.start)
    bar.update(4, 1, force=True)
    line = bar.line(bar.start + 40.0)  # 4 runs in 40 s: 36 left, 10 s each
    assert line.startswith("campaign: 12/48 runs, 8 stored earlier, 1 raised, 40s elapsed")
    assert line.endswith("~6m00s left")
    bar.close()
    assert tty.text.startswith("\r") and tty.text.endswith("\n")
    quiet, piped = _Stream(True), _Stream(False)
    for stream, enabled in ((quiet, False), (piped, True)):
        bar = CampaignProgress(5, 0, stream=stream, enabled=enabled)
        bar.update(5, force=True)
        bar.close()
        assert stream.text == ""


def test_a_damaged_store_is_one_line(tmp_path):
    from verify.errors import VerifyInputError

    store = ResultStore(tmp_path / "results")
    store.append([{"key": "a"}])
    (store.folder / ".part-0-x.parquet.tmp").write_bytes(b"half a file")  # a crashed write
    assert ResultStore(store.folder).keys() == {"a"}  # temporary files are not parts
    (store.folder / "part-9-broken.parquet").write_bytes(b"not parquet")
    with pytest.raises(VerifyInputError, match="not a readable part of a campaign store"):
        ResultStore(store.folder).keys()
    (tmp_path / "file").write_text("")
    with pytest.raises(VerifyInputError, match="must be a folder"):
        ResultStore(tmp_path / "file")
