"""Two small Sphinx extensions for this site.

``verify-cli``: the command-line reference, generated from the ``verify`` command's own
argparse parser (:func:`verify.cli._build_parser`): one section per command and nested
command, holding exactly what ``verify COMMAND --help`` prints (80 columns), examples
included. It imports the parser, so the reference cannot drift from the flags.

Docstrings as written: the package's docstrings write norms as ``|x|`` and globs as
``*.toml``, plain text that reStructuredText would read as substitutions and emphasis.
:func:`plain_bars` escapes a ``|`` outside a table row or literal block before autodoc
parses a docstring.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.util.docutils import SphinxDirective


def help_texts() -> list[tuple[str, str]]:
    """(command line, its --help text) for ``verify`` and every (nested) command."""
    from verify.cli import _build_parser, command_parsers

    saved = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = "80"  # argparse wraps to the terminal: fix it for the build
    try:
        parser = _build_parser()
        out = [("verify", parser.format_help())]
        out += [(" ".join(("verify", *path)), sub.format_help())
                for path, sub in command_parsers(parser)]
    finally:
        if saved is None:
            del os.environ["COLUMNS"]
        else:
            os.environ["COLUMNS"] = saved
    return out


class Docstring(SphinxDirective):
    """``verify-docstring MODULE``: a module's docstring as preformatted text (for the
    format references written as plain text, with TOML examples inside)."""

    required_arguments = 1
    has_content = False

    def run(self) -> list[nodes.Node]:
        import importlib
        import inspect

        text = inspect.getdoc(importlib.import_module(self.arguments[0])) or ""
        block = nodes.literal_block(text, text)
        block["language"] = "text"
        return [block]


class CliReference(SphinxDirective):
    """``verify-cli``: a section per command with its help text."""

    has_content = False

    def run(self) -> list[nodes.Node]:
        sections = []
        for command, text in help_texts():
            section = nodes.section(ids=[nodes.make_id(command)])
            section += nodes.title(text=command)
            block = nodes.literal_block(text, text)
            block["language"] = "text"
            section += block
            sections.append(section)
        return sections


def plain_bars(app, what, name, obj, options, lines: list[str]) -> None:
    """Escape ``|`` outside literal blocks (``|sum d_i|`` is a norm, not a substitution)
    and a ``*`` that starts no emphasis (``*.toml``, ``a * b``; a bullet stays)."""
    literal = False
    for i, line in enumerate(lines):
        if literal and line.strip() and not line.startswith((" ", "\t")):
            literal = False
        if not literal:  # the package's docstrings hold no grid tables
            line = line.replace("|", r"\|")
            line = re.sub(r"(?<=\S)(\s+)\*(?=\s)", r"\1\*", line)  # a * b, not a bullet
            line = re.sub(r"(?<=[/\s(])\*(?=\.)", r"\*", line)  # *.toml, *.json
            lines[i] = line
        if line.rstrip().endswith("::"):
            literal = True


_LINK = re.compile(r"\[([^\]\n]+)\]\(([^)\s#]+)(#[^)\s]*)?\)")


def repository_links(app, docname: str, source: list[str]) -> None:
    """A Markdown link from a page to a file of the repository outside ``docs/`` (a note's
    ``[TRUSTED.md](../../verify/passivity/TRUSTED.md)``) becomes the text and the file's
    repository path in code: the site does not hold that file, and a link to it would be a
    broken reference (an error under ``-W``). Links to missing files still warn."""
    srcdir = Path(app.srcdir).resolve()
    root = srcdir.parent
    page_dir = (srcdir / docname).parent

    def plain(match: re.Match) -> str:
        text, target = match.group(1), match.group(2)
        if "://" in target or target.startswith("mailto:"):
            return match.group(0)
        path = (page_dir / target).resolve()
        if path.is_relative_to(srcdir) or not path.is_relative_to(root) \
                or not path.exists():
            return match.group(0)
        return f"{text} (`{path.relative_to(root).as_posix()}`)"

    source[0] = _LINK.sub(plain, source[0])


def setup(app: Sphinx) -> dict[str, object]:
    app.connect("source-read", repository_links)
    app.add_directive("verify-cli", CliReference)
    app.add_directive("verify-docstring", Docstring)
    app.connect("autodoc-process-docstring", plain_bars)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
