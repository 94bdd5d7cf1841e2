"""The claim registry: an ordered collection of the paper's claims, with unique ids.

Checks register themselves in :data:`REGISTRY` with the :meth:`ClaimRegistry.claim`
decorator; the modules of checks are listed in :mod:`verify.claims.catalog`, which is what
to import for the full registry. This module imports none of them, so every module of
checks may import it. The checks are run by :mod:`verify.claims.runner`.
"""

from __future__ import annotations

from collections.abc import Callable

from verify.claims.model import CheckFunction, Claim


class ClaimRegistry:
    """An ordered collection of claims with unique ids."""

    def __init__(self) -> None:
        self._claims: dict[str, Claim] = {}

    def claim(
        self,
        *,
        id: str,
        section: str,
        paper_ref: str,
        paper_says: str,
        statement: str,
        method: str,
        scope: str,
        latex: str = "",
        paper_latex: str = "",
        repair_latex: str = "",
    ) -> Callable[[CheckFunction], CheckFunction]:
        """Decorator registering a check function under a claim id.

        ``latex``, ``paper_latex`` and ``repair_latex`` are the LaTeX forms (text with
        ``$...$`` formulas) of ``statement``, ``paper_says`` and the repaired statement,
        used by the typeset reports.
        """

        def register(check: CheckFunction) -> CheckFunction:
            if id in self._claims:
                raise ValueError(f"claim id registered twice: {id}")
            self._claims[id] = Claim(
                id=id,
                section=section,
                paper_ref=paper_ref,
                paper_says=paper_says,
                statement=statement,
                method=method,
                scope=scope,
                check=check,
                latex=latex,
                paper_latex=paper_latex,
                repair_latex=repair_latex,
            )
            return check

        return register

    def __iter__(self):
        return iter(self._claims.values())

    def __len__(self) -> int:
        return len(self._claims)

    def get(self, claim_id: str) -> Claim:
        return self._claims[claim_id]

    def ids(self) -> list[str]:
        return list(self._claims)


#: The registry of the paper's claims; populated by importing :mod:`verify.claims.catalog`.
REGISTRY = ClaimRegistry()
