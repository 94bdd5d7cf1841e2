"""One evaluator, three algebras: exact, batched numpy, CasADi.

Values are held entry-wise: a 3x3 matrix is a list of three rows of three scalars, a
vector a list of three scalars, an angle the pair (cos, sin). Only the scalar type
changes between algebras: :class:`~verify.proof.exact.KnownFraction` for exact checks,
numpy arrays of shape (N,) for N sample points at once, CasADi ``SX`` for the
optimisation-based falsifier. The evaluator is therefore written once and cannot
disagree with itself between the proof and the falsification of a step.

Each algebra also says how a variable's parameters become its value (the
parametrisations of :class:`~verify.proof.expr.Variable`) and what lambda_min is.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from fractions import Fraction
from typing import Any

import numpy as np

from verify.proof.expr import Expr, ProofSyntaxError, Variable

Value = Any


def to_float(value: Fraction | int) -> float:
    """A rational as the nearest float; beyond the float range +-inf (never OverflowError).

    Only the untrusted numerical side converts to float; an infinite or NaN value there
    simply yields no candidate counterexample.
    """
    try:
        return float(value)
    except OverflowError:
        return math.inf if value > 0 else -math.inf


def evaluate(e: Expr, algebra: Algebra, env: Mapping[int, Value]) -> Value:
    """Value of ``e`` with variables (by uid) bound in ``env``; shared subtrees once."""
    cache: dict[int, Value] = {}

    def ev(node: Expr) -> Value:
        return cache[id(node)]

    # children before parents, without recursion (a deep tree must not exhaust the stack)
    stack: list[tuple[Expr, bool]] = [(e, False)]
    while stack:
        node, expanded = stack.pop()
        if id(node) in cache:
            continue
        if expanded or not node.args:
            cache[id(node)] = _apply(node, algebra, env, ev)
        else:
            stack.append((node, True))
            stack.extend((a, False) for a in node.args if id(a) not in cache)
    return cache[id(e)]


def _apply(node: Expr, alg: Algebra, env, ev: Callable[[Expr], Value]) -> Value:
    op = node.op
    if op == "var":
        try:
            return env[node.data.uid]
        except KeyError:
            raise ProofSyntaxError(f"variable {node.data.name} is not bound") from None
    if op == "const":
        return alg.const(node.data)
    if op == "identity":
        return [[alg.const(Fraction(int(i == j))) for j in range(3)] for i in range(3)]
    if op == "zero":
        z = alg.const(Fraction(0))
        return {(): z, (3,): [z] * 3, (3, 3): [[z] * 3 for _ in range(3)]}[node.shape]
    if op == "chart_gap":
        zero, one = alg.const(Fraction(0)), alg.const(Fraction(1))
        return (-one, zero) if node.data == "angle" else [zero, zero, one]
    if op == "lambda_min":
        return alg.lambda_min(node, ev(node.args[0]))
    a = [ev(x) for x in node.args]
    if op == "add":
        return _zip(node.shape, a[0], a[1], lambda x, y: x + y)
    if op == "neg":
        return _map(node.shape, a[0], lambda x: -x)
    if op == "scale":
        s = a[0]
        return _map(node.shape, a[1], lambda x: s * x)
    if op == "matmul":
        m, x = a
        if node.shape == (3,):
            return [m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] for i in range(3)]
        return [
            [m[i][0] * x[0][j] + m[i][1] * x[1][j] + m[i][2] * x[2][j] for j in range(3)]
            for i in range(3)
        ]
    if op == "transpose":
        m = a[0]
        return [[m[j][i] for j in range(3)] for i in range(3)]
    if op == "trace":
        m = a[0]
        return m[0][0] + m[1][1] + m[2][2]
    if op == "sym":
        m, half = a[0], alg.const(Fraction(1, 2))
        return [[half * (m[i][j] + m[j][i]) for j in range(3)] for i in range(3)]
    if op == "sk":
        m, half = a[0], alg.const(Fraction(1, 2))
        return [[half * (m[i][j] - m[j][i]) for j in range(3)] for i in range(3)]
    if op == "hat":
        x, y, z = a[0]
        zero = alg.const(Fraction(0))
        return [[zero, -z, y], [z, zero, -x], [-y, x, zero]]
    if op == "vee":
        m, half = a[0], alg.const(Fraction(1, 2))
        return [
            half * (m[2][1] - m[1][2]),
            half * (m[0][2] - m[2][0]),
            half * (m[1][0] - m[0][1]),
        ]
    if op == "dot":
        u, v = a
        return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
    if op == "outer":
        u, v = a
        return [[u[i] * v[j] for j in range(3)] for i in range(3)]
    if op == "cos":
        return a[0][0]
    if op == "sin":
        return a[0][1]
    raise ProofSyntaxError(f"unknown operation {op}")


def _map(shape, value, f):
    if shape == ():
        return f(value)
    if shape == (3,):
        return [f(x) for x in value]
    return [[f(x) for x in row] for row in value]


def _zip(shape, u, v, f):
    if shape == ():
        return f(u, v)
    if shape == (3,):
        return [f(x, y) for x, y in zip(u, v, strict=True)]
    return [[f(x, y) for x, y in zip(r, s, strict=True)] for r, s in zip(u, v, strict=True)]


class Algebra:
    """Scalar type of an evaluation: constants, lambda_min, parametrisations."""

    def const(self, value: Fraction) -> Value:
        raise NotImplementedError

    def lambda_min(self, node: Expr, matrix: Value) -> Value:
        raise NotImplementedError

    def bind(self, variable: Variable, params: list[Value]) -> Value:
        """The value of ``variable`` from its parameters (see Variable's docstring)."""
        p = params
        one = self.const(Fraction(1))
        two = self.const(Fraction(2))
        kind = variable.kind
        if kind == "rotation":
            w, x, y, z = p
            n = w * w + x * x + y * y + z * z
            m = [
                [w * w + x * x - y * y - z * z, two * (x * y - w * z), two * (x * z + w * y)],
                [two * (x * y + w * z), w * w - x * x + y * y - z * z, two * (y * z - w * x)],
                [two * (x * z - w * y), two * (y * z + w * x), w * w - x * x - y * y + z * z],
            ]
            return self.divide_rows(m, n)
        if kind == "unit_vector":
            a, b = p
            n = one + a * a + b * b
            return self.divide_rows([[two * a, two * b, a * a + b * b - one]], n)[0]
        if kind == "angle":
            (t,) = p
            n = one + t * t
            c, s = self.divide_rows([[one - t * t, two * t]], n)[0]
            return (c, s)
        if kind == "vector":
            return list(p)
        if kind == "matrix":
            return [list(p[0:3]), list(p[3:6]), list(p[6:9])]
        if kind == "symmetric":
            a11, a22, a33, a12, a13, a23 = p
            return [[a11, a12, a13], [a12, a22, a23], [a13, a23, a33]]
        if kind == "scalar":
            return p[0]
        raise ProofSyntaxError(f"unknown variable kind {kind}")

    def divide_rows(self, rows: list[list[Value]], denominator: Value) -> list[list[Value]]:
        return [[x / denominator for x in row] for row in rows]


class NumpyAlgebra(Algebra):
    """Batched floating point: every scalar is an array of shape (N,)."""

    def __init__(self, size: int):
        self.size = size

    def const(self, value: Fraction) -> Value:
        return np.full(self.size, to_float(value))

    def lambda_min(self, node: Expr, matrix: Value) -> Value:
        stacked = np.stack([np.stack(row, axis=-1) for row in matrix], axis=-2)
        sym = 0.5 * (stacked + np.swapaxes(stacked, -1, -2))
        finite = np.all(np.isfinite(sym), axis=(-1, -2))
        out = np.full(sym.shape[:-2], np.nan)
        if finite.any():  # inf/NaN entries (huge constants) give NaN, not LinAlgError
            out[finite] = np.linalg.eigvalsh(sym[finite])[..., 0]
        return out

