"""``verify check FILE --coq DIR``: the verified steps of a file's derivations as a Coq
development, written, audited and compiled.

Only what the checker verified is exported: a step whose verdict is not *verified*
(refuted, inconclusive, premises that contradict each other) never becomes a theorem,
and a derivation's claim is stated only when the derivation as a whole is verified. Each
derivation is exported in a forked process under the step budget
(:func:`verify.proof.budget.run_bounded`), so an expression too large for the exporter
is a step not exported, never a hang or a crash. The development is audited and read
back after writing (:func:`verify.coq.development.write_development`) and compiled by
``coqc``; the outcome is True only when every verified step reached Coq and ``coqc``
accepted every file (or, with ``allow_partial``, when ``coqc`` accepted what was
exported; each missing step is named).
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence
from pathlib import Path

from verify.coq.derivations import StepExport, derivation_unit
from verify.coq.development import CoqAuditError, coqc_available, write_development
from verify.coq.text import module_identifier
from verify.coq.unit import CoqExportError, CoqUnit
from verify.proof.budget import Budget, BudgetExceededError, run_bounded
from verify.proof.derivation import Derivation
from verify.proof.expr import MAX_DEPTH

NOT_VERIFIED = ("not verified by the checker (refuted, inconclusive or with premises "
                "that cannot hold): never exported")


def _export_one(d: Derivation, module: str, steps: frozenset[int], whole: bool
                ) -> tuple[CoqUnit | None, list[StepExport]]:
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 10 * MAX_DEPTH))  # trees are walked recursively
    try:
        return derivation_unit(d, module=module, exportable=steps, claim=whole,
                               exportable_reason=NOT_VERIFIED)
    finally:
        sys.setrecursionlimit(limit)


def export_verified(derivations: Sequence[Derivation], results: Sequence,
                    budget: Budget | None) -> tuple[list[CoqUnit], list[StepExport],
                                                    list[StepExport]]:
    """Units of the verified steps, every step's fate, and the verified steps that did not
    become a theorem (the missing ones)."""
    units: list[CoqUnit] = []
    fates: list[StepExport] = []
    missing: list[StepExport] = []
    taken: set[str] = set()
    for d, r in zip(derivations, results, strict=True):
        module = module_identifier(d.name, taken)
        steps = frozenset(k for k, s in enumerate(r.steps, start=1) if s.verdict == "verified")
        whole = r.verdict == "verified"
        work: Callable = lambda d=d, m=module, s=steps, w=whole: _export_one(d, m, s, w)  # noqa: E731
        try:
            unit, these = work() if budget is None else run_bounded(work, budget)
        except (BudgetExceededError, RuntimeError, CoqExportError, RecursionError,
                MemoryError, ValueError) as exc:
            why = f"the exporter stopped: {str(exc)[:200]}"
            unit = None
            these = [StepExport(d.name, k, None, why if k in steps else NOT_VERIFIED)
                     for k in range(1, len(d.steps) + 1)]
        if unit is not None:
            units.append(unit)
        fates += these
        missing += [f for f in these if f.theorem is None and f.step in steps]
    return units, fates, missing


def write_and_compile(folder: Path, derivations: Sequence[Derivation], results: Sequence,
                      *, budget: Budget | None = None, allow_partial: bool = False,
                      say: Callable[[str], None] = print) -> bool:
    """Export the verified steps to ``folder``, audit, compile; True when the exit status
    may be 0 (see the module's docstring). Prints one line per missing step."""
    from verify.coq.command import check_and_audit, development_files_of

    units, fates, missing = export_verified(derivations, results, budget)
    for f in fates:
        if f.theorem is None:
            tag = "missing" if f in missing else "not exported"
            say(f"  Coq: {f.derivation} step {f.step} {tag}: {f.reason}")
    try:
        write_development(folder, units)
    except CoqExportError as exc:  # the audit (CoqAuditError) or a name clash
        say(f"Coq development refused, nothing written: {exc}")
        return False
    except ValueError as exc:
        say(f"Coq development refused, nothing written: {exc}")
        return False
    done = sum(1 for f in fates if f.theorem)
    verified = done + len(missing)
    say(f"Coq development: {folder} ({done} of {verified} verified steps as theorems)")
    if not coqc_available():
        say("Coq: coqc not found: the development is not compiled, so no step is "
            "re-checked (apt-get install coq libcoq-stdlib)")
        return False
    seconds = budget.seconds if budget is not None else 600.0
    result, problems = check_and_audit(development_files_of(units), timeout_seconds=seconds)
    for p in problems:
        say(f"Coq audit: {p}")
    if not result.ok:
        tail = [ln for ln in result.output.splitlines() if ln.strip()][-3:]
        say(f"Coq: coqc refused {result.failed_file}: " + " / ".join(tail))
        return False
    if problems:
        return False
    say("Coq: coqc accepted every file; Print Assumptions lists only Coq's real-number "
        "axioms")
    if missing:
        names = ", ".join(f"{f.derivation} step {f.step}" for f in missing)
        if allow_partial:
            say(f"Coq: partial (--allow-partial): not in Coq: {names}")
            return True
        say(f"Coq: {len(missing)} verified step(s) not in Coq ({names}); exit 1 "
            "(--allow-partial accepts a partial development)")
        return False
    return True


__all__ = ["NOT_VERIFIED", "CoqAuditError", "export_verified", "write_and_compile"]
