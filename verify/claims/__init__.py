"""The claim registry (DESIGN.md: "The spine is a claim registry")."""

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
