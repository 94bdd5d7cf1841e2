"""Dropping an assumption of Lemma 1 or Theorem 1 breaks its conclusion (Assumption 1, 2 and 5)."""

from __future__ import annotations

import numpy as np
import sympy as sp

from verify import so3
from verify.sim import counterexamples as cx
from verify.sim import properties as props
from verify.sim.humans import StaticGainHuman
from verify.sim.inputs import Reference
from verify.sim.scenario import Scenario


def test_exact_boundary_state_with_negative_h_dot():
    w = cx.lemma1_boundary_witness()
    assert w is not None
    assert w.R_bar.T * w.R_bar == sp.eye(3) and w.R_l.T * w.R_l == sp.eye(3)
    assert w.R_bar.det() == 1 and w.R_l.det() == 1
    assert w.h == 0 and w.h_dot < 0 and w.lambda_min_sym_rl <= 0
    # the same h' from the simulator's vector field, in floats
    R_bar, R_l = (np.array(M.tolist(), dtype=float) for M in (w.R_bar, w.R_l))
    h_dot = np.trace(R_bar @ so3.sk(R_bar.T @ R_l))
    assert abs(h_dot - float(w.h_dot)) < 1e-14


def test_with_item_2_sym_rl_positive_no_boundary_state_has_negative_h_dot():
    """Lemma 1's boundary argument: on tr(R-bar_r) = 1 with sym(R_rl) > 0, h' >= 0."""
    R_bar = cx._rational_rotation((1, 1, 0, 0))
    for q in cx._small_quaternions():
        R_l = cx._rational_rotation(q)
        if (R_l + R_l.T).is_positive_definite:
            M = R_bar.T * R_l
            assert (R_bar * (M - M.T) / 2).trace() >= 0


def test_simulated_lemma1_counterexample_is_found_shrunk_and_confirmed():
    found = cx.lemma1_counterexample(budget=60)
    assert found is not None and found.confirmed
    assert found.parameters["lambda_min(sym R_rl(0))"] < 0  # item 2 fails at the start
    assert found.parameters["tr(R-bar_r(0))"] >= 1  # Lemma 1's own premise holds
    assert found.measure > 1e-3
    _check_figure(found)


def _check_figure(found) -> None:
    """The run's figure: SVG and PDF (vector, no raster inside), both panels with a
    y-axis label, set in Computer Modern; the same bytes when drawn twice."""
    import re
    from unittest import mock

    from verify.sim import outputs
    from verify.sim.energy import energy

    E = energy(found.trajectory, False)
    files = outputs.counterexample_figure(found.trajectory, E, r"$\mathrm{tr}\,\bar R_r$")
    assert files["pdf"].startswith(b"%PDF-") and b"<svg" in files["svg"][:400]
    assert b"<image" not in files["svg"] and b"/Subtype /Image" not in files["pdf"]
    assert files == outputs.counterexample_figure(found.trajectory, E,
                                                  r"$\mathrm{tr}\,\bar R_r$")
    with mock.patch("verify.artefacts.figure_bytes.vector_figures",
                    side_effect=lambda fig: fig) as caught:
        fig = outputs.counterexample_figure(found.trajectory, E, "t")
    assert caught.called
    assert all(ax.get_ylabel() for ax in fig.axes)
    fonts = set(re.findall(rb"/BaseFont /(?:[A-Z]{6}\+)?(\w+)", files["pdf"]))
    assert fonts and all(f.lower().startswith(b"cm") for f in fonts), fonts  # no DejaVu


def test_non_passive_lagging_human_breaks_convergence():
    found = cx.passivity_counterexample(cx.lagging_human(), budget=20, examples=10)
    assert found is not None and found.confirmed
    assert found.parameters["min supply int e^T omega_h^b"] < -1.0  # supply unbounded below


def test_lemma1_property_is_checked_until_the_premise_is_lost():
    scenario = Scenario(so3.exp(np.array([[0.0, 1.0, 0.0]])), 1.0, StaticGainHuman(np.eye(2)),
                        Reference.constant(np.eye(3)),
                        R_l0=so3.exp(np.array([0.0, 1.4, 0.0])))
    result = props.lemma1_invariance(props.RunPair.of(scenario, 2.0, 1 / 60))
    assert result.holds is True, result.line()


def test_search_budget_never_makes_hypothesis_replay_flaky():
    """Past its budget the search answers 'no' for new parameters only: the example it
    found still fails when hypothesis replays it (a changed answer raised FlakyFailure)."""
    from hypothesis import strategies as st

    from verify.sim.counterexamples import _search

    runs = []

    def fails(x: int) -> bool:
        runs.append(x)
        return x > 10

    for budget in (1, 3, 8, 40):
        runs.clear()
        found, calls = _search(st.integers(0, 10_000), fails, budget, 60)
        assert calls == len(runs) <= budget
        assert found is None or found > 10
