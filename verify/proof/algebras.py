"""The exact and the CasADi algebras of the evaluator (numpy's is in ``evaluate``)."""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

import casadi as ca
from sympy import QQ
from sympy.polys.rings import PolyElement, ring

from verify.proof import spectral
from verify.proof.evaluate import Algebra, Value, evaluate, to_float
from verify.proof.exact import Denominators, KnownFraction, constant, over_factor
from verify.proof.expr import Expr, Variable, structural_key


def _safe(name: str) -> str:
    return re.sub(r"\W", "_", name.encode("ascii", "replace").decode()) or "v"


@dataclass
class ExactSpace:
    """Polynomial ring of a derivation: one generator per parameter and per lambda_min."""

    variables: list[Variable]
    atoms: list[Expr]  # lambda_min nodes, one per structurally distinct argument

    def __post_init__(self) -> None:
        names: list[str] = []
        for v in self.variables:
            names += [f"{_safe(v.name)}{v.uid}_{i}" for i in range(v.parameter_count)]
        names += [f"lambda_min{k}" for k in range(len(self.atoms))]
        self.ring, *gens = ring(",".join(names), QQ) if names else (ring("unused", QQ)[0],)
        self.gens: list[PolyElement] = list(gens)
        self.param_gens: dict[int, list[PolyElement]] = {}
        i = 0
        for v in self.variables:
            self.param_gens[v.uid] = self.gens[i : i + v.parameter_count]
            i += v.parameter_count
        self.atom_gens = {structural_key(a.args[0]): self.gens[i + k]
                          for k, a in enumerate(self.atoms)}

    def algebra(self) -> ExactAlgebra:
        return ExactAlgebra(self)


class ExactAlgebra(Algebra):
    """Exact rational functions (:class:`KnownFraction`) of the parameters."""

    def __init__(self, space: ExactSpace):
        self.space = space
        self.den = Denominators(space.ring, [])
        self._atoms: list[spectral.Atom] = []
        self._values: dict[tuple, KnownFraction] = {}

    def const(self, value: Fraction) -> Value:
        return constant(value, self.den)

    def lambda_min(self, node: Expr, matrix: Value) -> Value:
        """The atom's generator, or a known atom's value scaled (see :mod:`spectral`)."""
        key = structural_key(node.args[0])
        if key not in self._values:
            gen = KnownFraction(self.space.atom_gens[key], (), self.den)
            self._values[key] = spectral.canonical(self._atoms, matrix, gen).value
        return self._values[key]

    def divide_rows(self, rows, denominator):
        if not isinstance(denominator, KnownFraction) or any(denominator.exps):
            raise TypeError("exact parametrisations divide by a polynomial")
        flat = [x for row in rows for x in row]
        if any(any(x.exps) for x in flat):
            raise TypeError("exact parametrisations have polynomial numerators")
        values = over_factor([x.num for x in flat], denominator.num, self.den)
        width = len(rows[0])
        return [values[k : k + width] for k in range(0, len(values), width)]

    def environment(self) -> dict[int, Value]:
        env = {}
        for v in self.space.variables:
            params = [KnownFraction(g, (), self.den) for g in self.space.param_gens[v.uid]]
            env[v.uid] = self.bind(v, params)
        return env


def exact_value(e: Expr, space: ExactSpace) -> KnownFraction:
    """Exact value of a scalar expression as a rational function of the parameters."""
    alg = space.algebra()
    return evaluate(e, alg, alg.environment())


class CasadiAlgebra(Algebra):
    """CasADi SX scalars, for the IPOPT slack minimisation of inequality steps."""

    def const(self, value: Fraction) -> Value:
        return ca.SX(to_float(value))

    def lambda_min(self, node: Expr, matrix: Value) -> Value:
        return symmetric_lambda_min(matrix)


def det3(m: Sequence[Sequence[Value]]) -> Value:
    """Determinant of a 3x3 matrix of scalars (any scalar type), by cofactors."""
    return (
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    )


def symmetric_lambda_min(m: Sequence[Sequence[Value]]) -> Value:
    """Closed-form smallest eigenvalue of sym(M), 3x3 (trigonometric formula).

    Smooth except where eigenvalues coincide; it only steers a search whose findings
    are re-checked exactly, so the kinks do no harm to a verdict.
    """
    a = [[0.5 * (m[i][j] + m[j][i]) for j in range(3)] for i in range(3)]
    q = (a[0][0] + a[1][1] + a[2][2]) / 3
    p1 = a[0][1] ** 2 + a[0][2] ** 2 + a[1][2] ** 2
    p2 = (a[0][0] - q) ** 2 + (a[1][1] - q) ** 2 + (a[2][2] - q) ** 2 + 2 * p1
    p = ca.sqrt(p2 / 6 + 1e-30)
    b = [[(a[i][j] - (q if i == j else 0)) / p for j in range(3)] for i in range(3)]
    r = ca.fmin(ca.fmax(det3(b) / 2, -1 + 1e-12), 1 - 1e-12)
    angle = ca.acos(r) / 3
    return q + 2 * p * ca.cos(angle + 2 * math.pi / 3)
