"""The claims' ids and paper references, written out so ``verify list`` loads no check.

``verify list`` prints this table instead of importing every module of checks (which
loads sympy, cvxpy, numba and scipy.stats: about 5 s against under 1 s;
``benchmarks/bench_startup.py``). It is generated from the registry
(:mod:`verify.claims.catalog`) by ``python -m verify.claims.index``, and
``tests/test_claim_index.py`` fails when the two differ, naming that command.
"""

# ruff: noqa: E501  (generated rows, one claim per line)
from __future__ import annotations

#: (claim id, where in the paper), in the registry's order.
CLAIMS: tuple[tuple[str, str], ...] = (
    ('sec2.d-dot', 'Section 2, d-dot = S(d) Omega'),
    ('sec2.dbar-defined', 'Section 2, definition of dbar'),
    ('sec2.dbar-jacobian', 'Section 2, d dbar / d d in W(d) and eq. (3)'),
    ('sec2.wtw-invertible', 'Section 2, A(d) = I - W (W^T W)^{-1} W^T'),
    ('sec2.w-rank-two', 'Section 2, W(d) (needed by the repair)'),
    ('sec2.stealthiness', 'Section 2, eq. (3)'),
    ('sec2.projector', 'Section 2, A(d)'),
    ('sec2.dbar-dot', 'Section 2, eq. (2)-(3); Section 3 first paragraph'),
    ('sec2.dbar-stays-defined', 'Section 2 (eq. (3)) and Section 3 (R-bar e3 = dbar)'),
    ('sec3.rbar-e3', 'Section 3, eq. (4) and the sentence after it'),
    ('lemma1.rodrigues-spectrum', 'Lemma 1 proof, eq. (14)'),
    ('sec3.rbar-dot-form', 'eqs. (9), (12a), (13)'),
    ('lemma1.h-dot', 'Lemma 1 proof, eq. (15)'),
    ('lemma1.boundary', 'Lemma 1 proof, boundary argument'),
    ('lemma1.trace-inequality', 'Lemma 1 proof, property cited from Hatanaka et al. (2015)'),
    ('lemma1.nagumo-gradient', 'Lemma 1 proof, Nagumo premise'),
    ('lemma1.invariance', 'Lemma 1, conclusion'),
    ('thm1.phi', 'Theorem 1 proof, definition of φ'),
    ('thm1.storage-derivatives', 'Theorem 1 proof, Ṡ_r and Ṡ_rl chains, S_h'),
    ('thm1.v-dot', 'Theorem 1 proof, eq. (17)'),
    ('thm1.lasalle-derivative', 'Theorem 1 proof, LaSalle step'),
    ('thm1.lasalle-storage', "Theorem 1 proof, LaSalle's principle"),
    ('lemma1.premise-needed', 'Lemma 1 with Assumption 1, item 2'),
    ('thm1.passivity-needed', 'Theorem 1 with Assumption 1, item 5'),
    ('lemma1.sos-reproofs', 'Lemma 1 proof, every inequality'),
    ('thm1.sos-reproofs', 'Theorem 1 proof, the inequalities of Ṡ_r, Ṡ_rl and V̇'),
    ('sec4.model-class', 'Section 4, human model structure'),
    ('sec4.nu-criterion', 'Section 4, passivity analysis'),
    ('sec4.reconstructed-models', 'Section 4, identified models for k_s = 2.5 and 3.0'),
    ('sec4.nu-curves-indices', 'Section 4, passivity analysis (figures of nu(w) and Bode diagrams)'),
    ('sec4.identification', 'Section 4, Human Modeling (identification from the VR experiment)'),
)


def render() -> str:
    """This module's source, regenerated from the full registry."""
    from pathlib import Path

    from verify.claims.catalog import REGISTRY

    text = Path(__file__).read_text(encoding="utf-8")
    head, rest = text.split("CLAIMS: tuple[tuple[str, str], ...] = (\n", 1)
    tail = rest.split("\n)\n", 1)[1]
    rows = "".join(f"    ({c.id!r}, {c.paper_ref!r}),\n" for c in REGISTRY)
    return f"{head}CLAIMS: tuple[tuple[str, str], ...] = (\n{rows})\n{tail}"


def main() -> None:
    """Rewrite this module from the registry (after adding or renaming a claim)."""
    from pathlib import Path

    from verify.artefacts.atomic import write_atomic

    write_atomic(Path(__file__), render())
    print(f"wrote {Path(__file__)} ({len(CLAIMS)} claims before)")


if __name__ == "__main__":
    main()
