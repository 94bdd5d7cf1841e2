"""`verify gate MODEL --plot FILE`: the figure of what the gate decided (paper, Section 4).

nu(w) and the relative index R(w) with the band, the margin and the exact witness
marked; PNG, PDF or SVG by suffix, written atomically, the same bytes on every run; a bad
``--plot`` fails before any work with one line and exit 2.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from verify.cli import main
from verify.errors import VerifyInputError
from verify.passivity import decide, decide_band, load_model
from verify.passivity.figure import (
    _smallest,
    _witness_frequency,
    figure_paths,
    passivity_figure_bytes,
)

MODELS = Path(__file__).resolve().parents[1] / "verify" / "data" / "models"
KS25 = MODELS / "reconstructed_ks2p5.toml"
KS30 = MODELS / "reconstructed_ks3p0.toml"


def test_pdf_is_vector_and_png_is_png(tmp_path, capsys):
    pdf, png = tmp_path / "nu.pdf", tmp_path / "nu.png"
    assert main(["gate", str(KS25), "--plot", str(pdf), "--certificates",
                 str(tmp_path / "c")]) == 1
    assert main(["gate", str(KS25), "--plot", str(png), "--certificates",
                 str(tmp_path / "c")]) == 1
    data = pdf.read_bytes()
    assert data.startswith(b"%PDF") and b"/Subtype /Image" not in data  # no raster inside
    assert b"/Type3" not in data  # TrueType text a journal's tools can read
    assert png.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
    assert f"figure: {pdf}" in capsys.readouterr().out
    assert not list(tmp_path.glob(".*.tmp"))  # the temporary file was renamed


def test_svg_is_vector_and_reproducible(tmp_path, capsys):
    """``--plot nu.svg`` writes SVG like the report's figures: vector, text as paths, the
    same bytes on a second run."""
    svg = tmp_path / "nu.svg"
    args = ["gate", str(KS30), "--plot", str(svg), "--certificates", str(tmp_path / "c")]
    assert main(args) == 0
    first = svg.read_bytes()
    assert first.lstrip().startswith(b"<?xml") and b"<svg" in first[:2000]
    assert b"<image" not in first  # no raster inside
    assert b"<text" not in first  # glyphs as paths: no font needed to view it
    assert main(args) == 0
    assert svg.read_bytes() == first
    assert f"figure: {svg}" in capsys.readouterr().out


def test_same_bytes_on_every_run():
    d = decide(load_model(KS25))
    assert passivity_figure_bytes(d, "pdf") == passivity_figure_bytes(d, "pdf")
    assert passivity_figure_bytes(d, "png") == passivity_figure_bytes(d, "png")


def test_the_figure_marks_the_exact_witness_and_the_smallest_nu():
    d = decide(load_model(KS25))
    assert _witness_frequency(d) == Fraction(5, 2)
    omega, value = _smallest(d)
    assert 2 < omega < 3 and value < 0  # of H itself, not of H - margin
    pdf = passivity_figure_bytes(d, "pdf")
    assert len(pdf) > 5000


def test_band_and_margin_are_drawn_for_h_itself():
    """With a margin the decision sees H - nu0 I; the figure's smallest nu is of H."""
    m = load_model(KS25)
    d = decide_band(m, (0, 2), margin=Fraction(-1, 100))
    omega, value = _smallest(d)
    assert abs(omega - 2) < 1e-6 and abs(value) < 1e-6  # nu(2) = 0 for this model
    assert passivity_figure_bytes(d, "png").startswith(b"\x89PNG")


def test_several_models_one_file_each(tmp_path, capsys):
    out = tmp_path / "nu.pdf"
    code = main(["gate", str(KS25), str(KS30), "--plot", str(out), "--certificates",
                 str(tmp_path / "c")])
    assert code == 1
    assert sorted(p.name for p in tmp_path.glob("*.pdf")) == [
        "nu-reconstructed_ks2p5.pdf", "nu-reconstructed_ks3p0.pdf"]
    assert not out.exists()


@pytest.mark.parametrize("name, message", [
        ("nu", "must end in .png, .pdf or .svg"),
    ("dir.pdf", "is a directory"),
])
def test_bad_plot_targets_exit_2_before_any_work(tmp_path, capsys, name, message):
    (tmp_path / "dir.pdf").mkdir()
    certs = tmp_path / "c"
    code = main(["gate", str(KS25), "--plot", str(tmp_path / name), "--certificates",
                 str(certs)])
    err = capsys.readouterr().err
    assert code == 2 and message in err and err.count("\n") == 1
    assert not certs.exists()  # nothing decided, nothing written


def test_duplicate_stems_and_model_files_are_refused(tmp_path):
    a, b = tmp_path / "a" / "m.toml", tmp_path / "b" / "m.toml"
    with pytest.raises(VerifyInputError, match="share a stem"):
        figure_paths(tmp_path / "nu.pdf", [a, b])
    target = tmp_path / "m.pdf"
    target.write_text("x")
    with pytest.raises(VerifyInputError, match="one of the model files"):
        figure_paths(target, [target])


def test_a_tiny_negative_tail_is_visible():
    """nu -> -3e-4 beside values near 1: drawn on a symmetric-log axis whose tick labels
    include a negative number (the tail is not flattened onto the zero line)."""
    import matplotlib

    matplotlib.use("Agg", force=True)
    d = decide(([-0.0003, 1], [1, 1]))
    assert passivity_figure_bytes(d, "pdf").startswith(b"%PDF")
    from verify.passivity.figure import SMALL_DIP, _curves, frequency_grid

    w = frequency_grid(d.model, [])
    nu, _ = _curves(d.model, w)
    assert nu.min() < 0 and -nu.min() < SMALL_DIP * (nu.max() - nu.min())


def test_curves_survive_a_pole_on_the_grid():
    from verify.passivity.figure import _curves

    m = load_model(MODELS / "example_state_space.toml")
    lossless = decide(([1, 0], [1, 0, 1])).model  # s/(s^2 + 1): a pole at w = 1
    nu, R = _curves(lossless, np.array([0.5, 1.0, 2.0]))
    assert np.isnan(R[1])
    assert np.isnan(nu[1]) and np.isfinite(nu[[0, 2]]).all()
    assert np.isfinite(_curves(m, np.array([1.0]))[0]).all()


@pytest.mark.parametrize("case", ["ks25", "ks30", "band", "tail", "static"])
def test_tick_labels_and_legends_do_not_overlap(case):
    """No two tick labels of an axis touch (a symlog axis over 37 decades once did)."""
    from itertools import pairwise

    import matplotlib.pyplot as plt

    from verify.passivity.figure import passivity_figure

    d = {"ks25": lambda: decide(load_model(KS25)), "ks30": lambda: decide(load_model(KS30)),
         "band": lambda: decide_band(load_model(KS25), (0, 2), margin=Fraction(-1, 100)),
         "tail": lambda: decide(([-0.0003, 1], [1, 1])),
         "static": lambda: decide(np.eye(2))}[case]()
    fig = passivity_figure(d)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            boxes = sorted((t.get_window_extent(renderer) for t in axis.get_ticklabels()
                            if t.get_visible() and t.get_text()),
                           key=lambda b: (b.x0, b.y0))
            for a, b in pairwise(boxes):
                assert not a.overlaps(b), (case, a, b)
    plt.close(fig)


def test_names_with_dollars_and_margins_beyond_floats_draw():
    """A user's '$' in a model name is text, not mathtext; a margin beyond the float range
    (decided exactly) is named in the caption but not drawn."""
    d = decide(([1], [1, 1]), name="cost $5 k_s")
    assert passivity_figure_bytes(d, "png").startswith(b"\x89PNG")
    far = decide(([1], [1, 1]), margin="-1e400")
    assert far.verdict == "passive"
    assert passivity_figure_bytes(far, "pdf").startswith(b"%PDF")


@pytest.mark.parametrize("model,band,margin", [
    (KS25, None, Fraction(0)),
    (KS25, (Fraction(1), Fraction(10)), Fraction(0)),
    (KS30, None, Fraction(0)),
    (KS30, None, Fraction(1, 100)),
])
def test_the_report_draws_the_gate_figure_in_the_papers_font_without_missing_glyphs(
        tmp_path, model, band, margin):
    """The report embeds the gate's figure set in Computer Modern (cmr10), which has no
    Greek or approximate-sign glyphs: every such sign must be mathtext, or matplotlib
    drops it with a 'Glyph ... missing' warning and the figure shows a box."""
    import warnings

    from verify.claims.figures import gate_figure

    m = load_model(model)
    d = decide(m, margin) if band is None else decide_band(m, band)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        svg = gate_figure(d, tmp_path / "gate.svg")
    missing = [str(w.message) for w in caught if "missing from font" in str(w.message)]
    assert missing == []
    assert svg.read_bytes().startswith(b"<?xml")
    assert svg.with_suffix(".pdf").read_bytes().startswith(b"%PDF")
