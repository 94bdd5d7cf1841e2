"""The paper's Coq development: Lemma 1 and Theorem 1, one unit per derivation.

:func:`paper_units` exports every derivation of :mod:`verify.paper_proofs.lemma1` and
:mod:`verify.paper_proofs.theorem1` (the same objects ``verify all`` checks) with
:mod:`verify.coq.derivations`; :func:`derivation_units` does the same for any list of
derivations (a user's file). The text is deterministic: same bytes on every run.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence

from verify.coq.derivations import StepExport, derivation_unit
from verify.coq.text import module_identifier
from verify.coq.unit import CoqUnit
from verify.proof.derivation import Derivation


def derivation_units(derivations: Sequence[Derivation], *, prefix: str = "") -> list[CoqUnit]:
    """One unit per derivation with an exportable step (deterministic text)."""
    return derivation_exports(derivations, prefix=prefix)[0]


def derivation_exports(derivations: Sequence[Derivation], *, prefix: str = "",
                       exportable: Sequence[tuple[frozenset[int], bool]] | None = None
                       ) -> tuple[list[CoqUnit], list[StepExport]]:
    """One unit per derivation with an exportable step, and every step's fate.

    ``exportable``: per derivation, the steps the checker verified and whether the
    derivation as a whole was verified (its claim is stated only then); None exports
    every step (the paper's own derivations).
    """
    units: list[CoqUnit] = []
    fates: list[StepExport] = []
    taken: set[str] = set()
    for i, d in enumerate(derivations):
        name = module_identifier(d.name, taken, prefix=prefix)
        steps_ok, whole = exportable[i] if exportable is not None else (None, True)
        unit, steps = derivation_unit(
            d, module=name, exportable=steps_ok, claim=whole,
            exportable_reason="not verified by the checker (refuted, inconclusive or "
            "with premises that cannot hold): never exported")
        fates += steps
        if unit is not None:
            units.append(unit)
    return units, fates


def paper_derivations() -> list[Derivation]:
    """Every derivation of Lemma 1 and Theorem 1, in the paper's order."""
    from verify.paper_proofs import lemma1, theorem1

    out = (lemma1.rodrigues_spectrum() + lemma1.rbar_dot_form() + lemma1.h_dot()
           + lemma1.boundary() + lemma1.gradient() + lemma1.trace_inequality())
    loop = theorem1.ClosedLoop()
    out += (theorem1.phi_identity() + theorem1.s_r_dot(loop) + theorem1.s_rl_dot(loop)
            + theorem1.storage_sign() + theorem1.v_dot(loop) + theorem1.lasalle(loop))
    return out


def paper_exports() -> tuple[list[CoqUnit], list[StepExport]]:
    """The paper's units and every step's fate, exported once per process (the
    derivations are the package's own and the text is deterministic)."""
    units, fates = _paper_exports()
    return list(units), list(fates)


@functools.cache
def _paper_exports() -> tuple[tuple[CoqUnit, ...], tuple[StepExport, ...]]:
    units, fates = derivation_exports(paper_derivations())
    return tuple(units), tuple(fates)


def paper_units() -> list[CoqUnit]:
    """The paper's development units (deterministic text)."""
    return paper_exports()[0]
