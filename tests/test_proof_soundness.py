"""Hostile derivations: each tries to talk the proof checker into a wrong verdict.

Grouped by the kind of hole it probes (see ``verify/proof/TRUSTED.md``): charts that miss
points, vacuous premises, conclusions that drop their conditions, untrusted dynamics,
bypassing the API, wrong counterexamples, internal errors, and false negatives about
lambda_min and float rounding. Each asserts the sound outcome: never "verified" for a
claim that is false or vacuous, and a counterexample only if it meets every declaration.
"""

from __future__ import annotations

import copy
import dataclasses
import json
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from verify.cli import main
from verify.proof import (
    I3,
    Context,
    Derivation,
    Nonneg,
    ProofSyntaxError,
    SearchSettings,
    assumed,
    by_algebra,
    by_bound,
    by_citation,
    check,
    cos,
    dot,
    hat,
    lambda_min,
    positive,
    rodrigues,
    sin,
    sk,
    square,
    sym,
    tr,
)
from verify.proof.checker import step_problem
from verify.proof.confirm import Counterexample, confirm
from verify.proof.derivation import Step
from verify.proof.evaluate import NumpyAlgebra
from verify.proof.expr import Expr, Variable, chart_gap

# what --quick uses is samples=96, hypothesis_examples=25, ipopt_starts=1; smaller here
SMALL = SearchSettings(samples=48, hypothesis_examples=12, ipopt_starts=1, seed=11)


def _verdict(d: Derivation) -> str:
    return check(d, SMALL).verdict


def _not_verified(d: Derivation) -> None:
    result = check(d, SMALL)
    assert result.verdict != "verified", [s.exact for s in result.steps]
    for s in result.steps:
        if s.counterexample is not None:
            assert s.verdict in ("refuted", "inconclusive")


# -- 1. charts that miss points ----------------------------------------------------------
def test_angle_chart_misses_pi_and_the_unit_vector_chart_misses_the_north_pole():
    """The gap points are where the charts tend as their parameters grow."""
    alg = NumpyAlgebra(1)
    big = np.array([1e7])
    c, s = alg.bind(Variable("θ", "angle"), [big])
    assert np.allclose([c[0], s[0]], [-1, 0], atol=1e-6)
    u = alg.bind(Variable("u", "unit_vector"), [big, big])
    assert np.allclose([x[0] for x in u], [0, 0, 1], atol=1e-6)
    assert chart_gap(Variable("θ", "angle")).label == "π"


def test_quaternion_chart_reaches_rotations_by_pi():
    """Every rotation has a unit quaternion: angle pi about x is q = (0, 1, 0, 0)."""
    alg = NumpyAlgebra(1)
    q = [np.array([x]) for x in (0.0, 1.0, 0.0, 0.0)]
    R = np.array([[x[0] for x in row] for row in alg.bind(Variable("R", "rotation"), q)])
    assert np.allclose(R, np.diag([1, -1, -1]))


def test_sin_zero_does_not_give_cos_one():
    ctx = Context("gap")
    th = ctx.angle("θ")
    on = ctx.condition("sin θ = 0", sin(th), 0)
    d = Derivation("cos one", cos(th), ctx, where=(on,)).equals(1, by_algebra())
    result = check(d, SMALL)
    assert result.verdict == "refuted"
    assert result.steps[0].counterexample["values"]["θ"]["kind"] == "chart gap"


def test_cos_minus_one_does_not_give_the_identity_rotation():
    ctx = Context("gap")
    xi, th = ctx.unit_vector("ξ"), ctx.angle("θ")
    on = ctx.condition("cos θ = -1", cos(th), -1)
    d = Derivation("R = I", rodrigues(xi, th), ctx, where=(on,)).equals(I3, by_algebra())
    assert _verdict(d) == "refuted"


def test_a_factor_vanishing_only_at_pi_is_not_cancelled():
    ctx = Context("gap")
    th, x = ctx.angle("θ"), ctx.scalar("x")
    on = ctx.condition("(1 + cos θ) x = 0", (1 + cos(th)) * x, 0)
    d = Derivation("x = 0", x, ctx, where=(on,)).equals(0, by_algebra())
    assert _verdict(d) == "refuted"


def test_an_inequality_under_a_condition_is_checked_at_pi_too():
    ctx = Context("gap")
    th = ctx.angle("θ")
    on = ctx.condition("sin θ = 0", sin(th), 0)
    d = Derivation("cos ≥ 0", cos(th), ctx, where=(on,)).ge(0, by_bound(square(cos(th))))
    assert _verdict(d) == "refuted"


def test_a_true_step_whose_condition_holds_only_at_pi_is_verified():
    """Not over-strict: cos θ = -1 has its only solution at the chart's gap."""
    ctx = Context("gap")
    th = ctx.angle("θ")
    on = ctx.condition("cos θ = -1", cos(th), -1)
    d = Derivation("sin zero", sin(th), ctx, where=(on,)).equals(0, by_algebra())
    result = check(d, SMALL)
    assert result.verdict == "verified", result.steps[0].exact
    assert "points the charts miss" in result.steps[0].exact


def test_a_unit_vector_in_a_condition_is_checked_at_the_pole():
    ctx = Context("gap")
    u, v = ctx.unit_vector("u"), ctx.vector("v")
    on = ctx.condition("<u, v> = 1", dot(u, v), 1)
    d = Derivation("uv", dot(v, u) * dot(u, v), ctx, where=(on,)).equals(1, by_algebra())
    assert [w.name for w in step_problem(d, d.steps[0]).gap_variables] == ["u"]
    result = check(d, SMALL)
    assert result.verdict == "verified"
    assert "points the charts miss" in result.steps[0].exact


def test_a_unit_vector_absent_from_the_conditions_is_covered_by_continuity():
    ctx = Context("gap")
    xi, th = ctx.unit_vector("ξ"), ctx.angle("θ")
    on = ctx.condition("cos θ = 0", cos(th), 0)
    R = rodrigues(xi, th)
    d = Derivation("square", R * R, ctx, where=(on,)).equals(
        I3 + 2 * (hat(xi) * hat(xi)), by_algebra()
    )
    problem = step_problem(d, d.steps[0])
    assert {v.name for v in problem.gap_variables} == {"θ"}  # ξ is free on cos θ = 0
    result = check(d, SMALL)
    assert result.verdict == "verified"
    assert "points the charts miss" in result.steps[0].exact


# -- 2. vacuous conditions and contradictory assumptions ------------------------------------
def _anything(ctx: Context, where=(), assumes=()) -> Derivation:
    x = ctx.scalar("x")
    return Derivation("anything", x, ctx, where=where, assumes=assumes).equals(
        x + 1, by_algebra()
    )


def test_a_constant_false_condition_is_vacuous():
    ctx = Context("vacuous")
    d = _anything(ctx, where=(ctx.condition("tr(I) = 2", tr(I3), 2),))
    result = check(d, SMALL)
    assert result.verdict == "inconclusive"
    assert "no common real solution" in result.steps[0].exact


def test_lambda_min_of_the_identity_is_one_not_five():
    ctx = Context("vacuous")
    d = _anything(ctx, where=(ctx.condition("λmin(I) = 5", lambda_min(I3), 5),))
    result = check(d, SMALL)
    assert result.verdict == "inconclusive"
    assert "vacuous" in result.steps[0].exact


def test_contradictory_conditions_on_one_variable_are_vacuous():
    ctx = Context("vacuous")
    x = ctx.scalar("x")
    a, b = ctx.condition("x = 0", x, 0), ctx.condition("x = 1", x, 1)
    d = Derivation("x = 5", x, ctx, where=(a, b)).equals(5, by_algebra())
    assert _verdict(d) == "inconclusive"


def test_a_condition_with_no_real_solution_is_not_verified():
    ctx = Context("vacuous")
    x, y = ctx.scalar("x"), ctx.scalar("y")
    c = ctx.condition("x² + 1 = 0", x * x + 1, 0)
    d = Derivation("y = 1", y, ctx, where=(c,)).equals(y * (x * x + 2), by_algebra())
    result = check(d, SMALL)
    assert result.verdict == "inconclusive"
    assert "no common real solution" in result.steps[0].exact  # x² + 1 is definite
    c2 = ctx.condition("x² + y² + 1 = 2xy", x * x + y * y + 1, 2 * x * y)  # not by shape
    d2 = Derivation("y = 1", y, ctx, where=(c2,)).equals(y * (x * x + y * y + 2 - 2 * x * y),
                                                        by_algebra())
    result = check(d2, SMALL)
    assert result.verdict == "inconclusive"
    assert "no sampled point" in result.steps[0].exact


def test_an_assumption_false_as_a_constant_is_vacuous():
    ctx = Context("vacuous")
    neg = ctx.assume("-1 > 0", Fraction(-1) * 1, "pos")
    x = ctx.scalar("x")
    d = Derivation("x ≥ x + 1", x, ctx).ge(x + 1, by_bound(assumed(neg)))
    result = check(d, SMALL)
    assert result.verdict == "inconclusive"
    assert "false as a constant" in result.steps[0].exact


def test_minus_identity_is_not_positive_definite():
    ctx = Context("vacuous")
    d = _anything(ctx, assumes=(ctx.assume("-I ≻ 0", -I3, "pd"),))
    assert _verdict(d) == "inconclusive"


def test_contradictory_sign_assumptions_are_not_verified():
    ctx = Context("vacuous")
    x, y = ctx.scalar("x"), ctx.scalar("y")
    a = ctx.assume("x > 0", x, "pos")
    b = ctx.assume("-x - 1 > 0", -x - 1, "pos")
    d = Derivation("y ≥ y + 1", y, ctx).ge(y + 1, by_bound(assumed(b), assumed(a)))
    result = check(d, SMALL)
    assert result.verdict == "inconclusive", result.steps[0].exact
    assert "no sampled point" in result.steps[0].exact


def test_a_true_constant_assumption_does_not_block_a_proof():
    ctx = Context("fine")
    R = ctx.rotation("R")
    d = Derivation("cyclic", tr(R.T * R), ctx, assumes=(ctx.assume("I ⪰ 0", I3, "psd"),))
    assert _verdict(d.equals(3, by_algebra())) == "verified"


# -- 3. a conclusion carries its conditions --------------------------------------------------
def test_steps_under_incompatible_conditions_do_not_chain():
    ctx = Context("chain")
    x = ctx.scalar("x")
    zero, one = ctx.condition("x = 0", x, 0), ctx.condition("x = 1", x, 1)
    d = Derivation("x = x - 1", x, ctx)
    d.equals(0, by_algebra(), where=(zero,)).equals(x - 1, by_algebra(), where=(one,))
    result = check(d, SMALL)
    assert [s.verdict for s in result.steps] == ["verified", "verified"]
    assert result.verdict == "inconclusive"
    data = result.to_json()
    assert data["conditions"] == ["x = 0", "x = 1"]
    assert "x = 0" in data["conclusion"] and "x = 1" in data["conclusion"]
    assert data["vacuous"]


def test_a_conclusion_states_every_condition_and_assumption():
    ctx = Context("chain")
    x, k = ctx.scalar("x"), ctx.scalar("k", positive=True)
    c1, c2 = ctx.condition("x² = 4", x * x, 4), ctx.condition("k = 2", k, 2)
    d = Derivation("chain", x * x * k, ctx)
    d.equals(4 * k, by_algebra(), where=(c1,)).equals(8, by_algebra(), where=(c2,))
    result = check(d, SMALL)
    assert result.verdict == "verified"
    assert result.conditions == ["x² = 4", "k = 2"]
    # k's declared sign is part of what the chain is checked under, and is stated too
    assert result.conclusion.endswith("where x² = 4; k = 2 assuming k > 0 (declared)")


# -- 4. declared dynamics ----------------------------------------------------------------------
def test_a_rotation_derivative_that_is_not_tangent_is_refused():
    ctx = Context("dyn")
    R, w = ctx.rotation("R"), ctx.vector("ω")
    with pytest.raises(ProofSyntaxError, match="skew"):
        ctx.dynamics(R, hat(w))
    ctx.dynamics(R, hat(w) * R)  # left-invariant form is tangent too


def test_redeclared_dynamics_are_refused():
    ctx = Context("dyn")
    R, S, w = ctx.rotation("R"), ctx.rotation("S"), ctx.vector("ω")
    ctx.dynamics(R, R * hat(w))
    with pytest.raises(ProofSyntaxError, match="already declared"):
        ctx.constant(R)
    ctx.constant(S)
    with pytest.raises(ProofSyntaxError, match="already declared"):
        ctx.dynamics(S, S * hat(w))


def test_unit_vector_and_symmetric_dynamics_are_checked():
    ctx = Context("dyn")
    u, w, A, M = ctx.unit_vector("u"), ctx.vector("w"), ctx.symmetric("A"), ctx.matrix("M")
    with pytest.raises(ProofSyntaxError, match="orthogonal"):
        ctx.dynamics(u, w)
    ctx.dynamics(u, hat(w) * u)
    with pytest.raises(ProofSyntaxError, match="symmetric"):
        ctx.dynamics(A, M)


def test_dynamics_of_another_contexts_variable_are_refused():
    ctx, other = Context("a"), Context("b")
    R = other.rotation("R")
    with pytest.raises(ProofSyntaxError, match="not a variable of context"):
        ctx.constant(R)


def test_angle_dynamics_with_a_scalar_rate():
    ctx = Context("dyn")
    th, w = ctx.angle("θ"), ctx.scalar("ω")
    ctx.constant(w)
    ctx.dynamics(th, w)
    d = Derivation("d cos", ctx.ddt(cos(th) * cos(th) + sin(th) * sin(th)), ctx)
    assert _verdict(d.equals(0, by_algebra())) == "verified"
    d2 = Derivation("d cos", ctx.ddt(cos(th)), ctx).equals(w * sin(th), by_algebra())
    assert _verdict(d2) == "refuted"


# -- 5. bypassing the API --------------------------------------------------------------------
def test_nonneg_terms_cannot_be_made_or_altered_by_hand():
    ctx = Context("bypass")
    x = ctx.scalar("x")
    with pytest.raises(ProofSyntaxError, match="kernel"):
        Nonneg(-x * x - 1, "trust me")
    with pytest.raises(ProofSyntaxError, match="kernel"):
        dataclasses.replace(square(x), value=-x * x - 1)
    forged = copy.copy(square(x))
    object.__setattr__(forged, "value", -x * x - 1)
    d = Derivation("forged", 0 * x, ctx).ge(-x * x - 1, by_bound(forged))
    result = check(d, SMALL)
    assert result.verdict != "verified"
    assert "kernel" in result.steps[0].exact
    with pytest.raises(ProofSyntaxError):
        square(x) + forged


def test_an_altered_kernel_term_is_not_accepted():
    ctx = Context("bypass")
    x = ctx.scalar("x")
    term = square(x)
    object.__setattr__(term, "value", -x * x - 1)
    d = Derivation("altered", 0 * x, ctx).ge(-x * x - 1, by_bound(term))
    assert "kernel" in check(d, SMALL).steps[0].exact


def test_moving_the_start_after_the_steps_is_caught():
    ctx = Context("bypass")
    x = ctx.scalar("x")
    d = Derivation("moved", x * x, ctx).ge(0, by_bound(square(x)))
    d.start = x
    with pytest.raises(ProofSyntaxError, match="does not start"):
        check(d, SMALL)


def test_a_hand_appended_step_must_start_where_the_previous_ended():
    ctx = Context("bypass")
    x = ctx.scalar("x")
    d = Derivation("appended", x, ctx).equals(x + 0, by_algebra())
    d.steps.append(Step("=", x + 1, x + 1, by_algebra()))
    with pytest.raises(ProofSyntaxError, match="step 1 ended"):
        check(d, SMALL)


def test_expressions_are_immutable_and_hand_built_trees_are_refused():
    ctx = Context("bypass")
    R = ctx.rotation("R")
    e = tr(R)
    with pytest.raises(ProofSyntaxError, match="immutable"):
        e.op = "const"
    fake = Expr("trace", (ctx.vector("v"),), ())  # trace of a vector
    d = Derivation("fake", fake, ctx).equals(0, by_algebra())
    with pytest.raises(ProofSyntaxError, match="malformed"):
        check(d, SMALL)


def test_variables_cannot_choose_their_identity_or_an_unknown_kind():
    with pytest.raises(TypeError):
        Variable("x", "scalar", False, 7)  # the uid is not an argument
    with pytest.raises(ProofSyntaxError, match="unknown variable kind"):
        Variable("x", "quaternion")
    with pytest.raises(ProofSyntaxError, match="positive"):
        Variable("R", "rotation", True)


# -- 6. counterexamples meet every declaration ---------------------------------------------------
def test_a_positive_gain_is_not_refuted_by_its_negative_root():
    ctx = Context("cx")
    k = ctx.scalar("k", positive=True)
    sq = ctx.condition("k² = 4", k * k, 4)
    d = Derivation("k = 2", k, ctx, where=(sq,)).equals(2, by_algebra())
    result = check(d, SMALL)  # true, but the ideal of k² = 4 does not know k > 0
    assert result.verdict == "inconclusive" and result.steps[0].counterexample is None
    problem = step_problem(d, d.steps[0])
    point = {k.data.uid: np.array([-2.0])}
    assert not isinstance(confirm(problem, point), Counterexample)


def test_two_conditions_on_one_variable_hold_together_in_a_counterexample():
    ctx = Context("cx")
    x = ctx.scalar("x")
    a = ctx.condition("(x - 1)(x - 2) = 0", (x - 1) * (x - 2), 0)
    b = ctx.condition("(x - 1)(x - 3) = 0", (x - 1) * (x - 3), 0)
    d = Derivation("x = 1", x, ctx, where=(a, b)).equals(1, by_algebra())
    assert _verdict(d) == "verified"
    problem = step_problem(d, d.steps[0])
    for bad in (2.0, 3.0):
        assert not isinstance(confirm(problem, {x.data.uid: np.array([bad])}), Counterexample)
    # where the step holds exactly, the violation is rejected, with the rounding it used
    from verify.proof.falsify import Rejected

    assert confirm(problem, {x.data.uid: np.array([1.0 + 1e-12])}) == Rejected(10**6)


def test_a_point_outside_the_assumptions_is_no_counterexample():
    ctx = Context("cx")
    x = ctx.scalar("x")
    pos = ctx.assume("x > 0", x, "pos")
    d = Derivation("x ≥ 0", x, ctx, assumes=(pos,)).ge(0, by_citation("sign"))
    result = check(d, SMALL)
    assert result.verdict == "inconclusive"
    problem = step_problem(d, d.steps[0])
    assert not isinstance(confirm(problem, {x.data.uid: np.array([-1.0])}), Counterexample)


def test_a_counterexample_meets_a_matrix_assumption_exactly():
    ctx = Context("cx")
    R = ctx.rotation("R")
    pd = ctx.assume("sym(R) ≻ 0", R, "pd")
    d = Derivation("tr R ≥ 2", tr(R), ctx, assumes=(pd,)).ge(2, by_citation("wrong"))
    result = check(d, SMALL)
    assert result.verdict == "refuted"
    q = [Fraction(p) for p in result.steps[0].counterexample["values"]["R"]["parameters"]]
    w, x, y, z = q
    assert 3 * w * w - x * x - y * y - z * z > 0  # tr R > 1 <=> sym(R) pd


# -- 7. no internal errors -----------------------------------------------------------------------
def test_lambda_min_mixed_with_a_parameter_in_a_condition():
    ctx = Context("crash")
    R, x = ctx.rotation("R"), ctx.scalar("x")
    c = ctx.condition("λmin(sym R) = x", lambda_min(sym(R)), x)
    d = Derivation("x", x, ctx, where=(c,)).equals(lambda_min(sym(R)), by_algebra())
    result = check(d, SMALL)
    assert result.verdict in ("verified", "inconclusive")
    bad = Derivation("x", x, ctx, where=(c,)).equals(x + 1, by_algebra())
    assert check(bad, SMALL).verdict != "verified"


def test_huge_constants_do_not_overflow():
    ctx = Context("crash")
    x = ctx.scalar("x")
    big = 10**400
    d = Derivation("big", big * x, ctx).equals(x * big, by_algebra())
    assert _verdict(d) == "verified"
    wrong = Derivation("big", big * x, ctx).equals(x * big + 1, by_algebra())
    assert _verdict(wrong) != "verified"
    c = ctx.condition("x = 10^400", x, big)
    under = Derivation("big", x, ctx, where=(c,)).equals(big, by_algebra())
    assert check(under, SMALL).verdict in ("verified", "inconclusive")


# -- 8. false negatives: lambda_min and rounding ----------------------------------------------
def test_lambda_min_sees_the_symmetric_part_scale_and_rotation():
    ctx = Context("spectral")
    M, A, Q = ctx.matrix("M"), ctx.symmetric("A"), ctx.rotation("Q")
    for lhs, rhs in [
        (lambda_min(M), lambda_min(sym(M))),
        (lambda_min(2 * A), 2 * lambda_min(A)),
        (lambda_min(Q * A * Q.T), lambda_min(A)),
        (lambda_min(I3), 1),
    ]:
        d = Derivation("spectral", lhs, ctx).equals(rhs, by_algebra())
        assert _verdict(d) == "verified", d.steps[0].lhs


def test_lambda_min_canonical_form_proves_nothing_false():
    ctx = Context("spectral")
    A, Q = ctx.symmetric("A"), ctx.rotation("Q")
    for lhs, rhs in [
        (lambda_min(3 * A), 2 * lambda_min(A)),
        (lambda_min(-A), -lambda_min(A)),
        (lambda_min(Q * A), lambda_min(A)),
    ]:
        d = Derivation("spectral", lhs, ctx).equals(rhs, by_algebra())
        assert _verdict(d) != "verified", d.steps[0].lhs


def test_float_rounding_does_not_downgrade_an_exact_proof():
    ctx = Context("rounding")
    x = ctx.scalar("x")
    big = 10**12
    d = Derivation("cancel", (x + big) - big, ctx).equals(x, by_algebra())
    result = check(d, SearchSettings(samples=256, hypothesis_examples=40, ipopt_starts=1,
                                     seed=2))
    step = result.steps[0]
    assert step.verdict == "verified", step.exact
    assert step.falsification["violations_undecided"] == 0
    assert step.falsification["violations_rejected_exactly"] > 0
    off = Derivation("off", (x + big) - big, ctx).equals(x + Fraction(1, 10**9), by_algebra())
    assert _verdict(off) == "refuted"


# -- verify check on hostile files -----------------------------------------------------------
HEADER = """
from verify.proof import Context, Derivation, by_algebra, tr, hat
ctx = Context("user")
R, w = ctx.rotation("R"), ctx.vector("w")
d = Derivation("cyclic", tr(R), ctx).equals(tr(R.T), by_algebra())
"""


@pytest.mark.parametrize(
    ("body", "message"),
    [
        ("import sys\nsys.exit(0)\n", "exited"),
        ("import os\nos._exit(0)\n", "exited"),
        ("raise SystemExit\n", "exited"),
        ("import posix\nposix._exit(0)\n", "exited"),
        ("ctx.dynamics(R, R * hat(w))\nctx.constant(R)\n", "already declared"),
        ("from verify.proof import Nonneg\nNonneg(tr(R), 'trust me')\n", "kernel"),
        ("d.start = tr(R) + 1\n", "does not start"),
        (
            "from verify.proof.justify import ByAlgebra\n"
            "class Evil(ByAlgebra):\n"
            "    def describe(self):\n"
            "        raise SystemExit(0)\n"
            "d = Derivation('evil', tr(R), ctx).equals(tr(R.T), Evil())\n",
            "justification of verify.proof",
        ),
        (
            "class Note:\n"
            "    def __format__(self, spec):\n"
            "        raise SystemExit(0)\n"
            "d = Derivation('evil', tr(R), ctx).equals(tr(R.T), by_algebra(Note()))\n",
            "expected a string",
        ),
    ],
)
def test_hostile_files_are_malformed_with_one_line_and_no_json(tmp_path, capsys, body, message):
    path = tmp_path / "hostile.py"
    path.write_text(HEADER + body)
    out = tmp_path / "out.json"
    assert main(["check", str(path), "--quick", "--json", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and message in err
    assert not out.exists()


def test_check_prints_the_conditions_of_the_conclusion(tmp_path, capsys):
    path = tmp_path / "chain.py"
    path.write_text(
        "from verify.proof import Context, Derivation, by_algebra\n"
        "ctx = Context('c')\nx = ctx.scalar('x')\n"
        "a, b = ctx.condition('x = 0', x, 0), ctx.condition('x = 1', x, 1)\n"
        "d = Derivation('c', x, ctx).equals(0, by_algebra(), where=(a,))"
        ".equals(x - 1, by_algebra(), where=(b,))\n"
    )
    out = tmp_path / "out.json"
    assert main(["check", str(path), "--quick", "--json", str(out)]) == 1
    printed = capsys.readouterr().out
    assert "where x = 0; x = 1" in printed and "inconclusive" in printed
    assert json.loads(out.read_text())[0]["verdict"] == "inconclusive"


def test_trusted_md_names_every_chart():
    text = (Path(__file__).resolve().parents[1] / "verify" / "proof" / "TRUSTED.md").read_text()
    for word in ("θ = π", "(0, 0, 1)", "quaternion", "Nonneg", "continuity"):
        assert word in text


def test_positive_declared_gain_used_with_a_true_bound_still_verifies():
    ctx = Context("fine")
    k, x = ctx.scalar("k", positive=True), ctx.scalar("x")
    d = Derivation("k x² ≥ 0", k * x * x, ctx).ge(0, by_bound(positive(k) * square(x)))
    assert _verdict(d) == "verified"


def test_lambda_min_shift_and_scalar_matrices():
    ctx = Context("spectral")
    A, x = ctx.symmetric("A"), ctx.scalar("x")
    for lhs, rhs in [
        (lambda_min(A + 3 * I3), lambda_min(A) + 3),
        (lambda_min(x * I3), x),
        (lambda_min(Fraction(1, 2) * A - I3), Fraction(1, 2) * lambda_min(A) - 1),
    ]:
        assert _verdict(Derivation("shift", lhs, ctx).equals(rhs, by_algebra())) == "verified"
    wrong = Derivation("shift", lambda_min(A + 3 * I3), ctx).equals(lambda_min(A) + 2,
                                                                      by_algebra())
    assert _verdict(wrong) != "verified"


def test_a_gain_used_as_a_constant_cannot_get_dynamics_later():
    ctx = Context("dyn")
    k, R, w = ctx.scalar("k"), ctx.rotation("R"), ctx.vector("ω")
    ctx.dynamics(R, R * hat(w))
    ctx.ddt(k * tr(R))
    with pytest.raises(ProofSyntaxError, match="already declared"):
        ctx.dynamics(k, tr(R))


def test_subclassed_derivations_and_steps_are_refused():
    ctx = Context("bypass")
    x = ctx.scalar("x")

    class Sneaky(Derivation):
        pass

    d = Sneaky("s", x, ctx).equals(x, by_algebra())
    with pytest.raises(ProofSyntaxError, match="takes a Derivation"):
        check(d, SMALL)


def test_deep_and_too_deep_expressions_are_decided_or_refused():
    ctx = Context("crash")
    x = ctx.scalar("x")
    e = x
    for _ in range(900):
        e = e + x
    assert _verdict(Derivation("deep", e, ctx).equals(901 * x, by_algebra())) == "verified"
    for _ in range(200):
        e = e + x
    with pytest.raises(ProofSyntaxError, match="nested more than"):
        check(Derivation("too deep", e, ctx).equals(1101 * x, by_algebra()), SMALL)


def test_huge_constants_inside_lambda_min():
    ctx = Context("crash")
    A = ctx.symmetric("A")
    big = 10**400
    d = Derivation("big", lambda_min(big * A), ctx).equals(big * lambda_min(A), by_algebra())
    assert check(d, SMALL).verdict in ("verified", "inconclusive")
    wrong = Derivation("big", lambda_min(big * A), ctx).equals(lambda_min(A), by_algebra())
    assert check(wrong, SMALL).verdict != "verified"


def test_only_an_exact_counterexample_or_an_undecided_violation_overrides_an_exact_proof(
    monkeypatch,
):
    """With the exact check forced to pass on a false step, the exact counterexample
    makes it an internal disagreement, and a violation exact arithmetic cannot decide
    keeps it inconclusive; neither is ever 'verified'."""
    from verify.proof import checker

    monkeypatch.setattr(checker, "_exact_check", lambda step, problem: (True, "forced"))
    ctx = Context("override")
    R = ctx.rotation("R")
    d = Derivation("false", tr(R), ctx).equals(tr(R * R), by_algebra())
    step = check(d, SMALL).steps[0]
    assert step.verdict == "inconclusive" and "INTERNAL DISAGREEMENT" in step.exact
    monkeypatch.setattr(checker, "search", lambda problem, cfg, confirm: _undecided(
        problem, cfg))
    step = check(d, SMALL).steps[0]
    assert step.verdict == "inconclusive" and "not decided exactly" in step.exact


def _undecided(problem, cfg):
    from verify.proof.falsify import SearchReport

    report = SearchReport(feasible=1, undecided=1)
    report.candidates.append({})
    return report, None


def test_the_pinned_unit_vector_is_the_north_pole_exactly():
    ctx = Context("gap")
    u, th = ctx.unit_vector("u"), ctx.angle("θ")
    on = ctx.condition("cos θ = <u, u> - 1", cos(th), dot(u, u) - 1)
    d = Derivation("u", u, ctx, where=(on,)).equals(u, by_algebra())
    pinned = step_problem(d, d.steps[0]).pinned([u.data, th.data])
    assert [x.num for x in pinned.exact(u)] == [0, 0, 1]
    assert [x.num for x in pinned.exact(cos(th))] == [-1]
    assert pinned.conditions_empty  # cos π = 0 is false: that piece has no points


def test_conditions_unsatisfiable_in_every_chart_are_decided_exactly():
    ctx = Context("vacuous")
    th = ctx.angle("θ")
    a = ctx.condition("cos θ = -1", cos(th), -1)
    b = ctx.condition("sin θ = 1", sin(th), 1)
    d = Derivation("anything", cos(th), ctx, where=(a, b)).equals(5, by_algebra())
    result = check(d, SMALL)
    assert result.verdict == "inconclusive"
    assert "every chart" in result.steps[0].exact


def test_a_positive_gain_conditioned_negative_is_vacuous():
    ctx = Context("vacuous")
    k = ctx.scalar("k", positive=True)
    c = ctx.condition("k = -1", k, -1)
    d = Derivation("k", k * k, ctx, where=(c,)).equals(1, by_algebra())
    result = check(d, SMALL)
    assert result.verdict == "inconclusive" and "no sampled point" in result.steps[0].exact


def test_a_condition_true_only_approximately_is_not_a_witness():
    """x² + 10⁻²⁰ = 0 has no real root, though floats find |x² + 10⁻²⁰| tiny at x = 0."""
    ctx = Context("vacuous")
    x = ctx.scalar("x")
    c = ctx.condition("x² + 10⁻²⁰ = 0", x * x + Fraction(1, 10**20), 0)
    d = Derivation("1 = -10²⁰ x²", 1, ctx, where=(c,)).equals(-(10**20) * x * x, by_algebra())
    assert check(d, SMALL).verdict == "inconclusive"


def test_a_duck_typed_assumption_is_refused():
    class Fake:
        kind, label, cite = "pos", "trust me", ""

        def __init__(self, expr):
            self.expr = expr

    ctx = Context("bypass")
    x = ctx.scalar("x")
    with pytest.raises(ProofSyntaxError, match=r"ctx\.assume"):
        assumed(Fake(-x * x - 1))


def test_two_angles_at_pi_together():
    """cos θ + cos φ = -2 holds only at θ = φ = π: outside both charts at once."""
    ctx = Context("gap")
    th, ph = ctx.angle("θ"), ctx.angle("φ")
    on = ctx.condition("cos θ + cos φ = -2", cos(th) + cos(ph), -2)
    wrong = Derivation("sin", sin(th) + cos(ph), ctx, where=(on,)).equals(1, by_algebra())
    result = check(wrong, SMALL)
    assert result.verdict == "refuted"
    values = result.steps[0].counterexample["values"]
    assert values["θ"]["kind"] == values["φ"]["kind"] == "chart gap"
    right = Derivation("sin", sin(th) + cos(ph), ctx, where=(on,)).equals(-1, by_algebra())
    assert _verdict(right) == "verified"


def test_rotation_dynamics_must_be_skew_not_merely_small():
    ctx = Context("dyn")
    R, M = ctx.rotation("R"), ctx.matrix("M")
    with pytest.raises(ProofSyntaxError, match="skew"):
        ctx.dynamics(R, R * (M + I3))
    ctx.dynamics(R, R * sk(M))


def test_replaced_bound_terms_are_refused():
    ctx = Context("bypass")
    x = ctx.scalar("x")
    because = by_bound(square(x))
    d = Derivation("swap", x * x, ctx).ge(0, because)
    because.terms = [object()]
    with pytest.raises(ProofSyntaxError, match="replaced"):
        check(d, SMALL)
    because.terms = (object(),)
    assert check(d, SMALL).verdict == "inconclusive"


def test_a_condition_pinning_a_unit_vector_to_the_pole_is_covered():
    """With the pole itself as a constant, u·e3 = 1 holds only outside u's chart."""
    ctx = Context("gap")
    u = ctx.unit_vector("u")
    e3 = chart_gap(u.data)
    on = ctx.condition("<u, e3> = 1", dot(u, e3), 1)
    wrong = Derivation("u3", dot(u, e3), ctx, where=(on,)).equals(0, by_algebra())
    result = check(wrong, SMALL)
    assert result.verdict == "refuted"
    assert result.steps[0].counterexample["values"]["u"]["value"] == [0.0, 0.0, 1.0]
