"""The claim registry: every claim of the paper, its check and its verdict.

The registry (:mod:`~verify.claims.registry`) imports no module of checks; the modules of
checks (``section*``) register into it and are listed in :mod:`~verify.claims.catalog`,
the module to import for the full registry; :mod:`~verify.claims.runner` runs them.
"""

from verify.claims.model import (
    CheckContext,
    Claim,
    ClaimResult,
    Evidence,
    EvidenceKind,
    Outcome,
    Verdict,
)
from verify.claims.registry import ClaimRegistry
from verify.claims.runner import RunResult, run_claim, run_claims

__all__ = [
    "CheckContext",
    "Claim",
    "ClaimRegistry",
    "ClaimResult",
    "Evidence",
    "EvidenceKind",
    "Outcome",
    "RunResult",
    "Verdict",
    "run_claim",
    "run_claims",
]
