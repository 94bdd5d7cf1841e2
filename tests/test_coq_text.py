"""The Coq text layer: file text is inert in comments, identifiers are generated."""

from __future__ import annotations

import re

import pytest
from hypothesis import given
from hypothesis import strategies as st

from verify.coq.audit import strip_comments
from verify.coq.text import (
    MAX_COMMENT_CHARS,
    RESERVED_MODULES,
    generated_identifier,
    inert_comment,
    module_identifier,
)
from verify.coq.unit import comment_text

#: Template characters that may stand beside inert text in a ``.v`` file.
_BESIDE = ["(** ", "(", "*", ")", " *)", ""]


@given(st.text(max_size=300))
def test_inert_text_is_one_comment_whatever_stands_beside_it(text):
    inert = inert_comment(text)
    assert "(*" not in inert and "*)" not in inert and '"' not in inert
    assert all(ch == " " or ch.isprintable() for ch in inert)
    inert.encode("utf-8")  # no lone surrogate
    if not inert:
        return
    for left in _BESIDE:
        for right in _BESIDE:
            markers = [left.count(m) + right.count(m) for m in ("(*", "*)")]
            joined = f"{left}{inert}{right}"
            assert [joined.count(m) for m in ("(*", "*)")] == markers
            source = f"(** {inert} *)\nTheorem t : True."
            assert strip_comments(source).strip() == "Theorem t : True."


@pytest.mark.parametrize("text", [
    "x*) Axiom cheat : False. (*", '"', "*note", "note(", "(*)", "\ud800", "a\nb", "\u202e",
])
def test_hostile_text_is_made_inert(text):
    inert = inert_comment(text)
    assert "(*" not in f"({inert})" and "*)" not in f"({inert})" and '"' not in inert
    assert comment_text(text) == inert


def test_long_text_is_cut_and_hashed():
    long = "9" * 5001
    inert = inert_comment(long)
    assert len(inert) <= MAX_COMMENT_CHARS + 40
    assert re.search(r"\[sha256:[0-9a-f]{16}\]$", inert)
    assert inert != inert_comment("9" * 5002)


def test_plain_text_is_kept():
    assert inert_comment("tr(R̄_r) = 1 + 2 cos(θ)") == "tr(R̄_r) = 1 + 2 cos(θ)"


@pytest.mark.parametrize("name", ["step1", "claim", "k_pos", "q_x", "E", "T1", "if",
                                  "le_by_slack", "Admitted", "using", "R", "", "*)", "ü"])
def test_generated_identifiers_are_never_the_file_name(name):
    ident = generated_identifier("v", 3, name)
    assert re.fullmatch(r"v_3_[A-Za-z0-9_]+", ident)
    assert ident != name


def test_generated_identifiers_are_distinct_by_index():
    assert generated_identifier("v", 1, "x_2") != generated_identifier("v", 2, "x")
    with pytest.raises(ValueError):
        generated_identifier("V", 1, "x")
    with pytest.raises(ValueError):
        generated_identifier("v", 0, "x")


@pytest.mark.parametrize("name", ["SO3", "All", "so3", "QCert", "Reals", "Theorem",
                                  "Proof", "d_1_x", "x", "*)"])
def test_module_names_never_collide_with_the_prelude(name):
    taken: set[str] = set()
    module = module_identifier(name, taken)
    assert module.casefold() not in RESERVED_MODULES
    assert re.fullmatch(r"[a-z][A-Za-z0-9]*_[A-Za-z0-9_]*", module)
    again = module_identifier(name, taken)
    assert again.casefold() != module.casefold()


def test_paper_module_names_are_kept():
    assert module_identifier("lemma1.trace-form", set()) == "lemma1_trace_form"
    assert module_identifier("thm1.V-dot", set()) == "thm1_V_dot"


def test_every_prelude_module_name_is_reserved():
    """A unit named like a prelude module would shadow it in the development."""
    from verify.coq.development import PRELUDE_ORDER
    from verify.coq.text import RESERVED_MODULES

    assert {name.casefold() for name in PRELUDE_ORDER} <= RESERVED_MODULES
