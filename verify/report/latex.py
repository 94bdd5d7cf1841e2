"""The report as a LaTeX appendix for the paper (``verify all --latex``).

``reports/appendix.tex`` is a self-contained document (``pdflatex appendix.tex`` in the
report folder builds it; the figures are read from beside it): a summary table of every
claim of Sections 2-4 with its verdict, then per section of the paper the step tables of
its derivations (Lemma 1 and Theorem 1 step by step) and per claim what the paper
writes, what was checked, the verdict, the finding, the repair, the evidence with the
file names of its certificates, and its figures. Everything between
``% begin appendix`` and ``% end appendix`` can be pasted into the paper's source.

The text comes from the same LaTeX sources as the HTML and Markdown reports
(:mod:`verify.report.mathtex`); it is ASCII and uses only amsmath, amssymb, graphicx,
longtable, array, geometry and url, which every TeX distribution ships.
"""

from __future__ import annotations

from pathlib import PurePosixPath

from verify.claims.model import ClaimResult
from verify.claims.runner import RunResult
from verify.report.mathtex import latex_text, prose_to_latex
from verify.report.render import (
    ENVIRONMENT_NOTE,
    VERDICT_MARK,
    VERDICT_MEANING,
    _figure_href,
    claim_latex,
    report_data,
    sections,
)
from verify.report.run_info import RunInfo
from verify.report.steps import (
    DerivationTable,
    common_evidence,
    derivation_tables,
    sos_twins,
    table_evidence,
)

__all__ = ["render_latex"]

_PREAMBLE = r"""\documentclass[10pt]{article}
\usepackage[T1]{fontenc}
\usepackage{lmodern}
\usepackage{amsmath,amssymb}
\usepackage{graphicx}
\usepackage{longtable,array}
\usepackage[margin=2.2cm]{geometry}
\usepackage{url}
\setlength{\LTpre}{4pt}\setlength{\LTpost}{4pt}
\sloppy
\begin{document}
"""


def _tt(text: str) -> str:
    """A file name or identifier in typewriter type that may break at any character."""
    return r"\path{" + text.replace("}", "").replace("{", "").replace("%", "") + "}"


def _code(text: str) -> str:
    """Typewriter text safe in moving arguments (captions, headings)."""
    return r"\texttt{" + latex_text(text) + "}"


def _verdict(text: str) -> str:
    return r"\textbf{" + latex_text(text) + "}"


def _table(t: DerivationTable, common: str) -> list[str]:
    own = table_evidence(t, common)
    out = [
        r"\begin{longtable}{@{}p{0.07\linewidth}p{0.66\linewidth}p{0.21\linewidth}@{}}",
        r"\hline",
        r"\multicolumn{3}{@{}p{0.97\linewidth}@{}}{" + _tt(t.name) + " (claim " + _tt(t.claim)
        + "): " + t.statement_latex + " --- " + _verdict(t.verdict) + r"}\\",
        r"\hline\endhead",
        r"start & \multicolumn{2}{p{0.89\linewidth}@{}}{$" + t.start_latex + r"$}\\[2pt]",
    ]
    for row in t.rows:
        why = row.justification_latex
        if row.assumptions != "none":
            why += "; assumes " + row.assumptions_latex
        if row.evidence and row.evidence not in (common, own):
            why += "; exact check: " + latex_text(row.evidence)
        if row.coq_theorem:
            why += r"; Coq: \texttt{" + latex_text(row.coq_theorem) + "}"
        verdict = latex_text(row.verdict + (f", {row.proved_by}" if row.proved_by else ""))
        out.append(f"{row.step} & " + r"\multicolumn{2}{p{0.89\linewidth}@{}}{$"
                   + row.relation_latex + r"$}\\*")
        out.append(r" & {\small " + why + r"} & {\small " + verdict + r"}\\[3pt]")
    if own:
        out.append(r" & \multicolumn{2}{p{0.89\linewidth}@{}}{\small exact check of each step "
                   r"above: " + latex_text(own) + r"}\\")
    out += [r"\hline", r"\end{longtable}"]
    return out


def _evidence(e, figures: list[str]) -> str:
    text = f"[{latex_text(e.kind.value)}, {'pass' if e.passed else 'FAIL'}] " \
        + prose_to_latex(e.summary)
    href = _figure_href(e)
    if href:
        figures.append(href)
        return text + f" (Figure~\\ref{{fig:{_label(href)}}})"
    if e.path:
        return text + " (file " + _tt(PurePosixPath(e.path).name) + ")"
    return text


def _label(href: str) -> str:
    return "".join(ch if ch.isalnum() else "-" for ch in href)


def _claim(r: ClaimResult) -> list[str]:
    c, o = r.claim, r.outcome
    tex = claim_latex(r)
    out = [r"\subsubsection*{" + _code(c.id) + " --- " + latex_text(VERDICT_MARK[o.verdict])
           + "}", r"\begin{description}",
           r"\item[Paper] (" + prose_to_latex(c.paper_ref) + ") " + tex["paper"],
           r"\item[Checked] " + tex["statement"],
           r"\item[How] " + tex["method"],
           r"\item[Scope] " + tex["scope"],
           r"\item[Finding] " + tex["finding"]]
    if "repair" in tex:
        out.append(r"\item[Repaired statement] " + tex["repair"])
    figures: list[str] = []
    items = [_evidence(e, figures) for e in o.evidence]
    if items:
        out.append(r"\item[Evidence]\mbox{}\begin{itemize}")
        out += [r"\item{} " + item for item in items]
        out.append(r"\end{itemize}")
    else:
        out.append(r"\item[Evidence] none recorded")
    out.append(r"\end{description}")
    for e in o.evidence:
        href = _figure_href(e)
        if href:
            out += [r"\begin{figure}[htbp]\centering",
                    r"\includegraphics[width=0.8\linewidth]{" + href + "}",
                    r"\caption{" + _code(c.id) + ": " + prose_to_latex(e.summary)
                    + r"}\label{fig:" + _label(href) + "}", r"\end{figure}"]
    return out


def render_latex(run: RunResult, info: RunInfo | None = None) -> str:
    """``appendix.tex``: the run as a LaTeX appendix (see the module docstring)."""
    info = info or RunInfo.from_environment()
    data = report_data(run, info)
    lines = [_PREAMBLE.rstrip("\n"), "% begin appendix", r"\appendix",
             r"\section{Machine verification of the claims}",
             "Every checkable claim of the paper, checked by the \\texttt{verify} tool (seed "
             f"{run.seed}). Verdicts mean:", r"\begin{itemize}"]
    lines += [r"\item \textbf{" + latex_text(VERDICT_MARK[v]) + "}: " + latex_text(m) + "."
              for v, m in VERDICT_MEANING.items()]
    lines += [r"\end{itemize}",
              r"\begin{longtable}{@{}p{0.3\linewidth}p{0.48\linewidth}p{0.16\linewidth}@{}}",
              r"\hline claim & paper & verdict\\ \hline\endhead"]
    for r in run.results:
        lines.append(_tt(r.claim.id) + " & " + prose_to_latex(r.claim.paper_ref) + " & "
                     + _verdict(VERDICT_MARK[r.outcome.verdict]) + r"\\")
    lines += [r"\hline", r"\end{longtable}"]
    twins = sos_twins(run.results)
    for section, results in sections(run.results):
        lines.append(r"\subsection{Section " + latex_text(section) + "}")
        tables = derivation_tables(results, twins)
        if tables:
            common = common_evidence(tables)
            n = sum(len(t.rows) for t in tables)
            lines.append(f"Every step of this part of the proof ({n} steps in {len(tables)} "
                         "derivations); each step relates the previous expression to the one "
                         "on its row." + (" Exact check of every step unless its row says "
                                          "otherwise: " + latex_text(common) + "."
                                          if common else ""))
            for t in tables:
                lines += _table(t, common)
        for r in results:
            lines += _claim(r)
        lines.append(r"\clearpage")
    lines += [r"\subsection{Environment}", latex_text(ENVIRONMENT_NOTE), r"\begin{itemize}"]
    lines += [r"\item " + latex_text(f"{k}: {v}") for k, v in data["environment"].items()]
    lines += [r"\end{itemize}", "Generated " + latex_text(info.stamp)
              + (" (SOURCE\\_DATE\\_EPOCH)." if info.reproducible else "."),
              "% end appendix", r"\end{document}"]
    text = "\n".join(lines) + "\n"
    return text.encode("ascii", "replace").decode("ascii")
