"""Render a :class:`~verify.claims.runner.RunResult` as Markdown, HTML and JSON.

The three renderings come from the same data: the claim registry's results. The text
says, per claim, what the paper writes, what was checked, the verdict, the finding in
plain words, the repair where one is needed, and the evidence.

Reproducible text: every report is a function of the code, the inputs and the seed. The
generation time and the timings of the checks (including the per-step times the proof
checker records) are never written into a report; ``verify all`` prints them and keeps
them in a separate run record (:mod:`verify.report.run_info`), so a committed report stays
byte-identical when it is regenerated.
"""

from __future__ import annotations

import html
import json
import platform
from importlib import metadata
from typing import Any

from verify import __version__
from verify.artefacts.html_style import REPORT_CSS
from verify.claims.model import ClaimResult, EvidenceKind, Verdict
from verify.claims.runner import RunResult
from verify.report.canonical import canonical_data
from verify.report.evidence_html import value_html
from verify.report.mathml import markdown_prose, mathml, prose_html
from verify.report.mathtex import normalise, prose_to_latex
from verify.report.steps import (
    StepRow,
    common_evidence,
    derivation_tables,
    sos_twins,
    table_evidence,
)

REPORT_SCHEMA = "verify-report/3"

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


#: every library whose version can change a result, a certificate or an artefact's bytes
RESULT_LIBRARIES = ("numpy", "scipy", "sympy", "python-flint", "casadi", "cvxpy", "clarabel",
                    "control", "numba", "hypothesis", "matplotlib", "pyarrow", "latex2mathml")

#: What Coq's kernel re-checks of this report and what stays trusted (the development is
#: ``certificates/coq/``, written by ``verify all``; ``verify coq --check`` compiles it).
KERNEL_NOTE = (
    "Every step whose row names a Coq theorem (module.stepK) is also stated in Coq from the"
    " readable definitions of certificates/coq/SO3.v (3 x 3 real matrices, tr, hat, vee, "
    "sk, sym, the energy function of Theorem 1's proof, rotations written by quaternions), "
    "with the paper's assumptions as named hypotheses, and proved there by field, ring, lra"
    " and lemmas proved once (such as: a rotation times its transpose is the identity). "
    "A theorem module.name is in the Coq module of that name: a file of its own, or a "
    "module of one of the files that group the units (Lemma1Steps.v, Thm1Steps.v, "
    "SosSteps.v, Certificates.v), which load the libraries once for all of them. "
    "Each SOS step (sos_<derivation>_step<k>.step<k>_by_sos) is proved from its certificate"
    " (certificates/coq/SOSCert.v): Coq re-checks by computation that the step's slack "
    "equals the certificate's weighted sum of squares (an exact LDL factorisation of each "
    "Gram matrix) and proves each multiplier positive semidefinite from the named "
    "hypotheses; where a unit vector or an angle enters through a chart, the points the "
    "chart misses (the pole (0, 0, 1), the angle pi) rest on the Python checker's "
    "continuity argument. Coq also re-checks the KYP certificate of the reconstruction for "
    "k_s = 3.0 from A, B, C, D and P (QCert.v) and the exact-band certificate of the one "
    "for k_s = 2.5 on [0, 3/2] rad/s from A, B, C, D and polynomial witnesses (BandCert.v, "
    "which computes the frequency response's numerator and denominator itself). 'verify coq"
    " --check' compiles the development and audits it: no Admitted, admit or Axiom, and "
    "Print Assumptions lists only Coq's real-number axioms and excluded middle (and, for "
    "the KYP units, which compute on machine integers, Coq's primitive integers). A "
    "positive-real certificate's stability is proved from a Lyapunov witness (PoleCert.v) "
    "when A is Hurwitz (with a pole on the imaginary axis its unit is exported in part), "
    "and a gate's refutation of one model is a Coq unit too (WitnessCert.v, written by "
    "verify gate --coq). Robust certificates over a region of identified models are units "
    "too (RobustCert.v proves once the ellipsoid's enclosing box, interval arithmetic over "
    "Q, the cover by a tree of boxes, the region's dual bound that shows a box misses it, "
    "and the Hurwitz condition of degree 2; each unit checks its leaves by computation), "
    "except those certificates/coq/NOT_EXPORTED.json lists with the reason; the report "
    "names each robust certificate's theorem. Along solutions "
    "(Coquelicot's derivatives): every rotation matrix is rot q (RotSurj.v); Lemma 1's "
    "invariance for every solution of eq. (13) under item 2 "
    "(Conclusions.lemma1_invariance_on_interval, by a last-exit argument); Theorem 1's "
    "energy V does not increase (its rate is at most minus k_s times item 2's bound "
    "times the energy of the leader relative to the average), for a human "
    "passive with a differentiable storage (Conclusions.thm1_energy_nonincreasing); by "
    "Barbalat's lemma (Barbalat.v) that energy of the leader relative to the average tends"
    " to 0, given a nonnegative storage and a Lipschitz energy along the solution as named "
    "premises (Conclusions.thm1_phi_sync_converges); the trajectory layer (Traj.v) proves "
    "the product rule and the other derivative rules once. Every derivation unit whose "
    "first expression is a time derivative (h-dot, the energies' rates, V-dot, the LaSalle "
    "step's derivative) also proves it (module.ddt): for every trajectory satisfying the "
    "declared dynamics, is_derive of the differentiated expression is that first "
    "expression, the rules applied by Coq along the expression. For an LTI human with a KYP "
    "certificate, its quadratic storage (half the form of P in the human's state) is "
    "proved dissipative from the certificate "
    "(LTIHuman.v), and along every solution of the closed loop with that human V does not "
    "increase, V(t) plus the integral of k_s lambda times the energy of the leader "
    "relative to the average is at most V(0), and the "
    "human's state stays bounded (item 4 for its state; Thm1LTI.v), for the k_s = 3.0 "
    "reconstruction (Thm1_<certificate>.thm1_energy) and for every model verify gate --coq "
    "certifies with a KYP certificate. With a bounded, Lipschitz human "
    "command and item 3 in asymptotic form (a vanishing command implies d_l -> d_r) as "
    "named premises, dbar -> d_r (Converge.v: Conclusions.thm1_dbar_converges_to_dr, by "
    "Barbalat's lemma in its second form; the paper's item 3 with LaSalle's invariance "
    "principle is not proved)."
    " Trusted beyond Coq and Coquelicot: the exporter's translation of each statement, and "
    "that the adjugate formula is the model's frequency response once Coq has checked it "
    "inverts sI - A (stated in BandCert.v)."
)


ENVIRONMENT_NOTE = ("The libraries whose versions can change a verdict, a certificate or the "
                    "bytes of an artefact (solvers propose, exact arithmetic decides; "
                    "matplotlib draws the figures, pyarrow writes campaign stores, "
                    "latex2mathml typesets this page):")


def _versions() -> dict[str, str]:
    out = {"python": platform.python_version(), "verify": __version__}
    for pkg in RESULT_LIBRARIES:
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
        {**e, "data": canonical_data(_timeless(e["data"])
                                     if e["kind"] == EvidenceKind.DERIVATION.value
                                     else e["data"])}
        for e in data["evidence"]]
    return data


def report_data(run: RunResult) -> dict[str, Any]:
    """The JSON document of a run (schema ``verify-report/3``: no date, no timings)."""
    from verify.report.kernel_status import annotate_claims

    return {
        "schema": REPORT_SCHEMA,
        "seed": run.seed,
        "environment": _versions(),
        "counts": run.counts(),
        # each step and claim with its Coq theorem and kernel status
        "claims": annotate_claims([_claim_json(r) for r in run.results]),
    }


def render_json(run: RunResult) -> str:
    return json.dumps(report_data(run), indent=2, sort_keys=False) + "\n"


def _md_escape(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def sections(results) -> list[tuple[str, list[ClaimResult]]]:
    """Claims grouped by section, each section once, in order of first appearance."""
    groups: dict[str, list[ClaimResult]] = {}
    for r in results:
        groups.setdefault(r.claim.section, []).append(r)
    return list(groups.items())


def _figure_href(e) -> str | None:
    """Link of a figure relative to the report directory (figures live in reports/figures)."""
    if e.kind is EvidenceKind.FIGURE:
        return e.data.get("href") or e.path
    return None


def _evidence_data(e) -> Any:
    data = e.to_json()["data"]
    return canonical_data(_timeless(data) if e.kind is EvidenceKind.DERIVATION else data)


def claim_latex(r: ClaimResult) -> dict[str, str]:
    """The LaTeX text (``$...$`` formulas) of a claim's fields, for the typeset formats."""
    c, o = r.claim, r.outcome
    out = {
        "paper": c.paper_latex or prose_to_latex(c.paper_says),
        "statement": c.latex or prose_to_latex(c.statement),
        "method": prose_to_latex(c.method),
        "scope": prose_to_latex(c.scope),
        "finding": prose_to_latex(o.finding),
    }
    if o.repaired_statement:
        out["repair"] = c.repair_latex or prose_to_latex(o.repaired_statement)
    return out


def _evidence_line(e) -> str:
    status = "pass" if e.passed else "FAIL"
    summary = markdown_prose(prose_to_latex(e.summary))
    href = _figure_href(e)
    if href:
        return (f"- [{e.kind.value}, {status}] {summary} (`{href}`)\n\n"
                f"    ![{_md_escape(normalise(e.summary))[:80]}]({href})\n")
    path = f" (`{e.path}`)" if e.path else ""
    theorem = _evidence_theorem(e)
    coq = f"; Coq: `{theorem}` (kernel: coq)" if theorem else ""
    return f"- [{e.kind.value}, {status}] {summary}{path}{coq}"


def _evidence_theorem(e) -> str:
    """The Coq theorem of a robust certificate's evidence ("" for any other)."""
    from verify.report.kernel_status import evidence_theorem

    return evidence_theorem({"path": e.path, "passed": e.passed})


def _verdict_cell(row: StepRow) -> str:
    return row.verdict + (f", {row.proved_by}" if row.proved_by else "")


def _steps_markdown(results, twins) -> list[str]:
    tables = derivation_tables(results, twins)
    if not tables:
        return []
    common = common_evidence(tables)
    n = sum(len(t.rows) for t in tables)
    out = [f"Every step of this part of the proof ({n} steps in {len(tables)} derivations). "
           "Each derivation starts from its first expression; each step relates the previous "
           "expression to the one on its row, with its justification and verdict below it.",
           ""]
    for t in tables:
        own = table_evidence(t, common)
        out += [f"**`{t.name}`** (claim `{t.claim}`): {markdown_prose(t.statement_latex)} "
                f"— **{t.verdict}**", "",
                "| step | expression; justification | verdict |", "|---|---|---|",
                f"| start | ${t.start_latex}$ | |"]
        for row in t.rows:
            why = markdown_prose(row.justification_latex)
            if row.assumptions != "none":
                why += "; assumes " + markdown_prose(row.assumptions_latex)
            if row.evidence and row.evidence not in (common, own):
                why += "; exact check: " + _md_escape(row.evidence)
            if row.coq_theorem:
                why += f"; Coq: `{row.coq_theorem}`"
            out.append(f"| {row.step} | ${row.relation_latex}$ | |")
            out.append(f"| | {why} | **{_verdict_cell(row)}** |")
        if own:
            out.append(f"| | exact check of each step above: {_md_escape(own)} | |")
        out.append("")
    if common:
        out += [f"Exact check of every step unless its row says otherwise: {common}.", ""]
    return out


def render_markdown(run: RunResult) -> str:
    """The Markdown report; formulas are ``$...$`` LaTeX (GitHub and most viewers typeset
    them), one heading per section of the paper."""
    data = report_data(run)
    lines = [
        "# Verification report",
        "",
        "Machine checks of *Passivity-based Semi-autonomous Rotational Motion Navigation for "
        "Rigid-body Networks* (the paper's LaTeX source is not distributed with this "
        f"repository), by `verify all` (seed {run.seed}).",
        "",
        "## Summary",
        "",
        "| claim | paper | verdict |",
        "|---|---|---|",
    ]
    for r in run.results:
        lines.append(
            f"| [`{r.claim.id}`](#{r.claim.id.replace('.', '')}) | "
            f"{markdown_prose(prose_to_latex(r.claim.paper_ref))}"
            f" | **{VERDICT_MARK[r.outcome.verdict]}** |"
        )
    counts = ", ".join(f"{v} {k}" for k, v in data["counts"].items() if v)
    lines += ["", f"Totals: {counts}.", "", "Verdicts mean:", ""]
    lines += [f"- **{VERDICT_MARK[v]}**: {m}." for v, m in VERDICT_MEANING.items()]
    lines += ["", "### Kernel check (Coq)", "", KERNEL_NOTE]
    twins = sos_twins(run.results)
    for section, results in sections(run.results):
        lines += ["", f"## Section {section}", ""]
        lines += _steps_markdown(results, twins)
        for r in results:
            lines += _claim_markdown(r)
    lines += ["", "## Environment", "", ENVIRONMENT_NOTE, ""]
    lines += [f"- {k}: {v}" for k, v in data["environment"].items()]
    return "\n".join(lines) + "\n"


def _claim_markdown(r: ClaimResult) -> list[str]:
    c, o = r.claim, r.outcome
    tex = claim_latex(r)
    out = [
        f"### `{c.id}` — {VERDICT_MARK[o.verdict]}",
        "",
        f"- **Paper** ({markdown_prose(prose_to_latex(c.paper_ref))}): "
        f"{markdown_prose(tex['paper'])}",
        f"- **Checked**: {markdown_prose(tex['statement'])}",
        f"- **How**: {markdown_prose(tex['method'])}",
        f"- **Scope**: {markdown_prose(tex['scope'])}",
        f"- **Finding**: {markdown_prose(tex['finding'])}",
    ]
    if "repair" in tex:
        out.append(f"- **Repaired statement**: {markdown_prose(tex['repair'])}")
    out += ["- **Evidence**:", ""]
    out += ["  " + _evidence_line(e) for e in o.evidence]
    out.append("")
    return out


def _steps_html(results, twins) -> str:
    esc = html.escape
    tables = derivation_tables(results, twins)
    if not tables:
        return ""
    common = common_evidence(tables)
    n = sum(len(t.rows) for t in tables)
    parts = [f"<p>Every step of this part of the proof ({n} steps in {len(tables)} "
             "derivations). Each derivation starts from its first expression; each step "
             "relates the previous expression to the one on its row, with its justification "
             "and verdict below it.</p>"]
    for t in tables:
        own = table_evidence(t, common)
        rows = [f"<tr class='head'><th colspan='3'><code>{esc(t.name)}</code> (claim "
                f"<a href='#{esc(t.claim)}'><code>{esc(t.claim)}</code></a>): "
                f"{prose_html(t.statement_latex)} — <span class='{esc(t.verdict)}'>"
                f"{esc(t.verdict)}</span></th></tr>",
                f"<tr class='rel'><td>start</td><td colspan='2'>{mathml(t.start_latex)}</td></tr>"]
        for row in t.rows:
            why = prose_html(row.justification_latex)
            if row.assumptions != "none":
                why += "; assumes " + prose_html(row.assumptions_latex)
            if row.evidence and row.evidence not in (common, own):
                why += f"<br>exact check: {esc(row.evidence)}"
            if row.coq_theorem:
                why += f"<br>Coq: <code>{esc(row.coq_theorem)}</code>"
            rows.append(f"<tr class='rel'><td>{esc(row.step)}</td><td colspan='2'>"
                        f"{mathml(row.relation_latex)}</td></tr>")
            rows.append(f"<tr class='why'><td></td><td>{why}</td><td><span "
                        f"class='{esc(row.verdict)}'>{esc(row.verdict)}</span>"
                        + (f" · {esc(row.proved_by)}" if row.proved_by else "")
                        + "</td></tr>")
        if own:
            rows.append(f"<tr class='why'><td></td><td colspan='2'>exact check of each step "
                        f"above: {esc(own)}</td></tr>")
        parts.append("<table class='proof'><colgroup><col class='k'><col><col class='v'>"
                     "</colgroup>" + "".join(rows) + "</table>")
    if common:
        parts.append(f"<p>Exact check of every step unless its row says otherwise: "
                     f"{esc(common)}.</p>")
    return "\n".join(parts)


def _evidence_html(e) -> str:
    esc = html.escape
    href = _figure_href(e)
    return (
        f"<li class='{'' if e.passed else 'fail'}'>[{esc(e.kind.value)}, "
        f"{'pass' if e.passed else 'FAIL'}] {prose_html(prose_to_latex(e.summary))}"
        + (f" (<code>{esc(e.path)}</code>)" if e.path and not href else "")
        + (f"; Coq: <code>{esc(_evidence_theorem(e))}</code> (kernel: coq)"
           if _evidence_theorem(e) else "")
        + (f"<br><img src='{esc(href)}' alt='{esc(normalise(e.summary))}'>" if href else "")
        + (f"<details><summary>data</summary>{_evidence_table(e)}</details>"
           if e.data else "")
        + "</li>"
    )


def _evidence_table(e) -> str:
    """The evidence's data as tables; a derivation's steps are the step table above, so
    here only its other fields (the steps' full record is in report.json)."""
    data = _evidence_data(e)
    if e.kind is EvidenceKind.DERIVATION and isinstance(data, dict) and "steps" in data:
        steps = len(data["steps"])
        data = {k: v for k, v in data.items() if k != "steps"}
        data["steps"] = f"{steps}, in the table above (each in full in report.json)"
    return value_html(data)


def _claim_html(r: ClaimResult) -> str:
    esc = html.escape
    c, o = r.claim, r.outcome
    tex = claim_latex(r)
    repair = (f"<dt>Repaired statement</dt><dd>{prose_html(tex['repair'])}</dd>"
              if "repair" in tex else "")
    ev = "".join(_evidence_html(e) for e in o.evidence)
    return (
        f"<div class='claim' id='{esc(c.id)}'><h3><code>{esc(c.id)}</code> — "
        f"<span class='{o.verdict.value}'>{esc(VERDICT_MARK[o.verdict])}</span></h3>"
        f"<dl><dt>Paper ({prose_html(prose_to_latex(c.paper_ref))})</dt>"
        f"<dd>{prose_html(tex['paper'])}</dd>"
        f"<dt>Checked</dt><dd>{prose_html(tex['statement'])}</dd>"
        f"<dt>How</dt><dd>{prose_html(tex['method'])}</dd>"
        f"<dt>Scope</dt><dd>{prose_html(tex['scope'])}</dd>"
        f"<dt>Finding</dt><dd>{prose_html(tex['finding'])}</dd>{repair}"
        f"<dt>Evidence</dt><dd><ul>{ev}</ul></dd></dl></div>"
    )


def render_html(run: RunResult) -> str:
    """The HTML report: formulas as MathML (rendered natively by current browsers), one
    heading per section, one table per derivation."""
    esc = html.escape
    data = report_data(run)
    rows = "".join(
        f"<tr><td><a href='#{esc(r.claim.id)}'><code>{esc(r.claim.id)}</code></a></td>"
        f"<td>{prose_html(prose_to_latex(r.claim.paper_ref))}</td>"
        f"<td class='{r.outcome.verdict.value}'>"
        f"{esc(VERDICT_MARK[r.outcome.verdict])}</td></tr>"
        for r in run.results
    )
    parts = [
        "<!doctype html><html lang='en'><head><meta charset='utf-8'>",
        "<meta name='viewport' content='width=device-width, initial-scale=1'>",
        "<title>Verification report</title>",
        f"<style>{REPORT_CSS}</style></head><body>",
        "<h1>Verification report</h1>",
        f"<p>By <code>verify all</code> (seed {run.seed}).</p>",
        "<h2>Summary</h2><table class='summary'><tr><th>claim</th><th>paper</th>"
        "<th>verdict</th>"
        f"</tr>{rows}</table>",
        "<ul>"
        + "".join(
            f"<li><span class='{v.value}'>{esc(VERDICT_MARK[v])}</span>: {esc(m)}</li>"
            for v, m in VERDICT_MEANING.items()
        )
        + "</ul>",
        f"<h3>Kernel check (Coq)</h3><p>{esc(KERNEL_NOTE)}</p>",
    ]
    twins = sos_twins(run.results)
    for section, results in sections(run.results):
        parts.append(f"<h2>Section {esc(section)}</h2>")
        steps = _steps_html(results, twins)
        if steps:
            parts.append(steps)
        parts += [_claim_html(r) for r in results]
    env = "".join(f"<li>{esc(k)}: {esc(v)}</li>" for k, v in data["environment"].items())
    parts.append(f"<h2>Environment</h2><p>{esc(ENVIRONMENT_NOTE)}</p><ul>{env}</ul>")
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"
