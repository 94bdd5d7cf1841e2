"""A user can install the package: wheel and sdist from a clean clone, in fresh venvs.

``python -m build`` on a clean clone of this repository makes a wheel and an sdist; each
installs (``--no-deps``) into a fresh virtual environment whose third-party packages come
from this interpreter's site-packages (so the test needs no network), and there
``verify --version`` and the main job on Section 2, ``verify all --only sec2``, run from
an empty folder, importing the installed copy, not this checkout. The wheel must carry the
package data: the Coq prelude, the shipped logs, models, networks, campaigns and the
paper's derivations. Slow (two builds and two installs). CITATION.cff is checked here too.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

#: Package data a working install needs (a path inside the wheel, by glob).
PACKAGE_DATA = ("verify/coq/prelude/SO3.v", "verify/coq/prelude/BandCert.v",
                "verify/data/logs/passive_human.npz", "verify/data/logs/passive_human.toml",
                "verify/data/models/reconstructed_ks3p0.toml",
                "verify/data/networks/formation_n8.toml", "verify/data/campaigns/small.toml",
                "verify/data/derivations/theorem1.v_dot.json")


def test_citation_file_names_this_version():
    yaml = pytest.importorskip("yaml")
    from verify import __version__

    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    assert cff["cff-version"] == "1.2.0" and cff["type"] == "software"
    assert str(cff["version"]) == __version__
    assert cff["title"] and cff["authors"] and cff["license"] == "MIT"


def _run(args: list, cwd: Path, env: dict | None = None, timeout: int = 1200):
    done = subprocess.run([str(a) for a in args], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=timeout, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, f"{args}:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    return done


def _fresh_venv(where: Path) -> Path:
    """A new venv whose own site-packages holds only what is installed into it, plus a
    path file listing this interpreter's site-packages (the dependencies; path files
    listed there, such as an editable install of this checkout, are not processed)."""
    _run([sys.executable, "-m", "venv", where], cwd=where.parent)
    site = next((where / "lib").glob("python3*/site-packages"))
    deps = [p for p in sys.path if p.endswith("site-packages") and Path(p).is_dir()]
    (site / "zz_dependencies.pth").write_text("\n".join(deps) + "\n", encoding="utf-8")
    return where / "bin"


@pytest.mark.slow
def test_wheel_and_sdist_install_and_run_the_main_job(tmp_path):
    pytest.importorskip("build")
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    clone = tmp_path / "clone"
    _run(["git", "clone", "-q", "--no-hardlinks", ROOT, clone], cwd=tmp_path)
    dist = tmp_path / "dist"
    # no isolation: the build backend of this environment, so no download is needed
    _run([sys.executable, "-m", "build", "--no-isolation", "--skip-dependency-check",
          "--outdir", dist, clone], cwd=tmp_path)
    (wheel,) = dist.glob("*.whl")
    (sdist,) = dist.glob("*.tar.gz")
    names = set(zipfile.ZipFile(wheel).namelist())
    missing = [p for p in PACKAGE_DATA if p not in names]
    assert not missing, missing
    assert not any(n.startswith(("tests/", "docs/", "reports/")) for n in names)

    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    for name, artefact, extra in (("wheel", wheel, []), ("sdist", sdist,
                                                        ["--no-build-isolation"])):
        bin_dir = _fresh_venv(tmp_path / f"venv-{name}")
        _run([bin_dir / "python", "-m", "pip", "install", "-q", "--no-deps", "--no-index",
              *extra, artefact], cwd=tmp_path, env=env)
        work = tmp_path / f"work-{name}"
        work.mkdir()
        where = _run([bin_dir / "python", "-c", "import verify; print(verify.__file__)"],
                     cwd=work, env=env).stdout.strip()
        assert Path(where).is_relative_to(tmp_path / f"venv-{name}"), where
        version = _run([bin_dir / "verify", "--version"], cwd=work, env=env).stdout
        assert version.startswith("verify ") and "Coq prelude sha256 " in version
        done = _run([bin_dir / "verify", "all", "--only", "sec2", "--no-latex", "--jobs",
                     "1", "--quick"], cwd=work, env=env)
        assert "refuted" in done.stdout  # W^T W is singular: the main finding
        assert (work / "build" / "only" / "reports" / "report.html").is_file()
