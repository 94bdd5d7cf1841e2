"""report.html shows evidence data as tables and typeset values, never as JSON text."""

from __future__ import annotations

import re

from verify.report.evidence_html import LIST_ROWS, rational_html, value_html

IDENTIFICATION = {"distance": "35704861244582801215371210251967598510745/3863416241778610030",
                  "chi2": "5152973109693711/281474976710656", "inside": True}


def test_a_mapping_is_a_table_with_typeset_keys_and_values():
    page = value_html(IDENTIFICATION)
    assert page.startswith("<table class='evidence'>")
    assert page.count("<tr>") == 3
    assert "&quot;" not in page and '"chi2"' not in page and "{" not in page
    # the long rational: its decimal value and its size, not 40 digits of text
    assert "≈ 9.24178e+21" in page and "41/19 digits" in page
    assert "35704861244582801215371210251967598510745" not in page
    assert "≈ 18.307" in page and "16/15 digits" in page  # chi2: 16 digits, a decimal
    assert "<td>yes</td>" in page


def test_short_rationals_are_fractions_with_their_value():
    out = rational_html("-36/389")
    assert re.search(r"<mo>&#x02212;</mo><mfrac><mrow><mn>36</mn></mrow><mrow><mn>389</mn>",
                     out)
    assert out.endswith("≈ -0.092545</span>")


def test_keys_are_typeset_as_prose():
    page = value_html({"min tr(R-bar_r) - 1": "1/3"})
    assert "<math" in page and "min tr(R-bar_r) - 1" not in page


def test_lists_of_records_are_tables_and_long_lists_are_cut():
    rows = [{"omega": f"{k}/2", "nu": -k} for k in range(LIST_ROWS + 5)]
    page = value_html(rows)
    assert page.count("<tr>") == LIST_ROWS + 1  # header and the first rows
    assert "… and 5 more (all in report.json)" in page


def test_a_numeric_matrix_is_a_mathml_matrix_and_text_is_escaped():
    assert "<mtable" in value_html({"P": [["1/2", "0"], ["0", "3"]]})
    page = value_html({"<b>": "<script>alert(1)</script>"})
    assert "<script" not in page and "<b>" not in page  # text never becomes markup


def test_the_whole_report_html_holds_no_json_text():
    """The committed report's claims rendered again: every evidence's data is a table,
    none is JSON text (report.json still has it)."""
    from report_fixtures import committed_run

    from verify.report.render import render_html, render_json

    run = committed_run()
    page = render_html(run)
    assert "<pre>" not in page and "&quot;chi2&quot;" not in page
    assert not re.search(r"&quot;[\w -]+&quot;:", page)  # no "key": of JSON anywhere
    assert page.count("<details><summary>data</summary><table class='evidence'>") >= 20
    assert '"chi2": "5152973109693711/281474976710656"' in render_json(run)
