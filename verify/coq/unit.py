"""One exported Coq file: its module name, its source and the theorems it proves; the
error every exporter raises, and text made safe inside a Coq comment."""

from __future__ import annotations

import re
from dataclasses import dataclass

from verify.coq.text import inert_comment

_COQ_IDENT = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")


class CoqExportError(ValueError):
    """A step or certificate the exporter cannot state or prove in Coq (one line, with
    the reason)."""


def comment_text(text: str) -> str:
    """Text inert inside a Coq comment: :func:`verify.coq.text.inert_comment`."""
    return inert_comment(text)


@dataclass(frozen=True)
class CoqUnit:
    """A ``.v`` file of a development.

    ``name`` is the module (file stem); ``text`` the Coq source, which ``Require``s the
    prelude modules it uses by their qualified names (``From VerifyCoq Require Import
    SO3.``); ``theorems`` the top theorems whose ``Print Assumptions`` must list only the
    paper's named hypotheses and Coq's real-number axioms; ``source`` says what the unit
    was exported from (a claim id and step, a certificate file name), for reports.
    """

    name: str
    text: str
    theorems: tuple[str, ...]
    source: str = ""
    #: (theorem, statement) of every theorem the unit states, as the exporter wrote
    #: them: the round trip after writing (:func:`verify.coq.audit.statement_problems`)
    #: compares the file with these; empty for units not checked that way.
    statements: tuple[tuple[str, str], ...] = ()
    #: (theorem, term tree) of the same theorems, built from the expressions the unit
    #: was exported from (:func:`verify.coq.reparse.intended`): the written statement,
    #: read back, must be this tree.
    terms: tuple[tuple[str, str], ...] = ()
    #: The unit's check computes on machine integers (``QCert.kyp_wcheck``): its theorems'
    #: ``Print Assumptions`` may also list the primitive integers of Coq and their
    #: specifications (:data:`verify.coq.audit.MACHINE_INTEGER_AXIOMS`), and no other
    #: unit's may.
    machine_words: bool = False
    #: The file the unit is written into, as a module of its own name beside the other
    #: units of that bundle (:mod:`verify.coq.bundle`); empty: a file of its own.
    bundle: str = ""

    def __post_init__(self) -> None:
        if not _COQ_IDENT.match(self.name):
            raise ValueError(f"Coq module name must be an identifier, got name={self.name!r}")
        if self.bundle and not _COQ_IDENT.match(self.bundle):
            raise ValueError(f"Coq bundle name must be an identifier, got {self.bundle!r}")
        for theorem in self.theorems:
            if not _COQ_IDENT.match(theorem):
                raise ValueError(f"Coq theorem name must be an identifier, got {theorem!r}")
