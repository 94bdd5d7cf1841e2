"""Every flag and argument of every `verify` command says what it does."""

from __future__ import annotations

import argparse

from verify.cli import _build_parser


def _actions(parser: argparse.ArgumentParser, path: tuple[str, ...] = ()):
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from _actions(sub, (*path, name))
        elif not isinstance(action, argparse._HelpAction):
            yield path, action


def test_every_argument_has_help_text():
    missing = [(" ".join(path), action.option_strings or action.dest)
               for path, action in _actions(_build_parser()) if not action.help]
    assert not missing, missing


def test_all_documents_its_outputs():
    (all_parser,) = [a for a in _build_parser()._actions
                     if isinstance(a, argparse._SubParsersAction)]
    text = all_parser.choices["all"].format_help()
    for flag in ("--latex", "--certificates", "--out", "--only", "--jobs", "--seed",
                 "--run-record"):
        assert flag in text
    assert "appendix.tex" in text and "default: 20261121" in text
    assert "build/run.json" in text and "build/only/reports" in text
