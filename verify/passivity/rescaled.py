"""A decision about an exactly rescaled model, stated for the model as written.

A :class:`~verify.passivity.decision.Decision` of the scaled model and its
:class:`~verify.passivity.search.scaling.Rescaling` flow in; the decision about the model
as written flows out, its evidence mapped back by the congruence of
:mod:`verify.passivity.search.scaling` and re-checked exactly (a KYP certificate), re-decided
on the model as written (a frequency-domain certificate) or mapped (a witness).
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction
from typing import TYPE_CHECKING

import numpy as np

from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import Certificate, check_kyp
from verify.passivity.fd_decision import decide_positive_real
from verify.passivity.search.scaling import Rescaling, map_witness
from verify.passivity.verdicts import INCONCLUSIVE

if TYPE_CHECKING:
    from verify.passivity.decision import Decision
    from verify.passivity.model import LTIModel


def restore(d: Decision, r: Rescaling, model: LTIModel, em, margin: Fraction) -> Decision:
    """The decision of the rescaled model stated for the model as written.

    A certificate is mapped back and re-checked exactly against ``em`` (the exact model
    as written, margin applied); if that check failed (it cannot, by the congruence in
    :mod:`verify.passivity.search.scaling`) the verdict would be inconclusive.
    """
    out = replace(d, model=model, margin=margin)
    if d.nu_min is not None:
        with np.errstate(all="ignore"):  # floats (an estimate): may overflow to inf
            out = replace(out, nu_min=(float(np.ldexp(d.nu_min[0], r.freq)),
                                       float(np.ldexp(d.nu_min[1], r.gain))))
    if d.certificate is not None and not hasattr(d.certificate, "P"):
        # a frequency-domain certificate is about the scaled model; the exact route does
        # not need the scaling, so it is re-run on the model as written
        verdict, reason, cert, witness = decide_positive_real(
            em, model.name, model.source, {"margin": str(margin)})
        return replace(out, verdict=verdict, reason=reason, certificate=cert,
                       witness=witness)
    if d.certificate is not None:
        factor = ex.mpq(r.p_factor)
        P = [[factor * x for x in row] for row in d.certificate.P]
        check = check_kyp(em, P)
        if not check.ok:
            return replace(out, verdict=INCONCLUSIVE, certificate=None,
                           reason=f"the rescaled certificate fails on the model as written: "
                           f"{check.reason}")
        cert = Certificate(model.name, model.source, em, P, dict(d.certificate.meta))
        return replace(out, certificate=cert, reason=f"{d.reason} ({r.describe()}; "
                       f"P = 2^{r.gain - r.freq - 2 * r.state} P_s re-checked exactly on "
                       "the model as written)")
    if d.witness is not None:
        mapped = map_witness(d.witness, r)
        return replace(out, witness=mapped, reason=mapped.summary)
    return replace(out, reason=f"{d.reason} ({r.describe()})")



__all__ = ["restore"]
