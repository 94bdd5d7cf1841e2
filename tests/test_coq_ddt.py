"""Derivative theorems of the derivations that start from ``ctx.ddt`` (Section 3, eqs.
(13), (15), (17)): every such derivation of the paper states ``ddt``, its statement reads
back as the tree it was made from, Coq proves it with the trajectory rules (prelude
``Traj.v``), and a wrong derivative or wrong dynamics make ``coqc`` refuse it."""

from __future__ import annotations

import functools
import re
import shutil
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest
from coq_tools import run_coqc

from verify.coq.audit import forbidden_commands, statement_problems
from verify.coq.ddt import THEOREM, ddt_start
from verify.coq.derivations import derivation_unit
from verify.coq.development import coqc_available, prelude_sources
from verify.coq.paper import paper_derivations, paper_units
from verify.coq.reparse import parse_statement
from verify.proof import Context, Derivation, by_algebra, hat, phi, sk, tr, vee
from verify.proof.expr import dot

#: The paper's derivations whose first expression is a time derivative (or one taken at
#: R_l = R-bar, R-bar = R_l, R-bar = R_l (2 xi xi^T - I)).
PAPER_DDT = {"lemma1.h-dot", "thm1.S_r-dot", "thm1.S_rl-dot", "thm1.V-dot",
             "thm1.V-dot-zero-on-sync", "thm1.lasalle-derivative",
             "thm1.lasalle-derivative-from-sk-only"}


def _coquelicot(folder: Path) -> bool:
    (folder / "Probe.v").write_text("From Coquelicot Require Import Hierarchy Derive.\n")
    done = subprocess.run([shutil.which("coqc") or "coqc", "Probe.v"], cwd=folder,
                          capture_output=True, text=True, timeout=120)
    return done.returncode == 0


@pytest.fixture(scope="module")
def traj_dir(tmp_path_factory):
    """SO3.v and Traj.v compiled (skips without coqc or Coquelicot)."""
    if not coqc_available():
        pytest.skip("coqc not installed")
    folder = tmp_path_factory.mktemp("coq-traj")
    if not _coquelicot(folder):
        pytest.skip("Coquelicot not installed (apt-get install libcoq-coquelicot)")
    sources = prelude_sources()
    for name in ("SO3", "Traj"):
        (folder / f"{name}.v").write_text(sources[name])
        run_coqc(folder, f"{name}.v", check=True)
    return folder


@functools.cache
def _paper_units():
    return paper_units()


def _unit(name: str):
    (unit,) = [u for u in _paper_units() if u.source == name]
    return unit


def test_every_paper_derivation_from_a_derivative_states_ddt():
    derivations = paper_derivations()
    starts = {d.name for d in derivations if ddt_start(d) is not None}
    assert starts == PAPER_DDT
    for unit in _paper_units():
        assert (THEOREM in unit.theorems) == (unit.source in PAPER_DDT), unit.name


def test_ddt_statements_read_back_as_their_trees():
    for unit in _paper_units():
        if THEOREM not in unit.theorems:
            continue
        statement = dict(unit.statements)[THEOREM]
        assert parse_statement(statement) == dict(unit.terms)[THEOREM]
        assert statement_problems(unit.name, unit.text, dict(unit.statements),
                                  dict(unit.terms)) == []


def test_a_changed_dynamics_premise_fails_the_round_trip():
    unit = _unit("lemma1.h-dot")
    statement = dict(unit.statements)[THEOREM]
    old = "(mscale v_4_k_s (v_2_Rbar t))"
    assert statement.startswith("is_mderiv v_2_Rbar t (mmul " + old)
    forged = unit.text.replace(f"Theorem {THEOREM} : {statement}",
                               f"Theorem {THEOREM} : " + statement.replace(
                                   old, "(mscale (2 * v_4_k_s) (v_2_Rbar t))", 1))
    problems = statement_problems(unit.name, forged, dict(unit.statements), dict(unit.terms))
    assert problems and "ddt" in problems[0]


def test_substituted_starts_carry_the_substitution_as_premises():
    unit = _unit("thm1.V-dot-zero-on-sync")
    statement = dict(unit.statements)[THEOREM]
    assert re.search(r"-> \(v_\d+_R_l t\) = \(v_\d+_Rbar t\) -> is_derive", statement)
    unit = _unit("thm1.lasalle-derivative-from-sk-only")
    assert re.search(r"-> \(v_\d+_Rbar t\) = \(mmul \(v_\d+_R_l t\)",
                     dict(unit.statements)[THEOREM])


def _section(text: str) -> str:
    """The unit's trajectory part alone (header and derivative section)."""
    head = text[text.index("From Coq Require"):text.index("Section ")]
    return head + text[text.index("From Coquelicot"):]


def _compiles(folder: Path, text: str, name: str) -> subprocess.CompletedProcess:
    (folder / f"{name}.v").write_text(text)
    return run_coqc(folder, f"{name}.v")


def test_the_h_dot_derivative_compiles_and_mutations_fail(traj_dir):
    text = _section(_unit("lemma1.h-dot").text)
    assert _compiles(traj_dir, text, "HDot").returncode == 0
    conclusion = text[text.index("is_derive (fun s"):]
    # wrong derivative: the factor k_s doubled in the conclusion only
    wrong = conclusion.replace("(mscale v_4_k_s (v_2_Rbar t))",
                               "(mscale (2 * v_4_k_s) (v_2_Rbar t))", 1)
    assert wrong != conclusion
    done = _compiles(traj_dir, text.replace(conclusion, wrong), "HDotWrong")
    assert done.returncode != 0
    # wrong dynamics: R-bar-dot = k_s sk(R-bar^T R_l) R-bar instead of eq. (13)
    premise = ("is_mderiv v_2_Rbar t (mmul (mscale v_4_k_s (v_2_Rbar t)) "
               "(sk (mmul (mT (v_2_Rbar t)) v_3_R_l)))")
    assert premise in text
    other = "is_mderiv v_2_Rbar t (mmul (sk (mmul (mT (v_2_Rbar t)) v_3_R_l)) " \
            "(mscale v_4_k_s (v_2_Rbar t)))"
    done = _compiles(traj_dir, text.replace(premise, other), "HDotDynamics")
    assert done.returncode != 0


@pytest.mark.slow
def test_every_paper_derivative_theorem_compiles(traj_dir):
    for unit in _paper_units():
        if THEOREM in unit.theorems:
            done = _compiles(traj_dir, _section(unit.text), f"D_{unit.name}")
            assert done.returncode == 0, unit.name + done.stdout + done.stderr


def _users_derivation(name: str) -> Derivation:
    """A user's derivation with a hostile name: d/dt of phi(R) + S along R-dot = R hat(w),
    S-dot = -<vee(sk R), w> (the storage pattern of Theorem 1)."""
    ctx = Context(name)
    R = ctx.rotation("R *) Axiom evil : False. (*")
    w = ctx.vector("w\"")
    S = ctx.scalar("Theorem")
    ctx.dynamics(R, R * hat(w))
    ctx.dynamics(S, -dot(vee(sk(R)), w))
    d = Derivation(name, ctx.ddt(phi(R) + S).named("V̇ *)"), ctx)
    d.equals(Fraction(-1, 2) * tr(R * hat(w)) - dot(vee(sk(R)), w),
             by_algebra("product rule"))
    return d


def test_a_users_derivation_from_a_derivative_exports_ddt():
    d = _users_derivation("evil *) Axiom x : False. (* ddt")
    unit, _ = derivation_unit(d)
    assert unit is not None and THEOREM in unit.theorems
    assert forbidden_commands({"U.v": unit.text}) == []
    statement = dict(unit.statements)[THEOREM]
    assert statement.startswith("is_mderiv v_1_")
    assert parse_statement(statement) == dict(unit.terms)[THEOREM]


def test_a_users_derivative_theorem_compiles(traj_dir):
    d = _users_derivation("evil *) Axiom x : False. (* ddt")
    unit, _ = derivation_unit(d)
    done = _compiles(traj_dir, _section(unit.text), "UserDdt")
    assert done.returncode == 0, done.stdout + done.stderr
