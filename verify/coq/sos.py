"""Export of SOS certificates (``verify-sos-certificate/1``) to Coq, one unit each.

An SOS step of the paper (Lemma 1 and Theorem 1, the ``by_sos`` twins of the hand
steps, :mod:`verify.paper_proofs.sos_proofs`) claims ``lhs <= rhs`` (or ``>=``). Its
unit states that inequality with the prelude's definitions (``SO3.v``), printed from the
same expression trees the Python checker reads (:func:`verify.coq.terms.coq_text`), and
proves it from the certificate with the prelude ``SOSCert.v``:

1. **the certificate as data**: the target polynomial ``T`` over the parameters (a
   rotation's quaternion entries, a unit vector's stereographic pair, an angle's
   half-angle tangent, free entries, scalars, one real per lambda_min), and per block
   its multiplier ``H`` (a polynomial matrix) and squares ``(d, u)`` from an exact
   LDL^T of its Gram matrix (computed here, untrusted: Coq re-checks the identity);
2. **the identity** ``T = sum d * u^T H u`` with every ``d >= 0``, decided by
   ``vm_compute`` on the data (``cert_ok``, sound by ``sos_nonneg`` proved once);
3. **the multipliers' grounds**: each ``H`` is ``c * D * (sym A - lam I)``
   (lambda_min's hypothesis), ``c * D * sym M`` (an assumed ``pd``/``psd`` matrix) or
   ``c`` (a product of declared-positive scalars and assumed non-negative ones), with
   ``c >= 0`` from those hypotheses and ``D`` a product of norms ``|q|^2 > 0``;
4. **the link**: ``(rhs - lhs) * D = F * T`` at the parameters with ``D > 0``,
   ``F >= 0``, so the slack is ``>= 0`` and the step holds.

In a step over rotations, scalars and vectors (the Theorem 1 steps), 3 and 4 are proved
by computation: the tactic ``sos_reify`` reads the statement, as written with the
prelude's operations (``rot q``, ``mmul``, ``mT``, ``sk``, ``hat``, ``vee``, ``tr``,
``phi``, ``vdot``, ...), into an expression ``sx`` of those operations, without unfolding
them; Coq computes its value (each matrix subexpression once, as nine entry polynomials
over products of norms) and compares it with ``T`` (or ``H``'s entries) by ``vm_compute``
(``link_ok``, ``mult_psd_9r``: soundness proved once, ``ev_sound``). Otherwise (charts,
free matrices) ``field`` proves them after unfolding the prelude, or ``lra`` where there
is no rotation, chart, angle or denominator (the identities are then polynomial).

Charts. A unit vector ``xi`` is stated with the hypothesis ``xi = stereo a b`` and an
angle ``theta`` with ``cos theta``, ``sin theta`` given by ``t = tan(theta/2)``: the
theorem holds for every unit vector but the pole ``(0, 0, 1)`` and every angle but
``pi``. The Python checker covers those points by continuity; the kernel does not, and
each such unit says so. Rotations (quaternions) and free entries miss nothing.
"""

from __future__ import annotations

import functools
import json
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

from verify.coq.terms import (
    CoqExportError,
    Naming,
    ascii_identifier,
    assumption_hypothesis,
    coq_text,
)
from verify.coq.unit import CoqUnit, comment_text

HEADER = """From Coq Require Import Reals QArith List Lra.
From VerifyCoq Require Import SO3 SOSCert.
Import ListNotations.
Open Scope R_scope.
"""

UNFOLD = "cbv beta iota zeta delta [evalMZ qfR dotR map zeval meval hd tl env Qnum]"


@dataclass(frozen=True)
class SosStep:
    """A ``by_sos`` step and where it comes from (the hand derivation and step)."""

    derivation: object  # a one-step verify.proof Derivation (the SOS twin)
    original: str
    step: int


def unit_name(original: str, step: int) -> str:
    return f"sos_{ascii_identifier(original)}_step{step}"


def theorem_name(step: int) -> str:
    return f"step{step}_by_sos"


# -- exact LDL^T -------------------------------------------------------------------------
def ldl(gram: list[list[Fraction]]) -> list[tuple[Fraction, list[Fraction]]]:
    """Q = sum_l d_l v_l v_l^T exactly (unit lower-triangular columns v_l), or refuse.

    A zero pivot needs a zero remaining column; a negative pivot means Q is not PSD.
    """
    n = len(gram)
    a = [row[:] for row in gram]
    out: list[tuple[Fraction, list[Fraction]]] = []
    for j in range(n):
        d = a[j][j]
        if d < 0:
            raise CoqExportError("a Gram matrix is not PSD (negative LDL^T pivot)")
        if d == 0:
            if any(a[i][j] != 0 for i in range(j + 1, n)):
                raise CoqExportError("a Gram matrix is not PSD (zero pivot, non-zero column)")
            continue
        col = [Fraction(0)] * n
        col[j] = Fraction(1)
        for i in range(j + 1, n):
            col[i] = a[i][j] / d
        for i in range(j + 1, n):
            if col[i]:
                f = col[i] * d
                for k in range(j + 1, i + 1):
                    if col[k]:
                        a[i][k] -= f * col[k]
        # keep the trailing block symmetric (only the lower triangle was updated)
        for i in range(j + 1, n):
            for k in range(j + 1, i):
                a[k][i] = a[i][k]
        out.append((d, col))
    return out


# -- Coq text of data --------------------------------------------------------------------
def _q(c: Fraction) -> str:
    return f"({c.numerator}#{c.denominator})%Q" if c.denominator != 1 else \
        f"({c.numerator})%Q" if c < 0 else f"{c.numerator}%Q"


def _mono(m) -> str:
    return "[" + ";".join(str(int(k)) for k in m) + "]%nat"


def poly_data(p: dict) -> str:
    """A polynomial (exponent tuple -> rational) as SOSCert's ``poly`` (sorted terms)."""
    terms = sorted(p.items())
    return "[" + "; ".join(f"({_mono(m)}, {_q(Fraction(c))})" for m, c in terms) + "]"


# -- the unit ----------------------------------------------------------------------------
def sos_unit(step: SosStep, data: dict, *, file_label: str,
             module: str | None = None) -> CoqUnit:
    """The unit of one certificate (``data``, parsed JSON) for ``step`` (its module
    ``module``, by default named after the step)."""
    from verify.sos import poly as pl

    (st,) = step.derivation.steps
    problem, sp = _step_program(step)
    if tuple(data.get("variables", ())) != tuple(sp.program.variables):
        raise CoqExportError("the certificate's variables are not this step's parameters")
    n = len(sp.program.variables)
    naming = Naming()
    space = problem.space
    lines: list[str] = []
    env: list[str] = []
    factor_text = _chart_factors(naming, space)  # factor poly key -> (text, 0 < text)
    unfold_extra: list[str] = []
    rot_positions: dict[tuple, tuple[int, str]] = {}  # |q|^2 -> (env position, q <> 0)

    def key_of(poly) -> tuple:
        return tuple(sorted(pl.from_ring(poly).items()))

    for v in space.variables:
        nm = naming.variable(v)
        label = comment_text(v.name)
        g = space.param_gens[v.uid]
        if v.kind == "rotation":
            lines += [f"(** {label}: a rotation, rot q with |q|^2 <> 0 *)",
                      f"Variable q_{nm} : quat.",
                      f"Hypothesis q_{nm}_nonzero : qn q_{nm} <> 0.",
                      f"Local Notation {nm} := (rot q_{nm}).", ""]
            rot_positions[key_of(g[0] ** 2 + g[1] ** 2 + g[2] ** 2 + g[3] ** 2)] = (
                len(env), f"q_{nm}_nonzero")
            env += [f"(q{c} q_{nm})" for c in "wxyz"]
        elif v.kind == "unit_vector":
            a, b = f"a_{nm}", f"b_{nm}"
            lines += [f"(** {label}: a unit vector in the stereographic chart (every unit "
                      "vector but the pole (0, 0, 1)) *)",
                      f"Variable {nm} : V3.", f"Variables {a} {b} : R.",
                      f"Hypothesis {nm}_chart : {nm} = stereo {a} {b}.", ""]
            env += [a, b]
            unfold_extra.append(f"rewrite ?{nm}_chart; unfold stereo")
        elif v.kind == "angle":
            t = f"t_{nm}"
            lines += [f"(** {label}: an angle with tan({label}/2) = {t} (every angle but "
                      "pi) *)",
                      f"Variable {nm} : R.", f"Variable {t} : R.",
                      f"Hypothesis {nm}_cos : cos {nm} = (1 - {t} * {t}) / (1 + {t} * {t}).",
                      f"Hypothesis {nm}_sin : sin {nm} = 2 * {t} / (1 + {t} * {t}).", ""]
            env.append(t)
            unfold_extra.append(f"rewrite ?{nm}_cos, ?{nm}_sin")
        elif v.kind == "symmetric":
            parts = [f"{nm}_{ij}" for ij in ("11", "22", "33", "12", "13", "23")]
            lines += [f"(** {label}: a symmetric matrix, by its six entries *)",
                      f"Variables {' '.join(parts)} : R.",
                      f"Local Notation {nm} := (symm {' '.join(parts)}).", ""]
            env += parts
        elif v.kind == "matrix":
            lines += [f"(** {label}: a matrix *)", f"Variable {nm} : M3.", ""]
            env += [f"(m{i}{j} {nm})" for i in "123" for j in "123"]
        elif v.kind == "vector":
            lines += [f"(** {label}: a vector *)", f"Variable {nm} : V3.", ""]
            env += [f"(v{i} {nm})" for i in "123"]
        else:
            lines += [f"(** {label}: a scalar *)", f"Variable {nm} : R."]
            if v.positive:
                lines.append(f"Hypothesis {nm}_pos : 0 < {nm}.")
            lines.append("")
            env.append(nm)
    lam_specs: dict[tuple, str] = {}
    from verify.proof.expr import structural_key

    for atom in space.atoms:
        lam = naming.lambda_atom(atom)
        arg = coq_text(atom.args[0], naming)
        lines += [f"(** lambda_min({comment_text(str(atom.args[0]))}): a lower bound suffices *)",
                  f"Variable {lam} : R.",
                  f"Hypothesis {lam}_spec : lam_min_spec {arg} {lam}.", ""]
        env.append(lam)
        lam_specs[structural_key(atom.args[0])] = lam
    if len(env) != n:
        raise CoqExportError("the step's parameters do not match its variables")
    assumptions: dict[int, tuple[str, object]] = {}
    for k, a in enumerate(st.because.assumptions, start=1):
        name = f"assumption{k}"
        lines += assumption_hypothesis(name, a, naming)
        assumptions[id(a)] = (name, a)

    def product_text(exps: dict[tuple, int]) -> tuple[str, str, str]:
        """(text, proof of 0 < text, proof of 0 <= text) of a product of known factors."""
        found = _power_product(sorted(exps.items()), factor_text)
        if found is None:
            return "1", "Rlt_0_1", "Rle_0_1"
        text, proof = found
        return text, proof, f"(Rlt_le _ _ {proof})"

    def den_exps(kf) -> dict[tuple, int]:
        return {key_of(f): e for f, e in zip(kf.den.factors, kf.exps, strict=False) if e}

    # -- the slack and the link --------------------------------------------------------
    (slack,) = problem.exact_slack
    exps = den_exps(slack)
    target_poly = pl.from_json(data["target"], n, "target")
    divided = {tuple(sorted(f.items())): k for f, k in sp.factors}
    d_exps = {key: e - divided.get(key, 0) for key, e in exps.items()}
    f_exps = {key: k - exps.get(key, 0) for key, k in divided.items()}
    d_text, d_pos, _ = product_text({k: e for k, e in d_exps.items() if e > 0})
    f_text, _, f_nonneg = product_text({k: e for k, e in f_exps.items() if e > 0})
    lhs, rhs = coq_text(st.lhs, naming), coq_text(st.rhs, naming)
    slack_text = f"({rhs} + - {lhs})" if st.relation == "<=" else f"({lhs} + - {rhs})"
    statement = f"{lhs} <= {rhs}" if st.relation == "<=" else f"{lhs} >= {rhs}"

    # -- blocks: multipliers and squares -----------------------------------------------
    multipliers = _multiplier_plans(problem, st.because, naming, assumptions, lam_specs)
    reflective = all(v.kind in ("rotation", "scalar", "vector") for v in space.variables)
    positions = sorted(rot_positions.values())
    qs_text = "[" + "; ".join(str(pos) for pos, _ in positions) + "]%nat"
    hq_text = "".join(f"apply Forall_cons; [exact {h}|]; " for _, h in positions)
    rewrites = "".join(f"{r}; " for r in unfold_extra)
    # With no rotation (|q|^2), chart or angle and no denominator in the slack, every
    # identity below is polynomial once unfolded: lra decides it (a monomial is an atom)
    # many times faster than field; otherwise field, with the non-zero denominators.
    closer = ("lra" if not rot_positions and not unfold_extra and not any(exps.values())
              else "field; sos_nonzero")
    body: list[str] = []
    block_names: list[str] = []
    psd_proofs: list[str] = []
    raw_blocks = data.get("blocks")
    if not isinstance(raw_blocks, list) or not raw_blocks:
        raise CoqExportError("the certificate has no blocks")
    for b_index, b in enumerate(raw_blocks, start=1):
        grounds = b.get("grounds")
        plan = multipliers.get(grounds)
        if plan is None:
            raise CoqExportError(f"block {b_index}: multiplier {grounds!r} is not one this "
                                 "step allows")
        matrix = [[pl.from_json(e, n, "multiplier") for e in row] for row in b["multiplier"]]
        basis = [tuple(m) for m in b["basis"]]
        k = len(matrix)
        gram = [[Fraction(x) for x in row] for row in b["gram"]]
        if len(gram) != k * len(basis):
            raise CoqExportError(f"block {b_index}: Gram size is not multiplier x basis")
        squares = []
        for dval, col in ldl(gram):
            u = []
            for i in range(k):
                comp: dict = {}
                for a_idx, mono in enumerate(basis):
                    c = col[a_idx * k + i]
                    if c:
                        comp[mono] = comp.get(mono, 0) + c
                u.append(poly_data(comp))
            squares.append(f"({_q(dval)}, [{'; '.join(u)}])")
        hname, sname = f"H{b_index}", f"S{b_index}"
        rows = "; ".join("[" + "; ".join(poly_data(e) for e in row) + "]" for row in matrix)
        body += [f"(** block {b_index}: {comment_text(grounds)} *)",
                 f"Definition {hname} : list (list poly) := [{rows}].",
                 f"Definition {sname} : list (Q * list poly) :=",
                 "  [" + ";\n   ".join(squares) + "].", ""]
        block_names.append(f"(mkBlock {hname} {sname})")
        lemma = f"{hname}_psd"
        if k == 1 and not plan.matrix:
            body += [f"Lemma {lemma} : mult_psd env {hname}.", "Proof.",
                     f"  unfold {hname}. apply mult_psd_scalar.",
                     "  rewrite zeval_peval by (vm_compute; reflexivity).",
                     f"  match goal with |- 0 <= ?g => replace g with {plan.scalar} "
                     f"by ({UNFOLD}; {rewrites}so3_unfold; {closer}) end.",
                     f"  exact {plan.scalar_proof}.", "Qed.", ""]
        elif k == 3 and plan.matrix and reflective:
            d = [0] * len(env)
            for key, e in plan.den_exps:
                d[rot_positions[key][0]] = e
            body += [f"Lemma {lemma} : mult_psd env {hname}.", "Proof.",
                     f"  unfold {hname}. sos_psd9 [{'; '.join(env)}] ({plan.scalar}) "
                     f"{plan.matrix} [{'; '.join(map(str, d))}]%nat.",
                     f"  - exact {plan.scalar_proof}.", f"  - exact {plan.matrix_proof}.",
                     "Qed.", ""]
        elif k == 3 and plan.matrix:
            dtext, dpos = plan.den
            c_text = f"({plan.scalar} * {dtext})"
            c_proof = f"(Rmult_le_pos _ _ {plan.scalar_proof} {dpos})"
            q_fun = f"fun x1 x2 x3 => qform {plan.matrix} (mkV x1 x2 x3)"
            body += [f"Lemma {lemma} : mult_psd env {hname}.", "Proof.",
                     f"  apply (mult_psd_3 env {hname} {c_text} ({q_fun})).",
                     "  - reflexivity.", f"  - exact {c_proof}.",
                     f"  - intros x1 x2 x3. exact ({plan.matrix_proof} (mkV x1 x2 x3)).",
                     f"  - intros x1 x2 x3. rewrite (evalM_Z env {hname} (eq_refl true <: "
                     f"all_int_matrix {hname} = true)). unfold {hname}. {UNFOLD}. "
                     f"{rewrites}so3_unfold. {closer}.", "Qed.", ""]
        else:
            raise CoqExportError(f"block {b_index}: a multiplier of size {k} with grounds "
                                 f"{grounds!r} is not exported")
        psd_proofs.append(lemma)
    grounds_proof = "blocks_psd_nil env"
    for lemma, block in reversed(list(zip(psd_proofs, block_names, strict=True))):
        grounds_proof = f"blocks_psd_cons env {block} _ {lemma} ({grounds_proof})"
    thm = theorem_name(step.step)
    head = [f"(** SOS certificate {file_label}, exported to Coq.",
            f"    It proves step {step.step} of the derivation {step.original!r} "
            f"(verify.paper_proofs): {comment_text(str(st.lhs))} {st.relation} "
            f"{comment_text(str(st.rhs))}.",
            "    The certificate's data (target polynomial, multipliers, LDL^T squares) "
            "is re-checked by vm_compute (SOSCert.cert_ok); the multipliers' grounds and "
            "the link from the statement to the target polynomial are proved "
            + ("by computation (SOSCert.mult_psd_9r, SOSCert.link_ok)." if reflective
               else "by field."),
            ]
    if unfold_extra:
        head.append("    Charts: a unit vector is stated in its stereographic chart (all but "
                    "the pole (0, 0, 1)) and an angle by tan(theta/2) (all but pi); the "
                    "missed points are covered by the Python checker's continuity argument, "
                    "not by this theorem.")
    head[-1] += " *)"
    section = f"Sos_{ascii_identifier(step.original)}_{step.step}"
    proof = [
        f"Theorem {thm} : {statement}.",
        "Proof.",
        f"  apply ({'le' if st.relation == '<=' else 'ge'}_by_slack _ _ {slack_text}); "
        "[reflexivity|].",
        "  destruct link as (D & F & HD & HF & E).",
        "  exact (slack_nonneg _ D F _ E HD HF "
        "(sos_nonneg env target blocks cert_checked grounds)).",
        "Qed.", ""]
    link_head = [f"Lemma link : exists D F, 0 < D /\\ 0 <= F /\\ {slack_text} * D = "
                 "F * peval env target.", "Proof."]
    if reflective:
        fe = [0] * (max((pos for pos, _ in rot_positions.values()), default=0) + 1)
        for key, k in d_exps.items():
            if k > 0:
                fe[rot_positions[key][0]] = k
        qs, hq = qs_text, hq_text
        link = [
            "(** The link, by computation: the statement's slack, read as an expression of "
            "the prelude's operations (sos_reify), times a positive product of quaternion "
            "norms is the target polynomial at the parameters times a non-negative one. *)",
            *link_head,
            f"  assert (Hq : Forall (fun p => qnR env p <> 0) {qs}) by ({hq}apply Forall_nil).",
            f"  sos_link [{'; '.join(env)}] {qs} Hq [{'; '.join(map(str, fe))}]%nat.",
            "Qed.", ""]
    else:
        link = [
            f"(** The link: the slack of the statement times {comment_text(d_text)} is the "
            "target polynomial at the parameters (times the factors divided out of it), "
            "by field. *)",
            *link_head,
            f"  exists {d_text}, {f_text}. split; [exact {d_pos}|]. "
            f"split; [exact {f_nonneg}|].",
            "  rewrite (zeval_peval env target (eq_refl true <: all_int target = true)).",
            f"  unfold target. {UNFOLD}. {rewrites}so3_unfold. {closer}.",
            "Qed.", ""]
    text = "\n".join([
        *head, "", HEADER, f"Section {section}.", "", *lines,
        f"Let env : list R := [{'; '.join(env)}].", "",
        f"Definition target : poly := {poly_data(target_poly)}.", "",
        *body,
        f"Definition blocks : list block := [{'; '.join(block_names)}].", "",
        "Lemma cert_checked : cert_ok target blocks = true.",
        # the check is evaluated once, by the kernel at Qed (vm_compute in the proof
        # would evaluate it a second time)
        "Proof. vm_cast_no_check (eq_refl true). Qed.", "",
        "Lemma grounds : blocks_psd env blocks.",
        f"Proof. exact ({grounds_proof}). Qed.", "",
        *link,
        *proof,
        f"End {section}.", ""])
    return CoqUnit(module or unit_name(step.original, step.step), text, (thm,), file_label)


@dataclass(frozen=True)
class _Plan:
    """How a multiplier's grounds are proved: a non-negative scalar ``scalar`` (with its
    proof) times, for a 3 x 3 multiplier, ``den`` (the lifted denominator of the matrix,
    exponents by chart factor) times ``matrix`` whose quadratic form is non-negative by
    ``matrix_proof``."""

    scalar: str
    scalar_proof: str
    matrix: str = ""
    matrix_proof: str = ""
    den: tuple[str, str] = ("1", "Rle_0_1")  # text, proof 0 <= text
    den_exps: tuple[tuple[tuple, int], ...] = ()


def _multiplier_plans(problem, because, naming: Naming, assumptions,
                      lam_specs) -> dict[str, _Plan]:
    """Every multiplier the step allows, by its grounds, with how Coq proves it PSD.

    Mirrors :func:`verify.proof.sos_step.step_program`; Coq re-checks every link, so a
    mismatch here makes ``coqc`` fail, never accept.
    """
    import itertools

    from verify.proof.expr import structural_key, sym, variables_of
    from verify.proof.sos_step import MAX_PRODUCT, PARTIAL_CHARTS, _lifted
    from verify.sos import poly as pl

    space = problem.space
    scalars: list[tuple[str, str, str]] = []  # grounds, Coq text, proof 0 <= text

    def den_of(kfs):
        _nums, den = _lifted(kfs)
        exps = tuple((tuple(sorted(pl.from_ring(f).items())), e)
                     for f, e in zip(den.den.factors, den.exps, strict=False) if e)
        return _den_text(den, naming, space), exps

    for v in space.variables:
        if v.kind == "scalar" and v.positive:
            nm = naming.variable(v)
            scalars.append((f"{v.name} > 0 (declared)", nm, f"(Rlt_le _ _ {nm}_pos)"))
    matrices: list[tuple] = []  # grounds, matrix, its proof, den, den exps
    for a in because.assumptions:
        partial = sorted({v.name for v in variables_of(a.expr) if v.kind in PARTIAL_CHARTS})
        if partial:
            continue
        name, _ = assumptions[id(a)]
        e = coq_text(a.expr, naming)
        if a.kind in ("pos", "nonneg"):
            (value,) = problem.exact(a.expr)
            dtext, dpos = _den_text(value, naming, space)
            hyp = f"(Rlt_le _ _ {name})" if a.kind == "pos" else name
            text = e if dtext == "1" else f"({e} * {dtext})"
            proof = hyp if dtext == "1" else f"(Rmult_le_pos _ _ {hyp} {dpos})"
            scalars.append((f"assumed: {a.label}", text, proof))
        else:
            den, exps = den_of(problem.exact(sym(a.expr)))
            hyp = f"(pd_psd _ {name})" if a.kind == "pd" else name
            matrices.append((f"assumed: {a.label}", f"(sym {e})", hyp, den, exps))
    for atom in space.atoms:
        arg = atom.args[0]
        if all(v.is_zero() for v in problem.exact(arg - arg.T)):
            lam = lam_specs[structural_key(arg)]
            den, exps = den_of(problem.exact(arg))
            matrices.append((f"spectral: {atom} I ⪯ {arg} (symmetric)",
                             f"(msub (sym {coq_text(arg, naming)}) (mscale {lam} I3))",
                             f"{lam}_spec", den, exps))
    prods: list[tuple[str, str, str]] = []
    for size in range(1, MAX_PRODUCT + 1):
        for combo in itertools.combinations(scalars, size):
            text, proof = combo[0][1], combo[0][2]
            for _, t2, p2 in combo[1:]:
                text, proof = f"({text} * {t2})", f"(Rmult_le_pos _ _ {proof} {p2})"
            prods.append((" × ".join(g for g, _, _ in combo), text, proof))
    plans = {"1 (plain SOS)": _Plan("1", "Rle_0_1")}
    for grounds, text, proof in prods:
        plans[grounds] = _Plan(text, proof)
    for mg, mtext, mproof, den, exps in matrices:
        plans[mg] = _Plan("1", "Rle_0_1", mtext, mproof, den, exps)
        for grounds, text, proof in prods:
            plans[f"{grounds} × {mg}"] = _Plan(text, proof, mtext, mproof, den, exps)
    return plans


def _chart_factors(naming: Naming, space) -> dict[tuple, tuple[str, str]]:
    """The denominators the parametrisations bring (|q|^2 of a rotation, 1 + a^2 + b^2 of
    a unit vector's chart, 1 + t^2 of an angle's), each by its polynomial's key: its Coq
    text and the prelude's proof that it is positive."""
    from verify.sos import poly as pl

    def key_of(poly) -> tuple:
        return tuple(sorted(pl.from_ring(poly).items()))

    known: dict[tuple, tuple[str, str]] = {}
    for v in space.variables:
        nm = naming.variable(v)
        g = space.param_gens[v.uid]
        if v.kind == "rotation":
            w, x, y, z = g
            known[key_of(w * w + x * x + y * y + z * z)] = (
                f"(qn q_{nm})", f"(qn_pos q_{nm} q_{nm}_nonzero)")
        elif v.kind == "unit_vector":
            known[key_of(1 + g[0] ** 2 + g[1] ** 2)] = (
                f"(1 + a_{nm} * a_{nm} + b_{nm} * b_{nm})", f"(chart_den_pos a_{nm} b_{nm})")
        elif v.kind == "angle":
            known[key_of(1 + g[0] ** 2)] = (f"(1 + t_{nm} * t_{nm})", f"(angle_den_pos t_{nm})")
    return known


def _power_product(exps, known: dict[tuple, tuple[str, str]]) -> tuple[str, str] | None:
    """(text, proof of 0 < text) of the product of ``known`` factors to the powers
    ``exps`` ((key, exponent) pairs, in the order given; exponents <= 0 left out), or None
    for the empty product."""
    parts, proofs = [], []
    for key, e in exps:
        if e <= 0:
            continue
        if key not in known:
            raise CoqExportError("a denominator factor of no known chart")
        text, proof = known[key]
        parts.append(f"{text} ^ {e}")
        proofs.append(f"(pow_lt _ {e} {proof})")
    if not parts:
        return None
    # one factor is parenthesised too: a tactic's term list ("exists t, 1") takes no
    # bare "x ^ e"
    text, proof = (parts[0] if len(parts) > 1 else f"({parts[0]})"), proofs[0]
    for t2, p2 in zip(parts[1:], proofs[1:], strict=True):
        text, proof = f"({text} * {t2})", f"(Rmult_lt_0_compat _ _ {proof} {p2})"
    return text, proof


def _den_text(kf, naming: Naming, space) -> tuple[str, str]:
    """(text, proof of 0 <= text) of a known fraction's denominator."""
    from verify.sos import poly as pl

    exps = [(tuple(sorted(pl.from_ring(f).items())), e)
            for f, e in zip(kf.den.factors, kf.exps, strict=False)]
    found = _power_product(exps, _chart_factors(naming, space))
    if found is None:
        return "1", "Rle_0_1"
    text, proof = found
    return text, f"(Rlt_le _ _ {proof})"


# -- the paper's certificates ------------------------------------------------------------
def paper_sos_steps() -> list[SosStep]:
    """The ``by_sos`` twins of the paper's hand inequality steps (built once per
    process: they are the package's own, fixed objects)."""
    return list(_paper_sos_steps())


@functools.cache
def _paper_sos_steps() -> tuple[SosStep, ...]:
    from verify.paper_proofs.sos_proofs import sos_reproofs

    return tuple(SosStep(r.derivation, r.original, r.step) for r in sos_reproofs())


#: Each step's SOS program by the step object's identity (the object kept with it, so an
#: identity is never reused while its entry stands).
_PROGRAMS: dict[int, tuple[SosStep, object]] = {}


def _step_program(step: SosStep):
    """The step's problem and SOS program (:func:`verify.proof.sos_step.step_program`),
    formed once per step object: naming its certificate, comparing its statement and
    writing its unit all read the same pair."""
    from verify.proof.checker import step_problem
    from verify.proof.sos_step import step_program

    hit = _PROGRAMS.get(id(step))
    if hit is None or hit[0] is not step:
        d = step.derivation
        (st,) = d.steps
        problem = step_problem(d, st)
        hit = (step, (problem, step_program(problem, st.because)))
        _PROGRAMS[id(step)] = hit
    return hit[1]


def certificate_for(step: SosStep, folder: Path) -> Path:
    """The stored certificate file of a step (named by its claim key)."""
    from verify.sos.certificate import claim_key, file_name

    return Path(folder) / file_name(claim_key(_step_program(step)[1]))


def _statement_edited(step: SosStep, data: dict) -> str:
    """Why the certificate's written statement is not the step's (the paper's labels are
    the package's own, so it is written with them), or ""."""
    import dataclasses

    from verify.sos.certificate import statement_edited

    sp = _step_program(step)[1]
    return statement_edited(data, dataclasses.replace(sp, statement=sp.labelled))


def paper_sos_units(folder: Path) -> tuple[list[CoqUnit], dict[str, str]]:
    """Units of the paper's SOS certificates found in ``folder``, and every such file by
    name: its unit's theorem (``Module.theorem``), or why it was refused (a certificate
    that is not PSD, of another step, malformed), prefixed ``refused: ``."""
    units: list[CoqUnit] = []
    outcome: dict[str, str] = {}
    for step in paper_sos_steps():
        path = certificate_for(step, folder)
        if not path.is_file():
            continue
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
            edited = _statement_edited(step, data)
            if edited:
                outcome[path.name] = f"refused: {edited}"
                continue
            unit = sos_unit(step, data, file_label=path.name)
        except CoqExportError as exc:
            outcome[path.name] = f"refused: {exc}"
            continue
        except (OSError, UnicodeDecodeError, ValueError, KeyError, TypeError,
                AttributeError, IndexError) as exc:
            outcome[path.name] = f"refused: malformed SOS certificate ({type(exc).__name__})"
            continue
        units.append(unit)
        outcome[path.name] = f"{unit.name}.{unit.theorems[0]}"
    return units, outcome


__all__ = ["SosStep", "certificate_for", "ldl", "paper_sos_steps", "paper_sos_units",
           "poly_data", "sos_unit", "theorem_name", "unit_name"]
