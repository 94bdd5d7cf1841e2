"""A derivation file's SOS steps as Coq units (``verify check FILE --coq DIR``).

Every ``by_sos`` step of a user's derivation is exported by the same route as the
paper's SOS re-proofs (:mod:`verify.coq.sos`, prelude ``SOSCert.v``): the step is taken
as a one-step derivation over the same context, conditions and assumptions, its stored
certificate (written by the checker to the ``--certificates`` folder, named by the
step's claim key) is read back, and the unit proves the inequality from it. Module
names are generated (``UserSos_1``, ``UserSos_2``, ...), never taken from the file.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path

from verify.coq.sos import SosStep, certificate_for, sos_unit
from verify.coq.terms import CoqExportError
from verify.coq.unit import CoqUnit

PREFIX = "UserSos_"


def one_step(d, k: int):
    """Step ``k`` (1-based) of derivation ``d`` as a one-step derivation of its own."""
    from verify.proof.derivation import Derivation

    s = d.steps[k - 1]
    twin = Derivation(f"{d.name}.step{k}", s.lhs, d.context,
                      where=tuple(d.where) + tuple(s.where), assumes=d.assumes,
                      statement=f"step {k} of {d.name}", cite=d.cite)
    (twin.le if s.relation == "<=" else twin.ge)(s.rhs, s.because)
    return twin


def user_sos_units(derivations: Sequence, certificates: Path, *,
                   only: set[tuple[str, int]] | None = None, taken: set[str] | None = None
                   ) -> tuple[list[CoqUnit], dict[tuple[str, int], str]]:
    """Units of the derivations' SOS steps (those in ``only``, (derivation, step) pairs,
    when given), and each such step's fate: its theorem (``Module.theorem``) or
    ``refused: reason``. ``taken`` holds the casefolded module names already used."""
    units: list[CoqUnit] = []
    fates: dict[tuple[str, int], str] = {}
    taken = set() if taken is None else taken
    for d in derivations:
        for k, s in enumerate(d.steps, start=1):
            if s.because.kind != "sos" or s.relation not in ("<=", ">="):
                continue
            if only is not None and (d.name, k) not in only:
                continue
            step = SosStep(one_step(d, k), d.name, k)
            try:
                path = certificate_for(step, certificates)
            except (ValueError, KeyError, TypeError) as exc:  # no program for the step
                fates[(d.name, k)] = ("refused: no SOS program for the step "
                                      f"({type(exc).__name__})")
                continue
            if not path.is_file():
                fates[(d.name, k)] = ("refused: its certificate is not in the certificates "
                                      "folder (run verify check with the same --certificates)")
                continue
            index = len(units) + 1
            while f"{PREFIX}{index}".casefold() in taken:
                index += 1
            module = f"{PREFIX}{index}"
            try:
                data = json.loads(path.read_text(encoding="utf-8"))
                unit = sos_unit(step, data, file_label=path.name, module=module)
            except CoqExportError as exc:
                fates[(d.name, k)] = f"refused: {exc}"
                continue
            except (OSError, UnicodeDecodeError, ValueError, KeyError, TypeError,
                    AttributeError, IndexError) as exc:
                fates[(d.name, k)] = f"refused: malformed SOS certificate ({type(exc).__name__})"
                continue
            units.append(unit)
            taken.add(module.casefold())
            fates[(d.name, k)] = f"{unit.name}.{unit.theorems[0]}"
    return units, fates
