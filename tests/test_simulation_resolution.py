"""A run the integrator does not resolve is never "held" (Sections 2-3 checks on
trajectories): CF4's stability bound, the error estimate against the checked quantity's
scale, the adaptive fallback, and the campaign rows, report and ``verify simulate --check``
built on them. The large-k_s sweep is the one where fixed steps of 1/120 s used to report
every property held with tolerances of about 8."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from verify.campaign.execute import HELD, UNRESOLVED, column, execute_run
from verify.campaign.report import Campaign, build_blocks, render_markdown
from verify.campaign.runs import expand
from verify.inputs.campaign_spec import PROPERTIES, load_campaign_spec
from verify.sim import properties as props
from verify.sim.checks import CHECKS, check_scenario
from verify.sim.command import SimulateSettings, build_human, build_scenario
from verify.sim.resolution import RK4_REAL_STABILITY, stable_step, step_is_stable, stiffness

H = 1.0 / 120.0
MODELS = Path(__file__).resolve().parents[1] / "verify" / "data" / "models"


def scenario(k_s: float, seconds: float = 1.0, human: str = "vr", **kw):
    s = SimulateSettings(k_s=k_s, seconds=seconds, human=human, n=4, **kw)
    return build_scenario(s, build_human(s)[0])


# ---------------------------------------------------------------- the stability bound


def test_stability_bound_matches_rk4_on_the_loops_fastest_rate():
    sc = scenario(3.0)
    assert stiffness(sc) >= 2 * 3.0
    assert step_is_stable(sc, H) and not step_is_stable(sc, 1.01 * stable_step(sc))
    assert stable_step(sc) * stiffness(sc) == pytest.approx(RK4_REAL_STABILITY)
    for k_s in (300.0, 1000.0, 1e6):
        assert not step_is_stable(scenario(k_s), H)


def test_the_bound_is_where_the_fixed_step_really_diverges():
    """At 0.9 times the bound's k_s the fixed-step run settles where a fine one does; at
    1.1 times it keeps oscillating (the bound is the method's, not a guess)."""
    k_max = RK4_REAL_STABILITY / (H * 2.0)  # 2 k_s h = 2.785 with no other rates
    for factor, settles in ((0.9, True), (1.1, False)):
        sc = scenario(factor * k_max, seconds=1.0, autonomous="zero", human="static",
                      gain=0.0)
        assert step_is_stable(sc, H) is settles
        fine = props.simulate(sc, 1.0, H / 64)
        coarse = props.simulate(sc, 1.0, H)
        gap = float(np.max(np.abs(coarse.R_l[-10:] - fine.R_l[::64][-10:])))
        assert (gap < 1e-9 if settles else gap > 1e-2), (factor, gap)


# ---------------------------------------------------------------- the checks


@pytest.mark.parametrize("k_s", [300.0, 1000.0, 1e6])
def test_fixed_pair_beyond_stability_is_unresolved_never_held(k_s):
    sc = scenario(k_s)
    pair = props.RunPair.of(sc, 1.0, H)
    assert not pair.stable
    for name, check in CHECKS.items():
        result = check(pair)
        assert result.status is props.Status.UNRESOLVED and result.holds is None, name
        assert not result.resolved and result.conclusion is None
        assert "UNRESOLVED" in result.line()


def test_error_estimate_above_the_scale_is_unresolved():
    """A stable step whose estimate is too large for the quantity: unresolved."""
    sc = scenario(3.0)
    pair = props.RunPair.of(sc, 1.0, H)
    assert pair.unresolved(0.02, 1.0) and not pair.unresolved(0.005, 1.0)
    assert pair.unresolved(float("nan"), 1.0)  # NaN never passes as resolved
    result = props._result("x", 0.0, 0.5, {}, "", pair.unresolved(0.5, 1.0))
    assert result.status is props.Status.UNRESOLVED and result.holds is None


def test_large_ks_sweep_adaptive_resolves_or_reports_unresolved():
    """k_s = 300, 1000 at h = 1/120: the adaptive engine resolves them and its verdicts
    agree with a fixed-step pair at a stable step; k_s = 1e6: no engine within budget."""
    for k_s in (300.0, 1000.0):
        sc = scenario(k_s, seconds=1.0)
        checked = check_scenario(sc, 1.0, H)
        assert checked.engine.startswith("adaptive") and checked.resolved
        reference = props.RunPair.of(sc, 1.0, H / 32)  # stable: 2 k_s h <= 0.63
        assert reference.stable
        for name, result in checked.results.items():
            truth = CHECKS[name](reference)
            assert result.status == truth.status, (k_s, name, result.line(), truth.line())
    checked = check_scenario(scenario(1e6), 1.0, H)
    assert checked.engine == "none" and checked.pair is None
    assert all(r.status is props.Status.UNRESOLVED for r in checked.results.values())


def test_stealthiness_reuses_the_pair():
    """One pair per run: stealthiness on the pair equals the old three-pair version."""
    sc = scenario(3.0, autonomous="consensus")
    pair = props.RunPair.of(sc, 1.0, H)
    shared = props.stealthiness(pair)
    alone = props.stealthiness(sc, 1.0, H)
    assert shared.violation == alone.violation and shared.tolerance == alone.tolerance
    assert shared.status == alone.status == props.Status.HELD
    zero = props.RunPair.of(scenario(3.0, autonomous="zero"), 1.0, H)
    assert props.stealthiness(zero).violation == 0.0  # the pair is its own reference


# ---------------------------------------------------------------- campaign rows and report

SWEEP = """name = "large gains"
[sweep]
k_s = [300, 1000, 1e6]
n = 4
seeds = [0]
seconds = 1
step = "1/120"
[[humans]]
kind = "vr"
[checks]
properties = ["stealthiness", "quasi-average", "lemma1", "lyapunov", "lasalle"]
"""


def test_large_ks_sweep_rows_hold_nothing_unresolved(tmp_path):
    (tmp_path / "spec.toml").write_text(SWEEP)
    spec = load_campaign_spec(tmp_path / "spec.toml")
    runs = expand(spec)
    rows = {r.key: execute_run(r) for r in runs}
    by_ks = {r.k_s: rows[r.key] for r in runs}
    assert all(row["error"] is None for row in rows.values())
    assert by_ks[1e6]["engine"] == "none"
    assert all(by_ks[1e6][column(p)] == UNRESOLVED for p in PROPERTIES)
    assert by_ks[1e6]["convergence_time"] is None and by_ks[1e6]["max_V_rise"] is None
    for k in (300.0, 1000.0):
        assert by_ks[k]["engine"].startswith("adaptive")
        assert UNRESOLVED not in {by_ks[k][column(p)] for p in PROPERTIES}
    text = render_markdown(build_blocks(Campaign(spec, runs, rows))[0])
    assert text.count("held in 0 of 1; 1 unresolved (integration)") == len(PROPERTIES)
    assert "## Runs the integration did not resolve (1)" in text
    assert "adaptive rtol=1e-07 2" in text and "none 1" in text


def test_simulate_check_prints_unresolved(tmp_path, capsys):
    from verify.cli import main

    code = main(["simulate", "--ks", "1e6", "--seconds", "1", "--check", "--no-plots",
                 "--n", "4", "--out", str(tmp_path / "o")])
    out = capsys.readouterr().out
    assert code == 0 and "WARNING: the step" in out
    lines = [ln for ln in out.splitlines() if ln.startswith("    ")]
    assert len(lines) == 5 and all("UNRESOLVED" in ln for ln in lines)
    assert not any(": holds" in ln for ln in lines)


# ---------------------------------------------------------------- what held anyway

NONPASSIVE = f"""name = "non-passive"
[sweep]
k_s = [3.0]
n = 3
seeds = [0, 1]
seconds = 25
step = "1/60"
autonomous = "zero"
[[humans]]
model = "{(MODELS / 'reconstructed_ks2p5.toml').as_posix()}"
[checks]
properties = ["lyapunov", "lasalle"]
"""


def test_report_shows_conclusions_held_without_the_assumption(tmp_path):
    """The k_s = 2.5 human is not passive (Theorem 1's item 5 fails): the rows keep the
    conclusion, and the report says where it held anyway instead of only greying it."""
    (tmp_path / "spec.toml").write_text(NONPASSIVE)
    spec = load_campaign_spec(tmp_path / "spec.toml")
    runs = expand(spec)
    rows = {r.key: execute_run(r) for r in runs}
    for row in rows.values():
        assert row["human_gate"] == "not passive" and row["lasalle"] == "assumption-failed"
        converged = row["lasalle_violation"] <= row["lasalle_tolerance"]
        assert row["lasalle_conclusion"] == ("held" if converged else "failed")
    anyway = sum(row["lasalle_conclusion"] == HELD for row in rows.values())
    assert anyway >= 1  # the reconstructed model converges in these runs
    text = render_markdown(build_blocks(Campaign(spec, runs, rows))[0])
    assert "## What held outside the assumptions" in text
    assert f"outside the assumptions in all 2: conclusion held in {anyway}" in text
    assert f"| lasalle | reconstructed k_s = 2.5 [not passive] | 2 | {anyway}, at k_s = 3 |" \
        in text


# ---------------------------------------------------------------- attacks on "resolved"


def test_attack_stable_but_inaccurate_step_is_not_a_false_verdict():
    """2 k_s h = 2.6: inside the stability bound but far from accurate. Whatever the
    checks say must be what a fine, stable pair says, or unresolved."""
    k_s = 2.6 / (2 * H)
    sc = scenario(k_s, seconds=1.0, autonomous="zero", human="static", gain=0.0)
    assert step_is_stable(sc, H)
    checked = check_scenario(sc, 1.0, H)
    reference = props.RunPair.of(sc, 1.0, H / 16)
    for name, result in checked.results.items():
        if result is not None and result.resolved:
            assert result.status == CHECKS[name](reference).status, (name, result.line())


def test_attack_a_stiff_human_with_a_small_gain():
    """k_s = 1 but the human's state decays at 1e4 /s: the bound counts the human's rate,
    so the fixed 1/120 s step is not trusted and nothing is held on it."""
    import numpy as np

    from verify.sim.humans import LTIHuman

    stiff = LTIHuman(-1e4 * np.eye(2), 1e4 * np.eye(2), np.eye(2), np.zeros((2, 2)))
    sc = scenario(1.0, seconds=0.5, autonomous="zero")
    sc.human = stiff
    assert stiffness(sc) >= 1e4 and not step_is_stable(sc, H)
    pair = props.RunPair.of(sc, 0.5, H)
    assert all(CHECKS[p](pair).status is props.Status.UNRESOLVED for p in CHECKS)
    checked = check_scenario(sc, 0.5, H)
    assert checked.engine != "fixed"
    assert all(r.status is not props.Status.HELD for r in checked.results.values()
               if r is not None and not r.resolved)
