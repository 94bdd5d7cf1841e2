"""The README's Python examples and the public passivity API's docstring examples run.

The README's ``>>>`` snippets (section "Using it from Python") and the examples in
:mod:`verify.passivity.api` are doctests: an example whose printed answer changes fails
here, so the documentation cannot drift from the code.
"""

from __future__ import annotations

import doctest
import re
from pathlib import Path

import verify.passivity.api

README = Path(__file__).resolve().parents[1] / "README.md"
FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def test_readme_has_doctest_examples():
    """The README shows the API as runnable examples (a guard on the test below)."""
    text = README.read_text(encoding="utf-8")
    assert len(re.findall(r"^>>> ", text, flags=re.M)) >= 8
    assert "from verify.passivity import" in text


def test_readme_doctests_pass():
    result = doctest.testfile(str(README), module_relative=False, optionflags=FLAGS,
                              encoding="utf-8", verbose=False)
    assert result.attempted >= 8
    assert result.failed == 0


def test_api_docstring_examples_pass():
    result = doctest.testmod(verify.passivity.api, optionflags=FLAGS, verbose=False)
    assert result.attempted >= 8
    assert result.failed == 0


def test_readme_python_blocks_run(tmp_path, monkeypatch):
    """The plain ```python blocks of "Using it from Python" run as written."""
    text = README.read_text(encoding="utf-8")
    section = text.split("## Using it from Python", 1)[1].split("\n## ", 1)[0]
    blocks = [b for b in re.findall(r"```python\n(.*?)```", section, flags=re.S)
              if not b.lstrip().startswith(">>>")]
    assert blocks
    monkeypatch.chdir(tmp_path)
    for block in blocks:
        namespace: dict = {}
        exec(compile(block, str(README), "exec"), namespace)  # the project's own README
        for name, value in namespace.items():
            if name.startswith("test_") and callable(value):
                value()  # a hypothesis test defined in the README runs too
