"""Untrusted search for the robust verdict: a branch-and-bound tree in floating point.

The search proposes a tree of midpoint splits over (parameter box) x (frequency piece)
whose leaves are either *positive* (float interval bounds of N_1, N_2 and det clearly
> 0, :func:`verify.passivity.check.robust_band.leaf_bounds` evaluated with
:class:`FloatOps`) or *outside* (the box misses the confidence ellipsoid, shown by a
tangent plane at the box's nearest point, found by coordinate descent). Nothing here is
trusted: every leaf is re-evaluated exactly by :mod:`verify.passivity.check.robust_band`
(a leaf that fails there is split again), and boxes that the search cannot decide yield
candidate counterexamples (box centres inside the ellipsoid where a condition is
negative) for the exact witness check of :mod:`verify.identify.robust.verdict`.

All boxes of one depth are processed together as NumPy arrays (vectorised branch and
bound); the split coordinate is the one whose better half has the best normalised lower
bound (a look-ahead over every coordinate, :func:`_choose_splits`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np
from gmpy2 import mpq

from verify.passivity.check import robust_band as rb

#: A float lower bound counts as positive only above this fraction of the enclosure's size.
FLOAT_MARGIN = 1e-7


class FloatOps:
    """Interval arithmetic on arrays of float intervals (no outward rounding: proposals)."""

    @staticmethod
    def const(v: Any):
        x = np.float64(v)
        return x, x

    @staticmethod
    def add(a, b):
        return a[0] + b[0], a[1] + b[1]

    @staticmethod
    def sub(a, b):
        return a[0] - b[1], a[1] - b[0]

    @staticmethod
    def scale(k: int, a):
        return (k * a[0], k * a[1]) if k >= 0 else (k * a[1], k * a[0])

    @staticmethod
    def mul(a, b):
        p = (a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1])
        return np.minimum(np.minimum(p[0], p[1]), np.minimum(p[2], p[3])), \
            np.maximum(np.maximum(p[0], p[1]), np.maximum(p[2], p[3]))

    @staticmethod
    def sqr(a):
        lo, hi = a
        l2, h2 = lo * lo, hi * hi
        low = np.where(lo >= 0, l2, np.where(hi <= 0, h2, 0.0))
        high = np.where(lo >= 0, h2, np.where(hi <= 0, l2, np.maximum(l2, h2)))
        return low, high

    @staticmethod
    def power(t, m: int):
        return t[0] ** m, t[1] ** m


def float_bounds(LO: np.ndarray, HI: np.ndarray, variable: str, shape: rb.Shape
                 ) -> list[tuple[np.ndarray, np.ndarray]]:
    """(lo, hi) arrays of N_1, N_2, det for boxes given as rows of LO, HI."""
    box = [(LO[:, k], HI[:, k]) for k in range(LO.shape[1] - 1)]
    t = (LO[:, -1], HI[:, -1])
    with np.errstate(all="ignore"):
        return list(rb.leaf_bounds(box, t, variable, shape, FloatOps))


def _score(bounds) -> np.ndarray:
    """The worst lower bound of the three, each relative to its enclosure's size."""
    out = None
    for lo, hi in bounds:
        size = np.maximum(np.abs(lo), np.abs(hi)) + 1e-300
        s = lo / size
        out = s if out is None else np.minimum(out, s)
    return np.nan_to_num(out, nan=-np.inf)


def _positive(bounds) -> np.ndarray:
    ok = None
    for lo, hi in bounds:
        size = np.maximum(np.abs(lo), np.abs(hi))
        good = np.isfinite(lo) & (lo > FLOAT_MARGIN * size) & (lo > 0)
        ok = good if ok is None else ok & good
    return ok


@dataclass
class Ellipsoid:
    """Float view of the region for the outside test and candidate points."""

    center: np.ndarray
    S: np.ndarray  # inverse covariance
    chi2: float
    covariance: np.ndarray | None = None  # Σ of φ (for the first-order leaves)

    def q(self, theta: np.ndarray) -> np.ndarray:
        d = theta - self.center
        return np.einsum("ki,ij,kj->k", d, self.S, d)

    def nearest(self, LO: np.ndarray, HI: np.ndarray, sweeps: int = 30) -> np.ndarray:
        """Approximate minimiser of q over each box (coordinate descent)."""
        p = np.clip(self.center, LO, HI)
        diag = np.diag(self.S)
        for _ in range(sweeps):
            for k in range(p.shape[1]):
                d = p - self.center
                rest = d @ self.S[k] - d[:, k] * diag[k]
                p[:, k] = np.clip(self.center[k] - rest / diag[k], LO[:, k], HI[:, k])
        return p

    def lower(self, LO: np.ndarray, HI: np.ndarray, p: np.ndarray) -> np.ndarray:
        """Tangent-plane lower bound of q over each box at p (as the exact check does)."""
        g = 2 * (p - self.center) @ self.S
        return self.q(p) + np.sum(np.minimum(g * (LO - p), g * (HI - p)), axis=1)


def short(x: float, digits: int = 12) -> mpq:
    """A short decimal rational near x."""
    return mpq(Fraction(f"{x:.{digits}g}"))


def float_linear(LO: np.ndarray, HI: np.ndarray, variable: str, shape: rb.Shape,
                 ellipsoid: Ellipsoid) -> np.ndarray:
    """Float first-order bounds (:func:`verify.passivity.check.robust_band.linear_bound`)
    of the three conditions, the worst relative to its size, per box (proposals)."""
    dims = LO.shape[1] - 1
    ops = rb.GradOps(FloatOps, dims)
    t = (LO[:, -1], HI[:, -1])
    centre = (LO[:, :-1] + HI[:, :-1]) / 2
    with np.errstate(all="ignore"):
        at = rb.leaf_bounds([ops.variable((centre[:, k], centre[:, k]), k)
                             for k in range(dims)], t, variable, shape, ops)
        over = rb.leaf_bounds([ops.variable((LO[:, k], HI[:, k]), k) for k in range(dims)],
                              t, variable, shape, ops)
        worst = None
        for (value, _), (_, grad) in zip(at, over, strict=True):
            m = np.column_stack([(g[0] + g[1]) / 2 for g in grad])
            rho = np.column_stack([(g[1] - g[0]) / 2 for g in grad])
            quad = np.einsum("ki,ij,kj->k", m, ellipsoid.covariance, m)
            bound = (value[0] - np.sqrt(np.maximum(ellipsoid.chi2 * quad, 0))
                     + np.sum(m * (ellipsoid.center - centre), axis=1)
                     - np.sum(rho * (HI[:, :-1] - LO[:, :-1]) / 2, axis=1))
            size = np.abs(value[0]) + np.abs(value[1]) + 1e-300
            rel = np.nan_to_num(bound / size, nan=-np.inf)
            worst = rel if worst is None else np.minimum(worst, rel)
    return worst


def certified_root(grad, cov_phi, chi2: mpq) -> mpq:
    """A short rational r with r^2 >= chi2 m^T cov_phi m, m the gradient's midpoints: the
    largest first-order change over the region, rounded up so the exact check accepts it."""
    m = rb.gradient_midpoints(grad)
    n = len(m)
    need = chi2 * sum((m[i] * cov_phi[i][j] * m[j] for i in range(n) for j in range(n)),
                      mpq(0))
    root = short(math.sqrt(max(float(need), 0.0)) * (1 + 1e-6) + 1e-300, 6)
    while root * root < need:
        root = short(float(root) * (1 + 1e-5), 6)
    return root


def exact_linear_leaf(box: list[rb.Interval], variable: str, shape: rb.Shape, cov_phi,
                      phi_c, chi2: mpq, stability: bool) -> list | None:
    """A first-order leaf checked exactly, or None."""
    phi, t = box[:-1], box[-1]
    centre, parts = rb.linear_parts(phi, t, variable, shape)
    claimed, roots = [], []
    for value, grad in parts:
        root = certified_root(grad, cov_phi, chi2)
        low = rb.linear_bound(phi, centre, value, grad, phi_c, root)
        if not low > 0:
            return None
        claimed.append(floor_short(low))
        roots.append(root)
    if not rb.check_linear_leaf(box, variable, shape, cov_phi, phi_c, chi2, claimed, roots,
                                stability).ok:
        return None
    return ["linear", *[str(c) for c in claimed], *[str(r) for r in roots]]


def floor_short(q: mpq) -> mpq:
    """A rational <= q > 0 with 3 significant digits (the stored claimed bound: any
    positive number below the exact bound proves the leaf; short keeps files small)."""
    e = math.floor(math.log10(float(q))) - 2
    scale = mpq(10) ** e
    return mpq(int(q / scale)) * scale


@dataclass
class Node:
    split: int | None = None
    children: tuple[int, int] | None = None
    leaf: list | None = None


@dataclass
class SearchResult:
    """A tree (pre-order, as certificates store it) or why none was found."""

    tree: list | None
    leaves: int
    boxes: int
    reason: str
    candidates: list[tuple[np.ndarray, float]] = field(default_factory=list)


def search(root: list[rb.Interval], variable: str, shape: rb.Shape, ellipsoid: Ellipsoid,
           *, stability: bool, max_boxes: int = 60_000, exact: tuple | None = None
           ) -> SearchResult:
    """Branch and bound over ``root`` (φ then t): a proposed tree or the reason for none.

    Leaves are proposals: the caller checks the whole tree exactly
    (:func:`verify.identify.robust.band_check.check_leaves`). With ``exact`` =
    (Σ of φ, φc, χ) exact, boxes neither positive nor outside may become first-order
    leaves (checked exactly here, as they are costlier to propose).
    """
    nodes: list[Node] = [Node()]
    boxes: dict[int, list[rb.Interval]] = {0: root}
    active = [0]
    seen = 0
    candidates: list[tuple[np.ndarray, float]] = []
    while active:
        if seen + len(active) > max_boxes:
            return SearchResult(None, 0, seen, f"box budget of {max_boxes} boxes reached with "
                                f"{len(active)} boxes undecided", candidates)
        seen += len(active)
        LO = np.array([[float(a) for a, _ in boxes[i]] for i in active])
        HI = np.array([[float(b) for _, b in boxes[i]] for i in active])
        bounds = float_bounds(LO, HI, variable, shape)
        positive = _positive(bounds)
        if stability:
            for i in range(2):
                lo_a = [LO[:, i * shape.per_element + shape.zeros + 1 + k]
                        for k in range(shape.poles)]
                # a quick float screen; the exact leaf check runs Kharitonov's test
                positive &= np.all(np.array(lo_a) > 0, axis=0)
        p = ellipsoid.nearest(LO[:, :-1], HI[:, :-1])
        outside = ellipsoid.lower(LO[:, :-1], HI[:, :-1], p) > ellipsoid.chi2 * (1 + 1e-6)
        next_active = []
        split_needed = []
        for row, node_id in enumerate(active):
            leaf = None
            if positive[row]:  # claimed bounds: half the float bound, rounded down
                leaf = ["positive", *[str(floor_short(mpq(float(lo[row]) / 2)))
                                      for lo, _ in bounds]]
            elif outside[row]:
                leaf = ["outside", [str(short(v, 8)) for v in p[row]]]
            if leaf is not None:
                nodes[node_id].leaf = leaf
                del boxes[node_id]
            else:
                split_needed.append(row)
        if split_needed and exact is not None and ellipsoid.covariance is not None:
            rows = np.array(split_needed)
            linear = float_linear(LO[rows], HI[rows], variable, shape, ellipsoid)
            keep = []
            for j, row in enumerate(split_needed):
                leaf = None
                if linear[j] > FLOAT_MARGIN:
                    leaf = exact_linear_leaf(boxes[active[row]], variable, shape, *exact,
                                             stability)
                if leaf is None:
                    keep.append(row)
                else:
                    nodes[active[row]].leaf = leaf
                    del boxes[active[row]]
            split_needed = keep
        if split_needed:
            rows = np.array(split_needed)
            best = _choose_splits(LO[rows], HI[rows], variable, shape)
            centre = (LO[rows] + HI[rows]) / 2
            inside = ellipsoid.q(centre[:, :-1]) <= ellipsoid.chi2
            cb = float_bounds(centre, centre, variable, shape)
            worst = _score(cb)
            for j in range(len(split_needed)):
                if inside[j] and worst[j] < 0:
                    candidates.append((centre[j], float(worst[j])))
            if len(candidates) > 0 and len(candidates) >= 8:
                candidates.sort(key=lambda c: c[1])
                return SearchResult(None, 0, seen, "a box centre inside the region violates "
                                    "the conditions", candidates[:8])
            for j, row in enumerate(split_needed):
                node_id = active[row]
                k = int(best[j])
                left, right = rb.midpoint_split(boxes.pop(node_id), k)
                a, b = len(nodes), len(nodes) + 1
                nodes += [Node(), Node()]
                nodes[node_id].split, nodes[node_id].children = k, (a, b)
                boxes[a], boxes[b] = left, right
                next_active += [a, b]
        active = next_active
    tree, count = _preorder(nodes)
    candidates.sort(key=lambda c: c[1])
    return SearchResult(tree, count, seen, f"{count} leaves", candidates[:8])


def _choose_splits(LO: np.ndarray, HI: np.ndarray, variable: str, shape: rb.Shape
                   ) -> np.ndarray:
    """Per box, the coordinate whose better half scores best.

    Not the worse half: a box that fails in one corner fails in the half holding that
    corner whatever the split, so "best worst half" kept splitting the frequency (which
    helps a little everywhere) and never cut the corner off; the better half of a cut
    through the right parameter is decided at once (benchmarks/bench_identify_robust.py:
    the proved band grew from 3.3 to 5.4 rad/s for the widest region).
    """
    K, dims = LO.shape
    scores = np.full((K, dims), -np.inf)
    mid = (LO + HI) / 2
    for k in range(dims):
        width = HI[:, k] - LO[:, k]
        if not np.any(width > 0):
            continue
        H1, L2 = HI.copy(), LO.copy()
        H1[:, k], L2[:, k] = mid[:, k], mid[:, k]
        a = _score(float_bounds(LO, H1, variable, shape))
        b = _score(float_bounds(L2, HI, variable, shape))
        s = np.maximum(a, b)
        scores[:, k] = np.where(width > 0, s, -np.inf)
    return np.argmax(scores, axis=1)


def _preorder(nodes: list[Node]) -> tuple[list, int]:
    out: list = []
    count = 0
    stack = [0]
    while stack:
        node = nodes[stack.pop()]
        if node.leaf is not None:
            out.append(node.leaf)
            count += 1
        else:
            assert node.children is not None and node.split is not None
            out.append(node.split)
            stack += [node.children[1], node.children[0]]
    return out, count


__all__ = ["FLOAT_MARGIN", "Ellipsoid", "FloatOps", "SearchResult", "float_bounds",
           "floor_short", "search", "short"]
