"""The paper's own derivations (Section 3: Lemma 1 and Theorem 1) as committed data.

``verify all`` checks Lemma 1 and Theorem 1 (and builds their SOS twins,
:mod:`verify.paper_proofs.sos_proofs`) from the files in ``verify/data/derivations``
(schema ``verify-derivations/1``, read by the checker's own decoder, no Python of the
proofs run), exactly as CI checks a lab's committed derivations with ``verify check
FILE.json``. The Python in :mod:`verify.paper_proofs.lemma1` and
:mod:`verify.paper_proofs.theorem1` is the front end that writes them:

    python -m verify.paper_proofs.data          # rewrite the data files

and ``tests/test_paper_derivation_data.py`` keeps every file equal to what the front end
emits (the text ``verify check FILE.py --emit`` would write).
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from importlib import resources
from pathlib import Path

from verify.proof import Derivation
from verify.proof.isolate import data_text
from verify.proof.rebuild import loads
from verify.proof.wire import LIMITS, dumps, encode


def _storage() -> list[Derivation]:
    from verify.paper_proofs import theorem1

    loop = theorem1.ClosedLoop()
    return theorem1.s_r_dot(loop) + theorem1.s_rl_dot(loop) + theorem1.storage_sign()


def _v_dot() -> list[Derivation]:
    from verify.paper_proofs import theorem1

    return theorem1.v_dot(theorem1.ClosedLoop())


def _named(module: str, name: str) -> Callable[[], list[Derivation]]:
    def build() -> list[Derivation]:
        import importlib

        return getattr(importlib.import_module(f"verify.paper_proofs.{module}"), name)()

    return build


#: Each data file (without ``.json``) and the front end that writes it.
GROUPS: dict[str, Callable[[], list[Derivation]]] = {
    "lemma1.rodrigues_spectrum": _named("lemma1", "rodrigues_spectrum"),
    "lemma1.rbar_dot_form": _named("lemma1", "rbar_dot_form"),
    "lemma1.h_dot": _named("lemma1", "h_dot"),
    "lemma1.boundary": _named("lemma1", "boundary"),
    "lemma1.trace_inequality": _named("lemma1", "trace_inequality"),
    "lemma1.gradient": _named("lemma1", "gradient"),
    "theorem1.phi_identity": _named("theorem1", "phi_identity"),
    "theorem1.storage": _storage,
    "theorem1.v_dot": _v_dot,
    "theorem1.lasalle": _named("theorem1", "lasalle"),
}

PACKAGE = "verify.data"
FOLDER = "derivations"


def emitted(group: str) -> str:
    """The data text of a group as the front end emits it: the Python's derivations
    handed over as data, rebuilt by the checker's decoder and written canonically."""
    return data_text(loads(dumps(encode(GROUPS[group]()))))


def derivations(group: str) -> list[Derivation]:
    """A group's derivations, decoded from its committed data file."""
    if group not in GROUPS:
        raise KeyError(f"no paper derivation group {group!r}")
    text = resources.files(PACKAGE).joinpath(FOLDER, f"{group}.json").read_text("ascii")
    if len(text) > LIMITS["bytes"]:
        raise ValueError(f"{group}: derivations data larger than {LIMITS['bytes']} bytes")
    return loads(text)


def write_all(folder: Path) -> list[Path]:
    """Write every group's data file into ``folder`` (the package's data folder)."""
    from verify.artefacts.atomic import write_atomic

    out = []
    for group in GROUPS:
        path = folder / f"{group}.json"
        write_atomic(path, emitted(group))
        out.append(path)
    return out


def main() -> None:
    folder = Path(str(resources.files(PACKAGE))) / FOLDER
    folder.mkdir(exist_ok=True)
    for path in write_all(folder):
        print(path, file=sys.stdout)


if __name__ == "__main__":
    main()


__all__ = ["GROUPS", "derivations", "emitted", "write_all"]
