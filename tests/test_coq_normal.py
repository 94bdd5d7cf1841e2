"""The matrix-level normal form (``so3_norm`` in the prelude, :mod:`verify.coq.normal`).

The Python model must keep every value (checked exactly with rotations in quaternion
parameters) and cancel what Coq's rewriting cancels; an exported proof that uses it must
compile, and must fail when its statement is changed.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
from coq_tools import compile_development

from verify.coq.derivations import derivation_unit
from verify.coq.development import coqc_available
from verify.coq.normal import normal_form
from verify.coq.polys import atoms_for, entries, evaluate
from verify.coq.terms import Naming
from verify.proof import I3, Context, Derivation, by_algebra, tr
from verify.proof.expr import dot, hat, sk, variables_of, vee

needs_coqc = pytest.mark.skipif(not coqc_available(), reason="coqc is not installed")


def _setting():
    ctx = Context("normal")
    R, S = ctx.rotation("R"), ctx.rotation("S")
    A = ctx.matrix("A")
    w = ctx.vector("w")
    k = ctx.scalar("k", positive=True)
    return ctx, R, S, A, w, k


def _exprs():
    _, R, S, A, w, k = _setting()
    return [
        tr(R.T * S * sk(S.T * R * A)),
        (R.T * S).T * (R.T * A) - S.T * A,
        hat(k * (R.T * w)) * R.T,
        R.T * hat(w) * R - hat(R.T * w),
        dot(vee(sk(R.T * S)), S.T * w) + Fraction(1, 2) * tr(R.T * S * hat(S.T * w)),
        sk(I3 - R.T * S) + Fraction(1, 2) * (R.T * S - S.T * R),
    ]


def _values(e, generic, variables=None):
    atoms = atoms_for(variables or variables_of(e), [], Naming(), generic=generic)
    return atoms, entries(evaluate(e, atoms))


@pytest.mark.parametrize("hat_out", [False, True])
def test_the_normal_form_keeps_every_value(hat_out):
    for e in _exprs():
        atoms = atoms_for(variables_of(e), [], Naming())
        before = entries(evaluate(e, atoms))
        after = entries(evaluate(normal_form(e, hat=hat_out), atoms))
        for x, y in zip(before, after, strict=True):
            assert (x - y).num == 0, str(e)


def test_rotations_meeting_their_transposes_cancel_for_free_matrices():
    _, R, S, A, w, _ = _setting()
    e = (R.T * S).T * (R.T * A) - S.T * A  # S^T R R^T A - S^T A
    _, plain = _values(e, generic=True)
    assert any(x.num != 0 for x in plain)  # with R a free matrix it is not an identity
    _, normal = _values(normal_form(e), generic=True, variables=variables_of(e))
    assert all(x.num == 0 for x in normal)
    conj = R.T * hat(w) * R - hat(R.T * w)  # needs det R = 1: only with hat taken out
    v = variables_of(conj)
    assert any(x.num != 0 for x in _values(normal_form(conj), True, v)[1])
    assert all(x.num == 0 for x in _values(normal_form(conj, hat=True), True, v)[1])


def _rotation_units():
    ctx, R, S, A, w, k = _setting()
    d1 = Derivation("normal.cancel", tr(R.T * S * sk((R.T * S).T * (R.T * A))), ctx).equals(
        tr(R.T * S * sk(S.T * A)), by_algebra())
    d2 = Derivation("normal.conj", k * (R.T * hat(w) * R), ctx).equals(
        k * hat(R.T * w), by_algebra())
    out = []
    for d in (d1, d2):
        unit, fates = derivation_unit(d)
        assert all(f.theorem for f in fates), fates
        out.append(unit)
    return out


def test_identities_in_rotations_are_proved_on_free_matrices():
    cancel, conj = _rotation_units()
    assert "so3_norm." in cancel.text  # a free matrix A: the evaluator does not read it
    # rotations, vectors and scalars only: the evaluator, the normal form as its fallback
    assert "SOSCert.sos_eq" in conj.text and "so3_norm_hat;" in conj.text
    assert "From VerifyCoq Require SOSCert." in conj.text
    assert "SOSCert" not in cancel.text
    for unit in (cancel, conj):
        # every rotation generalised: no entry left to field in quaternion parameters
        assert "field" not in unit.text.split("Proof using", 1)[1]
        assert "generalize (rot q_v_1_R)" in unit.text  # generated, never Coq's R


@needs_coqc
def test_normalised_proofs_compile_and_a_changed_statement_fails(tmp_path):
    units = _rotation_units()
    ok, failed, _ = compile_development(tmp_path / "good", units)
    assert ok, failed
    cancel, conj = units
    old = "(mmul (mT (mmul (mT v_1_R) v_2_S)) (mmul (mT v_1_R) v_3_A))"
    assert old in cancel.text
    new = "(mmul (mT v_2_S) (mmul v_1_R v_3_A))"
    bad = type(cancel)(cancel.name, cancel.text.replace(old, new, 1),
                       cancel.theorems, cancel.source)
    ok, failed, _ = compile_development(tmp_path / "bad", [bad, conj])
    assert not ok and failed == f"{cancel.name}.v"


def _evaluator_only(unit):
    """``unit`` with the evaluator's fallback removed: ``first [ E | F ].`` becomes ``E.``"""
    lines = []
    for line in unit.text.splitlines():
        if line.strip().startswith("first [ SOSCert.sos_eq"):
            head, _, _ = line.partition(" | ")
            line = head.replace("first [ ", "", 1) + "."
        lines.append(line)
    return type(unit)(unit.name, "\n".join(lines), unit.theorems, unit.source)


@needs_coqc
def test_the_evaluator_alone_proves_the_step_and_refuses_a_changed_one(tmp_path):
    _, conj = _rotation_units()
    alone = _evaluator_only(conj)
    assert "so3_norm" not in alone.text.split("Proof using", 1)[1]
    ok, failed, _ = compile_development(tmp_path / "good", [alone])
    assert ok, failed
    old = "(hat (mvmul (mT v_1_R) v_2_w))"
    assert old in alone.text
    bad = type(alone)(alone.name, alone.text.replace(old, "(hat (mvmul v_1_R v_2_w))", 1),
                      alone.theorems, alone.source)
    ok, failed, _ = compile_development(tmp_path / "bad", [bad])
    assert not ok and failed == f"{alone.name}.v"


@needs_coqc
def test_the_evaluator_proves_vector_and_scalar_steps(tmp_path):
    ctx = Context("evalvs")
    R = ctx.rotation("R")
    w = ctx.vector("w")
    d1 = Derivation("evalvs.vector", R.T * (R * w), ctx).equals(w, by_algebra())
    d2 = Derivation("evalvs.scalar", dot(R.T * (R * w), w), ctx).equals(dot(w, w),
                                                                        by_algebra())
    units = []
    for d in (d1, d2):
        unit, fates = derivation_unit(d)
        assert all(f.theorem for f in fates), fates
        assert "SOSCert.sos_eq" in unit.text
        units.append(_evaluator_only(unit))
    ok, failed, _ = compile_development(tmp_path / "good", units)
    assert ok, failed
