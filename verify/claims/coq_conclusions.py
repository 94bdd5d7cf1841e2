"""Kernel evidence for the paper's conclusions along solutions (Section 3, Lemma 1,
Theorem 1).

:func:`lemma1_kernel_evidence` compiles, in a temporary folder, the development of the
``Conclusions`` unit (:mod:`verify.coq.conclusions`), prints the assumptions of its top
theorems and audits them (only Coq's and the standard library's axioms).
:func:`thm1_kernel_evidence` does the same for the KYP certificate unit of the shipped
k_s = 3.0 reconstruction (Section 4) and the unit of Theorem 1 with that human in the
loop (:mod:`verify.coq.thm1_lti`; prelude ``LTIHuman.v``, ``Thm1LTI.v``). Each result is
a certificate evidence that passed only when ``coqc`` accepted everything; without
``coqc`` it is ``None`` and the claim keeps its verdict of *assumption*. Compiled once
per process; the prelude's ``.vo`` files come from the prelude cache
(:mod:`verify.coq.prelude_cache`: compiled by this ``coqc`` once per prelude text), so
a run, or a worker process of a parallel run, compiles only the units.
"""

from __future__ import annotations

import tempfile
from functools import lru_cache
from pathlib import Path

from verify.claims.evidence import certificate
from verify.claims.model import Evidence
from verify.coq.audit import audit_assumptions
from verify.coq.conclusions import MODULE, conclusion_units
from verify.coq.development import coqc_available
from verify.coq.unit import CoqUnit

#: The shipped reconstruction whose certified human enters Theorem 1 (Section 4).
KS3_MODEL = "reconstructed_ks3p0.toml"


def _check(units: list[CoqUnit], top: CoqUnit) -> tuple[bool, str, tuple[str, ...]]:
    """Compile the development of ``units`` (the prelude from the cache) and audit it:
    (accepted, one-line reason, the top theorems of ``top``)."""
    from verify.coq.command import check_and_audit, development_files_of

    tops = _check_tops(top)
    result, problems = check_and_audit(development_files_of(units))
    if not result.ok:
        return False, f"coqc refused {result.failed_file}", tops
    if problems:
        return False, "audit: " + "; ".join(problems), tops
    return True, "axioms: " + ", ".join(audit_assumptions(result.output).axioms), tops


def ks3_units() -> tuple[CoqUnit, ...]:
    """The KYP certificate unit of the shipped k_s = 3.0 reconstruction (its certificate
    found by the gate now, in a temporary folder) and its Theorem 1 unit; empty when the
    gate does not certify it passive with a KYP certificate."""
    from dataclasses import replace
    from fractions import Fraction

    from verify.coq.kyp import CoqExportError, kyp_units_from_file
    from verify.passivity.gate import run_gate
    from verify.passivity.io.model_file import load_model

    models = Path(__file__).resolve().parents[1] / "data" / "models"
    model = replace(load_model(models / KS3_MODEL), source=f"verify/data/models/{KS3_MODEL}")
    with tempfile.TemporaryDirectory(prefix="verify-ks3-") as tmp:
        [result] = run_gate([model], Fraction(0), Path(tmp))
        if not result.passed or result.certificate_path is None:
            return ()
        try:
            units = kyp_units_from_file(Path(result.certificate_path))
        except CoqExportError:
            return ()
    return tuple(units) if len(units) == 2 else ()


@lru_cache(maxsize=1)
def _compiled() -> dict[str, tuple[bool, str, tuple[str, ...]]]:
    """For ``lemma1`` and ``thm1``: (accepted, one-line reason, top theorems). One
    development of the three units first (one prelude, one cache entry); when Coq or the
    audit refuses it, each part alone, to say which."""
    unit = conclusion_units()[0]
    units = ks3_units()
    if units:
        both = _check([unit, *units], unit)
        if both[0]:
            return {"lemma1": both, "thm1": (True, both[1], _check_tops(units[-1]))}
    return {"lemma1": _check([unit], unit),
            "thm1": (_check(list(units), units[-1]) if units else
                     (False, "the gate did not certify the k_s = 3.0 model with a KYP "
                      "certificate", ()))}


def _check_tops(top: CoqUnit) -> tuple[str, ...]:
    return tuple(f"{top.name}.{name}" for name in top.theorems)


def lemma1_kernel_evidence() -> Evidence | None:
    """Certificate evidence that Coq proves Lemma 1 along every solution, or ``None``
    when ``coqc`` is not installed."""
    if not coqc_available():
        return None
    ok, detail, _ = _compiled()["lemma1"]
    return certificate(
        "Coq (with Coquelicot) proves Conclusions.lemma1_invariance_on_interval and "
        "Conclusions.lemma1_invariance_on_half_line from the prelude Lemma1Inv.v, Traj.v "
        "and RotSurj.v, compiled here; " + detail, ok)


def thm1_kernel_evidence() -> tuple[Evidence, tuple[str, ...]] | None:
    """Certificate evidence that Coq proves Theorem 1's energy inequality with the
    certified k_s = 3.0 human in the loop, and the theorems' names; ``None`` when
    ``coqc`` is not installed."""
    if not coqc_available():
        return None
    ok, detail, tops = _compiled()["thm1"]
    return certificate(
        "Coq (with Coquelicot) proves " + (", ".join(tops) or "Theorem 1's unit")
        + " from the KYP certificate unit of the k_s = 3.0 reconstruction and the prelude "
        "LTIHuman.v, Thm1LTI.v, Thm1Energy.v, Barbalat.v, compiled here; " + detail,
        ok), tops


#: The Coq theorems behind Theorem 1's convergence (prelude Barbalat.v, Converge.v).
CONVERGENCE_THEOREMS = ("thm1_phi_sync_converges", "thm1_leader_average_axes",
                        "thm1_human_command_vanishes", "thm1_dbar_converges_to_dr")


def convergence_kernel_evidence() -> Evidence | None:
    """Certificate evidence that Coq proves Theorem 1's convergence chain along every
    solution (d̄ → d_r under the named premises), or ``None`` without ``coqc``."""
    if not coqc_available():
        return None
    ok, detail, _ = _compiled()["lemma1"]
    names = ", ".join(f"{MODULE}.{name}" for name in CONVERGENCE_THEOREMS)
    return certificate(
        f"Coq (with Coquelicot) proves {names} from the prelude Barbalat.v and Converge.v, "
        "compiled here; " + detail, ok)
