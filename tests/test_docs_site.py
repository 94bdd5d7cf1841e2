"""The documentation site keeps everything the README held, and builds.

:data:`FORMER_HEADINGS` are the headings of the README before it became a short front
door (frozen here as data, from the README of the main branch when the site was made):
each must still be a heading of some page under ``docs/``, so nothing the README dropped
is lost. The build itself (``sphinx-build -W``) runs in ``.ci/run``; a test here builds
it too when Sphinx is installed.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"

#: The README's headings (levels 1 to 4, outside code blocks) before the move.
FORMER_HEADINGS = [
    '# verify — machine checks for a passivity-based SO(3) control paper',
    '## Set-up (a fresh machine with Python 3.11)',
    '## What the report says (Section 2)',
    '## What the report says (Section 3: Lemma 1 and Theorem 1)',
    '### Lemma 1 and Theorem 1 in Coq',
    '## What the report says (Section 4: human passivity)',
    '## Commands',
    '## Gating a human model on passivity',
    '### Checking stored certificates',
    '### Reproducible artefacts',
    '## Kernel check (Coq)',
    '## Simulating the closed loop',
    '## From experiment logs to a CI gate: `verify identify`',
    '## Campaigns: where do the guarantees hold? `verify campaign`',
    '## Checking a derivation of your own',
    '## Using it from Python',
    '## Input layer',
    '## Outputs, errors and signals',
    '## Tests and profiles',
    '## Benchmarks',
    '## Layout',
]


def _headings(text: str) -> set[str]:
    out, fenced = set(), False
    for line in text.splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and re.match(r"^#{1,6} ", line):
            out.add(line.lstrip("#").strip())
    return out


def test_every_former_readme_heading_is_a_docs_heading():
    found: set[str] = set()
    for page in DOCS.rglob("*.md"):
        found |= _headings(page.read_text(encoding="utf-8"))
    former = [h.lstrip("#").strip() for h in FORMER_HEADINGS]
    assert len(former) >= 20
    # the title became the site's front page; every section kept its heading
    missing = [h for h in former[1:] if h not in found]
    assert not missing, missing


def test_notes_are_globbed_into_the_site():
    """A developer's note appears with no edit: the notes index is a glob toctree, and
    the site's front page links the notes index."""
    index = (DOCS / "notes" / "index.md").read_text(encoding="utf-8")
    assert re.search(r"```{toctree}\n(:[^\n]*\n)*:glob:", index)
    assert "notes/index" in (DOCS / "index.md").read_text(encoding="utf-8")


def test_every_page_is_in_a_toctree():
    """Sphinx warns (an error under -W) about a page in no toctree; this says which."""
    text = "\n".join(p.read_text(encoding="utf-8") for p in DOCS.rglob("*.md"))
    for page in DOCS.rglob("*.md"):
        rel = page.relative_to(DOCS).with_suffix("").as_posix()
        if rel in ("index",) or (rel.startswith("notes/") and rel != "notes/index"):
            continue
        assert rel in text or rel.split("/")[-1] in text, rel


@pytest.mark.slow
def test_the_site_builds_with_warnings_as_errors(tmp_path):
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_parser")
    done = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q",
                           "-b", "html", str(DOCS), str(tmp_path / "html")],
                          capture_output=True, text=True, timeout=1800)
    assert done.returncode == 0, done.stderr[-4000:]
    assert (tmp_path / "html" / "reference" / "cli.html").is_file()
    cli = (tmp_path / "html" / "reference" / "cli.html").read_text(encoding="utf-8")
    assert "verify gate" in cli and "examples:" in cli
