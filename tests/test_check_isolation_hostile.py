"""Attacks on `verify check FILE` once the file runs in its own process, grouped by class.

1. the file changes objects after building them, or the verifier itself;
2. the file ends its process (exits, threads, atexit, crashes) or overruns its budget;
3. the data handed over is forged;
4. rotations are rotations (no witness at the quaternion q = 0);
5. bounded work: printing, degrees, constants, conditions.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from verify.cli import main
from verify.proof import Context, Derivation, by_algebra, check, tr
from verify.proof.checker import step_problem
from verify.proof.confirm import exact_witness
from verify.proof.expr import ProofSyntaxError
from verify.proof.falsify import SearchSettings
from verify.proof.printing import to_text
from verify.proof.rebuild import decode
from verify.proof.wire import encode

HEADER = """
from fractions import Fraction
from verify.proof import (Context, Derivation, by_algebra, by_bound, by_sos, assumed,
                          square, tr, hat, sk)
ctx = Context("user")
R = ctx.rotation("R")
x = ctx.scalar("x")
"""
# a false claim: x^2 >= 1 is not a square plus nothing
FALSE = "d = Derivation('false', x * x, ctx).ge(1, by_bound(square(x)))\nDERIVATIONS = [d]\n"


def run(tmp_path: Path, body: str, *extra: str, capsys=None) -> int:
    path = tmp_path / "attack.py"
    path.write_text(HEADER + body)
    return main(["check", str(path), "--quick", "--certificates", str(tmp_path / "c"),
                 *extra])


# -- 1. mutation, subclassing and monkeypatching cannot reach the checker ---------------------
@pytest.mark.parametrize("body", [
    # the assumption's expression swapped after assumed() issued the term
    "a = ctx.assume('x >= 1', x - 1, 'nonneg')\nt = assumed(a)\n"
    "d = Derivation('d', x, ctx).ge(1, by_bound(t))\n"
    "object.__setattr__(a, 'expr', x * x)\nDERIVATIONS = [d]\n",
    # a term's value swapped through its __dict__-free frozen fields
    "t = square(x)\nobject.__setattr__(t, 'value', x * x - 1)\n" + FALSE,
    # monkeypatching the checker and the kernel in the file's process
    "import verify.proof.checker as c\nc.check_step = None\nc._exact_check = "
    "lambda *a: (True, 'trust me')\n" + FALSE,
    "import verify.proof.justify as j\nj.issued = lambda t: True\n" + FALSE,
])
def test_changes_made_by_the_file_do_not_verify_a_false_claim(tmp_path, body):
    assert run(tmp_path, body) in (1, 2)


def test_an_assumption_subclass_is_refused(tmp_path, capsys):
    body = ("from verify.proof.hypotheses import Assumption\n"
            "class A(Assumption):\n    def __eq__(self, other):\n        return True\n"
            "a = A('fake', x - 1, 'nonneg')\n"
            "d = Derivation('d', x, ctx).ge(1, by_sos(a))\n")
    assert run(tmp_path, body) == 2
    assert "ctx.assume" in capsys.readouterr().err


def test_a_str_subclass_label_is_a_plain_string_to_the_checker(tmp_path, capsys):
    body = ("import os\nclass Name(str):\n"
            "    def __format__(self, spec):\n        os._exit(0)\n"
            "    def __str__(self):\n        os._exit(0)\n"
            "y = (x * x).named(Name('y'))\n"
            "d = Derivation(Name('false'), y, ctx).ge(1, by_bound(square(x)))\n")
    assert run(tmp_path, body) == 1
    assert "false: refuted" in capsys.readouterr().out


def test_a_justification_changed_after_the_step_is_recorded(tmp_path):
    body = ("b = by_algebra('fine')\nd = Derivation('d', tr(R), ctx).equals(tr(R.T), b)\n"
            "class Note:\n    def __format__(self, s):\n        raise SystemExit(0)\n"
            "b.note = Note()\n")
    assert run(tmp_path, body) == 2


def test_dynamics_written_behind_the_api_are_checked_again(tmp_path, capsys):
    w = "w = ctx.vector('w')\n"
    body = (w + "ctx._dynamics[R.data.uid] = R + hat(w)\n"
            "d = Derivation('d', ctx.ddt(tr(R)), ctx).equals(tr(R + hat(w)), by_algebra())\n")
    assert run(tmp_path, body) == 2
    assert "skew" in capsys.readouterr().err


# -- 2. the file's process ends early, or overruns ---------------------------------------------
@pytest.mark.parametrize("body", [
    "import threading, os, time\n"
    "threading.Thread(target=lambda: os._exit(0)).start()\ntime.sleep(2)\n" + FALSE,
    "import atexit, os\natexit.register(lambda: os._exit(0))\n" + FALSE,
    "import ctypes\nctypes.CDLL(None).exit(0)\n" + FALSE,
    "import os, signal\nos.kill(os.getpid(), signal.SIGSEGV)\n" + FALSE,
])
def test_exits_and_crashes_never_give_exit_0(tmp_path, body):
    assert run(tmp_path, body) in (1, 2)


def test_a_file_that_never_ends_is_stopped_at_its_budget(tmp_path, capsys):
    assert run(tmp_path, "while True:\n    pass\n", "--budget-seconds", "3") == 2
    assert "budget" in capsys.readouterr().err


def test_a_file_that_eats_memory_is_stopped_at_its_budget(tmp_path, capsys):
    body = "blocks = []\nwhile True:\n    blocks.append(bytearray(2**26))\n"
    assert run(tmp_path, body, "--budget-memory", "1") == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1


# -- 3. forged data -----------------------------------------------------------------------------
def _data():
    ctx = Context("c")
    x = ctx.scalar("x")
    from verify.proof import by_bound, square

    d = Derivation("d", x * x + 1, ctx).ge(1, by_bound(square(x)))
    return json.loads(json.dumps(encode([d])))


@pytest.mark.parametrize("forge", [
    lambda d: d["terms"][0].update(make="positive"),          # square(x) relabelled
    lambda d: d["nodes"].append({"op": "add", "shape": "scalar", "value": None,
                                 "args": [0, 99], "label": None}),
    lambda d: d["nodes"][0].update(shape="matrix"),
    lambda d: d["nodes"][0].update(extra=1),
    lambda d: d.update(schema="verify-derivations/0"),
    lambda d: d["variables"][0].update(kind="quaternion"),
    lambda d: d["derivations"][0]["steps"][0]["because"].update(kind="sos"),
    lambda d: d["nodes"].__setitem__(
        0, {"op": "const", "shape": "scalar", "value": ["1" + "0" * 20000, "1"],
            "label": None, "args": []}),
])
def test_forged_data_is_refused(forge):
    data = _data()
    forge(data)
    with pytest.raises(ProofSyntaxError):
        decode(data)


def test_honest_data_round_trips():
    (d,) = decode(_data())
    assert check(d, SearchSettings(samples=32, hypothesis_examples=5, ipopt_starts=1,
                                   seed=1)).verdict == "verified"


# -- 4. rotations are rotations -----------------------------------------------------------------
def test_no_exact_witness_at_the_zero_quaternion():
    """tr R = 4 holds for no rotation; its numerator vanishes at q = 0, which is none."""
    ctx = Context("q0")
    R = ctx.rotation("R")
    c = ctx.condition("tr R = 4", tr(R), 4)
    d = Derivation("vacuous", tr(R), ctx, where=(c,)).equals(4, by_algebra())
    problem = step_problem(d, d.steps[0])
    assert not exact_witness(problem, {R.data.uid: np.zeros(4)})
    assert check(d, SearchSettings(samples=64, hypothesis_examples=10, ipopt_starts=1,
                                   seed=3)).verdict != "verified"


# four dense conditions in four unknowns: their Groebner basis takes minutes
DENSE = ("def dense(k):\n    e = k - 7\n    for i, a in enumerate(ys):\n"
         "        for j, b in enumerate(ys):\n"
         "            e = e + ((i * 7 + j * 3 + k) % 5 - 2) * a * a * b * (a + b + k)\n"
         "    return e\n")


# -- 5. bounded work -----------------------------------------------------------------------------
def test_a_doubling_tree_prints_and_checks_quickly(tmp_path, capsys):
    body = ("y = x\nfor _ in range(64):\n    y = y + y\n"
            "d = Derivation('double', y, ctx).equals(2**64 * x, by_algebra())\n")
    assert run(tmp_path, body) == 0
    ctx = Context("c")
    y = ctx.scalar("y")
    for _ in range(64):
        y = y + y
    assert len(to_text(y)) < 20_000


@pytest.mark.parametrize("body", [
    # (x + 1)^(2^16) by repeated squaring: 17 nodes, degree 65536
    "y = x + 1\nfor _ in range(16):\n    y = y * y\n"
    "d = Derivation('big', y, ctx).equals(y * 1, by_algebra())\n",
    # the condition x^4096 = 2
    "y = x\nfor _ in range(12):\n    y = y * y\n"
    "c = ctx.condition('x^4096 = 2', y, 2)\n"
    "d = Derivation('root', x * x, ctx, where=(c,)).ge(0, by_bound(square(x)))\n",
    # a constant of 5001 digits
    "d = Derivation('huge', 10**5000 * x, ctx).equals(x * 10**5000, by_algebra())\n",
])
def test_oversized_steps_are_inconclusive_before_the_work(tmp_path, capsys, body):
    assert run(tmp_path, body) == 1
    out = capsys.readouterr().out
    assert "budget exceeded before the work" in out


def test_dense_conditions_stop_at_the_step_budget(tmp_path, capsys):
    body = ("ys = [ctx.scalar(f'y{i}') for i in range(4)]\n"
            + DENSE +
            "cs = [ctx.condition(f'c{k}', dense(k + 1), 0) for k in range(4)]\n"
            "d = Derivation('dense', ys[0], ctx, where=tuple(cs)).equals(0, by_algebra())\n")
    assert run(tmp_path, body, "--budget-seconds", "6") == 1
    assert "budget exceeded" in capsys.readouterr().out


def test_the_file_budget_covers_every_step(tmp_path, capsys):
    """A file whose steps each take long: the later ones find no time left."""
    body = ("ys = [ctx.scalar(f'y{i}') for i in range(4)]\n"
            + DENSE +
            "cs = [ctx.condition(f'c{k}', dense(k + 1), 0) for k in range(4)]\n"
            "d = Derivation('dense', ys[0], ctx, where=tuple(cs))"
            ".equals(0, by_algebra()).equals(0, by_algebra()).equals(0, by_algebra())\n")
    assert run(tmp_path, body, "--budget-seconds", "6") == 1
    out = capsys.readouterr().out
    assert out.count("time budget is spent") == 2


def test_check_budget_options_are_validated(tmp_path, capsys):
    path = tmp_path / "ok.py"
    path.write_text(HEADER + "d = Derivation('d', tr(R), ctx).equals(tr(R.T), by_algebra())\n")
    assert main(["check", str(path), "--budget-seconds", "0"]) == 2
    assert main(["check", str(path), "--budget-memory", "inf"]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 2


def test_a_unit_of_work_past_its_memory_or_killed_is_budget_exceeded():
    import os

    from verify.proof.budget import Budget, BudgetExceededError, run_bounded

    assert run_bounded(lambda: 6 * 7, Budget(10, 2**28)) == 42
    with pytest.raises(BudgetExceededError, match="memory"):
        run_bounded(lambda: len(bytearray(2**31)), Budget(10, 2**28))
    with pytest.raises(BudgetExceededError):
        run_bounded(os.abort, Budget(10, 2**28))  # as FLINT does on a huge exponent
    with pytest.raises(BudgetExceededError, match="time"):
        run_bounded(lambda: any(iter(int, 1)), Budget(1, 2**28))  # spins, allocates nothing


def test_a_huge_power_is_refused_where_it_is_written(tmp_path, capsys):
    assert run(tmp_path, "d = Derivation('p', x ** (10**9), ctx).equals(x, by_algebra())\n") == 2
    assert "powers are at most" in capsys.readouterr().err


def test_a_scale_of_an_expression_is_no_term():
    data = _data()
    data["terms"].append({"make": "scale", "args": [{"const": ["2", "1"]}, {"node": 0}]})
    with pytest.raises(ProofSyntaxError, match="non-negative term"):
        decode(data)


def test_a_file_that_forges_a_huge_handover_is_refused(tmp_path, capsys):
    """The file writes on the handover pipe itself (it can: it runs in the child)."""
    body = ("import os, stat, ctypes\n"
            "for fd in range(3, 64):\n"
            "    try:\n"
            "        if stat.S_ISFIFO(os.fstat(fd).st_mode):\n"
            "            os.write(fd, b'C{\"derivations\":' + b' ' * (70 * 2**20) + b'}')\n"
            "    except OSError:\n"
            "        pass\n"
            "ctypes.CDLL(None).exit(0)\n")
    assert run(tmp_path, body) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "bytes of data" in err


def test_no_counterexample_at_the_zero_quaternion():
    """tr R = 4 ⇒ tr R = 5 is vacuously true; q = 0 meets the condition's numerator
    (0 = 0) and breaks the step, but q = 0 is no rotation: no counterexample there."""
    from verify.proof.confirm import confirm

    ctx = Context("q0")
    R = ctx.rotation("R")
    c = ctx.condition("tr R = 4", tr(R), 4)
    d = Derivation("vacuous", tr(R), ctx, where=(c,)).equals(5, by_algebra())
    problem = step_problem(d, d.steps[0])
    assert confirm(problem, {R.data.uid: np.zeros(4)}) is None  # not a point at all
    assert check(d, SearchSettings(samples=64, hypothesis_examples=10, ipopt_starts=1,
                                   seed=3)).verdict != "refuted"
