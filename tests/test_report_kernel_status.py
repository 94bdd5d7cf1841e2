"""report.json names what checked each step and claim (:mod:`verify.report.kernel_status`):
every verified step of a derivation has a Coq theorem of the committed development, or
says why not."""

from __future__ import annotations

import json
import re
from pathlib import Path

from report_fixtures import claim, derivation, run_of, step

from verify.coq.bundle import module_texts
from verify.report.kernel_status import COQ, EXACT_PYTHON, annotate_claims
from verify.report.render import report_data

ROOT = Path(__file__).resolve().parents[1]
REPORT = ROOT / "reports" / "report.json"
DEVELOPMENT = ROOT / "certificates" / "coq"


def _steps(claims):
    for c in claims:
        for e in c["evidence"]:
            if e["kind"] == "derivation":
                for s in e["data"]["steps"]:
                    yield c, e["data"]["name"], s


def test_every_verified_step_of_the_report_has_a_coq_theorem_of_the_development():
    claims = json.loads(REPORT.read_text())["claims"]
    checked = 0
    for c, name, s in _steps(claims):
        if s["verdict"] != "verified":
            continue
        assert "coq_theorem" in s and "kernel_status" in s, (c["id"], name, s["index"])
        if s["justification"].startswith("cited:"):
            assert s["kernel_status"].startswith("not-exported: a cited premise")
            continue
        theorem = s["coq_theorem"]
        assert theorem, f"{c['id']}: {name} step {s['index']} is verified without a Coq " \
            "theorem in report.json"
        assert s["kernel_status"] == COQ
        assert _theorem_in_development(theorem), theorem
        checked += 1
    assert checked >= 40  # the paper's Lemma 1 and Theorem 1 steps
    for c in claims:
        assert "kernel" in c and "coq_theorems" in c, c["id"]
    named = {s["coq_theorem"] for _, _, s in _steps(claims)} | {
        e["coq_theorem"] for c in claims for e in c["evidence"] if e.get("coq_theorem")}
    assert all(t in named for c in claims for t in c["coq_theorems"])


def _module_text(module: str) -> str | None:
    """The text of the unit ``module``: its own file, or its module in a bundle."""
    path = DEVELOPMENT / f"{module}.v"
    if path.is_file():
        return path.read_text()
    for bundle in sorted(DEVELOPMENT.glob("*.v")):
        found = module_texts(bundle.read_text())[1].get(module)
        if found is not None:
            return found
    return None


def _theorem_in_development(theorem: str) -> bool:
    module, _, local = theorem.partition(".")
    text = _module_text(module)
    return text is not None and re.search(rf"\b(Theorem|Lemma)\s+{re.escape(local)}\b",
                                          text) is not None


def test_the_robust_verdicts_of_the_report_name_their_coq_theorems():
    claims = json.loads(REPORT.read_text())["claims"]
    (ident,) = [c for c in claims if c["id"] == "sec4.identification"]
    robust = [e for e in ident["evidence"] if e.get("coq_theorem")]
    assert {e["coq_theorem"].rpartition(".")[2] for e in robust} == {
        "robust_passive", "robust_not_passive"}
    for e in robust:
        assert e["kernel_status"] == COQ and _theorem_in_development(e["coq_theorem"])
        assert e["coq_theorem"] in ident["coq_theorems"]
    # the claim also rests on exact Python evidence with no theorem (the nominal witness)
    assert ident["kernel"] == EXACT_PYTHON


def test_a_robust_certificate_evidence_is_annotated():
    from verify.report.kernel_status import annotate_evidence

    band = {"kind": "certificate", "summary": "s", "passed": True, "data": {},
            "path": "certificates/m-identified-robust-band-0-1-abc.json"}
    done = annotate_evidence(band)
    assert done["coq_theorem"] == "Cert_m_identified_robust_band_0_1_abc.robust_passive"
    assert done["kernel_status"] == COQ and annotate_evidence(done) == done
    refuted = {**band, "path": "certificates/m-identified-robust-refuted-at-2-abc.json"}
    assert annotate_evidence(refuted)["coq_theorem"].endswith(".robust_not_passive")
    assert "coq_theorem" not in annotate_evidence({**band, "passed": False})
    assert "coq_theorem" not in annotate_evidence({**band, "path": "certificates/k.json"})


def test_the_committed_report_is_annotated_as_a_fresh_render_would_be():
    data = json.loads(REPORT.read_text())
    assert annotate_claims(data["claims"]) == data["claims"]


def test_statuses_of_a_rendered_run():
    hand = derivation("demo.chain", "x", [step(1, "=", "y"), step(2, "<=", "z",
                                                               "cited: a textbook bound")])
    run = run_of(claim("c.one", "S", evidence=[hand]))
    [c] = report_data(run)["claims"]
    steps = c["evidence"][0]["data"]["steps"]
    assert steps[0]["coq_theorem"] == "demo_chain.step1" and steps[0]["kernel_status"] == COQ
    assert steps[1]["coq_theorem"] is None
    assert steps[1]["kernel_status"].startswith("not-exported: a cited premise")
    # a verified step without a theorem keeps the claim from the status "coq"
    assert c["kernel"] == EXACT_PYTHON and c["coq_theorems"] == ["demo_chain.step1"]


def test_markdown_and_html_name_a_robust_certificate_theorem():
    from verify.claims.evidence import certificate
    from verify.report import render

    name = "passive_human-identified-robust-band-0-7.97-3da104e65018.json"
    e = certificate("s", True, path=f"certificates/{name}")
    theorem = "Cert_passive_human_identified_robust_band_0_7_97_3da104e65018.robust_passive"
    assert f"Coq: `{theorem}` (kernel: coq)" in render._evidence_line(e)
    assert f"Coq: <code>{theorem}</code> (kernel: coq)" in render._evidence_html(e)
    plain = certificate("s", True, path="certificates/k.json")
    assert "Coq:" not in render._evidence_line(plain) + render._evidence_html(plain)
