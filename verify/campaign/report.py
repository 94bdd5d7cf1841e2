"""The campaign report: where the properties held over the swept parameters, and why not.

In: the campaign's runs (in spec order) and their stored rows. Out: Markdown and HTML
with figures (PNG bytes that depend only on the data, :mod:`verify.artefacts.figure_bytes`)
and ``commands.txt`` (one ``verify simulate`` line per run). Sections:

* the humans, each with the passivity gate's verdict on its model file
  (:func:`verify.passivity.decide`, exact; computed once per file content). Theorem 1
  assumes a passive human (Assumption 1, item 5), so a run with a human that is not
  passive is outside the theorem whatever its outcome;
* per property, a map over k_s and the other swept parameters: how many runs held,
  failed, or had an assumption fail along the trajectory (Lemma 1 needs sym(R_rl) > 0;
  Theorem 1's convergence a constant reference and a storage function);
* the convergence time of |dbar - d_r| against k_s per human (median and range over
  seeds; the first time after which it stays below the threshold);
* the runs that failed a property or raised, with parameters and the command that
  reproduces each.

The text is a function of the spec and the rows, except the final "Timings" block
(wall times, workers), kept last so that two reports of the same campaign differ only
there.
"""

from __future__ import annotations

import functools
import html
import math
import re
import statistics
from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from verify.artefacts.html_style import REPORT_CSS
from verify.campaign.execute import (
    ASSUMPTION,
    FAILED,
    HELD,
    NOT_APPLICABLE,
    NOT_CHECKED,
    UNRESOLVED,
    column,
)
from verify.campaign.reproduce import simulate_command
from verify.campaign.runs import Human, Run
from verify.inputs.campaign_spec import CampaignSpec

TIMINGS_HEADING = "Timings (not reproducible)"
MAX_LISTED = 200  # failing runs listed in the report text (all are in commands.txt)

PROPERTY_TITLE = {
    "stealthiness": "Stealthiness (Section 2: d̄ unchanged by the autonomous input)",
    "quasi-average": "R̄ e₃ = d̄ (Section 3)",
    "lemma1": "Lemma 1 (tr R̄_r ≥ 1 while sym R_rl ≻ 0)",
    "lyapunov": "Theorem 1: V non-increasing, V̇ below eq. (9)",
    "lasalle": "Theorem 1: convergence (‖d̄ − d_r‖ to 10 % of its peak by T)",
}

#: What a cell of the property tables and maps shows, worst first: its colour class (HTML),
#: its colour (figure) and its meaning (legend). "Outside the assumptions": an assumption
#: of the claim failed along the run (for Theorem 1, e.g. a human with no passivity
#: certificate), so the paper promises nothing there; the conclusion is checked anyway.
CATEGORIES = (
    ("failed", "#e06666", "failed under the assumptions"),
    ("unresolved", "#ffd966", "unresolved by the integration, or raised"),
    ("failed-outside", "#f6b26b", "failed outside the assumptions (no promise broken)"),
    ("held-outside", "#9fc5e8", "held, some runs outside the assumptions"),
    ("held", "#b6d7a8", "held in every run"),
    ("none", "#eeeeee", "no run applies (n/a)"),
)


# ---------------------------------------------------------------- gate verdicts


_GATE_CACHE: dict[tuple[object, ...], tuple[str, str]] = {}


def gate_verdict(human: Human) -> tuple[str, str]:
    """(verdict, reason) of the passivity gate for a human, once per file content."""
    key = tuple(human.identity().items())
    if key in _GATE_CACHE:
        return _GATE_CACHE[key]
    if human.kind == "model":
        from verify.passivity import decide
        from verify.passivity.io.model_file import model_from_bytes

        decision = decide(model_from_bytes(human.text or b"", human.label))
        found = (str(decision.verdict), " ".join(decision.reason.split()))
    elif human.kind == "static":
        gain = float(human.gain or 0.0)
        found = (("passive", "K + K^T = 2 gain I >= 0") if gain >= 0
                 else ("not passive", "K + K^T = 2 gain I < 0"))
    else:
        found = ("not established", "the VR operator is not an LTI model; the gate does not "
                 "apply")
    _GATE_CACHE[key] = found
    return found


# ---------------------------------------------------------------- a tiny document model


@dataclass
class Table:
    header: list[str]
    rows: list[list[str]]
    classes: list[list[str]] | None = None  # an HTML class per cell ("" for none)


@dataclass
class Figure:
    path: str  # relative to the report
    alt: str


@dataclass
class Code:
    text: str


Block = tuple[str, Any]  # ("h1" | "h2" | "p", text), ("table" | "figure" | "code", obj)
#                          or ("legend", [(class, meaning), ...]): what the colours mean


#: characters that can open Markdown or HTML constructs anywhere in a line (a link or
#: image needs "](" or "][" after its text, so "[gate]" labels stay as they read)
_MD_SPECIAL = re.compile(r"([\\`*<>&|#]|\](?=[(\[]))")
#: what opens a block (list, quote, heading, rule, ordered list) at a line's start
_MD_BLOCK_START = re.compile(r"^(\s*)([-+=~_])")
_MD_ORDERED = re.compile(r"^(\s*\d+)([.)])")


def md_text(text: str) -> str:
    """``text`` as literal Markdown inline text: one line (a spec's name or a human's
    label cannot open a heading or a block), with HTML and Markdown punctuation
    backslash-escaped (CommonMark: any ASCII punctuation may be escaped)."""
    line = " ".join(str(text).split())
    line = _MD_SPECIAL.sub(r"\\\1", line)
    if line.startswith("["):  # "[label]: url" at a line's start defines a link
        line = "\\" + line
    line = _MD_ORDERED.sub(r"\1\\\2", line)
    return _MD_BLOCK_START.sub(r"\1\\\2", line)


def _fence(text: str) -> str:
    """A code fence longer than any backtick run in ``text`` (so it cannot be closed)."""
    runs = [len(m) for m in re.findall(r"`+", text)]
    return "`" * max(3, 1 + max(runs, default=0))


def render_markdown(blocks: Sequence[Block]) -> str:
    out: list[str] = []
    for kind, item in blocks:
        if kind == "h1":
            out += [f"# {md_text(item)}", ""]
        elif kind == "h2":
            out += [f"## {md_text(item)}", ""]
        elif kind == "p":
            out += [md_text(item), ""]
        elif kind == "table":
            out.append("| " + " | ".join(md_text(h) for h in item.header) + " |")
            out.append("|" + "---|" * len(item.header))
            out += ["| " + " | ".join(md_text(c) for c in row) + " |" for row in item.rows]
            out.append("")
        elif kind == "figure":
            out += [f"![{md_text(item.alt)}](<{item.path}>)", ""]
        elif kind == "code":
            fence = _fence(item.text)
            out += [fence, item.text.rstrip("\n"), fence, ""]
        elif kind == "legend":
            out += ["Colours (HTML report and figure): " + "; ".join(
                md_text(f"{name}: {meaning}") for name, meaning in item) + ".", ""]
    return "\n".join(out).rstrip("\n") + "\n"


#: the campaign report's own additions to the main report's style: code blocks wrap
#: (a reproducing command is never cut off), figures fit the page, tables keep margins;
#: words in tables never break inside (a table wider than the page scrolls sideways);
#: a cell's colour is its category (:data:`CATEGORIES`)
_CAMPAIGN_CSS = ("pre{background:#f6f6f6;padding:.6em;white-space:pre-wrap;"
                 "overflow-wrap:anywhere}img{max-width:100%}table{margin:.6em 0 1em}"
                 "div.wide{overflow-x:auto}div.wide table{width:auto;min-width:60%}"
                 "div.wide td,div.wide th{overflow-wrap:normal;word-break:normal;"
                 "hyphens:manual}div.wide td.path{overflow-wrap:break-word}"
                 "div.wide td.reason{min-width:20em}"
                 + "".join(f"td.{name}{{background:{colour}}}"
                           for name, colour, _ in CATEGORIES)
                 + "td.passive{color:#176a1e;font-weight:bold}"
                 "td.not-passive{color:#b00020;font-weight:bold}"
                 "span.key{display:inline-block;width:1em;height:1em;margin:0 .3em 0 .8em;"
                 "vertical-align:-.15em;border:1px solid #999}")


def _cell_html(text: str, kind: str) -> str:
    """A cell's escaped text; a path may break after each ``/`` (and nowhere else)."""
    escaped = html.escape(text)
    return escaped.replace("/", "/<wbr>") if kind == "path" else escaped


def render_html(blocks: Sequence[Block], title: str) -> str:
    """HTML in the style of the main report (``verify all``'s report.html)."""
    e = html.escape
    out = ["<!doctype html>", "<html lang='en'><head><meta charset='utf-8'>",
           f"<title>{e(title)}</title>", f"<style>{REPORT_CSS}{_CAMPAIGN_CSS}</style>",
           "</head><body>"]
    for kind, item in blocks:
        if kind in ("h1", "h2"):
            out.append(f"<{kind}>{e(item)}</{kind}>")
        elif kind == "p":
            out.append(f"<p>{e(item)}</p>")
        elif kind == "table":
            out.append("<div class='wide'><table><thead><tr>"
                       + "".join(f"<th>{e(h)}</th>" for h in item.header)
                       + "</tr></thead><tbody>")
            classes = item.classes or [[""] * len(row) for row in item.rows]
            out += ["<tr>" + "".join(f"<td class='{e(k)}'>{_cell_html(c, k)}</td>" if k else
                                     f"<td>{e(c)}</td>"
                                     for c, k in zip(row, ks, strict=True)) + "</tr>"
                    for row, ks in zip(item.rows, classes, strict=True)]
            out.append("</tbody></table></div>")
        elif kind == "figure":
            out.append(f'<figure><img src="{e(item.path)}" alt="{e(item.alt)}"></figure>')
        elif kind == "code":
            out.append(f"<pre>{e(item.text)}</pre>")
        elif kind == "legend":
            out.append("<p>Colours:" + "".join(
                f"<span class='key' style='background:{colour}'></span>{e(meaning)}"
                for name, colour, meaning in CATEGORIES if name in dict(item)) + "</p>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------- aggregation


def _num(x: float | None, digits: int = 4) -> str:
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    return f"{x:.{digits}g}"


def varying(runs: Sequence[Run]) -> list[str]:
    """The swept parameters other than the human, k_s and the seed that take > 1 value."""
    names = ("n", "autonomous", "reference", "seconds", "step")
    return [p for p in names if len({getattr(r, p) for r in runs}) > 1]


def setting(run: Run, axes: Sequence[str]) -> str:
    """The label of a run's row in the maps: its human and the other varying parameters."""
    def shown(value: object) -> str:
        return _num(value) if isinstance(value, float) else str(value)

    extra = ", ".join(f"{a} = {shown(getattr(run, a))}" for a in axes)
    return run.human.label + (f" ({extra})" if extra else "")


@dataclass
class Campaign:
    """Runs and rows of a campaign, and the aggregates the report shows (each computed
    once: the report reads them many times, and a sweep may hold 10^5 runs)."""

    spec: CampaignSpec
    runs: list[Run]
    rows: dict[str, dict[str, Any]]

    @functools.cached_property
    def axes(self) -> list[str]:
        return varying(self.runs)

    @functools.cached_property
    def _setting_of(self) -> list[str]:
        axes, labels = self.axes, {}
        out = []
        for r in self.runs:  # setting labels per (human, other axes), built once each
            ident = (r.human.label, *(getattr(r, a) for a in axes))
            if ident not in labels:
                labels[ident] = setting(r, axes)
            out.append(labels[ident])
        return out

    def settings(self) -> list[str]:
        return list(dict.fromkeys(self._setting_of))

    def k_values(self) -> list[float]:
        return sorted({r.k_s for r in self.runs})

    @functools.cached_property
    def _cells(self) -> dict[tuple[str, float], list[tuple[Run, dict[str, Any]]]]:
        out: dict[tuple[str, float], list[tuple[Run, dict[str, Any]]]] = defaultdict(list)
        for r, s in zip(self.runs, self._setting_of, strict=True):
            if r.key in self.rows:
                out[s, r.k_s].append((r, self.rows[r.key]))
        return out

    def cells(self) -> dict[tuple[str, float], list[tuple[Run, dict[str, Any]]]]:
        return self._cells

    def humans(self) -> list[Human]:
        seen: dict[tuple[object, ...], Human] = {}
        for r in self.runs:
            seen.setdefault(tuple(r.human.identity().items()), r.human)
        return list(seen.values())


ANYWAY, NOT_ANYWAY = "anyway", "not-anyway"  # assumption failed; conclusion held / failed


def _counts(pairs: Sequence[tuple[Run, dict[str, Any]]], prop: str) -> dict[str, int]:
    counts = {HELD: 0, FAILED: 0, ASSUMPTION: 0, UNRESOLVED: 0, "error": 0,
              NOT_APPLICABLE: 0, ANYWAY: 0, NOT_ANYWAY: 0}
    for _, row in pairs:
        if row.get("error"):
            counts["error"] += 1
            continue
        status = row.get(column(prop)) or NOT_CHECKED
        if status in counts:
            counts[status] += 1
        if status == ASSUMPTION:
            conclusion = row.get(f"{column(prop)}_conclusion")
            if conclusion == HELD:
                counts[ANYWAY] += 1
            elif conclusion == FAILED:
                counts[NOT_ANYWAY] += 1
    return counts


def _cell_text(counts: dict[str, int], total: int) -> str:
    """What the runs of a cell did: held or failed under the assumptions, and, for the
    runs outside them (an assumption failed along the run), what the conclusion did
    there; worded so that a conclusion that held outside the theorem reads as held."""
    if counts[NOT_APPLICABLE] == total:
        return "n/a"
    outside = counts[ASSUMPTION]
    within = counts[HELD] + counts[FAILED]
    parts = []
    if within or not outside:
        text = f"held in {counts[HELD]} of {within if outside else total}"
        if outside:
            text += " within the assumptions"
        if counts[FAILED]:
            text += f", FAILED in {counts[FAILED]}"
        parts.append(text)
    if outside:
        where = f"all {outside}" if outside == total else f"{outside}"
        held, failed = counts[ANYWAY], counts[NOT_ANYWAY]
        text = f"outside the assumptions in {where}: conclusion held in {held}"
        if failed:
            text += f", failed in {failed}"
        parts.append(text)
    if counts[UNRESOLVED]:
        parts.append(f"{counts[UNRESOLVED]} unresolved (integration)")
    if counts["error"]:
        parts.append(f"{counts['error']} raised")
    if counts[NOT_APPLICABLE]:
        parts.append(f"{counts[NOT_APPLICABLE]} n/a")
    return "; ".join(parts)


def cell_category(counts: dict[str, int], total: int) -> str:
    """The cell's class in :data:`CATEGORIES` (its worst outcome)."""
    if total == 0 or counts[NOT_APPLICABLE] == total:
        return "none"
    if counts[FAILED]:
        return "failed"
    if counts[UNRESOLVED] or counts["error"]:
        return "unresolved"
    if counts[NOT_ANYWAY]:
        return "failed-outside"
    if counts[ANYWAY]:
        return "held-outside"
    return "held"


def convergence_summary(pairs: Sequence[tuple[Run, dict[str, Any]]]) -> tuple[
        list[float], int]:
    """Convergence times of the runs that converged, and how many did not."""
    times = [row["convergence_time"] for _, row in pairs
             if not row.get("error") and row.get("convergence_time") is not None]
    return times, len(pairs) - len(times)


def _convergence_text(pairs) -> str:
    times, never = convergence_summary(pairs)
    if not times:
        return f"none of {len(pairs)} converged"
    text = f"{statistics.median(times):.3g} s"
    if min(times) != max(times):
        text += f" [{min(times):.3g}, {max(times):.3g}]"
    return text + (f" ({never} of {len(pairs)} not converged)" if never else "")


# ---------------------------------------------------------------- figures


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _math_label(text: str) -> str:
    """A setting's label for a figure: ``k_s`` as math, any other ``$`` literal."""
    return text.replace("$", r"\$").replace("k_s", "$k_s$")


#: Largest number of k_s columns whose cells are written in (beyond, colours only).
MAX_ANNOTATED_COLUMNS = 12


def property_figure(c: Campaign) -> bytes:
    """One map per checked property, stacked: settings x k_s, each cell coloured by its
    category (:data:`CATEGORIES`) and, when there is room, its counts written in at a
    size readable at 100 % zoom (9 pt at 100 dpi: 12.5 px)."""
    import numpy as np
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    from verify.artefacts.figure_bytes import figure_bytes

    plt = _pyplot()
    props = list(c.spec.properties)
    settings, ks = c.settings(), c.k_values()
    cells = c.cells()
    names = [name for name, _, _ in CATEGORIES]
    cmap = ListedColormap([colour for _, colour, _ in CATEGORIES])
    rows_shown = min(len(settings), 60)
    annotate = len(ks) <= MAX_ANNOTATED_COLUMNS and len(settings) <= 40
    panel_h = 0.55 * rows_shown + 0.75
    fig, axes = plt.subplots(len(props), 1, figsize=(9.2, panel_h * len(props) + 1.0),
                             squeeze=False, layout="constrained")
    ticks = range(0, len(ks), max(1, -(-len(ks) // 20)))  # at most 20 k_s labels
    used: set[str] = set()
    for ax, prop in zip(axes[:, 0], props, strict=True):
        grid = np.zeros((len(settings), len(ks)))
        for i, s in enumerate(settings):
            for j, k in enumerate(ks):
                pairs = cells.get((s, k), [])
                counts = _counts(pairs, prop)
                category = cell_category(counts, len(pairs))
                used.add(category)
                grid[i, j] = names.index(category)
                if not annotate or category == "none":
                    continue
                judged = counts[HELD] + counts[FAILED] + counts[ANYWAY] + counts[NOT_ANYWAY]
                label = f"{counts[HELD] + counts[ANYWAY]}/{judged}"
                if counts[ASSUMPTION]:
                    label += f" ({counts[ASSUMPTION]} outside)"
                if counts[UNRESOLVED] or counts["error"]:
                    label += f"\n{counts[UNRESOLVED] + counts['error']} unresolved"
                ax.text(j, i, label, ha="center", va="center", fontsize=9)
        ax.imshow(grid, cmap=cmap, vmin=-0.5, vmax=len(names) - 0.5, aspect="auto",
                  interpolation="nearest")
        ax.set_xticks(list(ticks), [f"{ks[j]:g}" for j in ticks], fontsize=9)
        ax.set_yticks(range(len(settings)), [_math_label(s) for s in settings], fontsize=9)
        ax.set_xticks(np.arange(len(ks) + 1) - 0.5, minor=True)
        ax.set_yticks(np.arange(len(settings) + 1) - 0.5, minor=True)
        ax.grid(which="minor", color="white", lw=2)
        ax.tick_params(which="minor", length=0)
        ax.set_xlabel(r"$k_s$", fontsize=10)
        ax.set_title(PROPERTY_TITLE[prop], fontsize=10, loc="left")
    handles = [Patch(facecolor=colour, edgecolor="0.6", label=meaning)
               for name, colour, meaning in CATEGORIES if name in used]
    fig.legend(handles=handles, loc="outside lower center", ncol=2, fontsize=9,
               frameon=False)
    fig.suptitle("Conclusion held / runs judged per cell (outside: runs where an "
                 "assumption failed)", fontsize=10)
    return figure_bytes(fig, "png", dpi=100)


def convergence_figure(c: Campaign, gates: dict[str, str]) -> bytes:
    """Convergence time of |dbar - d_r| against k_s per setting (median, range, misses)."""
    from verify.artefacts.figure_bytes import figure_bytes

    plt = _pyplot()
    cells = c.cells()
    fig, ax = plt.subplots(figsize=(6.2, 4.2))  # with the legend beside: under 9.2 in
    highest = [max(times) for pairs in cells.values()
               for times in [convergence_summary(pairs)[0]] if times]
    top = 1.12 * max(highest) if highest else max(r.seconds for r in c.runs)
    for i, s in enumerate(c.settings()):
        xs, med, lo, hi, miss = [], [], [], [], []
        for k in c.k_values():
            times, never = convergence_summary(cells.get((s, k), []))
            if times:
                xs.append(k)
                med.append(statistics.median(times))
                lo.append(med[-1] - min(times))
                hi.append(max(times) - med[-1])
            if never:
                miss.append(k)
        color = f"C{i % 10}"
        ax.errorbar(xs, med, yerr=[lo, hi], color=color, marker="o", capsize=3,
                    label=_math_label(f"{s} [{gates.get(s, '')}]"))
        if miss:
            ax.plot(miss, [top * (1.0 + 0.02 * i)] * len(miss), "x", color=color, ms=8)
    ax.axhline(top, color="0.6", lw=0.5, ls="--")
    ax.set_ylim(0.0, top * (1.06 + 0.02 * len(c.settings())))  # fitted to the data
    if len(c.k_values()) <= 12:
        ax.set_xticks(c.k_values(), [f"{k:g}" for k in c.k_values()])
    ax.set_xlabel(r"$k_s$", fontsize=10)
    ax.set_ylabel("convergence time [s]", fontsize=10)
    ax.tick_params(labelsize=9)
    ax.grid(True, alpha=0.3)
    ax.set_title(r"$\Vert \bar d - d_r \Vert$" + f" < {c.spec.convergence_threshold:g} from "
                 "then on: median and range over seeds\n(× above the dashed line: not "
                 "converged by T)", fontsize=10)
    ax.legend(fontsize=9, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    return figure_bytes(fig, "png", dpi=100, bbox_inches="tight")


# ---------------------------------------------------------------- the report


def _human_path(human: Human, cwd: Path | None) -> str:
    from verify.campaign.reproduce import shown_path

    return "-" if human.path is None else shown_path(human.path, cwd)


def _parameters(run: Run) -> list[str]:
    return [run.key[:12], run.human.label, f"{run.k_s:g}", str(run.n), str(run.seed),
            run.autonomous, run.reference, f"{run.seconds:g}", f"{run.step:.4g}"]


PARAMETER_HEADER = ["key", "human", "k_s", "n", "seed", "autonomous", "reference",
                    "T [s]", "step [s]"]


def build_blocks(c: Campaign, *, cwd: Path | None = None
                 ) -> tuple[list[Block], dict[str, bytes], str]:
    """The report's blocks (reproducible part), its figures and commands.txt."""
    spec = c.spec
    blocks: list[Block] = [("h1", f"Campaign: {spec.name}")]
    if spec.description:
        blocks.append(("p", spec.description))
    stored = [r for r in c.runs if r.key in c.rows]
    raised = [r for r in stored if c.rows[r.key].get("error")]
    axes = ", ".join(f"{len(v)} {name}" for name, v in (
        ("humans", c.humans()), ("k_s", spec.k_s), ("n", spec.n), ("seeds", spec.seeds),
        ("autonomous inputs", spec.autonomous), ("references", spec.reference),
        ("run lengths", spec.seconds), ("steps", spec.step)) if len(v) > 1)
    blocks.append(("p", f"{len(c.runs)} runs ({axes or 'one setting'}); {len(stored)} stored, "
                   f"{len(raised)} raised. Properties checked: "
                   f"{', '.join(spec.properties) or 'none'}, all from one pair of runs at "
                   "steps h and h/2 (the step-doubling tolerance of verify.sim.properties; "
                   "error-controlled steps where the fixed step cannot resolve the loop, "
                   "and unresolved, never held, where neither can). Spec "
                   f"sha256 {spec.source_sha256[:16] or '-'}."))

    gates = {}
    human_rows = []
    for h in c.humans():
        verdict, reason = gate_verdict(h)
        short = reason if len(reason) <= 160 else reason[:157] + "..."
        human_rows.append([h.label, _human_path(h, cwd), h.sha256[:12] or "-", verdict, short])
        gates[h.label] = verdict
    gate_class = {"passive": "passive", "not passive": "not-passive"}
    blocks += [("h2", "Humans and their passivity verdicts"),
               ("p", "Theorem 1 assumes a passive human (Assumption 1, item 5); the verdict "
                "is the exact gate's (verify gate) on the model file as written."),
               ("table", Table(["human", "file", "sha256", "gate", "reason"], human_rows,
                               [["", "path", "", gate_class.get(row[3], ""), "reason"]
                                for row in human_rows]))]

    settings, ks, cells = c.settings(), c.k_values(), c.cells()
    gate_of = {s: gates.get(r.human.label, "") for r, s in zip(c.runs, c._setting_of,
                                                               strict=True)}
    header = ["setting [gate]", *[f"k_s = {k:g}" for k in ks]]
    blocks.append(("h2", "Properties over the swept parameters"))
    blocks.append(("p", "Each cell counts the runs over seeds"
                   + (f" (settings differ in the human and in {', '.join(c.axes)})"
                      if c.axes else "")
                   + ". Outside the assumptions: an assumption of the claim failed along "
                   "the run (for Theorem 1, a human with no passivity certificate, "
                   "sym R_rl ≻ 0 lost, or a switching reference), so the paper promises "
                   "nothing there; the conclusion was checked all the same."))
    used: set[str] = set()
    for prop in spec.properties:
        rows, classes = [], []
        for s in settings:
            row, kinds = [f"{s} [{gate_of[s]}]"], [""]
            for k in ks:
                pairs = cells.get((s, k), [])
                counts = _counts(pairs, prop)
                row.append(_cell_text(counts, len(pairs)) if pairs else "-")
                kinds.append(cell_category(counts, len(pairs)))
            used.update(kinds[1:])
            rows.append(row)
            classes.append(kinds)
        blocks += [("p", PROPERTY_TITLE[prop]), ("table", Table(header, rows, classes))]
    if spec.properties:
        blocks.append(("legend", [(name, meaning) for name, _, meaning in CATEGORIES
                                  if name in used]))
    blocks += findings_blocks(c, gate_of)
    figures: dict[str, bytes] = {}
    if spec.properties and stored:
        figures["figures/properties.png"] = property_figure(c)
        blocks.append(("figure", Figure("figures/properties.png", "property map")))

    blocks.append(("h2", "Convergence time of ‖d̄ − d_r‖"))
    blocks.append(("p", "The first sample time after which ‖d̄ − d_r‖ stays below "
                   f"{spec.convergence_threshold:g} until the end of the run; median "
                   "[min, max] over the runs of a cell that converged."))
    rows = [[f"{s} [{gate_of[s]}]", *[_convergence_text(cells[(s, k)]) if cells.get((s, k))
                                     else "-" for k in ks]] for s in settings]
    blocks.append(("table", Table(header, rows)))
    if stored:
        figures["figures/convergence.png"] = convergence_figure(c, gate_of)
        blocks.append(("figure", Figure("figures/convergence.png", "convergence time")))

    failing = [(r, [p for p in spec.properties if c.rows[r.key].get(column(p)) == FAILED])
               for r in stored]
    failing = [(r, ps) for r, ps in failing if ps]
    blocks.append(("h2", f"Runs that failed a property ({len(failing)})"))
    if failing:
        rows = []
        for r, ps in failing[:MAX_LISTED]:
            row = c.rows[r.key]
            why = "; ".join(f"{p}: {_num(row[f'{column(p)}_violation'], 3)} > "
                            f"{_num(row[f'{column(p)}_tolerance'], 3)}" for p in ps)
            rows.append([*_parameters(r), why])
        blocks.append(("table", Table([*PARAMETER_HEADER, "failed (violation > tolerance)"],
                                      rows)))
        if len(failing) > MAX_LISTED:
            blocks.append(("p", f"... and {len(failing) - MAX_LISTED} more (the store has "
                           "them all)."))
        blocks.append(("p", "Reproduce one of them (the same scenario, seed and human; "
                       "--check repeats the property checks):"))
        blocks.append(("code", Code("\n".join(simulate_command(r, cwd=cwd)
                                              for r, _ in failing[:10]))))
    else:
        blocks.append(("p", "None."))
    if raised:
        blocks.append(("h2", f"Runs that raised ({len(raised)})"))
        blocks.append(("table", Table([*PARAMETER_HEADER, "error"], [
            [*_parameters(r), c.rows[r.key]["error"]] for r in raised[:MAX_LISTED]])))
    unresolved = [(r, [p for p in spec.properties
                       if c.rows[r.key].get(column(p)) == UNRESOLVED]) for r in stored]
    unresolved = [(r, ps) for r, ps in unresolved if ps]
    if unresolved:
        blocks.append(("h2", f"Runs the integration did not resolve ({len(unresolved)})"))
        blocks.append(("p", "Their properties are neither held nor failed: the fixed step is "
                       "beyond CF4's stability for the loop's rates, or the error estimate "
                       "exceeds 1 % of the checked quantity's scale, and error-controlled "
                       "steps did not resolve them within the step budget. Rerun with a "
                       "smaller step."))
        blocks.append(("table", Table([*PARAMETER_HEADER, "unresolved", "why"], [
            [*_parameters(r), ", ".join(ps), c.rows[r.key].get("engine_note") or "-"]
            for r, ps in unresolved[:MAX_LISTED]])))
    missing = [r for r in c.runs if r.key not in c.rows]
    if missing:
        blocks.append(("p", f"{len(missing)} runs have no row yet (interrupted or lost); "
                       "rerun the campaign with --resume."))
    blocks.append(("h2", "Reproducing a run"))
    blocks.append(("p", "Every run is rebuilt by verify simulate with the same settings "
                   "(commands.txt has one line per run, keyed by the run key), e.g.:"))
    if c.runs:
        blocks.append(("code", Code(simulate_command(c.runs[0], cwd=cwd))))
    commands = "".join(f"{r.key}  {simulate_command(r, cwd=cwd)}\n" for r in c.runs)
    return blocks, figures, commands


def engine_counts(c: Campaign) -> dict[str, int]:
    """Stored runs per integration engine (``fixed``, ``adaptive rtol=...``, ``none``)."""
    counts: dict[str, int] = defaultdict(int)
    for r in c.runs:
        row = c.rows.get(r.key)
        if row is not None and not row.get("error"):
            counts[row.get("engine") or "-"] += 1
    return dict(sorted(counts.items()))


def _at(count: int, ks: list[str]) -> str:
    """``3, at k_s = 2, 3`` or ``none``."""
    return "none" if not count else f"{count}, at k_s = {', '.join(ks)}"


def findings_blocks(c: Campaign, gate_of: dict[str, str]) -> list[Block]:
    """Where a conclusion held although an assumption failed (and where it failed)."""
    cells = c.cells()
    rows = []
    for prop in c.spec.properties:
        for s in c.settings():
            counts = {ANYWAY: 0, NOT_ANYWAY: 0, ASSUMPTION: 0}
            ks_anyway, ks_not = [], []
            for k in c.k_values():
                got = _counts(cells.get((s, k), []), prop)
                for name in counts:
                    counts[name] += got[name]
                if got[ANYWAY]:
                    ks_anyway.append(f"{k:g}")
                if got[NOT_ANYWAY]:
                    ks_not.append(f"{k:g}")
            if counts[ASSUMPTION]:
                rows.append([prop, f"{s} [{gate_of[s]}]", str(counts[ASSUMPTION]),
                             _at(counts[ANYWAY], ks_anyway), _at(counts[NOT_ANYWAY], ks_not)])
    engines = engine_counts(c)
    out: list[Block] = [("h2", "What held outside the assumptions")]
    out.append(("p", "Runs whose assumption failed along the trajectory (for Theorem 1: "
                "a human without a passivity certificate, sym(R_rl) > 0 lost, a switching "
                "reference) are outside the paper's guarantees; the conclusion was still "
                "checked on them, within the same tolerance. Integration engines of the "
                "stored runs: " + (", ".join(f"{k} {v}" for k, v in engines.items()) or "-")
                + "."))
    if rows:
        out.append(("table", Table(["property", "setting [gate]",
                                    "runs outside the assumptions",
                                    "conclusion held there", "conclusion failed there"], rows,
                                   [["", "", "", "held-outside" if r[3] != "none" else "",
                                     "failed-outside" if r[4] != "none" else ""]
                                    for r in rows])))
    else:
        out.append(("p", "No run had an assumption fail."))
    return out


def timing_blocks(c: Campaign, session: dict[str, str]) -> list[Block]:
    """The final block: wall times of the stored runs and of this session."""
    walls = [row["wall_time"] for row in c.rows.values() if row.get("wall_time") is not None]
    rows = [[k, v] for k, v in session.items()]
    if walls:
        rows += [["wall time per run (mean, max)", f"{statistics.mean(walls):.3g} s, "
                  f"{max(walls):.3g} s"], ["wall time of all runs", f"{sum(walls):.4g} s"]]
    return [("h2", TIMINGS_HEADING), ("table", Table(["", "value"], rows))]


def write_report(c: Campaign, out: Path, session: dict[str, str], *,
                 cwd: Path | None = None) -> list[Path]:
    """Write campaign.md, campaign.html, figures and commands.txt into ``out``."""
    from verify.artefacts.atomic import write_all_atomic

    blocks, figures, commands = build_blocks(c, cwd=cwd)
    blocks = blocks + timing_blocks(c, session)
    files: dict[Path, bytes | str] = {out / name: data for name, data in figures.items()}
    files[out / "commands.txt"] = commands
    files[out / "campaign.md"] = render_markdown(blocks)
    files[out / "campaign.html"] = render_html(blocks, f"Campaign: {c.spec.name}")
    write_all_atomic(files)
    return list(files)


__all__ = ["TIMINGS_HEADING", "Campaign", "build_blocks", "gate_verdict", "render_html",
           "render_markdown", "write_report"]
