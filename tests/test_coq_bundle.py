"""Units written as modules of one file (:mod:`verify.coq.bundle`): the theorems keep
their names, ``coqc`` accepts the bundle, and the audit reads each module as the unit's
own file, so nothing can be slipped in between modules or above them."""

from __future__ import annotations

from dataclasses import replace

import pytest
from coq_tools import compile_development, compile_prelude, run_coqc

from verify.coq.bundle import bundle_text, module_texts
from verify.coq.check_export import export_verified
from verify.coq.development import (
    CoqAuditError,
    audit_problems,
    coqc_available,
    render_development,
    write_development,
)
from verify.coq.export import in_bundle
from verify.coq.unit import CoqUnit
from verify.proof import Context, Derivation, by_algebra

needs_coqc = pytest.mark.skipif(not coqc_available(), reason="coqc is not installed")


class _Step:
    verdict = "verified"


class _Result:
    def __init__(self, d: Derivation) -> None:
        self.steps = [_Step() for _ in d.steps]
        self.verdict = "verified"


def _units() -> list[CoqUnit]:
    ctx = Context("c")
    x, y = ctx.scalar("x"), ctx.scalar("y")
    first = Derivation("bundle.first", x * (x + y), ctx).equals(
        x * x + x * y, by_algebra())
    second = Derivation("bundle.second", (x + y) * (x - y), ctx).equals(
        x * x - y * y, by_algebra())
    units, _fates, missing = export_verified([first, second],
                                             [_Result(first), _Result(second)], None)
    assert not missing and len(units) == 2
    return in_bundle(units, "Pair")


def test_a_bundle_is_one_file_with_a_module_per_unit():
    units = _units()
    files = render_development(units)
    assert "Pair.v" in files and not any(f"{u.name}.v" in files for u in units)
    header, modules = module_texts(files["Pair.v"])
    assert list(modules) == [u.name for u in units]
    assert "Require" in header and "Theorem" not in header
    assert all("Require" not in text for text in modules.values())
    assert "From VerifyCoq Require Import Pair." in files["All.v"]
    assert f"{units[0].name}.step1" in files["All.v"]
    assert audit_problems(files, units) == []
    # one unit alone keeps its own file
    assert in_bundle(units[:1], "Pair") == units[:1]


def test_text_between_or_above_modules_is_refused():
    units = _units()
    files = render_development(units)
    text = files["Pair.v"]
    first, second = units[0].name, units[1].name
    above = text.replace(f"Module {first}.",
                         f"Theorem cheat : 0 = 0.\nProof. reflexivity. Qed.\n\nModule {first}.")
    assert any("stated before the first module" in p
               for p in audit_problems({**files, "Pair.v": above}, units))
    between = text.replace(f"Module {second}.",
                           f"Module other.\nTheorem cheat : 0 = 0.\nProof. reflexivity. Qed.\n"
                           f"End other.\n\nModule {second}.")
    assert any("module other is not a unit" in p
               for p in audit_problems({**files, "Pair.v": between}, units))
    changed = text.replace("Theorem step1", "Theorem step1 : 0 = 0. Proof. reflexivity. "
                           "Qed.\nTheorem step1b", 1)
    assert audit_problems({**files, "Pair.v": changed}, units)
    dropped = text[:text.index(f"Module {second}.")]
    assert any(f"unit {second} is missing" in p
               for p in audit_problems({**files, "Pair.v": dropped}, units))
    typed = text.replace(f"Module {first}.", f"Module Type {first}.")
    assert any("outside the template" in p
               for p in audit_problems({**files, "Pair.v": typed}, units))


def test_a_bundle_name_may_not_be_a_unit_name_nor_hold_a_dependency_of_a_lone_unit():
    units = _units()
    lone = CoqUnit("Pair", "From VerifyCoq Require Import SO3.\n", ())
    with pytest.raises(ValueError, match="clashes"):
        render_development([*units, lone])
    needs = CoqUnit("needs", f"From VerifyCoq Require Import SO3 {units[0].name}.\n", ())
    with pytest.raises(ValueError, match="requires a unit written into a bundle"):
        render_development([*units, needs])
    with pytest.raises(ValueError, match="bundle name"):
        replace(units[0], bundle="not a name")


def test_a_forged_bundle_file_is_refused_and_nothing_written(tmp_path):
    units = _units()
    forged = [replace(units[0], text=units[0].text.replace(
        "End ", "Theorem claim2 : 0 = 1.\nProof. Admitted.\nEnd ", 1)), units[1]]
    with pytest.raises(CoqAuditError):
        write_development(tmp_path / "coq", forged)
    assert not (tmp_path / "coq").exists()


@needs_coqc
def test_coqc_accepts_the_bundle_and_all_v_finds_every_theorem(tmp_path):
    units = _units()
    folder = compile_prelude(tmp_path)
    ok, failed, output = compile_development(folder, units)
    assert ok, (failed, output)
    done = run_coqc(folder, "All.v", check=True)
    assert "Axioms:" in done.stdout or "Closed under the global context" in done.stdout


@needs_coqc
def test_a_unit_may_import_an_earlier_module_of_its_bundle(tmp_path):
    units = _units()
    later = replace(units[1], text=units[1].text.replace(
        "From VerifyCoq Require Import SO3.",
        f"From VerifyCoq Require Import SO3 {units[0].name}."))
    text = bundle_text("Pair", [units[0], later])
    header, modules = module_texts(text)
    assert "From VerifyCoq Require SO3.\n" in header
    assert f"Import Reals Lra SO3 {units[0].name}." in modules[later.name]
    folder = compile_prelude(tmp_path)
    ok, failed, output = compile_development(folder, [units[0], later])
    assert ok, (failed, output)


def test_a_comment_line_that_reads_like_a_require_stays_in_its_comment():
    units = _units()
    text = units[0].text.replace(
        "(** Exported from", "(** a line of a comment:\nFrom Coq Require Import Extraction.\n"
        "   Exported from", 1)
    assert "\nFrom Coq Require Import Extraction.\n" in text
    header, modules = module_texts(bundle_text("Pair", [replace(units[0], text=text),
                                                        units[1]]))
    assert "Extraction" not in header
    module = modules[units[0].name]
    assert "\nFrom Coq Require Import Extraction.\n" in module  # still in the comment
    assert not any(line.startswith("Import") and "Extraction" in line
                   for line in module.splitlines())
