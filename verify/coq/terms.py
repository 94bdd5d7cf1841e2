"""Coq text of the proof language's expressions, written with the prelude ``SO3.v``.

Each operation of :mod:`verify.proof.expr` has one counterpart in the prelude (paper,
Section 3): ``tr``, ``sk``, ``sym``, ``hat``, ``vee``, ``vdot``, ``outer``, ``mmul``,
``mT``, ``madd``, ``mscale``, ``I3``; ``phi`` (Theorem 1's energy function) is printed
as ``phi`` when the tree has its shape, (1/2) tr(I - R). Variables are printed by the
Coq names a :class:`Naming` gives them; lambda_min(A) is printed as the real variable
that stands for it (its hypothesis ``lam_min_spec A lam`` is declared by the section).
"""

from __future__ import annotations

from fractions import Fraction

from verify.coq.text import ascii_spelling, generated_identifier
from verify.coq.unit import CoqExportError, comment_text
from verify.proof.expr import (
    MATRIX,
    SCALAR,
    VECTOR,
    Expr,
    Variable,
    postorder,
    structural_key,
)

# Names the prelude or Coq's standard library already use.
RESERVED = frozenset("""
R V3 M3 mkV mkM v1 v2 v3 m11 m12 m13 m21 m22 m23 m31 m32 m33 vadd vneg vscale vzero vdot
madd mscale mneg msub mmul mvmul mT I3 Z3 tr outer symm sk sym hat vee phi fro2 det quat
mkQ qw qx qy qz qvec qn rot row1 row2 row3 qform psd pd lam_min_spec cos sin sqrt exp
PI Set Prop Type fun forall exists let in match end with as Theorem Lemma Proof Qed
Section End Variable Variables Hypothesis Let Definition Notation Local step
""".split())



def ascii_identifier(text: str) -> str:
    """A Coq identifier spelling ``text`` in ASCII (Greek letters by name, R̄ as Rbar)."""
    name = ascii_spelling(text)
    if not name or not name[0].isalpha():
        name = "x" + name
    return name


class Naming:
    """Coq names of the variables and lambda_min atoms of one exported section."""

    def __init__(self) -> None:
        self.used: set[str] = set()
        self.names: dict[int, str] = {}
        self.lambdas: dict[tuple, tuple[str, Expr]] = {}

    def fresh(self, base: str) -> str:
        name = base if base not in RESERVED else base + "_v"
        k = 2
        candidate = name
        while candidate in self.used or candidate in RESERVED:
            candidate = f"{name}_{k}"
            k += 1
        self.used.add(candidate)
        return candidate

    def variable(self, v: Variable) -> str:
        """``v_<n>_<hint>`` (:func:`verify.coq.text.generated_identifier`): the n-th
        variable named, never the file's name itself."""
        if v.uid not in self.names:
            name = generated_identifier("v", len(self.names) + 1, v.name)
            self.used.add(name)
            self.names[v.uid] = name
        return self.names[v.uid]

    def lambda_atom(self, node: Expr) -> str:
        key = structural_key(node.args[0])
        if key not in self.lambdas:
            self.lambdas[key] = (self.fresh(f"lam{len(self.lambdas) + 1}"), node.args[0])
        return self.lambdas[key][0]


#: Bits of a constant's numerator or denominator the exporter writes (as the checker's
#: size limits, :data:`verify.proof.size.MAX_CONSTANT_BITS`).
MAX_CONSTANT_BITS = 8192
#: Characters of one Coq term the exporter writes (shared subtrees counted each time).
MAX_TERM_CHARS = 400_000


def constant(c: Fraction) -> str:
    if max(c.numerator.bit_length(), c.denominator.bit_length()) > MAX_CONSTANT_BITS:
        raise CoqExportError(f"a constant has more than {MAX_CONSTANT_BITS} bits: too long "
                             "for the exporter")
    if c.denominator == 1:
        return str(c.numerator) if c >= 0 else f"({c.numerator})"
    return f"({c.numerator}/{c.denominator})"


def _is_phi(e: Expr) -> Expr | None:
    """R when ``e`` is (1/2) * tr(I - R) as :func:`verify.proof.expr.phi` builds it."""
    if (e.op == "scale" and e.args[0].op == "const" and e.args[0].data == Fraction(1, 2)
            and e.args[1].op == "trace"):
        inner = e.args[1].args[0]
        if inner.op == "add" and inner.args[0].op == "identity" and inner.args[1].op == "neg":
            return inner.args[1].args[0]
    return None


def coq_text(e: Expr, naming: Naming, *, use_phi: bool = True,
             bound: dict[int, str] | None = None) -> str:
    """The Coq term of ``e``, built children first without recursion (so depth is not
    limited by Python's stack); refused (:class:`CoqExportError`) when the written term
    would exceed :data:`MAX_TERM_CHARS` characters (a shared subtree is written once per
    occurrence, so its length is counted once per occurrence, before any text is made).

    ``bound``: subtrees (by ``id``) written as the ``let`` names given
    (:func:`let_bindings`)."""
    bound = bound or {}
    length: dict[int, int] = {}
    order = postorder(e)
    for node in order:
        length[id(node)] = (len(bound[id(node)]) if id(node) in bound and node is not e
                            else 16 + sum(length[id(a)] for a in node.args))
        if length[id(node)] > MAX_TERM_CHARS:
            raise CoqExportError(f"a term would be more than {MAX_TERM_CHARS} characters "
                                 "of Coq (shared subterms written out)")
    memo: dict[int, str] = {}
    for node in order:
        if id(node) in bound and node is not e:
            memo[id(node)] = bound[id(node)]
        else:
            memo[id(node)] = _node(node, lambda x: memo[id(x)], naming, use_phi)
    return memo[id(e)]


#: A statement longer than this (characters) names its long shared subterms with ``let``.
LET_STATEMENT_CHARS = 4000
#: A shared subterm is let-bound when its own text is at least this long.
LET_MIN_CHARS = 120


def let_bindings(exprs: list[Expr], naming: Naming) -> tuple[list[tuple[str, str]],
                                                             dict[int, str]]:
    """``let`` names for the shared subterms of ``exprs`` (non-leaf nodes used more than
    once whose text is at least :data:`LET_MIN_CHARS`), each written once: the
    definitions in order (each uses only earlier names) and the map ``id -> name``."""
    uses: dict[int, int] = {}
    for node in postorder(*exprs):
        for a in node.args:
            uses[id(a)] = uses.get(id(a), 0) + 1
    bound: dict[int, str] = {}
    lets: list[tuple[str, str]] = []
    for node in postorder(*exprs):
        if node.args and uses.get(id(node), 0) > 1:
            text = coq_text(node, naming, bound=bound)
            if len(text) >= LET_MIN_CHARS:
                name = f"s_{len(lets) + 1}"
                lets.append((name, text))
                bound[id(node)] = name
    return lets, bound


def _node(e: Expr, go, naming: Naming, use_phi: bool) -> str:
    op, a, shape = e.op, e.args, e.shape
    if op == "var":
        return naming.variable(e.data)
    if op == "const":
        return constant(e.data)
    if op == "identity":
        return "I3"
    if op == "zero":
        return {SCALAR: "0", VECTOR: "vzero", MATRIX: "Z3"}[shape]
    if op == "lambda_min":
        return naming.lambda_atom(e)
    if op in ("cos", "sin"):
        return f"({op} {go(a[0])})"
    if use_phi and (r := _is_phi(e)) is not None:
        return f"(phi {go(r)})"
    if op == "add":
        if shape == SCALAR:
            return f"({go(a[0])} + {go(a[1])})"
        return f"({'vadd' if shape == VECTOR else 'madd'} {go(a[0])} {go(a[1])})"
    if op == "neg":
        if shape == SCALAR:
            return f"(- {go(a[0])})"
        return f"({'vneg' if shape == VECTOR else 'mneg'} {go(a[0])})"
    if op == "scale":
        if shape == SCALAR:
            return f"({go(a[0])} * {go(a[1])})"
        return f"({'vscale' if shape == VECTOR else 'mscale'} {go(a[0])} {go(a[1])})"
    if op == "matmul":
        return f"({'mvmul' if shape == VECTOR else 'mmul'} {go(a[0])} {go(a[1])})"
    unary = {"transpose": "mT", "trace": "tr", "sk": "sk", "sym": "sym", "hat": "hat",
             "vee": "vee"}
    if op in unary:
        return f"({unary[op]} {go(a[0])})"
    if op == "dot":
        return f"(vdot {go(a[0])} {go(a[1])})"
    if op == "outer":
        return f"(outer {go(a[0])} {go(a[1])})"
    raise CoqExportError(f"no Coq counterpart for the operation {op!r}")


#: How each kind of declared assumption reads as a Coq proposition about its term.
ASSUMPTION_STATEMENTS = {"pos": "0 < {}", "nonneg": "0 <= {}", "pd": "pd {}", "psd": "psd {}"}


def assumption_hypothesis(name: str, assumption, naming: Naming) -> list[str]:
    """A paper assumption (``pos``, ``nonneg``, ``pd`` or ``psd`` of an expression) as a
    named ``Hypothesis``, its label and citation in a comment above it."""
    statement = ASSUMPTION_STATEMENTS[assumption.kind].format(coq_text(assumption.expr, naming))
    cite = f" ({comment_text(assumption.cite)})" if assumption.cite else ""
    return [f"(** assumption: {comment_text(assumption.label)}{cite} *)",
            f"Hypothesis {name} : {statement}.", ""]

