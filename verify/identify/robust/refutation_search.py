"""Untrusted search for a region-wide refutation: one frequency, one direction, a tree.

Every model of a confidence region fails passivity on a band when, at one frequency w of
the band and one real direction v, g = (D_1 D_2 / 2) v^T (H_θ(jw) + H_θ(jw)^H) v < 0 for
every θ of the region (:func:`verify.passivity.check.robust_band.direction_bounds`; the
paper's Section 4 class: diagonal rational elements, constant off-diagonal elements).

The search (floating point, proposals only):

1. candidate (w, v): on a grid of the band, v the eigenvector of the smallest eigenvalue
   of the nominal H(jw) + H(jw)^H (real symmetric for this class), scored by the
   first-order upper bound of g over the ellipsoid, g(φc) + sqrt(χ ∇g^T Σ_φ ∇g),
   relative to D_1 D_2; the most negative few are tried, w and v rounded to short
   rationals;
2. for each, a branch and bound over the box enclosing the region's image in φ whose
   leaves are *negative* (float interval upper bound of g < 0), *outside* (the box
   misses the ellipsoid) or *linear* (first-order bound, checked exactly as it is made);
   a box is split at the midpoint of the coordinate with the largest
   |∂g/∂φ_k| x width.

The tree is then checked leaf by leaf in exact arithmetic
(:func:`verify.identify.robust.refutation_check.check_tree`); only a checked tree is
returned. A region that holds a passive model is never refuted: some leaf would have to
contain it, and its exact check fails.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np
from gmpy2 import mpq

from verify.identify.model.region import Region, half_widths
from verify.identify.robust import refutation_certificate as rfc
from verify.identify.robust import refutation_check
from verify.identify.robust.band_certificate import shape_of
from verify.identify.robust.proof_search import (
    Ellipsoid,
    FloatOps,
    certified_root,
    floor_short,
    short,
)
from verify.passivity.check import robust_band as rb

#: Boxes the branch and bound may visit per candidate (w, v).
MAX_BOXES = 6_000
#: Candidate (w, v) tried.
TRIES = 4


@dataclass
class Refutation:
    """A checked region-wide refutation (certificate as JSON) or why none was found."""

    certificate: dict[str, Any] | None
    reason: str


def _float_g(phi: np.ndarray, x: np.ndarray, v: np.ndarray, shape: rb.Shape, dims: int):
    """g, its gradient in φ (columns), D_1 D_2, at points φ (rows) and x (one per row)."""
    ops = rb.GradOps(FloatOps, dims)
    box = [ops.variable((phi[:, k], phi[:, k]), k) for k in range(dims)]
    with np.errstate(all="ignore"):
        g, d1, d2 = rb.direction_bounds(box, (x, x), (v[:, 0], v[:, 1]), shape, ops)
    grad = np.column_stack([gk[0] for gk in g[1]])
    return g[0][0], grad, d1[0][0] * d2[0][0]


def _grid(band: tuple[Fraction, Fraction] | None) -> np.ndarray:
    if band is None:
        return np.geomspace(1e-3, 1e5, 400)
    lo, hi = float(band[0]), float(band[1])
    return np.unique(np.r_[np.linspace(lo, hi, 200),
                           np.geomspace(max(lo, hi * 1e-3), hi, 200)])


def candidates(phi_c: np.ndarray, cov_phi: np.ndarray, chi2: float, shape: rb.Shape,
               band: tuple[Fraction, Fraction] | None, tries: int = TRIES
               ) -> list[tuple[mpq, tuple[mpq, mpq]]]:
    """Rational (w, v) whose first-order bound of g over the region is most negative."""
    omega = _grid(band)
    dims = len(phi_c)
    P = np.tile(phi_c, (len(omega), 1))
    x = omega**2
    # nominal Hermitian part [[2 N1/D1, c], [c, 2 N2/D2]] and its weakest direction
    n1, _, d1d2 = _float_g(P, x, np.tile([1.0, 0.0], (len(omega), 1)), shape, dims)
    n2, _, _ = _float_g(P, x, np.tile([0.0, 1.0], (len(omega), 1)), shape, dims)
    # g with v = e1 is N1 D2, with e2 is N2 D1: Re h_i = N_i / D_i
    with np.errstate(all="ignore"):
        re1, re2 = n1 / d1d2, n2 / d1d2  # (N1 D2)/(D1 D2) = N1/D1
    c = phi_c[-1]
    M = np.empty((len(omega), 2, 2))
    M[:, 0, 0], M[:, 1, 1] = 2 * re1, 2 * re2
    M[:, 0, 1] = M[:, 1, 0] = c
    finite = np.all(np.isfinite(M), axis=(1, 2)) & (d1d2 > 0)
    if not np.any(finite):
        return []
    omega, M = omega[finite], M[finite]
    V = np.linalg.eigh(M)[1][:, :, 0]  # the weakest direction per frequency
    V = V / np.max(np.abs(V), axis=1)[:, None]
    g, grad, dd = _float_g(np.tile(phi_c, (len(omega), 1)), omega**2, V, shape, dims)
    spread = np.sqrt(np.maximum(np.einsum("ki,ij,kj->k", grad, cov_phi, grad) * chi2, 0))
    with np.errstate(all="ignore"):
        score = (g + spread) / dd
    scored = [(float(score[k]), float(omega[k]), V[k]) for k in range(len(omega))
              if np.isfinite(score[k]) and dd[k] > 0]
    scored.sort(key=lambda s: s[0])
    out: list[tuple[mpq, tuple[mpq, mpq]]] = []
    for score, w, v in scored:
        if score >= 0 or len(out) >= tries:
            break
        wq = short(w, 6)
        if band is not None:
            wq = min(max(wq, mpq(band[0])), mpq(band[1]))
        vq = (short(float(v[0]), 6), short(float(v[1]), 6))
        if all(abs(float(wq) - float(o[0])) > 1e-3 * max(1.0, float(wq)) for o in out):
            out.append((wq, vq))
    return out


def _exact_linear(box: list[rb.Interval], x: mpq, v: tuple[mpq, mpq], shape: rb.Shape,
                  cov_phi, phi_c, chi2: mpq) -> list | None:
    """A first-order leaf ["linear", claimed, root] that passes the exact check, or None."""
    dims = len(box)
    ops = rb.GradOps(rb.ExactOps, dims)
    centre = [(lo + hi) / 2 for lo, hi in box]
    at = rb.direction_bounds([ops.variable((c, c), k) for k, c in enumerate(centre)],
                             (x, x), v, shape, ops)[0]
    over = rb.direction_bounds([ops.variable(iv, k) for k, iv in enumerate(box)], (x, x), v,
                               shape, ops)[0]
    value = rb.ExactOps.scale(-1, at[0])
    grad = [rb.ExactOps.scale(-1, gk) for gk in over[1]]
    root = certified_root(grad, cov_phi, chi2)
    low = rb.linear_bound(box, centre, value, grad, phi_c, root)
    if not low > 0:
        return None
    claimed = -floor_short(low)
    if not rb.check_negative_linear_leaf(box, x, v, shape, cov_phi, phi_c, chi2, claimed,
                                         root).ok:
        return None
    return ["linear", str(claimed), str(root)]


def _tree(root: list[rb.Interval], x: mpq, v: tuple[mpq, mpq], shape: rb.Shape,
          ellipsoid: Ellipsoid, exact: tuple, max_boxes: int) -> tuple[list | None, str]:
    """A proposed tree (pre-order) over ``root`` or (None, why)."""
    dims = len(root)
    # node: ("split", k, left, right) or ("leaf", leaf)
    nodes: list[Any] = [None]
    boxes = {0: root}
    active = [0]
    seen = 0
    xf, vf = float(x), (float(v[0]), float(v[1]))
    while active:
        if seen + len(active) > max_boxes:
            return None, f"box budget of {max_boxes} boxes reached"
        seen += len(active)
        LO = np.array([[float(a) for a, _ in boxes[i]] for i in active])
        HI = np.array([[float(b) for _, b in boxes[i]] for i in active])
        box = [(LO[:, k], HI[:, k]) for k in range(dims)]
        with np.errstate(all="ignore"):
            g, d1, d2 = rb.direction_bounds(box, (xf, xf), vf, shape, FloatOps)
        size = np.maximum(np.abs(g[0]), np.abs(g[1]))
        negative = np.isfinite(g[1]) & (g[1] < -1e-7 * size) & (d1[0] > 0) & (d2[0] > 0)
        p = ellipsoid.nearest(LO, HI)
        outside = ellipsoid.lower(LO, HI, p) > ellipsoid.chi2 * (1 + 1e-6)
        split = []
        for row, node_id in enumerate(active):
            leaf = None
            if negative[row]:
                leaf = ["negative", str(-floor_short(mpq(-float(g[1][row]) / 2)))]
            elif outside[row]:
                leaf = ["outside", [str(short(val, 8)) for val in p[row]]]
            else:
                leaf = _exact_linear(boxes[node_id], x, v, shape, *exact)
            if leaf is None:
                split.append(row)
            else:
                nodes[node_id] = ("leaf", leaf)
                del boxes[node_id]
        if split:
            rows = np.array(split)
            centre = (LO[rows] + HI[rows]) / 2
            inside = ellipsoid.q(centre) <= ellipsoid.chi2
            gc, grad, _ = _float_g(centre, np.full(len(rows), xf),
                                   np.tile(vf, (len(rows), 1)), shape, dims)
            if np.any(inside & (gc >= 0)):
                return None, ("a model inside the region has v^T (H + H^H) v >= 0 at this "
                              "w (float)")
            width = HI[rows] - LO[rows]
            choice = np.argmax(np.nan_to_num(np.abs(grad) * width, nan=np.inf), axis=1)
        next_active = []
        for j, row in enumerate(split):
            node_id = active[row]
            k = int(choice[j])
            left, right = rb.midpoint_split(boxes.pop(node_id), k)
            a, b = len(nodes), len(nodes) + 1
            nodes += [None, None]
            nodes[node_id] = ("split", k, a, b)
            boxes[a], boxes[b] = left, right
            next_active += [a, b]
        active = next_active
    out: list = []
    stack = [0]
    while stack:
        node = nodes[stack.pop()]
        if node[0] == "leaf":
            out.append(node[1])
        else:
            out.append(node[1])
            stack += [node[3], node[2]]
    return out, f"{sum(1 for n in out if isinstance(n, list))} leaves"


def refute_region(region: Region, structure_text: str,
                  band: tuple[Fraction, Fraction] | None, *, name: str, source: str,
                  max_boxes: int = MAX_BOXES, tries: int = TRIES) -> Refutation:
    """A checked certificate that no model of the region is passive on ``band`` (None:
    all frequencies), or why none was found (module docstring)."""
    shape = shape_of(structure_text)
    phi, cov_phi = rb.reduce_region(region.center, region.covariance)
    r = half_widths(cov_phi, region.chi2)
    S = rb.inverse(cov_phi)
    covf = np.array([[float(x) for x in row] for row in cov_phi])
    ellipsoid = Ellipsoid(np.array([float(x) for x in phi]),
                          np.array([[float(x) for x in row] for row in S]),
                          float(region.chi2), covf)
    found = candidates(ellipsoid.center, covf, ellipsoid.chi2, shape, band, tries)
    if not found:
        return Refutation(None, "no frequency and direction where every model of the region "
                          "fails (first-order screen)")
    root = [(c - h, c + h) for c, h in zip(phi, r, strict=True)]
    reasons = []
    for w, v in found:
        tree, why = _tree(root, w * w, v, shape, ellipsoid, (cov_phi, phi, region.chi2),
                          max_boxes)
        if tree is None:
            reasons.append(f"w = {float(w):.4g}: {why}")
            continue
        data = rfc.certificate_json(name, source, structure_text, region, band, w, v, r,
                                    tree)
        refusal = refutation_check.check_tree(data, shape, region, w, v)
        if refusal is None:
            return Refutation(data, f"v^T (H + H^H) v < 0 at w = {w} rad/s for every model "
                              f"of the region: {data['leaves']} leaves checked exactly")
        reasons.append(f"w = {float(w):.4g}: the proposed tree fails the exact check "
                       f"({refusal})")
    return Refutation(None, "; ".join(reasons))


__all__ = ["MAX_BOXES", "TRIES", "Refutation", "candidates", "refute_region"]
