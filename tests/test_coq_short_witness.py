"""Short refutation witnesses (``verify.coq.refutation.short_witness``) and the faster
audit text scan: the kernel's work on a refutation grows with the digits of w and z, so
the exporter writes the simplest w and a rounded z that the exact check still accepts.

The unit of a 10-state model written with decimal ``repr``s (not passive at about
1.9e17 rad/s: the decimals break C = B^T Q by about 1e-17) used to carry a 150-digit w
and did not compile in 600 s; its compile here is marked slow.
"""

from __future__ import annotations

import random
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from coq_tools import compiles

from verify.coq import refutation as rf
from verify.coq.audit import strip_comments
from verify.coq.development import coqc_available
from verify.passivity.decision import decide
from verify.passivity.io.model_file import load_model
from verify.passivity.port_hamiltonian import random_port_hamiltonian

ROOT = Path(__file__).resolve().parents[1]
MODELS = ROOT / "verify" / "data" / "models"

needs_coqc = pytest.mark.skipif(not coqc_available(), reason="coqc not installed")


def _digits(x: Fraction) -> int:
    return len(str(abs(x.numerator))) + len(str(x.denominator))


def _brute_simplest(lo: Fraction, hi: Fraction) -> Fraction:
    q = 1
    while True:
        p = -(-lo.numerator * q // lo.denominator)  # ceil(lo q)
        if Fraction(p, q) <= hi:
            return Fraction(p, q)
        q += 1


def test_simplest_between_is_the_least_denominator_then_numerator():
    rng = random.Random(7)
    for _ in range(400):
        a = Fraction(rng.randint(0, 200), rng.randint(1, 60))
        b = a + Fraction(rng.randint(0, 30), rng.randint(1, 400))
        assert rf.simplest_between(a, b) == _brute_simplest(a, b), (a, b)
    assert rf.simplest_between(Fraction(5, 2), Fraction(5, 2)) == Fraction(5, 2)
    with pytest.raises(ValueError):
        rf.simplest_between(Fraction(1), Fraction(0))


@pytest.fixture(scope="module")
def decimal_model_decision(tmp_path_factory):
    """A passive port-Hamiltonian model of 10 states written with decimal reprs: the
    exact decimals make it (barely) not passive at high frequency."""
    A, B, C, D = random_port_hamiltonian(10, 2, np.random.default_rng([11, 10]), False)

    def mat(M) -> str:
        return "[" + ", ".join("[" + ", ".join(repr(float(x)) for x in row) + "]"
                               for row in M) + "]"

    path = tmp_path_factory.mktemp("decimal") / "ph10.toml"
    path.write_text(f'name = "pH 10 decimal"\ndescription = "test"\n\n[state_space]\n'
                    f"A = {mat(A)}\nB = {mat(B)}\nC = {mat(C)}\nD = {mat(D)}\n")
    return decide(load_model(path))


def test_the_decimal_model_gets_a_short_witness_that_the_exact_check_accepts(
        decimal_model_decision):
    d = decimal_model_decision
    assert d.verdict == "not passive"
    base, found = rf.decision_witness(d)
    assert isinstance(found, rf.FrequencyWitness)
    # the gate's own witness frequency is a long fraction; the exported one is short
    gate_omega = Fraction(d.witness.data["omega"])
    assert _digits(gate_omega) > 100
    assert _digits(found.omega) <= 24
    assert all(_digits(x) <= 4 for x in (*found.a, *found.b))
    # re-checked exactly, as Coq computes it
    assert found.value < 0
    assert rf.form_at(base, found.omega, found.a, found.b) == found.value
    assert abs(found.omega - gate_omega) <= gate_omega / 2


def test_shortening_keeps_a_band_witness_in_its_band_and_negative():
    base, found = rf.decision_witness(decide(load_model(MODELS / "reconstructed_ks2p5.toml")))
    long = rf.FrequencyWitness(found.omega + Fraction(1, 10 ** 30),
                               tuple(x * Fraction(10 ** 20 + 1, 10 ** 20) for x in found.a),
                               found.b, Fraction(-1))
    band = (Fraction(9, 4), Fraction(11, 4))
    short = rf.short_witness(base, long, band)
    assert band[0] <= short.omega <= band[1]
    assert short.value < 0
    assert rf.form_at(base, short.omega, short.a, short.b) == short.value
    assert _digits(short.omega) <= 3


@needs_coqc
@pytest.mark.slow
def test_the_decimal_models_refutation_unit_compiles(prelude_dir, decimal_model_decision):
    unit = rf.decision_unit(decimal_model_decision, "Refutation_decimal")
    assert compiles(prelude_dir, unit.text, "Refutation_decimal")


def _strip_reference(text: str) -> str:
    """The audit's earlier character-by-character scan."""
    out, depth, i, n = [], 0, 0, len(text)
    while i < n:
        if text.startswith("(*", i):
            depth, i = depth + 1, i + 2
        elif depth and text.startswith("*)", i):
            depth, i = depth - 1, i + 2
        elif not depth and text[i] == '"':
            j = text.find('"', i + 1)
            i = n if j < 0 else j + 1
        else:
            if not depth:
                out.append(text[i])
            i += 1
    return "".join(out)


def test_strip_comments_matches_the_character_scan():
    rng = random.Random(3)
    for _ in range(20000):
        text = "".join(rng.choice('(*)"ab \n') for _ in range(rng.randint(0, 40)))
        assert strip_comments(text) == _strip_reference(text), repr(text)
    source = (ROOT / "verify" / "coq" / "prelude" / "QCert.v").read_text()
    assert strip_comments(source) == _strip_reference(source)


def test_units_are_compiled_in_rounds_after_the_units_they_require(tmp_path):
    from verify.coq.development import unit_levels

    texts = {"Cert_a.v": "From VerifyCoq Require Import QCert.\n",
             "Thm1_a.v": "From VerifyCoq Require QCert LTIHuman Cert_a.\n",
             "Cert_b.v": "(* Cert_a is named in a comment only *) Definition x := 1.\n",
             "Thm1_b.v": "From VerifyCoq Require Cert_b.\n"}
    for rel, text in texts.items():
        (tmp_path / rel).write_text(text)
    assert unit_levels(tmp_path, list(texts)) == [["Cert_a.v", "Cert_b.v"],
                                                  ["Thm1_a.v", "Thm1_b.v"]]
    (tmp_path / "Cert_a.v").write_text("From VerifyCoq Require Thm1_a.\n")  # a cycle
    assert unit_levels(tmp_path, list(texts)) == [["Cert_b.v"], ["Thm1_b.v"],
                                                  ["Cert_a.v", "Thm1_a.v"]]
