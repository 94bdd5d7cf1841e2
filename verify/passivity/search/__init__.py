"""Untrusted: searches that propose certificates and witnesses, never verdicts.

These modules work in floating point or with heuristics, and everything they return is
re-checked exactly by :mod:`verify.passivity.check` before it counts: Riccati interior
points of the KYP LMI (:mod:`.riccati`) and the KYP search around them, with the exact
removal of the LMI's equality constraints (:mod:`.kyp`, :mod:`.reduce`); the SDP that
proposes generalized KYP certificates for a band (:mod:`.gkyp_sdp`); the minimum of
nu(w) (paper, Section 4) located by Hamiltonian level crossings (:mod:`.hamiltonian`);
rounding of certificates to a coarse rational grid so their bytes do not depend on the
BLAS (:mod:`.canonical`); exact power-of-two rescaling of badly scaled models
(:mod:`.scaling`); and the search for a nearby passive model behind the
"passive within tolerance" verdict (:mod:`.tolerance`). A failure or a wrong proposal
here yields "inconclusive", never a positive verdict.
"""
