"""Progress of the long commands: stage lines on stderr, only on a terminal or when asked.

stdout stays the result (safe to pipe); a stage line names the command, the seconds since
it started and the stage.
"""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest

from verify.cli import main
from verify.progress import Stages, progress_wanted

MODELS = Path(__file__).resolve().parents[1] / "verify" / "data" / "models"
LINE = re.compile(r"^verify \w+: \[ *\d+\.\d s\] \S")


class _Tty(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_stage_lines_only_on_a_terminal_or_when_forced():
    pipe, tty = io.StringIO(), _Tty()
    Stages.for_command("verify x", stream=pipe)("hidden")
    Stages.for_command("verify x", stream=tty)("shown")
    Stages.for_command("verify x", stream=pipe, forced=True)("forced")
    Stages.for_command("verify x", stream=tty, quiet=True)("quiet")
    assert pipe.getvalue().splitlines() == [pipe.getvalue().splitlines()[0]]
    assert "forced" in pipe.getvalue() and "hidden" not in pipe.getvalue()
    assert LINE.match(tty.getvalue()) and "shown" in tty.getvalue()
    assert "quiet" not in tty.getvalue()
    assert not progress_wanted(pipe) and progress_wanted(tty)


def test_gate_progress_goes_to_stderr_and_only_when_asked(tmp_path, capsys):
    model = str(MODELS / "reconstructed_ks2p5.toml")
    main(["gate", model, "--certificates", str(tmp_path)])
    quiet = capsys.readouterr()
    assert quiet.err == ""
    main(["gate", model, "--certificates", str(tmp_path), "--progress"])
    shown = capsys.readouterr()
    lines = shown.err.splitlines()
    assert lines and all(LINE.match(x) for x in lines)
    assert "deciding model 1 of 1: reconstructed k_s = 2.5 (4 states, 2 port(s))" in lines[0]
    seconds = re.compile(r"\d+\.\d+ s\)")
    assert seconds.sub("", shown.out) == seconds.sub("", quiet.out)  # the result is unchanged


@pytest.mark.slow
def test_identify_progress_names_each_stage(tmp_path, capsys):
    """``verify identify`` was silent for 25-33 s; with --progress every stage is named."""
    from identify_models import open_loop_log

    from verify.identify.data.example_logs import EXAMPLES
    from verify.inputs.experiment_log import write_log

    ex = EXAMPLES[0]
    log = write_log(open_loop_log(ex.model(), trials=4, seed=ex.seed), tmp_path / "l.npz")
    main(["identify", str(log), "--split", "2:2", "--out", str(tmp_path / "out"),
          "--progress"])
    err = capsys.readouterr().err.splitlines()
    stages = [x.split("] ", 1)[1] for x in err if LINE.match(x)]
    assert stages[0].startswith("reading 1 log(s)")
    assert any(s.startswith("estimating the model") for s in stages)
    assert stages[-1].startswith("writing the files") or any(
        "cannot" in s for s in stages)
    # the passive fit, once one silent stage of about 28 s, names its four fits
    fits = [s.split("(fit ")[1] for s in stages if s.startswith("passivity test:")]
    assert fits in ([], ["1 of 4)", "2 of 4)", "3 of 4)", "4 of 4)"])
