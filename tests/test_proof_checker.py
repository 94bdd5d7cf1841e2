"""The proof checker (verify.proof): exact decisions, falsification, mutations.

Mutated derivations must be rejected with a counterexample that is confirmed exactly
by the checker; the tests then re-evaluate the counterexample numerically, so a test
cannot pass because a text matched.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from verify.paper_proofs import lemma1, theorem1
from verify.proof import (
    I3,
    Context,
    Derivation,
    ProofSyntaxError,
    SearchSettings,
    by_algebra,
    by_bound,
    by_citation,
    check,
    cos,
    hat,
    lambda_min,
    outer,
    positive,
    rodrigues,
    sk,
    square,
    sym,
    tr,
    trace_lower_bound,
)
from verify.proof.evaluate import NumpyAlgebra, evaluate
from verify.proof.problem import flatten

QUICK = SearchSettings(samples=96, hypothesis_examples=25, ipopt_starts=1, seed=5)
HALF = Fraction(1, 2)


def _violation_at_counterexample(d: Derivation, index: int, cx: dict) -> float:
    """Relative violation of step ``index`` re-evaluated in floating point at ``cx``."""
    step = d.steps[index]
    from verify.proof.expr import variables_of

    variables = variables_of(step.lhs, step.rhs)
    alg = NumpyAlgebra(1)
    env = {}
    for v in variables:
        params = cx["values"][v.name]["approx_parameters"]
        env[v.uid] = alg.bind(v, [np.array([p]) for p in params])
    lhs = np.array(flatten(evaluate(step.lhs, alg, env)), dtype=float).ravel()
    rhs = np.array(flatten(evaluate(step.rhs, alg, env)), dtype=float).ravel()
    size = 1 + np.abs(lhs).max() + np.abs(rhs).max()
    if step.relation == "=":
        return float(np.abs(lhs - rhs).max() / size)
    slack = (lhs - rhs)[0] if step.relation == ">=" else (rhs - lhs)[0]
    return float(-slack / size)


def _assert_refuted(d: Derivation, index: int) -> None:
    result = check(d, QUICK)
    step = result.steps[index]
    assert step.verdict == "refuted", (d.name, step.exact, step.falsification)
    assert result.verdict == "refuted"
    assert step.counterexample is not None
    assert _violation_at_counterexample(d, index, step.counterexample) > 1e-9


# -- the paper's derivations ----------------------------------------------------------------
PAPER = {
    "spectrum": lemma1.rodrigues_spectrum,
    "h-dot": lemma1.h_dot,
    "rbar-dot": lemma1.rbar_dot_form,
    "boundary": lemma1.boundary,
    "gradient": lemma1.gradient,
    "phi": theorem1.phi_identity,
    "S_r": theorem1.s_r_dot,
    "S_rl": theorem1.s_rl_dot,
    "S_h": theorem1.storage_sign,
    "V": theorem1.v_dot,
    "lasalle": theorem1.lasalle,
}


@pytest.mark.parametrize("name", sorted(PAPER))
def test_paper_derivations_verify_in_every_step(name):
    for d in PAPER[name]():
        result = check(d, QUICK)
        assert [s.verdict for s in result.steps] == ["verified"] * len(d.steps), d.name
        assert all(s.counterexample is None for s in result.steps)


def test_trace_inequality_as_quoted_is_refuted_and_the_repair_verified():
    quoted, psd, sym_psd = lemma1.trace_inequality()
    _assert_refuted(quoted, 0)
    assert check(psd, QUICK).verdict == "verified"
    assert check(sym_psd, QUICK).verdict == "verified"


# -- mutations ---------------------------------------------------------------------------------
def _h_dot_context():
    ctx, Rr, Rb, Rl, ks = lemma1.closed_loop_context()
    return ctx, Rr.T * Rb, Rr.T * Rl, ks


def test_flipped_sign_is_refuted():
    ctx, Rbr, Rrl, ks = _h_dot_context()
    d = Derivation("flip", HALF * ks * tr(Rrl - Rrl.T * Rbr * Rbr), ctx)
    d.equals(-HALF * ks * tr(Rrl - Rrl.T * Rbr * Rbr), by_algebra())
    _assert_refuted(d, 0)


def test_dropped_half_is_refuted():
    ctx, Rbr, Rrl, ks = _h_dot_context()
    d = Derivation("half", ks * tr(Rbr * sk(Rbr.T * Rrl)), ctx)
    d.equals(ks * tr(Rrl - Rrl.T * Rbr * Rbr), by_algebra("factor 1/2 dropped"))
    _assert_refuted(d, 0)


def test_moved_transpose_is_refuted():
    ctx, Rbr, Rrl, ks = _h_dot_context()
    d = Derivation("transpose", ks * tr(Rbr * sk(Rbr.T * Rrl)), ctx)
    d.equals(HALF * ks * tr(Rrl - Rrl * Rbr.T * Rbr), by_algebra("transpose moved"))
    _assert_refuted(d, 0)


def test_wrong_boundary_condition_is_refuted_with_an_algebraic_angle():
    ctx = Context("boundary")
    xi, theta = ctx.unit_vector("ξ"), ctx.angle("θ")
    R = rodrigues(xi, theta)
    wrong = ctx.condition("cosθ = 1/2", cos(theta), HALF)
    d = Derivation("wrong boundary", R * R, ctx, where=(wrong,))
    d.equals(2 * outer(xi, xi) - I3, by_algebra())
    _assert_refuted(d, 0)


def test_reversed_inequality_is_refuted():
    ctx = Context("reversed")
    xi, Rrl = ctx.unit_vector("ξ"), ctx.rotation("R_rl")
    ks = ctx.scalar("k_s", positive=True)
    P = outer(xi, xi)
    d = Derivation("reversed", ks * tr(sym(Rrl) * (I3 - P)), ctx)
    d.le(
        ks * lambda_min(sym(Rrl)) * tr(I3 - P),
        by_bound(positive(ks) * trace_lower_bound(sym(Rrl), I3 - P, gram=hat(xi))),
    )
    _assert_refuted(d, 0)


def test_reversed_v_dot_bound_is_refuted():
    loop = theorem1.ClosedLoop()
    bound = theorem1.v_dot(loop)[0].steps[1].rhs
    d = Derivation("V-dot reversed", loop.ctx.ddt(loop.V), loop.ctx).ge(
        bound, by_citation("mutated")
    )
    _assert_refuted(d, 0)


@pytest.mark.parametrize("name", sorted(PAPER))
def test_every_equality_step_of_the_paper_with_a_flipped_sign_is_refuted(name):
    """Systematic mutation: negate the right side of each equality step (not 0 = 0)."""
    mutated = 0
    for build in [PAPER[name]]:
        for d in build():
            for step in d.steps:
                if step.relation != "=" or step.rhs.op in ("zero", "const"):
                    continue
                m = Derivation(f"{d.name}-neg", step.lhs, d.context, where=d.where,
                               assumes=d.assumes)
                m.equals(-step.rhs, step.because, where=step.where)
                _assert_refuted(m, 0)
                mutated += 1
    assert mutated >= 1


# -- what is not verified --------------------------------------------------------------------
def test_a_true_step_resting_on_a_citation_is_inconclusive_not_verified():
    ctx = Context("citation")
    G = ctx.matrix("G")
    d = Derivation("cited", tr(G.T * G), ctx).ge(0, by_citation("folklore"))
    result = check(d, QUICK)
    assert result.steps[0].verdict == "inconclusive"
    assert result.steps[0].counterexample is None


def test_a_wrong_gram_premise_leaves_a_true_step_inconclusive():
    ctx = Context("premise")
    xi, Rrl = ctx.unit_vector("ξ"), ctx.rotation("R_rl")
    P = outer(xi, xi)
    d = Derivation("premise", tr(sym(Rrl) * (I3 - P)), ctx).ge(
        lambda_min(sym(Rrl)) * tr(I3 - P),
        by_bound(trace_lower_bound(sym(Rrl), I3 - P, gram=2 * hat(xi))),
    )
    step = check(d, QUICK).steps[0]
    assert step.verdict == "inconclusive"
    assert "premise fails" in step.exact or "not the sum" in step.exact


def test_a_certificate_that_does_not_add_up_is_not_accepted():
    ctx = Context("sum")
    G = ctx.matrix("G")
    d = Derivation("sum", 2 * tr(G.T * G), ctx).ge(0, by_bound(square(G)))
    assert check(d, QUICK).steps[0].verdict == "inconclusive"


# -- language errors -----------------------------------------------------------------------------
def test_floats_and_shape_errors_are_refused_where_written():
    ctx = Context("errors")
    R, v = ctx.rotation("R"), ctx.vector("v")
    with pytest.raises(ProofSyntaxError, match="Fraction"):
        _ = 0.5 * R
    with pytest.raises(ProofSyntaxError, match="equal shapes"):
        _ = R + v
    with pytest.raises(ProofSyntaxError, match="no dynamics"):
        ctx.ddt(tr(R))
    d = Derivation("mix", tr(R), ctx).le(3, by_citation("x"))
    with pytest.raises(ProofSyntaxError, match="mix"):
        d.ge(-1, by_citation("x"))


def test_ipopt_finds_a_violation_confined_to_a_small_region():
    """tr R >= -1 + 1/1000 fails only within ~0.045 rad of angle pi; one random point and
    one hypothesis example will not see it, the slack minimisation does."""
    ctx = Context("small region")
    R = ctx.rotation("R")
    d = Derivation("near pi", tr(R), ctx).ge(-1 + Fraction(1, 1000), by_citation("mutated"))
    cfg = SearchSettings(samples=1, hypothesis_examples=1, ipopt_starts=2, seed=3)
    result = check(d, cfg)
    step = result.steps[0]
    assert step.verdict == "refuted"
    assert step.falsification["ipopt_runs"] >= 1
    assert _violation_at_counterexample(d, 0, step.counterexample) > 0


def test_matrix_chains_may_end_in_zero():
    ctx = Context("zero")
    R = ctx.rotation("R")
    d = Derivation("skew of identity", sk(R.T * R), ctx).equals(0, by_algebra("RᵀR = I"))
    assert check(d, QUICK).verdict == "verified"
