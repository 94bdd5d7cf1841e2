"""The paper's derivations are committed as data, equal to what the Python front end
emits, and `verify check FILE.json` checks such data without running any Python of it."""

from __future__ import annotations

from importlib import resources

import pytest

from verify.cli import main
from verify.paper_proofs.data import FOLDER, GROUPS, PACKAGE, derivations, emitted
from verify.proof import check
from verify.proof.falsify import SearchSettings
from verify.proof.wire import encode


def _committed(group: str) -> str:
    return resources.files(PACKAGE).joinpath(FOLDER, f"{group}.json").read_text("ascii")


@pytest.mark.parametrize("group", sorted(GROUPS))
def test_committed_data_is_what_the_front_end_emits(group):
    assert _committed(group) == emitted(group), (
        f"{group}: regenerate with python -m verify.paper_proofs.data")


def test_every_data_file_belongs_to_a_group():
    files = {p.name for p in resources.files(PACKAGE).joinpath(FOLDER).iterdir()
             if p.name.endswith(".json")}
    assert files == {f"{g}.json" for g in GROUPS}


def test_decoded_paper_derivations_check_as_the_python_ones():
    cfg = SearchSettings(samples=16, hypothesis_examples=5, ipopt_starts=1, seed=5)
    from verify.paper_proofs import lemma1

    from_data = [check(d, cfg).verdict for d in derivations("lemma1.rbar_dot_form")]
    from_python = [check(d, cfg).verdict for d in lemma1.rbar_dot_form()]
    assert from_data == from_python == ["verified"] * len(from_python)


def test_verify_check_reads_committed_data(tmp_path, capsys):
    path = tmp_path / "rbar.json"
    path.write_text(_committed("lemma1.rbar_dot_form"))
    assert main(["check", str(path), "--quick", "--certificates", str(tmp_path / "c")]) == 0
    assert "verified in every step" in capsys.readouterr().out


def test_sos_twins_from_data_have_the_python_s_certificate_keys(monkeypatch):
    """The paper's SOS re-proofs are built from the decoded data; their claim keys (and
    so the committed certificates they bind) are those of the Python front end's."""
    import verify.paper_proofs.sos_proofs as sos_proofs
    from verify.proof.checker import step_problem
    from verify.proof.sos_step import step_program
    from verify.sos.certificate import claim_key

    def keys() -> list[str]:
        return [claim_key(step_program(step_problem(r.derivation, r.derivation.steps[0]),
                                       r.derivation.steps[0].because))
                for r in sos_proofs.sos_reproofs()]

    from_data = keys()
    monkeypatch.setattr(sos_proofs, "hand_derivations", sos_proofs.python_hand_derivations)
    assert from_data == keys() and len(from_data) >= 10


@pytest.mark.parametrize("name", ["damped_leader", "sos_inequalities"])
def test_the_examples_data_is_what_their_python_emits(name):
    """examples/NAME.json is committed beside examples/NAME.py, as a lab would commit
    its derivations for CI (`verify check NAME.py --emit NAME.json`)."""
    from pathlib import Path

    from verify.proof.isolate import data_text
    from verify.proof.rebuild import loads
    from verify.proof.user_file import load_derivations
    from verify.proof.wire import dumps

    examples = Path(__file__).resolve().parents[1] / "examples"
    python = load_derivations(examples / f"{name}.py")  # our own example: trusted here
    emitted_text = data_text(loads(dumps(encode(python))))
    assert (examples / f"{name}.json").read_text() == emitted_text
