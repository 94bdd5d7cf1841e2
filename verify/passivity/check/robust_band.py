"""Exact robust passivity over a parameter region: interval forms, leaves and their check.

The models are the 2 x 2 transfer matrices of the paper's Section 4 ("Human Modeling")
and their generalisation: diagonal elements h_i(s) = num_i(s)/den_i(s) (``zeros`` zeros,
``poles`` poles, den_i monic) and constant off-diagonal elements c12, c21. With
c = c12 + c21,

    H(jw) + H(jw)^H = [[2 Re h_1, c], [c, 2 Re h_2]],

and, writing x = w^2, N_i(x) = Re(num_i(jw) conj(den_i(jw))) and D_i(x) = |den_i(jw)|^2
(both polynomials in x, because they are even in w), the matrix is positive definite at w
exactly when

    N_1 > 0,  N_2 > 0,  4 N_1 N_2 - c^2 D_1 D_2 > 0

(Sylvester's criterion, multiplied by D_1 D_2 > 0; N_i > 0 also excludes den_i(jw) = 0).
For x >= 1 the same polynomials are written in y = 1/x and multiplied by the power of y
that makes them polynomials (their formal degrees), so that [0, inf] in x becomes the
two compact pieces x in [0, 1] and y in [0, 1], y = 0 standing for w -> infinity.

Everything here is exact (gmpy2 ``mpq``): interval arithmetic on rational intervals
(R. E. Moore, R. B. Kearfott and M. J. Cloud, *Introduction to Interval Analysis*, SIAM
2009, Ch. 5: the natural interval extension encloses the range), Kharitonov's theorem for
Hurwitz stability of a box of monic denominators (V. L. Kharitonov, Differential'nye
Uravneniya 14, 1978; exact for independent coefficient intervals), the box enclosing the
ellipsoid (θ - θc)^T Σ^-1 (θ - θc) <= χ (half-widths r_i with r_i^2 >= χ Σ_ii, since
max of e_i^T d over d^T Σ^-1 d <= χ is sqrt(χ Σ_ii)) and the test that a box misses the
ellipsoid (a tangent plane of the convex quadratic form bounds it from below).

The form evaluated on a leaf is defined once, in :func:`leaf_bounds`, for any interval
arithmetic (:class:`ExactOps` here; the untrusted prover passes a float one to propose
leaves), so the checker re-evaluates exactly what the prover aimed at.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import flint
from gmpy2 import mpq

from verify.passivity.check import exact as ex
from verify.passivity.check.qpoly import is_hurwitz

Interval = tuple[Any, Any]

#: Limits on a certificate's tree (a hostile file must not ask for unbounded work).
MAX_DEPTH = 400
MAX_NODES = 400_000


class ExactOps:
    """Interval arithmetic on exact rational intervals (lo, hi), lo <= hi."""

    @staticmethod
    def const(v: Any) -> Interval:
        q = mpq(v)
        return q, q

    @staticmethod
    def add(a: Interval, b: Interval) -> Interval:
        return a[0] + b[0], a[1] + b[1]

    @staticmethod
    def sub(a: Interval, b: Interval) -> Interval:
        return a[0] - b[1], a[1] - b[0]

    @staticmethod
    def scale(k: int, a: Interval) -> Interval:
        return (k * a[0], k * a[1]) if k >= 0 else (k * a[1], k * a[0])

    @staticmethod
    def mul(a: Interval, b: Interval) -> Interval:
        p = (a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1])
        return min(p), max(p)

    @staticmethod
    def sqr(a: Interval) -> Interval:
        lo, hi = a
        if lo >= 0:
            return lo * lo, hi * hi
        if hi <= 0:
            return hi * hi, lo * lo
        return mpq(0), max(lo * lo, hi * hi)

    @staticmethod
    def power(t: Interval, m: int) -> Interval:
        """t^m for an interval with t >= 0 (monotone)."""
        return t[0] ** m, t[1] ** m


@dataclass(frozen=True)
class Shape:
    """Degrees of the diagonal elements: ``zeros`` <= ``poles``, ``poles`` >= 1."""

    zeros: int
    poles: int

    @property
    def per_element(self) -> int:
        return self.zeros + 1 + self.poles

    @property
    def parameters(self) -> int:
        """Length of θ: both diagonal elements, then c12 and c21."""
        return 2 * self.per_element + 2

    @property
    def reduced(self) -> int:
        """Length of φ = (diagonal parameters, c12 + c21), what the conditions depend on."""
        return 2 * self.per_element + 1

    @property
    def n_degree(self) -> int:
        """Formal degree of N_i in x."""
        return (self.zeros + self.poles) // 2


def element(box: Sequence[Interval], i: int, shape: Shape, ops) -> tuple[list, list]:
    """(b, a) of diagonal element i in ascending powers of s, a_p = 1 (structure order:
    b_z .. b_0 then a_{p-1} .. a_0, see :mod:`verify.identify.estimate.structure`)."""
    block = list(box[i * shape.per_element:(i + 1) * shape.per_element])
    b = block[: shape.zeros + 1][::-1]
    a = [*block[shape.zeros + 1:][::-1], ops.const(1)]
    return b, a


def _sign(e: int) -> int:
    return -1 if e % 2 else 1


def n_coefficients(b: list, a: list, shape: Shape, ops) -> list:
    """C_m, m = 0 .. n_degree, of N(x) = Re(num(jw) conj(den(jw))) = sum C_m x^m:
    C_m = sum over k + l = 2m of (-1)^(m - l) b_k a_l."""
    out = []
    for m in range(shape.n_degree + 1):
        acc = ops.const(0)
        for k in range(shape.zeros + 1):
            l_ = 2 * m - k
            if 0 <= l_ <= shape.poles:
                acc = ops.add(acc, ops.scale(_sign(m - l_), ops.mul(b[k], a[l_])))
        out.append(acc)
    return out


def d_coefficients(a: list, shape: Shape, ops) -> list:
    """E_m, m = 0 .. poles, of D(x) = |den(jw)|^2 = sum E_m x^m:
    E_m = a_m^2 + sum over k < l, k + l = 2m of 2 (-1)^(m - l) a_k a_l."""
    out = []
    for m in range(shape.poles + 1):
        acc = ops.sqr(a[m])
        for k in range(m):
            l_ = 2 * m - k
            if l_ <= shape.poles:
                acc = ops.add(acc, ops.scale(2 * _sign(m - l_), ops.mul(a[k], a[l_])))
        out.append(acc)
    return out


def polynomial(coefficients: list, t: Interval, variable: str, degree: int, ops) -> Interval:
    """sum C_m x^m at x = t ("x"), or y^degree sum C_m y^-m at y = t ("y"); t >= 0."""
    acc = ops.const(0)
    for m, c in enumerate(coefficients):
        power = m if variable == "x" else degree - m
        acc = ops.add(acc, c if power == 0 else ops.mul(c, ops.power(t, power)))
    return acc


def leaf_bounds(box: Sequence[Interval], t: Interval, variable: str, shape: Shape,
                ops) -> tuple[Interval, Interval, Interval]:
    """Enclosures of (N_1, N_2, det) over a box of φ and t (module docstring).

    φ = (diagonal parameters in structure order, c = c12 + c21): the conditions depend on
    the off-diagonal elements only through their sum.
    ``variable`` "x": t = w^2; "y": t = 1/w^2 and each polynomial is multiplied by
    t^(its formal degree): N_i by t^n_degree, det by t^(2 poles).
    """
    Ns, Ds = [], []
    for i in range(2):
        b, a = element(box, i, shape, ops)
        Ns.append(polynomial(n_coefficients(b, a, shape, ops), t, variable,
                             shape.n_degree, ops))
        Ds.append(polynomial(d_coefficients(a, shape, ops), t, variable, shape.poles, ops))
    c = box[-1]
    first = ops.scale(4, ops.mul(Ns[0], Ns[1]))
    if variable == "y":
        gap = 2 * (shape.poles - shape.n_degree)
        if gap:
            first = ops.mul(first, ops.power(t, gap))
    det = ops.sub(first, ops.mul(ops.sqr(c), ops.mul(Ds[0], Ds[1])))
    return Ns[0], Ns[1], det


# ------------------------------------------------------------------ one direction, one frequency


def direction_bounds(box: Sequence[Interval], x: Interval, v: Sequence[Any], shape: Shape,
                     ops) -> tuple[Interval, Interval, Interval]:
    """Enclosures of (g, D_1, D_2) over a box of φ at x = w^2, for a real direction v.

    v^T (H(jw) + H(jw)^H) v = 2 v_1^2 N_1/D_1 + 2 v_2^2 N_2/D_2 + 2 v_1 v_2 c; multiplied by
    D_1 D_2 / 2 (positive where D_1, D_2 > 0, i.e. no pole at jw):

        g = v_1^2 N_1 D_2 + v_2^2 N_2 D_1 + v_1 v_2 c D_1 D_2.

    g < 0 with D_1, D_2 > 0 at one w shows the model is not passive at w (the Hermitian
    part has a negative direction); on every point of a box, for every model of the box.
    """
    Ns, Ds = [], []
    for i in range(2):
        b, a = element(box, i, shape, ops)
        Ns.append(polynomial(n_coefficients(b, a, shape, ops), x, "x", shape.n_degree, ops))
        Ds.append(polynomial(d_coefficients(a, shape, ops), x, "x", shape.poles, ops))
    v1, v2 = ops.const(v[0]), ops.const(v[1])
    g = ops.add(ops.mul(ops.mul(ops.sqr(v1), Ns[0]), Ds[1]),
                ops.mul(ops.mul(ops.sqr(v2), Ns[1]), Ds[0]))
    g = ops.add(g, ops.mul(ops.mul(ops.mul(v1, v2), box[-1]), ops.mul(Ds[0], Ds[1])))
    return g, Ds[0], Ds[1]


def check_negative_leaf(box: list[Interval], x: mpq, v: Sequence[mpq], shape: Shape,
                        claimed: mpq) -> LeafResult:
    """Every model of the box fails at x = w^2: the exact enclosure of g lies below the
    claimed bound < 0 and those of D_1, D_2 above 0 (:func:`direction_bounds`)."""
    if not claimed < 0:
        return LeafResult(False, f"claimed upper bound of g {claimed} is not < 0")
    g, d1, d2 = direction_bounds(box, (x, x), v, shape, ExactOps)
    if not (d1[0] > 0 and d2[0] > 0):
        return LeafResult(False, "a denominator |den_i(jw)|^2 is not bounded away from 0")
    if g[1] > claimed:
        return LeafResult(False, f"upper bound of g is {g[1]}, above the claimed {claimed}")
    return LeafResult(True, "")


def check_negative_linear_leaf(box: list[Interval], x: mpq, v: Sequence[mpq], shape: Shape,
                               covariance, phi_c: Sequence[mpq], chi2: mpq, claimed: mpq,
                               sqrt_bound: mpq) -> LeafResult:
    """Every model of the box's part of the ellipsoid fails at x = w^2: the first-order
    form (:func:`linear_bound`) of -g is >= -``claimed`` > 0 there, ``sqrt_bound`` s
    with s >= 0 and s^2 >= χ m^T Σ m, and D_1, D_2 > 0 on the box."""
    if not claimed < 0:
        return LeafResult(False, f"claimed upper bound of g {claimed} is not < 0")
    dims = len(box)
    ops = GradOps(ExactOps, dims)
    centre = [(lo + hi) / 2 for lo, hi in box]
    t = (x, x)
    at_centre = direction_bounds([ops.variable((c, c), k) for k, c in enumerate(centre)], t,
                                 v, shape, ops)[0]
    over_box = direction_bounds([ops.variable(iv, k) for k, iv in enumerate(box)], t, v,
                                shape, ops)
    d1, d2 = over_box[1][0], over_box[2][0]
    if not (d1[0] > 0 and d2[0] > 0):
        return LeafResult(False, "a denominator |den_i(jw)|^2 is not bounded away from 0")
    value = ExactOps.scale(-1, at_centre[0])
    grad = [ExactOps.scale(-1, gk) for gk in over_box[0][1]]
    m = gradient_midpoints(grad)
    quad = sum((m[i] * covariance[i][j] * m[j] for i in range(dims) for j in range(dims)),
               mpq(0))
    if sqrt_bound < 0 or sqrt_bound * sqrt_bound < chi2 * quad:
        return LeafResult(False, f"{sqrt_bound} is not >= sqrt(chi2 m^T Σ m)")
    low = linear_bound(box, centre, value, grad, phi_c, sqrt_bound)
    if low < -claimed:
        return LeafResult(False, f"first-order bound of -g is {low}, below {-claimed}")
    return LeafResult(True, "")


# ------------------------------------------------------------------ first-order form


class GradOps:
    """Interval arithmetic carrying enclosures of the gradient in φ (forward mode).

    A value is (interval, gradient intervals); ``base`` is the interval arithmetic
    (:class:`ExactOps`, or a float one for proposals). Frequency powers carry no gradient.
    """

    def __init__(self, base, dims: int) -> None:
        self.base, self.dims = base, dims

    def _zero(self):
        return [self.base.const(0)] * self.dims

    def variable(self, interval: Interval, k: int):
        grad = self._zero()
        grad[k] = self.base.const(1)
        return interval, grad

    def const(self, v: Any):
        return self.base.const(v), self._zero()

    def add(self, a, b):
        B = self.base
        return B.add(a[0], b[0]), [B.add(x, y) for x, y in zip(a[1], b[1], strict=True)]

    def sub(self, a, b):
        B = self.base
        return B.sub(a[0], b[0]), [B.sub(x, y) for x, y in zip(a[1], b[1], strict=True)]

    def scale(self, k: int, a):
        B = self.base
        return B.scale(k, a[0]), [B.scale(k, x) for x in a[1]]

    def mul(self, a, b):
        B = self.base
        return B.mul(a[0], b[0]), [B.add(B.mul(a[0], y), B.mul(b[0], x))
                                   for x, y in zip(a[1], b[1], strict=True)]

    def sqr(self, a):
        B = self.base
        return B.sqr(a[0]), [B.scale(2, B.mul(a[0], x)) for x in a[1]]

    def power(self, t: Interval, m: int):
        return self.base.power(t, m), self._zero()


def linear_parts(box: Sequence[Interval], t: Interval, variable: str, shape: Shape
                 ) -> tuple[list[mpq], list[tuple[Interval, list[Interval]]]]:
    """The box centre φ0, and per condition (N_1, N_2, det): the enclosure of its value at
    (φ0, t) and of its gradient in φ over (box, t), exactly."""
    dims = len(box)
    ops = GradOps(ExactOps, dims)
    centre = [(lo + hi) / 2 for lo, hi in box]
    at_centre = leaf_bounds([ops.variable((c, c), k) for k, c in enumerate(centre)], t,
                            variable, shape, ops)
    over_box = leaf_bounds([ops.variable(iv, k) for k, iv in enumerate(box)], t, variable,
                           shape, ops)
    return centre, [(v[0], g[1]) for v, g in zip(at_centre, over_box, strict=True)]


def linear_bound(box: Sequence[Interval], centre: Sequence[mpq], value: Interval,
                 grad: Sequence[Interval], phi_c: Sequence[mpq], sqrt_bound: mpq) -> mpq:
    """A lower bound of a condition f over (box ∩ ellipsoid) x t (first-order form).

    With φ0 the box centre, m the midpoint of the gradient enclosure G over the box and
    ρ its radius: for φ in the box, f(φ) = f(φ0) + g(ξ)·(φ - φ0) with g(ξ) in G (mean
    value theorem on the segment, inside the box), and
    g(ξ)·(φ - φ0) >= m·(φ - θc) + m·(θc - φ0) - Σ ρ_k |φ_k - φ0_k|; over the ellipsoid
    m·(φ - θc) >= -sqrt(χ m^T Σ m) >= -``sqrt_bound``.
    """
    bound = value[0] - sqrt_bound
    for (lo, hi), c, pc, (glo, ghi) in zip(box, centre, phi_c, grad, strict=True):
        m, rho = (glo + ghi) / 2, (ghi - glo) / 2
        bound += m * (pc - c) - rho * (hi - lo) / 2
    return bound


def gradient_midpoints(grad: Sequence[Interval]) -> list[mpq]:
    return [(lo + hi) / 2 for lo, hi in grad]


def check_linear_leaf(box: list[Interval], variable: str, shape: Shape, covariance,
                      phi_c: Sequence[mpq], chi2: mpq, claimed: Sequence[mpq],
                      sqrt_bounds: Sequence[mpq], stability: bool) -> LeafResult:
    """The first-order form (:func:`linear_bound`) shows N_1, N_2 and det >= the claimed
    bounds > 0 on the box's part of the ellipsoid; ``sqrt_bounds`` s_j must satisfy
    s_j >= 0 and s_j^2 >= χ m_j^T Σ m_j."""
    phi, t = box[:-1], box[-1]
    centre, parts = linear_parts(phi, t, variable, shape)
    n = len(phi)
    for name, (value, grad), c, s in zip(("N_1", "N_2", "det"), parts, claimed, sqrt_bounds,
                                         strict=True):
        if not c > 0:
            return LeafResult(False, f"claimed lower bound of {name} {c} is not > 0")
        m = gradient_midpoints(grad)
        quad = sum((m[i] * covariance[i][j] * m[j] for i in range(n) for j in range(n)),
                   mpq(0))
        if s < 0 or s * s < chi2 * quad:
            return LeafResult(False, f"{name}: {s} is not >= sqrt(chi2 m^T Σ m)")
        low = linear_bound(phi, centre, value, grad, phi_c, s)
        if low < c:
            return LeafResult(False, f"first-order bound of {name} is {low}, below the "
                              f"claimed {c}")
    return stable_denominators(phi, shape) if stability else LeafResult(True, "")


# ------------------------------------------------------------------ stability (Kharitonov)


def hurwitz(coefficients: Sequence[mpq]) -> bool:
    """Routh's test, exact: True iff the real polynomial (ascending coefficients, positive
    leading one) has every root in Re s < 0 (:func:`verify.passivity.check.qpoly.is_hurwitz`);
    an empty list or a leading coefficient that is not positive gives False."""
    if not coefficients or not coefficients[-1] > 0:
        return False
    return is_hurwitz(flint.fmpq_poly([flint.fmpq(int(c.numerator), int(c.denominator))
                                       for c in coefficients]))


def stable_denominators(box: Sequence[Interval], shape: Shape) -> LeafResult:
    """Both diagonal denominators Hurwitz for every parameter vector of ``box``."""
    for i in range(2):
        _, a = element(box, i, shape, ExactOps)
        if not kharitonov_stable(a):
            return LeafResult(False, f"denominator {i + 1} fails Kharitonov's test")
    return LeafResult(True, "")


_KHARITONOV = ((0, 0, 1, 1), (1, 1, 0, 0), (0, 1, 1, 0), (1, 0, 0, 1))


def kharitonov_stable(a: Sequence[Interval]) -> bool:
    """Every monic polynomial with coefficients in the intervals ``a`` (ascending) is
    Hurwitz: the four Kharitonov polynomials are (Kharitonov's theorem)."""
    return all(hurwitz([a[k][pattern[k % 4]] for k in range(len(a))])
               for pattern in _KHARITONOV)


# ------------------------------------------------------------------ the region


def reduce_region(center: Sequence[mpq], covariance: Sequence[Sequence[mpq]]
                  ) -> tuple[list[mpq], list[list[mpq]]]:
    """The image of the ellipsoid under θ -> φ = (θ_1 .. θ_{p-2}, θ_{p-1} + θ_p).

    For φ = A θ with A of full row rank, A maps {d : d^T Σ^-1 d <= χ} onto
    {e : e^T (A Σ A^T)^-1 e <= χ} (Cauchy-Schwarz in the Σ^-1 inner product), so a
    statement about every φ in the image is one about every θ in the region.
    """
    p = len(center)
    phi = [*center[:-2], center[-2] + center[-1]]
    k = p - 1

    def row(i: int) -> list[mpq]:  # row i of A Σ, A summing the last two coordinates
        if i < k - 1:
            return list(covariance[i])
        return [covariance[-2][j] + covariance[-1][j] for j in range(p)]

    AS = [row(i) for i in range(k)]
    out = [[AS[i][j] if j < k - 1 else AS[i][-2] + AS[i][-1] for j in range(k)]
           for i in range(k)]
    return phi, out



def enclosure_ok(covariance: Sequence[Sequence[mpq]], chi2: mpq,
                 half_widths: Sequence[mpq]) -> str | None:
    """None if r_i >= 0 and r_i^2 >= chi2 Σ_ii for every i, else the first failure."""
    for i, r in enumerate(half_widths):
        if r < 0 or r * r < chi2 * covariance[i][i]:
            return f"half-width {i} = {r} does not cover sqrt(chi2 Σ_{i}{i})"
    return None


def inverse(covariance: Sequence[Sequence[mpq]]) -> list[list[mpq]]:
    """Σ^-1 exactly (FLINT rational matrices)."""
    n = len(covariance)
    M = flint.fmpq_mat(n, n, [flint.fmpq(int(x.numerator), int(x.denominator))
                              for row in covariance for x in row])
    inv = M.inv()
    return [[mpq(int(inv[i, j].p), int(inv[i, j].q)) for j in range(n)] for i in range(n)]


def quadratic_form(S: Sequence[Sequence[mpq]], center: Sequence[mpq],
                   theta: Sequence[mpq]) -> mpq:
    """(θ - θc)^T S (θ - θc), exactly."""
    d = [t - c for t, c in zip(theta, center, strict=True)]
    n = len(d)
    return sum((d[i] * sum((S[i][j] * d[j] for j in range(n)), mpq(0)) for i in range(n)),
               mpq(0))


def outside_bound(S: Sequence[Sequence[mpq]], center: Sequence[mpq],
                  box: Sequence[Interval], point: Sequence[mpq]) -> mpq:
    """A lower bound of the quadratic form over the box, from its tangent plane at
    ``point``: q(θ) >= q(p) + g^T (θ - p) with g = 2 S (p - θc) (q is convex for S > 0),
    minimised over the box coordinate by coordinate."""
    n = len(center)
    d = [p - c for p, c in zip(point, center, strict=True)]
    g = [2 * sum((S[i][j] * d[j] for j in range(n)), mpq(0)) for i in range(n)]
    bound = quadratic_form(S, center, point)
    for i in range(n):
        lo, hi = box[i]
        bound += min(g[i] * (lo - point[i]), g[i] * (hi - point[i]))
    return bound


# ------------------------------------------------------------------ the tree of leaves


def midpoint_split(box: list[Interval], k: int) -> tuple[list[Interval], list[Interval]]:
    """The two halves of ``box`` along coordinate k, at the exact midpoint."""
    lo, hi = box[k]
    mid = (lo + hi) / 2
    left, right = list(box), list(box)
    left[k], right[k] = (lo, mid), (mid, hi)
    return left, right


class TreeError(ValueError):
    """A malformed tree of leaves (one-line message)."""


def leaves(tree: Sequence[Any], root: list[Interval]):
    """Yield (box, leaf) for a pre-order tree over ``root``: an int k splits the current
    box at the midpoint of coordinate k (left half first), a list is a leaf. The leaves of
    a well-formed tree partition the root box (up to shared faces), by construction; a
    tree with missing or extra nodes is refused."""
    dims = len(root)
    stack: list[tuple[list[Interval], int]] = [(root, 0)]
    position = 0
    if len(tree) > MAX_NODES:
        raise TreeError(f"the tree has more than {MAX_NODES} nodes")
    while stack:
        box, depth = stack.pop()
        if position >= len(tree):
            raise TreeError("the tree ends before every box is decided (a node is missing)")
        node = tree[position]
        position += 1
        if isinstance(node, bool) or not isinstance(node, int | list):
            raise TreeError(f"node {position - 1} is neither a split index nor a leaf")
        if isinstance(node, int):
            if not 0 <= node < dims:
                raise TreeError(f"node {position - 1} splits coordinate {node}, not one of "
                                f"0..{dims - 1}")
            if depth >= MAX_DEPTH:
                raise TreeError(f"the tree is deeper than {MAX_DEPTH}")
            left, right = midpoint_split(box, node)
            stack.append((right, depth + 1))
            stack.append((left, depth + 1))
        else:
            yield box, node
    if position != len(tree):
        raise TreeError(f"{len(tree) - position} node(s) after the last box (an extra node)")


@dataclass(frozen=True)
class LeafResult:
    ok: bool
    reason: str


def check_positive_leaf(box: list[Interval], variable: str, shape: Shape,
                        claimed: Sequence[mpq], stability: bool) -> LeafResult:
    """The exact enclosures of N_1, N_2 and det have lower bounds >= the claimed ones, and
    those are > 0; with ``stability`` the box's denominators pass Kharitonov's test."""
    theta, t = box[:-1], box[-1]
    bounds = leaf_bounds(theta, t, variable, shape, ExactOps)
    for name, (lo, _), c in zip(("N_1", "N_2", "det"), bounds, claimed, strict=True):
        if not c > 0:
            return LeafResult(False, f"claimed lower bound of {name} {c} is not > 0")
        if lo < c:
            return LeafResult(False, f"lower bound of {name} is {lo}, below the claimed {c}")
    return stable_denominators(theta, shape) if stability else LeafResult(True, "")


def check_outside_leaf(box: list[Interval], S, center, chi2: mpq,
                       point: Sequence[mpq]) -> LeafResult:
    """The parameter box misses the ellipsoid: the tangent-plane bound exceeds chi2."""
    bound = outside_bound(S, center, box[:-1], point)
    if bound <= chi2:
        return LeafResult(False, f"the tangent-plane bound {float(bound):.6g} does not "
                          f"exceed chi2 = {float(chi2):.6g}")
    return LeafResult(True, "")


def is_positive_definite(covariance: Sequence[Sequence[mpq]]) -> bool:
    """Σ = Σ^T > 0, exactly (LDL^T)."""
    return ex.pd_ldl([list(r) for r in covariance]).ok


__all__ = [
    "MAX_DEPTH",
    "MAX_NODES",
    "ExactOps",
    "GradOps",
    "Interval",
    "LeafResult",
    "Shape",
    "TreeError",
    "check_linear_leaf",
    "check_negative_leaf",
    "check_negative_linear_leaf",
    "check_outside_leaf",
    "check_positive_leaf",
    "d_coefficients",
    "direction_bounds",
    "element",
    "enclosure_ok",
    "gradient_midpoints",
    "hurwitz",
    "inverse",
    "is_positive_definite",
    "kharitonov_stable",
    "leaf_bounds",
    "leaves",
    "linear_bound",
    "linear_parts",
    "midpoint_split",
    "n_coefficients",
    "outside_bound",
    "polynomial",
    "quadratic_form",
    "reduce_region",
]
