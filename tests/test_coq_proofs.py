"""The paper's proofs exported to Coq: statements, determinism, and coqc as the judge.

Tests that run ``coqc`` skip cleanly where it is not installed. Tampering tests change
one thing in an exported unit (a statement, a hypothesis, a coefficient) and require
``coqc`` to refuse the file.
"""

from __future__ import annotations

import re
import subprocess
from fractions import Fraction

import pytest
from coq_tools import compile_development

from verify.coq.derivations import derivation_unit
from verify.coq.development import coqc_available, write_development
from verify.proof import (
    I3,
    Context,
    Derivation,
    by_algebra,
    by_bound,
    cos,
    positive,
    rodrigues,
    sin,
    square,
    tr,
)

needs_coqc = pytest.mark.skipif(not coqc_available(), reason="coqc is not installed")


def _small() -> list[Derivation]:
    """Rodrigues' trace (a unit vector and an angle), an inequality by a square and a
    positive gain, and a side condition."""
    ctx = Context("small")
    xi, theta = ctx.unit_vector("ξ"), ctx.angle("θ")
    k = ctx.scalar("k", positive=True)
    R = rodrigues(xi, theta)
    trace = Derivation("small.trace", tr(R), ctx).equals(1 + 2 * cos(theta), by_algebra())
    bound = Derivation("small.bound", k * (1 - cos(theta)) * (1 - cos(theta)) + k, ctx).ge(
        k, by_bound(positive(k) * square(1 - cos(theta))))
    bound.ge(Fraction(1, 2) * k, by_bound(Fraction(1, 2) * positive(k)))
    on = ctx.condition("cosθ = 0", cos(theta), 0)
    cond = Derivation("small.condition", sin(theta) * sin(theta), ctx, where=(on,)).equals(
        1, by_algebra())
    return [trace, bound, cond]


def _units(derivations):
    out = []
    for d in derivations:
        unit, fates = derivation_unit(d)
        assert all(f.theorem for f in fates), fates
        out.append(unit)
    return out


def test_statements_use_the_prelude_and_name_every_hypothesis():
    trace, bound, cond = _units(_small())
    assert "Theorem step1 : (tr (madd (madd I3 (mscale (sin v_2_theta) (hat v_1_xi)))" in trace.text
    assert "Hypothesis v_1_xi_unit : vdot v_1_xi v_1_xi = 1." in trace.text
    assert "Hypothesis v_2_k_pos : 0 < v_2_k." in bound.text
    assert "Theorem step1 : " in bound.text and " >= v_2_k." in bound.text
    assert "Theorem claim : " in bound.text and "Rge_trans" in bound.text
    assert bound.theorems == ("step1", "step2", "claim")
    assert "Hypothesis condition1 : (cos v_1_theta) = 0." in cond.text
    assert re.search(r"Proof using .*condition1", cond.text)


def test_export_is_deterministic_and_has_no_escape_hatch():
    first = [u.text for u in _units(_small())]
    second = [u.text for u in _units(_small())]
    assert first == second
    for text in first:
        assert not re.search(r"\b(Admitted|admit|Axiom|Parameter|Conjecture)\b", text)


def test_a_cited_step_is_not_exported():
    from verify.paper_proofs import lemma1

    quoted = lemma1.trace_inequality()[0]
    unit, fates = derivation_unit(quoted)
    assert unit is None
    assert fates[0].theorem is None and "cited" in fates[0].reason


def test_a_false_step_is_refused_by_the_exporter():
    ctx = Context("false")
    xi, theta = ctx.unit_vector("ξ"), ctx.angle("θ")
    d = Derivation("false.trace", tr(rodrigues(xi, theta)), ctx).equals(
        1 + 2 * sin(theta), by_algebra())
    unit, fates = derivation_unit(d)
    assert unit is None and fates[0].theorem is None
    assert "not an identity" in fates[0].reason


@needs_coqc
def test_small_units_compile(tmp_path):
    ok, failed, output = compile_development(tmp_path, _units(_small()))
    assert ok, (failed, output)


@needs_coqc
@pytest.mark.parametrize("change", ["swapped statement", "dropped hypothesis",
                                    "changed coefficient"])
def test_tampered_units_fail(tmp_path, change):
    trace, bound, cond = _units(_small())
    if change == "swapped statement":
        unit, old, new = trace, "= (1 + (2 * (cos v_2_theta)))", "= (1 + (2 * (sin v_2_theta)))"
    elif change == "dropped hypothesis":
        unit, old, new = cond, "Hypothesis condition1 : (cos v_1_theta) = 0.", ""
        # keep the name so only the missing fact can make the proof fail
        new = "Hypothesis condition1 : (cos v_1_theta) = (cos v_1_theta)."
    else:
        unit = bound
        old, new = "((v_2_k * (1 + (- (cos v_1_theta)))) * (1 + (- (cos v_1_theta))))", \
            "((v_2_k * (1 + (- (cos v_1_theta)))) * (2 + (- (cos v_1_theta))))"
    assert old in unit.text
    tampered = type(unit)(unit.name, unit.text.replace(old, new), unit.theorems, unit.source)
    ok, failed, _ = compile_development(tmp_path, [tampered])
    assert not ok and failed == f"{unit.name}.v"


def test_fractions_print_exactly():
    ctx = Context("frac")
    k = ctx.scalar("k")
    d = Derivation("frac", Fraction(3, 4) * k + Fraction(1, 4) * k, ctx).equals(k, by_algebra())
    (unit,) = _units([d])
    assert "((3/4) * v_1_k)" in unit.text and "((1/4) * v_1_k)" in unit.text


@pytest.mark.slow
@needs_coqc
def test_paper_development_compiles_and_assumes_only_the_reals(tmp_path):
    from verify.coq.paper import paper_exports

    units, fates = paper_exports()
    again = [u.text for u in paper_exports()[0]]
    assert [u.text for u in units] == again
    for unit in units:
        assert not re.search(r"\b(Admitted|admit|Axiom|Parameter|Conjecture)\b", unit.text)
    missing = [f for f in fates if f.theorem is None and "cited" not in f.reason]
    assert not missing, missing
    files = write_development(tmp_path, units)
    for f in files:
        done = subprocess.run(["coqc", "-R", ".", "VerifyCoq", f.name], cwd=tmp_path,
                              capture_output=True, text=True, timeout=900, check=False)
        assert done.returncode == 0, (f.name, done.stdout + done.stderr)
    printed = done.stdout
    axioms = {line.split(" :")[0] for line in printed.splitlines()
              if line and not line[0].isspace() and line not in (
                  "Axioms:", "Closed under the global context")}
    allowed = {"ClassicalDedekindReals.sig_not_dec", "ClassicalDedekindReals.sig_forall_dec",
               "FunctionalExtensionality.functional_extensionality_dep",
               "Rdefinitions.R", "Rdefinitions.R0", "Rdefinitions.R1", "Rdefinitions.Rplus",
               "Rdefinitions.Rmult", "Rdefinitions.Ropp", "Rdefinitions.Rinv",
               "Rdefinitions.Rlt", "Rdefinitions.Rabst", "Rdefinitions.Rrepr",
               "Rdefinitions.Rquot1", "Rdefinitions.Rquot2", "Rdefinitions.RinvImpl.Rinv",
               "Rdefinitions.RbaseSymbolsImpl.R", "Rdefinitions.RbaseSymbolsImpl.R0",
               "Rdefinitions.RbaseSymbolsImpl.R1", "Rdefinitions.RbaseSymbolsImpl.Rplus",
               "Rdefinitions.RbaseSymbolsImpl.Rmult", "Rdefinitions.RbaseSymbolsImpl.Ropp",
               "Rdefinitions.RbaseSymbolsImpl.Rlt", "Rdefinitions.RbaseSymbolsImpl.Rabst",
               "Rdefinitions.RbaseSymbolsImpl.Rrepr", "Rdefinitions.RbaseSymbolsImpl.Rquot1",
               "Rdefinitions.RbaseSymbolsImpl.Rquot2", "Rdefinitions.RbaseSymbolsImpl.R_Impl",
               "Rdefinitions.RbaseSymbolsImpl.R0_def", "Rdefinitions.RbaseSymbolsImpl.R1_def",
               "Rdefinitions.RbaseSymbolsImpl.Rplus_def",
               "Rdefinitions.RbaseSymbolsImpl.Rmult_def",
               "Rdefinitions.RbaseSymbolsImpl.Ropp_def", "Rdefinitions.RbaseSymbolsImpl.Rlt_def",
               "Rdefinitions.RinvImpl.Rinv_def", "Raxioms.completeness", "Raxioms.archimed",
               "Rtrigo_def.cos", "Rtrigo_def.sin"}
    assert axioms <= allowed, axioms - allowed


def test_identity_entries_are_split_per_entry():
    ctx = Context("split")
    R, A = ctx.rotation("R"), ctx.matrix("A")
    d = Derivation("split", R.T * R * A, ctx).equals(A, by_algebra())
    (unit,) = _units([d])
    assert unit.text.count("\n  - ") == 9
    # rotations only: the prelude's evaluator compares the nine entries, the entries split
    # in its fallback
    ctx = Context("split2")
    R = ctx.rotation("R")
    d = Derivation("split2", R.T * R, ctx).equals(I3, by_algebra())
    (unit,) = _units([d])
    assert "SOSCert.sos_eq" in unit.text and "so3_split; so3_poly ]." in unit.text


def test_check_exports_only_verified_steps(tmp_path):
    from verify.coq.check_export import NOT_VERIFIED, export_verified
    from verify.coq.development import write_development
    from verify.proof import check
    from verify.proof.falsify import SearchSettings

    derivations = _small()
    quick = SearchSettings(samples=32, hypothesis_examples=5, ipopt_starts=1, seed=1)
    results = [check(d, quick) for d in derivations]
    assert all(r.verdict == "verified" for r in results)
    units, fates, missing = export_verified(derivations, results, None)
    assert not missing and all(f.theorem for f in fates) and len(fates) == 4
    write_development(tmp_path / "coq", units)
    project = (tmp_path / "coq" / "_CoqProject").read_text().splitlines()
    # only the prelude modules the units require: no certificate or trajectory files
    assert project == ["-R . VerifyCoq", "SO3.v", "small_trace.v", "small_bound.v",
                       "small_condition.v", "All.v"]
    # a step the checker did not verify is never exported, and the claim goes with it
    results[1].steps[1].verdict = "inconclusive"
    units, fates, missing = export_verified(derivations, results, None)
    bound = next(u for u in units if u.name == "small_bound")
    assert bound.theorems == ("step1",) and not missing
    assert [f.reason for f in fates if f.theorem is None] == [NOT_VERIFIED]
