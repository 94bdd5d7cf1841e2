"""Exact values of expressions over the atoms Coq sees, and ideal-membership cofactors.

Coq's ``field`` decides an identity between rational functions of *free* reals. In an
exported section the free reals are the atoms below (after the prelude's definitions
are unfolded): a rotation's quaternion entries ``qw q .. qz q`` (entries of ``rot q``
are rational in them, with the denominator ``qn q``), a unit vector's entries, the
``cos``/``sin`` of an angle, free vector, matrix and symmetric entries, scalars and
the real standing for each lambda_min. A unit vector (``vdot u u = 1``), an angle
(``cos^2 + sin^2 = 1``) and a side condition are not free: an identity that needs them
is proved from *cofactors*, ``lhs - rhs = sum_k c_k g_k`` with each ``g_k = 0`` a
hypothesis or a lemma. This module computes those cofactors (Buchberger's algorithm,
each basis element tracked as a combination of the original generators); Coq re-checks
the identity with ``field``, so nothing here is trusted.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction

from sympy import QQ
from sympy.polys.monomials import monomial_div, monomial_lcm
from sympy.polys.orderings import grevlex
from sympy.polys.rings import ring

from verify.coq.terms import CoqExportError, Naming
from verify.proof.expr import Expr, Variable, postorder, structural_key

MAX_BASIS = 40


class Q:
    """numerator / product of quaternion norms (exponents ``den``); no gcd is taken."""

    __slots__ = ("atoms", "den", "num")

    def __init__(self, atoms: Atoms, num, den: tuple[int, ...]):
        self.atoms, self.num, self.den = atoms, num, den

    def _lift(self, den: tuple[int, ...]):
        num = self.num
        for i, (have, want) in enumerate(zip(self.den, den, strict=True)):
            if want > have:
                num = num * self.atoms.norm_power(i, want - have)
        return num

    def __add__(self, other: Q) -> Q:
        den = tuple(max(a, b) for a, b in zip(self.den, other.den, strict=True))
        return Q(self.atoms, self._lift(den) + other._lift(den), den)

    def __sub__(self, other: Q) -> Q:
        return self + (-other)

    def __neg__(self) -> Q:
        return Q(self.atoms, -self.num, self.den)

    def __mul__(self, other: Q) -> Q:
        return Q(self.atoms, self.num * other.num,
                 tuple(a + b for a, b in zip(self.den, other.den, strict=True)))


@dataclass
class Atoms:
    """The polynomial ring over a section's atoms, with each atom's Coq text."""

    ring: object
    gens: dict[str, object]
    coq: dict[str, str]
    rotations: list[str]  # Coq names of the rotations, in the order of Q.den
    norms: list[object]  # each rotation's quaternion norm (a polynomial)
    values: dict[int, object] = field(default_factory=dict)
    lambdas: dict[tuple, object] = field(default_factory=dict)
    _powers: dict[tuple[int, int], object] = field(default_factory=dict)

    def norm_power(self, i: int, k: int):
        if (i, k) not in self._powers:
            self._powers[(i, k)] = self.norms[i] ** k
        return self._powers[(i, k)]

    def const(self, c) -> Q:
        return Q(self, self.ring(c), (0,) * len(self.norms))

    def poly(self, p) -> Q:
        return Q(self, p, (0,) * len(self.norms))


def atoms_for(variables: list[Variable], lambda_nodes: list[Expr], naming: Naming, *,
              generic: bool | frozenset[int] = False) -> Atoms:
    """Polynomial generators for every variable and lambda_min atom of a section.

    With ``generic``, a rotation is a matrix of nine free entries (``G_R`` in Coq, after
    ``generalize (rot q_R)``): an identity that holds there holds for every rotation
    and is proved by ``field`` on low-degree polynomials. A set of variable uids makes
    only those rotations free matrices.
    """
    if not isinstance(generic, frozenset):
        generic = frozenset(v.uid for v in variables) if generic else frozenset()
    names: list[str] = []
    coq: dict[str, str] = {}
    plan: list[tuple[Variable, list[str]]] = []
    for v in variables:
        n = naming.variable(v)
        if v.kind == "rotation" and v.uid in generic:
            parts = [(f"r{i}{j}_{n}", f"(m{i}{j} G_{n})") for i in "123" for j in "123"]
        elif v.kind == "rotation":
            parts = [(f"q{c}_{n}", f"(q{c} q_{n})") for c in "wxyz"]
        elif v.kind in ("unit_vector", "vector"):
            parts = [(f"{c}_{n}", f"({c} {n})") for c in ("v1", "v2", "v3")]
        elif v.kind == "angle":
            parts = [(f"cos_{n}", f"(cos {n})"), (f"sin_{n}", f"(sin {n})")]
        elif v.kind == "matrix":
            parts = [(f"m{i}{j}_{n}", f"(m{i}{j} {n})") for i in "123" for j in "123"]
        elif v.kind == "symmetric":
            parts = [(f"{n}_{ij}", f"{n}_{ij}") for ij in ("11", "22", "33", "12", "13", "23")]
        else:
            parts = [(f"s_{n}", n)]
        plan.append((v, [p for p, _ in parts]))
        for p, text in parts:
            names.append(p)
            coq[p] = text
    lam_keys = []
    for node in lambda_nodes:
        key = structural_key(node.args[0])
        if key in lam_keys:
            continue
        lam_keys.append(key)
        p = f"lam_{naming.lambda_atom(node)}"
        names.append(p)
        coq[p] = naming.lambda_atom(node)
    if not names:
        names.append("unused")
        coq["unused"] = "0"
    P, *gens = ring(names, QQ, grevlex)
    g = dict(zip(names, gens, strict=True))
    rotations = [naming.variable(v) for v, _ in plan
                 if v.kind == "rotation" and v.uid not in generic]
    norms = []
    for v, ps in plan:
        if v.kind == "rotation" and v.uid not in generic:
            w, a, b, c = (g[p] for p in ps)
            norms.append(w * w + a * a + b * b + c * c)
    atoms = Atoms(P, g, coq, rotations, norms)
    for v, ps in plan:
        x = [atoms.poly(g[p]) for p in ps]
        if v.kind == "rotation" and v.uid in generic:
            atoms.values[v.uid] = [x[0:3], x[3:6], x[6:9]]
        elif v.kind == "rotation":
            i = rotations.index(naming.variable(v))
            w, a, b, c = (g[p] for p in ps)
            m = [[w * w + a * a - b * b - c * c, 2 * (a * b - w * c), 2 * (a * c + w * b)],
                 [2 * (a * b + w * c), w * w - a * a + b * b - c * c, 2 * (b * c - w * a)],
                 [2 * (a * c - w * b), 2 * (b * c + w * a), w * w - a * a - b * b + c * c]]
            den = tuple(int(j == i) for j in range(len(norms)))
            atoms.values[v.uid] = [[Q(atoms, e, den) for e in row] for row in m]
        elif v.kind in ("unit_vector", "vector"):
            atoms.values[v.uid] = list(x)
        elif v.kind == "angle":
            atoms.values[v.uid] = (x[0], x[1])
        elif v.kind == "matrix":
            atoms.values[v.uid] = [x[0:3], x[3:6], x[6:9]]
        elif v.kind == "symmetric":
            a11, a22, a33, a12, a13, a23 = x
            atoms.values[v.uid] = [[a11, a12, a13], [a12, a22, a23], [a13, a23, a33]]
        else:
            atoms.values[v.uid] = x[0]
    atoms.lambdas = {key: atoms.poly(g[f"lam_{naming.lambdas[key][0]}"]) for key in lam_keys}
    return atoms


def evaluate(e: Expr, atoms: Atoms):
    """The exact value of ``e``: a :class:`Q`, a 3-list or a 3x3 list of them."""
    val: dict[int, object] = {}
    half = atoms.const(QQ(1, 2))
    zero = atoms.const(0)
    for node in postorder(e):
        op, a = node.op, [val[id(x)] for x in node.args]
        if op == "var":
            out = atoms.values[node.data.uid]
        elif op == "const":
            out = atoms.const(QQ(node.data.numerator, node.data.denominator))
        elif op == "identity":
            out = [[atoms.const(int(i == j)) for j in range(3)] for i in range(3)]
        elif op == "zero":
            out = {(): zero, (3,): [zero] * 3, (3, 3): [[zero] * 3 for _ in range(3)]}[
                node.shape]
        elif op == "lambda_min":
            out = atoms.lambdas[structural_key(node.args[0])]
        elif op == "chart_gap":
            raise CoqExportError("a chart's missing point (chart_gap) has no Coq statement")
        elif op == "add":
            out = _zip(a[0], a[1], lambda x, y: x + y)
        elif op == "neg":
            out = _map(a[0], lambda x: -x)
        elif op == "scale":
            out = _map(a[1], lambda x, s=a[0]: s * x)
        elif op == "matmul":
            m, x = a
            if node.shape == (3,):
                out = [m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] for i in range(3)]
            else:
                out = [[m[i][0] * x[0][j] + m[i][1] * x[1][j] + m[i][2] * x[2][j]
                        for j in range(3)] for i in range(3)]
        elif op == "transpose":
            out = [[a[0][j][i] for j in range(3)] for i in range(3)]
        elif op == "trace":
            out = a[0][0][0] + a[0][1][1] + a[0][2][2]
        elif op == "sym":
            m = a[0]
            out = [[half * (m[i][j] + m[j][i]) for j in range(3)] for i in range(3)]
        elif op == "sk":
            m = a[0]
            out = [[half * (m[i][j] - m[j][i]) for j in range(3)] for i in range(3)]
        elif op == "hat":
            x, y, z = a[0]
            out = [[zero, -z, y], [z, zero, -x], [-y, x, zero]]
        elif op == "vee":
            m = a[0]
            out = [half * (m[2][1] - m[1][2]), half * (m[0][2] - m[2][0]),
                   half * (m[1][0] - m[0][1])]
        elif op == "dot":
            out = a[0][0] * a[1][0] + a[0][1] * a[1][1] + a[0][2] * a[1][2]
        elif op == "outer":
            out = [[a[0][i] * a[1][j] for j in range(3)] for i in range(3)]
        elif op == "cos":
            out = a[0][0]
        elif op == "sin":
            out = a[0][1]
        else:
            raise CoqExportError(f"cannot evaluate the operation {op!r}")
        val[id(node)] = out
    return val[id(e)]


def _map(x, f):
    if isinstance(x, tuple):
        raise CoqExportError("an angle is used outside cos/sin")
    if isinstance(x, list):
        return [_map(y, f) for y in x]
    return f(x)


def _zip(x, y, f):
    if isinstance(x, list):
        return [_zip(p, q, f) for p, q in zip(x, y, strict=True)]
    return f(x, y)


def entries(value) -> list:
    """The scalar entries of a value, row by row (the order of ``m3_ext``/``v3_ext``)."""
    if isinstance(value, list):
        return [z for row in value for z in (row if isinstance(row, list) else [row])]
    return [value]


def denominator_text(den: tuple[int, ...], atoms: Atoms) -> str:
    """The product of quaternion norms ``den`` as a Coq term (1 when empty)."""
    factors = [f"(qn q_{name})" + (f" ^ {k}" if k > 1 else "")
               for name, k in zip(atoms.rotations, den, strict=True) if k]
    return " * ".join(factors) or "1"


def poly_text(p, atoms: Atoms) -> str:
    """A polynomial over the atoms as a Coq real expression."""
    if p == 0:
        return "0"
    names = list(atoms.gens)
    terms = []
    for monom, coeff in sorted(p.terms(), key=lambda t: t[0], reverse=True):
        c = Fraction(int(coeff.numerator), int(coeff.denominator))
        factors = []
        for name, k in zip(names, monom, strict=True):
            if k:
                factors.append(atoms.coq[name] + (f" ^ {k}" if k > 1 else ""))
        if not factors:
            terms.append(_const(c))
        elif c == 1:
            terms.append(" * ".join(factors))
        else:
            terms.append(" * ".join([_const(c), *factors]))
    return "(" + " + ".join(terms) + ")"


def _const(c: Fraction) -> str:
    if c.denominator == 1:
        return f"({c.numerator})" if c < 0 else str(c.numerator)
    return f"({c.numerator}/{c.denominator})"


# -- ideal membership with cofactors -----------------------------------------------------
def cofactors(target, generators: list, *, complete: bool = True) -> list | None:
    """Polynomials c_k with target = sum_k c_k * generators[k], or None if none exist.

    Buchberger's algorithm over the ring's order, each basis element carrying its
    representation in the original generators; then division of ``target``. Without
    ``complete``, division by the generators only (cheap, may miss a membership).
    """
    if target == 0:
        return [target.ring.zero for _ in generators]
    ring = target.ring
    basis: list[tuple[object, list]] = []
    for i, g in enumerate(generators):
        if g != 0:
            rep = [ring.zero] * len(generators)
            rep[i] = ring.one
            basis.append((g, rep))
    pairs = [(i, j) for j in range(len(basis)) for i in range(j)] if complete else []
    while pairs:
        i, j = pairs.pop(0)
        (f, rf), (g, rg) = basis[i], basis[j]
        lcm = monomial_lcm(f.LM, g.LM)
        mf = ring.from_dict({monomial_div(lcm, f.LM): ring.domain.one / f.LC})
        mg = ring.from_dict({monomial_div(lcm, g.LM): ring.domain.one / g.LC})
        s = mf * f - mg * g
        srep = [mf * x - mg * y for x, y in zip(rf, rg, strict=True)]
        r, rrep = _reduce(s, srep, basis)
        if r != 0:
            if len(basis) >= MAX_BASIS:
                raise CoqExportError("the side conditions' Groebner basis is too large")
            basis.append((r, rrep))
            pairs += [(k, len(basis) - 1) for k in range(len(basis) - 1)]
    zero = [ring.zero] * len(generators)
    r, rep = _reduce(target, zero, basis)
    if r != 0:
        return None
    return [-x for x in rep]


def _reduce(f, frep: list, basis: list) -> tuple:
    """f - sum q_b b (remainder) and frep - sum q_b rep_b."""
    if not basis or f == 0:
        return f, frep
    quotients, r = f.div([b for b, _ in basis])
    rep = list(frep)
    for q, (_, brep) in zip(quotients, basis, strict=True):
        if q != 0:
            rep = [x - q * y for x, y in zip(rep, brep, strict=True)]
    return r, rep
