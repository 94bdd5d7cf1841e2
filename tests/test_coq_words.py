"""KYP units on machine words (QCert.kyp_wcheck): the literals, the integer witnesses,
and the audit that allows Coq's primitive integers for those units only."""

from __future__ import annotations

import random
import re
from fractions import Fraction

from gmpy2 import mpq

from verify.coq.audit import MACHINE_INTEGER_AXIOMS, audit_assumptions
from verify.coq.development import WORD_THEOREMS, render_development
from verify.coq.kyp import LIMB_BITS, word_literal, word_matrix
from verify.coq.unit import CoqUnit


def decode(lit: str) -> tuple[int, bool]:
    """(value, second denominator) of a ``wnum`` literal, as QCert.wZ reads it."""
    m = re.fullmatch(r"\(W([pn]) (\d+)\)", lit)
    if m:
        return (int(m.group(2)) if m.group(1) == "p" else -int(m.group(2))), False
    m = re.fullmatch(r"\(Wl (true|false) (true|false) \[([\d; ]*)\]\)", lit)
    assert m, lit
    limbs = [int(w) for w in m.group(3).split(";") if w.strip()]
    assert all(0 <= w < 1 << LIMB_BITS for w in limbs)
    value = sum(w << (LIMB_BITS * k) for k, w in enumerate(limbs))
    return (-value if m.group(1) == "true" else value), m.group(2) == "true"


def test_word_literals_stand_for_the_integer():
    rng = random.Random(5)
    for bits in (0, 1, 40, 61, 62, 63, 124, 125, 300):
        for _ in range(20):
            x = rng.randrange(-(1 << bits), (1 << bits) + 1)
            for second in (False, True):
                assert decode(word_literal(x, second)) == (x, second)


def test_a_word_matrix_is_the_rational_matrix_times_its_scale():
    rng = random.Random(7)
    for _ in range(30):
        rows = [[mpq(Fraction(rng.randrange(-10**6, 10**6), rng.choice(
            [1, 2**11, 2**60, 3**40 * 2**5]))) for _ in range(4)] for _ in range(3)]
        wm = word_matrix(rows)
        lits = re.findall(r"\(W[pnl][^()]*\)", wm.text)
        assert len(lits) == 12
        for k, lit in enumerate(lits):
            num, second = decode(lit)
            x = rows[k // 4][k % 4]
            assert mpq(num, wm.d2 if second else wm.d1) == x
            assert wm.scaled[k // 4][k % 4] == x * wm.scale


BLOCKS = """Axioms:
ClassicalDedekindReals.sig_forall_dec : forall P : nat -> Prop, True
Axioms:
ClassicalDedekindReals.sig_forall_dec : forall P : nat -> Prop, True
Uint63.mulc_spec : forall x y : int, True
PrimInt63.int : Set
"""


def test_machine_integers_are_allowed_for_the_word_theorems_only():
    assert {"PrimInt63.mulc", "Uint63.mulc_spec"} <= MACHINE_INTEGER_AXIOMS
    assert audit_assumptions(BLOCKS, word_block=True).ok
    plain = audit_assumptions(BLOCKS)
    assert not plain.ok and plain.disallowed == ("PrimInt63.int", "Uint63.mulc_spec")
    first = "Axioms:\nUint63.mulc_spec : t\nAxioms:\nPrimInt63.int : Set\n"
    assert not audit_assumptions(first, word_block=True).ok  # in the other block


def test_all_v_prints_the_word_theorems_last_and_apart():
    plain = CoqUnit("Plain", "Theorem t : True. Proof. exact I. Qed.\n", ("t",))
    words = CoqUnit("Words", "Theorem passive : True. Proof. exact I. Qed.\n", ("passive",),
                    machine_words=True)
    all_v = render_development([words, plain])["All.v"]
    assert all_v.index("Print Assumptions top_theorems.") < all_v.index(
        f"Print Assumptions {WORD_THEOREMS}.")
    assert "Plain.t" in all_v.split("Print Assumptions top_theorems.")[0]
    assert "Words.passive" in all_v.split("Print Assumptions top_theorems.")[1]
