"""The full registry of the paper's claims.

Imports every module of checks, in the order of the reports, so that they register in
:data:`REGISTRY`; import :data:`REGISTRY` from here whenever every claim is needed.
"""

from verify.claims import (
    section2,  # noqa: F401  (Section 2, stealthy control)
    section3,  # noqa: F401  (Lemma 1 and Theorem 1)
    section3_dynamics,  # noqa: F401  (trajectories; dropped assumptions)
    section3_sos,  # noqa: F401  (inequality steps re-proved by SOS certificates)
    section4,  # noqa: F401  (human passivity)
    section4_identification,  # noqa: F401  (identification from the shipped logs)
)
from verify.claims.registry import REGISTRY

__all__ = ["REGISTRY"]
