"""Theorem 1's LaSalle step in Coq, in asymptotic form (prelude ``Converge.v`` and the
``Conclusions`` unit): d̄ → d_r follows from the proved φ(R_lᵀR̄) → 0, Barbalat's
second form and item 3 of Assumption 1 in asymptotic form; each named premise is
needed (dropping or weakening it makes ``coqc`` refuse), and the conclusion cannot be
moved to another axis (Section 3, Theorem 1's proof)."""

from __future__ import annotations

import pytest
from coq_tools import compiles

from verify.coq.audit import forbidden_commands
from verify.coq.conclusions import THEOREMS, conclusion_units
from verify.coq.development import PRELUDE_ORDER, prelude_sources

NEW_TOPS = ("barbalat_second_form", "thm1_lasalle_relative_rate", "thm1_leader_average_axes",
            "thm1_human_command_vanishes", "thm1_dbar_converges_to_dr")

ITEM3 = ("  (vanishes (fun t => vnorm (ws t)) ->\n"
         "   vanishes (fun t => vnorm (vsub (mvmul (Rl t) e3) (mvmul Rr e3)))) ->\n")
LIPSCHITZ = ("  (forall s t, 0 <= s -> 0 <= t -> vnorm (vsub (ws t) (ws s)) <= Lw * Rabs (t - s)) "
             "->\n")
BOUNDED = "  (forall t, 0 <= t -> vnorm (ws t) <= Bw) ->\n"
OBJECTIVE = "  vanishes (fun t => vnorm (vsub (mvmul (Rb t) e3) (mvmul Rr e3))).\n"


def converge_source() -> str:
    return prelude_sources()["Converge"]


def unit_text() -> str:
    return conclusion_units()[0].text


def theorem_block(text: str, name: str) -> tuple[int, int]:
    """Start and end (after its ``Qed.``) of theorem ``name`` in ``text``."""
    start = text.index(f"Theorem {name} ")
    return start, text.index("Qed.", start) + len("Qed.")


def mutate_theorem(name: str, old: str, new: str) -> str:
    """The Conclusions unit with ``old`` replaced by ``new`` in theorem ``name`` only."""
    text = unit_text()
    start, end = theorem_block(text, name)
    block = text[start:end]
    assert block.count(old) == 1, (name, old)
    return text[:start] + block.replace(old, new) + text[end:]


def test_converge_is_in_the_prelude_after_barbalat():
    order = list(PRELUDE_ORDER)
    assert order.index("Barbalat") < order.index("Converge")
    assert "Converge" in prelude_sources()


def test_the_unit_states_the_new_theorems_with_their_premises():
    unit = conclusion_units()[0]
    for name in NEW_TOPS:
        assert name in unit.theorems and name in THEOREMS
        assert f"Theorem {name} " in unit.text
    start, end = theorem_block(unit.text, "thm1_dbar_converges_to_dr")
    block = unit.text[start:end]
    for premise in (ITEM3, LIPSCHITZ, BOUNDED):
        assert premise in block
    assert block.endswith(OBJECTIVE + "Proof. intros. apply (dbar_converges Rr Rb Rl ws Sh dSh "
                          "ks lam Bw Lw); assumption. Qed.")
    assert "asymptotic form" in THEOREMS["thm1_dbar_converges_to_dr"]


def test_no_forbidden_command_in_converge():
    assert forbidden_commands({"Converge.v": converge_source()}) == []


def test_the_unmutated_unit_compiles(prelude_dir):
    assert compiles(prelude_dir, unit_text(), "ConclusionsCopy")


@pytest.mark.parametrize("name,old,new", [
    # item 3 dropped: nothing links the vanishing command to the reference axis
    ("thm1_dbar_converges_to_dr", ITEM3, ""),
    # the command's rate dropped: Barbalat's second form has no uniform continuity
    ("thm1_dbar_converges_to_dr", LIPSCHITZ, ""),
    ("thm1_human_command_vanishes", LIPSCHITZ, ""),
    # the bounded command dropped: phi(R_l^T R-bar) need not be Lipschitz
    ("thm1_leader_average_axes", BOUNDED, ""),
    # the objective moved to another axis of R_r
    ("thm1_dbar_converges_to_dr", OBJECTIVE,
     OBJECTIVE.replace("(mvmul Rr e3)", "(mvmul Rr (mkV 1 0 0))")),
    # R-bar's axis claimed to reach the leader's axis at a rate: |d_l - d-bar| <= 0
    ("thm1_leader_average_axes",
     "  vanishes (fun t => vnorm (vsub (mvmul (Rl t) e3) (mvmul (Rb t) e3))).",
     "  forall t, 0 <= t -> vnorm (vsub (mvmul (Rl t) e3) (mvmul (Rb t) e3)) = 0."),
])
def test_unit_mutations_make_coqc_fail(prelude_dir, name, old, new):
    assert not compiles(prelude_dir, mutate_theorem(name, old, new), "ConclusionsMutant")


CONVERGE_ITEM3 = ("Hypothesis item3_asymptotic :\n  vanishes (fun t => vnorm (ws t)) -> "
                  "vanishes (fun t => vnorm (vsub (mvmul (Rl t) e3) (mvmul Rr e3))).")
CONVERGE_LIPSCHITZ = "  vnorm (vsub (ws t) (ws s)) <= Lw * Rabs (t - s)."
BARBALAT2 = "  vanishes (fun t => f t - L) -> unif_cont df -> vanishes df."


@pytest.mark.slow  # each mutant recompiles Converge.v, about 5 CPU seconds
@pytest.mark.parametrize("old,new", [
    # item 3 made vacuous (d_l -> d-bar, already proved): d-bar -> d_r no longer follows
    (CONVERGE_ITEM3, CONVERGE_ITEM3.replace("(mvmul Rr e3)", "(mvmul (Rb t) e3)")),
    # a command whose jumps may stay of size 1: it need not die out
    (CONVERGE_LIPSCHITZ, CONVERGE_LIPSCHITZ[:-1] + " + 1."),
    # Barbalat's second form without uniform continuity (sin(t^2)/t is a counterexample)
    (BARBALAT2, "  vanishes (fun t => f t - L) -> vanishes df."),
])
def test_converge_mutations_make_coqc_fail(prelude_dir, old, new):
    text = converge_source()
    assert text.count(old) == 1, old
    assert compiles(prelude_dir, text, "ConvergeCopy")
    assert not compiles(prelude_dir, text.replace(old, new), "ConvergeMutant")


def test_the_finding_says_re_checked_only_when_coq_accepted():
    from verify.claims.evidence import certificate
    from verify.claims.section3 import convergence_finding

    accepted = convergence_finding(certificate("coq", True))
    assert "re-checked in this run" in accepted and "not re-checked" not in accepted
    refused = convergence_finding(certificate("coq", False))
    assert "did not accept the proof, so not re-checked in this run" in refused
    missing = convergence_finding(None)
    assert "is not installed here, so not re-checked in this run" in missing
    for text in (accepted, refused, missing):
        # the premises that stay named, and the step left unproved
        assert "Conclusions.thm1_phi_sync_converges" in text
        assert "thm1_dbar_converges_to_dr" in text
        assert "item 3 in asymptotic form" in text and "Lipschitz" in text
        assert "LaSalle's theorem on the ω-limit set: not proved." in text


def test_without_coqc_there_is_no_convergence_evidence(monkeypatch):
    import verify.claims.coq_conclusions as coq_conclusions

    monkeypatch.setattr(coq_conclusions, "coqc_available", lambda: False)
    assert coq_conclusions.convergence_kernel_evidence() is None
