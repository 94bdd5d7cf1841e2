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

#: Coq's primitive 63-bit integers (``PrimInt63``) and the axioms of the standard
#: library that specify them (``Uint63``): the KYP units' check computes on them, through
#: bignums' ``BigZ`` (``QCert.kyp_wcheck``). Allowed for those units' theorems only
#: (:func:`audit_assumptions` with ``word_block``).
MACHINE_INTEGER_AXIOMS: frozenset[str] = frozenset(
    [f"PrimInt63.{op}" for op in (
        "int", "add", "addc", "addcarryc", "addmuldiv", "compare", "div", "diveucl",
        "diveucl_21", "eqb", "head0", "land", "leb", "lor", "lsl", "lsr", "ltb", "lxor",
        "mod", "mul", "mulc", "sub", "subc", "subcarryc", "tail0")]
    + [f"Uint63.{spec}" for spec in (
        "add_spec", "addc_def_spec", "addcarryc_def_spec", "addmuldiv_def_spec",
        "compare_def_spec", "div_spec", "diveucl_21_spec", "diveucl_def_spec",
        "eqb_correct", "eqb_refl", "head0_spec", "land_spec", "leb_spec", "lor_spec",
        "lsl_spec", "lsr_spec", "ltb_spec", "lxor_spec", "mod_spec", "mul_spec",
        "mulc_spec", "of_to_Z", "sub_spec", "subc_def_spec", "subcarryc_def_spec",
        "tail0_spec")])

_FORBIDDEN = re.compile(r"\b(Admitted|admit|Axiom|Axioms|Parameter|Parameters|Conjecture)\b")


_COMMENT_TOKEN = re.compile(r'\(\*|\*\)|"')


def strip_comments(text: str) -> str:
    """Coq source without comments (nested) and string literals."""
    out, depth, i, n = [], 0, 0, len(text)
    pos = 0  # start of the text outside comments not yet copied
    while i < n:
        found = _COMMENT_TOKEN.search(text, i)
        if found is None:
            break
        token, start = found.group(), found.start()
        if token == "(*":
            if not depth:
                out.append(text[pos:start])
            depth, i = depth + 1, start + 2
        elif token == "*)":
            if depth:  # outside comments a stray "*)" stays in the text
                depth -= 1
                pos = start + 2
            i = start + 2
        elif depth:  # a quote inside a comment
            i = start + 1
        else:
            out.append(text[pos:start])
            j = text.find('"', start + 1)
            i = pos = n if j < 0 else j + 1
    if not depth:
        out.append(text[pos:])
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


def assumption_blocks(output: str) -> list[str]:
    """The output of successive ``Print Assumptions`` commands, one block each: a block
    starts at an ``Axioms:`` heading or is the line ``Closed under the global context``."""
    blocks: list[list[str]] = []
    for line in output.splitlines():
        if line == "Axioms:" or line.startswith("Closed under the global context"):
            blocks.append([line])
        elif blocks:
            blocks[-1].append(line)
    return ["\n".join(b) + "\n" for b in blocks]


def audit_assumptions(output: str, allowed: Iterable[str] = ALLOWED_AXIOMS, *,
                      word_block: bool = False) -> AssumptionAudit:
    """Every axiom ``Print Assumptions`` printed is allowed. With ``word_block`` the
    last block is that of the machine-integer units' theorems (``All.v`` prints it
    last), where :data:`MACHINE_INTEGER_AXIOMS` are allowed too."""
    allowed_set = set(allowed)
    blocks = assumption_blocks(output) if word_block else []
    if blocks:
        head = "".join(blocks[:-1])
        found = [(n, n in allowed_set) for n in printed_axioms(head)]
        found += [(n, n in allowed_set or n in MACHINE_INTEGER_AXIOMS)
                  for n in printed_axioms(blocks[-1])]
    else:
        found = [(n, n in allowed_set) for n in printed_axioms(output)]
    names = tuple(sorted({n for n, _ in found}))
    bad = tuple(sorted({n for n, ok in found if not ok}))
    return AssumptionAudit(not bad, names, bad)


#: The first words of the top-level commands the exporters' templates write (a command
#: between ``Proof`` and ``Qed`` is a tactic, and only ``Qed`` may end it); ``Local`` only
#: as ``Local Notation`` or ``Local Open``, ``Print`` only as ``Print Assumptions``
#: (``All.v``), ``Module`` only as ``Module <name>`` (a unit of a bundle,
#: :mod:`verify.coq.bundle`).
TEMPLATE_COMMANDS: frozenset[str] = frozenset({
    "From", "Require", "Import", "Open", "Section", "Module", "End", "Variable", "Variables",
    "Hypothesis", "Hypotheses", "Local", "Let", "Definition", "Theorem", "Lemma", "Proof",
    "Print",
})
_TWO_WORDS = {"Local": ("Notation", "Open"), "Print": ("Assumptions",)}
_PLAIN_MODULE = re.compile(
    r"Module\s+(?!(?:Type|Import|Export)\b)[A-Za-z][A-Za-z0-9_]*\Z")


def sentences(text: str) -> list[str]:
    """The sentences of Coq source (comments and strings removed; each ends at a ``.``
    followed by white space or the end), stripped, empty ones left out."""
    parts = re.split(r"\.(?=\s|\Z)", strip_comments(text))
    return [p.strip() for p in parts if p.strip()]


def template_problems(files: Mapping[str, str], skip: Iterable[str] = ()) -> list[str]:
    """``file: problem`` for every top-level command of the ``.v`` files (those not in
    ``skip``: the prelude) that is not one of the templates' (:data:`TEMPLATE_COMMANDS`),
    every proof not ended by ``Qed`` and any text after the last sentence."""
    skipped = set(skip)
    found: list[str] = []
    for name, text in sorted(files.items()):
        if not name.endswith(".v") or name in skipped:
            continue
        stripped = strip_comments(text).rstrip()
        if stripped and not stripped.endswith("."):
            found.append(f"{name}: text after the last command")
        in_proof = False
        for sentence in sentences(text):
            words = sentence.split()
            head = words[0]
            if in_proof:
                if head in ("Qed", "Defined", "Admitted", "Abort", "Save"):
                    in_proof = False
                    if head != "Qed" or len(words) > 1:
                        found.append(f"{name}: a proof ends with {sentence[:40]!r}, not Qed")
                continue
            if head not in TEMPLATE_COMMANDS or (
                    head in _TWO_WORDS and (len(words) < 2 or words[1] not in _TWO_WORDS[head])
            ) or (head == "Module" and not _PLAIN_MODULE.match(sentence)):
                found.append(f"{name}: command outside the template: {sentence[:60]!r}")
            in_proof = head == "Proof"
        if in_proof:
            found.append(f"{name}: a proof is not closed")
    return found


_THEOREM = re.compile(r"(Theorem|Lemma)\s+([A-Za-z_][A-Za-z0-9_']*)\s*:\s*(.*)\Z", re.S)


def stated_theorems(text: str) -> dict[str, str]:
    """Theorem (and lemma) name -> statement as written in Coq source (white space
    collapsed); a name stated twice keeps its first statement and is listed as ``name#2``."""
    found: dict[str, str] = {}
    for sentence in sentences(text):
        m = _THEOREM.match(sentence)
        if m:
            name = m.group(2)
            while name in found:
                name += "#2"
            found[name] = " ".join(m.group(3).split())
    return found


def statement_problems(name: str, text: str, intended: Mapping[str, str],
                       trees: Mapping[str, str] | None = None) -> list[str]:
    """The round trip of a unit's statements: the theorems ``text`` states are exactly
    those of ``intended`` (name -> statement), each with its intended statement, and,
    with ``trees``, each statement read back (:func:`verify.coq.reparse.parse_statement`)
    is the intended term tree."""
    written = stated_theorems(text)
    for k, tree in (trees or {}).items():
        if k in written:
            # imported here: the term reader loads the proof layer, which a unit
            # without term trees (a gate's) does not need
            from verify.coq.reparse import ReparseError, parse_statement

            try:
                ok = parse_statement(written[k]) == tree
            except ReparseError as exc:
                return [f"{name}: theorem {k} does not read back ({exc})"]
            if not ok:
                return [f"{name}: theorem {k} reads back as another term than the one "
                        "exported"]
    problems = [f"{name}: theorem {k} is not one the exporter wrote"
                for k in written if k not in intended]
    for k, statement in intended.items():
        if k not in written:
            problems.append(f"{name}: theorem {k} is missing")
        elif written[k] != " ".join(statement.split()):
            problems.append(f"{name}: theorem {k} does not state what was exported")
    return problems
