"""Numerical falsification of a step: random points, hypothesis, and IPOPT (untrusted).

Three searches look for a point where a step fails: a batch of random and adversarial
points (Haar rotations, rotations near the identity and near angle pi, boundary points);
a hypothesis search over parameters that favours special values (0, +-1, tiny, huge),
which often lands on exactly representable counterexamples; and, for inequality steps,
IPOPT through CasADi minimising the slack from several starts, subject to the step's
side conditions and assumptions. Side conditions are met by solving them for one
parameter. Every candidate is handed to :mod:`verify.proof.confirm`, which decides it
exactly; a candidate that cannot be confirmed is reported, never turned into a verdict.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import casadi as ca
import numpy as np
from hypothesis import HealthCheck, find, settings
from hypothesis import strategies as st
from hypothesis.errors import NoSuchExample

from verify.proof.algebras import CasadiAlgebra, det3
from verify.proof.evaluate import NumpyAlgebra, evaluate, to_float
from verify.proof.expr import Variable, lambda_min
from verify.proof.problem import StepProblem, flatten

Point = dict[int, np.ndarray]  # variable uid -> parameter vector

RELATIVE_TOLERANCE = 1e-8


@dataclass
class SearchSettings:
    samples: int = 256
    hypothesis_examples: int = 60
    ipopt_starts: int = 3
    seed: int = 0


@dataclass
class SearchReport:
    random_points: int = 0
    hypothesis_examples: int = 0
    ipopt_runs: int = 0
    worst_violation: float = -math.inf
    candidates: list[Point] = field(default_factory=list)
    feasible: int = 0  # sampled points meeting every condition and assumption (floats)
    feasible_points: list[Point] = field(default_factory=list)  # a few of them
    rejected: int = 0  # numerical violations that exact arithmetic showed to be rounding
    undecided: int = 0  # numerical violations exact arithmetic could not decide

    def merge(self, other: SearchReport) -> None:
        self.random_points += other.random_points
        self.hypothesis_examples += other.hypothesis_examples
        self.ipopt_runs += other.ipopt_runs
        self.worst_violation = max(self.worst_violation, other.worst_violation)
        self.candidates += other.candidates
        self.feasible += other.feasible
        self.feasible_points += other.feasible_points
        self.rejected += other.rejected
        self.undecided += other.undecided

    def to_json(self) -> dict:
        return {
            "random_points": self.random_points,
            "hypothesis_examples": self.hypothesis_examples,
            "ipopt_runs": self.ipopt_runs,
            "feasible_points": self.feasible,
            "violations_rejected_exactly": self.rejected,
            "violations_undecided": self.undecided,
            "worst_relative_violation": (
                None if not np.isfinite(self.worst_violation) else float(self.worst_violation)
            ),
        }


# -- sampling ----------------------------------------------------------------------------
def sample_parameters(variables: list[Variable], n: int, rng: np.random.Generator) -> dict:
    """n parameter vectors per variable: generic and adversarial mixtures."""
    out = {}
    for v in variables:
        if v.kind == "rotation":
            q = rng.normal(size=(n, 4))
            third = n // 3
            q[:third, 0] *= 1e3  # near the identity
            q[third : 2 * third, 0] *= 1e-3  # near angle pi
            out[v.uid] = q
        elif v.kind == "unit_vector":
            u = rng.normal(size=(n, 3))
            u /= np.linalg.norm(u, axis=1, keepdims=True)
            out[v.uid] = u[:, :2] / (1.0 - u[:, 2:3])
        elif v.kind == "angle":
            out[v.uid] = np.tan(rng.uniform(-np.pi, np.pi, size=(n, 1)) / 2)
        elif v.kind == "scalar" and v.positive:
            out[v.uid] = np.exp(rng.normal(scale=1.5, size=(n, 1)))
        else:
            scale = np.exp(rng.normal(scale=1.0, size=(n, 1)))
            out[v.uid] = rng.normal(size=(n, v.parameter_count)) * scale
    return out


def gen_index(problem: StepProblem) -> dict:
    """ring generator -> (variable uid, parameter index)."""
    index = {}
    for v in problem.variables:
        for i, g in enumerate(problem.space.param_gens[v.uid]):
            index[g] = (v.uid, i)
    return index


def solve_parameter(problem: StepProblem, poly, exclude=()) -> tuple | None:
    """Choose the parameter to solve a condition for: lowest positive degree, angles first.

    None when the condition involves a lambda_min atom (not a polynomial in the
    parameters) or only parameters in ``exclude`` (already fixed by another condition).
    """
    index = gen_index(problem)
    if any(poly.degree(g) > 0 for g in poly.ring.gens if g not in index):
        return None
    kinds = {v.uid: v.kind for v in problem.variables}
    best = None
    for gen, (uid, i) in index.items():
        deg = poly.degree(gen)
        if deg < 1 or gen in exclude:
            continue
        rank = (0 if kinds[uid] == "angle" else 1, deg)
        if best is None or rank < best[0]:
            best = (rank, gen, uid, i)
    return None if best is None else best[1:]


def _univariate_coefficients(poly, gen, params: dict, index: dict, n: int) -> np.ndarray:
    """Coefficients (n, deg+1), highest first, of poly in ``gen`` at the other parameters."""
    j = poly.ring.gens.index(gen)
    deg = poly.degree(gen)
    coeffs = np.zeros((n, deg + 1))
    for monom, c in poly.terms():
        term = np.full(n, to_float(c))
        for k, e in enumerate(monom):
            if e and k != j:
                uid, i = index[poly.ring.gens[k]]
                term = term * params[uid][:, i] ** e
        coeffs[:, deg - monom[j]] += term
    return coeffs


def apply_conditions(problem: StepProblem, params: dict, rng) -> np.ndarray:
    """Solve the side conditions, each for a parameter no earlier condition fixed.

    Returns the mask of usable samples: those where every condition holds afterwards
    (checked together, to float accuracy) and every positive scalar is positive.
    """
    n = next(iter(params.values())).shape[0] if params else 1
    ok = np.ones(n, dtype=bool)
    index = gen_index(problem)
    positive = {uid for uid, v in ((v.uid, v) for v in problem.variables)
                if v.kind == "scalar" and v.positive}
    solved: set = set()
    for poly in problem.condition_polynomials:
        choice = solve_parameter(problem, poly, solved)
        if choice is None:
            if solved and solve_parameter(problem, poly) is not None:
                continue  # fixed by earlier conditions; the joint check below decides
            return np.zeros(n, dtype=bool)
        gen, uid, i = choice
        solved.add(gen)
        coeffs = _univariate_coefficients(poly, gen, params, index, n)
        for s in range(n):
            if not ok[s] or not np.all(np.isfinite(coeffs[s])):
                ok[s] = False
                continue
            c = np.trim_zeros(coeffs[s], "f")
            if len(c) < 2:
                ok[s] = False
                continue
            roots = np.roots(c)
            real = roots[np.abs(roots.imag) <= 1e-9 * (1 + np.abs(roots.real))].real
            if uid in positive:
                real = real[real > 0]
            if real.size == 0:
                ok[s] = False
                continue
            pick = rng.integers(real.size) if rng is not None else int(np.argmin(np.abs(real)))
            params[uid][s, i] = real[pick]
    if problem.conditions and ok.any():
        diffs = [c.difference for c in problem.conditions]
        sides = [e for c in problem.conditions for e in (c.lhs, c.rhs)]
        with np.errstate(all="ignore"):
            values = numeric_values(problem, params, diffs + sides)
        for k in range(len(diffs)):
            size = 1 + np.abs(values[len(diffs) + 2 * k][0]) + np.abs(
                values[len(diffs) + 2 * k + 1][0])
            ok &= np.abs(values[k][0]) <= 1e-7 * size
    return ok


def numeric_values(problem: StepProblem, params: dict, exprs) -> list:
    alg = NumpyAlgebra(next(iter(params.values())).shape[0] if params else 1)
    env = {v.uid: alg.bind(v, [params[v.uid][:, i] for i in range(v.parameter_count)])
           for v in problem.variables}
    return [[np.asarray(x, dtype=float) for x in flatten(evaluate(e, alg, env))] for e in exprs]


def assumptions_hold(problem: StepProblem, params: dict) -> np.ndarray:
    n = next(iter(params.values())).shape[0] if params else 1
    ok = np.ones(n, dtype=bool)
    if not problem.assumptions:
        return ok
    # a matrix assumption is about lambda_min of its symmetric part, as the algebra computes it
    exprs = [lambda_min(a.expr) if a.kind in ("pd", "psd") else a.expr
             for a in problem.assumptions]
    for a, (x,) in zip(problem.assumptions, numeric_values(problem, params, exprs), strict=True):
        threshold = {"pd": 1e-9, "pos": 1e-12}.get(a.kind)
        ok &= x > threshold if threshold is not None else x >= 0
    return ok


def relative_violation(problem: StepProblem, params: dict) -> np.ndarray:
    """> 0 where the step fails by more than the relative tolerance (NaN -> -inf)."""
    slack, lhs, rhs = numeric_values(problem, params, [problem.slack_expr, problem.lhs,
                                                       problem.rhs])
    size = 1.0 + np.max(np.abs(np.stack(lhs)), axis=0) + np.max(np.abs(np.stack(rhs)), axis=0)
    s = np.stack(slack)
    if problem.relation == "=":
        bad = np.max(np.abs(s), axis=0) / size
    else:
        bad = -s[0] / size
    out = bad - RELATIVE_TOLERANCE
    return np.where(np.isfinite(out), out, -np.inf)


def _point(params: dict, s: int) -> Point:
    return {uid: np.array(p[s], dtype=float) for uid, p in params.items()}


# -- searches ----------------------------------------------------------------------------
def random_search(problem: StepProblem, cfg: SearchSettings, report: SearchReport) -> None:
    rng = np.random.default_rng(cfg.seed)
    params = sample_parameters(problem.variables, cfg.samples, rng)
    ok = apply_conditions(problem, params, rng) & assumptions_hold(problem, params)
    report.random_points += int(ok.sum())
    report.feasible += int(ok.sum())
    report.feasible_points += [_point(params, int(k)) for k in np.flatnonzero(ok)[:3]]
    if not ok.any():
        return
    viol = np.where(ok, relative_violation(problem, params), -np.inf)
    report.worst_violation = max(report.worst_violation, float(np.max(viol)))
    for s in np.argsort(-viol)[:3]:
        if viol[s] > 0:
            report.candidates.append(_point(params, int(s)))


_SPECIAL = [0.0, 1.0, -1.0, 2.0, -2.0, 0.5, 1e-4, -1e-4, 1e4]


def hypothesis_search(problem: StepProblem, cfg: SearchSettings, report: SearchReport) -> None:
    """hypothesis.find over parameters with special values; shrinks to simple points."""
    sizes = [(v.uid, v.parameter_count) for v in problem.variables]
    total = sum(c for _, c in sizes)
    coordinate = st.one_of(
        st.sampled_from(_SPECIAL), st.floats(-3, 3, allow_nan=False, allow_infinity=False)
    )
    positive = st.one_of(st.sampled_from([1.0, 2.0, 0.5, 1e-3, 1e3]), st.floats(1e-3, 1e3))
    kinds = [v for v in problem.variables for _ in range(v.parameter_count)]
    strategy = st.tuples(*[
        positive if (v.kind == "scalar" and v.positive) else coordinate for v in kinds
    ]) if total else st.just(())
    rng = None  # deterministic root choice, as hypothesis needs for shrinking
    seen, feasible = [0], [0]

    def params_of(values) -> dict:
        out, k = {}, 0
        for uid, c in sizes:
            out[uid] = np.array([values[k : k + c]], dtype=float)
            k += c
        return out

    def fails(values) -> bool:
        seen[0] += 1
        params = params_of(values)
        try:
            with np.errstate(all="ignore"):
                if not apply_conditions(problem, params, rng)[0]:
                    return False
                if not assumptions_hold(problem, params)[0]:
                    return False
                feasible[0] += 1
                if len(report.feasible_points) < 6:
                    report.feasible_points.append(_point(params, 0))
                return bool(relative_violation(problem, params)[0] > 0)
        except (ZeroDivisionError, FloatingPointError, np.linalg.LinAlgError, RecursionError):
            return False

    try:
        found = find(
            strategy,
            fails,
            settings=settings(
                max_examples=cfg.hypothesis_examples,
                database=None,
                derandomize=True,
                suppress_health_check=list(HealthCheck),
                deadline=None,
            ),
        )
    except NoSuchExample:
        found = None
    report.hypothesis_examples += seen[0]
    report.feasible += feasible[0]
    if found is not None:
        params = params_of(found)
        apply_conditions(problem, params, rng)
        report.candidates.insert(0, _point(params, 0))


def ipopt_search(problem: StepProblem, cfg: SearchSettings, report: SearchReport) -> None:
    """Minimise the slack of an inequality step with IPOPT from a few feasible starts."""
    if problem.relation == "=" or not problem.variables:
        return
    sizes = [(v, v.parameter_count) for v in problem.variables]
    x = ca.SX.sym("x", sum(c for _, c in sizes))
    alg, env, k = CasadiAlgebra(), {}, 0
    lower, upper = [], []
    for v, c in sizes:
        env[v.uid] = alg.bind(v, [x[k + i] for i in range(c)])
        lo, hi = (1e-3, 1e3) if (v.kind == "scalar" and v.positive) else (-5.0, 5.0)
        lower += [lo] * c
        upper += [hi] * c
        k += c
    (slack,) = flatten(evaluate(problem.slack_expr, alg, env))
    g, glo, ghi = [], [], []
    for cond in problem.conditions:
        (d,) = flatten(evaluate(cond.difference, alg, env))
        g.append(d)
        glo.append(0.0)
        ghi.append(0.0)
    for a in problem.assumptions:
        value = evaluate(a.expr, alg, env)
        for m in _assumption_constraints(a.kind, value):
            g.append(m)
            glo.append(1e-9 if a.kind in ("pd", "pos") else 0.0)
            ghi.append(ca.inf)
    nlp = {"x": x, "f": slack, "g": ca.vertcat(*g) if g else ca.SX(0, 1)}
    solver = ca.nlpsol(
        "slack", "ipopt", nlp,
        {"ipopt.print_level": 0, "print_time": False, "ipopt.sb": "yes",
         "ipopt.max_iter": 150},
    )
    rng = np.random.default_rng(cfg.seed + 2)
    params = sample_parameters(problem.variables, 64, rng)
    ok = apply_conditions(problem, params, rng) & assumptions_hold(problem, params)
    starts = np.flatnonzero(ok)[: cfg.ipopt_starts]
    for s in starts:
        x0 = np.concatenate([params[v.uid][s] for v, _ in sizes])
        x0 = np.clip(x0, lower, upper)
        try:
            sol = solver(x0=x0, lbx=lower, ubx=upper, lbg=glo, ubg=ghi)
        except RuntimeError:
            continue
        report.ipopt_runs += 1
        xs = np.asarray(sol["x"]).ravel()
        point, k = {}, 0
        for v, c in sizes:
            point[v.uid] = xs[k : k + c][None, :]
            k += c
        with np.errstate(all="ignore"):
            if not (assumptions_hold(problem, point)[0]):
                continue
            viol = relative_violation(problem, point)[0]
        report.worst_violation = max(report.worst_violation, float(viol))
        if viol > 0:
            report.candidates.append({uid: p[0] for uid, p in point.items()})


def _assumption_constraints(kind: str, value) -> list:
    if kind in ("pos", "nonneg"):
        return [value]
    m = [[0.5 * (value[i][j] + value[j][i]) for j in range(3)] for i in range(3)]
    m1 = m[0][0]
    m2 = m[0][0] * m[1][1] - m[0][1] * m[1][0]
    det = det3(m)
    if kind == "pd":
        return [m1, m2, det]  # Sylvester's criterion
    minors2 = [m2, m[0][0] * m[2][2] - m[0][2] ** 2, m[1][1] * m[2][2] - m[1][2] ** 2]
    return [m[0][0], m[1][1], m[2][2], *minors2, det]


def search(problem: StepProblem, cfg: SearchSettings, confirm=None):
    """Run the searches in turn; stop at the first candidate ``confirm`` accepts.

    The cheap batch of random points goes first; confirmation rounds a candidate to
    the shortest rationals that still fail, so reported points stay readable.

    Returns the report and the confirmed counterexample (or None).
    """
    report = SearchReport()
    tried = 0
    for run in (random_search, hypothesis_search, ipopt_search):
        with np.errstate(all="ignore"):
            run(problem, cfg, report)
        if confirm is None:
            continue
        for candidate in report.candidates[tried:]:
            found = confirm(problem, candidate)
            if isinstance(found, Rejected):
                report.rejected += 1
            elif found is None:
                report.undecided += 1
            else:
                return report, found
        tried = len(report.candidates)
    return report, None


@dataclass(frozen=True)
class Rejected:
    """What ``confirm`` returns for a violation exact arithmetic disproves: at the point
    rounded to rationals with denominators up to ``denominators``, every declaration
    holds and the step holds exactly (the numerical violation was float rounding)."""

    denominators: int
