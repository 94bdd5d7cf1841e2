"""Passivity of LTI human models H(s), decided exactly (paper, Section 4).

In: a human model, an :class:`LTIModel` built from a TOML model file
(:func:`load_model`), from exact or floating-point matrices
(:func:`from_state_space`, :func:`from_transfer_function`), or from a python-control or
scipy.signal object (:func:`from_python`); every number is kept as the exact rational
it denotes. Out: a :class:`Decision` from :func:`decide` (the whole frequency axis,
optionally with a margin nu0) or a band decision from :func:`decide_band` (nu(w) >= 0
on [w1, w2] only), whose verdict is :data:`PASSIVE`, :data:`NOT_PASSIVE` or
:data:`INCONCLUSIVE` (members of :class:`GateVerdict`) with its reason; a passive
verdict carries a certificate and a not-passive verdict a witness, both checked in
exact arithmetic. Each certificate kind's exact checker lives here (in ``check`` and
``io``); a stored file of any kind is re-checked by
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
  search and check (:mod:`.verdicts`, :mod:`.decision`, :mod:`.fd_decision`,
  :mod:`.rescaled`, :mod:`.band`, :mod:`.indices`) and the ``verify gate`` command (:mod:`.gate`).

The names below are loaded on first use, so importing one submodule does not import the
solvers behind the others.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from verify.passivity.band import BandDecision, decide_band
    from verify.passivity.decision import Decision, decide
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
    "LTIModel",
    "decide",
    "decide_band",
    "from_python",
    "from_state_space",
    "from_transfer_function",
    "load_model",
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
    "decide": "verify.passivity.decision",
    "decide_band": "verify.passivity.band",
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
