"""Typeset reports: one LaTeX source per formula, MathML in HTML, $...$ in Markdown, a
LaTeX appendix that compiles, and page layout (one heading per section, one table per
derivation with each step's relation on its own row)."""

from __future__ import annotations

import re
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pytest
from report_fixtures import claim, derivation, registry_run, run_of, step

from verify.report.latex import render_latex, render_supplement
from verify.report.mathml import markdown_prose, mathml, prose_html, split_math
from verify.report.mathtex import prose_to_latex, to_latex
from verify.report.render import render_html, render_markdown


@pytest.mark.parametrize(("plain", "latex"), [
    ("tr(R̄_rᵀ) >= 1", r"\operatorname{tr}(\bar{R}_{r}^{\top}) \geq 1"),
    ("(-1/4) k_s", r"-\tfrac{1}{4} k_{s}"),
    ("λmin(sym(R_rl))", r"\lambda_{\min}(\operatorname{sym}(R_{rl}))"),
    ("sk(R)^∨", r"\operatorname{sk}(R)^{\vee}"),
    ("hat(ω_h^s)", r"\widehat{\omega _{h}^{s}}"),
    ("<grad h, ω>", r"\langle \operatorname{grad} h, \omega \rangle"),
    ("cosθ ≠ 0", r"\cos\theta \neq 0"),
    ("(W^T W)^{-1}", r"(W^{\top} W)^{-1}"),
    ("d/dt(R_lᵀR̄)", r"\tfrac{d}{dt}(R_{l}^{\top}\bar{R})"),
    ("V̇ ≤ 0", r"\dot{V} \leq 0"),
    ("‖I - R‖_F²", r"\Vert I - R\Vert _{F}^{2}"),
])
def test_plain_notation_becomes_latex(plain, latex):
    assert to_latex(plain) == latex


def test_words_inside_a_formula_are_upright_text():
    out = to_latex("boundary h = 0, i.e. cosθ = 0")
    assert out.startswith(r"\text{boundary}") and r"\text{i.e.}" in out


def test_prose_marks_formulas_and_keeps_words():
    out = prose_to_latex("tr(AB) ≥ λmin(A) tr(B) for A symmetric and B any square matrix.")
    assert out.startswith(r"$\operatorname{tr}(AB) \geq \lambda_{\min}(A)")
    assert out.endswith("any square matrix.") and out.count("$") % 2 == 0


def _run():
    steps = [
        step(1, "=", "(1/2) k_s tr(R_rl - R_rlᵀ R̄_r R̄_r)", "algebra (cyclic trace)"),
        step(2, ">=", "k_s λmin(sym(R_rl)) tr(I - ξξᵀ)", "trace inequality",
             conditions=["boundary h = 0, i.e. cosθ = 0"],
             assumptions=["λmin(sym(R_rl)) > 0 (Assumption 1, item 2)"],
             exact="slack = sum of 1 non-negative term(s) exactly"),
        step(3, ">=", "0", "positivity", exact="slack = sum of 1 non-negative term(s) exactly"),
    ]
    a = claim("lemma9.a", "3, Lemma 9", latex=r"Every step, with $\dot{h} \geq 0$.",
              evidence=[derivation("lemma9.chain", "ḣ", steps, "ḣ ≥ 0 on the boundary")])
    b = claim("sec9.b", "9 Other", statement="W^T W is invertible", repaired="use W^+",
              finding="It is not: rank W = 2.")
    c = claim("lemma9.c", "3, Lemma 9", statement="lambda_min(A) >= 0")
    return run_of(a, b, c)


def test_html_formulas_are_wellformed_mathml():
    page = render_html(_run())
    blocks = re.findall(r"<math\b.*?</math>", page, flags=re.S)
    assert len(blocks) >= 10
    for block in blocks:
        root = ET.fromstring(block)  # well-formed XML in the MathML namespace
        assert root.tag == "{http://www.w3.org/1998/Math/MathML}math"
    assert "class='tex'" not in page  # no formula fell back to raw LaTeX
    assert "<mfrac>" in page and "<msubsup>" in page


def _visible_text(page: str) -> str:
    page = re.sub(r"<math\b.*?</math>", " ", page, flags=re.S)
    page = re.sub(r"<(pre|code|style)\b.*?</\1>", " ", page, flags=re.S)
    return re.sub(r"<[^>]+>", " ", page)


def test_no_ascii_math_left_in_the_html_of_statements_and_steps():
    text = _visible_text(render_html(_run()))
    for ascii_math in (">=", "lambda_min", "^T", "λmin", "ᵀ", "R_rl"):
        assert ascii_math not in text, ascii_math


def test_every_registered_claim_has_latex_forms_that_typeset():
    run = registry_run()
    for r in run.results:
        c = r.claim
        assert c.paper_latex, c.id  # what the paper says always has formulas or words
        for source in (c.latex, c.paper_latex, c.repair_latex):
            for is_math, piece in split_math(source):
                if is_math:
                    assert piece.isascii() and "class='tex'" not in mathml(piece), (c.id, piece)
                else:
                    assert "\\" not in piece.replace("\\%", "").replace("\\_", ""), (c.id, piece)
        assert bool(c.repair_latex) == (c.id in {
            "sec2.wtw-invertible", "sec2.stealthiness", "sec2.projector", "sec2.dbar-dot",
            "sec3.rbar-e3", "lemma1.trace-inequality", "lemma1.nagumo-gradient",
            "lemma1.invariance", "sec4.nu-criterion", "thm1.lasalle-storage"}), c.id


def test_each_section_heading_appears_once():
    run = registry_run()
    md = render_markdown(run)
    headings = [line for line in md.splitlines() if line.startswith("## Section")]
    assert len(headings) == len(set(headings)) >= 5
    assert "## Section 3, Lemma 1" in headings and "## Section 3, Theorem 1" in headings
    page = render_html(run)
    h2 = re.findall(r"<h2>(Section [^<]*)</h2>", page)
    assert len(h2) == len(set(h2)) == len(headings)
    # every claim is still there, once
    for r in run.results:
        assert page.count(f"<div class='claim' id='{r.claim.id}'>") == 1


def test_steps_have_their_relation_on_their_own_row_and_shared_evidence_once():
    page = render_html(_run())
    table = re.search(r"<table class='proof'>.*?</table>", page, flags=re.S).group(0)
    rel_rows = re.findall(r"<tr class='rel'>(.*?)</tr>", table, flags=re.S)
    assert len(rel_rows) == 4  # start + 3 steps, each a row holding only the formula
    for row in rel_rows:
        assert "colspan='2'" in row and "<math" in row and "algebra" not in row
    # the check two steps share is stated once under the table, not per row
    assert table.count("slack = sum of 1 non-negative term(s) exactly") == 0
    assert _visible_text(page).count("slack = sum of 1 non-negative term(s) exactly") == 1
    assert table.count("lhs - rhs = 0 exactly") == 1  # the step that differs says its own


def test_markdown_keeps_dollar_math_in_table_rows():
    md = render_markdown(_run())
    assert r"| 1 | $= \tfrac{1}{2} k_{s} \operatorname{tr}(" in md
    rows = [line for line in md.splitlines() if line.startswith("| 2 |")]
    assert rows and rows[0].count("|") - rows[0].count("\\|") == 4
    assert r"- **Checked**: Every step, with $\dot{h} \geq 0$." in md


def test_markdown_and_html_come_from_the_same_source():
    source = r"It holds: $\lVert s \rVert \leq 1$ (100\% of \_runs)."
    assert markdown_prose(source) == r"It holds: $\lVert s \rVert \leq 1$ (100% of _runs)."
    assert prose_html(source).startswith("It holds: <math")
    assert "(100% of _runs)." in prose_html(source)


def test_appendix_is_short_ascii_latex_with_every_claim():
    tex = render_latex(_run())
    assert tex.isascii()
    assert tex.startswith(r"\documentclass[10pt,twocolumn]{article}")
    assert tex.rstrip().endswith(r"\end{document}")
    part = tex.split("% begin appendix", 1)[1].split("% end appendix", 1)[0]
    assert "longtable" not in part and r"\begin{tabularx}{\columnwidth}" in part
    for cid in ("lemma9.a", "sec9.b", "lemma9.c"):
        assert part.count(r"\noindent \path{" + cid + "}") == 1
    assert "Repair:" in part and r"\ref{" not in part
    for internal in ("[exact-identity", "(declared)", "latex2mathml", "pass]"):
        assert internal not in tex


def test_supplement_is_ascii_latex_with_every_claim():
    tex = render_supplement(_run())
    assert tex.isascii()
    assert tex.startswith(r"\documentclass") and tex.rstrip().endswith(r"\end{document}")
    assert "latex2mathml typesets" not in tex
    for cid in ("lemma9.a", "sec9.b", "lemma9.c"):
        assert tex.count(r"\subsubsection*{\texttt{" + cid.replace("_", r"\_")) == 1
    assert tex.count(r"\subsection{Section 3, Lemma 9}") == 1
    assert r"\lambda_{\min}(\operatorname{sym}(R_{rl}))" in tex
    assert "Repaired statement" in tex


def _pdflatex(tex: str, where, name: str = "appendix") -> subprocess.CompletedProcess:
    (where / f"{name}.tex").write_text(tex)
    return subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                           f"{name}.tex"], cwd=where, capture_output=True, text=True,
                          timeout=300, check=False)


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
def test_supplement_compiles_with_pdflatex(tmp_path):
    from report_fixtures import registry_run

    from verify.claims.evidence import figure
    from verify.claims.figures import _pyplot, _save

    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(3, 2))
    ax.plot([0, 1], [0, 1])
    _save(fig, tmp_path / "figures" / "line.png")
    drawn = claim("sec9.figure", "9 Other", evidence=[
        figure("a line, $5 & 100% of it", path="figures/line.png")])
    run = registry_run()
    tex = render_supplement(run_of(*_run().results, drawn, *run.results))
    assert r"\includegraphics[width=0.8\linewidth]{figures/line.png}" in tex
    done = _pdflatex(tex, tmp_path, "supplement")
    assert done.returncode == 0, done.stdout[-2000:]
    assert (tmp_path / "supplement.pdf").read_bytes()[:5] == b"%PDF-"
    assert "Overfull \\hbox" not in done.stdout or done.stdout.count("Overfull") < 5


#: a two-column paper as an author's would be (the paper's own ifacconf class is not in
#: Debian's TeX packages): its preamble loads the packages the appendix asks for
TWO_COLUMN_PAPER = (r"\documentclass[10pt,twocolumn]{article}" "\n"
                    r"\usepackage{amsmath,amssymb,graphicx,tabularx,array,url}" "\n"
                    r"\begin{document}" "\n" r"\section{Introduction} Text." "\n"
                    "%s\n" r"\end{document}" "\n")


def _pages(done: subprocess.CompletedProcess) -> int:
    """The page count pdflatex reports ("Output written on x.pdf (3 pages, ...)")."""
    return int(re.search(r"Output written on \S+ \((\d+) pages?", done.stdout).group(1))


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
def test_the_short_appendix_pastes_into_a_two_column_paper(tmp_path):
    """The part between the markers, pasted into a two-column paper, builds in one pass
    with nothing wider than its column, and the committed run's appendix is 2-4 pages."""
    from report_fixtures import committed_run

    tex = render_latex(committed_run())
    part = tex.split("% begin appendix", 1)[1].split("% end appendix", 1)[0]
    part = part.split("\n", 1)[1]  # the marker line's remainder names the packages
    done = _pdflatex(TWO_COLUMN_PAPER % (r"\appendix" + "\n" + part), tmp_path, "paper")
    assert done.returncode == 0, done.stdout[-3000:]
    log = (tmp_path / "paper.log").read_text(errors="replace")
    assert "Rerun" not in log and "undefined" not in log.lower()
    assert not re.findall(r"Overfull \\hbox \((\d+\.\d+)pt", log) or max(
        float(x) for x in re.findall(r"Overfull \\hbox \((\d+\.\d+)pt", log)) < 2
    done = _pdflatex(tex, tmp_path, "appendix")
    assert done.returncode == 0, done.stdout[-3000:]
    assert 2 <= _pages(done) <= 4


def test_verify_all_latex_writes_the_appendix(tmp_path, capsys):
    from verify.cli import main

    out = tmp_path / "reports"
    assert main(["all", "--only", "thm1.phi", "--quick", "--latex", "--out", str(out),
                 "--certificates", str(tmp_path / "certs"), "--jobs", "1"]) == 0
    tex = (out / "supplement.tex").read_text()
    assert r"\subsubsection*{\texttt{thm1.phi}" in tex and tex.isascii()
    assert r"\path{thm1.phi}" in (out / "appendix.tex").read_text()
    assert "appendix.tex" in capsys.readouterr().out
    assert not (tmp_path / "reports" / "appendix.pdf").exists()
    assert main(["all", "--only", "thm1.phi", "--quick", "--no-latex", "--out",
                 str(tmp_path / "r2"), "--certificates", str(tmp_path / "certs"),
                 "--jobs", "1"]) == 0
    assert not (tmp_path / "r2" / "appendix.tex").exists()  # left out on request
    assert not (tmp_path / "r2" / "supplement.tex").exists()



def _chromium() -> str | None:
    return shutil.which("chromium") or shutil.which("chromium-browser")


@pytest.mark.slow
@pytest.mark.skipif(_chromium() is None, reason="chromium is not installed")
def test_chromium_parses_the_formulas_as_mathml(tmp_path):
    """The DOM Chromium builds holds the MathML elements (not text), and it renders."""
    page = tmp_path / "report.html"
    page.write_text(render_html(_run()))
    common = [_chromium(), "--headless", "--no-sandbox", "--disable-gpu",
              "--disable-background-networking", "--no-first-run",
              "--disable-component-update", "--disable-sync",
              f"--user-data-dir={tmp_path / 'profile'}"]
    dom = subprocess.run([*common, "--dump-dom", page.as_uri()], capture_output=True,
                         text=True, timeout=180, check=True).stdout
    assert dom.count("<math") == page.read_text().count("<math") >= 10
    assert "<msubsup>" in dom and "<mfrac>" in dom
    shot = tmp_path / "shot.png"
    subprocess.run([*common, f"--screenshot={shot}", "--window-size=1000,1400", page.as_uri()],
                   capture_output=True, timeout=180, check=True)
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize(("prose", "formula"), [
    ("equals <-2 sk(R̄_r)^∨, ω>: the gradient",
     r"$\langle -2 \operatorname{sk}(\bar{R}_{r})^{\vee}, \omega \rangle$"),
    ("so <grad h, grad h> = 4 on it",
     r"$\langle \operatorname{grad} h, \operatorname{grad} h\rangle = 4$"),
])
def test_an_inner_product_in_prose_is_one_formula(prose, formula):
    assert formula in prose_to_latex(prose)
