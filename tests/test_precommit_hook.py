"""The pre-commit hook of ``.pre-commit-hooks.yaml`` gates model files in a lab's repository.

A scratch git repository with a ``.pre-commit-config.yaml`` of three lines that names this
repository by its local path (offline: pre-commit clones it, and the ``verify-gate-system``
hook runs the ``verify`` of this environment, so nothing is downloaded) rejects a commit
that adds a non-passive model and accepts one that adds a passive model. The
``verify-gate`` hook (pre-commit builds its own environment with the package, which needs
the package index) is checked to be the same gate. Skipped when pre-commit or git is
missing.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
MODELS = ROOT / "verify" / "data" / "models"

pytest.importorskip("pre_commit")
yaml = pytest.importorskip("yaml")
pytestmark = pytest.mark.skipif(shutil.which("git") is None, reason="git is not installed")


def _git(cwd: Path, *args: str, env: dict[str, str]) -> subprocess.CompletedProcess:
    return subprocess.run(["git", *args], cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=120)


def _env(tmp_path: Path) -> dict[str, str]:
    env = dict(os.environ)
    env.update(PRE_COMMIT_HOME=str(tmp_path / "pre-commit-home"),
               GIT_AUTHOR_NAME="lab", GIT_AUTHOR_EMAIL="lab@example.org",
               GIT_COMMITTER_NAME="lab", GIT_COMMITTER_EMAIL="lab@example.org",
               GIT_CONFIG_GLOBAL=os.devnull, GIT_CONFIG_NOSYSTEM="1")
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env.get('PATH', '')}"
    return env


def _hook_source(tmp_path: Path, env: dict[str, str]) -> tuple[Path, str]:
    """A local repository holding this checkout's hook manifest, and its commit: this
    repository's HEAD when the manifest is committed unchanged, else a one-file copy."""
    head = _git(ROOT, "rev-parse", "HEAD", env=env)
    committed = _git(ROOT, "show", "HEAD:.pre-commit-hooks.yaml", env=env)
    manifest = (ROOT / ".pre-commit-hooks.yaml").read_text(encoding="utf-8")
    if head.returncode == 0 and committed.returncode == 0 and committed.stdout == manifest:
        return ROOT, head.stdout.strip()
    source = tmp_path / "hooks"
    source.mkdir()
    (source / ".pre-commit-hooks.yaml").write_text(manifest, encoding="utf-8")
    _git(source, "init", "-q", env=env)
    _git(source, "add", ".", env=env)
    _git(source, "commit", "-qm", "hooks", env=env)
    return source, _git(source, "rev-parse", "HEAD", env=env).stdout.strip()


def test_manifest_hooks_gate_the_same_files():
    hooks = {h["id"]: h for h in yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())}
    assert set(hooks) == {"verify-gate", "verify-gate-system"}
    python, system = hooks["verify-gate"], hooks["verify-gate-system"]
    assert python["language"] == "python" and system["language"] == "system"
    for key in ("entry", "files", "require_serial"):
        assert python[key] == system[key], key
    assert python["entry"].startswith("verify gate ")


def test_scratch_repository_rejects_a_non_passive_model_and_accepts_a_passive_one(tmp_path):
    env = _env(tmp_path)
    source, rev = _hook_source(tmp_path, env)
    lab = tmp_path / "lab"
    (lab / "models").mkdir(parents=True)
    assert _git(lab, "init", "-q", env=env).returncode == 0
    (lab / ".pre-commit-config.yaml").write_text(
        f"repos:\n  - repo: {source}\n    rev: {rev}\n"
        "    hooks: [{id: verify-gate-system}]\n", encoding="utf-8")
    (lab / ".gitignore").write_text("build/\n", encoding="utf-8")
    _git(lab, "add", ".", env=env)
    assert _git(lab, "commit", "-qm", "config", "--no-verify", env=env).returncode == 0
    install = subprocess.run([sys.executable, "-m", "pre_commit", "install"], cwd=lab,
                             env=env, capture_output=True, text=True, timeout=300)
    assert install.returncode == 0, install.stdout + install.stderr

    shutil.copy(MODELS / "reconstructed_ks2p5.toml", lab / "models" / "lagging.toml")
    _git(lab, "add", "models/lagging.toml", env=env)
    refused = _git(lab, "commit", "-m", "add a lagging operator", env=env)
    assert refused.returncode != 0, refused.stdout + refused.stderr
    assert "FAIL" in refused.stdout + refused.stderr
    assert "not passive" in refused.stdout + refused.stderr
    assert _git(lab, "log", "--oneline", env=env).stdout.count("\n") == 1  # not committed

    _git(lab, "rm", "-q", "--cached", "models/lagging.toml", env=env)
    (lab / "models" / "lagging.toml").unlink()
    shutil.copy(MODELS / "reconstructed_ks3p0.toml", lab / "models" / "operator.toml")
    _git(lab, "add", "models/operator.toml", env=env)
    accepted = _git(lab, "commit", "-m", "add a passive operator", env=env)
    assert accepted.returncode == 0, accepted.stdout + accepted.stderr
    assert "Passed" in accepted.stdout + accepted.stderr
    assert _git(lab, "log", "--oneline", env=env).stdout.count("\n") == 2
