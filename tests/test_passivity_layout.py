"""The passivity package's layout: trusted checks apart from searches, and its public API."""

from __future__ import annotations

import ast
import importlib
import os
import subprocess
import sys
from pathlib import Path

import pytest

import verify.passivity as passivity

PACKAGE = Path(passivity.__file__).parent


def _imported_modules(path: Path) -> set[str]:
    """Every module an ``import`` or ``from ... import`` in the file names (lazy ones too)."""
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module is not None:
            names.add(node.module)
            names.update(f"{node.module}.{alias.name}" for alias in node.names)
    return names


@pytest.mark.parametrize("path", sorted((PACKAGE / "check").glob("*.py")), ids=lambda p: p.name)
def test_trusted_checks_never_import_the_searches(path):
    """A verdict rests on check/ only if no check reaches into search/ for its answer."""
    bad = {m for m in _imported_modules(path)
           if m.startswith(("verify.passivity.search", "verify.passivity.decision",
                            "verify.passivity.band", "verify.passivity.fd_decision",
                            "verify.passivity.indices", "verify.passivity.gate"))
           or m.split(".")[0] in {"cvxpy", "clarabel"}}
    assert not bad, f"{path.name} imports {sorted(bad)}"


@pytest.mark.parametrize("sub", ["check", "search", "io"])
def test_each_part_says_whether_it_is_trusted(sub):
    doc = importlib.import_module(f"verify.passivity.{sub}").__doc__ or ""
    assert ("Trusted" in doc.split("\n")[0]) == (sub == "check")
    assert "trusted" in doc.lower()


def test_public_api_names_resolve_to_their_definitions():
    from verify.passivity import api, indices, model
    from verify.passivity.io import model_file

    # the public decide / decide_band accept any model form (verify.passivity.api)
    assert passivity.decide is api.decide
    assert passivity.decide_band is api.decide_band
    assert passivity.nu is api.nu and passivity.relative_index is api.relative_index
    assert passivity.IndexBounds is indices.IndexBounds
    assert passivity.load_model is model_file.load_model
    assert passivity.LTIModel is model.LTIModel
    assert (passivity.PASSIVE, passivity.NOT_PASSIVE, passivity.INCONCLUSIVE) == (
        "passive", "not passive", "inconclusive")
    for name in passivity.__all__:
        assert getattr(passivity, name) is not None
    with pytest.raises(AttributeError, match="no attribute 'decidee'"):
        passivity.decidee  # noqa: B018


def test_public_api_decides_a_model_end_to_end():
    m = passivity.from_state_space([[-1]], [[1]], [[1]], [[0]], name="first order")
    d = passivity.decide(m)
    assert isinstance(d, passivity.Decision)
    assert d.verdict == passivity.PASSIVE and d.certificate is not None
    d = passivity.decide(passivity.from_state_space([[-1]], [[1]], [[-1]], [[0]]))
    assert d.verdict == passivity.NOT_PASSIVE and d.witness is not None


def test_star_import_and_subpackage_imports_are_cycle_free():
    """Each part imports on its own in a fresh interpreter, in either order."""
    code = ("import verify.passivity.check.exact, verify.certificates.registry;"
            "from verify.passivity import *;"
            "import verify.passivity.search.kyp;"
            "assert callable(decide) and callable(load_model)")
    root = PACKAGE.parent.parent
    env = {**os.environ, "PYTHONPATH": str(root)}
    out = subprocess.run([sys.executable, "-c", code + "; import verify; print(verify.__file__)"],
                         cwd=root, env=env, capture_output=True, text=True, timeout=120,
                         check=True)
    assert out.stdout.strip() == str(root / "verify" / "__init__.py")
