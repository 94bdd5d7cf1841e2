"""Every formula of the rendered reports is LaTeX with no leftovers of the checks' plain
notation: rendered from the committed report's outcomes (every registered claim, its
finding and evidence as the checks wrote them) and from the spellings a reader once found
untranslated, the Markdown report, the HTML report and the LaTeX appendix must hold none
of the patterns below inside a formula, and none of the plain spellings outside one."""

from __future__ import annotations

import html as html_lib
import re

import pytest
from report_fixtures import claim, committed_run, run_of

from verify.claims.model import Evidence, EvidenceKind
from verify.report.latex import render_latex, render_supplement
from verify.report.mathml import split_math
from verify.report.render import render_html, render_markdown

#: inside a formula's LaTeX source (or the text of a MathML element)
IN_MATH = {
    "a character lost to ASCII": r"\?",
    "bar spelled out": r"bar_|\\text\{bar|-\\text\{bar",
    "a function name as a subscript": r"_\{sos\}",
    "sum spelled out": r"(?<![\\\w])sum\b|\\text\{sum\}",
    "kappa spelled out": r"(?<![\\\w])kappa\b|\\text\{kappa",
    "chi2 spelled out": r"chi2",
    "a Python list": r"\[\s*'",
    "a claim id": r"\b(?:sec|lemma|thm)\d\.",
    "tan as text": r"\\text\{tan",
    "words run together with a symbol": r"\\dot\{V\} ?at\b|\}at\b",
    "a trailing tilde": r"[A-Za-z]~|\\sim\s*[=)]",
    "alpha or pi spelled out": r"(?<![\\\w])(alpha|pi)\b|\\text\{alpha",
    "hat spelled out": r"(?<![\\\w])hat\b|\\text\{hat",
    "dot spelled out": r"\\text\{dot",
}
#: in the text around formulas
IN_TEXT = {
    "R-bar spelled out": r"\b[A-Za-z]-bar_",
    "kappa(W)": r"\bkappa\(",
    "chi2": r"\bchi2\b",
    "a Python list": r"\['",
    "W~": r"\b[A-Z]~",
    "alpha = pi/2": r"\balpha = pi",
    "hat v": r"\bhat [a-z]\b",
    "1/|sum d_i|": r"\bsum d_i",
}

#: the spellings once found untranslated, each in a sentence as the checks write them
SPELLINGS = [
    "On the boundary 1 - tan²(θ/2) = 0 and tr(R-bar_r) >= 1; see lemma1.boundary-h-dot.",
    "V̇ at R_l = R̄ vanishes; sec2.dbar-dot and thm1.S_rl-dot.step4-sos agree, by_sos() too.",
    "kappa(W) grows like 1/|sum d_i| on a nearly opposite pair; W~ = P (n I - sum d_i) P.",
    "along it alpha grows at unit rate and reaches 0 at alpha = pi/2, in finite time",
    "tr(A hat v) = 0 and chi2 = 18.31, exact; not PSD at v = ['-1', '1'], so not passive",
]


def _spelling_run():
    evidence = tuple(Evidence(EvidenceKind.NUMERICAL, s, {}) for s in SPELLINGS)
    return run_of(*(claim(f"sec9.c{k}", "9", statement=s, finding=s, paper=s,
                          evidence=evidence) for k, s in enumerate(SPELLINGS)))


def _formulas_and_text(source: str) -> tuple[list[str], str]:
    pieces = split_math(source)
    return [p for m, p in pieces if m], " ".join(p for m, p in pieces if not m)


def _html_math_and_text(page: str) -> tuple[list[str], str]:
    maths = re.findall(r"<math\b.*?</math>", page, flags=re.S)
    # an accent (the over-mark of a mover: W-tilde, R-bar) is typeset, not a leftover
    maths = [re.sub(r"<mo\b[^>]*>[^<]*</mo></mover>", "</mover>", m) for m in maths]
    inner = [html_lib.unescape(re.sub(r"<[^>]+>", "", m)) for m in maths]
    rest = re.sub(r"<math\b.*?</math>", " ", page, flags=re.S)
    rest = re.sub(r"<(pre|style)\b.*?</\1>", " ", rest, flags=re.S)  # evidence data as JSON
    return inner, html_lib.unescape(re.sub(r"<[^>]+>", " ", rest))


def _leftovers(formulas: list[str], text: str) -> list[str]:
    found = [f"{what}: {f}" for f in formulas for what, p in IN_MATH.items()
             if re.search(p, f)]
    found += [f"{what} in text: ...{text[max(0, m.start() - 40):m.end() + 40]}..."
              for what, p in IN_TEXT.items() for m in re.finditer(p, text)]
    return found


@pytest.fixture(scope="module", params=["committed", "spellings"])
def run(request):
    return committed_run() if request.param == "committed" else _spelling_run()


def test_markdown_formulas_have_no_leftovers(run):
    md = render_markdown(run)
    md = re.sub(r"`[^`\n]*`", " ", md)  # code spans name files and claims as they are
    md = re.sub(r"!\[[^\]]*\]\([^)]*\)", " ", md)  # figure links
    formulas, text = _formulas_and_text(md)
    assert formulas
    assert _leftovers(formulas, text) == []


def test_appendix_and_supplement_formulas_have_no_leftovers(run):
    for tex in (render_latex(run), render_supplement(run)):
        body = re.sub(r"\\(path|texttt|url|includegraphics(\[[^]]*\])?)\{[^}]*\}", " ", tex)
        formulas, text = _formulas_and_text(body)
        assert formulas
        assert _leftovers(formulas, text) == []
        assert tex.isascii()


def test_html_formulas_have_no_leftovers(run):
    page = render_html(run)
    page = re.sub(r"<code>.*?</code>", " ", page, flags=re.S)
    formulas, text = _html_math_and_text(page)
    assert formulas
    assert _leftovers(formulas, text) == []
    assert "merror" not in page  # no formula the converter refused


def test_the_leftover_patterns_catch_the_old_spellings():
    """The patterns are not vacuous: the raw spellings trip them."""
    assert _leftovers([r"1 - \text{tan}?(\theta /2)", r"\text{lemma1.boundary}-\dot{h}",
                       r"\dot{V} at R_{l}", "by_{sos}()"], "kappa(W) and W~ and ['-1']")


def test_an_exact_counterexample_is_written_in_rationals():
    from verify.claims.proofs import exact_value_text

    value = {"parameters": ["-7/8", "-19/7", "15/2", "39/5", "-36/5", "-12/5"],
             "value": [-0.875, 7.8, -7.2, 7.8, -2.714286, -2.4, -7.2, -2.4, 7.5]}
    assert exact_value_text("A", value) == ("A = ((-7/8, 39/5, -36/5), (39/5, -19/7, -12/5), "
                                        "(-36/5, -12/5, 15/2)) exactly (rows)")
    value["value"][4] = -2.71  # matches no parameter: the rounding is stated
    assert "rounded to 6 decimals; exact parameters -7/8" in exact_value_text("A", value)


def test_a_witness_value_is_written_exactly_or_said_to_be_rounded():
    from fractions import Fraction

    from verify.passivity.check.witness import _rounded_up, vector_witness

    short = vector_witness(Fraction(21, 8), 2.625, "-0.0938", [1, 0], Fraction(-3, 32), 1)
    assert "v = -3/32 < 0" in short.summary
    long = vector_witness(Fraction(21, 8), 2.625, "-0.0938", [1, 0],
                          Fraction(-93841234567, 10 ** 12), 1)
    assert "-0.0938 (rounded; exact in the data)" in long.summary
    assert long.data["value"] == "-93841234567/1000000000000"
    bound = Fraction(-9386, 100000)  # rounded to nearest: -0.0939, below the bound
    assert _rounded_up(bound) == "-0.0938" and Fraction("-0.0938") >= bound


def test_a_written_double_hyphen_is_not_set_as_an_en_dash_in_latex():
    """A flag such as --check keeps both hyphens in LaTeX; en and em dashes stay dashes."""
    from verify.report.mathtex import latex_text

    assert latex_text("verify coq --check") == "verify coq -{}-check"
    assert latex_text("Sections 2–4 — done") == "Sections 2--4 --- done"
    assert latex_text("---") == "-{}-{}-"
