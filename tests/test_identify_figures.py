"""Figures of an identification: reproducible bytes, drawn from what they are given."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
from identify_models import PAPER_THETA, correlated_covariance

from verify.identify import figures as fg
from verify.identify.estimate.structure import Structure

OMEGA = np.geomspace(1e-2, 60, 200)


def test_figures_are_reproducible_pngs():
    theta = np.array(PAPER_THETA)
    cov = correlated_covariance(PAPER_THETA)
    t = np.arange(0, 5, 0.05)
    y = np.column_stack([np.sin(t), np.cos(t)])
    make = (
        lambda: fg.validation_figure([t, t], [y, y], [0.9 * y, 0.8 * y], [81.0, 64.0]),
        lambda: fg.bode_figure(Structure.paper(), theta, cov, 18.3, OMEGA, Fraction(19, 20)),
        lambda: fg.nu_figure(Structure.paper(), theta, OMEGA, (0.0, 6.7), (0.0, 5.0)),
    )
    for draw in make:
        a, b = draw(), draw()
        assert a[:8] == b"\x89PNG\r\n\x1a\n" and a == b


def test_ellipsoid_samples_lie_in_the_ellipsoid():
    theta = np.array(PAPER_THETA)
    cov = correlated_covariance(PAPER_THETA)
    pts = fg.ellipsoid_samples(theta, cov, 18.3, count=300)
    d = pts - theta
    q = np.einsum("ki,ij,kj->k", d, np.linalg.inv(cov), d)
    assert np.all(q <= 18.3 * (1 + 1e-9)) and q.max() > 0.5 * 18.3


def _drawn_axes(monkeypatch, values: np.ndarray) -> list:
    """The axes nu_figure draws for the given nu values (the figure is caught before it
    becomes bytes)."""
    import verify.identify.robust.verdict as verdict

    caught = []
    monkeypatch.setattr(verdict, "float_nu", lambda structure, center, omega: values)
    monkeypatch.setattr(fg, "figure_bytes", lambda fig: caught.append(fig) or b"")
    fg.nu_figure(Structure.paper(), np.array(PAPER_THETA), OMEGA, None, None)
    (fig,) = caught
    return fig.axes


def test_a_tiny_negative_tail_of_nu_gets_a_zoomed_panel(monkeypatch):
    """The passive human's nu dips to about -1.4e-4 beside values near 0.6: at full scale
    that is the zero line, so a second panel shows it, its lower limit below the dip."""
    values = 0.6 * np.exp(-OMEGA) - 1.4e-4 * (OMEGA > 30)
    axes = _drawn_axes(monkeypatch, values)
    assert len(axes) == 2
    low, high = axes[1].get_ylim()
    assert low < -1.4e-4 < 0 < high < 1e-3
    assert any("not passive" in t.get_text() for t in axes[1].get_legend().get_texts())


def test_a_visible_negative_part_needs_no_zoom(monkeypatch):
    values = 0.6 * np.exp(-OMEGA) - 0.05 * (OMEGA > 3)
    assert len(_drawn_axes(monkeypatch, values)) == 1
