"""Hostile derivation files against the path from a file to Coq, each with its sound
outcome: no file text reaches a ``.v`` file as code, every exporter failure is a step
not exported (never a crash, a hang or a half-written folder), and ``verify check
--coq`` exits 0 only when every verified step reached Coq and ``coqc`` accepted it."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from fractions import Fraction

import pytest
from coq_tools import compiles

from verify.cli import main
from verify.coq.audit import forbidden_commands, sentences, strip_comments
from verify.coq.check_export import NOT_VERIFIED, export_verified
from verify.coq.derivations import derivation_unit, said
from verify.coq.development import CoqAuditError, coqc_available, write_development
from verify.coq.unit import CoqUnit
from verify.proof import (
    Context,
    Derivation,
    by_algebra,
    by_bound,
    cos,
    dot,
    hat,
    positive,
    square,
)
from verify.proof.budget import Budget
from verify.proof.expr import ProofSyntaxError, chart_gap
from verify.proof.isolate import data_text

needs_coqc = pytest.mark.skipif(not coqc_available(), reason="coqc is not installed")

FORGED = ("evil *) Axiom cheat : forall x : R, x + x = 3*x. Theorem claim2 : forall x : "
          "R, x + x = 3*x. Proof. exact cheat. Qed. (* \"")


@dataclass
class _Step:
    verdict: str = "verified"


@dataclass
class _Result:
    """What the exporter reads of a checker's result: each step's verdict, the whole's."""

    steps: list = field(default_factory=list)
    verdict: str = "verified"


def _verified(*derivations: Derivation) -> list[_Result]:
    return [_Result([_Step() for _ in d.steps]) for d in derivations]


def _export(*derivations: Derivation):
    return export_verified(list(derivations), _verified(*derivations), None)


def _forged() -> Derivation:
    ctx = Context("c")
    x = ctx.scalar("x")
    return Derivation(FORGED, x + x, ctx, statement='" *) Axiom c2 : False. (*',
                      cite="*)").equals(2 * x, by_algebra(note="*note"))


def _code(text: str) -> str:
    """A unit's Coq commands without comments (what coqc runs)."""
    return strip_comments(text)


# -- nothing a file writes is code -----------------------------------------------------------
def test_a_forged_name_stays_in_comments():
    (unit,), _fates, missing = _export(_forged())
    assert not missing and unit.theorems == ("step1",)
    code = _code(unit.text)
    assert not forbidden_commands({"u.v": unit.text})
    assert "cheat :" not in code and "claim2" not in code and "3*x" not in code
    assert [s.split()[1] for s in sentences(unit.text) if s.startswith("Theorem")] == ["step1"]
    assert re.fullmatch(r"[a-z][A-Za-z0-9_]*", unit.name)


def test_a_forged_unit_is_refused_by_the_audit_and_nothing_is_written(tmp_path):
    (unit,), _, _ = _export(_forged())
    forged = CoqUnit(unit.name, unit.text.replace(
        "End ", "Axiom cheat : False.\nTheorem claim2 : 0 = 1.\nProof. Admitted.\nEnd ", 1),
        unit.theorems, unit.source, unit.statements)
    with pytest.raises(CoqAuditError):
        write_development(tmp_path / "coq", [forged])
    assert not (tmp_path / "coq").exists()
    assert [p.name for p in tmp_path.iterdir()] == []  # no staging folder left


def test_a_changed_statement_fails_the_round_trip(tmp_path):
    (unit,), _, _ = _export(_forged())
    changed = CoqUnit(unit.name, unit.text.replace("(2 * v_1_x)", "(3 * v_1_x)"),
                      unit.theorems, unit.source, unit.statements)
    with pytest.raises(CoqAuditError, match="does not state what was exported"):
        write_development(tmp_path / "coq", [changed])
    # the recorded text changed with it: the tree built from the step still refuses it
    statements = tuple((k, v.replace("(2 * v_1_x)", "(3 * v_1_x)"))
                       for k, v in unit.statements)
    both = CoqUnit(changed.name, changed.text, changed.theorems, changed.source, statements,
                   unit.terms)
    with pytest.raises(CoqAuditError, match="another term"):
        write_development(tmp_path / "coq", [both])
    assert not (tmp_path / "coq").exists()


def test_statements_read_back_as_the_exported_trees():
    from verify.coq.reparse import parse_statement

    (unit,), _, _ = _export(_reserved_names())
    for name, statement in unit.statements:
        assert parse_statement(statement) == dict(unit.terms)[name]


@needs_coqc
def test_a_forged_name_in_a_json_file_never_compiles_into_a_theorem(tmp_path, capsys):
    data = tmp_path / "forged.json"
    data.write_text(data_text([_forged()]))
    out_dir = tmp_path / "coq"
    rc = main(["check", str(data), "--quick", "--coq", str(out_dir)])
    out = capsys.readouterr().out
    assert rc == 0, out
    assert "coqc accepted every file" in out
    units = [p for p in out_dir.glob("*.v") if p.name not in
             ("SO3.v", "QCert.v", "SOSCert.v", "BandCert.v", "All.v")]
    assert len(units) == 1
    code = _code(units[0].read_text())
    assert not forbidden_commands({"u.v": code}) and "3*x" not in code
    assert re.findall(r"Theorem (\w+)", code) == ["step1"]


def _reserved_names() -> Derivation:
    ctx = Context("reserved")
    names = ["step1", "claim", "k_pos", "q_x", "E", "T1", "le_by_slack", "if", "Admitted",
             "using", 'a"b', "*x", "R"]
    xs = [ctx.scalar(n, positive=(n == "k_pos")) for n in names]
    k = xs[2]
    total = xs[0]
    for x in xs[1:]:
        total = total + x
    gap = xs[4] - xs[5]
    d = Derivation('label "quoted" (*', total + k * (gap * gap), ctx)
    d.equals(total + k * ((xs[5] - xs[4]) * (xs[5] - xs[4])),
             by_algebra(note="*starts with a star"))
    d.ge(total, by_bound(positive(k) * square(xs[5] - xs[4]), note='"quoted" *'))
    return d


@needs_coqc
def test_quotes_stars_and_reserved_names_export_and_compile(prelude_dir):
    (unit,), _fates, missing = _export(_reserved_names())
    assert not missing and unit.theorems == ("step1", "step2", "claim")
    assert compiles(prelude_dir, unit.text, unit.name)


# -- no exit 3, no hang, no half folder ------------------------------------------------------
@pytest.mark.parametrize("name", ["SO3", "All", "so3", "QCert", "Reals", "\ud800"])
def test_prelude_and_awkward_names_get_their_own_module(tmp_path, name):
    ctx = Context("c")
    x = ctx.scalar("x\ud800")
    d = Derivation(name, x + x, ctx).equals(2 * x, by_algebra())
    units, _fates, missing = _export(d)
    assert not missing
    write_development(tmp_path / "coq", units)
    assert (tmp_path / "coq" / f"{units[0].name}.v").read_text(encoding="utf-8")
    assert units[0].name.casefold() not in {"so3", "all", "qcert", "reals"}


def _not_exported(d: Derivation) -> str:
    _units, _fates, missing = _export(d)
    assert missing and all(f.theorem is None for f in missing)
    return missing[0].reason


def test_a_5001_digit_constant_is_a_step_not_exported():
    ctx = Context("c")
    x = ctx.scalar("x")
    c = Fraction(10 ** 5000)
    reason = _not_exported(Derivation("big", x + c, ctx).equals(c + x, by_algebra()))
    assert "constant" in reason


def test_a_shared_subterm_squared_forty_times_is_bounded():
    ctx = Context("c")
    x = ctx.scalar("x")
    s = x + 1
    for _ in range(40):
        s = s * s
    reason = _not_exported(Derivation("square", s, ctx).equals(s, by_algebra()))
    assert "too large" in reason


def test_a_sum_nested_991_deep_exports(tmp_path):
    ctx = Context("c")
    x = ctx.scalar("x")
    s = x
    for _ in range(990):
        s = s + x
    d = Derivation("deep", s, ctx).equals(991 * x, by_algebra())
    units, _, missing = _export(d)
    assert not missing and units[0].theorems == ("step1",)
    # through a forked process (results pickled) and the audit in this one
    units, _, missing = export_verified([d], _verified(d), Budget(60, 2 * 2**30))
    assert not missing
    write_development(tmp_path / "coq", units)
    assert (tmp_path / "coq" / f"{units[0].name}.v").exists()


def test_a_chart_gap_condition_is_a_step_not_exported():
    ctx = Context("c")
    u = ctx.unit_vector("u")
    gap = ctx.condition("gap", dot(u, chart_gap(u.data)), 1)
    reason = _not_exported(Derivation("gap", dot(u, u), ctx, where=(gap,)).equals(
        1, by_algebra()))
    assert "chart_gap" in reason


def test_a_variable_of_another_context_is_a_step_not_exported():
    ctx, other = Context("c"), Context("other")
    x, y = ctx.scalar("x"), other.scalar("y")
    reason = _not_exported(Derivation("foreign", x + y, ctx).equals(y + x, by_algebra()))
    assert "not of the derivation's context" in reason


def test_twelve_rotations_take_a_bounded_number_of_attempts(monkeypatch):
    import verify.coq.derivations as derivations

    calls = []
    plain = derivations._entry_tactic
    monkeypatch.setattr(derivations, "_entry_tactic",
                        lambda *a, **k: calls.append(1) or plain(*a, **k))
    ctx = Context("r12")
    u = ctx.vector("u")
    rotations = [ctx.rotation(f"R{i}") for i in range(12)]
    lhs = dot(rotations[0] * u, rotations[0] * u)
    for R in rotations[1:]:
        lhs = lhs + dot(R * u, R * u)
    d = Derivation("rot12", lhs, ctx).equals(12 * dot(u, u), by_algebra())
    _units, _fates, missing = _export(d)
    assert not missing
    assert len(calls) < 12  # a few attempts, not 2^12 subsets


def test_the_tangency_recheck_is_refused_before_expansion():
    ctx = Context("t")
    R, v = ctx.rotation("R"), ctx.vector("v")
    xs = [ctx.scalar(f"x{i}") for i in range(40)]
    s = xs[0]
    for x in xs[1:]:
        s = s + x
    p = s
    for _ in range(23):
        p = p * s
    with pytest.raises(ProofSyntaxError, match="too large"):
        ctx.dynamics(R, R * hat(v) * p)


# -- honest exit status ----------------------------------------------------------------------
def test_contradictory_premises_are_never_exported():
    from verify.proof import check
    from verify.proof.falsify import SearchSettings

    ctx = Context("c")
    t = ctx.angle("θ")
    zero = ctx.condition("cos θ = 0", cos(t), 0)
    one = ctx.condition("cos θ = 1", cos(t), 1)
    d = Derivation("contradiction", cos(t), ctx, where=(zero, one)).equals(0, by_algebra())
    d.equals(1, by_algebra())
    result = check(d, SearchSettings(samples=16, hypothesis_examples=5, ipopt_starts=1))
    assert result.verdict != "verified"
    _units, fates, missing = export_verified([d], [result], None)
    assert not [f for f in fates if f.theorem]
    assert {f.reason for f in fates} == {NOT_VERIFIED} and not missing


@needs_coqc
def test_check_coq_exits_1_when_a_verified_step_is_missing(tmp_path, capsys, monkeypatch):
    import verify.coq.derivations as derivations
    from verify.coq.unit import CoqExportError

    def refuse(*args, **kwargs):
        raise CoqExportError("forced refusal")

    monkeypatch.setattr(derivations, "_equality_script", refuse)
    ctx = Context("c")
    x = ctx.scalar("x")
    data = tmp_path / "d.json"
    data.write_text(data_text([Derivation("gone", x + x, ctx).equals(2 * x, by_algebra())]))
    rc = main(["check", str(data), "--quick", "--coq", str(tmp_path / "coq")])
    out = capsys.readouterr().out
    assert "1 of 1 derivation(s) verified" in out
    assert rc == 1 and "gone step 1 missing: forced refusal" in out
    rc = main(["check", str(data), "--quick", "--coq", str(tmp_path / "coq2"),
               "--allow-partial"])
    out = capsys.readouterr().out
    assert rc == 0 and "not in Coq: gone step 1" in out


# -- comments state exactly the theorem under them ---------------------------------------------
def _comment_before(text: str, theorem: str) -> str:
    i = text.index(f"\nTheorem {theorem} :")
    start = text.rindex("(**", 0, i)
    return text[start:i]


@pytest.mark.parametrize("builder", ["paper", "small"])
def test_every_comment_states_exactly_the_theorem_under_it(builder):
    if builder == "paper":
        from verify.coq.paper import paper_derivations
        derivations = paper_derivations()
    else:
        derivations = [_reserved_names(), _forged()]
    for d in derivations:
        unit, fates = derivation_unit(d)
        if unit is None:
            continue
        statements = dict(unit.statements)
        for f in fates:
            if f.theorem is None:
                continue
            step = d.steps[f.step - 1]
            comment = _comment_before(unit.text, f"step{f.step}")
            said_it = f"(** Step {f.step}: {said(step.lhs)} {step.relation} {said(step.rhs)}\n"
            assert comment.startswith(said_it), (d.name, comment)
            rel = {"=": "=", "<=": "<=", ">=": ">="}[step.relation]
            assert f" {rel} " in statements[f"step{f.step}"]
        if "claim" in unit.theorems:
            comment = _comment_before(unit.text, "claim")
            rel = {s.relation for s in d.steps} - {"="}
            assert comment == (f"(** The derivation's claim: {said(d.start)} "
                               f"{rel.pop() if rel else '='} {said(d.current)} *)")
        head = unit.text[:unit.text.index("*)")]
        assert "Context only, not theorems of this file" in head


def test_the_three_overclaiming_comments_are_context_only():
    from verify.coq.paper import paper_units

    units = {u.name: u for u in paper_units()}
    for name in ("lemma1_trace_form", "lemma1_spectrum", "thm1_V_dot_zero_implies_sync"):
        head = units[name].text[:units[name].text.index("*)")]
        summary = head.split("the derivation's summary:")[1]
        assert "Context only, not theorems of this file:" in head
        assert "Statement:" not in head and summary.strip()


@needs_coqc
def test_long_shared_subterms_are_written_once_and_compile(prelude_dir):
    from verify.coq.reparse import parse_statement

    ctx = Context("c")
    x, k = ctx.scalar("x"), ctx.scalar("k", positive=True)
    a = x * x + 1
    for _ in range(8):
        a = a + a
    b = (x + 1) * (x + 1)
    for _ in range(7):
        b = b + b
    equal = Derivation("lets.eq", a, ctx).equals(256 * (x * x) + 256, by_algebra())
    bound = Derivation("lets.le", b + k, ctx).ge(b, by_bound(positive(k)))
    units, _, missing = _export(equal, bound)
    assert not missing
    for unit in units:
        statement = dict(unit.statements)["step1"]
        assert statement.startswith("let s_1 := ") and len(statement) < 4000
        assert parse_statement(statement) == dict(unit.terms)["step1"]
        assert compiles(prelude_dir, unit.text, unit.name)


def test_a_sum_doubled_forty_times_is_refused_not_written():
    ctx = Context("c")
    x = ctx.scalar("x")
    s = x + 1
    for _ in range(40):
        s = s + s
    reason = _not_exported(Derivation("doubled", s, ctx).equals(s, by_algebra()))
    assert "characters" in reason or "too large" in reason
