"""Arguments of the wrong kind given to the public API: one clear message each.

Every message names what was expected, the argument and its value, and the fix
(verify.validation); none of these may fail later with an AttributeError or be
silently accepted.
"""

import numpy as np
import pytest
from hypothesis.errors import InvalidArgument

from verify import so3, strategies
from verify.errors import VerifyInputError
from verify.proof import (
    Context,
    Derivation,
    ProofSyntaxError,
    assumed,
    by_algebra,
    by_bound,
    positive,
    square,
    tr,
)


@pytest.fixture
def ctx():
    return Context("arguments")


@pytest.fixture
def R(ctx):
    return ctx.rotation("R")


def test_positive_of_a_number_names_the_fix():
    with pytest.raises(ProofSyntaxError, match=r"but got k=2; declare it with "
                                               r"ctx\.scalar\(name, positive=True\)"):
        positive(2)


def test_positive_of_an_undeclared_scalar_says_why(ctx):
    x = ctx.scalar("x")
    with pytest.raises(ProofSyntaxError, match="x is not a variable declared positive"):
        positive(x)


def test_square_of_a_float_names_the_argument():
    with pytest.raises(ProofSyntaxError, match=r"Expected an expression .* but got g=1\.5; "
                                               r"did you mean"):
        square(1.5)


def test_assumed_of_an_expression_suggests_ctx_assume(ctx, R):
    with pytest.raises(ProofSyntaxError, match=r"assumption=Expr\(tr\(R\)\).*did you mean "
                                               r"assumed\(ctx\.assume\("):
        assumed(tr(R))


@pytest.mark.parametrize("factory", [by_algebra, by_bound])
def test_justification_passed_without_calling_it(ctx, R, factory):
    d = Derivation("d", tr(R), ctx)
    name = factory.__name__
    with pytest.raises(ProofSyntaxError, match=rf"because={name} \(the function itself\); "
                                               rf"did you mean {name}\(\)\?"):
        d.equals(tr(R), factory)
    assert d.steps == []


def test_justification_of_another_kind(ctx, R):
    with pytest.raises(ProofSyntaxError, match=r"because='algebra'"):
        Derivation("d", tr(R), ctx).equals(tr(R), "algebra")


def test_unknown_assumption_kind_lists_the_valid_ones(ctx, R):
    with pytest.raises(ProofSyntaxError, match=r"one of 'pd', 'psd', 'pos', 'nonneg', but "
                                               r"got kind='positive'"):
        ctx.assume("a", tr(R), "positive")


@pytest.mark.parametrize("v", [[1.0, 2.0, 3.0, 4.0], [1.0, 2.0], np.zeros((5, 4)), 3.0])
def test_hat_refuses_anything_but_3_vectors(v):
    with pytest.raises(VerifyInputError, match=r"Expected vectors of shape \(\.\.\., 3\), but "
                                               r"got v="):
        so3.hat(v)


def test_hat_of_3_vectors_unchanged():
    v = np.array([[1.0, 2.0, 3.0], [0.0, -1.0, 0.5]])
    H = so3.hat(v)
    assert H.shape == (2, 3, 3)
    np.testing.assert_array_equal(H @ np.array([0.0, 0.0, 1.0]), np.cross(v, [0.0, 0.0, 1.0]))


@pytest.mark.parametrize("angle", [7.0, -0.1, float("nan"), True, "pi"])
def test_rotations_near_angle_outside_0_pi_is_refused(angle):
    with pytest.raises(InvalidArgument, match=rf"but got angle={angle!r}"):
        strategies.rotations_near_angle(angle)


def test_strategy_options_are_keyword_only():
    with pytest.raises(TypeError):
        strategies.networks(1, 5)
    with pytest.raises(TypeError):
        strategies.rotations_near_angle(1.0, 1e-3)
    with pytest.raises(TypeError):
        strategies.passive_lti_models(3)


@pytest.mark.parametrize("call, name", [
    (lambda: strategies.networks(max_bodies=0), "max_bodies=0"),
    (lambda: strategies.networks(min_bodies=5, max_bodies=2), "max_bodies=2"),
    (lambda: strategies.near_cancelling_networks(max_bodies=1.5), "max_bodies=1.5"),
    (lambda: strategies.passive_humans(max_states=0), "max_states=0"),
    (lambda: strategies.scenarios(autonomous=("zero", "chaos")), "autonomous='chaos'"),
    (lambda: strategies.scenarios(humans=strategies.passive_humans), "humans=passive_humans"),
])
def test_strategy_options_checked_when_built(call, name):
    with pytest.raises(InvalidArgument, match=f"but got {name}"):
        call()
