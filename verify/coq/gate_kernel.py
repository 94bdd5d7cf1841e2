"""``verify gate --coq DIR``: every verdict of the gate as a Coq unit, and its kernel status.

A *passive* verdict's certificate file becomes a unit (:mod:`verify.coq.export`); a *not
passive* verdict's witness becomes a refutation unit (:mod:`verify.coq.refutation`:
``model_ok /\\ ~ positive_real``, or ``~ band_passive`` on a band). The development is
written to DIR and compiled with ``coqc`` when it is installed; each verdict then gets
its kernel status, the one a CI reads in the gate's JSON and JUnit outputs:

- ``coq``: its unit was accepted by ``coqc`` and the audit (theorem named);
- ``exact-python``: decided by the exact Python checker; Coq did not check it (coqc
  missing, or it refused the development: the line says which);
- ``not-exported: REASON``: no unit was written for it (no verdict, or no witness Coq's
  check accepts).

With ``--require-coq`` the gate fails unless every verdict it printed has status ``coq``.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from verify.coq.command import INSTALL_HINT, check_and_audit, development_files, write_export
from verify.coq.development import coqc_available
from verify.coq.export import Export, NotExported, export_certificates
from verify.coq.kyp import CoqExportError
from verify.coq.refutation import decision_unit
from verify.coq.thm1_lti import PREFIX as THM1_PREFIX
from verify.coq.unit import CoqUnit
from verify.errors import VerifyInputError
from verify.passivity.verdicts import NOT_PASSIVE

COQ = "coq"
#: coqc processes at once for the gate's units (each unit is one coqc process).
GATE_JOBS = max(1, min(2, os.cpu_count() or 1))
EXACT_PYTHON = "exact-python"
NOT_EXPORTED = "not-exported"


@dataclass(frozen=True)
class KernelStatus:
    """What checked a verdict: ``kernel`` (``coq``, ``exact-python`` or
    ``not-exported: reason``) and the Coq theorem that states it, when there is one;
    for a passive verdict with a KYP certificate, ``closed_loop`` names the theorem of
    Theorem 1 with that human in the loop (:mod:`verify.coq.thm1_lti`), when Coq
    accepted it."""

    kernel: str
    theorem: str | None = None
    closed_loop: str | None = None

    def to_json(self) -> dict:
        return {"kernel": self.kernel, "coq_theorem": self.theorem,
                "coq_closed_loop_theorem": self.closed_loop}


def default_status(result) -> KernelStatus:
    """The status of a gate result when no Coq development is asked for."""
    if result.error is not None:
        return KernelStatus(f"{NOT_EXPORTED}: no verdict (internal error of the tool)")
    if result.passed or result.decision.verdict == NOT_PASSIVE:
        return KernelStatus(EXACT_PYTHON)
    return KernelStatus(f"{NOT_EXPORTED}: no verdict to prove ({result.decision.verdict})")


def _units_of(result, index: int) -> tuple[tuple[CoqUnit, ...], str, str]:
    """(units, reason when none, what it is exported in part without): the verdict's
    unit first, then (a KYP certificate) the unit of Theorem 1 with that human."""
    if result.error is not None:
        return (), "no verdict (internal error of the tool)", ""
    if result.certificate_path is not None:
        export = export_certificates([Path(result.certificate_path)])
        if export.units:
            partly = "; ".join(i.reason for i in export.partly)
            return export.units, "", partly
        reason = export.not_exported[0].reason if export.not_exported else "not exported"
        return (), reason, ""
    if result.decision.verdict == NOT_PASSIVE:
        try:
            return (decision_unit(result.decision, f"Refutation_{index + 1}"),), "", ""
        except CoqExportError as exc:
            return (), str(exc), ""
    return (), f"no verdict to prove ({result.decision.verdict})", ""


def gate_kernel(results: Sequence, folder: Path) -> tuple[list[KernelStatus], bool]:
    """Write the development of the gate's verdicts to ``folder``, compile it when coqc is
    installed, print one line per step; each result's kernel status, and False when
    coqc (or the audit) refused the development."""
    units: list[CoqUnit] = []
    owner: list[int] = []
    loop_of: dict[int, str] = {}
    primary: list[CoqUnit] = []
    part_of: dict[int, str] = {}
    statuses: list[KernelStatus] = [default_status(r) for r in results]
    left: list[NotExported] = []
    partly: list[NotExported] = []
    for k, r in enumerate(results):
        made, reason, part = _units_of(r, k)
        name = r.decision.model.name
        if not made:
            statuses[k] = KernelStatus(f"{NOT_EXPORTED}: {reason}")
            left.append(NotExported(name, "gate verdict", reason))
            continue
        units.append(made[0])
        primary.append(made[0])
        owner.append(k)
        for extra in made[1:]:
            units.append(extra)
            if extra.name.startswith(THM1_PREFIX):
                loop_of[k] = f"{extra.name}.{extra.theorems[0]}"
        if part:
            partly.append(NotExported(name, "gate verdict", part))
            part_of[k] = part
    export = Export(tuple(units), tuple(left), tuple(partly))
    try:
        write_export(folder, export)
    except OSError as exc:
        raise VerifyInputError(f"cannot write {folder}: {exc.strerror or exc}") from None
    print(f"coq: wrote {folder} ({len(units)} unit(s))")
    for item in left:
        print(f"coq: {item.file}: not exported: {item.reason}")
    for item in partly:
        print(f"coq: {item.file}: exported in part: {item.reason}")
    if not units:
        return statuses, True
    if not coqc_available():
        print(f"coq: coqc not found, not compiled ({INSTALL_HINT})")
        return statuses, True
    # independent units (the verdicts of different models) two at a time: the
    # machine a lab's CI runs on has at least two cores
    result, problems = check_and_audit(development_files(export), GATE_JOBS)
    if result.ok and not problems:
        total = sum(s for _, s in result.timings)
        if result.prelude:
            print(f"coq: {result.prelude}")
        files = ", ".join(f"{rel} {s:.1f} s" for rel, s in result.timings)
        print(f"coq: compiled by coqc, accepted: {files} ({total:.1f} s)")
        for unit, k in zip(primary, owner, strict=True):
            theorem = f"{unit.name}.{unit.theorems[0]}"
            # a unit that states part of the verdict: the rest is the Python checker's
            statuses[k] = KernelStatus(EXACT_PYTHON if k in part_of else COQ, theorem,
                                       loop_of.get(k))
        return statuses, True
    failed = result.failed_file or "All.v"
    print(f"coq: coqc did not accept the development ({failed})")
    tail = [ln for ln in result.output.splitlines() if ln.strip()][-6:]
    if not result.ok and tail:
        print("coq: coqc: " + "\n      ".join(tail))
    for problem in problems:
        print(f"coq: audit: {problem}")
    return statuses, False


def require_coq_problems(results: Sequence, statuses: Sequence[KernelStatus]) -> list[str]:
    """The verdicts ``--require-coq`` refuses: each printed verdict not accepted by coqc."""
    return [f"{r.decision.model.name}: {s.kernel}"
            for r, s in zip(results, statuses, strict=True) if s.kernel != COQ]
