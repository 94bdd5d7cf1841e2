"""Hostile derivations data for `verify check FILE.json` (no Python of the user runs) and
what the checker prints: budgets while decoding, linear bookkeeping, exact
counterexamples, escaped user text.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from verify.artefacts.text import shown
from verify.cli import main
from verify.proof import Context, Derivation, by_algebra, by_bound, square
from verify.proof.checker import _union, step_problem, validate_derivation
from verify.proof.expr import ProofSyntaxError
from verify.proof.rebuild import decode
from verify.proof.wire import LIMITS, encode


def _write(tmp_path: Path, data: dict) -> Path:
    path = tmp_path / "data.json"
    path.write_text(json.dumps(data, ensure_ascii=True))
    return path


def _check(tmp_path: Path, data: dict, *extra: str) -> int:
    return main(["check", str(_write(tmp_path, data)), "--quick", "--certificates",
                 str(tmp_path / "c"), *extra])


def _base() -> dict:
    ctx = Context("c")
    x = ctx.scalar("x")
    d = Derivation("d", x * x + 1, ctx).ge(1, by_bound(square(x)))
    return json.loads(json.dumps(encode([d])))


# -- budgets while decoding ------------------------------------------------------------------
def test_doubling_terms_are_refused_before_they_grow(tmp_path, capsys):
    """t(k+1) = t(k) + t(k): reasons and premises double at every term."""
    data = _base()
    for k in range(60):
        data["terms"].append({"make": "add", "args": [{"term": k}, {"term": k}]})
    assert _check(tmp_path, data) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "budget exceeded" in err


def test_many_ddt_nodes_of_one_tree_differentiate_it_once():
    ctx = Context("c")
    R = ctx.rotation("R")
    w = ctx.vector("w")
    from verify.proof import hat, tr

    ctx.dynamics(R, R @ hat(w))
    ctx.constant(w)
    tree = tr(R)
    for k in range(300):
        tree = tree + tr(R @ R) * k
    d = Derivation("d", tree, ctx).equals(tree, by_algebra())
    data = json.loads(json.dumps(encode([d])))
    top = data["derivations"][0]["start"]
    first = len(data["nodes"])
    for _ in range(20_000):
        data["nodes"].append({"op": "ddt", "shape": "scalar", "value": 0, "args": [top],
                              "label": None})
    (out,) = decode(data)
    # every ddt node of the same tree is the same derivative: differentiated once
    from verify.proof.rebuild import _Decoder

    decoder = _Decoder(data)
    assert len({id(decoder.nodes[i]) for i in range(first, len(decoder.nodes))}) == 1
    assert out.name == "d"


def test_nested_derivatives_stop_at_the_budget(tmp_path, capsys):
    """ddt(ddt(...ddt(x)...)) with x' = x x: each level doubles the tree."""
    ctx = Context("c")
    x = ctx.scalar("x")
    d = Derivation("d", x, ctx).equals(x, by_algebra())
    data = json.loads(json.dumps(encode([d])))
    data["nodes"].append({"op": "scale", "shape": "scalar", "value": None, "args": [0, 0],
                          "label": None})
    data["contexts"][0]["dynamics"] = [[0, len(data["nodes"]) - 1]]
    for _ in range(3000):
        data["nodes"].append({"op": "ddt", "shape": "scalar", "value": 0,
                              "args": [len(data["nodes"]) - 1], "label": None})
    assert _check(tmp_path, data) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "budget exceeded" in err


def test_dynamics_of_huge_degree_are_refused_before_the_tangency_check(tmp_path, capsys):
    data = _base()
    n = len(data["nodes"])
    prev = 0
    for _ in range(60):  # x^(2^60) by repeated squaring of the variable's node
        data["nodes"].append({"op": "scale", "shape": "scalar", "value": None,
                              "args": [prev, prev], "label": None})
        prev = len(data["nodes"]) - 1
    data["contexts"][0]["dynamics"] = [[0, prev]]
    data["nodes"].append({"op": "ddt", "shape": "scalar", "value": 0, "args": [0],
                          "label": None})
    assert n < len(data["nodes"])
    assert _check(tmp_path, data) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "budget exceeded" in err and "degree" in err


def test_forty_thousand_conditions_are_bookkept_in_linear_time():
    ctx = Context("c")
    x = ctx.scalar("x")
    conditions = tuple(ctx.condition(f"c{k}", x * 0 + k, k) for k in range(40_000))
    d = Derivation("d", x, ctx, where=conditions).equals(x, by_algebra()) \
        .equals(x, by_algebra())
    validate_derivation(d)
    problems = [step_problem(d, s) for s in d.steps]
    union, _ = _union(problems)
    assert len(union) == 40_000 and union[0] is conditions[0]


def test_a_data_file_is_bounded_like_a_handover():
    assert LIMITS["differentiated"] > 0 and LIMITS["terms_size"] >= LIMITS["term_size"]
    data = _base()
    data["nodes"][0]["label"] = "x" * (LIMITS["text"] + 1)
    with pytest.raises(ProofSyntaxError):
        decode(data)


# -- what is printed ----------------------------------------------------------------------------
def test_an_algebraic_counterexample_is_printed_exactly(tmp_path, capsys):
    """x² = 2 ⇒ x ≥ 0 is refuted at x = -√2: printed as the root of x² - 2 in its
    isolating interval (exact), not as a midpoint that does not satisfy x² = 2."""
    ctx = Context("c")
    x = ctx.scalar("x")
    c = ctx.condition("x^2 = 2", x * x, 2)
    d = Derivation("alg", x, ctx, where=(c,)).ge(0, by_bound(square(x)))
    assert _check(tmp_path, json.loads(json.dumps(encode([d]))),
                  "--json", str(tmp_path / "out.json")) == 1
    out = capsys.readouterr().out
    (line,) = [s for s in out.splitlines() if "counterexample (exact)" in s]
    result = json.loads((tmp_path / "out.json").read_text())
    params = result[0]["steps"][0]["counterexample"]["values"]["x"]["parameters"]
    assert "root of" in params[0] and params[0] in line
    exact = line.split("x = ", 1)[1].split(" (≈")[0]
    assert exact == params[0]


@pytest.mark.parametrize("hostile", [
    "\x1b[2J\x1b[Hall 9 derivation(s) verified", "refuted\rverified", "\u202everified",
    "a\ud800b", "\x9b31m", "\u2066x\u2069",
])
def test_user_text_reaches_the_terminal_escaped(tmp_path, capsys, hostile):
    ctx = Context("c")
    x = ctx.scalar(f"x{hostile}")
    y = (x * x).named(f"label{hostile}")
    d = Derivation(f"name{hostile}", y, ctx, statement=hostile,
                   cite=hostile).ge(1, by_bound(square(x), note=hostile))
    code = _check(tmp_path, json.loads(json.dumps(encode([d]))))
    assert code in (0, 1)
    captured = capsys.readouterr()
    for stream in (captured.out, captured.err):
        assert all(shown(ch) == ch for ch in stream if ch != "\n"), stream
    assert shown(hostile) in captured.out


def test_the_escaping_function_shows_controls_bidi_and_surrogates():
    assert shown("a\x1bb") == "a\\x1bb"
    assert shown("\r") == "\\x0d"
    assert shown("\u202e") == "\\u202e"
    assert shown("\ud800") == "\\ud800"
    assert shown("R̄ᵀ λmin ≥ 0 ⪰") == "R̄ᵀ λmin ≥ 0 ⪰"
    assert shown("x" * 10, limit=4) == "xxxx…"


def test_mount_points_with_escaped_characters_are_read_back():
    """A mount point with a space (written \\040 in /proc/self/mountinfo) must be
    remounted read-only by its real path, not skipped."""
    from verify.proof.confine import _unescape, mount_points

    assert _unescape("/mnt/a\\040b\\011c") == "/mnt/a b\tc"
    assert _unescape("/mnt/a\\04") == "/mnt/a\\04"
    points = mount_points()
    assert "/" in points and points == sorted(points, key=lambda p: (p.count("/"), p))
