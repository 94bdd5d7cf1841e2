"""Printed claims of checked certificates are what was proved, and an edited one fails.

Attacks, each with its sound outcome (`verify certificates check` run as a command, since
a CI job reads its exit code):

- declared signs dropped: ``x y >= 0`` valid only for x > 0, y > 0 is printed with them;
- an assumption dropped: the shipped ``c (1 + tr R) >= 0`` is printed with ``c >= 0``,
  printed from the assumption's tree, not its label;
- a misleading name: a rotation named ``R)+tr(R`` is printed quoted, never as
  ``tr(R)+tr(R) <= 3``;
- an edited statement (``tr(R) <= 2`` written on the certificate of ``tr(R) <= 3``, with
  or without the step's labels edited to match, on a user's or on the paper's
  certificate): exit 1, "statement edited", never "ok".
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from verify.proof import Context, Derivation, by_sos, certificate_store, check, tr
from verify.proof.budget import Budget
from verify.proof.checker import step_problem
from verify.proof.claim_text import claim_text
from verify.proof.falsify import SearchSettings
from verify.proof.printing import is_plain_name, name_text, to_text
from verify.sos.certificate import file_name

SMALL = SearchSettings(samples=16, hypothesis_examples=3, ipopt_starts=1, seed=5)
SHIPPED = Path(__file__).resolve().parents[1] / "certificates"


def _certificate(tmp_path_factory, d: Derivation) -> dict:
    """The certificate ``verify check`` writes for the one by_sos step of ``d``."""
    store = tmp_path_factory.mktemp("store")
    # in a forked step (budget=...): the solver's thread pool never starts in this process
    with certificate_store(store, source="file:mine.py"):
        assert check(d, SMALL, budget=Budget(120, 2**31)).verdict == "verified"
    (path,) = store.glob("sos-*.json")
    return json.loads(path.read_text())


@pytest.fixture(scope="module")
def signs(tmp_path_factory) -> dict:
    ctx = Context("user")
    x, y = ctx.scalar("x", positive=True), ctx.scalar("y", positive=True)
    return _certificate(tmp_path_factory, Derivation("xy", x * y, ctx).ge(0, by_sos()))


@pytest.fixture(scope="module")
def assumed(tmp_path_factory) -> dict:
    """The shipped example's "assumed sign" step (examples/sos_inequalities.py)."""
    ctx = Context("SOS over SO(3)")
    R = ctx.rotation("R")
    c = ctx.scalar("c")
    c_nonneg = ctx.assume("c ≥ 0", c, "nonneg")
    return _certificate(tmp_path_factory, Derivation("assumed sign", c * (1 + tr(R)), ctx)
                        .ge(0, by_sos(c_nonneg)))


@pytest.fixture(scope="module")
def bracket(tmp_path_factory) -> dict:
    ctx = Context("user")
    R = ctx.rotation("R)+tr(R")
    return _certificate(tmp_path_factory, Derivation("tr", tr(R), ctx).le(3, by_sos()))


@pytest.fixture(scope="module")
def trace(tmp_path_factory) -> dict:
    ctx = Context("user")
    R = ctx.rotation("R")
    return _certificate(tmp_path_factory, Derivation("tr", tr(R), ctx).le(3, by_sos()))


def _write(folder: Path, data: dict) -> Path:
    path = folder / file_name(data["claim"]["key"])
    path.write_text(json.dumps(data, sort_keys=True, indent=1), encoding="utf-8")
    return path


def _certificates_check(*paths: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "verify.cli", "certificates", "check",
                           *map(str, paths)], capture_output=True, text=True, timeout=300)


def _claim_line(out: str) -> str:
    (line,) = [ln for ln in out.splitlines() if ln.startswith(("ok", "INVALID"))]
    return line


# -- declared signs, assumptions ----------------------------------------------------------
def test_declared_signs_are_printed_with_the_claim(tmp_path, signs):
    done = _certificates_check(_write(tmp_path, signs))
    assert done.returncode == 0, done.stdout + done.stderr
    line = _claim_line(done.stdout)
    assert line.startswith("ok") and ": x y >= 0 for all x > 0, y > 0:" in line
    assert ": x y >= 0:" not in line


def test_the_shipped_assumption_is_printed_with_the_claim(tmp_path, assumed):
    done = _certificates_check(_write(tmp_path, assumed))
    assert done.returncode == 0, done.stdout + done.stderr
    line = _claim_line(done.stdout)
    assert ": c (1 + tr(R)) >= 0 for all c ∈ ℝ, R ∈ SO(3) with c >= 0:" in line
    assert ": c (1 + tr(R)) >= 0:" not in line


def test_an_assumption_is_printed_from_its_tree_not_its_label():
    """A label is the author's word: "c ≥ 5" on the assumption c >= 0 prints c >= 0."""
    ctx = Context("user")
    c = ctx.scalar("c")
    lie = ctx.assume("c ≥ 5", c, "nonneg")
    A = ctx.matrix("A")
    pd = ctx.assume("A is the identity", A, "pd")
    d = Derivation("x", c * c, ctx).ge(0, by_sos(lie, pd))
    text = claim_text(step_problem(d, d.steps[0]))
    assert text.assumptions == ("c >= 0", "sym(A) ≻ 0")
    assert text.declarations == ("c ∈ ℝ", "A ∈ ℝ³ˣ³")


def test_the_shipped_certificates_print_their_premises():
    """The paper's certificates (bound to the paper's steps, written with the package's
    labels) name their declared gain, Assumption 1's sign, and what each label stands
    for."""
    done = _certificates_check(SHIPPED / "sos-0d7a67545a4e02ce9d38.json",
                               SHIPPED / "sos-3c0bd7455cbf7e25ea7e.json")
    assert done.returncode == 0, done.stdout + done.stderr
    sign, bound = [ln for ln in done.stdout.splitlines() if ln.startswith("ok")]
    assert "for all k_s > 0, R_rl ∈ SO(3)" in sign and "with sym(R_rl) ≻ 0" in sign
    assert "for all k_s > 0, R_r, R̄, R_l ∈ SO(3)" in bound
    assert "writing " in bound and "R_rl = R_rᵀ R_l" in bound
    assert "φ(R_lᵀR̄) = (1/2) tr(I - R_lᵀ R̄)" in bound


# -- names --------------------------------------------------------------------------------
def test_a_name_with_brackets_is_printed_quoted(tmp_path, bracket):
    done = _certificates_check(_write(tmp_path, bracket))
    assert done.returncode == 0, done.stdout + done.stderr
    line = _claim_line(done.stdout)
    assert ': tr("R)+tr(R") <= 3 for all "R)+tr(R" ∈ SO(3):' in line
    assert "tr(R)+tr(R)" not in line


@pytest.mark.parametrize("name", ["R", "R₁", "R̄_r", "k_s", "ξ", "x2", "x′", "_t"])
def test_identifier_names_are_printed_bare(name):
    assert is_plain_name(name) and name_text(name) == name


@pytest.mark.parametrize("name, printed", [
    ("R)+tr(R", '"R)+tr(R"'),
    ("a b", '"a b"'),          # juxtaposition is a product
    ("x^2", '"x^2"'),
    ("Rᵀ", '"Rᵀ"'),            # the printer's transpose
    ("x²", '"x²"'),
    ("2", '"2"'),              # a number
    ("I", '"I"'),              # the identity
    ("tr", '"tr"'),
    ("λmin", '"λmin"'),
    ("", '""'),
    ('a"b', '"a\\"b"'),        # a quote inside is escaped
    ("a\\", '"a\\\\"'),
    ("\x1b[2J", '"\\u001b[2J"'),  # a control character never reaches the terminal
    ("Α", '"Α"'),              # Greek capital alpha, not the Latin A
    ("ο", '"ο"'),              # Greek omicron, not the Latin o
    ("R\u0305", '"R\u0305"'),    # an overline looks like the bar R̄
    ("a\u0304", '"a\u0304"'),    # not in NFC: the same look as ā
    ("ā", '"ā"'),
])
def test_names_that_could_be_misread_are_quoted(name, printed):
    assert not is_plain_name(name) and name_text(name) == printed


def test_two_variables_that_print_alike_are_told_apart():
    ctx = Context("user")
    R1, R2 = ctx.rotation("R"), ctx.rotation("R")
    d = Derivation("x", tr(R1.T * R2), ctx).ge(-1, by_sos())
    text = claim_text(step_problem(d, d.steps[0]))
    assert text.inequality == "tr(Rᵀ R#2) >= -1"
    assert text.declarations == ("R, R#2 ∈ SO(3)",)


def test_labels_do_not_reach_the_tree_text():
    ctx = Context("user")
    R = ctx.rotation("R")
    e = tr(R).named("3")
    assert to_text(e) == "3" and to_text(e, labels=False) == "tr(R)"


# -- edited statements ----------------------------------------------------------------------
def _edited(data: dict, statement: str, label: str | None = None) -> dict:
    data = json.loads(json.dumps(data))
    data["claim"]["statement"] = statement
    if label is not None:  # the step's constant 3 labelled to read as the edit
        nodes = data["step"]["nodes"]
        k = next(i for i, n in enumerate(nodes)
                 if n["op"] == "const" and n["value"] == ["3", "1"])
        nodes[k]["label"] = label
    return data


@pytest.mark.parametrize("label", [None, "2"])
def test_an_edited_statement_exits_1(tmp_path, trace, label):
    done = _certificates_check(_write(tmp_path, _edited(trace, "tr(R) <= 2", label)))
    assert done.returncode == 1, done.stdout + done.stderr
    line = _claim_line(done.stdout)
    assert line.startswith("INVALID") and "statement edited" in line
    assert "tr(R) <= 3 for all R ∈ SO(3)" in line  # what the certificate does prove
    assert not any(ln.startswith("ok") for ln in done.stdout.splitlines())


def test_edited_labels_with_the_true_statement_print_the_tree(tmp_path, trace):
    """The step's labels are ignored: with the written statement left as the tree says,
    the certificate is valid and printed as tr(R) <= 3."""
    done = _certificates_check(_write(tmp_path, _edited(trace, "tr(R) <= 3", "2")))
    assert done.returncode == 0, done.stdout + done.stderr
    assert ": tr(R) <= 3 for all R ∈ SO(3):" in _claim_line(done.stdout)


def test_an_edited_statement_among_valid_ones_fails_the_run(tmp_path, trace, signs):
    _write(tmp_path, signs)
    _write(tmp_path, _edited(trace, "tr(R) <= 2"))
    done = _certificates_check(tmp_path)
    assert done.returncode == 1
    assert "1 of 2 certificate(s) valid" in done.stdout


def test_an_edited_statement_of_the_paper_exits_1(tmp_path):
    shipped = SHIPPED / "sos-ca4209e02297c7d04166.json"
    data = json.loads(shipped.read_text(encoding="utf-8"))
    data["claim"]["statement"] = data["claim"]["statement"].replace(">= 0", ">= 1")
    done = _certificates_check(_write(tmp_path, data))
    assert done.returncode == 1, done.stdout + done.stderr
    assert "statement edited" in _claim_line(done.stdout)


def test_verify_coq_refuses_an_edited_paper_statement(tmp_path):
    from verify.coq.sos import paper_sos_units

    name = "sos-ca4209e02297c7d04166.json"
    data = json.loads((SHIPPED / name).read_text(encoding="utf-8"))
    data["claim"]["statement"] = "k_s >= 0"
    _write(tmp_path, data)
    _units, outcome = paper_sos_units(tmp_path)
    assert outcome[name].startswith("refused: statement edited")


def test_verify_coq_exits_1_on_an_edited_paper_certificate(tmp_path):
    """`verify coq` over a certificates folder where one of the paper's SOS certificates
    carries an edited statement writes the rest, names the refusal and exits 1."""
    import shutil

    certificates = tmp_path / "certificates"
    shutil.copytree(SHIPPED, certificates, ignore=shutil.ignore_patterns("coq"))
    name = "sos-ca4209e02297c7d04166.json"
    data = json.loads((certificates / name).read_text(encoding="utf-8"))
    data["claim"]["statement"] = "k_s >= 0"
    (certificates / name).write_text(json.dumps(data), encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "verify.cli", "coq", "--out",
                           str(tmp_path / "coq")], cwd=tmp_path, capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "statement edited" in done.stdout


def test_verify_check_renews_a_stored_statement_that_is_not_the_steps(tmp_path, trace):
    """A certificate written with another statement (an earlier version's labelled text,
    or an edit) is reused by `verify check` and rewritten with its step's statement."""
    store = tmp_path / "store"
    store.mkdir()
    path = _write(store, _edited(trace, "tr(R) <= 2"))
    ctx = Context("user")
    R = ctx.rotation("R")
    d = Derivation("tr", tr(R), ctx).le(3, by_sos())
    with certificate_store(store, source="file:mine.py"):
        assert check(d, SMALL, budget=Budget(120, 2**31)).verdict == "verified"
    assert json.loads(path.read_text())["claim"]["statement"] == "tr(R) <= 3"
    assert _certificates_check(path).returncode == 0


def test_a_labelled_user_step_is_written_and_printed_as_its_tree(tmp_path_factory, tmp_path):
    """A user's label is the author's word: the certificate is written with the tree's
    text (so it is not refused as edited) and printed as that, with no label in it."""
    ctx = Context("user")
    R = ctx.rotation("R")
    phi = (3 - tr(R)).named("φ(R)")
    data = _certificate(tmp_path_factory, Derivation("phi", phi, ctx).ge(0, by_sos()))
    assert data["claim"]["statement"] == "3 - tr(R) >= 0"
    done = _certificates_check(_write(tmp_path, data))
    assert done.returncode == 0, done.stdout + done.stderr
    line = _claim_line(done.stdout)
    assert ": 3 - tr(R) >= 0 for all R ∈ SO(3):" in line and "φ" not in line


def test_many_labels_are_defined_within_bounds():
    """A tree that doubles at every level, each level labelled: the claim is printed in
    linear time (one memo over all definitions) and names at most MAX_DEFINITIONS."""
    from verify.proof.claim_text import MAX_DEFINITIONS

    ctx = Context("user")
    x = ctx.scalar("x")
    e = x
    for k in range(200):
        e = (e + e).named(f"L{k}")
    d = Derivation("wide", e, ctx).ge(0, by_sos())
    text = claim_text(step_problem(d, d.steps[0]))
    assert len(text.definitions) == MAX_DEFINITIONS + 1
    assert text.definitions[-1] == f"… ({200 - MAX_DEFINITIONS} more labels)"
    assert text.inequality == "… >= 0"  # the tree's text is abbreviated, never built
