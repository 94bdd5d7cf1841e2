"""Kernel evidence for the paper's conclusions along solutions (Section 3, Lemma 1,
Theorem 1).

:func:`lemma1_kernel_evidence` compiles, in a temporary folder, the prelude modules the
``Conclusions`` unit needs and the unit itself (:mod:`verify.coq.conclusions`), prints
the assumptions of its top theorems and audits them (only Coq's and the standard
library's axioms). The result is a certificate evidence that passed only when ``coqc``
accepted everything; without ``coqc`` it is ``None`` and the claim keeps its verdict of
*assumption*. Compiled once per process.
"""

from __future__ import annotations

import subprocess
import tempfile
from functools import lru_cache
from pathlib import Path

from verify.claims.evidence import certificate
from verify.claims.model import Evidence
from verify.coq.audit import audit_assumptions
from verify.coq.conclusions import MODULE, conclusion_units
from verify.coq.development import LOGICAL_ROOT, coqc_available, prelude_sources

#: The prelude modules the Conclusions unit requires, in dependency order.
NEEDED = ("SO3", "RotSurj", "Traj", "Lemma1Inv", "Thm1Energy", "Barbalat", "Converge")


def _coqc(folder: Path, rel: str) -> subprocess.CompletedProcess:
    return subprocess.run(["coqc", "-R", ".", LOGICAL_ROOT, rel], cwd=folder,
                          capture_output=True, text=True, timeout=900, check=False)


@lru_cache(maxsize=1)
def _compiled() -> tuple[bool, str]:
    """(accepted, one-line reason) for the prelude modules, the unit and its audit."""
    unit = conclusion_units()[0]
    sources = prelude_sources()
    with tempfile.TemporaryDirectory(prefix="verify-conclusions-") as tmp:
        folder = Path(tmp)
        files = [(f"{name}.v", sources[name]) for name in NEEDED]
        files.append((f"{MODULE}.v", unit.text))
        tops = ", ".join(f"{MODULE}.{name}" for name in unit.theorems)
        files.append(("Audit.v", f"From {LOGICAL_ROOT} Require {MODULE}.\n"
                      f"Definition tops := ({tops}).\nPrint Assumptions tops.\n"))
        for rel, text in files:
            (folder / rel).write_text(text, encoding="utf-8")
            done = _coqc(folder, rel)
            if done.returncode != 0:
                return False, f"coqc refused {rel}"
        audit = audit_assumptions(done.stdout)
        if not audit.ok:
            return False, "axioms beyond the allowed ones: " + ", ".join(audit.disallowed)
        return True, "axioms: " + ", ".join(audit.axioms)


def lemma1_kernel_evidence() -> Evidence | None:
    """Certificate evidence that Coq proves Lemma 1 along every solution, or ``None``
    when ``coqc`` is not installed."""
    if not coqc_available():
        return None
    ok, detail = _compiled()
    return certificate(
        "Coq (with Coquelicot) proves Conclusions.lemma1_invariance_on_interval and "
        "Conclusions.lemma1_invariance_on_half_line from the prelude Lemma1Inv.v, Traj.v "
        "and RotSurj.v, compiled here; " + detail, ok)


#: The Coq theorems behind Theorem 1's convergence (prelude Barbalat.v, Converge.v).
CONVERGENCE_THEOREMS = ("thm1_phi_sync_converges", "thm1_leader_average_axes",
                        "thm1_human_command_vanishes", "thm1_dbar_converges_to_dr")


def convergence_kernel_evidence() -> Evidence | None:
    """Certificate evidence that Coq proves Theorem 1's convergence chain along every
    solution (d̄ → d_r under the named premises), or ``None`` without ``coqc``."""
    if not coqc_available():
        return None
    ok, detail = _compiled()
    names = ", ".join(f"{MODULE}.{name}" for name in CONVERGENCE_THEOREMS)
    return certificate(
        f"Coq (with Coquelicot) proves {names} from the prelude Barbalat.v and Converge.v, "
        "compiled here; " + detail, ok)
