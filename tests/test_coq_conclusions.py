"""The paper's conclusions along solutions in Coq (prelude ``RotSurj.v``, ``Traj.v``,
``Lemma1Inv.v`` and the ``Conclusions`` unit): they compile, print only the standard
axioms, and fail when a premise the proof needs is dropped or weakened, or when the
conclusion is strengthened beyond what holds (Section 3, Lemma 1)."""

from __future__ import annotations

import pytest
from coq_tools import compiles, run_coqc

from verify.coq.audit import audit_assumptions, forbidden_commands
from verify.coq.conclusions import THEOREMS, conclusion_units
from verify.coq.development import PRELUDE_ORDER, prelude_sources, render_development

ITEM2 = "exists lam, 0 < lam /\\ lam_min_spec (mmul (mT Rr) (Rl t)) lam."
CONCLUSION = ("  1 <= tr (mmul (mT Rr) (Rb 0)) -> forall t, 0 <= t <= T -> "
              "1 <= tr (mmul (mT Rr) (Rb t)).")


def lemma1_source() -> str:
    return prelude_sources()["Lemma1Inv"]


def mutated(old: str, new: str) -> str:
    text = lemma1_source()
    assert text.count(old) == 1, old
    return text.replace(old, new)


def test_prelude_order_lists_the_new_modules_after_their_dependencies():
    order = list(PRELUDE_ORDER)
    assert order.index("SO3") < order.index("RotSurj") < order.index("Traj") \
        < order.index("Lemma1Inv") < order.index("Thm1Energy") < order.index("Barbalat")
    assert set(order) <= set(prelude_sources())


def test_no_forbidden_command_in_the_new_files():
    files = {f"{n}.v": prelude_sources()[n]
             for n in ("RotSurj", "Traj", "Lemma1Inv", "Thm1Energy", "Barbalat")}
    files["Conclusions.v"] = conclusion_units()[0].text
    assert forbidden_commands(files) == []


def test_conclusions_unit_names_its_top_theorems():
    unit = conclusion_units()[0]
    assert unit.theorems == tuple(THEOREMS)
    for name in unit.theorems:
        assert f"Theorem {name} " in unit.text
    files = render_development([unit])
    assert "Conclusions.lemma1_invariance_on_interval" in files["All.v"]


def test_the_paper_development_includes_the_conclusions():
    from pathlib import Path

    from verify.coq.export import paper_development_units

    root = Path(__file__).resolve().parents[1]
    names = [u.name for u in paper_development_units(root / "certificates").units]
    assert "Conclusions" in names


def test_conclusions_compile_with_only_standard_axioms(prelude_dir):
    unit = conclusion_units()[0]
    assert compiles(prelude_dir, unit.text, "Conclusions")
    probe = ("From VerifyCoq Require Conclusions.\nDefinition all_tops := ("
             + ", ".join(f"Conclusions.{n}" for n in unit.theorems)
             + ").\nPrint Assumptions all_tops.\n")
    (prelude_dir / "ProbeConclusions.v").write_text(probe)
    done = run_coqc(prelude_dir, "ProbeConclusions.v", check=True)
    audit = audit_assumptions(done.stdout)
    assert audit.ok, audit.disallowed
    assert "ClassicalDedekindReals.sig_forall_dec" in audit.axioms


@pytest.mark.parametrize("old,new", [
    # Assumption 1, item 2 dropped: the hypothesis says nothing about R_rl any more
    (ITEM2, "exists lam, 0 < lam."),
    # the boundary bound weakened: lambda_min(sym R_rl) >= 0 instead of > 0
    (ITEM2, "exists lam, 0 <= lam /\\ lam_min_spec (mmul (mT Rr) (Rl t)) lam."),
    # the conclusion strengthened to tr >= 1.1
    (CONCLUSION, CONCLUSION.replace("-> 1 <= tr (mmul (mT Rr) (Rb t))",
                                    "-> 11/10 <= tr (mmul (mT Rr) (Rb t))")),
])
def test_lemma1_mutations_make_coqc_fail(prelude_dir, old, new):
    assert not compiles(prelude_dir, mutated(old, new), "Lemma1Mutant")


SUPPLY = "  dSh t <= vdot (vee (sk (mmul (mT (Rl t)) Rr))) (mvmul (mT (Rl t)) (ws t))."


@pytest.mark.parametrize("old,new", [
    # a human that may supply energy of its own (rate up to the power plus 1)
    (SUPPLY, SUPPLY[:-1] + " + 1."),
    # Assumption 1, item 2 weakened to lambda >= 0 (the bound -k_s lam phi must fail);
    # slow: each mutant re-reads Thm1Energy.v up to its error
    pytest.param("Hypothesis lam_pos : 0 < lam.", "Hypothesis lam_pos : 0 <= lam.",
                 marks=pytest.mark.slow),
])
def test_theorem1_mutations_make_coqc_fail(prelude_dir, old, new):
    text = prelude_sources()["Thm1Energy"]
    assert text.count(old) == 1, old
    assert not compiles(prelude_dir, text.replace(old, new), "Thm1Mutant")


@pytest.mark.slow  # the prelude's own Thm1Energy.v is the same text, compiled anyway
def test_theorem1_unmutated_copy_compiles(prelude_dir):
    assert compiles(prelude_dir, prelude_sources()["Thm1Energy"], "Thm1Copy")


def test_lemma1_unmutated_copy_compiles(prelude_dir):
    # the control of the mutation tests: the same file under another name compiles
    assert compiles(prelude_dir, lemma1_source(), "Lemma1Copy")


LIPSCHITZ = ("  Rabs (phi (mmul (mT (Rl t)) (Rb t)) - phi (mmul (mT (Rl s)) (Rb s))) "
             "<= Lp * Rabs (t - s).")


def test_convergence_needs_the_lipschitz_premise(prelude_dir):
    # a rate bound with slack 1 no longer forces phi(R_l^T R-bar) -> 0 (it may oscillate)
    text = prelude_sources()["Barbalat"]
    assert text.count(LIPSCHITZ) == 1
    assert compiles(prelude_dir, text, "BarbalatCopy")
    weak = text.replace(LIPSCHITZ, LIPSCHITZ[:-1] + " + 1.")
    assert not compiles(prelude_dir, weak, "BarbalatMutant")
