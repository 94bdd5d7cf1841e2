"""Audit of a Coq development: no proof left open, no axiom beyond the allowed ones.

Two checks, both on text: :func:`forbidden_commands` finds ``Admitted``, ``admit``,
``Axiom``, ``Parameter`` and ``Conjecture`` in the source of every ``.v`` file (comments
and strings removed); :func:`audit_assumptions` reads the output of ``Print Assumptions``
for every top theorem (``All.v``) and refuses any axiom not in :data:`ALLOWED_AXIOMS`,
Coq's own axioms of the real numbers and excluded middle. Hypotheses of the paper are
section variables, which Coq turns into premises of the theorems, so they never appear
as axioms.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

#: The axioms Coq's standard library of real numbers (8.16) rests on, and excluded
#: middle (``Classical_Prop.classic``), which the standard library's mean value theorem
#: behind Theorem 1's "V does not increase" (prelude ``Thm1Energy.v``) brings in.
ALLOWED_AXIOMS: frozenset[str] = frozenset({
    "ClassicalDedekindReals.sig_forall_dec",
    "ClassicalDedekindReals.sig_not_dec",
    "FunctionalExtensionality.functional_extensionality_dep",
    "Classical_Prop.classic",
})

_FORBIDDEN = re.compile(r"\b(Admitted|admit|Axiom|Axioms|Parameter|Parameters|Conjecture)\b")


def strip_comments(text: str) -> str:
    """Coq source without comments (nested) and string literals."""
    out, depth, i, n = [], 0, 0, len(text)
    while i < n:
        if text.startswith("(*", i):
            depth, i = depth + 1, i + 2
        elif depth and text.startswith("*)", i):
            depth, i = depth - 1, i + 2
        elif not depth and text[i] == '"':
            j = text.find('"', i + 1)
            i = n if j < 0 else j + 1
        else:
            if not depth:
                out.append(text[i])
            i += 1
    return "".join(out)


def forbidden_commands(files: Mapping[str, str]) -> list[str]:
    """``file: word`` for every forbidden command in the ``.v`` sources given."""
    found = []
    for name, text in sorted(files.items()):
        if name.endswith(".v"):
            found += [f"{name}: {m.group(1)}" for m in _FORBIDDEN.finditer(strip_comments(text))]
    return found


@dataclass(frozen=True)
class AssumptionAudit:
    ok: bool
    axioms: tuple[str, ...]
    disallowed: tuple[str, ...]


def printed_axioms(output: str) -> list[str]:
    """Names listed under ``Axioms:`` in ``Print Assumptions`` output."""
    names, heading = [], None
    for line in output.splitlines():
        if not line or line[0].isspace():
            continue
        if line.endswith(":") and " " not in line.strip()[:-1].strip():
            heading = line[:-1]
            continue
        if line.startswith("Closed under the global context"):
            heading = None
            continue
        if heading == "Axioms":
            names.append(line.split()[0])
    return names


def audit_assumptions(output: str, allowed: Iterable[str] = ALLOWED_AXIOMS) -> AssumptionAudit:
    """Every axiom ``Print Assumptions`` printed is allowed."""
    names = tuple(sorted(set(printed_axioms(output))))
    allowed_set = set(allowed)
    bad = tuple(n for n in names if n not in allowed_set)
    return AssumptionAudit(not bad, names, bad)
