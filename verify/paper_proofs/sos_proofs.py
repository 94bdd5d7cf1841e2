"""The inequality steps of Lemma 1 and Theorem 1 again, each proved by ``by_sos()``.

The hand-written derivations (:mod:`verify.paper_proofs.lemma1`, ``theorem1``) justify
each inequality by named non-negative terms. Here every such step becomes a one-step
derivation with the same context, side conditions, left and right sides, justified by
an SOS certificate found by the checker instead; the assumptions the hand terms use
(Lemma 1's sign, Assumption 1 item 2) are offered to ``by_sos`` as multipliers. A step
the SOS search cannot reach comes out *inconclusive* and is listed as such; the hand
proof stands either way.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from verify.paper_proofs import lemma1, theorem1
from verify.proof import Derivation, by_sos
from verify.proof.justify import ByBound


@dataclass(frozen=True)
class SosReproof:
    """The SOS twin of step ``step`` (1-based) of the hand derivation ``original``."""

    original: str
    step: int
    derivation: Derivation


def hand_derivations() -> list[Derivation]:
    """Every derivation of Lemma 1 and Theorem 1 that has an inequality step, decoded
    from the committed data (:mod:`verify.paper_proofs.data`) as ``verify all`` checks
    them."""
    from verify.paper_proofs.data import derivations

    out = [d for group in ("lemma1.boundary", "lemma1.trace_inequality", "theorem1.storage",
                           "theorem1.v_dot") for d in derivations(group)]
    return [d for d in out if any(s.relation != "=" for s in d.steps)]


def python_hand_derivations() -> list[Derivation]:
    """The same derivations built by the Python of the paper's proofs (the front end)."""
    loop = theorem1.ClosedLoop()
    out = (lemma1.boundary() + lemma1.trace_inequality()
           + theorem1.s_r_dot(loop) + theorem1.s_rl_dot(loop) + theorem1.v_dot(loop))
    return [d for d in out if any(s.relation != "=" for s in d.steps)]


def sos_reproofs() -> list[SosReproof]:
    out = []
    for d in hand_derivations():
        for k, s in enumerate(d.steps, start=1):
            if s.relation == "=" or not isinstance(s.because, ByBound):
                continue
            used = []
            for t in s.because.terms:
                used += [a for a in t.assumptions if a not in used]
            twin = Derivation(f"{d.name}.step{k}-sos", s.lhs, d.context,
                              where=tuple(d.where) + tuple(s.where), assumes=d.assumes,
                              statement=f"step {k} of {d.name}, proved by an SOS certificate",
                              cite=d.cite)
            add = twin.le if s.relation == "<=" else twin.ge
            add(s.rhs, by_sos(*used, note=f"SOS re-proof of step {k}"))
            out.append(SosReproof(d.name, k, twin))
    return out


OUT_OF_REACH = {
    "thm1.V-dot.step2-sos": "Gram order 372 over 15 parameters, degree 12 (the two trace "
    "bounds at once); measured: Clarabel fails after about 2 minutes",
    "thm1.V-dot-zero-implies-sync.step1-sos": "the same program as thm1.V-dot step 2",
}


def program_for_key(key: str, statement: str | None = None):
    """The re-derived SOS program of the paper's by_sos step with this claim key, or None.

    ``statement`` (the certificate's text of the step) only says which steps to rebuild
    first; the match is on the key of the re-derived program, so a certificate whose
    statement was edited is still bound to its step (and then refused as edited).
    """
    from verify.proof.checker import step_problem
    from verify.proof.sos_step import step_program
    from verify.sos.certificate import claim_key

    reproofs = sos_reproofs()

    def written(r: SosReproof) -> bool:
        step = r.derivation.steps[0]
        return f"{step.lhs} {step.relation} {step.rhs}" == statement

    # the steps whose text is the certificate's first: one is usually the match
    for r in sorted(reproofs, key=lambda r: not written(r)):
        d = r.derivation
        step = d.steps[0]
        sp = step_program(step_problem(d, step), step.because)
        if claim_key(sp) == key:
            # the paper's labels are this package's own: written and reported with them
            return dataclasses.replace(sp, statement=sp.labelled)
    return None


__all__ = ["OUT_OF_REACH", "SosReproof", "hand_derivations", "program_for_key",
           "python_hand_derivations", "sos_reproofs"]
