"""A proof checker for derivations over SO(3) (Lemma 1 and Theorem 1 of Section 3).

Write a derivation in Python with :class:`Context` and :class:`Derivation`, justify
each step (:func:`by_algebra`, :func:`by_bound` with non-negative terms such as
:func:`trace_lower_bound`, :func:`by_sos` with an exact sum-of-squares certificate, or
:func:`by_citation`), and decide it with :func:`check`.
The paper's Lemma 1 and Theorem 1 are written this way in :mod:`verify.paper_proofs`.
What a "verified" rests on (the exact kernel, the charts and how their missing points
are covered, what a derivation file can and cannot do) is in ``verify/proof/TRUSTED.md``.
"""

from verify.proof.checker import DerivationResult, ProofVerdict, StepResult, check
from verify.proof.derivation import Context, Derivation
from verify.proof.expr import (
    I3,
    ProofSyntaxError,
    VariableKind,
    cos,
    dot,
    fro2,
    hat,
    lambda_min,
    outer,
    phi,
    rodrigues,
    sin,
    sk,
    substitute,
    sym,
    tr,
    vee,
)
from verify.proof.falsify import SearchSettings
from verify.proof.hypotheses import Assumption, Condition
from verify.proof.justify import (
    KERNEL,
    Nonneg,
    assumed,
    by_algebra,
    by_bound,
    by_citation,
    by_sos,
    positive,
    square,
    trace_lower_bound,
    trace_psd_product,
)
from verify.proof.sos_step import certificate_store

__all__ = [
    "I3",
    "KERNEL",
    "Assumption",
    "Condition",
    "Context",
    "Derivation",
    "DerivationResult",
    "Nonneg",
    "ProofSyntaxError",
    "ProofVerdict",
    "SearchSettings",
    "StepResult",
    "VariableKind",
    "assumed",
    "by_algebra",
    "by_bound",
    "by_citation",
    "by_sos",
    "certificate_store",
    "check",
    "cos",
    "dot",
    "fro2",
    "hat",
    "lambda_min",
    "outer",
    "phi",
    "positive",
    "rodrigues",
    "sin",
    "sk",
    "square",
    "substitute",
    "sym",
    "tr",
    "trace_lower_bound",
    "trace_psd_product",
    "vee",
]
