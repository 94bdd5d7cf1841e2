"""nu(w) and its minimum by Hamiltonian level crossings (paper, Section 4)."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest

from verify.passivity.decision import NOT_PASSIVE, candidate_frequencies, decide
from verify.passivity.model import from_state_space
from verify.passivity.search.hamiltonian import LEVEL_GAP, level_crossings, nu_minimum, nu_values


def arrays(A, B, C, D):
    return [np.atleast_2d(np.array(x, dtype=float)) for x in (A, B, C, D)]


def notch(z: float = 1e-5, w0: float = 3.7, depth: float = 1.02):
    """1 + 1/(s+100) - k s/(s^2 + 2 z w0 s + w0^2) with k = depth 2 z w0: Re of the
    resonance term is depth at w0 and falls off within ~z w0, so nu < 0 only on a band
    of relative width ~1e-5 around w0, far narrower than any sweep's spacing."""
    k = depth * 2 * z * w0
    return arrays([[0, 1, 0], [-w0**2, -2 * z * w0, 0], [0, 0, -100]], [[0], [1], [1]],
                  [[0, -k, 1]], [[1]])


@pytest.mark.parametrize(
    "system, omega, value",
    [
        (arrays([[-1]], [[1]], [[1]], [[0]]), math.inf, 0.0),  # 1/(s+1): inf at infinity
        (arrays([[-1]], [[1]], [[1]], [[1]]), math.inf, 1.0),  # (s+2)/(s+1)
        # 1/(s^2+s+1): with t = w^2 - 1, Re h = -t/(t^2 + t + 1), least at t = 1: -1/3
        (arrays([[0, 1], [-1, -1]], [[0], [1]], [[1, 0]], [[0]]), math.sqrt(2), -1 / 3),
    ],
)
def test_known_minima(system, omega, value):
    found = nu_minimum(*system)
    assert found.value == pytest.approx(value, abs=1e-9)
    if math.isinf(omega):
        assert found.at_infinity
    else:
        assert found.omega == pytest.approx(omega, rel=1e-6)
    assert found.lower <= found.value


def test_reconstructed_ks2p5_minimum_and_band():
    """Diagonal (0.5 s + 1)/(s^2 + s + 2), skew constant coupling: nu = Re h."""
    from verify.passivity.io.model_file import load_model

    m = load_model("verify/data/models/reconstructed_ks2p5.toml")
    x = np.linspace(0, 50, 500001)  # w^2; Re h = (2 - x/2)/((2 - x)^2 + x)
    reference = float(np.min((2 - x / 2) / ((2 - x) ** 2 + x)))
    found = nu_minimum(m.A, m.B, m.C, m.D)
    assert found.value == pytest.approx(reference, rel=1e-6) and 2 < found.omega < 3
    on_band = nu_minimum(m.A, m.B, m.C, m.D, band=(0.0, 1.5))
    assert on_band.omega == pytest.approx(1.5) and on_band.value > 0


def test_crossings_are_where_nu_meets_the_level():
    A, B, C, D = arrays([[0, 1], [-1, -1]], [[0], [1]], [[1, 0]], [[0]])
    assert level_crossings(A, B, C, D, 0.0) is None  # R = D + D^T = 0: the test does not apply
    crossings = level_crossings(A, B, C, D, -0.2)  # Re h = -1/5 at w^2 = 3 -+ sqrt 3
    expected = [math.sqrt(3 - math.sqrt(3)), math.sqrt(3 + math.sqrt(3))]
    assert crossings is not None and crossings == pytest.approx(expected)
    assert nu_values(A, B, C, D, crossings) == pytest.approx([-0.2, -0.2])


def test_a_narrow_notch_between_grid_points_is_found_and_witnessed_exactly():
    A, B, C, D = notch()
    swept, _ = candidate_frequencies(A, B, C, D)
    assert swept == []  # the sweep alone misses the violation
    found = nu_minimum(A, B, C, D)
    assert found.value < 0 and found.omega == pytest.approx(3.7, rel=1e-6)
    d = decide(from_state_space(A, B, C, D, name="notch"))
    assert d.verdict == NOT_PASSIVE and d.witness.kind == "frequency"
    assert abs(float(Fraction(d.witness.data["omega"])) - 3.7) < 1e-4


def _random_stable(rng, n: int, m: int):
    A = rng.normal(size=(n, n))
    A -= (np.max(np.linalg.eigvals(A).real) + rng.uniform(0.05, 1.0)) * np.eye(n)
    return A, rng.normal(size=(n, m)), rng.normal(size=(m, n)), rng.normal(size=(m, m))


def _check_against_grid(seed: int, count: int) -> None:
    """The located minimum is a value of nu at a point, no more than the level gap above a
    dense grid's minimum, and the certified-by-crossings level lies below that minimum."""
    rng = np.random.default_rng(seed)
    grid = np.concatenate([[0.0], np.logspace(-3, 3, 20001), [math.inf]])
    for _ in range(count):
        A, B, C, D = _random_stable(rng, int(rng.integers(1, 6)), int(rng.integers(1, 3)))
        found = nu_minimum(A, B, C, D)
        reference = float(np.nanmin(nu_values(A, B, C, D, grid)))
        scale = max(1.0, abs(reference))
        assert found.lower <= reference + 1e-12 * scale
        assert found.value <= reference + 2 * LEVEL_GAP * scale
        again = nu_values(A, B, C, D, np.array([found.omega]))[0]
        assert again == pytest.approx(found.value, abs=1e-12)


def test_random_models_against_a_dense_grid():
    _check_against_grid(seed=7, count=8)


@pytest.mark.slow
def test_random_models_against_a_dense_grid_deep():
    _check_against_grid(seed=8, count=200)
