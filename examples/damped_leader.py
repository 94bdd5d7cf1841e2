"""An extension of the paper, checked with `verify check examples/damped_leader.py`.

Suppose the virtual leader also damps towards the reference:
omega_l = k_s sk(R_l^T R-bar)^vee + R_l^T omega_h^s - k_d sk(R_rl)^vee, with k_d > 0.
Then S_rl = phi(R_rl) gains the extra term -(k_d/2) tr(R_rl hat(-sk(R_rl)^vee)), which
is -k_d |sk(R_rl)^vee|^2 <= 0. The derivation below states it step by step.
"""

from fractions import Fraction

from verify.proof import (
    Context,
    Derivation,
    by_algebra,
    by_bound,
    dot,
    hat,
    phi,
    positive,
    sk,
    square,
    tr,
    vee,
)

ctx = Context("damped leader")
Rr, Rb, Rl = ctx.rotation("R_r"), ctx.rotation("R̄"), ctx.rotation("R_l")
ks = ctx.scalar("k_s", positive=True)
kd = ctx.scalar("k_d", positive=True)
w = ctx.vector("ω_h^s")
Rrl = (Rr.T * Rl).named("R_rl")
Rbr = (Rr.T * Rb).named("R̄_r")
damping = (kd * vee(sk(Rrl))).named("k_d sk(R_rl)^∨")
omega_l = ks * vee(sk(Rl.T * Rb)) + Rl.T * w - damping
ctx.constant(Rr)
ctx.dynamics(Rl, Rl * hat(omega_l))

undamped = -Fraction(1, 2) * tr(Rrl * (ks * sk(Rrl.T * Rbr) + hat(Rl.T * w)))
extra = Derivation(
    "damped.S_rl-dot",
    ctx.ddt(phi(Rrl)).named("Ṡ_rl"),
    ctx,
    statement="the damping adds -k_d |sk(R_rl)^∨|² to Ṡ_rl",
)
extra.equals(undamped - kd * dot(vee(sk(Rrl)), vee(sk(Rrl))),
             by_algebra("tr(R hat v) = -2 <sk(R)^∨, v>"))
extra.le(undamped, by_bound(positive(kd) * square(vee(sk(Rrl))), note="k_d > 0"))

DERIVATIONS = [extra]
