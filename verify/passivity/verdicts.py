"""The passivity gate's verdicts, a closed set shared by every decision route.

Nothing flows in; the four verdicts flow out, used by the KYP route
(:mod:`verify.passivity.decision`), the exact frequency-domain route
(:mod:`verify.passivity.fd_decision`), bands and tolerances alike.
"""

from __future__ import annotations

import enum


class GateVerdict(enum.StrEnum):
    """Verdicts of the passivity gate, over all frequencies and over a band.

    A StrEnum, as :class:`verify.claims.model.Verdict` and
    :class:`verify.proof.checker.ProofVerdict`: a member equals, prints and serialises to
    JSON as its plain string, so the gate's JSON and reports are unchanged. Only
    ``PASSIVE`` rests on an exactly checked certificate of the model as written;
    ``PASSIVE_WITHIN`` on one of a perturbed model (:mod:`verify.passivity.search.tolerance`);
    ``NOT_PASSIVE`` always carries an exactly checked witness.
    """

    PASSIVE = "passive"
    NOT_PASSIVE = "not passive"
    INCONCLUSIVE = "inconclusive"
    PASSIVE_WITHIN = "passive within tolerance"


PASSIVE, NOT_PASSIVE, INCONCLUSIVE, PASSIVE_WITHIN = GateVerdict


__all__ = ["INCONCLUSIVE", "NOT_PASSIVE", "PASSIVE", "PASSIVE_WITHIN", "GateVerdict"]
