"""Several units written into one ``.v`` file, each as a module of its own name.

Every ``coqc`` run loads the real numbers' library afresh (about a second of CPU before
the first step is checked); a development of fifty one-derivation files spends a quarter
of its compile time loading. A bundle is one file: a header that ``Require``s every
library its units use, once, then each unit's text as ``Module <unit>. … End <unit>.``,
with its ``Require Import`` lines turned into ``Import``s of the libraries already loaded.
A theorem keeps its name ``<unit>.<theorem>`` (``All.v`` imports the bundle), and every
module's text is audited as the unit's own file would be (:func:`module_texts`).

In: :class:`~verify.coq.unit.CoqUnit` s sharing :attr:`~verify.coq.unit.CoqUnit.bundle`.
Out: the bundle's source, and back from a source each module's text for the audit.
"""

from __future__ import annotations

import re
import textwrap
from collections.abc import Sequence

from verify.coq.audit import strip_comments
from verify.coq.unit import CoqUnit, comment_text

#: A unit's own ``Require`` line as the exporters write it (``From <root> Require
#: [Import] <names>.``, alone on its line).
_REQUIRE_LINE = re.compile(
    r"^From ([A-Za-z][A-Za-z0-9_]*) Require( Import)? ([A-Za-z][A-Za-z0-9_ ]*)\.$")
_MODULE_LINE = re.compile(r"^Module ([A-Za-z][A-Za-z0-9_]*)\.$", re.M)


def _split_requires(unit: CoqUnit, siblings: set[str]) -> tuple[list[tuple[str, str]], str]:
    """(root, library) pairs the unit loads, and its text with its ``Require`` lines
    replaced by one ``Import`` (where the first of them was) of the libraries it
    imports. A sibling module (a unit of the same bundle, defined earlier in the file)
    is not loaded: an ``Import`` of it names the module itself. Only lines of code count:
    a comment's line that reads like a ``Require`` stays in the comment."""
    code = set(strip_comments(unit.text).splitlines())
    loads: list[tuple[str, str]] = []
    imports: list[str] = []
    kept: list[str] = []
    at = -1
    for line in unit.text.splitlines():
        match = _REQUIRE_LINE.match(line) if line in code else None
        if match is None:
            kept.append(line)
            continue
        at = len(kept) if at < 0 else at
        root, do_import, names = match.group(1), match.group(2), match.group(3).split()
        for name in names:
            if name not in siblings:
                loads.append((root, name))
            if do_import:
                imports.append(name)
    if imports:
        kept.insert(at, f"Import {' '.join(imports)}.")
    return loads, "\n".join(kept).strip("\n")


def bundle_text(name: str, units: Sequence[CoqUnit]) -> str:
    """The source of the bundle ``name`` holding ``units`` in order (a unit may use the
    units before it, by their module names)."""
    seen: set[str] = set()
    loads: list[tuple[str, str]] = []
    modules: list[str] = []
    for unit in units:
        unit_loads, body = _split_requires(unit, seen)
        loads += [pair for pair in unit_loads if pair not in loads]
        modules.append(f"Module {unit.name}.\n\n{body}\n\nEnd {unit.name}.\n")
        seen.add(unit.name)
    roots: dict[str, list[str]] = {}
    for root, library in loads:
        roots.setdefault(root, []).append(library)
    header = "".join(f"From {root} Require {' '.join(libs)}.\n" for root, libs in roots.items())
    names = ", ".join(unit.name for unit in units)
    intro = textwrap.fill(comment_text(
        f"{len(units)} units in one file, each a module of its own name: {names}. "
        "The libraries are loaded once, below; each module imports those its unit uses."),
        width=88, initial_indent="(** ", subsequent_indent="    ", break_long_words=False,
        break_on_hyphens=False)
    return f"{intro} *)\n\n{header}\n" + "\n".join(modules)


def module_texts(text: str) -> tuple[str, dict[str, str]]:
    """A bundle's header (the text before its first module) and each module's text (from
    its ``Module`` line to the next one), by module name; a name written twice keeps
    its first text and is listed again as ``name#2``."""
    found = list(_MODULE_LINE.finditer(text))
    header = text[: found[0].start()] if found else text
    modules: dict[str, str] = {}
    for k, match in enumerate(found):
        end = found[k + 1].start() if k + 1 < len(found) else len(text)
        key = match.group(1)
        while key in modules:
            key += "#2"
        modules[key] = text[match.start():end]
    return header, modules
