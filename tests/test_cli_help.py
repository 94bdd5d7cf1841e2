"""Every flag and argument of every `verify` command says what it does."""

from __future__ import annotations

import argparse

from verify.cli import _build_parser, command_parsers


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


def test_every_command_help_ends_with_examples_that_parse():
    """Each ``verify COMMAND --help`` ends with two or three examples, and each example is
    a command line the parser accepts (so an example cannot name a flag that is gone)."""
    import shlex

    parser = _build_parser()
    commands = list(command_parsers(parser))
    assert len(commands) >= 11
    for path, sub in commands:
        text = sub.format_help()
        assert "\nexamples:\n" in text, path
        tail = text.split("\nexamples:\n", 1)[1]
        lines = [line.strip() for line in tail.splitlines() if line.startswith("  verify ")]
        assert 2 <= len(lines) <= 3, (path, lines)
        for line in lines:
            words = shlex.split(line.split(" | ")[0])  # a pipe's first command
            args = parser.parse_args(words[1:])
            assert args.command == path[0], line
        # the examples come last: nothing but their lines after the heading
        assert all(line.startswith("  ") for line in tail.splitlines() if line), path


def test_check_help_names_the_json_form():
    text = _build_parser()._subparsers._group_actions[0].choices["check"].format_help()
    assert "verify-derivations/1" in " ".join(text.split())
    assert "--emit" in text


def test_version_prints_the_prelude_digest(capsys):
    """``verify --version``: the version and the SHA-256 of the Coq prelude, which changes
    with any prelude file's text."""
    import hashlib

    import pytest

    from verify import __version__
    from verify.coq import development

    with pytest.raises(SystemExit) as stop:
        _build_parser().parse_args(["--version"])
    assert stop.value.code == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == f"verify {__version__}"
    digest = out[1].removeprefix("Coq prelude sha256 ")
    assert digest == development.prelude_digest() and len(digest) == 64
    sources = development.prelude_sources()
    assert set(sources) >= {"SO3", "QCert", "SOSCert", "BandCert"}
    expected = hashlib.sha256()
    for name, text in sources.items():
        expected.update(f"{name}.v\0{len(text.encode())}\0".encode() + text.encode())
    assert digest == expected.hexdigest()
