"""Inequalities over SO(3) proved by SOS certificates (``verify check`` this file).

No hand-written non-negative terms: each step says ``by_sos()`` and the checker finds a
sum-of-squares certificate of the slack, rounds it to rationals and checks it exactly;
the certificate is written to ``certificates/`` (``--certificates DIR`` to change) and
reused on the next run.
"""

from verify.proof import (
    I3,
    Context,
    Derivation,
    by_sos,
    dot,
    lambda_min,
    sk,
    sym,
    tr,
    vee,
)

ctx = Context("SOS over SO(3)")
R, R1, R2 = ctx.rotation("R"), ctx.rotation("R₁"), ctx.rotation("R₂")
A = ctx.symmetric("A")
k = ctx.scalar("k", positive=True)
c = ctx.scalar("c")
c_nonneg = ctx.assume("c ≥ 0", c, "nonneg")

DERIVATIONS = [
    Derivation("trace at most 3", tr(R), ctx, statement="tr R ≤ 3").le(3, by_sos()),
    Derivation("trace at least -1", tr(R), ctx, statement="tr R ≥ -1").ge(-1, by_sos()),
    Derivation("axis part", dot(vee(sk(R)), vee(sk(R))), ctx,
               statement="|sk(R)^∨|² ≤ 3 - tr R").le(3 - tr(R), by_sos()),
    Derivation("relative trace", tr(R1.T * R2), ctx,
               statement="tr(R₁ᵀR₂) ≥ -1").ge(-1, by_sos()),
    Derivation("gain", k * tr(I3 - R1 * R2), ctx,
               statement="k tr(I - R₁R₂) ≥ 0 for k > 0").ge(0, by_sos()),
    Derivation("assumed sign", c * (1 + tr(R)), ctx,
               statement="c (1 + tr R) ≥ 0 when c ≥ 0").ge(0, by_sos(c_nonneg)),
    Derivation("gradient norm", (3 - tr(R)) * (1 + tr(R)), ctx,
               statement="(3 - tr R)(1 + tr R) ≥ 0").ge(0, by_sos()),
    Derivation("trace bound", tr(A * sym(I3 - R)), ctx,
               statement="tr(A sym(I - R)) ≥ λmin(A) tr(I - R)").ge(
        lambda_min(A) * tr(I3 - R), by_sos()),
]
