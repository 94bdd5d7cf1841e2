"""Forged SOS certificates of user claims are refused by `verify certificates check`.

Classes: a changed statement; mislabelled multipliers (-1 and w called plain SOS); a key
matching neither the file name nor the content; malformed or unknown fields (source);
a certificate without its step.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from verify.cli import main
from verify.proof import Context, Derivation, by_sos, certificate_store, check, tr
from verify.proof.budget import Budget
from verify.proof.falsify import SearchSettings
from verify.sos.certificate import file_name

SMALL = SearchSettings(samples=16, hypothesis_examples=3, ipopt_starts=1, seed=5)


@pytest.fixture(scope="module")
def honest(tmp_path_factory) -> dict:
    store = tmp_path_factory.mktemp("store")
    ctx = Context("user")
    R = ctx.rotation("R")
    d = Derivation("tr", tr(R), ctx).le(3, by_sos())
    # in a forked step (budget=...): the SOS solver's thread pool never starts in the
    # test process, whose later forks would otherwise inherit a pool with no threads
    with certificate_store(store, source="file:mine.py"):
        assert check(d, SMALL, budget=Budget(120, 2**31)).verdict == "verified"
    (path,) = store.glob("sos-*.json")
    return json.loads(path.read_text())


def _write(tmp_path: Path, data: dict, name: str | None = None) -> Path:
    path = tmp_path / (name or file_name(data["claim"]["key"]))
    path.write_text(json.dumps(data, sort_keys=True, indent=1))
    return path


def test_the_honest_certificate_is_valid(tmp_path, honest, capsys):
    assert main(["certificates", "check", str(_write(tmp_path, honest))]) == 0
    assert "bound to its step" in capsys.readouterr().out


def _plain_block(data: dict, poly: list) -> dict:
    n = len(data["variables"])
    return {"grounds": "1 (plain SOS)", "multiplier": [[poly]],
            "basis": [[0] * n], "gram": [["1"]]}


@pytest.mark.parametrize("forge", [
    # the statement changed to tr(R) <= 2
    lambda d: d["claim"].update(statement="tr(R) <= 2"),
    # a block whose multiplier is -1, labelled plain SOS
    lambda d: d["blocks"].append(_plain_block(d, [[[0] * len(d["variables"]), "-1"]])),
    # a block whose multiplier is the parameter w, labelled plain SOS
    lambda d: d["blocks"].append(_plain_block(
        d, [[[1] + [0] * (len(d["variables"]) - 1), "1"]])),
    # the step changed to tr(R) <= 2 with its statement (numerator no longer matches)
    lambda d: (d["claim"].update(statement="tr(R) <= 2"),
               d["step"]["nodes"].__setitem__(
                   next(i for i, n in enumerate(d["step"]["nodes"]) if n["op"] == "const"),
                   {"op": "const", "shape": "scalar", "value": ["2", "1"], "args": [],
                    "label": None})),
    # no step: nothing to bind the statement, key and multipliers to
    lambda d: d.pop("step"),
])
def test_forged_certificates_are_refused(tmp_path, honest, forge, capsys):
    data = json.loads(json.dumps(honest))
    forge(data)
    assert main(["certificates", "check", str(_write(tmp_path, data))]) != 0
    out = capsys.readouterr()
    assert "INVALID" in out.out or "verify:" in out.err


@pytest.mark.parametrize("forge", [
    lambda d: d["claim"].update(key="0" * 64),                    # key of nothing
    lambda d: d["claim"].update(source={"file": "x"}),            # malformed source
    lambda d: d["claim"].update(source="file:../../etc/passwd"),  # not a file name
    lambda d: d.update(comment="trust me"),                       # unknown field
    lambda d: d["blocks"][0].update(extra=1),                     # unknown block field
])
def test_malformed_or_unbound_fields_are_refused(tmp_path, honest, forge):
    data = json.loads(json.dumps(honest))
    forge(data)
    name = file_name(honest["claim"]["key"])  # the file keeps its honest name
    assert main(["certificates", "check", str(_write(tmp_path, data, name))]) != 0


def test_a_file_name_that_is_not_the_key_is_refused(tmp_path, honest, capsys):
    assert main(["certificates", "check",
                 str(_write(tmp_path, honest, "sos-00000000000000000000.json"))]) != 0
    assert "file name" in capsys.readouterr().out


def test_a_factor_raised_to_the_power_64_is_refused_before_the_work(tmp_path, honest, capsys):
    """The issue's 17 KB certificate: a many-term factor to the 64th power (2.7 GB)."""
    data = json.loads(json.dumps(honest))
    n = len(data["variables"])
    square_terms = [[[2 if j == i else 0 for j in range(n)], "1"] for i in range(n)]
    data["factors"] = [{"polynomial": [[[0] * n, "1"], *square_terms], "power": 64}]
    assert main(["certificates", "check", str(_write(tmp_path, data))]) != 0
    assert "too large" in capsys.readouterr().out


def test_certificates_check_budget_options_are_validated(tmp_path, honest, capsys):
    path = _write(tmp_path, honest)
    assert main(["certificates", "check", str(path), "--budget-seconds", "-1"]) == 2
    assert main(["certificates", "check", str(path), "--budget-seconds", "nan"]) == 2
    assert main(["certificates", "check", str(path), "--budget-memory", "0.5"]) == 0


def _negate(poly: list) -> list:
    return [[m, c[1:] if c.startswith("-") else "-" + c] for m, c in poly]


def _false_claim(honest: dict, grounds: str, keep_step: bool) -> dict:
    """tr(R) >= 3 (false): a consistent identity numerator = (-1) * SOS, the block's
    multiplier -1 labelled ``grounds``; optionally with the step changed to match."""
    data = json.loads(json.dumps(honest))
    n = len(data["variables"])
    data["claim"]["statement"] = "tr(R) >= 3"
    data["numerator"] = _negate(data["numerator"])
    data["target"] = _negate(data["target"])
    data["blocks"][0]["grounds"] = grounds
    data["blocks"][0]["multiplier"] = [[[[[0] * n, "-1"]]]]
    if keep_step:
        data["step"]["derivations"][0]["steps"][0]["relation"] = ">="
    else:
        data.pop("step")
    return data


@pytest.mark.parametrize("grounds", ["1 (plain SOS)", "k > 0 (declared)"])
@pytest.mark.parametrize("keep_step", [True, False])
def test_a_consistent_certificate_of_a_false_claim_is_refused(tmp_path, honest, grounds,
                                                             keep_step, capsys):
    """The identity holds exactly and the Gram matrix is PSD: only the multiplier -1,
    not what its label says and not one the step allows, makes it false."""
    from verify.sos.certificate import Parsed, _identity

    data = _false_claim(honest, grounds, keep_step)
    assert _identity(Parsed(data)).ok  # the forgery is internally consistent
    assert main(["certificates", "check", str(_write(tmp_path, data))]) == 1
    out = capsys.readouterr().out
    assert "INVALID" in out and ("multiplier" in out or "step" in out or "key" in out)


def test_an_edited_label_cannot_change_what_a_certificate_is_reported_as(tmp_path, honest,
                                                                         capsys):
    """The constant 3 of tr(R) <= 3 labelled "2" and the statement edited to match: the
    key (numerator, multipliers) is unchanged, so the certificate is still one of
    tr(R) <= 3; its written statement is not that, so it is refused as edited (exit 1),
    never accepted with a remark."""
    data = json.loads(json.dumps(honest))
    nodes = data["step"]["nodes"]
    k = next(i for i, n in enumerate(nodes) if n["op"] == "const" and n["value"] == ["3", "1"])
    nodes[k]["label"] = "2"
    data["claim"]["statement"] = "tr(R) <= 2"
    assert main(["certificates", "check", str(_write(tmp_path, data))]) == 1
    out = capsys.readouterr().out
    assert not any(line.startswith("ok") for line in out.splitlines())
    (line,) = [line for line in out.splitlines() if line.startswith("INVALID")]
    assert "statement edited" in line and "tr(R) <= 3 for all R ∈ SO(3)" in line


def test_a_certificate_statement_reaches_the_terminal_escaped(tmp_path, honest, capsys):
    data = json.loads(json.dumps(honest))
    data["claim"]["statement"] = "\x1b[2J\x1b[Hok tr(R) <= 2\r\u202e"
    assert main(["certificates", "check", str(_write(tmp_path, data))]) != 0
    out = capsys.readouterr().out
    assert "\x1b" not in out and "\r" not in out and "\u202e" not in out
    assert "\\x1b[2J" in out or "INVALID" in out


def test_a_step_resting_on_declared_signs_says_so(tmp_path, capsys):
    """x y >= 0 by SOS with x, y declared positive: the multipliers are those signs, so
    the printed statement and the JSON name them (they were printed with no assumption)."""
    ctx = Context("user")
    x, y = ctx.scalar("x", positive=True), ctx.scalar("y", positive=True)
    d = Derivation("xy", x * y, ctx).ge(0, by_sos())
    from verify.proof.wire import encode

    path = tmp_path / "xy.json"
    path.write_text(json.dumps(encode([d])))
    out_json = tmp_path / "out.json"
    assert main(["check", str(path), "--quick", "--certificates", str(tmp_path / "c"),
                 "--json", str(out_json)]) == 0
    out = capsys.readouterr().out
    assert "x y >= 0 assuming x > 0 (declared); y > 0 (declared)" in out
    (result,) = json.loads(out_json.read_text())
    assert result["declarations"] == ["x > 0 (declared)", "y > 0 (declared)"]
    assert result["steps"][0]["declarations"] == result["declarations"]
