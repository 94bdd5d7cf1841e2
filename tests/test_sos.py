"""by_sos(): SOS certificates found, rounded, checked exactly, stored and re-checked.

Covers: the five-plus own inequalities over SO(3) (verified), a premise k > 0 and an
assumption as multipliers, lambda_min through the spectral multiplier, a false
inequality (refuted with an exact counterexample, never verified), a true inequality
that is not SOS (Motzkin: inconclusive, never verified), the certificate JSON (bytes
reproducible, re-checked by `verify certificates check`), tampered and hostile
certificates (rejected), and the SOS twins of the paper's Lemma 1 steps.
"""

from __future__ import annotations

import copy
import json
from pathlib import Path

import pytest

from verify.certificates.sos_kind import check_sos_certificate_data
from verify.cli import main
from verify.proof import (
    I3,
    Context,
    Derivation,
    ProofSyntaxError,
    by_sos,
    certificate_store,
    check,
    dot,
    lambda_min,
    sk,
    sym,
    tr,
    vee,
)
from verify.proof.falsify import SearchSettings
from verify.sos import poly as pl
from verify.sos.certificate import check_bound
from verify.sos.check import check_identity_and_psd
from verify.sos.program import Block, scalar_multiplier

FAST = SearchSettings(samples=48, hypothesis_examples=8, ipopt_starts=1, seed=3)
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "sos_inequalities.py"


def _ctx():
    ctx = Context("sos tests")
    return ctx, ctx.rotation("R"), ctx.rotation("R1"), ctx.rotation("R2")


def _one(d: Derivation, store: Path | None = None):
    with certificate_store(store):
        return check(d, FAST).steps[0]


OWN = {
    "tr R <= 3": lambda ctx, R, R1, R2: Derivation("a", tr(R), ctx).le(3, by_sos()),
    "|sk(R)^v|^2 <= 3 - tr R": lambda ctx, R, R1, R2: Derivation(
        "b", dot(vee(sk(R)), vee(sk(R))), ctx).le(3 - tr(R), by_sos()),
    "tr(R1^T R2) >= -1": lambda ctx, R, R1, R2: Derivation(
        "c", tr(R1.T * R2), ctx).ge(-1, by_sos()),
    "k tr(I - R1 R2) >= 0, k > 0": lambda ctx, R, R1, R2: Derivation(
        "d", ctx.scalar("k", positive=True) * tr(I3 - R1 * R2), ctx).ge(0, by_sos()),
    "(3 - tr R)(1 + tr R) >= 0": lambda ctx, R, R1, R2: Derivation(
        "e", (3 - tr(R)) * (1 + tr(R)), ctx).ge(0, by_sos()),
}


@pytest.mark.parametrize("name", sorted(OWN))
def test_own_inequalities_are_verified_by_exact_certificates(name):
    step = _one(OWN[name](*_ctx()))
    assert step.verdict == "verified", step.exact
    assert "exact identity" in step.exact


def test_the_premise_k_positive_is_needed():
    ctx, R, _, _ = _ctx()
    k = ctx.scalar("k")  # not declared positive: k (3 - tr R) >= 0 is false
    step = _one(Derivation("k free", k * (3 - tr(R)), ctx).ge(0, by_sos()))
    assert step.verdict == "refuted"
    assert step.counterexample is not None


def test_an_assumption_enters_as_a_multiplier_only_when_named():
    ctx, R, _, _ = _ctx()
    c = ctx.scalar("c")
    sign = ctx.assume("c ≥ 0", c, "nonneg")
    used = _one(Derivation("with", c * (1 + tr(R)), ctx).ge(0, by_sos(sign)))
    assert used.verdict == "verified", used.exact
    assert any("c ≥ 0" in a for a in used.assumptions)
    unused = _one(Derivation("without", c * (1 + tr(R)), ctx).ge(0, by_sos()))
    assert unused.verdict != "verified"


def test_lambda_min_through_the_spectral_multiplier():
    ctx, R, _, _ = _ctx()
    A = ctx.symmetric("A")
    d = Derivation("trace bound", tr(A * sym(I3 - R)), ctx).ge(
        lambda_min(A) * tr(I3 - R), by_sos())
    step = _one(d)
    assert step.verdict == "verified", step.exact


def test_lambda_min_of_a_non_symmetric_argument_gets_no_spectral_multiplier():
    ctx, R, _, _ = _ctx()
    M = ctx.matrix("M")
    d = Derivation("no spectral", tr(M * sym(I3 - R)), ctx).ge(
        lambda_min(M) * tr(I3 - R), by_sos())
    assert _one(d).verdict != "verified"


def test_false_inequality_is_refused_with_an_exact_counterexample():
    ctx, R, _, _ = _ctx()
    step = _one(Derivation("false", tr(R), ctx).ge(0, by_sos()))
    assert step.verdict == "refuted"
    assert step.exact.startswith("no SOS certificate")
    assert step.counterexample is not None


def test_nonnegative_but_not_sos_is_inconclusive_never_verified():
    ctx = Context("Motzkin")
    x, y = ctx.scalar("x"), ctx.scalar("y")
    motzkin = x**4 * y**2 + x**2 * y**4 - 3 * x**2 * y**2 + 1
    step = _one(Derivation("motzkin", motzkin, ctx).ge(0, by_sos()))
    assert step.verdict == "inconclusive"
    assert step.counterexample is None


def test_by_sos_arguments_are_validated():
    ctx, R, _, _ = _ctx()
    with pytest.raises(ProofSyntaxError, match=r"ctx\.assume"):
        by_sos(R)
    for bad in (0, 2.5, True, 99):
        with pytest.raises(ProofSyntaxError, match="degree"):
            by_sos(degree=bad)
    step = _one(Derivation("eq", tr(R), ctx).equals(tr(R.T), by_sos()))
    assert step.verdict != "verified"


# -- certificates ------------------------------------------------------------------------
@pytest.fixture(scope="module")
def stored(tmp_path_factory):
    """One certificate written by a by_sos step, and the step that made it."""
    directory = tmp_path_factory.mktemp("sos")
    ctx, R, _, _ = _ctx()
    d = Derivation("axis", dot(vee(sk(R)), vee(sk(R))), ctx).le(3 - tr(R), by_sos())
    step = _one(d, directory)
    assert step.verdict == "verified", step.exact
    (path,) = sorted(directory.glob("sos-*.json"))
    return directory, path, d


def test_certificate_is_reused_and_reproducible(stored, monkeypatch):
    import verify.sos.prove

    directory, path, d = stored
    before = path.read_bytes()

    def no_solver(*args, **kwargs):
        raise AssertionError("the stored certificate should have been reused")

    monkeypatch.setattr(verify.sos.prove, "find_certificate", no_solver)
    again = _one(d, directory)
    assert again.verdict == "verified", again.exact
    assert path.name in again.exact
    assert path.read_bytes() == before
    data = json.loads(before)
    assert data["schema"] == "verify-sos-certificate/1"
    assert check_sos_certificate_data(data, path).ok


def test_a_tampered_stored_certificate_is_not_reused(stored, tmp_path):
    _, path, d = stored
    data = _tampered(json.loads(path.read_text()), "gram entry")
    copy_dir = tmp_path / "store"
    copy_dir.mkdir()
    (copy_dir / path.name).write_text(json.dumps(data))
    step = _one(d, copy_dir)  # rejected, so searched again and rewritten
    assert step.verdict == "verified"
    assert check_sos_certificate_data(json.loads((copy_dir / path.name).read_text()),
                                      path).ok


def test_verify_certificates_check_accepts_and_rejects(stored, tmp_path, capsys):
    _, path, _ = stored
    assert main(["certificates", "check", str(path)]) == 0
    data = json.loads(path.read_text())
    gram = data["blocks"][0]["gram"]
    gram[0][0] = str(pl.rational(gram[0][0], "x") + 1)
    bad = tmp_path / "tampered.json"
    bad.write_text(json.dumps(data))
    assert main(["certificates", "check", str(bad)]) == 1
    assert "INVALID" in capsys.readouterr().out


def _tampered(data: dict, how: str) -> dict:
    data = copy.deepcopy(data)
    block = data["blocks"][0]
    if how == "gram entry":
        block["gram"][0][0] = str(pl.rational(block["gram"][0][0], "x") + 1)
    elif how == "asymmetric gram":
        block["gram"][0][1] = str(pl.rational(block["gram"][0][1], "x") + 1)
    elif how == "numerator":
        data["numerator"][0][1] = str(pl.rational(data["numerator"][0][1], "x") * 2)
    elif how == "target and numerator scaled":
        data["numerator"] = [[m, str(pl.rational(c, "x") * 2)] for m, c in data["numerator"]]
        data["target"] = [[m, str(pl.rational(c, "x") * 2)] for m, c in data["target"]]
    elif how == "negative gram":
        n = len(block["gram"])
        block["gram"] = [["-1" if r == s else "0" for s in range(n)] for r in range(n)]
    elif how == "factor":
        data["factors"] = [{"polynomial": [[[0] * len(data["variables"]), "-1"]], "power": 1}]
    return data


@pytest.mark.parametrize("how", ["gram entry", "asymmetric gram", "numerator",
                                 "target and numerator scaled", "negative gram", "factor"])
def test_tampered_certificates_are_rejected(stored, how):
    _, path, _ = stored
    data = _tampered(json.loads(path.read_text()), how)
    assert not check_sos_certificate_data(data, path).ok


def test_a_certificate_is_bound_to_its_step(stored):
    from verify.proof.checker import step_problem
    from verify.proof.sos_step import step_program

    _, path, _ = stored
    data = json.loads(path.read_text())
    ctx, R, _, _ = _ctx()
    other = Derivation("other", tr(R), ctx).le(3, by_sos())
    sp = step_program(step_problem(other, other.steps[0]), other.steps[0].because)
    assert not check_bound(data, sp).ok
    # a multiplier the step does not allow (a made-up 'assumption') is refused
    ctx2, R2, _, _ = _ctx()
    same = Derivation("axis", dot(vee(sk(R2)), vee(sk(R2))), ctx2).le(3 - tr(R2), by_sos())
    sp2 = step_program(step_problem(same, same.steps[0]), same.steps[0].because)
    assert check_bound(data, sp2).ok
    forged = copy.deepcopy(data)
    forged["blocks"][0]["grounds"] = "assumed: anything I like"
    assert not check_bound(forged, sp2).ok


CHECK_ALONE = """
import json, pickle, sys
from pathlib import Path

from verify.sos.certificate import check_against_program, check_form

path, program = Path(sys.argv[1]), Path(sys.argv[2])
data, sp = json.loads(path.read_text()), pickle.loads(program.read_bytes())
assert check_form(data, path) == ""
result = check_against_program(data, sp, "bound to the given program")
assert result.ok and result.reason.startswith(sp.claim + ": exact identity"), result
assert result.reason.endswith("; bound to the given program"), result
forged = json.loads(path.read_text())
forged["claim"]["statement"] = "1 >= 0"
assert not check_against_program(forged, sp, "").ok
forged = json.loads(path.read_text())
forged["claim"]["key"] = "0" * 64
assert not check_against_program(forged, sp, "").ok
loaded = sorted(m for m in sys.modules if m.startswith(("verify.proof", "verify.paper_proofs")))
assert loaded == [], loaded
print("checked alone")
"""


def test_the_sos_library_checks_a_certificate_against_a_given_program_alone(tmp_path):
    """verify.sos.certificate decides a stored certificate from its data and the program
    of its claim, with neither the proof checker nor the paper's proofs imported."""
    import os
    import pickle
    import subprocess
    import sys

    from verify.paper_proofs.sos_proofs import program_for_key

    root = Path(__file__).resolve().parents[1]
    path = root / "certificates" / "sos-ca4209e02297c7d04166.json"
    data = json.loads(path.read_text())
    sp = program_for_key(data["claim"]["key"], data["claim"]["statement"])
    assert sp is not None and type(sp).__module__ == "verify.sos.program"
    program = tmp_path / "program.pickle"
    program.write_bytes(pickle.dumps(sp))
    env = {**os.environ, "PYTHONPATH": str(root)}
    done = subprocess.run([sys.executable, "-c", CHECK_ALONE, str(path), str(program)],
                          capture_output=True, text=True, env=env, cwd=tmp_path,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "checked alone"


@pytest.mark.parametrize("payload", [
    [], {"schema": "verify-sos-certificate/1"},
    {"schema": "verify-sos-certificate/1", "variables": ["x"], "claim": {"key": "k",
     "statement": "s"}, "numerator": [[[1], "0.5"]], "target": [], "factors": [],
     "blocks": []},
    {"schema": "verify-sos-certificate/1", "variables": ["x"], "claim": {"key": "k",
     "statement": "s"}, "numerator": [[[10**6], "1"]], "target": [], "factors": [],
     "blocks": []},
    {"schema": "verify-sos-certificate/1", "variables": ["x"], "claim": {"key": "k",
     "statement": "s"}, "numerator": [[[1], "__import__('os')"]], "target": [],
     "factors": [], "blocks": []},
])
def test_hostile_certificate_files_are_one_line_errors(payload, tmp_path, capsys):
    bad = tmp_path / "hostile.json"
    bad.write_text(json.dumps(payload))
    assert main(["certificates", "check", str(bad)]) in (1, 2)
    err = capsys.readouterr().err
    assert "Traceback" not in err


def test_exact_check_rejects_an_indefinite_gram():
    # x^2 + y^2 = z^T Q z with Q = [[1, 2], [2, 1]]? the identity fails; with a valid
    # identity but an indefinite Q (x^2 - y^2 + 2 y^2) the PSD test must fail
    one = scalar_multiplier("1", pl.constant(1, 2))
    block = Block(one, ((1, 0), (0, 1)))
    target = {(2, 0): 1, (0, 2): 1}
    from gmpy2 import mpq
    good = [[mpq(1), mpq(0)], [mpq(0), mpq(1)]]
    assert check_identity_and_psd(target, [block], [good]).ok
    target2 = {(2, 0): 1, (1, 1): 4, (0, 2): 1}
    indefinite = [[mpq(1), mpq(2)], [mpq(2), mpq(1)]]
    result = check_identity_and_psd(target2, [block], [indefinite])
    assert not result.ok and "PSD" in result.reason


def test_example_file_checks(tmp_path, capsys):
    code = main(["check", str(EXAMPLE), "--quick", "--certificates", str(tmp_path)])
    out = capsys.readouterr().out
    assert code == 0, out
    files = sorted(tmp_path.glob("sos-*.json"))
    assert len(files) >= 8
    assert main(["certificates", "check", str(tmp_path)]) == 0


# -- the paper ---------------------------------------------------------------------------
def test_lemma1_inequality_steps_are_reproved_by_sos(tmp_path):
    from verify.paper_proofs.sos_proofs import sos_reproofs
    from verify.sos.certificate import PAPER

    twins = [r for r in sos_reproofs() if r.original.startswith("lemma1.")]
    assert len(twins) == 5
    with certificate_store(tmp_path, PAPER):
        for r in twins:
            result = check(r.derivation, FAST)
            assert result.verdict == "verified", (r.derivation.name, result.steps[0].exact)
    files = sorted(tmp_path.glob("sos-*.json"))
    assert len(files) == 5  # none for the charts' missed points (covered by continuity)
    for f in files:  # bound again to the paper's step, re-derived by name-free key
        assert check_sos_certificate_data(json.loads(f.read_text()), f).ok
    data = json.loads(files[0].read_text())
    data["claim"]["key"] = "0" * 64  # a paper certificate for no step of the paper
    assert not check_sos_certificate_data(data, files[0]).ok
    data = json.loads(files[0].read_text())
    data["blocks"][0]["grounds"] = "assumed: whatever helps"
    assert not check_sos_certificate_data(data, files[0]).ok


@pytest.mark.slow
def test_theorem1_reachable_steps_are_reproved_by_sos():
    from verify.paper_proofs.sos_proofs import OUT_OF_REACH, sos_reproofs

    twins = [r for r in sos_reproofs() if r.original.startswith("thm1.")]
    assert len(twins) == 5
    for r in twins:
        result = check(r.derivation, FAST)
        if r.derivation.name in OUT_OF_REACH:  # refused as too large: never verified
            assert result.verdict == "inconclusive", result.steps[0].exact
            assert "too large" in result.steps[0].exact
        else:
            assert result.verdict == "verified", (r.derivation.name, result.steps[0].exact)


def test_report_marks_steps_proved_by_hand_terms_and_by_sos(tmp_path):
    from verify.claims.catalog import REGISTRY
    from verify.claims.model import CheckContext
    from verify.claims.runner import run_claims
    from verify.report.render import render_markdown

    wanted = ("lemma1.trace-inequality", "lemma1.sos-reproofs")
    claims = [c for c in REGISTRY if c.id in wanted]
    run = run_claims(claims, CheckContext(quick=True, out_dir=tmp_path,
                                          certificates_dir=tmp_path / "certs"))
    text = render_markdown(run)

    def verdicts(name: str) -> list[str]:
        """The verdict cells of one derivation's step table."""
        block = text.split(f"**`{name}`**", 1)[1].split("\n\n", 2)[1]
        return [line.rsplit("|", 2)[1].strip() for line in block.splitlines()
                if line.startswith("| |") and line.rstrip().endswith("** |")]

    assert verdicts("lemma1.trace-inequality-psd") == ["**verified, hand terms + SOS**"]
    assert verdicts("lemma1.trace-inequality-psd.step1-sos") == ["**verified, SOS**"]
    (quoted,) = verdicts("lemma1.trace-inequality-as-quoted")
    assert quoted.endswith("citation**")


def test_an_assumption_on_a_partial_chart_is_not_a_multiplier():
    # 1 + cos θ <= 0 holds only at θ = π, which tan(θ/2) misses: on the chart the
    # assumption's numerator is the constant -2, and -2 * (t²/2) + 1 = 1 - t² would
    # "prove" cos θ >= 0 there. It is false at θ = π, so it must not be verified.
    from verify.proof import cos

    ctx = Context("partial chart")
    theta = ctx.angle("θ")
    at_pi = ctx.assume("1 + cos θ <= 0", -(1 + cos(theta)), "nonneg")
    step = _one(Derivation("cos", cos(theta), ctx).ge(0, by_sos(at_pi)))
    assert step.verdict != "verified", step.exact


def test_rounding_then_exact_correction_lands_on_the_affine_space():
    """Peyrl-Parrilo: a perturbed float Gram, rounded, misses the identity; the exact
    correction restores it and the interior margin keeps the Gram PSD."""
    import numpy as np

    from verify.sos.program import SosProgram
    from verify.sos.prove import blocks_for
    from verify.sos.rounding import correct, round_grams
    from verify.sos.search import solve

    n = 2
    target = {(4, 0): 1, (0, 4): 1, (0, 0): 1, (1, 1): -1}  # x^4 + y^4 + 1 - xy > 0
    one = scalar_multiplier("1", pl.constant(1, n))
    blocks = blocks_for(SosProgram(("x", "y"), target, (one,)), [[0], [1]])
    result = solve(blocks, target)
    assert result.grams is not None
    noisy = [g + 1e-7 * np.random.default_rng(0).standard_normal(g.shape) for g in result.grams]
    noisy = [(g + g.T) / 2 for g in noisy]
    rounded = round_grams(noisy, 10**9)
    assert not check_identity_and_psd(target, blocks, rounded).ok  # misses the identity
    fixed = correct(blocks, rounded, target)
    assert fixed is not None
    assert check_identity_and_psd(target, blocks, fixed).ok
