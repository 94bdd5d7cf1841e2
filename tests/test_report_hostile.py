"""Hostile text for the report renderers, grouped by attack class.

Claim texts, derivation steps and evidence summaries are written by checks and, through
``verify check``, by users' derivation files. Whatever they hold, the HTML must not gain
markup, the LaTeX appendix must stay ASCII with balanced groups (and compile), and a
Markdown table row must keep its columns.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from dataclasses import replace

import pytest
from report_fixtures import claim, derivation, run_of, step

from verify.report.latex import render_latex, render_supplement
from verify.report.mathml import mathml, split_math
from verify.report.mathtex import latex_text, prose_to_latex, to_latex
from verify.report.render import render_html, render_markdown


def _balanced(tex: str) -> bool:
    depth = 0
    tex = tex.replace("\\\\", "").replace(r"\{", "").replace(r"\}", "")
    for ch in tex:
        depth += {"{": 1, "}": -1}.get(ch, 0)
        if depth < 0:
            return False
    return depth == 0


def _hostile_run(text: str):
    steps = [step(1, "=", text, text, conditions=[text], assumptions=[text], exact=text)]
    return run_of(claim("x.hostile", "9 " + text, statement=text, paper=text, finding=text,
                        repaired=text, evidence=[derivation("x.d", text, steps, text)]))


MARKUP = ["<script>alert(1)</script>", "</math><img src=x onerror=alert(1)>",
          "a' onmouseover='alert(1)", "<!-- comment -->"]
LATEX = [r"\input{/etc/passwd}", r"\def\x{1}\x", "}{}}{", "$a$ and $", "100% # & ~ ^ _",
         r"\\ \begin{document}", "\\"]
NOTATION = ["tr((A", ")))", "hat(", "vee(sk(R", "^^^", "__x", "<a, b", "a > b >", "(1/0)",
            "x^{", "R_{", "d/dt", "⟨☃⟩ ≥ 🙂", "\u0304\u0307", "R̄̇ᵀᵀ²", ""]
ALL = MARKUP + LATEX + NOTATION


class TestMarkupInjection:
    @pytest.mark.parametrize("text", MARKUP + LATEX)
    def test_html_gains_no_elements(self, text):
        page = render_html(_hostile_run(text))
        assert "<script>" not in page and "<img src=x" not in page
        assert "onmouseover='alert" not in page and "<!-- comment -->" not in page

    @pytest.mark.parametrize("text", MARKUP)
    def test_every_math_block_stays_wellformed(self, text):
        page = render_html(_hostile_run(text))
        for block in re.findall(r"<math\b.*?</math>", page, flags=re.S):
            ET.fromstring(block)


class TestLatexInjection:
    @pytest.mark.parametrize("text", ALL)
    def test_appendix_is_ascii_with_balanced_groups(self, text):
        for tex in (render_latex(_hostile_run(text)), render_supplement(_hostile_run(text))):
            assert tex.isascii()
            body = tex.split(r"\begin{document}", 1)[1]
            assert _balanced(body), text
            assert r"\input{" not in body and r"\def\x" not in body

    @pytest.mark.parametrize("text", ALL)
    def test_each_formula_is_balanced_ascii(self, text):
        for out in (to_latex(text), prose_to_latex(text), latex_text(text)):
            assert out.isascii() and _balanced(out), (text, out)

    @pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
    def test_appendix_of_every_hostile_text_compiles(self, tmp_path):
        results = [replace(r, claim=replace(r.claim, id=f"x.hostile{k}"))
                   for k, text in enumerate(ALL) for r in _hostile_run(text).results]
        for name, render in (("appendix", render_latex), ("supplement", render_supplement)):
            (tmp_path / f"{name}.tex").write_text(render(run_of(*results)))
            done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                                   f"{name}.tex"], cwd=tmp_path, capture_output=True,
                                  text=True, timeout=300, check=False)
            assert done.returncode == 0, done.stdout[-3000:]


class TestDollarsAndDelimiters:
    def test_a_dollar_in_prose_is_text_not_math(self):
        out = prose_to_latex("it costs $5 and $6")
        assert [is_math for is_math, _ in split_math(out)] == [False]
        assert "\\$5" in out

    @pytest.mark.parametrize("text", NOTATION)
    def test_broken_notation_still_converts_to_mathml(self, text):
        assert "class='tex'" not in mathml(to_latex(text)), text


class TestMarkdownTables:
    @pytest.mark.parametrize("text", ["a | b", "|s| > 0", "x || y", "‖x‖ | y"])
    def test_a_pipe_does_not_split_a_table_row(self, text):
        md = render_markdown(_hostile_run(text))
        rows = [line for line in md.splitlines() if line.startswith("| 1 |")
                or (line.startswith("| |") and line.endswith("** |"))]
        assert rows
        for row in rows:
            unescaped = len(re.findall(r"(?<!\\)\|", row))
            assert unescaped == 4, row
