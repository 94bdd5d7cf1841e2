"""Passivity of LTI human models H(s), decided exactly (paper, Section 4).

The public face (:mod:`.api`) takes a model in any form a control engineer holds it: a
python-control or scipy.signal object, ``(A, B, C, D)`` or ``(num, den)`` as NumPy
arrays or lists, a static gain, a model file's path (:func:`load_model`), or an
:class:`LTIModel` (:func:`as_model`; also :func:`from_python`,
:func:`from_state_space`, :func:`from_transfer_function`). Every number is kept as the
exact rational it denotes. Out:

* :func:`decide`: a :class:`Decision` on the whole frequency axis (optionally with a
  margin nu0), and :func:`decide_band`: a :class:`BandDecision` on nu(w) >= nu0 for
  w in [w1, w2] only; the verdict is :data:`PASSIVE`, :data:`NOT_PASSIVE` or
  :data:`INCONCLUSIVE` (members of :class:`GateVerdict`) with its reason; a passive
  verdict carries a certificate and a not-passive verdict a witness, both checked in
  exact arithmetic;
* :func:`nu` and :func:`relative_index`: the curves nu(w) = lambda_min(H(jw) +
  H(jw)^H)/2 and R(w) = sigma_max((I - H)(I + H)^-1) in floating point (to look at);
* :func:`passivity_indices`, :func:`ifp_index`, :func:`ofp_index`: nu_IFP and rho_OFP
  as :class:`IndexBounds` (numerical estimate, exact lower and upper bounds).

Any bad argument is one :class:`~verify.errors.VerifyInputError` with a one-line
message. Each certificate kind's exact checker lives here (in ``check`` and ``io``); a
stored file of any kind is re-checked by
:func:`verify.certificates.check_stored_certificate`.

Where the code lives, by what a verdict rests on:

* :mod:`verify.passivity.check` (trusted): the exact rational checks, namely LDL^T and
  dominance tests of semidefiniteness, KYP and generalized KYP certificate checks, the
  complete frequency-domain decision and its certificate re-check, witness confirmation
  and the exact minimal realisation. A passive or not-passive verdict rests on this
  package alone.
* :mod:`verify.passivity.search` (untrusted): Riccati and SDP proposals, the Hamiltonian
  minimum of nu(w), rescaling and rounding of certificates, the tolerance search. Their
  output is only ever a proposal for ``check``; when it fails, the verdict is
  inconclusive.
* :mod:`verify.passivity.io`: model files in, certificate JSON out and back in (strict
  parsing, the tie of a certificate to its model file).
* Top level: the model type (:mod:`.model`, :mod:`.rational`), the decisions that drive
  search and check (:mod:`.api`, :mod:`.verdicts`, :mod:`.decision`, :mod:`.fd_decision`,
  :mod:`.rescaled`, :mod:`.band`, :mod:`.indices`) and the ``verify gate`` command (:mod:`.gate`).

The names below are loaded on first use, so importing one submodule does not import the
solvers behind the others.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from verify.passivity.api import (
        as_model,
        decide,
        decide_band,
        ifp_index,
        nu,
        ofp_index,
        passivity_indices,
        relative_index,
    )
    from verify.passivity.band import BandDecision
    from verify.passivity.decision import Decision
    from verify.passivity.indices import IndexBounds
    from verify.passivity.io.model_file import load_model
    from verify.passivity.model import (
        LTIModel,
        from_python,
        from_state_space,
        from_transfer_function,
    )
    from verify.passivity.verdicts import (
        INCONCLUSIVE,
        NOT_PASSIVE,
        PASSIVE,
        PASSIVE_WITHIN,
        GateVerdict,
    )

__all__ = [
    "INCONCLUSIVE",
    "NOT_PASSIVE",
    "PASSIVE",
    "PASSIVE_WITHIN",
    "BandDecision",
    "Decision",
    "GateVerdict",
    "IndexBounds",
    "LTIModel",
    "as_model",
    "decide",
    "decide_band",
    "from_python",
    "from_state_space",
    "from_transfer_function",
    "ifp_index",
    "load_model",
    "nu",
    "ofp_index",
    "passivity_indices",
    "relative_index",
]

_HOME = {
    "INCONCLUSIVE": "verify.passivity.verdicts",
    "NOT_PASSIVE": "verify.passivity.verdicts",
    "PASSIVE": "verify.passivity.verdicts",
    "PASSIVE_WITHIN": "verify.passivity.verdicts",
    "BandDecision": "verify.passivity.band",
    "Decision": "verify.passivity.decision",
    "GateVerdict": "verify.passivity.verdicts",
    "LTIModel": "verify.passivity.model",
    "IndexBounds": "verify.passivity.indices",
    "as_model": "verify.passivity.api",
    "decide": "verify.passivity.api",
    "decide_band": "verify.passivity.api",
    "ifp_index": "verify.passivity.api",
    "nu": "verify.passivity.api",
    "ofp_index": "verify.passivity.api",
    "passivity_indices": "verify.passivity.api",
    "relative_index": "verify.passivity.api",
    "from_python": "verify.passivity.model",
    "from_state_space": "verify.passivity.model",
    "from_transfer_function": "verify.passivity.model",
    "load_model": "verify.passivity.io.model_file",
}


def __getattr__(name: str) -> Any:
    """The public name ``name``, imported from its module on first use (PEP 562)."""
    home = _HOME.get(name)
    if home is None:
        raise AttributeError(f"module 'verify.passivity' has no attribute {name!r}")
    value = getattr(import_module(home), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
