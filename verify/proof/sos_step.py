"""``by_sos()`` (:func:`verify.proof.justify.by_sos`): an inequality step proved by an
exact sum-of-squares certificate.

The slack of ``lhs >= rhs`` (or ``rhs - lhs`` for ``<=``) is a rational function
num / prod f_k^e_k of the parameters whose denominator factors f_k (|q|^2, 1 + a^2 +
b^2, 1 + t^2) are positive, so the step holds where the parametrisation is defined iff
num >= 0 there; num is a polynomial in free real parameters (quaternions need no
normalisation: num is homogeneous in each quaternion, and non-negativity on R^4
covers every rotation). The checker

1. divides known factors f_k out of num where they divide exactly (num = prod f^k p,
   with f >= 0, so p >= 0 suffices);
2. builds the multipliers it may use, each PSD for a reason it re-derives itself:
   1 (plain SOS); every scalar declared positive; every assumption passed to
   ``by_sos`` (pos/nonneg: the numerator of the assumed scalar; pd/psd: the numerator
   of sym(M)); for each lambda_min(A) with A exactly symmetric, the matrix
   num(A) - lambda_min(A) den(A) I (the spectral fact of the kernel); and products of
   scalar multipliers with these (the Positivstellensatz cone, truncated by degree);
3. searches a certificate p = sum_k <Q_k, H_k (x) z_k z_k^T> (:mod:`verify.sos`,
   untrusted), rounds it to rationals and checks it exactly (trusted); the identity is
   a polynomial identity in every parameter, lambda_min atoms included, so it holds
   whatever their values, and the multipliers' signs are the only facts used.

Charts. The identity holds for every real parameter, so the slack is >= 0 on the image
of the charts; the half-angle and stereographic charts miss points (theta = pi, a pole),
and the slack, a continuous function on the manifold, is >= 0 there too because the
image is dense. With an assumption as multiplier the claim is only made where the
assumption holds, and that set may meet a missed point with no chart point nearby
(e.g. "1 + cos theta <= 0" holds at theta = pi only). So an assumption whose expression
involves an angle or a unit vector is never used as a multiplier: the assumptions used
then depend only on fully charted variables (rotations by quaternions, vectors,
matrices, scalars), the set where they hold is a product with the partially charted
factors, and density works again.

No certificate means *inconclusive*, never verified. Side conditions (``where=``) are
not used: a certificate proves the inequality everywhere, hence under any condition.
Certificates are kept as JSON (:mod:`verify.sos.certificate`), reused when a stored one
matches the step exactly, and re-checked by ``verify certificates check``.
"""

from __future__ import annotations

import contextlib
import contextvars
import dataclasses
import itertools
from pathlib import Path

from verify.proof.claim_text import claim_text
from verify.proof.expr import ProofSyntaxError, sym, variables_of
from verify.proof.justify import BySos
from verify.proof.problem import StepProblem
from verify.sos import poly as pl
from verify.sos.program import Multiplier, SosProgram, StepProgram, scalar_multiplier

PARTIAL_CHARTS = ("angle", "unit_vector")  # parametrisations that miss points
MAX_PRODUCT = 3  # at most this many scalar facts multiplied into one multiplier


# -- the program of a step --------------------------------------------------------------
def _lifted(values) -> tuple[list, object]:
    """Numerators over one common denominator (a KnownFraction list), and that denominator."""
    n = max(len(v.exps) for v in values)
    target = tuple(max(v._padded(n)[k] for v in values) for k in range(n))
    return [v._lift(target) for v in values], values[0].__class__(
        values[0].den.ring.one, target, values[0].den)


def _matrix_multiplier(problem: StepProblem, expr, grounds: str, shift=None):
    """num(sym M) (minus shift * den * I) as a 3x3 polynomial matrix, or None."""
    entries = problem.exact(expr)
    nums, den = _lifted(entries)
    d = den.denominator()
    rows = []
    for i in range(3):
        row = []
        for j in range(3):
            e = nums[3 * i + j]
            if i == j and shift is not None:
                e = e - shift * d
            row.append(pl.from_ring(e))
        rows.append(tuple(row))
    return Multiplier(grounds, tuple(rows))


def step_program(problem: StepProblem, because: BySos) -> StepProgram:
    """Target polynomial and multipliers of a step, re-derived from the step alone."""
    (slack,) = problem.exact_slack
    space = problem.space
    num = slack.num
    factors: list[tuple[pl.Poly, int]] = []
    for f in slack.den.factors:
        k = 0
        while num:
            q, r = num.div(f)
            if r:
                break
            num, k = q, k + 1
        if k:
            factors.append((pl.from_ring(f), k))
    names = _names(space)
    groups: list[list[int]] = []
    i = 0
    for v in space.variables:
        groups.append(list(range(i, i + v.parameter_count)))
        i += v.parameter_count
    groups += [[i + k] for k in range(len(space.atoms))]
    scalars: list[Multiplier] = []
    for v in space.variables:
        if v.kind == "scalar" and v.positive:
            scalars.append(scalar_multiplier(f"{v.name} > 0 (declared)",
                                             pl.from_ring(space.param_gens[v.uid][0])))
    matrices: list[Multiplier] = []
    for a in because.assumptions:
        partial = sorted({v.name for v in variables_of(a.expr) if v.kind in PARTIAL_CHARTS})
        if partial:
            # the chart misses points (theta = pi, a pole of the sphere) where the
            # assumption may hold while it holds at no nearby chart point; a multiplier
            # from it would prove nothing there (see the module docstring)
            continue
        if a.kind in ("pos", "nonneg"):
            (value,) = problem.exact(a.expr)
            scalars.append(scalar_multiplier(f"assumed: {a.label}", pl.from_ring(value.num)))
        else:
            matrices.append(_matrix_multiplier(problem, sym(a.expr), f"assumed: {a.label}"))
    for atom in space.atoms:
        arg = atom.args[0]
        if all(v.is_zero() for v in problem.exact(arg - arg.T)):
            gen = space.atom_gens[_key(arg)]
            matrices.append(_matrix_multiplier(
                problem, arg, f"spectral: {atom} I ⪯ {arg} (symmetric)", shift=gen))
    target = pl.from_ring(num)
    top = because.degree if because.degree is not None else pl.degree(target)
    n = len(names)
    mults = [scalar_multiplier("1 (plain SOS)", pl.constant(1, n))]
    products: list[Multiplier] = []
    for size in range(1, MAX_PRODUCT + 1):
        for combo in itertools.combinations(scalars, size):
            g = pl.constant(1, n)
            for m in combo:
                g = pl.mul(g, m.matrix[0][0])
            if pl.degree(g) <= top:
                products.append(scalar_multiplier(" × ".join(m.grounds for m in combo), g))
    mults += products
    for mat in matrices:
        mults.append(mat)
        for prod in products[: len(scalars) * 2]:
            g = prod.matrix[0][0]
            scaled = tuple(tuple(pl.mul(g, e) for e in row) for row in mat.matrix)
            if max(pl.degree(e) for row in scaled for e in row) <= top:
                mults.append(Multiplier(f"{prod.grounds} × {mat.grounds}", scaled))
    program = SosProgram(names, target, tuple(mults))
    claim = claim_text(problem)
    return StepProgram(program, groups, pl.from_ring(slack.num), factors, claim.inequality,
                       labelled=f"{problem.lhs} {problem.relation} {problem.rhs}",
                       declarations=claim.declarations, assumptions=claim.assumptions,
                       definitions=claim.definitions)


def _names(space) -> tuple[str, ...]:
    """Parameter names stable across runs (the ring's names carry creation counters)."""
    names: list[str] = []
    seen: dict[str, int] = {}
    for v in space.variables:
        k = seen.get(v.name, 0)
        seen[v.name] = k + 1
        base = v.name if not k else f"{v.name}#{k}"
        names += [f"{base}[{i}]" for i in range(v.parameter_count)]
    names += [f"λmin{k}" for k in range(len(space.atoms))]
    return tuple(names)


def _key(e):
    from verify.proof.expr import structural_key

    return structural_key(e)


# -- where certificates are kept ---------------------------------------------------------
_STORE: contextvars.ContextVar[tuple[Path | None, str]] = contextvars.ContextVar(
    "sos_store", default=(None, ""))


@contextlib.contextmanager
def certificate_store(directory: Path | None, source: str = ""):
    """Within the block, by_sos steps reuse and write certificates in ``directory``.

    ``source`` names where the claims come from (``verify.paper_proofs`` for the
    paper's proofs, whose certificates ``verify certificates check`` binds again).
    """
    token = _STORE.set((Path(directory) if directory is not None else None, source))
    try:
        yield
    finally:
        _STORE.reset(token)


def exact_check(step, problem: StepProblem) -> tuple[bool, str]:
    """The exact check of a by_sos step (called by :func:`verify.proof.checker`)."""
    from verify.sos import certificate as cert
    from verify.sos.prove import find_certificate

    if step.relation == "=":
        return False, "an equality is justified by algebra, not by an SOS certificate"
    try:
        sp = step_program(problem, step.because)
    except (ArithmeticError, ValueError, TypeError, KeyError, AttributeError) as exc:
        return False, f"no SOS program for this step ({type(exc).__name__}: {exc})"
    key = cert.claim_key(sp)
    store, source = _STORE.get()
    if source == cert.PAPER:  # the paper's certificates are written with its own labels
        sp = dataclasses.replace(sp, statement=sp.labelled)
    if store is not None:
        stored = cert.lookup(store, key)
        if stored is not None:
            result = cert.check_bound(stored, sp)
            if result.ok:
                _renew(store, stored, sp, source, step, problem)
                return True, f"{result.reason}; certificate {cert.file_name(key)}"
    found = find_certificate(sp.program, sp.groups, max_degree=step.because.degree)
    if not found.check.ok:
        return False, f"no SOS certificate: {found.check.reason}"
    # the paper's certificates are bound to the paper's step by their key, with its
    # labels; any other carries its step, to be bound to it again
    data = cert.to_data(sp, found.blocks, found.grams, key, source,
                        step=None if source == cert.PAPER else _step_data(step, problem))
    result = cert.check_bound(data, sp)  # the same trusted check a stored file gets
    if not result.ok:
        return False, f"SOS certificate rejected: {result.reason}"
    where = ""
    if store is not None:
        try:
            cert.write(store, data)
        except OSError as exc:
            where = f" (not written: {exc.strerror or exc})"
    # the same text whether the certificate was found now or read back (reproducible)
    return True, f"{result.reason}; certificate {cert.file_name(key)}{where}"


def _renew(store: Path, stored: dict, sp, source: str, step, problem: StepProblem) -> None:
    """Rewrite a stored certificate that re-checks but was written before certificates
    carried their step, or with another statement than its step's tree (its labelled
    text, as earlier versions wrote it, or an edited one), so that ``verify certificates
    check`` binds it again and does not refuse it as edited."""
    from verify.sos import certificate as cert

    renewed = dict(stored)
    claim = stored.get("claim")
    if isinstance(claim, dict) and claim.get("statement") != sp.statement:
        renewed["claim"] = {**claim, "statement": sp.statement}
    if "step" not in stored and source != cert.PAPER:
        step_data = _step_data(step, problem)
        if step_data is not None:
            renewed["step"] = step_data
    if renewed != stored:
        with contextlib.suppress(OSError):
            cert.write(store, renewed)


def _step_data(step, problem: StepProblem) -> dict | None:
    """The step as data (:mod:`verify.proof.wire`): a one-step derivation with the step's
    conditions and assumptions, so that a stored certificate can be bound to it again."""
    from verify.proof.derivation import Context, Derivation, Step
    from verify.proof.wire import encode

    ctx = Context("certificate")
    ctx.variables = list(problem.variables)
    ctx._dynamics = {v.uid: None for v in problem.variables if v.kind == "scalar"}
    d = Derivation("certificate", step.lhs, ctx, tuple(problem.conditions),
                   tuple(problem.assumptions))
    d.steps = [Step(step.relation, step.lhs, step.rhs, step.because)]
    try:
        return encode([d])
    except ProofSyntaxError:
        return None


__all__ = ["certificate_store", "exact_check", "step_program"]
