r"""The report in LaTeX for the paper (``verify all --latex``): an appendix and a supplement.

Two self-contained documents, each built by ``pdflatex`` in the report folder:

* ``appendix.tex`` (:func:`render_latex`) is the short appendix an author pastes into the
  paper: everything between ``% begin appendix`` and ``% end appendix`` is plain
  ``tabularx`` and paragraphs that fit one column of a two-column paper (the paper's
  ``ifacconf`` class, or ``\documentclass[twocolumn]{article}`` as here): per section of
  the paper (Sections 2-4), a table of its claims with their verdicts, then per claim the
  finding, the repair where one is needed and the certificates that back it. It has no
  cross-references, so one pdflatex pass builds it.
* ``supplement.tex`` (:func:`render_supplement`) is the full record, one column: the step
  tables of the derivations (Lemma 1 and Theorem 1 step by step), per claim what the
  paper writes, what was checked and how, the evidence with the file names of its
  certificates, and the figures (vector PDF beside the report's SVG where the claim drew
  one). Its figure references need a second pdflatex pass.

The text comes from the same LaTeX sources as the HTML and Markdown reports
(:mod:`verify.report.mathtex`); it is ASCII and uses only amsmath, amssymb, graphicx,
tabularx, longtable, array, geometry and url, which every TeX distribution ships
(Debian's ``texlive-latex-base`` and ``lmodern``).
"""

from __future__ import annotations

import re
from pathlib import PurePosixPath

from verify.claims.model import ClaimResult, EvidenceKind, Verdict
from verify.claims.runner import RunResult
from verify.report.mathtex import latex_text, prose_to_latex
from verify.report.render import (
    KERNEL_NOTE,
    VERDICT_MARK,
    VERDICT_MEANING,
    _figure_href,
    claim_latex,
    report_data,
    sections,
)
from verify.report.steps import (
    DerivationTable,
    common_evidence,
    derivation_tables,
    sos_twins,
    table_evidence,
)

__all__ = ["APPENDIX_PACKAGES", "render_latex", "render_supplement"]

#: the packages the pasteable part of appendix.tex needs in the paper's preamble
APPENDIX_PACKAGES = ("amsmath", "amssymb", "tabularx", "array", "url")

_APPENDIX_PREAMBLE = r"""\documentclass[10pt,twocolumn]{article}
\usepackage[T1]{fontenc}
\usepackage{lmodern}
\usepackage{amsmath,amssymb}
\usepackage{tabularx,array}
\usepackage[margin=1.8cm]{geometry}
\usepackage{url}
\raggedbottom
\begin{document}
"""

#: the environment note of the LaTeX documents (what typesets them is LaTeX itself)
ENVIRONMENT_NOTE_LATEX = ("The libraries whose versions can change a verdict, a certificate "
                          "or the bytes of an artefact (solvers propose, exact arithmetic "
                          "decides; matplotlib draws the figures, pyarrow writes campaign "
                          "stores):")

#: evidence kinds as a reader says them
KIND_WORDS = {
    EvidenceKind.DERIVATION: "Derivation",
    EvidenceKind.FIGURE: "Figure",
}

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


def _kind_words(e) -> str:
    """``Exact identity:``, ``Counterexample:``: the evidence kind as words, and a failed
    piece of evidence says so."""
    words = KIND_WORDS.get(e.kind, e.kind.value.replace("-", " ").capitalize())
    return latex_text(words) + (r" (\textbf{failed})" if not e.passed else "") + ": "


def _graphic(href: str) -> str:
    """The file LaTeX includes for a figure: the vector PDF drawn beside an SVG."""
    return href[:-4] + ".pdf" if href.endswith(".svg") else href


def _evidence(e, figures: list[str]) -> str:
    text = _kind_words(e) + prose_to_latex(e.summary)
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
                    r"\includegraphics[width=0.8\linewidth]{" + _graphic(href) + "}",
                    r"\caption{" + _code(c.id) + ": " + prose_to_latex(e.summary)
                    + r"}\label{fig:" + _label(href) + "}", r"\end{figure}"]
    return out


def render_supplement(run: RunResult) -> str:
    """``supplement.tex``: the full record of the run (see the module docstring)."""
    data = report_data(run)
    lines = [_PREAMBLE.rstrip("\n"), r"\appendix",
             r"\section{Machine verification of the claims: supplement}",
             "Every checkable claim of the paper, checked by the \\texttt{verify} tool (seed "
             f"{run.seed}). Verdicts mean:", r"\begin{itemize}"]
    lines += [r"\item \textbf{" + latex_text(VERDICT_MARK[v]) + "}: " + latex_text(m) + "."
              for v, m in VERDICT_MEANING.items()]
    lines += [r"\end{itemize}", r"\subsection*{Kernel check (Coq)}",
              latex_text(KERNEL_NOTE),
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
    lines += [r"\subsection{Environment}", latex_text(ENVIRONMENT_NOTE_LATEX),
              r"\begin{itemize}"]
    lines += [r"\item " + latex_text(f"{k}: {v}") for k, v in data["environment"].items()]
    lines += [r"\end{itemize}", r"\end{document}"]
    text = "\n".join(lines) + "\n"
    return text.encode("ascii", "replace").decode("ascii")


# ---------------------------------------------------------------------- the short appendix

_SHORT_VERDICT = {
    Verdict.VERIFIED: "verified",
    Verdict.REPAIRED: "repaired",
    Verdict.REFUTED: "refuted",
    Verdict.ASSUMPTION: "assumption",
    Verdict.INCONCLUSIVE: "inconclusive",
}
_HASHED = re.compile(r"^(?P<stem>.+?)-[0-9a-f]{12,}(?P<ext>\.json)$")


def certificate_names(r: ClaimResult) -> list[str]:
    """The certificate files that back a claim, in order, each once: those its evidence
    stores and the SOS certificates its derivation steps name."""
    names: list[str] = []
    for e in r.outcome.evidence:
        if e.kind is EvidenceKind.CERTIFICATE and e.path:
            names.append(PurePosixPath(e.path).name)
        if e.kind is EvidenceKind.DERIVATION:
            for step in e.data.get("steps", ()):
                names += re.findall(r"certificate (sos-[0-9a-f]+\.json)", step.get("exact", ""))
    return list(dict.fromkeys(names))


def _short_name(name: str) -> str:
    """A certificate file name without its content hash (the supplement has the full
    name): ``reconstructed-k_s-3.0-99babda880e6.json`` is ``reconstructed-k_s-3.0``."""
    m = _HASHED.match(name)
    return m.group("stem") if m else name


def _certificates_line(r: ClaimResult) -> str:
    names = certificate_names(r)
    if not names:
        return ""
    sos = [n for n in names if n.startswith("sos-")]
    named = [_short_name(n) for n in names if not n.startswith("sos-")]
    parts = [_tt(n) for n in dict.fromkeys(named)]
    if sos:
        parts.append(f"{len(sos)} SOS certificate" + ("s" if len(sos) > 1 else ""))
    return r" \emph{Certificates:} " + ", ".join(parts) + "."


def _summary_table(results: list[ClaimResult]) -> list[str]:
    out = [r"\par\smallskip\noindent{\footnotesize",
           r"\begin{tabularx}{\columnwidth}{@{}>{\raggedright\arraybackslash}X"
           r">{\raggedright\arraybackslash}p{0.22\columnwidth}@{}}",
           r"\hline claim (where in the paper) & verdict\\ \hline"]
    for r in results:
        out.append(_tt(r.claim.id) + " (" + prose_to_latex(r.claim.paper_ref) + ") & "
                   + _verdict(_SHORT_VERDICT[r.outcome.verdict]) + r"\\")
    out += [r"\hline", r"\end{tabularx}}\par\smallskip"]
    return out


def _code_spans(text: str) -> str:
    """Text between backquotes (a command such as `verify gate`) in typewriter type."""
    return re.sub(r"`([^`$\n]+)`", r"\\texttt{\1}", text)


def _claim_paragraph(r: ClaimResult) -> str:
    tex = claim_latex(r)
    text = (r"\noindent " + _tt(r.claim.id) + " --- "
            + _verdict(_SHORT_VERDICT[r.outcome.verdict]) + ". " + tex["finding"])
    if "repair" in tex:
        text += r" \emph{Repair:} " + tex["repair"]
        if not text.rstrip().endswith("."):
            text += "."
    return _code_spans(text) + _certificates_line(r) + r"\par\smallskip"


def render_latex(run: RunResult) -> str:
    """``appendix.tex``: the short appendix (see the module docstring)."""
    counts = run.counts()
    said = ", ".join(f"{n} {_SHORT_VERDICT[Verdict(v)]}" for v, n in counts.items() if n)
    lines = [_APPENDIX_PREAMBLE.rstrip("\n"), r"\appendix",
             "% begin appendix (needs \\usepackage{" + ",".join(APPENDIX_PACKAGES) + "})",
             r"\section{Machine verification of the claims}",
             "Every checkable claim of Sections 2--4 was checked by machine (the "
             r"\texttt{verify} tool, seed " + f"{run.seed}" + "): identities and inequalities "
             "by exact rational arithmetic, passivity by exactly re-checked KYP, band and SOS "
             "certificates, dynamic conclusions by seeded simulation. Of "
             f"{len(run.results)} claims: {said}. "
             r"\emph{Verified}: holds exactly; \emph{repaired}: fails or is undefined as "
             r"written, the stated repair holds exactly; \emph{refuted}: false, with an "
             r"exactly checked witness; \emph{assumption}: needed by the argument, not "
             "checkable. The supplement gives every step, the evidence and the figures; "
             "the certificates are re-checked with no solver by "
             r"\texttt{verify certificates check}, and every verified step of Lemma~1 and "
             r"Theorem~1 and the KYP certificate are re-checked by Coq's kernel "
             r"(\texttt{verify coq -{}-check})."]
    for section, results in sections(run.results):
        lines.append(r"\subsection*{Section " + latex_text(section) + "}")
        lines += _summary_table(results)
        lines += [_claim_paragraph(r) for r in results]
    lines += ["% end appendix", r"\end{document}"]
    text = "\n".join(lines) + "\n"
    return text.encode("ascii", "replace").decode("ascii")
