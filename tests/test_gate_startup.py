"""Start-up: ``verify gate`` on a small model imports only what its route needs.

A CI job that gates model files one process at a time pays every import each time, so
the command and its KYP route (Riccati proposal, exact check) must not import the SDP
solver (cvxpy, and scipy.stats through it), scipy.optimize, sympy, or the plotting and
distributed stacks. Checked in a fresh interpreter's ``sys.modules``; the timings live in
``benchmarks/bench_startup.py``.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MODELS = ROOT / "verify" / "data" / "models"
NOT_NEEDED = ("cvxpy", "scipy.stats", "scipy.optimize", "sympy", "matplotlib", "dask",
              "numba", "control")

PROBE = """
import json, sys
from verify.cli import main
code = main(sys.argv[1:])
print(json.dumps({"code": code, "loaded": sorted(m for m in NOT_NEEDED if m in sys.modules)}))
"""


def _loaded(*argv: str) -> dict:
    script = f"NOT_NEEDED = {NOT_NEEDED!r}\n{PROBE}"
    done = subprocess.run([sys.executable, "-c", script, *argv], capture_output=True,
                          text=True, cwd=ROOT, env={"PYTHONPATH": str(ROOT),
                                                    "OPENBLAS_NUM_THREADS": "1",
                                                    "PATH": "/usr/bin:/bin"})
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_import_of_the_command_loads_no_heavy_library():
    done = subprocess.run([sys.executable, "-c", "import sys, verify.cli; print(sorted("
                           f"m for m in {NOT_NEEDED!r} if m in sys.modules))"],
                          capture_output=True, text=True, cwd=ROOT,
                          env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"


def test_gate_on_small_passive_models_loads_no_solver_or_sympy(tmp_path):
    out = _loaded("gate", str(MODELS / "example_state_space.toml"),
                  str(MODELS / "reconstructed_ks3p0.toml"), "--certificates", str(tmp_path))
    assert out == {"code": 0, "loaded": []}


def test_gate_on_a_model_refuted_on_the_real_axis_loads_no_solver_or_sympy(tmp_path):
    model = tmp_path / "m.toml"
    model.write_text("[state_space]\nA = [[-1.0]]\nB = [[1.0]]\nC = [[-1.0]]\nD = [[0.0]]\n")
    out = _loaded("gate", str(model), "--certificates", str(tmp_path))
    assert out == {"code": 1, "loaded": []}
