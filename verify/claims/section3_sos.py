"""Claims: the inequality steps of Lemma 1 and Theorem 1, re-proved by SOS certificates.

Each inequality step of the hand-written proofs (:mod:`verify.paper_proofs`, decoded from
their committed data) has an SOS twin (:mod:`verify.paper_proofs.sos_proofs`): the same
step justified by ``by_sos()``,
whose certificate the checker finds, rounds to rationals and checks exactly. The step
tables of the report mark which steps rest on hand terms, on SOS, or on both.
Certificates are reused from and written to the run's certificates directory, so a
second run (and ``verify certificates check``) needs no solver.
"""

from __future__ import annotations

from verify.claims.evidence import argument
from verify.claims.model import CheckContext, Outcome
from verify.claims.proofs import check_all, outcome_from
from verify.claims.registry import REGISTRY
from verify.claims.section3 import LEMMA, THEOREM
from verify.proof import certificate_store
from verify.sos.certificate import PAPER

METHOD = (
    "Each inequality step of the hand proof again, justified by by_sos(): a Gram-matrix "
    "SDP (cvxpy + Clarabel, untrusted) with multipliers k_s > 0, the assumptions the hand "
    "terms use and the spectral fact sym(A) - λmin(A) I ⪰ 0; rounded to rationals and "
    "checked exactly (identity of polynomials, exact LDLᵀ/dominance for every Gram "
    "block). Stored as verify-sos-certificate/1 JSON."
)


def _run(prefix: str, context: CheckContext, salt: int) -> Outcome:
    from verify.paper_proofs.sos_proofs import OUT_OF_REACH, sos_reproofs

    twins = [r for r in sos_reproofs() if r.original.startswith(prefix)]
    reachable = [r.derivation for r in twins if r.derivation.name not in OUT_OF_REACH]
    with certificate_store(context.certificates_dir, PAPER):
        results = check_all(reachable, context, salt)
    skipped = [r for r in twins if r.derivation.name in OUT_OF_REACH]
    proved = ", ".join(f"{r.original} step {r.step}" for r in twins
                       if r.derivation.name not in OUT_OF_REACH)
    finding = f"Re-proved by SOS certificates: {proved}."
    if skipped:
        finding += " Out of reach of the SOS search (left to the hand terms): " + "; ".join(
            f"{r.original} step {r.step} ({OUT_OF_REACH[r.derivation.name]})" for r in skipped
        ) + "."
    extra = tuple(
        argument(f"{r.original} step {r.step}: not attempted by SOS "
                 f"({OUT_OF_REACH[r.derivation.name]}); the hand proof stands.")
        for r in skipped
    )
    return outcome_from(results, finding, extra=extra)


@REGISTRY.claim(
    id="lemma1.sos-reproofs",
    section=LEMMA,
    paper_ref="Lemma 1 proof, every inequality",
    paper_says="ḣ ≥ k_s λmin(sym R_rl) tr(I - ξξᵀ) ≥ 0 on the boundary; the trace "
    "inequality.",
    statement="Every inequality step of the Lemma 1 derivations holds by an exact SOS "
    "certificate found without hand-written terms.",
    method=METHOD,
    scope="as the hand-written steps",
    paper_latex=(
        r"$\dot{h} \geq k_s \lambda_{\min}(\operatorname{sym} R_{rl}) "
        r"\operatorname{tr}(I - \xi \xi^{\top}) \geq 0$ on the boundary; the trace "
        "inequality."
    ),
)
def lemma1_sos(context: CheckContext) -> Outcome:
    return _run("lemma1.", context, 31)


@REGISTRY.claim(
    id="thm1.sos-reproofs",
    section=THEOREM,
    paper_ref="Theorem 1 proof, the inequalities of Ṡ_r, Ṡ_rl and V̇",
    paper_says="The bounds of Ṡ_r and Ṡ_rl, and V̇ ≤ 0.",
    statement="The inequality steps of the Theorem 1 derivations that the SOS search "
    "reaches hold by exact SOS certificates found without hand-written terms.",
    method=METHOD,
    scope="as the hand-written steps",
    paper_latex=r"The bounds of $\dot{S}_r$ and $\dot{S}_{rl}$, and $\dot{V} \leq 0$.",
)
def theorem1_sos(context: CheckContext) -> Outcome:
    return _run("thm1.", context, 32)
