"""Imports every module of checks so that they register in :data:`REGISTRY`.

Later sections (Lemma 1, Theorem 1, human passivity) add their modules here.
"""

from verify.claims import (
    section2,  # noqa: F401  (registers the Section 2 claims)
    section3,  # noqa: F401  (Lemma 1 and Theorem 1)
)
from verify.claims.registry import REGISTRY

__all__ = ["REGISTRY"]
