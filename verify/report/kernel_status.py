"""What checked each step and claim of a report, for the machine-readable report.json.

Every step of a checked derivation and every claim gets its Coq theorem (in the
development ``verify all`` writes to ``certificates/coq/``; ``verify coq --check``
compiles it) and a status:

- ``coq``: the step (the claim: every verified step of it, and at least one) is a
  theorem of the development;
- ``exact-python``: decided by the exact Python checkers (an exact identity, an exact
  counterexample, a certificate re-checked exactly) with no Coq theorem;
- ``not-exported: REASON``: nothing the kernel or the exact checker proves (a cited
  premise, numerical evidence, an assumption of the paper).

The names follow :func:`verify.report.steps.step_coq_theorem`; a test compares them with
the committed development. An evidence entry whose file is a robust band or refutation
certificate over an identified region (the paper's Section 4) gets its unit's theorem
(``Cert_<file>.robust_passive`` or ``.robust_not_passive``, RobustCert.v) and ``coq``;
a claim lists those theorems too, and is ``coq`` only when nothing exact it rests on lacks
a theorem.
"""

from __future__ import annotations

from typing import Any

from verify.claims.model import EvidenceKind

COQ = "coq"
EXACT_PYTHON = "exact-python"
NOT_EXPORTED = "not-exported"

#: Evidence kinds decided by exact computation in Python.
EXACT_KINDS = frozenset({"exact-identity", "exact-instance", "counterexample", "certificate",
                         "derivation"})


def step_status(name: str, step: dict, twins: set[tuple[str, int]]) -> tuple[str, str]:
    """(Coq theorem or "", status) of one step of the derivation ``name``."""
    from verify.report.steps import step_coq_theorem

    theorem = step_coq_theorem(name, step, twins)
    if theorem:
        return theorem, COQ
    if step["verdict"] == "verified":
        if step["justification"].startswith("cited:"):
            return "", f"{NOT_EXPORTED}: a cited premise ({step['justification']})"
        return "", EXACT_PYTHON
    if step["verdict"] == "refuted" and step.get("counterexample"):
        return "", EXACT_PYTHON
    return "", f"{NOT_EXPORTED}: the step is {step['verdict']}, nothing to prove"


def evidence_theorem(evidence: dict[str, Any]) -> str:
    """The Coq theorem of a passed evidence entry whose file is a robust certificate
    ("" otherwise): every shipped robust certificate is a unit of the development."""
    from verify.coq.kyp import module_name
    from verify.coq.robust import BAND_THEOREM, REFUTATION_THEOREM

    name = str(evidence.get("path") or "").rsplit("/", 1)[-1]
    if not evidence.get("passed", True) or not name.endswith(".json"):
        return ""
    if "-robust-refuted-" in name:
        return f"{module_name(name)}.{REFUTATION_THEOREM}"
    if "-robust-band-" in name:
        return f"{module_name(name)}.{BAND_THEOREM}"
    return ""


def annotate_evidence(evidence: dict[str, Any]) -> dict[str, Any]:
    """A robust certificate's evidence entry with ``coq_theorem`` and ``kernel_status``
    (``coq``); any other entry unchanged."""
    done = {k: v for k, v in evidence.items() if k not in ("coq_theorem", "kernel_status")}
    theorem = evidence_theorem(done)
    return {**done, "coq_theorem": theorem, "kernel_status": COQ} if theorem else done


def twins_of(claims: list[dict[str, Any]]) -> set[tuple[str, int]]:
    """(derivation, step) pairs whose SOS twin was verified, from the claims' JSON (as
    :func:`verify.report.steps.sos_twins` from the results)."""
    out = set()
    for c in claims:
        for e in c["evidence"]:
            if e["kind"] == EvidenceKind.DERIVATION.value and e["data"]["verdict"] == "verified":
                head, _, tail = e["data"]["name"].rpartition(".step")
                if tail.endswith("-sos") and tail[:-4].isdigit():
                    out.add((head, int(tail[:-4])))
    return out


def annotate_derivation(data: dict, twins: set[tuple[str, int]]) -> dict:
    """A derivation's JSON with ``coq_theorem`` and ``kernel_status`` on each step (the
    steps' own ``kernel`` lists the exact checker's trusted facts)."""
    steps = []
    for step in data.get("steps", []):
        theorem, status = step_status(data["name"], step, twins)
        steps.append({**step, "coq_theorem": theorem or None, "kernel_status": status})
    return {**data, "steps": steps}


def claim_status(claim: dict[str, Any]) -> dict[str, Any]:
    """The claim's ``kernel`` status and ``coq_theorems`` from its annotated JSON."""
    theorems: list[str] = []
    missing = False
    exact = False
    for e in claim["evidence"]:
        if e["kind"] == EvidenceKind.DERIVATION.value:
            for step in e["data"].get("steps", []):
                if step.get("coq_theorem"):
                    theorems.append(step["coq_theorem"])
                elif step.get("verdict") == "verified":
                    missing = True
        if e["kind"] in EXACT_KINDS and e.get("passed", True):
            exact = True
            if e.get("coq_theorem"):
                theorems.append(e["coq_theorem"])
            elif e["kind"] != EvidenceKind.DERIVATION.value:
                missing = True
    verdict = claim["verdict"]
    if verdict == "refuted":  # by an exact counterexample, whatever its steps' theorems
        status = EXACT_PYTHON if exact else f"{NOT_EXPORTED}: no exact evidence"
    elif theorems and not missing:
        status = COQ
    elif exact and verdict != "assumption":
        status = EXACT_PYTHON
    elif verdict == "assumption":
        status = f"{NOT_EXPORTED}: an assumption of the paper, not proved"
    else:
        status = f"{NOT_EXPORTED}: no exact evidence (numerical or argued)"
    return {"kernel": status, "coq_theorems": theorems}


def annotate_claims(claims: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The claims' JSON with every derivation step and every claim annotated (a pure
    function of the JSON: annotating a report.json again changes nothing)."""
    twins = twins_of(claims)
    out = []
    for c in claims:
        evidence = [{**e, "data": annotate_derivation(e["data"], twins)}
                    if e["kind"] == EvidenceKind.DERIVATION.value else annotate_evidence(e)
                    for e in c["evidence"]]
        done = {k: v for k, v in c.items() if k not in ("kernel", "coq_theorems")}
        done["evidence"] = evidence
        out.append({**done, **claim_status(done)})
    return out
