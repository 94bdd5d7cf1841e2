"""Exact confirmation of a numerical counterexample to a step.

A candidate point from the falsifiers is rounded to rational parameters (a rational
quaternion gives an exactly orthogonal rotation, a rational stereographic pair an exact
unit vector). A side condition is then solved exactly for one parameter: a rational
root when the condition has one, otherwise a real algebraic number kept as its
minimal polynomial and an isolating interval. lambda_min of a rational symmetric
matrix is likewise the smallest root of its characteristic polynomial. The sign of the
step's slack at the point is decided by interval arithmetic over rationals, refining
the isolating intervals until zero is excluded. Only then is the point a counterexample.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import sympy as sp
from sympy import QQ

from verify.inputs.numbers import fraction
from verify.proof.evaluate import Algebra, to_float
from verify.proof.falsify import Point, Rejected, gen_index, solve_parameter
from verify.proof.problem import StepProblem, flatten, principal_minors

REFINEMENTS = 80


@dataclass
class Algebraic:
    """A real root of a square-free rational polynomial, isolated in [lo, hi]."""

    poly: sp.Poly
    lo: Fraction
    hi: Fraction

    def _sign(self, x: Fraction) -> int:
        v = self.poly.eval(sp.Rational(x.numerator, x.denominator))
        return int(sp.sign(v))

    def refine(self) -> None:
        if self.lo == self.hi:
            return
        s_lo = self._sign(self.lo)
        if s_lo == 0:
            self.hi = self.lo
            return
        mid = (self.lo + self.hi) / 2
        s_mid = self._sign(mid)
        if s_mid == 0:
            self.lo = self.hi = mid
        elif s_mid == s_lo:
            self.lo = mid
        else:
            self.hi = mid

    def describe(self) -> str:
        return f"root of {self.poly.as_expr()} in [{self.lo}, {self.hi}]"


def _isolated_roots(poly: sp.Poly) -> list[Algebraic]:
    poly = sp.Poly(sp.sqf_part(poly.as_expr()), *poly.gens)
    out = []
    for (lo, hi), _ in poly.intervals():
        a = Algebraic(poly, fraction(lo), fraction(hi))
        if a.lo != a.hi and (a._sign(a.lo) == 0 or a._sign(a.hi) == 0):
            root = a.lo if a._sign(a.lo) == 0 else a.hi
            a.lo = a.hi = root
        out.append(a)
    return out


def _interval_poly(poly, values: dict) -> tuple[Fraction, Fraction]:
    """Range of a polynomial over intervals {ring generator index: (lo, hi)} (exact)."""
    lo_sum, hi_sum = Fraction(0), Fraction(0)
    for monom, c in poly.terms():
        c = fraction(c)
        lo, hi = c, c
        for k, e in enumerate(monom):
            if not e:
                continue
            a, b = values[k]
            plo, phi = _interval_power(a, b, e)
            candidates = [lo * plo, lo * phi, hi * plo, hi * phi]
            lo, hi = min(candidates), max(candidates)
        lo_sum += lo
        hi_sum += hi
    return lo_sum, hi_sum


def _interval_power(a: Fraction, b: Fraction, e: int) -> tuple[Fraction, Fraction]:
    ends = [a**e, b**e]
    if e % 2 == 0 and a <= 0 <= b:
        return Fraction(0), max(ends)
    return min(ends), max(ends)


@dataclass
class ExactPoint:
    rationals: dict  # ring generator -> Fraction
    algebraic: dict  # ring generator -> Algebraic


def _to_qq(x: Fraction):
    return QQ(x.numerator, x.denominator)


def exact_point(problem: StepProblem, point: Point, limit: int = 10**6) -> ExactPoint | None:
    """Rational parameters near ``point`` (denominators <= limit); conditions solved exactly."""
    index = gen_index(problem)
    rationals = {}
    for gen, (uid, i) in index.items():
        x = float(point[uid][i])
        if not np.isfinite(x):
            return None
        rationals[gen] = Fraction(x).limit_denominator(limit)
    algebraic: dict = {}
    solved: set = set()
    for poly in problem.condition_polynomials:
        choice = solve_parameter(problem, poly, solved)
        if choice is None:
            if solved and solve_parameter(problem, poly) is not None:
                continue  # fixed by earlier conditions; declarations_hold decides
            return None
        gen = choice[0]
        solved.add(gen)
        target = rationals.pop(gen)
        rest = poly.subs([(g, _to_qq(v)) for g, v in rationals.items()])
        if any(rest.degree(g) > 0 for g in rest.ring.gens if g != gen):
            return None
        symbol = sp.Symbol("x")
        uni = sp.Poly(rest.as_expr().subs(gen.as_expr(), symbol), symbol)
        if uni.degree() < 1:
            return None
        roots = []
        for factor, _ in sp.factor_list(uni.as_expr())[1]:
            roots += _isolated_roots(sp.Poly(factor, symbol))
        if positive_gen(problem, gen):
            roots = [r for r in roots if r.hi > 0]
        if not roots:
            return None
        best = min(roots, key=lambda r: abs(to_float(r.lo + r.hi) / 2 - to_float(target)))
        if best.lo == best.hi:
            rationals[gen] = best.lo
        else:
            algebraic[gen] = best
    return ExactPoint(rationals, algebraic)


def _lambda_min_roots(problem: StepProblem, xp: ExactPoint) -> dict | None:
    out = {}
    subs = [(g, _to_qq(v)) for g, v in xp.rationals.items()]
    for atom in problem.space.atoms:
        gen = problem.space.atom_gens[_key(atom)]
        entries = problem.exact(atom.args[0])
        values = []
        for value in entries:
            num = value.num.subs(subs)
            den = value.denominator().subs(subs)
            if not num.is_ground or not den.is_ground or not den:
                return None  # depends on an algebraic parameter or another atom
            values.append(_rational(num.LC if num else 0) / _rational(den.LC))
        m = sp.Matrix(3, 3, values)
        lam = sp.Symbol("lam")
        charpoly = ((m + m.T) / 2).charpoly(lam)
        out[gen] = _isolated_roots(sp.Poly(charpoly.as_expr(), lam))[0]
    return out


def _rational(c) -> sp.Rational:
    f = fraction(QQ(c))
    return sp.Rational(f.numerator, f.denominator)


def _key(atom):
    from verify.proof.expr import structural_key

    return structural_key(atom.args[0])


def _sign_at(value, xp: ExactPoint, atoms: dict) -> int | None:
    """Exact sign (-1, 0 only if provably zero never, 1) of a KnownFraction, or None."""
    subs = [(g, _to_qq(v)) for g, v in xp.rationals.items()]
    num = value.num.subs(subs)
    den = value.denominator().subs(subs)
    if not num:
        return 0
    gens = num.ring.gens
    unknown = {**xp.algebraic, **atoms}
    if den.is_ground and not den:
        return None
    for _ in range(REFINEMENTS):
        boxes = {}
        for k, g in enumerate(gens):
            if g in unknown:
                boxes[k] = (unknown[g].lo, unknown[g].hi)
            elif num.degree(g) > 0 or den.degree(g) > 0:
                return None
        lo, hi = _interval_poly(num, boxes)
        dlo, _ = _interval_poly(den, boxes)
        if dlo > 0 and (lo > 0 or hi < 0):
            return 1 if lo > 0 else -1
        if all(a.lo == a.hi for a in unknown.values()):
            return 0 if lo == hi == 0 else None
        for a in unknown.values():
            a.refine()
    return None


@dataclass
class Counterexample:
    values: dict  # variable name -> description
    slack_sign: int
    entry: int
    algebraic: list[str]

    def to_json(self) -> dict:
        return {"values": self.values, "entry": self.entry, "algebraic": self.algebraic,
                "slack_sign": self.slack_sign}


def confirm(problem: StepProblem, point: Point) -> Counterexample | Rejected | None:
    """Decide a numerical violation at ``point`` exactly.

    Returns an exactly confirmed counterexample (a point meeting every declaration,
    condition and assumption exactly, where the step fails), :class:`Rejected` when the
    point rounded to rationals (denominators up to 10^6) meets every declaration and the
    step holds there exactly (the violation was float rounding), or None when neither
    could be decided. Short rationals are tried first, so a reported point is readable.
    """
    outcome = None
    for limit in (8, 100, 10**4, 10**6):
        outcome = _confirm_at(problem, point, limit)
        if isinstance(outcome, Counterexample):
            return outcome
    return outcome


def _confirm_at(problem: StepProblem, point: Point, limit: int
                ) -> Counterexample | Rejected | None:
    xp = exact_point(problem, point, limit)
    if xp is None:
        return None
    atoms = _lambda_min_roots(problem, xp)
    if atoms is None or not declarations_hold(problem, xp, atoms):
        return None
    decided = True
    for entry, value in enumerate(problem.exact_slack):
        sign = _sign_at(value, xp, atoms)
        if sign is None:
            decided = False
            continue
        failing = sign != 0 if problem.relation == "=" else sign < 0
        if failing:
            return Counterexample(_describe(problem, xp), sign, entry,
                                  [a.describe() for a in xp.algebraic.values()])
    return Rejected(limit) if decided else None


def exact_witness(problem: StepProblem, point: Point) -> bool:
    """A point near ``point`` (rationals, conditions solved exactly) meets every
    declaration, condition and assumption exactly: the premises are not vacuous."""
    for limit in (8, 100, 10**4, 10**6):
        xp = exact_point(problem, point, limit)
        if xp is None:
            continue
        atoms = _lambda_min_roots(problem, xp)
        if atoms is not None and declarations_hold(problem, xp, atoms):
            return True
    return False


def positive_gen(problem: StepProblem, gen) -> bool:
    """``gen`` is the parameter of a scalar declared positive."""
    return any(v.kind == "scalar" and v.positive and problem.space.param_gens[v.uid][0] == gen
               for v in problem.variables)


def _is_zero_at(value, xp: ExactPoint) -> bool:
    """Exactly zero at the point: zero after the rational substitution, or a multiple of
    the minimal polynomial of the single algebraic parameter it still involves."""
    subs = [(g, _to_qq(v)) for g, v in xp.rationals.items()]
    num = value.num.subs(subs)
    if not num:
        return True
    left = [g for g in num.ring.gens if num.degree(g) > 0]
    if len(left) != 1 or left[0] not in xp.algebraic:
        return False
    symbol = sp.Symbol("x")
    uni = sp.Poly(num.as_expr().subs(left[0].as_expr(), symbol), symbol)
    minimal = sp.Poly(xp.algebraic[left[0]].poly.as_expr(), symbol)
    return uni.rem(minimal).is_zero


def charts_defined(problem: StepProblem, xp: ExactPoint, atoms: dict) -> bool:
    """Every variable at the point is what its kind says: a rotation's quaternion is not
    0 (|q|^2 > 0, so R is a rotation), a unit vector has norm 1 (decided exactly). The
    half-angle and stereographic denominators 1 + t^2, 1 + a^2 + b^2 never vanish."""
    from verify.proof.exact import KnownFraction
    from verify.proof.expr import dot, var

    alg_den = problem.exact_slack[0].den
    for v in problem.variables:
        if v.kind == "rotation":
            q = problem.space.param_gens[v.uid]
            norm = sum((g * g for g in q[1:]), q[0] * q[0])
            if _sign_at(KnownFraction(norm, (), alg_den), xp, atoms) != 1:
                return False
        elif v.kind == "unit_vector":
            (value,) = problem.exact(dot(var(v), var(v)) - 1)
            if not _is_zero_at(value, xp):
                return False
    return True


def declarations_hold(problem: StepProblem, xp: ExactPoint, atoms: dict) -> bool:
    """Every declaration holds exactly at the point, all at once: every chart is defined
    there (:func:`charts_defined`), positive scalars are > 0, every side condition is 0,
    every assumption holds (pd by Sylvester's leading minors, psd by all principal
    minors)."""
    from verify.proof.exact import KnownFraction

    alg_den = problem.exact_slack[0].den
    if not charts_defined(problem, xp, atoms):
        return False
    for v in problem.variables:
        if v.kind == "scalar" and v.positive:
            gen = problem.space.param_gens[v.uid][0]
            if _sign_at(KnownFraction(gen, (), alg_den), xp, atoms) != 1:
                return False
    for c in problem.conditions:
        (value,) = problem.exact(c.difference)
        if not _is_zero_at(value, xp):
            return False
    for a in problem.assumptions:
        if a.kind in ("pos", "nonneg"):
            (value,) = problem.exact(a.expr)
            sign = _sign_at(value, xp, atoms)
            if sign is None or sign < 0 or (a.kind == "pos" and sign == 0):
                return False
            continue
        m = problem.exact(a.expr)
        half = Fraction(1, 2)
        s = [[(m[3 * i + j] + m[3 * j + i]) * half for j in range(3)] for i in range(3)]
        minors = principal_minors(s)
        keys = ((0,), (0, 1), (0, 1, 2)) if a.kind == "pd" else tuple(minors)
        for k in keys:
            sign = _sign_at(minors[k], xp, atoms)
            if sign is None or sign < 0 or (a.kind == "pd" and sign == 0):
                return False
    return True


def _describe(problem: StepProblem, xp: ExactPoint) -> dict:
    """Human-readable exact values of every variable at the point."""
    out = {}
    alg = _FloatAlgebra()
    for v in problem.variables:
        gens = problem.space.param_gens[v.uid]
        exact, approx = [], []
        for g in gens:
            if g in xp.rationals:
                exact.append(str(xp.rationals[g]))
                approx.append(to_float(xp.rationals[g]))
            else:
                a = xp.algebraic[g]
                exact.append(a.describe())
                approx.append(to_float(a.lo + a.hi) / 2)
        value = alg.bind(v, approx)
        if isinstance(value, tuple):  # angle: report theta
            value = 2 * float(np.arctan(approx[0]))
        name = v.name if v.name not in out else f"{v.name}#{v.uid}"  # same name twice
        out[name] = {
            "kind": v.kind,
            "parameters": exact,
            "approx_parameters": approx,
            "value": np.round(np.array(flatten(value) if isinstance(value, list) else value,
                                       dtype=float), 6).tolist(),
        }
    for name, where in problem.pinned_names.items():  # at the point its chart misses
        out[name] = {"kind": "chart gap", "parameters": [where], "approx_parameters": [],
                     "value": [3.141593] if where == "π" else [0.0, 0.0, 1.0]}
    return out


class _FloatAlgebra(Algebra):
    def const(self, value: Fraction):
        return to_float(value)
