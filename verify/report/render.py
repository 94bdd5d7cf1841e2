"""Render a :class:`~verify.claims.registry.RunResult` as Markdown, HTML and JSON.

The three renderings come from the same data: the claim registry's results. The text
says, per claim, what the paper writes, what was checked, the verdict, the finding in
plain words, the repair where one is needed, and the evidence.

Reproducible text: everything but the final "Run" block is a function of the code, the
inputs and the seed. The generation time and the timings of the checks (including the
per-step times the proof checker records) appear only in that block, and not at all
when ``SOURCE_DATE_EPOCH`` is set (:mod:`verify.report.run_info`), so committed reports
diff cleanly.
"""

from __future__ import annotations

import html
import json
import platform
from importlib import metadata
from itertools import groupby
from typing import Any

from verify import __version__
from verify.claims.model import ClaimResult, EvidenceKind, Verdict
from verify.claims.registry import RunResult
from verify.report.run_info import RunInfo

REPORT_SCHEMA = "verify-report/2"

VERDICT_MARK = {
    Verdict.VERIFIED: "verified",
    Verdict.REPAIRED: "verified with repair",
    Verdict.REFUTED: "REFUTED",
    Verdict.ASSUMPTION: "assumption",
    Verdict.INCONCLUSIVE: "INCONCLUSIVE",
}

VERDICT_MEANING = {
    Verdict.VERIFIED: "the statement holds, by exact arithmetic or an exactly re-checked "
    "certificate; numerical falsification found nothing",
    Verdict.REPAIRED: "the statement as written fails or is undefined; the stated repair "
    "holds exactly",
    Verdict.REFUTED: "the statement is false; an exactly checked witness is given",
    Verdict.ASSUMPTION: "an assumption the argument needs (stated or implicit); not checkable",
    Verdict.INCONCLUSIVE: "no verdict could be reached; the evidence says why",
}


def _versions() -> dict[str, str]:
    out = {"python": platform.python_version(), "verify": __version__}
    for pkg in ("numpy", "scipy", "sympy", "casadi", "cvxpy", "clarabel", "hypothesis"):
        try:
            out[pkg] = metadata.version(pkg)
        except metadata.PackageNotFoundError:
            out[pkg] = "not installed"
    return out


def _timeless(value: Any) -> Any:
    """A derivation's JSON without the wall-clock ``seconds`` of it and of its steps."""
    if isinstance(value, dict):
        return {k: _timeless(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [_timeless(v) for v in value]
    return value


def _claim_json(r: ClaimResult) -> dict[str, Any]:
    data = r.to_json()
    data.pop("seconds", None)
    data["evidence"] = [
        {**e, "data": _timeless(e["data"])} if e["kind"] == EvidenceKind.DERIVATION.value
        else e for e in data["evidence"]]
    return data


def run_block(run: RunResult, info: RunInfo) -> dict[str, Any]:
    """The only part of a report that changes between runs: date and timings."""
    if info.reproducible:
        return {"generated": info.stamp, "source": "SOURCE_DATE_EPOCH",
                "timings": "omitted (SOURCE_DATE_EPOCH is set)"}
    return {"generated": info.stamp, "source": "clock", "seconds": round(run.seconds, 3),
            "timings": {r.claim.id: round(r.seconds, 4) for r in run.results}}


def report_data(run: RunResult, info: RunInfo | None = None) -> dict[str, Any]:
    """The JSON document of a run (schema ``verify-report/2``; ``run`` holds the date and
    timings, everything before it is reproducible)."""
    info = info or RunInfo.from_environment()
    return {
        "schema": REPORT_SCHEMA,
        "seed": run.seed,
        "environment": _versions(),
        "counts": run.counts(),
        "claims": [_claim_json(r) for r in run.results],
        "run": run_block(run, info),
    }


def render_json(run: RunResult, info: RunInfo | None = None) -> str:
    return json.dumps(report_data(run, info), indent=2, sort_keys=False) + "\n"


def _run_lines(run: RunResult, info: RunInfo) -> list[str]:
    """The Markdown "Run" block."""
    if info.reproducible:
        return [f"Generated {info.stamp} (SOURCE_DATE_EPOCH). Timings omitted, so that the "
                "report is identical between runs."]
    lines = [f"Generated {info.stamp} in {run.seconds:.1f} s. This block is the only part "
             "of the report that changes between runs (set SOURCE_DATE_EPOCH to omit it).",
             "", "| claim | seconds |", "|---|---|"]
    lines += [f"| `{r.claim.id}` | {r.seconds:.2f} |" for r in run.results]
    return lines


def _md_escape(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _sections(run: RunResult):
    return groupby(run.results, key=lambda r: r.claim.section)


def _figure_href(e) -> str | None:
    """Link of a figure relative to the report directory (figures live in reports/figures)."""
    if e.kind is EvidenceKind.FIGURE:
        return e.data.get("href") or e.path
    return None


def _evidence_data(e) -> Any:
    data = e.to_json()["data"]
    return _timeless(data) if e.kind is EvidenceKind.DERIVATION else data


def _evidence_line(e) -> str:
    status = "pass" if e.passed else "FAIL"
    href = _figure_href(e)
    if href:
        return (f"- [{e.kind.value}, {status}] {e.summary} (`{href}`)\n\n"
                f"    ![{_md_escape(e.summary)[:80]}]({href})\n")
    path = f" (`{e.path}`)" if e.path else ""
    return f"- [{e.kind.value}, {status}] {e.summary}{path}"


def _step_rows(results, twins: set[tuple[str, int]] | None = None) -> list[dict[str, str]]:
    """One row per derivation step of a section's claims; ``twins`` are the verified SOS
    twins of the whole run (they may sit in another claim's table)."""
    rows = []
    twins = _sos_twins(results) if twins is None else twins
    for r in results:
        for e in r.outcome.evidence:
            if e.kind is not EvidenceKind.DERIVATION:
                continue
            d = e.data
            rows.append(
                {"claim": r.claim.id, "derivation": d["name"], "step": "start",
                 "relation": d["start"],
                 "justification": d["statement"], "assumptions": "", "verdict": d["verdict"],
                 "evidence": f"derivation {d['verdict']}", "proved by": ""}
            )
            for step in d["steps"]:
                if step["counterexample"]:
                    vals = step["counterexample"]["values"]
                    proof = "counterexample: " + "; ".join(
                        f"{k} = {v['value']}" for k, v in vals.items()
                    )
                else:
                    proof = step["exact"]
                extra = []
                if step["conditions"]:
                    extra.append("where " + ", ".join(step["conditions"]))
                rows.append(
                    {
                        "claim": r.claim.id,
                        "derivation": d["name"],
                        "step": str(step["index"]),
                        "relation": f"{step['relation']} {step['rhs']}",
                        "justification": step["justification"]
                        + (f" [{'; '.join(extra)}]" if extra else ""),
                        "assumptions": ", ".join(step["assumptions"]) or "none",
                        "verdict": step["verdict"],
                        "evidence": proof,
                        "proved by": _proved_by(d["name"], step, twins),
                    }
                )
    return rows


def _sos_twins(results) -> set[tuple[str, int]]:
    """(derivation, step) pairs whose SOS twin (``<name>.step<k>-sos``) was verified."""
    out = set()
    for r in results:
        for e in r.outcome.evidence:
            if e.kind is EvidenceKind.DERIVATION and e.data["verdict"] == "verified":
                name = e.data["name"]
                head, _, tail = name.rpartition(".step")
                if tail.endswith("-sos") and tail[:-4].isdigit():
                    out.add((head, int(tail[:-4])))
    return out


def _proved_by(name: str, step: dict, twins: set[tuple[str, int]]) -> str:
    """How an inequality step is proved: hand terms, SOS, or both (equalities: empty)."""
    if step["relation"] == "=":
        return ""
    if "SOS certificate" in step["justification"]:
        return "SOS"
    if step["justification"].startswith("cited:"):
        return "citation"
    return "hand terms + SOS" if (name, step["index"]) in twins else "hand terms"


_STEP_COLUMNS = ("derivation", "step", "relation", "justification", "assumptions", "verdict",
                 "proved by", "evidence")


def _section_steps_markdown(results, twins=None) -> list[str]:
    rows = _step_rows(results, twins)
    if not rows:
        return []
    out = [
        f"Every step of this proof ({len(rows)} steps; each "
        "derivation starts from its first expression, and each row relates the previous "
        "expression to the one shown):",
        "",
        "| " + " | ".join(_STEP_COLUMNS) + " |",
        "|" + "---|" * len(_STEP_COLUMNS),
    ]
    for row in rows:
        cells = [_md_escape(row[c]) for c in _STEP_COLUMNS]
        cells[0] = f"`{cells[0]}`"
        cells[5] = f"**{cells[5]}**"  # the verdict
        out.append("| " + " | ".join(cells) + " |")
    out.append("")
    return out


def render_markdown(run: RunResult, info: RunInfo | None = None) -> str:
    info = info or RunInfo.from_environment()
    data = report_data(run, info)
    lines = [
        "# Verification report",
        "",
        "Machine checks of *Passivity-based Semi-autonomous Rotational Motion Navigation for "
        "Rigid-body Networks* (the paper in `shared/paper/paper.tex`), by `verify all` "
        f"(seed {run.seed}). Date and timings are in the last section, Run.",
        "",
        "## Summary",
        "",
        "| claim | paper | verdict |",
        "|---|---|---|",
    ]
    for r in run.results:
        lines.append(
            f"| [`{r.claim.id}`](#{r.claim.id.replace('.', '')}) | {_md_escape(r.claim.paper_ref)}"
            f" | **{VERDICT_MARK[r.outcome.verdict]}** |"
        )
    counts = ", ".join(f"{v} {k}" for k, v in data["counts"].items() if v)
    lines += ["", f"Totals: {counts}.", "", "Verdicts mean:", ""]
    lines += [f"- **{VERDICT_MARK[v]}**: {m}." for v, m in VERDICT_MEANING.items()]
    for section, results in _sections(run):
        results = list(results)
        lines += ["", f"## Section {section}", ""]
        lines += _section_steps_markdown(results, _sos_twins(run.results))
        for r in results:
            lines += _claim_markdown(r)
    lines += ["", "## Environment", ""]
    lines += [f"- {k}: {v}" for k, v in data["environment"].items()]
    lines += ["", "## Run", ""]
    lines += _run_lines(run, info)
    return "\n".join(lines) + "\n"


def _claim_markdown(r: ClaimResult) -> list[str]:
    c, o = r.claim, r.outcome
    out = [
        f"### `{c.id}` — {VERDICT_MARK[o.verdict]}",
        "",
        f"- **Paper** ({c.paper_ref}): {c.paper_says}",
        f"- **Checked**: {c.statement}",
        f"- **How**: {c.method}",
        f"- **Scope**: {c.scope}",
        f"- **Finding**: {o.finding}",
    ]
    if o.repaired_statement:
        out.append(f"- **Repaired statement**: {o.repaired_statement}")
    out += ["- **Evidence**:", ""]
    out += ["  " + _evidence_line(e) for e in o.evidence]
    out.append("")
    return out


_CSS = """
body{font-family:system-ui,sans-serif;max-width:1000px;margin:2em auto;padding:0 1em;
line-height:1.45;color:#222}
table{border-collapse:collapse;width:100%}td,th{border:1px solid #ccc;padding:4px 8px;
text-align:left;vertical-align:top}th{background:#f3f3f3}
.verified{color:#176a1e;font-weight:bold}.verified-with-repair{color:#8a5a00;font-weight:bold}
.refuted{color:#b00020;font-weight:bold}.assumption{color:#555;font-weight:bold}
.inconclusive{color:#b00020;font-weight:bold}.claim{border-top:1px solid #ddd;padding-top:.5em}
.fail{color:#b00020}code{background:#f6f6f6;padding:0 3px}details{margin:.3em 0}
"""


def _run_html(run: RunResult, info: RunInfo) -> str:
    """The HTML "Run" block (date and timings)."""
    esc = html.escape
    if info.reproducible:
        return (f"<h2>Run</h2><p>Generated {esc(info.stamp)} (SOURCE_DATE_EPOCH). Timings "
                "omitted, so that the report is identical between runs.</p>")
    rows = "".join(f"<tr><td><code>{esc(r.claim.id)}</code></td><td>{r.seconds:.2f}</td></tr>"
                   for r in run.results)
    return (f"<h2>Run</h2><p>Generated {esc(info.stamp)} in {run.seconds:.1f} s. This block "
            "is the only part of the report that changes between runs (set "
            "SOURCE_DATE_EPOCH to omit it).</p>"
            f"<table><tr><th>claim</th><th>seconds</th></tr>{rows}</table>")


def render_html(run: RunResult, info: RunInfo | None = None) -> str:
    esc = html.escape
    info = info or RunInfo.from_environment()
    data = report_data(run, info)
    rows = "".join(
        f"<tr><td><a href='#{esc(r.claim.id)}'><code>{esc(r.claim.id)}</code></a></td>"
        f"<td>{esc(r.claim.paper_ref)}</td><td class='{r.outcome.verdict.value}'>"
        f"{esc(VERDICT_MARK[r.outcome.verdict])}</td></tr>"
        for r in run.results
    )
    parts = [
        "<!doctype html><html lang='en'><head><meta charset='utf-8'>",
        "<title>Verification report</title>",
        f"<style>{_CSS}</style></head><body>",
        "<h1>Verification report</h1>",
        f"<p>By <code>verify all</code> (seed {run.seed}). Date and timings are in the last "
        "section, Run.</p>",
        "<h2>Summary</h2><table><tr><th>claim</th><th>paper</th><th>verdict</th>"
        f"</tr>{rows}</table>",
        "<ul>"
        + "".join(
            f"<li><span class='{v.value}'>{esc(VERDICT_MARK[v])}</span>: {esc(m)}</li>"
            for v, m in VERDICT_MEANING.items()
        )
        + "</ul>",
    ]
    for section, results in _sections(run):
        results = list(results)
        parts.append(f"<h2>Section {esc(section)}</h2>")
        rows = _step_rows(results, _sos_twins(run.results))
        if rows:
            head = "".join(f"<th>{c}</th>" for c in _STEP_COLUMNS)
            body = "".join(
                "<tr>" + "".join(
                    f"<td class='{esc(row[c])}'>{esc(row[c])}</td>" if c == "verdict"
                    else f"<td>{esc(row[c])}</td>" for c in _STEP_COLUMNS
                ) + "</tr>"
                for row in rows
            )
            parts.append(f"<p>Every step of this proof ({len(rows)} steps):</p>"
                         f"<table><tr>{head}</tr>{body}</table>")
        for r in results:
            c, o = r.claim, r.outcome
            ev = "".join(
                f"<li class='{'' if e.passed else 'fail'}'>[{esc(e.kind.value)}, "
                f"{'pass' if e.passed else 'FAIL'}] {esc(e.summary)}"
                + (
                    f"<br><img src='{esc(_figure_href(e))}' alt='{esc(e.summary)}' "
                    "style='max-width:100%'>"
                    if _figure_href(e)
                    else ""
                )
                + (
                    f"<details><summary>data</summary><pre>"
                    f"{esc(json.dumps(_evidence_data(e), indent=1))}</pre></details>"
                    if e.data
                    else ""
                )
                + "</li>"
                for e in o.evidence
            )
            repair = (
                f"<dt>Repaired statement</dt><dd>{esc(o.repaired_statement)}</dd>"
                if o.repaired_statement
                else ""
            )
            parts.append(
                f"<div class='claim' id='{esc(c.id)}'><h3><code>{esc(c.id)}</code> — "
                f"<span class='{o.verdict.value}'>{esc(VERDICT_MARK[o.verdict])}</span></h3>"
                f"<dl><dt>Paper ({esc(c.paper_ref)})</dt><dd>{esc(c.paper_says)}</dd>"
                f"<dt>Checked</dt><dd>{esc(c.statement)}</dd>"
                f"<dt>How</dt><dd>{esc(c.method)}</dd><dt>Scope</dt><dd>{esc(c.scope)}</dd>"
                f"<dt>Finding</dt><dd>{esc(o.finding)}</dd>{repair}"
                f"<dt>Evidence</dt><dd><ul>{ev}</ul></dd></dl></div>"
            )
    env = "".join(f"<li>{esc(k)}: {esc(v)}</li>" for k, v in data["environment"].items())
    parts.append(f"<h2>Environment</h2><ul>{env}</ul>")
    parts.append(_run_html(run, info) + "</body></html>")
    return "\n".join(parts) + "\n"
