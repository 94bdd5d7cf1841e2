"""Exact decision procedures reject wrong identities; the Section 2 verdicts; the runner."""

import sympy as sp

from verify.claims import CheckContext, Evidence, EvidenceKind, Outcome, Verdict, run_claims
from verify.claims.catalog import REGISTRY
from verify.claims.registry import ClaimRegistry
from verify.coq.development import coqc_available
from verify.symbolic import algebra as alg
from verify.symbolic.rational_network import RationalNetwork, nearly_antipodal_pair

EXPECTED = {
    "sec2.d-dot": Verdict.VERIFIED,
    "sec2.dbar-defined": Verdict.ASSUMPTION,
    "sec2.dbar-jacobian": Verdict.VERIFIED,
    "sec2.wtw-invertible": Verdict.REFUTED,
    "sec2.w-rank-two": Verdict.VERIFIED,
    "sec2.stealthiness": Verdict.REPAIRED,
    "sec2.projector": Verdict.REPAIRED,
    "sec2.dbar-dot": Verdict.REPAIRED,
    "sec2.dbar-stays-defined": Verdict.REFUTED,
    "sec3.rbar-e3": Verdict.REPAIRED,
    "lemma1.rodrigues-spectrum": Verdict.VERIFIED,
    "sec3.rbar-dot-form": Verdict.VERIFIED,
    "lemma1.h-dot": Verdict.VERIFIED,
    "lemma1.boundary": Verdict.VERIFIED,
    "lemma1.trace-inequality": Verdict.REFUTED,
    "lemma1.nagumo-gradient": Verdict.REPAIRED,
    # proved in Coq along every solution; re-checked only where coqc is installed
    "lemma1.invariance": Verdict.REPAIRED if coqc_available() else Verdict.ASSUMPTION,
    "thm1.phi": Verdict.VERIFIED,
    "thm1.storage-derivatives": Verdict.VERIFIED,
    "thm1.v-dot": Verdict.VERIFIED,
    "thm1.lasalle-derivative": Verdict.VERIFIED,
    # Theorem 1 with the certified k_s = 3.0 human, proved in Coq; re-checked with coqc
    "thm1.lasalle-storage": Verdict.REPAIRED if coqc_available() else Verdict.ASSUMPTION,
    "lemma1.premise-needed": Verdict.VERIFIED,
    "thm1.passivity-needed": Verdict.ASSUMPTION,
    "sec4.model-class": Verdict.VERIFIED,
    "sec4.nu-criterion": Verdict.REPAIRED,
    "sec4.reconstructed-models": Verdict.VERIFIED,
    "sec4.nu-curves-indices": Verdict.VERIFIED,
    "sec4.identification": Verdict.VERIFIED,
    "lemma1.sos-reproofs": Verdict.VERIFIED,
    "thm1.sos-reproofs": Verdict.VERIFIED,
}


def test_every_claim_gets_its_verdict_with_passing_evidence(tmp_path):
    run = run_claims(REGISTRY, CheckContext(quick=True, out_dir=tmp_path))  # figures go there
    got = {r.claim.id: r.outcome.verdict for r in run.results}
    assert got == EXPECTED
    for r in run.results:
        assert r.outcome.evidence, r.claim.id
        if r.outcome.verdict in (Verdict.VERIFIED, Verdict.REPAIRED):
            kinds = {e.kind for e in r.outcome.evidence}
            exact = {EvidenceKind.EXACT_IDENTITY, EvidenceKind.EXACT_INSTANCE,
                     EvidenceKind.DERIVATION, EvidenceKind.CERTIFICATE}
            assert kinds & exact, r.claim.id
            assert all(e.passed for e in r.outcome.evidence), r.claim.id
        if r.outcome.verdict is Verdict.REPAIRED:
            assert r.outcome.repaired_statement
        for e in r.outcome.evidence:
            if e.kind is EvidenceKind.FIGURE:
                assert (tmp_path / e.path).stat().st_size > 1000, r.claim.id
        if r.outcome.verdict is Verdict.REFUTED:
            assert any(
                e.kind is EvidenceKind.COUNTEREXAMPLE and e.passed for e in r.outcome.evidence
            ), r.claim.id


def test_rational_quaternion_rotation_is_exactly_orthogonal():
    R = alg.generic_rotation("q")
    assert alg.is_zero_matrix(R.T * R - sp.eye(3))
    assert alg.is_zero(R.det() - 1)


def test_exact_decision_rejects_mutated_identities():
    R = alg.generic_rotation("q")
    w = alg.vector_symbols("w")
    # the true identity R hat(e3) R^T = hat(R e3) and mutations of it
    assert alg.is_zero_matrix(R * alg.hat(alg.E3) * R.T - alg.hat(R * alg.E3))
    assert not alg.is_zero_matrix(R.T * alg.hat(alg.E3) * R - alg.hat(R * alg.E3))  # transpose
    assert not alg.is_zero_matrix(R * alg.hat(alg.E3) * R.T + alg.hat(R * alg.E3))  # sign
    assert not alg.is_zero_matrix(alg.hat(w) * alg.E3 - alg.hat(alg.E3) * w)  # d-dot sign


def test_root_modulo_decision_rejects_a_wrong_jacobian():
    s = alg.vector_symbols("s")
    ss = (s.T * s)[0, 0]
    r = sp.Symbol("r", positive=True)
    f = s / sp.sqrt(ss)
    right = (sp.eye(3) - s * s.T / ss) / sp.sqrt(ss)
    wrong = (sp.eye(3) - s * s.T / (2 * ss)) / sp.sqrt(ss)  # a dropped factor
    assert all(
        alg.is_zero_modulo_root(e, r, ss) for e in (f.jacobian(s) - right).subs(sp.sqrt(ss), r)
    )
    assert not all(
        alg.is_zero_modulo_root(e, r, ss) for e in (f.jacobian(s) - wrong).subs(sp.sqrt(ss), r)
    )


def test_exact_instances_show_singular_gram_and_rank_two():
    for net in (RationalNetwork.of([(1, 2, 3, 4), (2, -1, 0, 1)]), nearly_antipodal_pair(10**9)):
        assert net.gram.det() == 0
        assert net.w_unscaled.rank() == 2
        assert (net.w_unscaled * net.direction_sum).is_zero_matrix
        A = net.projector
        assert (A * A - A).is_zero_matrix and (A - A.T).is_zero_matrix
        # the stealthy identity with the exact (unscaled) Jacobian
        assert (net.jacobian_unscaled * net.s_matrix * A).is_zero_matrix


def test_exact_projector_from_a_wrong_formula_is_not_stealthy():
    net = RationalNetwork.of([(1, 2, 3, 4), (2, -1, 0, 1), (3, 0, 1, 1)])
    W = net.w_unscaled
    # the paper's formula with a naive fix (adding I instead of dbar dbar^T) is wrong
    wrong = sp.eye(3 * net.n) - W * (net.gram + sp.eye(3)).inv() * W.T
    assert not (net.jacobian_unscaled * net.s_matrix * wrong).is_zero_matrix


def _register(reg, claim_id):
    labels = dict.fromkeys(
        ("section", "paper_ref", "paper_says", "statement", "method", "scope"), "-"
    )
    return reg.claim(id=claim_id, **labels)


def test_runner_turns_a_crashing_check_into_inconclusive():
    reg = ClaimRegistry()

    @_register(reg, "x.crash")
    def crash(ctx):
        raise RuntimeError("boom")

    @_register(reg, "x.wrong-type")
    def wrong_type(ctx):
        return True

    @_register(reg, "x.ok")
    def ok(ctx):
        return Outcome(Verdict.VERIFIED, "fine", (Evidence(EvidenceKind.EXACT_IDENTITY, "e"),))

    run = run_claims(reg, CheckContext())
    verdicts = [r.outcome.verdict for r in run.results]
    assert verdicts == [Verdict.INCONCLUSIVE, Verdict.INCONCLUSIVE, Verdict.VERIFIED]
    assert "boom" in run.results[0].outcome.finding
    assert not run.all_verified()
