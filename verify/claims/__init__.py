"""The claim registry: every claim of the paper, its check and its verdict."""

from verify.claims.model import (
    CheckContext,
    Claim,
    ClaimResult,
    Evidence,
    EvidenceKind,
    Outcome,
    Verdict,
)
from verify.claims.registry import ClaimRegistry, RunResult, run_claim, run_claims

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
