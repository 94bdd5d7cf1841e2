"""A derivation file's SOS steps as Coq units (``verify check FILE --coq DIR``,
:mod:`verify.coq.user_sos`): the same ``SOSCert.v`` route as the paper's re-proofs."""

from __future__ import annotations

import re
from pathlib import Path

from coq_tools import run_coqc

from verify.cli import main

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "sos_inequalities.json"


def test_every_sos_step_of_the_example_is_exported_and_accepted(tmp_path, capsys,
                                                                prelude_dir):
    out = tmp_path / "coq"
    rc = main(["check", str(EXAMPLE), "--coq", str(out),
               "--certificates", str(tmp_path / "certs")])
    text = capsys.readouterr().out
    assert rc == 0, text  # every verified step in Coq and accepted by coqc
    assert "(8 of 8 verified steps as theorems)" in text
    assert "coqc accepted every file" in text
    assert "not exported" not in text and "missing" not in text
    units = sorted(out.glob("UserSos_*.v"))
    assert [u.stem for u in units] == [f"UserSos_{k}" for k in range(1, 9)]
    for unit in units:  # each beside the compiled prelude
        (prelude_dir / unit.name).write_text(unit.read_text())
        run_coqc(prelude_dir, unit.name, check=True)
    # a changed certificate number: the identity no longer holds and coqc refuses it
    first = units[0].read_text()
    changed = re.sub(r"(Definition S1 : list \(Q \* list poly\) :=\n  \[\()(\d+)%Q",
                     lambda m: f"{m.group(1)}{int(m.group(2)) + 1}%Q", first, count=1)
    assert changed != first
    (prelude_dir / "UserSos_changed.v").write_text(changed)
    assert run_coqc(prelude_dir, "UserSos_changed.v").returncode != 0


def test_a_missing_certificate_folder_is_named_not_exported(tmp_path, capsys):
    from verify.coq.user_sos import user_sos_units
    from verify.proof.isolate import read_data_file

    units, fates = user_sos_units(read_data_file(EXAMPLE), tmp_path / "empty")
    assert units == []
    assert len(fates) == 8
    assert all(f.startswith("refused: its certificate is not in") for f in fates.values())
