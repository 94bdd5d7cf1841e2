"""Export of derivations (:mod:`verify.proof.derivation`) to Coq, one section per file.

The exporter reads the same expression trees the Python checker decides: each step's
left and right sides, its side conditions, and, for an inequality, the non-negative
terms of its justification, re-issued from their recipes
(:func:`verify.proof.justify.recipe`). Each step becomes a Coq theorem stated with the
prelude's definitions (``SO3.v``):

- variables become ``Variable``s of a ``Section``: a rotation is ``rot q`` for a
  quaternion ``q`` with the hypothesis ``qn q <> 0``; a unit vector has the hypothesis
  ``vdot u u = 1``; an angle is a real (``cos``, ``sin`` from the standard library); a
  scalar declared positive has ``0 < k``; each lambda_min(A) is a real ``lam`` with the
  hypothesis ``lam_min_spec A lam`` (sym A - lam I is PSD, as a quadratic form);
- side conditions and the paper's assumptions are named ``Hypothesis``es (never proved
  facts), and each theorem's ``Proof using`` lists exactly those it may use, so after
  the section closes they are premises of the theorem;
- an equality is proved entry by entry, with rotations generalised to free matrices
  when possible (after the prelude's matrix-level normal form ``so3_norm`` when
  rotations must meet their transposes, :mod:`verify.coq.normal`; a step of at most two
  rotations that the normal form decides without cofactors is proved instead by the
  prelude's evaluator ``SOSCert.sos_eq``, the normal form kept as its fallback); an entry
  that is a
  polynomial identity is decided by ``lra`` (``so3_poly``), one with quaternion norms in
  its denominators by ``field``; cofactors ``lhs - rhs = sum c_k g_k`` enter when it
  needs a unit vector, an angle or a side condition (:mod:`verify.coq.polys` finds
  them, Coq re-checks);
- an inequality ``lhs <= rhs`` (``>=``) by its slack: Coq proves that the slack
  equals the sum of the justification's terms (as an equality above), and each term
  is non-negative by the prelude's lemmas (squares, declared positive scalars,
  assumptions, the trace inequality, the trace of a PSD product), whose premises are
  proved like equalities.

Derivatives (``ctx.ddt``) arrive as the trees :mod:`verify.proof.calculus` formed by
the product rule from the declared dynamics; the steps check the algebra from there on,
and a derivation that starts from a derivative also gets the theorem ``ddt``
(:mod:`verify.coq.ddt`): for every trajectory satisfying the declared dynamics, its
first expression is the derivative (Coquelicot's ``is_derive``), the rules applied in
Coq. A step justified by a citation is not exported; an SOS step is not
exported here: the paper's SOS certificates are units of their own
(:mod:`verify.coq.sos`), a user's derivation file keeps its by_sos steps out.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction

from verify.coq.ddt import THEOREM as DDT_THEOREM
from verify.coq.ddt import ddt_theorem
from verify.coq.normal import normal_form
from verify.coq.polys import Atoms, atoms_for, cofactors, denominator_text, entries, evaluate
from verify.coq.polys import poly_text as _poly_text
from verify.coq.reparse import intended_statement
from verify.coq.terms import (
    LET_STATEMENT_CHARS,
    CoqExportError,
    Naming,
    assumption_hypothesis,
    constant,
    coq_text,
    let_bindings,
)
from verify.coq.text import module_identifier
from verify.coq.unit import CoqUnit, comment_text
from verify.proof.derivation import Derivation, Step
from verify.proof.expr import MATRIX, SCALAR, VECTOR, Expr, nodes, variables_of
from verify.proof.hypotheses import Assumption, Condition
from verify.proof.justify import ByAlgebra, ByBound, Nonneg, recipe
from verify.proof.printing import to_text
from verify.proof.size import over_limits, over_term_limit

HEADER = """From Coq Require Import Reals Lra.
From VerifyCoq Require Import SO3.
Open Scope R_scope.
"""


@dataclass(frozen=True)
class StepExport:
    """What became of one step: its Coq theorem (``Module.theorem``) or why there is none."""

    derivation: str
    step: int
    theorem: str | None
    reason: str = ""


@dataclass
class _Section:
    """Names, hypotheses and atoms of one exported derivation."""

    naming: Naming
    atoms: Atoms
    lines: list[str] = field(default_factory=list)
    basic: list[str] = field(default_factory=list)  # hypotheses every step may use
    conditions: dict[int, str] = field(default_factory=dict)  # id(Condition) -> name
    condition_objs: dict[int, Condition] = field(default_factory=dict)
    assumptions: dict[int, str] = field(default_factory=dict)
    variables: list[str] = field(default_factory=list)
    gatoms: Atoms | None = None  # the same atoms with rotations as free matrices
    variables_list: list = field(default_factory=list)
    lambda_nodes: list = field(default_factory=list)
    mixed: dict = field(default_factory=dict)  # frozenset of free rotations -> Atoms
    units: list[tuple[str, str]] = field(default_factory=list)  # (kind, Coq name)


def module_name(derivation_name: str) -> str:
    """The module of a derivation exported alone (:func:`verify.coq.text.module_identifier`:
    never a prelude module, ``All`` or a keyword)."""
    return module_identifier(derivation_name, set())


def theorem_name(derivation_name: str, step: int) -> str:
    """The qualified Coq name of step ``step`` (1-based) of a derivation."""
    return f"{module_name(derivation_name)}.step{step}"


def derivation_unit(d: Derivation, *, module: str | None = None, source: str = "",
                    exportable: frozenset[int] | None = None, claim: bool = True,
                    exportable_reason: str = "not verified: not exported"
                    ) -> tuple[CoqUnit | None, list[StepExport]]:
    """The Coq unit of ``d`` (None if no step could be exported) and each step's fate.

    ``exportable``: the (1-based) steps that may be exported (the checker verified them);
    the others are left out with ``exportable_reason``. ``claim``: state the derivation's
    claim when every step is exported (False when the checker did not verify the
    derivation as a whole, e.g. its premises cannot hold together).
    """
    name = module or module_name(d.name)
    try:
        sec = _section(d)
    except _EXPORT_FAILURES as exc:
        why = f"the derivation's declarations cannot be exported: {_failure(exc)}"
        return None, [StepExport(d.name, k, None, why if exportable is None or k in exportable
                                 else exportable_reason)
                      for k in range(1, len(d.steps) + 1)]
    fates: list[StepExport] = []
    theorems: list[str] = []
    statements: list[tuple[str, str]] = []
    terms: list[tuple[str, str]] = []
    body: list[str] = []
    for k, step in enumerate(d.steps, start=1):
        thm = f"step{k}"
        if exportable is not None and k not in exportable:
            fates.append(StepExport(d.name, k, None, exportable_reason))
            continue
        try:
            made = _step_theorem(sec, d, step, thm, k)
        except _EXPORT_FAILURES as exc:
            fates.append(StepExport(d.name, k, None, _failure(exc)))
            continue
        if made is None:
            fates.append(StepExport(d.name, k, None, _not_exported_reason(step)))
            continue
        body.append(made[0])
        theorems.append(thm)
        statements.append((thm, made[1]))
        terms.append((thm, intended_statement(step.lhs, step.relation, step.rhs,
                                              sec.naming)))
        fates.append(StepExport(d.name, k, f"{name}.{thm}"))
    try:
        ddt = ddt_theorem(d, sec.naming)
    except _EXPORT_FAILURES:
        ddt = None  # no derivative theorem; the steps stand as exported
    if not theorems:
        return None, fates
    if len(theorems) == len(d.steps) > 1 and claim:
        text, statement = _claim_theorem(sec, d)
        body.append(text)
        theorems.append("claim")
        statements.append(("claim", statement))
        terms.append(("claim", intended_statement(d.start, _claim_relation(d), d.current,
                                                  sec.naming)))
    section = name
    head = [f"(** Exported from the derivation '{comment_text(d.name)}' (verify.proof).",
            "    Context only, not theorems of this file:",
            f"    the derivation's summary: {comment_text(d.statement)}",
            f"    its place in the paper: {comment_text(d.cite)}",
            "    Each theorem below is one step, exactly as the comment above it writes it,",
            "    under the hypotheses its Proof using line names. *)", "",
            HEADER if "SOSCert.sos_eq" not in "\n".join(body)
            else HEADER.replace("Require Import SO3.\n",
                                "Require Import SO3.\nFrom VerifyCoq Require SOSCert.\n"),
            f"Section {section}.", ""]
    tail: list[str] = []
    if ddt is not None:
        tail = [ddt[0]]
        theorems.append(DDT_THEOREM)
        statements.append((DDT_THEOREM, ddt[1]))
        terms.append((DDT_THEOREM, ddt[2]))
    text = "\n".join(head + sec.lines + [""] + body + [f"End {section}.", ""] + tail)
    return CoqUnit(name, text, tuple(theorems), source or d.name, tuple(statements),
                   tuple(terms)), fates


#: What exporting one step (or a derivation's declarations) may raise on a file's input:
#: each is that step not exported, with the reason, never a crash.
_EXPORT_FAILURES = (CoqExportError, ValueError, ArithmeticError, RecursionError, KeyError,
                    MemoryError)


def said(e: Expr) -> str:
    """``e`` as a comment says it: the tree itself (no author's label, which could name
    another term), made inert (:func:`verify.coq.text.inert_comment`)."""
    return comment_text(to_text(e, labels=False))


def _failure(exc: BaseException) -> str:
    if isinstance(exc, CoqExportError):
        return str(exc)
    if isinstance(exc, RecursionError):
        return "an expression too deep for the exporter"
    if isinstance(exc, MemoryError):
        return "out of memory in the exporter"
    return f"the exporter failed on it ({type(exc).__name__}: {str(exc)[:120]})"


def _section(d: Derivation) -> _Section:
    """Names, atoms and declarations of ``d``'s section (every variable of its context)."""
    exprs, lambda_nodes = _expressions(d)
    too_large = over_limits(*exprs)
    if too_large:
        raise CoqExportError(f"too large for the exporter: {too_large}")
    own = {v.uid for v in d.context.variables}
    used = variables_of(*exprs)
    foreign = [v for v in used if v.uid not in own]
    if foreign:
        raise CoqExportError(f"the variable {comment_text(foreign[0].name)!r} is not of the "
                             "derivation's context")
    naming = Naming()
    variables = [v for v in d.context.variables if v.uid in {w.uid for w in used}]
    atoms = atoms_for(variables, lambda_nodes, naming)
    sec = _Section(naming, atoms, gatoms=atoms_for(variables, lambda_nodes, naming,
                                                   generic=True),
                   variables_list=variables, lambda_nodes=lambda_nodes)
    _declare(sec, d, variables, lambda_nodes)
    return sec


def _claim_relation(d: Derivation) -> str:
    rels = {s.relation for s in d.steps} - {"="}
    return rels.pop() if rels else "="


def _claim_theorem(sec: _Section, d: Derivation) -> tuple[str, str]:
    """The derivation's conclusion, start REL end, chained from its step theorems."""
    rel = _claim_relation(d)
    names = {("=", "="): "eq_trans", ("<=", "<="): "Rle_trans", (">=", ">="): "Rge_trans",
             ("=", "<="): "eq_le_trans", ("<=", "="): "le_eq_trans",
             ("=", ">="): "eq_ge_trans", (">=", "="): "ge_eq_trans"}
    proof, acc = "step1", d.steps[0].relation
    for k, s in enumerate(d.steps[1:], start=2):
        lemma = names[(acc, s.relation)]
        holes = "" if lemma == "eq_trans" else " _ _ _"
        proof = f"({lemma}{holes} {proof} step{k})"
        acc = acc if s.relation == "=" else s.relation
    conds = list(d.where) + [c for s in d.steps for c in s.where]
    hyps = list(sec.basic) + [sec.conditions[id(c)] for c in conds]
    hyps += list(sec.assumptions.values())
    using = " ".join(dict.fromkeys(sec.variables + hyps))
    start, end = coq_text(d.start, sec.naming), coq_text(d.current, sec.naming)
    coq_rel = {"=": "=", "<=": "<=", ">=": ">="}[rel]
    statement = f"{start} {coq_rel} {end}"
    return "\n".join([
        f"(** The derivation's claim: {said(d.start)} {rel} {said(d.current)} *)",
        f"Theorem claim : {statement}.",
        f"Proof using {using}.", f"  exact {proof}.", "Qed.", ""]), statement


def _not_exported_reason(step: Step) -> str:
    kind = step.because.kind
    if kind == "citation":
        return "cited, not proved: there is nothing for Coq to check"
    if kind == "sos":
        return ("proved by an SOS certificate: the paper's are exported as units of their "
                "own (verify coq); a derivation file's are not exported")
    return f"justification {kind!r} is not exported"


# -- collecting ---------------------------------------------------------------------------
def _terms_of(step: Step) -> list[Nonneg]:
    if not isinstance(step.because, ByBound):
        return []
    out: list[Nonneg] = []
    todo = list(step.because.terms)
    while todo:
        t = todo.pop()
        out.append(t)
        how = recipe(t)
        if how is None:
            raise CoqExportError("a non-negative term has no recipe")
        todo += [x for x in how[1:] if isinstance(x, Nonneg)]
    return out


def _term_exprs(t: Nonneg) -> list[Expr]:
    how = recipe(t) or ()
    out = [t.value] + [x for x in how[1:] if isinstance(x, Expr)]
    out += [a.expr for a in how[1:] if isinstance(a, Assumption)]
    return out


def _expressions(d: Derivation) -> tuple[list[Expr], list[Expr]]:
    exprs: list[Expr] = [d.start]
    for c in d.where:
        exprs += [c.lhs, c.rhs]
    for a in d.assumes:
        exprs.append(a.expr)
    for s in d.steps:
        exprs += [s.lhs, s.rhs]
        for c in s.where:
            exprs += [c.lhs, c.rhs]
        try:
            for t in _terms_of(s):
                exprs += _term_exprs(t)
                exprs += [a.expr for a in t.assumptions]
        except CoqExportError:
            pass
    lambdas = [n for n in nodes(*exprs) if n.op == "lambda_min"]
    return exprs, lambdas


# -- the section's declarations -----------------------------------------------------------
def _declare(sec: _Section, d: Derivation, variables, lambda_nodes) -> None:
    out, naming = sec.lines, sec.naming
    for v in variables:
        n = naming.variable(v)
        label = comment_text(v.name)
        if v.kind == "rotation":
            out += [f"(** {label}: a rotation, rot q with |q|^2 <> 0 *)",
                    f"Variable q_{n} : quat.",
                    f"Hypothesis q_{n}_nonzero : qn q_{n} <> 0.",
                    f"Local Notation {n} := (rot q_{n}).", ""]
            sec.variables.append(f"q_{n}")
            sec.basic.append(f"q_{n}_nonzero")
        elif v.kind == "unit_vector":
            out += [f"(** {label}: a unit vector *)", f"Variable {n} : V3.",
                    f"Hypothesis {n}_unit : vdot {n} {n} = 1.", ""]
            sec.variables.append(n)
            sec.basic.append(f"{n}_unit")
            sec.units.append(("unit_vector", n))
        elif v.kind == "angle":
            out += [f"(** {label}: an angle *)", f"Variable {n} : R.", ""]
            sec.variables.append(n)
            sec.units.append(("angle", n))
        elif v.kind == "symmetric":
            parts = [f"{n}_{ij}" for ij in ("11", "22", "33", "12", "13", "23")]
            out += [f"(** {label}: a symmetric matrix, by its six entries *)",
                    f"Variables {' '.join(parts)} : R.",
                    f"Local Notation {n} := (symm {' '.join(parts)}).", ""]
            sec.variables += parts
        else:
            typ = {"vector": "V3", "matrix": "M3", "scalar": "R"}[v.kind]
            out += [f"(** {label}: a {v.kind} *)", f"Variable {n} : {typ}."]
            sec.variables.append(n)
            if v.kind == "scalar" and v.positive:
                out.append(f"Hypothesis {n}_pos : 0 < {n}.")
                sec.basic.append(f"{n}_pos")
            out.append("")
    seen: set[str] = set()
    for node in lambda_nodes:
        lam = naming.lambda_atom(node)
        if lam in seen:
            continue
        seen.add(lam)
        arg = coq_text(node.args[0], naming)
        out += [f"(** lambda_min({said(node.args[0])}) *)", f"Variable {lam} : R.",
                f"Hypothesis {lam}_spec : lam_min_spec {arg} {lam}.", ""]
        sec.variables.append(lam)
        sec.basic.append(f"{lam}_spec")
    conditions = list(d.where) + [c for s in d.steps for c in s.where]
    for c in conditions:
        if id(c) in sec.conditions:
            continue
        name = f"condition{len(sec.conditions) + 1}"
        sec.conditions[id(c)] = name
        sec.condition_objs[id(c)] = c
        out += [f"(** side condition: {comment_text(c.label)} *)",
                f"Hypothesis {name} : {coq_text(c.lhs, naming)} = {coq_text(c.rhs, naming)}.",
                ""]
    assumptions = list(d.assumes)
    for s in d.steps:
        try:
            for t in _terms_of(s):
                assumptions += list(t.assumptions)
        except CoqExportError:
            pass
    for a in assumptions:
        if id(a) in sec.assumptions:
            continue
        name = f"assumption{len(sec.assumptions) + 1}"
        sec.assumptions[id(a)] = name
        out += assumption_hypothesis(name, a, naming)


# -- steps ----------------------------------------------------------------------------------
def _step_theorem(sec: _Section, d: Derivation, step: Step, thm: str,
                  k: int) -> tuple[str, str] | None:
    """The theorem of one step (its text and its statement), None when its justification
    is not exported. The step's size is bounded before anything is expanded
    (:func:`verify.proof.size.over_term_limit`)."""
    naming = sec.naming
    conds = list(d.where) + list(step.where)
    if isinstance(step.because, ByAlgebra | ByBound):
        too_large = over_term_limit(step.lhs, step.rhs,
                                    *[x for c in conds for x in (c.lhs, c.rhs)])
        if too_large:
            raise CoqExportError(f"too large for the exporter: {too_large}")
    gens = conds
    hyps = list(sec.basic) + [sec.conditions[id(c)] for c in conds]
    lets: list[tuple[str, str]] = []
    lhs, rhs = coq_text(step.lhs, naming), coq_text(step.rhs, naming)  # bounded, or refused
    if len(lhs) + len(rhs) > LET_STATEMENT_CHARS:  # long shared subterms written once
        lets, bound = let_bindings([step.lhs, step.rhs], naming)
        lhs = coq_text(step.lhs, naming, bound=bound)
        rhs = coq_text(step.rhs, naming, bound=bound)
    note = step.because.describe()
    head = [f"(** Step {k}: {said(step.lhs)} {step.relation} {said(step.rhs)}",
            f"    ({comment_text(note)}) *)"]
    if isinstance(step.because, ByAlgebra):
        if step.relation != "=":
            raise CoqExportError("an algebra step must be an equality")
        body = _equality_script(sec, step.lhs, step.rhs, gens)
        statement = f"{lhs} = {rhs}"
    elif isinstance(step.because, ByBound):
        terms = _terms_of(step)
        for t in terms:
            hyps += [sec.assumptions[id(a)] for a in t.assumptions
                     if sec.assumptions[id(a)] not in hyps]
        body = _inequality_script(sec, step, gens)
        statement = f"{lhs} <= {rhs}" if step.relation == "<=" else f"{lhs} >= {rhs}"
    else:
        return None
    using = " ".join(dict.fromkeys(sec.variables + hyps))
    proof = f"Proof using {using}." if using else "Proof."
    if lets:  # the statement names its shared subterms; the proof works on them written out
        statement = "".join(f"let {n} := {t} in " for n, t in lets) + statement
        body = ["cbv zeta.", *body]
    return "\n".join([*head, f"Theorem {thm} : {statement}.", proof,
                      *("  " + line for line in body), "Qed.", ""]), statement


def _generators(sec: _Section, atoms: Atoms, conds: list[Condition]) -> list[tuple]:
    """(value, Coq text, proof of text = 0) of every equation the step may use."""
    out = []
    for kind, n in sec.units:
        if kind == "unit_vector":
            x = [atoms.gens[f"v{i}_{n}"] for i in (1, 2, 3)]
            out.append((atoms.poly(x[0] ** 2 + x[1] ** 2 + x[2] ** 2 - 1),
                        f"(vdot {n} {n} - 1)", f"(Rminus_diag_eq _ _ {n}_unit)"))
        else:
            c, s = atoms.gens[f"cos_{n}"], atoms.gens[f"sin_{n}"]
            out.append((atoms.poly(c * c + s * s - 1),
                        f"(cos {n} * cos {n} + sin {n} * sin {n} - 1)", f"(circle {n})"))
    for c in conds:
        value = evaluate(c.lhs, atoms) - evaluate(c.rhs, atoms)
        text = f"({coq_text(c.lhs, sec.naming)} - {coq_text(c.rhs, sec.naming)})"
        out.append((value, text, f"(Rminus_diag_eq _ _ {sec.conditions[id(c)]})"))
    return out


def _equality_script(sec: _Section, lhs: Expr, rhs: Expr, conds: list[Condition]) -> list[str]:
    """Tactics proving ``lhs = rhs`` (any shape) from the generators' vanishing.

    First with rotations as free matrices (conditions on rotations left out), as they
    stand, and only when that fails after the prelude's matrix-level normal form
    ``so3_norm`` (:mod:`verify.coq.normal`: rotations meeting their transposes cancel;
    of ``so3_norm`` and ``so3_norm_hat``, the one with fewer terms is written); when the
    identity holds there, ``generalize`` forgets that they are rotations and ``field``
    works on small polynomials. The normal form is tried second because its
    ``autorewrite`` costs more CPU in ``coqc`` than the larger polynomials save.
    Otherwise with some rotations in quaternion parameters, or with their
    orthogonality as cofactors, or all in quaternion parameters.
    """
    if lhs.shape not in (SCALAR, VECTOR, MATRIX):
        raise CoqExportError("only scalars, vectors and matrices are compared")
    rotations = [sec.naming.variable(v) for v in variables_of(lhs, rhs)
                 if v.kind == "rotation"]
    attempts = []
    free_attempts = 0  # the first ones: with free matrices (the first that works as the
    # rotations stand; else the normal form with the smaller polynomials)
    if rotations and sec.gatoms is not None:
        free = [c for c in conds
                if not any(v.kind == "rotation" for v in variables_of(c.lhs, c.rhs))]
        prefix = [f"generalize (rot q_{n}) as G_{n}; intro G_{n}." for n in rotations]
        normals = []
        for hat, tactic in ((False, "so3_norm."), (True, "so3_norm_hat.")):
            try:
                normals.append((tactic, (normal_form(lhs, hat=hat), normal_form(rhs, hat=hat))))
            except CoqExportError:
                pass
        attempts.append((sec.gatoms, _generators(sec, sec.gatoms, free), prefix, True))
        for tactic, sides in normals:
            attempts.append((sec.gatoms, _generators(sec, sec.gatoms, free),
                             [tactic, *prefix], True, sides))
        free_attempts = len(attempts)
        ortho_prefix, ortho = [], []
        for n in rotations:
            ortho_prefix += [
                f"pose proof (rot_orthogonal q_{n} q_{n}_nonzero) as OL_{n}.",
                f"pose proof (rot_orthogonal_r q_{n} q_{n}_nonzero) as OR_{n}.",
                f"pose proof (rot_det q_{n} q_{n}_nonzero) as D_{n}.",
                f"revert OL_{n} OR_{n} D_{n}; generalize (rot q_{n}) as G_{n}; "
                f"intros G_{n} OL_{n} OR_{n} D_{n}."]
            ortho += _orthogonality(sec.gatoms, n)
        attempts += _mixed_attempts(sec, lhs, rhs, conds)
        attempts.append((sec.gatoms, ortho + _generators(sec, sec.gatoms, free),
                         ortho_prefix, False))
    attempts.append((sec.atoms, _generators(sec, sec.atoms, conds), [], True))
    failure = CoqExportError("no attempt")
    best: tuple[int, list[str]] | None = None
    for k, (atoms, gens, prefix, complete, *sides) in enumerate(attempts):
        a, b = sides[0] if sides else (lhs, rhs)
        left, right = entries(evaluate(a, atoms)), entries(evaluate(b, atoms))
        try:
            tactics = [_entry_tactic(atoms, x - y, gens, complete)
                       for x, y in zip(left, right, strict=True)]
        except CoqExportError as exc:
            failure = exc
            continue
        if lhs.shape == SCALAR:
            script = [*prefix, tactics[0]]
        else:
            script = prefix + ["so3_split."] + [f"- {t}" for t in tactics]
        size = sum(len(x.num.terms()) + len(y.num.terms())
                   for x, y in zip(left, right, strict=True))
        if best is None or size < best[0]:
            best = (size, script)
        if k == 0 or k >= free_attempts - 1:
            return _by_evaluator(sec, lhs, rhs, best[1])
    if best is not None:
        return _by_evaluator(sec, lhs, rhs, best[1])
    raise failure


#: The operations the prelude's evaluator reads (``SOSCert.sos_reify``).
_EVALUATED_OPS = frozenset({"var", "const", "identity", "zero", "lambda_min", "add", "neg",
                            "scale", "matmul", "transpose", "trace", "sk", "sym", "hat",
                            "vee", "dot", "outer"})
_EVALUATED_KINDS = frozenset({"rotation", "vector", "unit_vector", "scalar", "symmetric"})
_NORMAL_FORMS = ("so3_norm.", "so3_norm_hat.")
#: Steps with more rotations keep the normal form: the evaluator expands each rotation in
#: its quaternion's entries, and for three rotations its polynomials cost ``coqc``
#: more than ``so3_norm`` (measured on the paper's Theorem 1 steps).
EVALUATOR_ROTATIONS = 2


def _by_evaluator(sec: _Section, lhs: Expr, rhs: Expr, script: list[str]) -> list[str]:
    """``script`` or, when it is the matrix-level normal form followed by plain polynomial
    identities (no hypothesis but the rotations' non-zero norms), the prelude's evaluator
    first (``SOSCert.sos_eq``: both sides' entries as polynomials over products of
    quaternion norms, compared by ``vm_compute``; paper, Lemma 1 and Theorem 1 proofs),
    with ``script`` as the fallback should the evaluator not read a term. An identity of
    the normal form with the rotations free holds for every rotation ``rot q``, so the
    evaluator's comparison succeeds wherever ``script`` does."""
    if not script or script[0] not in _NORMAL_FORMS:
        return script
    rest = [line for line in script[1:] if not line.startswith("generalize (rot ")]
    if rest and rest[0] == "so3_split.":
        rest = rest[1:]
        if any(line != "- so3_poly." for line in rest):
            return script
        closer = "so3_split; so3_poly"
    elif rest == ["so3_poly."]:
        closer = "so3_poly"
    else:
        return script
    if any(node.op not in _EVALUATED_OPS for node in nodes(lhs, rhs)):
        return script
    used = variables_of(lhs, rhs)
    if any(v.kind not in _EVALUATED_KINDS for v in used):
        return script
    if sum(v.kind == "rotation" for v in used) > EVALUATOR_ROTATIONS:
        return script
    params, qs = _evaluator_params(sec)
    steps = [line.rstrip(".") for line in script if line.startswith(("so3_norm", "generalize"))]
    fallback = "; ".join([*steps, closer])
    listed = " :: ".join([*params, "nil"])
    positions = " :: ".join([*(f"{p}%nat" for p in qs), "nil"])
    return [f"first [ SOSCert.sos_eq ({listed})%list ({positions})%list | {fallback} ]."]


def _evaluator_params(sec: _Section) -> tuple[list[str], list[int]]:
    """The evaluator's parameters (``env``: every entry of the section's rotations'
    quaternions, vectors, scalars, symmetric matrices and lambda_min atoms) and the
    positions of the quaternions in it."""
    params: list[str] = []
    qs: list[int] = []
    for v in sec.variables_list:
        n = sec.naming.variable(v)
        if v.kind == "rotation":
            qs.append(len(params))
            params += [f"(q{c} q_{n})" for c in "wxyz"]
        elif v.kind in ("vector", "unit_vector"):
            params += [f"(v{i} {n})" for i in (1, 2, 3)]
        elif v.kind == "scalar":
            params.append(n)
        elif v.kind == "symmetric":
            params += [f"{n}_{ij}" for ij in ("11", "22", "33", "12", "13", "23")]
    for node in sec.lambda_nodes:
        lam = sec.naming.lambda_atom(node)
        if lam not in params:
            params.append(lam)
    return params, qs


#: Rotations a step may have for the attempts with some of them free (:func:`_mixed_attempts`).
MIXED_ROTATIONS = 3


def _mixed_attempts(sec: _Section, lhs: Expr, rhs: Expr, conds: list[Condition]) -> list:
    """Attempts keeping one rotation (then two) as a quaternion, the others free.

    Only for a step with at most :data:`MIXED_ROTATIONS` rotations (at most six
    attempts; the paper's steps have three): a step with more takes the attempts with
    orthogonality cofactors and then all rotations in quaternion parameters
    (:func:`_equality_script`), so the number of attempts never grows with the subsets
    of its rotations."""
    import itertools

    rots = [v for v in variables_of(lhs, rhs) if v.kind == "rotation"]
    out: list = []
    if len(rots) > MIXED_ROTATIONS:
        return out
    for size in range(1, len(rots)):
        for kept in itertools.combinations(rots, size):
            free_rots = frozenset(v.uid for v in sec.variables_list
                                  if v.kind == "rotation" and v not in kept)
            if free_rots not in sec.mixed:
                sec.mixed[free_rots] = atoms_for(sec.variables_list, sec.lambda_nodes,
                                                 sec.naming, generic=free_rots)
            atoms = sec.mixed[free_rots]
            usable = [c for c in conds if all(v.kind != "rotation" or v.uid not in free_rots
                                              for v in variables_of(c.lhs, c.rhs))]
            prefix = [f"generalize (rot q_{sec.naming.variable(v)}) as G_{sec.naming.variable(v)}; "
                      f"intro G_{sec.naming.variable(v)}." for v in rots if v not in kept]
            out.append((atoms, _generators(sec, atoms, usable), prefix, True))
    return out


def _orthogonality(atoms: Atoms, n: str) -> list[tuple]:
    """G^T G = I, G G^T = I (upper triangles) and det G = 1 of a generalised rotation."""
    g = [[atoms.gens[f"r{i}{j}_{n}"] for j in "123"] for i in "123"]
    out = []
    for side, hyp in (("left", f"OL_{n}"), ("right", f"OR_{n}")):
        for i in range(3):
            for j in range(i, 3):
                if side == "left":
                    e = sum(g[k][i] * g[k][j] for k in range(3))
                    term = f"(mmul (mT G_{n}) G_{n})"
                else:
                    e = sum(g[i][k] * g[j][k] for k in range(3))
                    term = f"(mmul G_{n} (mT G_{n}))"
                e = e - int(i == j)
                entry = f"m{i + 1}{j + 1}"
                out.append((atoms.poly(e), f"({entry} {term} - {entry} I3)",
                            f"(Rminus_diag_eq _ _ (f_equal {entry} {hyp}))"))
    det = (g[0][0] * (g[1][1] * g[2][2] - g[1][2] * g[2][1])
           - g[0][1] * (g[1][0] * g[2][2] - g[1][2] * g[2][0])
           + g[0][2] * (g[1][0] * g[2][1] - g[1][1] * g[2][0]))
    out.append((atoms.poly(det - 1), f"(det G_{n} - 1)", f"(Rminus_diag_eq _ _ D_{n})"))
    return out


def _entry_tactic(atoms: Atoms, diff, gens: list[tuple], complete: bool = True) -> str:
    num = diff.num
    if num == 0:
        return f"{_closer(atoms)}."
    values = [g[0] for g in gens]
    cof = cofactors(num, [v.num for v in values], complete=complete)
    if cof is None:
        raise CoqExportError("not an identity of rational functions, even with the unit "
                             "vectors', angles' and side conditions' equations (a lambda_min "
                             "merge, or a step the checker did not verify)")
    used = [(c, g) for c, g in zip(cof, gens, strict=True) if c != 0]
    den = denominator_text(diff.den, atoms)
    parts, proofs = [], []
    for c, (value, text, proof) in used:
        gden = denominator_text(value.den, atoms)
        parts.append(f"({_poly_text(c, atoms)} * ({gden}) / ({den})) * {text}")
        proofs.append(proof)
    return (f"apply (eq_by_sum _ _ ({' + '.join(parts)})); "
            f"[rewrite {', '.join(proofs)}; ring | {_closer(atoms)}].")


def _closer(atoms: Atoms) -> str:
    """The tactic deciding an entry: with a rotation in quaternion parameters, ``field``
    (its denominators are quaternion norms); otherwise the entry is an identity of
    polynomials with rational coefficients, which ``lra`` decides (nonlinear monomials
    are atoms to it) many times faster than ``field`` (``so3_poly`` in the prelude)."""
    return "so3_unfold; field; so3_nonzero" if atoms.rotations else "so3_poly"


def _inequality_script(sec: _Section, step: Step, gens: list[tuple]) -> list[str]:
    lines: list[str] = []
    names: dict[int, str] = {}
    top = [_term(sec, t, lines, names, gens) for t in step.because.terms]
    total = step.because.terms[0].value
    proof = top[0]
    for t, name in zip(step.because.terms[1:], top[1:], strict=True):
        total = total + t.value
        proof = f"(Rplus_le_le_0_compat _ _ {proof} {name})"
    slack = step.rhs - step.lhs if step.relation == "<=" else step.lhs - step.rhs
    lines.append(f"assert (E : {coq_text(slack, sec.naming)} = "
                 f"{coq_text(total, sec.naming)}).")
    lines.append("{ " + " ".join(_equality_script(sec, slack, total, gens)) + " }")
    lemma = "le_by_slack" if step.relation == "<=" else "ge_by_slack"
    lines.append(f"exact ({lemma} _ _ _ E {proof}).")
    return lines


def _term(sec: _Section, t: Nonneg, lines: list[str], names: dict[int, str],
          gens: list[tuple]) -> str:
    """Name of a hypothesis ``0 <= value of t`` asserted in ``lines``."""
    if id(t) in names:
        return names[id(t)]
    how = recipe(t)
    if how is None:
        raise CoqExportError("a non-negative term has no recipe")
    kind, args = how[0], how[1:]
    naming = sec.naming
    value = coq_text(t.value, naming)
    if kind in ("add", "mul"):
        a, b = (_term(sec, x, lines, names, gens) for x in args)
        lemma = "Rplus_le_le_0_compat" if kind == "add" else "Rmult_le_pos"
        proof = f"({lemma} _ _ {a} {b})"
    elif kind == "scale":
        c, x = args
        inner = _term(sec, x, lines, names, gens)
        proof = (f"(Rmult_le_pos {constant(Fraction(c))} {coq_text(x.value, naming)} "
                 f"ltac:(lra) {inner})")
    elif kind == "square":
        (g,) = args
        lemma = {MATRIX: "fro2_nonneg", VECTOR: "vdot_self_nonneg", SCALAR: "sq_nonneg"}
        proof = f"({lemma[g.shape]} {coq_text(g, naming)})"
    elif kind == "positive":
        proof = f"(Rlt_le _ _ {naming.variable(args[0].data)}_pos)"
    elif kind == "assumed":
        (a,) = args
        h = sec.assumptions[id(a)]
        proof = f"(Rlt_le _ _ {h})" if a.kind == "pos" else h
    elif kind == "trace_lower_bound":
        a, b, gram, scale = args
        psym = _premise(sec, lines, a.T, a, gens)
        c_text, c_proof = _scale(sec, scale, lines, names, gens)
        pgram = _premise(sec, lines, _sym(b), _gram(scale, gram), gens)
        lam = naming.lambda_atom(Expr("lambda_min", (a,), SCALAR))
        proof = (f"(trace_lower_bound {coq_text(a, naming)} {coq_text(b, naming)} "
                 f"{coq_text(gram, naming)} {c_text} {lam} {psym} {pgram} {c_proof} "
                 f"{lam}_spec)")
    elif kind == "trace_psd_product":
        a, b, a_psd, _a_gram, b_gram, b_scale = args
        if a_psd is None:
            raise CoqExportError("trace_psd_product with a_gram= is not exported")
        psym = _premise(sec, lines, a.T, a, gens)
        from verify.proof.expr import sym
        pa = _premise(sec, lines, a, sym(a_psd.expr), gens)
        c_text, c_proof = _scale(sec, b_scale, lines, names, gens)
        pgram = _premise(sec, lines, _sym(b), _gram(b_scale, b_gram), gens)
        lemma = "trace_pd_product" if a_psd.kind == "pd" else "trace_psd_assumed_product"
        proof = (f"({lemma} {coq_text(a, naming)} {coq_text(a_psd.expr, naming)} "
                 f"{coq_text(b, naming)} {coq_text(b_gram, naming)} {c_text} {psym} {pa} "
                 f"{sec.assumptions[id(a_psd)]} {pgram} {c_proof})")
    else:
        raise CoqExportError(f"no Coq lemma for the term {kind!r}")
    name = f"T{len(names) + 1}"
    names[id(t)] = name
    lines.append(f"assert ({name} : 0 <= {value}) by exact {proof}.")
    return name


def _sym(b: Expr) -> Expr:
    from verify.proof.expr import sym
    return sym(b)


def _gram(scale, gram: Expr) -> Expr:
    c = scale.value if isinstance(scale, Nonneg) else Fraction(scale)
    return c * (gram.T * gram)


def _scale(sec: _Section, scale, lines, names, gens) -> tuple[str, str]:
    if isinstance(scale, Nonneg):
        return coq_text(scale.value, sec.naming), _term(sec, scale, lines, names, gens)
    return constant(Fraction(scale)), "ltac:(lra)"


def _premise(sec: _Section, lines: list[str], lhs: Expr, rhs: Expr, gens) -> str:
    name = f"P{sum(1 for x in lines if x.startswith('assert (P')) + 1}"
    lines.append(f"assert ({name} : {coq_text(lhs, sec.naming)} = "
                 f"{coq_text(rhs, sec.naming)}).")
    script = _equality_script(sec, lhs, rhs, gens)
    lines.append("{ " + " ".join(script) + " }")
    return name
