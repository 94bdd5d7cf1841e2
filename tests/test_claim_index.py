"""``verify list`` reads a written-out index of the claims; it must match the registry."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from verify.claims.catalog import REGISTRY
from verify.claims.index import CLAIMS, render

ROOT = Path(__file__).resolve().parents[1]


def test_index_matches_the_registry():
    assert list(CLAIMS) == [(c.id, c.paper_ref) for c in REGISTRY], (
        "the claim index is stale: run python -m verify.claims.index")
    assert render() == (ROOT / "verify" / "claims" / "index.py").read_text(encoding="utf-8")


def test_list_prints_every_claim_without_importing_the_checks():
    code = ("import sys; from verify.cli import main; main(['list']); "
            "heavy = [m for m in ('sympy', 'cvxpy', 'numba', 'scipy', 'verify.claims.catalog',"
            " 'verify.claims.section2') if m in sys.modules]; "
            "print('HEAVY', heavy)")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True,
                         text=True, timeout=120, check=True).stdout.splitlines()
    assert out[-1] == "HEAVY []"
    assert [line.split()[0] for line in out[:-1]] == [c.id for c in REGISTRY]
