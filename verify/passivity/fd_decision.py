"""The frequency-domain route of the passivity gate: verdict, certificate or witness.

Runs :func:`verify.passivity.check.frequency_domain.analyse` on the exact model and packages
its outcome: a positive-real certificate (:mod:`verify.passivity.check.fd_certificate`) for a
passive verdict, an exact witness (:mod:`verify.passivity.check.fd_witness`) otherwise. The
verdict is about the transfer function H(s), which the reason says, since a
non-minimal realisation may hide modes that no storage function on its state can cover.
"""

from __future__ import annotations

from verify.passivity.check import qpoly as qp
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.fd_certificate import PrCertificate
from verify.passivity.check.fd_witness import frequency_witness_for, near_axis_pole_witness
from verify.passivity.check.frequency_domain import analyse, axis_split
from verify.passivity.check.witness import Witness
from verify.passivity.verdicts import NOT_PASSIVE, PASSIVE, GateVerdict


def _pole_witness(kind: str, reason: str, fact, extra: dict) -> Witness:
    i, j = fact.entry
    return Witness(kind, reason, {
        "entry": [i, j], "denominator": qp.coeff_strings(fact.den),
        "routh_first_column": [str(x) for x in fact.routh],
        "axis_real_roots": fact.axis_real_roots, "axis_degree": fact.axis_degree, **extra})


def decide_positive_real(model: ExactModel, name: str = "", source: str = "",
                         meta: dict | None = None
                         ) -> tuple[GateVerdict, str, PrCertificate | None, Witness | None]:
    """(verdict, reason, certificate, witness) for positive realness of H, exactly."""
    an = analyse(model)
    if an.verdict == PASSIVE:
        return PASSIVE, an.reason, PrCertificate(name, source, model, an, dict(meta or {})), None
    kind = an.failure["kind"]
    if kind == "unstable-pole":
        return NOT_PASSIVE, an.reason, None, _pole_witness(kind, an.reason, an.failure["fact"], {})
    if kind == "repeated-axis-pole":
        fact = an.failure["fact"]
        return NOT_PASSIVE, an.reason, None, _pole_witness(
            kind, an.reason, fact, {"repeated_factor": qp.coeff_strings(fact.repeated_axis)})
    sp = an.split if an.split is not None else axis_split(an.tm.d)
    if kind == "residue-not-hermitian":
        w = near_axis_pole_witness(model, sp.rho, an.tm)
        if w is not None:
            return NOT_PASSIVE, f"{an.reason}; {w.summary}", None, w
        return NOT_PASSIVE, an.reason, None, Witness(
            kind, an.reason, {"rho": qp.coeff_strings(sp.rho),
                              "pole_polynomial": qp.coeff_strings(an.tm.d)})
    if kind == "residue-not-psd":
        pole, k = an.failure["pole"], an.failure["k"]
        return NOT_PASSIVE, an.reason, None, Witness(kind, an.reason, {
            "rho": qp.coeff_strings(sp.rho), "interval": [str(pole.lo), str(pole.hi)],
            "k": k, "residue_form": qp.coeff_strings(an.residue_forms[k - 1]),
            "signs": pole.signs})
    # kind == "frequency"
    k, Q = an.failure["k"], an.failure["quotient"]
    w = frequency_witness_for(model, Q, sp.rho, k, an.tm)
    if w is not None:
        return NOT_PASSIVE, w.summary, None, w
    # the exact sign fact alone (a point was not separated from the poles in budget)
    return NOT_PASSIVE, an.reason, None, Witness(
        "negative-minor-sum", an.reason, {"k": k, "quotient": qp.coeff_strings(Q)})
