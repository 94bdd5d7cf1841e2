"""The figure of a passivity decision: nu(w) and the relative index R(w) (paper, Section 4).

``verify gate MODEL --plot FILE`` draws what the gate decided, in the two views a control
engineer knows:

* top, nu(w) = lambda_min(H(jw) + H(jw)^H)/2 (the paper's passivity index of Section 4,
  MATLAB's ``passiveplot(G, "input")``), with the zero line, the margin nu0 when one was
  asked for, the band [w1, w2] when the question was about a band, the smallest nu found
  (Hamiltonian level crossings) and, for a *not passive* verdict, the exact witness
  frequency w* at which v^H (H + H^H) v < 0 was checked in rational arithmetic;
* bottom, the relative passivity index R(w) = sigma_max((I - H)(I + H)^-1) (MATLAB's
  ``passiveplot(G)``) with the line R = 1 and the shortage R > 1 shaded: R(w) <= 1
  exactly where nu(w) >= 0 (a log axis when R spans more than a decade).

The curves are floating point and only illustrate: the verdict, its certificate or its
witness rest on exact arithmetic (:mod:`verify.passivity.decision`,
:mod:`verify.passivity.band`), and the figure's caption line says which. A negative
dip that is small beside the curve's range (the reconstructions' -1e-4 tail beside
values near 1) is drawn on a symmetric-log axis so it stays visible.

The figure is rendered in memory with no date or version stamp
(:func:`verify.artefacts.figure_bytes.figure_bytes`) and written with a temporary file
and a rename (:func:`verify.artefacts.atomic.write_atomic`); PNG, PDF or SVG (vector, as
the HTML report's figures) by the file's suffix. :func:`passivity_figure_bytes` is the
reusable part (a report can embed it).
"""

from __future__ import annotations

import math
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np

from verify.artefacts.atomic import write_atomic
from verify.artefacts.figure_bytes import figure_bytes
from verify.errors import VerifyInputError
from verify.inputs.number_text import short_text
from verify.inputs.numbers import to_float

#: Suffixes ``--plot`` accepts, and the format each is written in.
FORMATS = {".png": "png", ".pdf": "pdf", ".svg": "svg"}
#: How a verdict line names a witness that is not a frequency.
WITNESS_WORDS = {
    "infinity": r"$D + D^{\mathsf{T}}$ is not PSD, so $\nu(\omega) < 0$ as $\omega \to \infty$",
    "rhp-point": r"a point $s^* > 0$ where $H(s^*) + H(s^*)^{\mathsf{T}}$ is not PSD",
    "unstable-pole": "a pole in Re s > 0",
    "pole-at-zero": "a pole at s = 0 that is not simple or not PSD",
    "negative-minor-sum": r"a principal-minor sum of $H + H^{\mathsf{H}}$ is negative in the band",
}
#: A negative dip smaller than this fraction of the curve's range gets a symlog axis.
SMALL_DIP = 0.02
#: ... but only a dip above float resolution: a smaller one is noise of the float curve
#: (the exact witness, if any, is marked all the same).
RESOLVED = 1e-9


def figure_format(path: Path, flag: str = "--plot") -> str:
    """``png``, ``pdf`` or ``svg`` from the file's suffix; a one-line error for anything
    else."""
    fmt = FORMATS.get(Path(path).suffix.lower())
    if fmt is None:
        raise VerifyInputError(f"{flag} {str(path)!r}: the file name must end in .png, .pdf "
                               "or .svg (the format is chosen by the suffix), e.g. nu.svg")
    return fmt


def frequency_grid(model: Any, marks: list[float], points: int = 1200) -> np.ndarray:
    """Log-spaced frequencies two decades around the poles and the marked frequencies,
    with the marks themselves inserted (so the curve passes through them)."""
    mags = [abs(p) for p in (np.linalg.eigvals(model.A) if model.n and
                             np.all(np.isfinite(model.A)) else []) if abs(p) > 0]
    finite = [w for w in marks if w > 0 and math.isfinite(w)]
    scale = mags + finite
    lo = min([1e-2, *(x / 100 for x in scale)])
    hi = max([1e2, *(x * 100 for x in scale)])
    # whole hundredths of a decade: the poles' last bits (BLAS-dependent) do not move the grid
    w = np.logspace(math.floor(100 * math.log10(lo)) / 100,
                    math.ceil(100 * math.log10(hi)) / 100, points)
    return np.unique(np.concatenate([w, np.array(finite, dtype=float)]))


def _curves(model: Any, w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """nu(w) and R(w) in floating point; NaN where H(jw) is undefined (a pole)."""
    from verify.passivity.api import _relative

    m = model.m
    H = np.full((w.size, m, m), np.nan, dtype=complex)
    with np.errstate(all="ignore"):
        try:
            H = model.frequency_response(w)
        except VerifyInputError:  # a pole on the grid: point by point
            for k, wk in enumerate(w):
                try:
                    H[k] = model.frequency_response([wk])[0]
                except VerifyInputError:
                    pass
        good = np.all(np.isfinite(H), axis=(1, 2))
        nu = np.full(w.size, np.nan)
        if good.any():
            Hg = H[good]
            nu[good] = np.linalg.eigvalsh((Hg + np.conj(np.swapaxes(Hg, 1, 2))) / 2)[:, 0]
        R = np.full(w.size, np.nan)
        R[good] = _relative(H[good])
    return nu, R


def _equals(w: Fraction) -> str:
    """``= 5/2`` for a short exact rational, ``≈ 3.13945e+17`` for a long one (the sign as
    mathtext, which every font draws)."""
    text = short_text(w)
    return r"$\approx$" + text[1:] if text.startswith("≈") else f"= {text}"


def _witness_frequency(decision: Any) -> Fraction | None:
    w = getattr(decision, "witness", None)
    if w is None or w.kind != "frequency" or "omega" not in w.data:
        return None
    try:
        return Fraction(str(w.data["omega"]))
    except (ValueError, ZeroDivisionError):
        return None


def _smallest(decision: Any) -> tuple[float, float] | None:
    """(omega, nu) of the smallest nu(w) of H itself (omega = inf for w -> infinity),
    on the decision's band if it has one; floating point, from the Hamiltonian search."""
    from verify.passivity.decision import propose
    from verify.passivity.search.hamiltonian import nu_minimum

    model, band = decision.model, getattr(decision, "band", None)
    if not model.float_view_finite:
        return None
    found = propose(nu_minimum, model.A, model.B, model.C, model.D,
                    None if band is None else (float(band[0]), float(band[1])))
    if found is None or not math.isfinite(found.value):
        return None
    # to the digits the legend prints and a little more: the search's last bits depend on
    # the BLAS, and this point is inserted into the plotted grid (same figure bytes on
    # every machine)
    return _canonical(found.omega), _canonical(found.value)


def _canonical(x: float) -> float:
    """``x`` to 8 significant digits (infinity kept)."""
    return float(f"{float(x):.8g}")


def _verdict_line(decision: Any, witness: Fraction | None) -> str:
    verdict = str(decision.verdict)
    band = getattr(decision, "band", None)
    where = "" if band is None else \
        f" on [{short_text(band[0])}, {short_text(band[1])}] rad/s"
    margin = getattr(decision, "margin", Fraction(0))
    need = "" if not margin else rf" with margin $\nu_0$ = {short_text(margin)}"
    if witness is not None:
        how = rf"exact witness at $\omega^*$ {_equals(witness)} rad/s"
    elif decision.witness is not None:
        kind = decision.witness.kind
        how = "exact witness: " + WITNESS_WORDS.get(kind, kind.replace("-", " "))
    elif decision.certificate is not None:
        how = "exactly checked certificate"
    else:
        how = "no exact evidence either way"
    return f"verdict: {verdict}{where}{need} ({how}); the curves are floating point"


def passivity_figure_bytes(decision: Any, fmt: str = "png") -> bytes:
    """The figure of a :class:`~verify.passivity.decision.Decision` or
    :class:`~verify.passivity.band.BandDecision` as PNG, PDF or
    SVG bytes (module docstring); SVG is vector like the report's figures (text as paths,
    fixed ids)."""
    import warnings

    import matplotlib

    with np.errstate(all="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # curves of extreme models overflow
        fig = passivity_figure(decision)
        if fmt == "png":
            return figure_bytes(fig, fmt, dpi=150)
        if fmt == "svg":
            with matplotlib.rc_context({"svg.fonttype": "path"}):
                return figure_bytes(fig, fmt)
        with matplotlib.rc_context({"pdf.fonttype": 42}):  # TrueType, not Type 3 fonts
            return figure_bytes(fig, fmt)


def passivity_figure(decision: Any) -> Any:
    """The decision's figure as a Matplotlib ``Figure`` (Agg), for a report that embeds it
    in its own pipeline; :func:`passivity_figure_bytes` renders and closes it."""
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    model = decision.model
    band = getattr(decision, "band", None)
    margin = to_float(getattr(decision, "margin", 0) or 0)
    margin = margin if math.isfinite(margin) else 0.0  # beyond the float range: not drawn
    witness = _witness_frequency(decision)
    if witness is not None and not math.isfinite(to_float(witness)):
        witness = None  # beyond the float range: named in the caption line only
    low = _smallest(decision)
    marks = [float(x) for x in ([] if band is None else band)]
    if witness is not None:
        marks.append(float(witness))
    if low is not None and math.isfinite(low[0]):
        marks.append(float(low[0]))
    w = frequency_grid(model, marks)
    nu, R = _curves(model, w)

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.0, 6.2), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 2]})
    title = model.name.replace("$", r"\$").replace("k_s", "$k_s$")  # a user's '$' is text
    fig.suptitle(f"Passivity of {title}", fontsize=11)
    top.semilogx(w, nu, color="C0", lw=1.6, label=r"$\nu(\omega)$")
    top.axhline(0.0, color="k", lw=0.8)
    if margin:
        top.axhline(margin, color="C2", lw=1.0, ls="--",
                    label=r"margin $\nu_0$" + f" {_equals(decision.margin)}")
    for ax in (top, bottom):
        if band is not None:
            ax.axvspan(float(band[0]) if band[0] > 0 else w[0], float(band[1]),
                       color="C1", alpha=0.12, lw=0,
                       label=(rf"band $[{short_text(band[0])}, {short_text(band[1])}]$ rad/s"
                              if ax is top else None))
        if witness is not None:
            ax.axvline(float(witness), color="C3", lw=1.0, ls=":")
        ax.grid(True, which="both", alpha=0.3)
    if witness is not None:
        k = int(np.argmin(np.abs(w - float(witness))))
        top.plot([float(witness)], [nu[k]], "o", color="C3", ms=6,
                 label=r"exact witness $\omega^*$" + f" {_equals(witness)} rad/s: "
                       + (r"$v^{\mathsf{H}}(H + H^{\mathsf{H}} - 2\nu_0 I)v < 0$" if margin
                          else r"$v^{\mathsf{H}}(H + H^{\mathsf{H}})v < 0$"))
    if low is not None and math.isinf(low[0]):
        top.plot([], [], " ", label=rf"$\inf\,\nu$ = {low[1]:.3g} as $\omega \to \infty$")
    elif low is not None and (witness is None or abs(low[0] - float(witness)) > 1e-9 * max(
            1.0, low[0])):
        k = int(np.argmin(np.abs(w - low[0])))
        if math.isfinite(nu[k]):
            top.plot([w[k]], [nu[k]], "v", color="C0", ms=6,
                     label=rf"smallest $\nu$ found: {nu[k]:.3g} at $\omega$ = {w[k]:.4g} rad/s")
    from matplotlib.ticker import FuncFormatter

    finite = nu[np.isfinite(nu)]
    if finite.size:
        lo_v, hi_v = float(finite.min()), float(finite.max())
        span = max(hi_v, margin, 0.0) - min(lo_v, margin, 0.0)
        if lo_v < 0 and span > 0 and RESOLVED * span < -lo_v < SMALL_DIP * span:
            # linear on [-|min|, |min|] (the whole negative part), logarithmic above
            top.set_yscale("symlog", linthresh=-lo_v, linscale=1.5)
            top.yaxis.set_major_formatter(FuncFormatter(lambda y, _pos: f"{y:.2g}"))
            top.yaxis.set_minor_formatter(FuncFormatter(lambda y, _pos: ""))
            top.set_ylabel(r"$\nu(\omega) = \lambda_{\min}(H + H^{\mathsf{H}})/2$" "\n"
                           "(symmetric log scale)")
        else:
            top.set_ylabel(r"$\nu(\omega) = \lambda_{\min}(H + H^{\mathsf{H}})/2$")
    top.legend(loc="best", fontsize=8, framealpha=0.9)

    positive = np.where(R > 0, R, np.nan)
    shown_R = positive[np.isfinite(positive)]
    wide = shown_R.size > 0 and float(shown_R.max()) > 10 * float(shown_R.min())
    bottom.plot(w, positive, color="C4", lw=1.6, label=r"$R(\omega)$")
    bottom.set_xscale("log")
    if wide:  # a log axis only when R spans more than a decade
        bottom.set_yscale("log")
    bottom.axhline(1.0, color="k", lw=0.8, label=r"$R = 1$ ($R \leq 1 \Leftrightarrow \nu \geq 0$)")
    shortage = np.isfinite(positive) & (positive > 1 + RESOLVED)  # above float noise
    if shortage.any():
        bottom.fill_between(w, 1.0, positive, where=shortage, color="C3", alpha=0.25, lw=0,
                            label=r"shortage of passivity, $R > 1$")
    if wide:
        bottom.yaxis.set_major_formatter(FuncFormatter(lambda y, _pos: f"{y:g}"))
        bottom.yaxis.set_minor_formatter(FuncFormatter(lambda y, _pos: ""))
    bottom.set_ylabel(r"$R(\omega) = \sigma_{\max}((I - H)(I + H)^{-1})$", fontsize=9)
    bottom.set_xlabel(r"$\omega$ [rad/s]")
    bottom.legend(loc="best", fontsize=8, framealpha=0.9)
    fig.text(0.5, 0.01, _verdict_line(decision, witness), ha="center", va="bottom", fontsize=8,
             wrap=True)
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    return fig


def write_passivity_figure(decision: Any, path: Path) -> Path:
    """Write the decision's figure to ``path`` (PNG, PDF or SVG by suffix), atomically."""
    path = Path(path)
    write_atomic(path, passivity_figure_bytes(decision, figure_format(path)))
    return path


def figure_paths(target: Path, sources: list[Path]) -> list[Path]:
    """Where each model's figure goes: ``target`` itself for one model; for several, one
    file per model, ``target``'s stem joined to each model file's stem (``nu.pdf`` and
    ``a.toml``, ``b.toml`` give ``nu-a.pdf``, ``nu-b.pdf``). Two models whose file stems
    coincide are refused, as is a target that is a directory or one of the models."""
    target = Path(target)
    figure_format(target)
    if target.is_dir():
        raise VerifyInputError(f"--plot {str(target)!r} is a directory; give a file name "
                               "ending in .png, .pdf or .svg")
    if len(sources) == 1:
        paths = [target]
    else:
        stems = [Path(s).stem for s in sources]
        if len(set(stems)) != len(stems):
            raise VerifyInputError(
                "--plot with several models writes one file per model named after the "
                "model file's stem, but two model files share a stem; plot them in "
                "separate calls")
        paths = [target.with_name(f"{target.stem}-{stem}{target.suffix}") for stem in stems]
    resolved = {Path(s).resolve() for s in sources}
    for p in paths:
        if p.resolve() in resolved:
            raise VerifyInputError(f"--plot {str(p)!r} is one of the model files; choose "
                                   "another name")
    return paths


__all__ = ["FORMATS", "figure_format", "figure_paths", "frequency_grid", "passivity_figure",
           "passivity_figure_bytes", "write_passivity_figure"]
