"""Every example of the documentation site runs (``docs/``; the notes excepted).

The conventions (also in ``docs/notes/docs-site.md``): per page, in order,

* a fenced block whose first line is ``# file: PATH`` is written to PATH in the page's
  scratch folder (a file the reader is asked to create);
* ``python`` blocks run in one namespace per page: a block of ``>>>`` lines as a doctest,
  any other block executed, and every ``test_*`` function it defines called;
* ``console`` blocks run each ``$ `` line with bash in the scratch folder; the lines shown
  after it must appear in its output (stdout and stderr) in that order, ``...`` matching
  any text, and a non-zero exit appears as a line ``[exit N]``;
* ``<!-- docs-test: slow -->`` just before a block runs it only with VERIFY_SLOW=1, and
  ``needs coqc`` skips it where coqc is not installed; other languages are not run.

The scratch folder holds links to this checkout's ``verify/`` and ``examples/`` (the
shipped data at the paths the pages name), and ``verify`` on PATH is this interpreter's.
"""

from __future__ import annotations

import doctest
import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
PAGES = sorted(p for p in DOCS.rglob("*.md")
               if "notes" not in p.relative_to(DOCS).parts and "_build" not in p.parts)
FENCE = re.compile(r"^(?:<!-- docs-test: (?P<marks>[^>]*?) -->\n)?```(?P<lang>[\w{}-]*)[^\n]*\n"
                   r"(?P<body>.*?)^```\s*$", re.S | re.M)
FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
SLOW = os.environ.get("VERIFY_SLOW") == "1"
#: a console command's bound (a page's slow blocks are bounded too)
COMMAND_SECONDS = 900


@dataclass
class Block:
    lang: str
    body: str
    marks: str
    line: int


def blocks(page: Path) -> list[Block]:
    text = page.read_text(encoding="utf-8")
    return [Block(m["lang"], m["body"], m["marks"] or "", text.count("\n", 0, m.start()) + 1)
            for m in FENCE.finditer(text)]


def _matches(expected: str, actual: str) -> bool:
    pattern = ".*".join(re.escape(part) for part in expected.strip().split("..."))
    return re.fullmatch(pattern, actual.strip()) is not None


def _shown_in_order(expected: list[str], actual: list[str]) -> str | None:
    """None when every expected line matches an actual line, in order; else the first
    expected line not found."""
    k = 0
    for line in expected:
        while k < len(actual) and not _matches(line, actual[k]):
            k += 1
        if k == len(actual):
            return line
        k += 1
    return None


def _console(body: str) -> list[tuple[str, list[str]]]:
    """(command, the lines shown after it) for each ``$ `` line."""
    out: list[tuple[str, list[str]]] = []
    for line in body.splitlines():
        if line.startswith("$ "):
            out.append((line[2:], []))
        elif out and line.strip():
            out[-1][1].append(line)
    return out


def _scratch(tmp_path: Path) -> dict[str, str]:
    for name in ("verify", "examples"):
        (tmp_path / name).symlink_to(ROOT / name, target_is_directory=True)
    env = dict(os.environ)
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env.get('PATH', '')}"
    env.pop("VERIFY_DEBUG", None)
    return env


def run_console(body: str, cwd: Path, env: dict[str, str], where: str) -> None:
    for command, shown in _console(body):
        done = subprocess.run(["bash", "-c", command], cwd=cwd, env=env, capture_output=True,
                              text=True, timeout=COMMAND_SECONDS, stdin=subprocess.DEVNULL)
        actual = (done.stdout + done.stderr).splitlines()
        if done.returncode:
            actual.append(f"[exit {done.returncode}]")
        missing = _shown_in_order(shown, actual)
        assert missing is None, (f"{where}: `{command}`: the page shows {missing!r}, the "
                                 "command printed:\n" + "\n".join(actual[-40:]))
        if not any(line.startswith("[exit ") for line in shown):
            assert done.returncode == 0, f"{where}: `{command}` exited {done.returncode}"


def run_python(block: Block, namespace: dict, where: str) -> None:
    if block.body.lstrip().startswith(">>>"):
        parser = doctest.DocTestParser()
        test = parser.get_doctest(block.body, namespace, where, where, block.line)
        runner = doctest.DocTestRunner(optionflags=FLAGS)
        runner.run(test, clear_globs=False)
        assert runner.failures == 0, f"{where}: a doctest failed (printed above)"
        return
    exec(compile(block.body, where, "exec"), namespace)  # the project's own pages
    for name, value in list(namespace.items()):
        if name.startswith("test_") and callable(value) and not getattr(value, "_ran", 0):
            value()
            try:
                value._ran = 1
            except AttributeError:
                pass


@pytest.mark.parametrize("page", PAGES, ids=[str(p.relative_to(DOCS)) for p in PAGES])
def test_page_examples_run(page: Path, tmp_path, monkeypatch):
    env = _scratch(tmp_path)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("PATH", env["PATH"])  # `verify` of this interpreter for Python too
    namespace: dict = {"__name__": f"docs.{page.stem}"}
    ran = skipped = 0
    for block in blocks(page):
        where = f"{page.relative_to(ROOT)}:{block.line}"
        first = block.body.splitlines()[0] if block.body else ""
        if first.startswith("# file: "):
            target = tmp_path / first.removeprefix("# file: ").strip()
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(block.body.split("\n", 1)[1], encoding="utf-8")
            continue
        if block.lang not in ("python", "console"):
            continue
        if ("slow" in block.marks and not SLOW) or (
                "needs coqc" in block.marks and shutil.which("coqc") is None):
            skipped += 1
            continue
        if block.lang == "console":
            run_console(block.body, tmp_path, env, where)
        else:
            run_python(block, namespace, where)
        ran += 1
    if ran == 0 and skipped:
        pytest.skip(f"{skipped} slow example(s); set VERIFY_SLOW=1")


def test_conventions_are_read():
    """A guard on the runner: the pages hold examples of each kind it runs, and every
    tutorial has at least one."""
    kinds = {(b.lang, b.body.lstrip().startswith(">>>")) for p in PAGES for b in blocks(p)}
    assert {("console", False), ("python", True), ("python", False)} <= kinds
    for page in (DOCS / "tutorials").glob("*.md"):
        assert any(b.lang in ("python", "console") for b in blocks(page)), page
    assert _shown_in_order(["PASS a ...", "1 of ..."], ["x", "PASS a (b)", "1 of 1"]) is None
    assert _shown_in_order(["FAIL"], ["PASS"]) == "FAIL"
