"""Sphinx configuration of the documentation site (MyST Markdown pages).

Built by ``.ci/run`` with ``sphinx-build -W`` (every warning is an error); the examples of
every page run in ``tests/test_docs_examples.py``.
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the package from this checkout, installed or not
sys.path.insert(0, str(Path(__file__).resolve().parent / "_ext"))

from verify import __version__  # noqa: E402

project = "verify"
author = "The verify authors"
copyright = "the verify authors"  # no year: the built site is the same every year
version = release = __version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "verify_docs",
]
source_suffix = {".md": "markdown"}
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]
myst_heading_anchors = 3
exclude_patterns = ["_build", "_ext"]
root_doc = "index"

autodoc_member_order = "bysource"
autodoc_typehints = "description"
autodoc_default_options = {"members": True, "undoc-members": False}
napoleon_numpy_docstring = True
napoleon_google_docstring = False

html_theme = "alabaster"
html_title = f"verify {__version__}"
html_static_path: list[str] = []
html_last_updated_fmt = None  # no clock time in the pages
