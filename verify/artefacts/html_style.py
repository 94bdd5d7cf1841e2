"""The style sheet of the HTML pages ``verify`` writes.

One style for the claims report (``verify all``'s report.html) and the campaign report
(``verify campaign``'s campaign.html), which adds its own rules after it. Text flows out;
nothing here knows of claims or campaigns.
"""

REPORT_CSS = """
body{font-family:system-ui,sans-serif;max-width:960px;margin:2em auto;padding:0 1em;
line-height:1.45;color:#222}
h2{border-bottom:2px solid #ccc;padding-bottom:.2em;margin-top:2em}
table{border-collapse:collapse;width:100%;margin:.6em 0;table-layout:auto}
td,th{border:1px solid #ccc;padding:4px 8px;text-align:left;vertical-align:top;
overflow-wrap:anywhere}th{background:#f3f3f3}
table.proof{table-layout:fixed;font-size:.95em}table.proof col.k{width:4em}
table.proof col.v{width:11em}
table.proof tr.head th{background:#eef2f7;font-weight:normal}
table.proof tr.rel td{border-bottom:none;padding-top:6px;overflow-x:auto}
table.proof tr.why td{border-top:none;color:#444;font-size:.93em}
math{font-size:1.12em}table.proof tr.rel math{font-size:1.2em}
.verified{color:#176a1e;font-weight:bold}.verified-with-repair{color:#8a5a00;font-weight:bold}
.refuted{color:#b00020;font-weight:bold}.assumption{color:#555;font-weight:bold}
.inconclusive{color:#b00020;font-weight:bold}.claim{border-top:1px solid #ddd;padding-top:.5em}
.fail{color:#b00020}code{background:#f6f6f6;padding:0 3px;overflow-wrap:anywhere}
details{margin:.3em 0}pre{white-space:pre-wrap;overflow-wrap:anywhere;max-height:24em;
overflow:auto;background:#fafafa;padding:.4em}img{max-width:100%;height:auto}
dt{font-weight:bold;margin-top:.3em}dd{margin-left:1.5em}
table.summary td:first-child,table.summary td:last-child{white-space:nowrap}
table.evidence{width:auto;font-size:.9em;margin:.3em 0}table.evidence th{font-weight:normal;
background:#f3f5f8;text-align:left;vertical-align:top}.approx,.exact,.more{color:#555}
"""
