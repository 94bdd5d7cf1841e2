"""``verify simulate``'s figures: math labels, S_h in the storage legend, ticks that do not
touch (paper, Theorem 1: V = S_r + S_rl + S_h)."""

from __future__ import annotations

from itertools import pairwise
from pathlib import Path

import pytest

import verify.sim.outputs as outputs
from verify.cli import main

MODELS = Path(__file__).resolve().parents[1] / "verify" / "data" / "models"


@pytest.fixture()
def figures(tmp_path, monkeypatch):
    """The figures of a short run, kept as Matplotlib objects (rendered all the same)."""
    kept = []
    render = outputs._png

    def keep(fig):
        fig.canvas.draw()  # lay out the ticks as in the file
        renderer = fig.canvas.get_renderer()
        fig.tick_boxes = [  # per axis, the visible tick labels' boxes, before closing
            [t.get_window_extent(renderer) for t in axis.get_ticklabels()
             if t.get_visible() and t.get_text()]
            for ax in fig.axes for axis in (ax.xaxis, ax.yaxis)]
        kept.append(fig)
        return render(fig)

    monkeypatch.setattr(outputs, "_png", keep)
    code = main(["simulate", "--n", "3", "--seconds", "2", "--model",
                 str(MODELS / "reconstructed_ks3p0.toml"), "--out", str(tmp_path)])
    assert code == 0
    return kept


def _legend(fig) -> list[str]:
    return [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().texts]


def test_storage_legend_names_every_term_including_s_h(figures):
    energy = figures[0]
    texts = _legend(energy)
    assert any("S_h" in t for t in texts) and any("V = S_r + S_{rl} + S_h" in t for t in texts)
    assert len(energy.axes[0].get_lines()) == 4  # V and its three terms


def test_labels_are_math_not_plain_ascii(figures):
    for fig in figures:
        texts = [*_legend(fig), *(ax.get_title() for ax in fig.axes),
                 *(ax.get_xlabel() for ax in fig.axes), *(ax.get_ylabel() for ax in fig.axes)]
        joined = " ".join(texts)
        for plain in ("R-bar", "lambda_min", "dbar", ">=", "|dbar"):
            assert plain not in joined, (plain, joined)


def test_tick_labels_do_not_overlap(figures):
    for fig in figures:
        assert any(fig.tick_boxes)
        for boxes in fig.tick_boxes:
            for a, b in pairwise(boxes):
                assert not a.overlaps(b), (fig.axes[0].get_title(), a, b)
