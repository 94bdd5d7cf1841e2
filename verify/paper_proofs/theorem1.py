"""Theorem 1 of the paper (Section 3): V-dot bound and the LaSalle step.

Closed loop of eqs. (9), (12), (13): R_r constant; R-bar-dot = k_s R-bar sk(R-bar^T R_l);
R_l-dot = R_l hat(omega_l) with omega_l = k_s sk(R_l^T R-bar)^vee + R_l^T omega_h^s; the
human command omega_h^s is a free vector (the proofs hold for every value of it). The
human's energy S_h of the proof is the integral of eq. (16), so its derivative is
declared: S_h-dot = -<sk(R_rl)^vee, omega_h^b>.
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
    hat,
    lambda_min,
    outer,
    phi,
    positive,
    sk,
    square,
    substitute,
    tr,
    trace_lower_bound,
    vee,
)
from verify.proof.expr import dot, fro2

HALF = Fraction(1, 2)
QUARTER = Fraction(1, 4)


class ClosedLoop:
    """The variables and named sub-expressions shared by Theorem 1's derivations."""

    def __init__(self) -> None:
        ctx = Context("Theorem 1, closed loop")
        self.ctx = ctx
        self.Rr, self.Rb, self.Rl = ctx.rotation("R_r"), ctx.rotation("R̄"), ctx.rotation("R_l")
        self.ks = ctx.scalar("k_s", positive=True)
        self.omega_s = ctx.vector("ω_h^s")
        self.Sh = ctx.scalar("S_h")
        Rr, Rb, Rl, ks = self.Rr, self.Rb, self.Rl, self.ks
        self.Rbr = (Rr.T * Rb).named("R̄_r")
        self.Rrl = (Rr.T * Rl).named("R_rl")
        self.omega_b = (Rl.T * self.omega_s).named("ω_h^b")
        self.omega_l = (ks * vee(sk(Rl.T * Rb)) + self.omega_b).named("ω_l")
        ctx.constant(Rr)
        ctx.dynamics(Rb, ks * Rb * sk(Rb.T * Rl))
        ctx.dynamics(Rl, Rl * hat(self.omega_l))
        ctx.dynamics(self.Sh, -dot(vee(self.Rrl), self.omega_b))
        self.Q = (Rl.T * Rb).named("R_lᵀR̄")
        self.A1 = (self.Rbr + self.Rbr.T).named("(R̄_r + R̄_rᵀ)")
        self.A2 = (self.Rrl + self.Rrl.T).named("(R_rl + R_rlᵀ)")
        self.lam1 = lambda_min(self.A1)
        self.lam2 = lambda_min(self.A2)
        self.V = phi(self.Rbr) + phi(self.Rrl) + self.Sh
        self.lemma1 = ctx.assume("λmin(R̄_r + R̄_rᵀ) ≥ 0", self.lam1, "nonneg", cite="Lemma 1")
        self.item2 = ctx.assume(
            "λmin(R_rl + R_rlᵀ) > 0", self.lam2, "pos", cite="Assumption 1, item 2"
        )

    def trace_bound_r(self) -> object:
        """tr{A1 (I - R-bar^T R_l)} >= lambda1 tr(I - R-bar^T R_l); sym(I - Q) = (I-Q)^T(I-Q)/2."""
        B = I3 - self.Rb.T * self.Rl
        return trace_lower_bound(self.A1, B, gram=B, gram_scale=HALF)

    def trace_bound_rl(self) -> object:
        B = I3 - self.Q
        return trace_lower_bound(self.A2, B, gram=B, gram_scale=HALF)


def phi_identity() -> list[Derivation]:
    ctx = Context("Theorem 1, energy function")
    R = ctx.rotation("R")
    d = Derivation("thm1.phi", phi(R), ctx, statement="φ(R) = tr(I - R)/2 = ‖I - R‖_F²/4",
                   cite="Theorem 1 proof, definition of φ")
    d.equals(QUARTER * fro2(I3 - R), by_algebra("RᵀR = I"))
    return [d]


def s_r_dot(loop: ClosedLoop | None = None) -> list[Derivation]:
    c = loop or ClosedLoop()
    ks, Rbr, Rrl = c.ks, c.Rbr, c.Rrl
    d = Derivation(
        "thm1.S_r-dot",
        c.ctx.ddt(phi(Rbr)).named("Ṡ_r"),
        c.ctx,
        statement="Ṡ_r ≤ -(k_s/2) λmin(R̄_r + R̄_rᵀ) φ(R̄ᵀR_l) - k_s φ(R̄_r) + k_s φ(R_rl)",
        cite="Theorem 1 proof, Ṡ_r chain",
    )
    d.equals(-HALF * tr(c.ctx.ddt(Rbr).named("(d/dt R̄_r)")), by_algebra("φ(R) = tr(I - R)/2"))
    d.equals(-HALF * ks * tr(Rbr * sk(Rbr.T * Rrl)), by_algebra("eq. (13)"))
    d.equals(-QUARTER * ks * tr(Rbr * (Rbr.T * Rrl - Rrl.T * Rbr)), by_algebra("sk definition"))
    d.equals(-QUARTER * ks * tr(Rrl - Rbr * Rrl.T * Rbr), by_algebra("R̄_r R̄_rᵀ = I"))
    d.equals(
        -QUARTER * ks * tr(c.A1 * (I3 - Rbr.T * Rrl)) + HALF * ks * tr(Rbr) - HALF * ks * tr(Rrl),
        by_algebra("add and subtract"),
    )
    d.equals(
        -QUARTER * ks * tr(c.A1 * (I3 - c.Rb.T * c.Rl))
        - HALF * ks * tr(I3 - Rbr)
        + HALF * ks * tr(I3 - Rrl),
        by_algebra("R̄_rᵀR_rl = R̄ᵀR_l"),
    )
    d.le(
        -HALF * ks * c.lam1 * phi(c.Rb.T * c.Rl) - ks * phi(Rbr) + ks * phi(Rrl),
        by_bound(QUARTER * positive(ks) * c.trace_bound_r(),
                 note="trace inequality, sym(I - R̄ᵀR_l) = ½(I - R̄ᵀR_l)ᵀ(I - R̄ᵀR_l) ⪰ 0"),
    )
    return [d]


def s_rl_dot(loop: ClosedLoop | None = None) -> list[Derivation]:
    c = loop or ClosedLoop()
    ks, Rbr, Rrl = c.ks, c.Rbr, c.Rrl
    d = Derivation(
        "thm1.S_rl-dot",
        c.ctx.ddt(phi(Rrl)).named("Ṡ_rl"),
        c.ctx,
        statement="Ṡ_rl ≤ -(k_s/2) λmin(R_rl + R_rlᵀ) φ(R_lᵀR̄) + k_s φ(R̄_r) - k_s φ(R_rl) "
        "+ <sk(R_rl)^∨, ω_h^b>",
        cite="Theorem 1 proof, Ṡ_rl chain",
    )
    d.equals(-HALF * tr(c.ctx.ddt(Rrl).named("(d/dt R_rl)")), by_algebra("φ(R) = tr(I - R)/2"))
    d.equals(-HALF * tr(Rrl * (ks * sk(Rrl.T * Rbr) + hat(c.omega_b))),
             by_algebra("eq. (12b), R_lᵀR̄ = R_rlᵀR̄_r"))
    d.equals(-HALF * ks * tr(Rrl * sk(Rrl.T * Rbr)) - HALF * tr(Rrl * hat(c.omega_b)),
             by_algebra("linearity"))
    d.le(
        -HALF * ks * c.lam2 * phi(c.Q) + ks * phi(Rbr) - ks * phi(Rrl)
        + dot(vee(sk(Rrl)), c.omega_b),
        by_bound(QUARTER * positive(ks) * c.trace_bound_rl(),
                 note="as for Ṡ_r, and tr(R hat ω) = -2<sk(R)^∨, ω>"),
    )
    return [d]


def storage_sign() -> list[Derivation]:
    """eq. (16) is stated with sk(R_l^T R_r)^vee = -sk(R_rl)^vee; S_h uses the latter."""
    ctx = Context("Theorem 1, human storage")
    Rr, Rl = ctx.rotation("R_r"), ctx.rotation("R_l")
    d = Derivation("thm1.S_h-sign", vee(sk(Rl.T * Rr)), ctx,
                   statement="sk(R_lᵀR_r)^∨ = -sk(R_rl)^∨, so S_h ≥ 0 is eq. (16)",
                   cite="eq. (16) and the definition of S_h")
    d.equals(-vee(sk(Rr.T * Rl)), by_algebra("(R_lᵀR_r) = R_rlᵀ"))
    return [d]


def v_dot(loop: ClosedLoop | None = None) -> list[Derivation]:
    c = loop or ClosedLoop()
    ks = c.ks
    identity = (
        -QUARTER * ks * (tr(c.A1 * (I3 - c.Rb.T * c.Rl)) + tr(c.A2 * (I3 - c.Q)))
    )
    bound = -HALF * ks * (c.lam1 + c.lam2) * phi(c.Q)
    d = Derivation(
        "thm1.V-dot",
        c.ctx.ddt(c.V).named("V̇"),
        c.ctx,
        statement="V̇ = -(k_s/4)[tr{(R̄_r+R̄_rᵀ)(I - R̄ᵀR_l)} + tr{(R_rl+R_rlᵀ)(I - R_lᵀR̄)}] "
        "≤ -(k_s/2)(λ1 + λ2) φ(R_lᵀR̄) ≤ 0",
        cite="Theorem 1 proof, eq. (17)",
    )
    d.equals(identity, by_algebra("Ṡ_r + Ṡ_rl + Ṡ_h; the human terms cancel"))
    d.le(
        bound,
        by_bound(QUARTER * positive(ks) * c.trace_bound_r(),
                 QUARTER * positive(ks) * c.trace_bound_rl(),
                 note="trace inequality twice"),
    )
    d.le(
        0,
        by_bound(
            HALF * positive(ks) * (assumed(c.lemma1) + assumed(c.item2))
            * (QUARTER * square(I3 - c.Q)),
            note="λ1 ≥ 0 (Lemma 1), λ2 > 0 (Assumption 1.2), φ(Q) = ‖I - Q‖²/4",
        ),
    )
    zero_implies_sync = Derivation(
        "thm1.V-dot-zero-implies-sync",
        Fraction(1, 8) * ks * (c.lam1 + c.lam2) * fro2(I3 - c.Q),
        c.ctx,
        statement="(k_s/8)(λ1 + λ2)‖I - R_lᵀR̄‖² ≤ -V̇: with λ1 + λ2 > 0, V̇ = 0 forces R_l = R̄",
        cite="Theorem 1 proof, 'V̇ = 0 iff R_l = R̄'",
    ).le(
        -c.ctx.ddt(c.V).named("V̇"),
        by_bound(QUARTER * positive(ks) * c.trace_bound_r(),
                 QUARTER * positive(ks) * c.trace_bound_rl(),
                 note="the bound of eq. (17) with φ(Q) = ‖I - Q‖²/4"),
    )
    on_sync = Derivation(
        "thm1.V-dot-zero-on-sync",
        substitute(c.ctx.ddt(c.V), {c.Rl: c.Rb}).named("V̇ at R_l = R̄"),
        c.ctx,
        statement="V̇ = 0 when R_l = R̄, whatever the human commands",
        cite="Theorem 1 proof, 'V̇ = 0 iff R_l = R̄'",
    ).equals(0, by_algebra("R_l = R̄"))
    return [d, zero_implies_sync, on_sync]


def lasalle(loop: ClosedLoop | None = None) -> list[Derivation]:
    c = loop or ClosedLoop()
    ctx, Rb, Rl, w = c.ctx, c.Rb, c.Rl, c.omega_s
    rate = ctx.ddt(Rl.T * Rb)
    on_set = Derivation(
        "thm1.lasalle-derivative",
        substitute(rate, {Rb: Rl}).named("d/dt(R_lᵀR̄) at R̄ = R_l"),
        ctx,
        statement="on R_l = R̄: d/dt(R_lᵀR̄) = -R_lᵀ hat(ω_h^s) R_l = -hat(R_lᵀ ω_h^s)",
        cite="Theorem 1 proof, LaSalle step",
    )
    on_set.equals(-(Rl.T * hat(w) * Rl), by_algebra("sk(I) = 0"))
    on_set.equals(-hat(Rl.T * w), by_algebra("Rᵀ hat(ω) R = hat(Rᵀω)"))
    # the proof first says V-dot = 0 'implies sk(R_l^T R-bar)^vee = 0'; that alone also
    # allows R_l^T R-bar = rotation by pi about some axis xi, where the formula differs
    xi = ctx.unit_vector("ξ")
    flip = (2 * outer(xi, xi) - I3).named("(2ξξᵀ - I)")
    weak = Derivation(
        "thm1.lasalle-derivative-from-sk-only",
        substitute(rate, {Rb: Rl * flip}).named("d/dt(R_lᵀR̄) at R̄ = R_l(2ξξᵀ - I)"),
        ctx,
        statement="with only sk(R_lᵀR̄) = 0 (R_lᵀR̄ = 2ξξᵀ - I, angle π) the formula changes",
        cite="Theorem 1 proof, 'which implies sk(R_lᵀR̄)^∨ = 0'",
    ).equals(-(Rl.T * hat(w) * Rl * flip), by_algebra("sk(2ξξᵀ - I) = 0"))
    return [on_set, weak]


__all__ = ["ClosedLoop", "lasalle", "phi_identity", "s_r_dot", "s_rl_dot", "storage_sign",
           "v_dot"]
