"""`verify check FILE`: exit 0 all verified, 1 refuted/inconclusive, 2 malformed file."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from verify.cli import main

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "damped_leader.py"

HEADER = """
from fractions import Fraction
from verify.proof import Context, Derivation, by_algebra, by_citation, tr, sk
ctx = Context("user")
R, S = ctx.rotation("R"), ctx.rotation("S")
"""


def write(tmp_path: Path, body: str, name: str = "mine.py") -> Path:
    path = tmp_path / name
    path.write_text(HEADER + body)
    return path


def test_shipped_example_verifies(capsys, tmp_path):
    out = tmp_path / "r.json"
    assert main(["check", str(EXAMPLE), "--quick", "--json", str(out)]) == 0
    data = json.loads(out.read_text())
    assert data[0]["verdict"] == "verified"
    assert [s["verdict"] for s in data[0]["steps"]] == ["verified", "verified"]


def test_a_false_step_exits_1_with_an_exact_counterexample(tmp_path, capsys):
    path = write(
        tmp_path,
        "d = Derivation('wrong', tr(R * S), ctx).equals(tr(S * R.T), by_algebra())\n"
        "DERIVATIONS = [d]\n",
    )
    assert main(["check", str(path), "--quick"]) == 1
    out = capsys.readouterr().out
    assert "refuted" in out and "counterexample (exact)" in out


def test_an_undecidable_step_exits_1(tmp_path, capsys):
    path = write(tmp_path, "d = Derivation('cited', tr(R), ctx).le(3, by_citation('x'))\n")
    assert main(["check", str(path), "--quick"]) == 1
    assert "inconclusive" in capsys.readouterr().out


def test_a_true_identity_exits_0(tmp_path):
    path = write(
        tmp_path,
        "d = Derivation('cyclic', tr(R * S), ctx).equals(tr(S * R), by_algebra())\n",
    )
    assert main(["check", str(path), "--quick"]) == 0


@pytest.mark.parametrize(
    "body, message",
    [
        ("d = Derivation('x', tr(R), ctx\n", "syntax error"),
        ("d = Derivation('x', 0.5 * tr(R), ctx)\n", "Fraction"),
        ("x = 1\n", "defines no derivation"),
        ("DERIVATIONS = [1]\n", "list of Derivation"),
        ("d = Derivation('x', tr(R), ctx)\n", "has no steps"),
        ("raise RuntimeError('boom')\n", "boom"),
    ],
)
def test_malformed_files_give_one_line_and_exit_2(tmp_path, capsys, body, message):
    path = write(tmp_path, body)
    assert main(["check", str(path)]) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.strip().splitlines()) == 1


def test_missing_and_non_python_files_exit_2(tmp_path, capsys):
    assert main(["check", str(tmp_path / "absent.py")]) == 2
    other = tmp_path / "d.txt"
    other.write_text("x")
    assert main(["check", str(other)]) == 2


def test_the_documented_example_checks(tmp_path):
    """The example of docs/guide/derivations.md (once the README's) checks."""
    readme = (Path(__file__).resolve().parents[1] / "docs" / "guide" / "derivations.md"
              ).read_text()
    start = readme.index("```python\nfrom fractions") + len("```python\n")
    path = tmp_path / "readme_example.py"
    path.write_text(readme[start : readme.index("```", start)])
    assert main(["check", str(path), "--quick"]) == 0


def test_user_certificates_default_to_the_git_ignored_build_folder():
    """`verify check FILE` on an example must not add files among the paper's
    certificates: its SOS certificates go under build/ unless --certificates says."""
    from verify.cli import GATE_CERTIFICATES, _build_parser

    args = _build_parser().parse_args(["check", "examples/sos_inequalities.py"])
    assert args.certificates == GATE_CERTIFICATES and GATE_CERTIFICATES.parts[0] == "build"
    ignored = (Path(__file__).resolve().parents[1] / ".gitignore").read_text().split()
    assert "build/" in ignored


def test_a_fifo_or_folder_named_like_a_derivation_file_is_refused_for_what_it_is(
        tmp_path, capsys):
    """Opening a FIFO for the front end must not block, and it is not "missing"."""
    fifo = tmp_path / "pipe.py"
    os.mkfifo(fifo)
    folder = tmp_path / "folder.py"
    folder.mkdir()
    for path, kind in ((fifo, "is a FIFO"), (folder, "is a directory")):
        assert main(["check", str(path), "--unsandboxed"]) == 2
        err = capsys.readouterr().err
        assert kind in err and len(err.strip().splitlines()) == 1, err
