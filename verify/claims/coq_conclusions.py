"""Kernel evidence for the paper's conclusions along solutions (Section 3, Lemma 1 and
Theorem 1).

:func:`lemma1_kernel_evidence` compiles, in a temporary folder, the prelude modules the
``Conclusions`` unit needs and the unit itself (:mod:`verify.coq.conclusions`), prints
the assumptions of its top theorems and audits them (only Coq's and the standard
library's axioms). :func:`thm1_kernel_evidence` then compiles, in the same folder, the
prelude's LTI human (``QCert.v``, ``LTIHuman.v``, ``Thm1LTI.v``), the KYP certificate
unit of the shipped k_s = 3.0 reconstruction (Section 4) and the unit of Theorem 1 with
that human in the loop (:mod:`verify.coq.thm1_lti`), and audits its top theorems. Each
result is a certificate evidence that passed only when ``coqc`` accepted everything;
without ``coqc`` it is ``None`` and the claim keeps its verdict of *assumption*.
Compiled once per process.
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
from verify.coq.unit import CoqUnit

#: The prelude modules the Conclusions unit requires, in dependency order.
NEEDED = ("SO3", "RotSurj", "Traj", "Lemma1Inv", "Thm1Energy", "Barbalat")
#: The further prelude modules of Theorem 1 with a certified LTI human.
NEEDED_LTI = ("QCert", "LTIHuman", "Thm1LTI")
#: The shipped reconstruction whose certified human enters Theorem 1 (Section 4).
KS3_MODEL = "reconstructed_ks3p0.toml"


def _coqc(folder: Path, rel: str) -> subprocess.CompletedProcess:
    return subprocess.run(["coqc", "-R", ".", LOGICAL_ROOT, rel], cwd=folder,
                          capture_output=True, text=True, timeout=900, check=False)


def _compile_and_audit(folder: Path, files: list[tuple[str, str]], tops: list[str],
                       probe: str) -> tuple[bool, str]:
    """Compile ``files`` in order in ``folder``, then print the assumptions of ``tops``."""
    modules = sorted({name.split(".")[0] for name in tops})
    files = [*files, (f"{probe}.v",
                      "".join(f"From {LOGICAL_ROOT} Require {m}.\n" for m in modules)
                      + f"Definition tops := ({', '.join(tops)}).\nPrint Assumptions tops.\n")]
    done = None
    for rel, text in files:
        (folder / rel).write_text(text, encoding="utf-8")
        done = _coqc(folder, rel)
        if done.returncode != 0:
            return False, f"coqc refused {rel}"
    audit = audit_assumptions(done.stdout if done else "")
    if not audit.ok:
        return False, "axioms beyond the allowed ones: " + ", ".join(audit.disallowed)
    return True, "axioms: " + ", ".join(audit.axioms)


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
    """For ``lemma1`` and ``thm1``: (accepted, one-line reason, top theorems)."""
    unit = conclusion_units()[0]
    sources = prelude_sources()
    out: dict[str, tuple[bool, str, tuple[str, ...]]] = {}
    with tempfile.TemporaryDirectory(prefix="verify-conclusions-") as tmp:
        folder = Path(tmp)
        files = [(f"{name}.v", sources[name]) for name in NEEDED]
        files.append((f"{MODULE}.v", unit.text))
        tops = [f"{MODULE}.{name}" for name in unit.theorems]
        ok, detail = _compile_and_audit(folder, files, tops, "Audit")
        out["lemma1"] = (ok, detail, tuple(tops))
        units = ks3_units()
        if not units:
            out["thm1"] = (False, "the gate did not certify the k_s = 3.0 model with a KYP "
                           "certificate", ())
            return out
        cert, thm1 = units
        tops = [f"{thm1.name}.{name}" for name in thm1.theorems]
        files = [(f"{name}.v", sources[name]) for name in NEEDED_LTI]
        files += [(f"{cert.name}.v", cert.text), (f"{thm1.name}.v", thm1.text)]
        ok, detail = _compile_and_audit(folder, files, tops, "AuditThm1")
        out["thm1"] = (ok, detail, tuple(tops))
    return out


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
