"""Lemma 1 of the paper (Section 3): tr(R-bar_r) >= 1 is forward invariant (Nagumo).

Each function returns derivations in the proof language, one per group of steps of the
paper's proof, in the paper's order. Steps follow the paper; where the paper's
justification is not enough, the step carries the premise that is (and the report says
so). Notation: R-bar_r = R_r^T R-bar, R_rl = R_r^T R_l, h = tr(R-bar_r) - 1.
"""

from __future__ import annotations

from fractions import Fraction

from verify.proof import (
    I3,
    Context,
    Derivation,
    assumed,
    by_algebra,
    by_bound,
    by_citation,
    cos,
    dot,
    hat,
    lambda_min,
    outer,
    positive,
    rodrigues,
    sin,
    sk,
    square,
    sym,
    tr,
    trace_lower_bound,
    trace_psd_product,
    vee,
)

HALF = Fraction(1, 2)
QUARTER = Fraction(1, 4)


def rodrigues_spectrum() -> list[Derivation]:
    """Eigenvalues of R + R^T are {2, 2cos t, 2cos t}; tr R = 1 + 2 cos t (eq. (14))."""
    ctx = Context("Lemma 1, Rodrigues form")
    xi, theta = ctx.unit_vector("ξ"), ctx.angle("θ")
    R = rodrigues(xi, theta).named("R̄_r")
    P = outer(xi, xi).named("ξξᵀ")
    spectral = Derivation(
        "lemma1.spectrum",
        R + R.T,
        ctx,
        statement="R + Rᵀ = 2 ξξᵀ + 2cosθ (I - ξξᵀ): eigenvalue 2 on ξ, 2cosθ twice on ξ⊥",
        cite="Lemma 1 proof, eigenvalues {2, 2cosθ, 2cosθ}",
    ).equals(2 * P + 2 * cos(theta) * (I3 - P), by_algebra("Rodrigues, |ξ| = 1"))
    projector = Derivation(
        "lemma1.spectrum-projector",
        P * P,
        ctx,
        statement="ξξᵀ is an orthogonal projector of rank tr(ξξᵀ) = 1",
        cite="Lemma 1 proof, eigenvalues",
    ).equals(P, by_algebra("|ξ| = 1"))
    rank = Derivation("lemma1.spectrum-rank", tr(P), ctx,
                      statement="rank of ξξᵀ is 1", cite="Lemma 1 proof").equals(
        1, by_algebra("|ξ| = 1"))
    trace = Derivation(
        "lemma1.trace-form",
        tr(R),
        ctx,
        statement="tr(R̄_r) = 1 + 2cosθ, so R̄_r + R̄_rᵀ ⪰ 0 ⟺ cosθ ≥ 0 ⟺ tr(R̄_r) ≥ 1",
        cite="Lemma 1 proof, eq. (14)",
    ).equals(1 + 2 * cos(theta), by_algebra("Rodrigues"))
    return [spectral, projector, rank, trace]


def closed_loop_context():
    """R_r constant, R-bar-dot = k_s R-bar sk(R-bar^T R_l) (eq. (13)), R_l free."""
    ctx = Context("Lemma 1, closed loop")
    Rr, Rb, Rl = ctx.rotation("R_r"), ctx.rotation("R̄"), ctx.rotation("R_l")
    ks = ctx.scalar("k_s", positive=True)
    ctx.constant(Rr)
    ctx.dynamics(Rb, ks * Rb * sk(Rb.T * Rl))
    return ctx, Rr, Rb, Rl, ks


def h_dot() -> list[Derivation]:
    """The chain for h-dot, eq. (15)."""
    ctx, Rr, Rb, Rl, ks = closed_loop_context()
    Rbr = (Rr.T * Rb).named("R̄_r")
    Rrl = (Rr.T * Rl).named("R_rl")
    h = tr(Rbr) - 1
    d = Derivation(
        "lemma1.h-dot",
        ctx.ddt(h).named("ḣ"),
        ctx,
        statement="ḣ = (k_s/2) tr(R_rl - R_rlᵀ R̄_r²) along eq. (13)",
        cite="Lemma 1 proof, eq. (15)",
    )
    d.equals(tr(ctx.ddt(Rbr).named("(d/dt R̄_r)")), by_algebra("h = tr(R̄_r) - 1, R_r constant"))
    d.equals(ks * tr(Rr.T * Rb * sk(Rb.T * Rl)), by_algebra("eq. (13)"))
    d.equals(ks * tr(Rbr * sk(Rbr.T * Rrl)), by_algebra("R̄ᵀR_l = R̄_rᵀR_rl"))
    d.equals(HALF * ks * tr(Rrl - Rrl.T * Rbr * Rbr), by_algebra("cyclic trace"))
    return [d]


def rbar_dot_form() -> list[Derivation]:
    """hat(tilde-omega) R-bar = k_s R-bar sk(R-bar^T R_l) for eq. (12a) (eq. (13))."""
    ctx = Context("Section 3, quasi-average dynamics")
    Rb, Rl = ctx.rotation("R̄"), ctx.rotation("R_l")
    ks = ctx.scalar("k_s", positive=True)
    omega = (ks * Rb * vee(sk(Rb.T * Rl))).named("ω̃_h^s")
    d = Derivation(
        "sec3.rbar-dot-form",
        hat(omega) * Rb,
        ctx,
        statement="with ω̃ = k_s R̄ sk(R̄ᵀR_l)^∨, hat(ω̃) R̄ = k_s R̄ sk(R̄ᵀR_l)",
        cite="eqs. (9), (12a), (13)",
    ).equals(ks * Rb * sk(Rb.T * Rl), by_algebra("hat(R v) = R hat(v) Rᵀ"))
    return [d]


def boundary() -> list[Derivation]:
    """On h = 0 (cos theta = 0): R-bar_r^2, the h-dot rewriting and its sign."""
    ctx = Context("Lemma 1, boundary")
    xi, theta = ctx.unit_vector("ξ"), ctx.angle("θ")
    Rrl = ctx.rotation("R_rl")
    ks = ctx.scalar("k_s", positive=True)
    Rbr = rodrigues(xi, theta).named("R̄_r")
    P = outer(xi, xi).named("ξξᵀ")
    on_boundary = ctx.condition("boundary h = 0, i.e. cosθ = 0", cos(theta), 0)
    sym_pd = ctx.assume(
        "λmin(sym(R_rl)) > 0", lambda_min(sym(Rrl)), "pos", cite="Assumption 1, item 2"
    )
    sym_pd_matrix = ctx.assume("sym(R_rl) ≻ 0", Rrl, "pd", cite="Assumption 1, item 2")

    square_form = Derivation(
        "lemma1.boundary-square",
        Rbr * Rbr,
        ctx,
        statement="on the boundary, R̄_r² = 2ξξᵀ - I",
        cite="Lemma 1 proof, boundary",
    )
    k = hat(xi)
    square_form.equals(
        I3 + 2 * sin(theta) * cos(theta) * k
        + (1 - (cos(theta) * cos(theta) - sin(theta) * sin(theta))) * (k * k),
        by_algebra("R̄_r² = exp(2θ ξ^), double-angle formulas"),
    )
    square_form.equals(I3 + 2 * (k * k), by_algebra("cosθ = 0"), where=(on_boundary,))
    square_form.equals(2 * P - I3, by_algebra("ξ^² = ξξᵀ - I for |ξ| = 1"))

    Rb2 = (2 * P - I3).named("(2ξξᵀ - I)")
    rewrite = Derivation(
        "lemma1.boundary-h-dot",
        HALF * ks * tr(Rrl - Rrl.T * Rbr * Rbr),
        ctx,
        where=(on_boundary,),
        statement="on the boundary ḣ = k_s tr{sym(R_rl)(I - ξξᵀ)} "
        "≥ k_s λmin(sym R_rl) tr(I - ξξᵀ) ≥ 0",
        cite="Lemma 1 proof, after eq. (15)",
    )
    rewrite.equals(
        QUARTER * ks * tr(Rrl + Rrl.T - Rrl * Rb2 - Rrl.T * Rb2),
        by_algebra("R̄_r² = 2ξξᵀ - I is symmetric on the boundary"),
    )
    rewrite.equals(HALF * ks * tr(sym(Rrl) * (I3 - Rb2)), by_algebra("sym(A) = (A + Aᵀ)/2"))
    rewrite.equals(ks * tr(sym(Rrl) * (I3 - P)), by_algebra("I - (2ξξᵀ - I) = 2(I - ξξᵀ)"))
    rewrite.ge(
        ks * lambda_min(sym(Rrl)) * tr(I3 - P),
        by_bound(
            positive(ks) * trace_lower_bound(sym(Rrl), I3 - P, gram=hat(xi)),
            note="trace inequality; premise I - ξξᵀ = hat(ξ)ᵀhat(ξ) ⪰ 0",
        ),
    )
    rewrite.ge(
        0,
        by_bound(
            positive(ks) * assumed(sym_pd) * square(hat(xi)),
            note="λmin(sym R_rl) > 0 and tr(I - ξξᵀ) = |hat ξ|²",
        ),
    )
    direct = Derivation(
        "lemma1.boundary-sign-direct",
        ks * tr(sym(Rrl) * (I3 - P)),
        ctx,
        statement="the paper's closing argument: sym(R_rl) ≻ 0 and I - ξξᵀ ⪰ 0 give ḣ ≥ 0",
        cite="Lemma 1 proof, last paragraph",
    ).ge(
        0,
        by_bound(
            positive(ks)
            * trace_psd_product(sym(Rrl), I3 - P, a_psd=sym_pd_matrix, b_gram=hat(xi)),
            note="tr of a product of PSD matrices",
        ),
    )
    return [square_form, rewrite, direct]


def gradient() -> list[Derivation]:
    """Nagumo's premise on SO(3): the gradient of h on the manifold, not in R^{3x3}."""
    ctx = Context("Lemma 1, gradient of h on SO(3)")
    R = ctx.rotation("R̄_r")
    w = ctx.vector("ω")
    on_boundary = ctx.condition("boundary tr(R̄_r) = 1", tr(R), 1)
    at_pi = ctx.condition("rotation angle π, tr(R̄_r) = -1", tr(R), -1)
    grad = (-2 * vee(R)).named("grad h")
    directional = Derivation(
        "lemma1.gradient-form",
        tr(R * hat(w)),
        ctx,
        statement="d/ds h(R̄_r exp(s ω^)) at s = 0 equals <-2 sk(R̄_r)^∨, ω>: "
        "the gradient of h on SO(3) is -2 sk(R̄_r)^∨",
        cite="Lemma 1 proof, Nagumo premise",
    ).equals(dot(grad, w), by_algebra("tr(A hat ω) = -2 <sk(A)^∨, ω>"))
    norm = Derivation(
        "lemma1.gradient-nonzero",
        dot(grad, grad),
        ctx,
        statement="|grad h|² = (3 - tr R̄_r)(1 + tr R̄_r) = 4 on the boundary (non-zero)",
        cite="Lemma 1 proof, Nagumo premise",
    )
    norm.equals((3 - tr(R)) * (1 + tr(R)), by_algebra("|sk(R)^∨|² = sin²θ"))
    norm.equals(4, by_algebra("tr R̄_r = 1"), where=(on_boundary,))
    vanishing = Derivation(
        "lemma1.gradient-vanishes-at-pi",
        dot(grad, grad),
        ctx,
        statement="at rotation angle π the gradient on SO(3) is 0 although ∂h/∂R = I there",
        cite="Lemma 1 proof: '∂h/∂R̄_r = I globally' is the ambient gradient",
    )
    vanishing.equals((3 - tr(R)) * (1 + tr(R)), by_algebra("|sk(R)^∨|² = sin²θ"))
    vanishing.equals(0, by_algebra("tr R̄_r = -1"), where=(at_pi,))
    return [directional, norm, vanishing]


def trace_inequality() -> list[Derivation]:
    """tr(AB) >= lambda_min(A) tr(B): as quoted (B any square matrix), and repaired."""
    ctx = Context("trace inequality")
    A, B = ctx.symmetric("A"), ctx.matrix("B")
    G, v = ctx.matrix("G"), ctx.vector("v")
    as_quoted = Derivation(
        "lemma1.trace-inequality-as-quoted",
        tr(A * B),
        ctx,
        statement="tr(AB) ≥ λmin(A) tr(B) for A symmetric, B any square matrix",
        cite="Lemma 1 proof, citing Hatanaka et al. (2015)",
    ).ge(lambda_min(A) * tr(B), by_citation("Hatanaka et al. 2015, as quoted in Lemma 1"))
    psd = (G.T * G).named("GᵀG")
    repaired = Derivation(
        "lemma1.trace-inequality-psd",
        tr(A * psd),
        ctx,
        statement="tr(AB) ≥ λmin(A) tr(B) for A symmetric and B = GᵀG ⪰ 0",
        cite="repair of the quoted inequality",
    ).ge(lambda_min(A) * tr(psd), by_bound(trace_lower_bound(A, psd, gram=G)))
    nonsym = (G.T * G + hat(v)).named("(GᵀG + hat v)")
    square_b = Derivation(
        "lemma1.trace-inequality-sym-psd",
        tr(A * nonsym),
        ctx,
        statement="B need not be symmetric: sym(B) ⪰ 0 suffices (tr(A hat v) = 0)",
        cite="repair of the quoted inequality",
    ).ge(lambda_min(A) * tr(nonsym), by_bound(trace_lower_bound(A, nonsym, gram=G)))
    return [as_quoted, repaired, square_b]


__all__ = ["boundary", "closed_loop_context", "gradient", "h_dot", "rbar_dot_form",
           "rodrigues_spectrum", "trace_inequality"]
