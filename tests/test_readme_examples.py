"""The README's examples and the public passivity API's docstring examples run.

The README keeps one example per use; the API by example moved to
``docs/guide/python.md`` (all of the documentation's examples run in
``tests/test_docs_examples.py``; the checks here are the fast core of them). An example
whose printed answer changes fails here, so the documentation cannot drift from the code.
"""

from __future__ import annotations

import doctest
import re
from pathlib import Path

import verify.passivity.api

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
PYTHON_GUIDE = ROOT / "docs" / "guide" / "python.md"
FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def test_readme_is_a_front_door():
    """At most about 250 lines, the two set-up commands, one example per use."""
    text = README.read_text(encoding="utf-8")
    assert len(text.splitlines()) <= 250
    assert "<!-- test-command -->" in text and ".venv/bin/verify all" in text
    assert "from verify.passivity import" in text and "verify gate" in text
    assert "from verify.strategies import" in text


def test_readme_doctests_pass():
    result = doctest.testfile(str(README), module_relative=False, optionflags=FLAGS,
                              encoding="utf-8", verbose=False)
    assert result.attempted >= 3
    assert result.failed == 0


def test_readme_python_blocks_run(tmp_path, monkeypatch):
    """The README's plain ```python block (a hypothesis test on the simulator) runs."""
    text = README.read_text(encoding="utf-8")
    blocks = [b for b in re.findall(r"```python\n(.*?)```", text, flags=re.S)
              if not b.lstrip().startswith(">>>")]
    assert blocks
    monkeypatch.chdir(tmp_path)
    for block in blocks:
        namespace: dict = {}
        # a pseudo file name: the block's line numbers are not the README's, so nothing
        # (hypothesis reads a test's source) may look them up in README.md
        exec(compile(block, "<README.md python block>", "exec"), namespace)  # our own README
        tests = [v for k, v in namespace.items() if k.startswith("test_") and callable(v)]
        assert tests
        for test in tests:
            test()


def test_python_guide_has_doctest_examples():
    """The API by example shows the passivity API as runnable examples."""
    text = PYTHON_GUIDE.read_text(encoding="utf-8")
    assert len(re.findall(r"^>>> ", text, flags=re.M)) >= 8
    assert "from verify.passivity import" in text


def test_python_guide_doctests_pass():
    result = doctest.testfile(str(PYTHON_GUIDE), module_relative=False, optionflags=FLAGS,
                              encoding="utf-8", verbose=False)
    assert result.attempted >= 8
    assert result.failed == 0


def test_api_docstring_examples_pass():
    result = doctest.testmod(verify.passivity.api, optionflags=FLAGS, verbose=False)
    assert result.attempted >= 8
    assert result.failed == 0
