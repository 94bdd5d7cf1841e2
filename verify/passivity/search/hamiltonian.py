"""The minimum of nu(w) (paper, Section 4) located by Hamiltonian level crossings, not a grid.

Section 4 of the paper defines nu(w) = lambda_min(H(jw) + H(jw)^H) / 2 and reads
passivity off nu >= 0. A grid of frequencies can step over a narrow dip (a lightly
damped resonance); the level-crossing test cannot.

Level crossings. For a level gamma put R = D + D^T - 2 gamma I. When R is nonsingular,
the frequencies w at which H(jw) + H(jw)^H - 2 gamma I is singular (an eigenvalue of
H + H^H crosses 2 gamma) are the imaginary eigenvalues j w of the Hamiltonian matrix

    M(gamma) = [[A - B R^-1 C,      -B R^-1 B^T       ],
                [C^T R^-1 C,        -A^T + C^T R^-1 B^T]],

the zeros of Phi(s) = H(s) + H(-s)^T - 2 gamma I, realised as
([[A, 0], [0, -A^T]], [[B], [-C^T]], [C, B^T], R).

The minimum. Start from the smallest nu among a few frequencies (0, w -> infinity, the
pole magnitudes). With gamma just below the current best value, the crossings split the
axis into intervals on which nu - gamma keeps its sign; nu < gamma somewhere exactly
when some interval does, so evaluating nu at the midpoint of every interval between
consecutive crossings either improves the best value or shows (up to the tolerance of
the eigenvalue test) that none lies below gamma. This is the Boyd-Balakrishnan /
Bruinsma-Steinbuch iteration for the H-infinity norm, applied to nu. A last local
polish refines the minimiser. The result is a floating-point estimate: the gate turns
it into exact statements with :mod:`verify.passivity.check.witness` and KYP certificates.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]

#: gamma is placed this far (relative) below the best value found so far.
LEVEL_GAP = 1e-7
#: An eigenvalue counts as imaginary when |Re| <= this times the norm of M(gamma) (a false
#: positive only costs one evaluation of nu; a false negative could miss a dip).
IMAGINARY_TOLERANCE = 1e-8
MAX_ITERATIONS = 60


def nu_values(A: Array, B: Array, C: Array, D: Array, omega: Array) -> Array:
    """nu(w) = lambda_min(H(jw) + H(jw)^H)/2 (paper, Section 4), NaN at a pole; w = inf allowed."""
    n = A.shape[0]
    out = np.empty(len(omega))
    for k, w in enumerate(omega):
        if math.isinf(w) or n == 0:
            H = D.astype(complex)
        else:
            try:
                H = C @ np.linalg.solve(1j * w * np.eye(n) - A, B) + D
            except np.linalg.LinAlgError:
                out[k] = np.nan
                continue
        out[k] = np.linalg.eigvalsh(H + H.conj().T)[0] / 2
    return out


def hamiltonian(A: Array, B: Array, C: Array, D: Array, gamma: float) -> Array | None:
    """M(gamma) of the module docstring; None when R = D + D^T - 2 gamma I is singular."""
    m = D.shape[0]
    R = D + D.T - 2.0 * gamma * np.eye(m)
    if np.linalg.cond(R) > 1e14:
        return None
    Ri = np.linalg.inv(R)
    return np.block([[A - B @ Ri @ C, -B @ Ri @ B.T],
                     [C.T @ Ri @ C, -A.T + C.T @ Ri @ B.T]])


def level_crossings(A: Array, B: Array, C: Array, D: Array, gamma: float) -> Array | None:
    """Sorted w >= 0 where some eigenvalue of H(jw) + H(jw)^H equals 2 gamma.

    None when the test does not apply (R singular). Poles of H on the imaginary axis show
    up as well; nu is undefined there and they only serve as interval ends.
    """
    M = hamiltonian(A, B, C, D, gamma)
    if M is None:
        return None
    if M.shape[0] == 0:
        return np.zeros(0)
    eig = np.linalg.eigvals(M)
    scale = max(1.0, float(np.linalg.norm(M, 1)))
    imaginary = eig[np.abs(eig.real) <= IMAGINARY_TOLERANCE * scale]
    return np.unique(np.abs(imaginary.imag))


@dataclass(frozen=True)
class NuMinimum:
    """Where nu is smallest on a band (default: all w >= 0 and w -> infinity).

    ``omega`` is ``math.inf`` when the infimum is the limit w -> infinity (nu(inf) =
    lambda_min(D + D^T)/2). ``lower`` is the last level at which no crossing was found
    (numerically nu >= lower on the band). All floating point: an estimate, not a proof.
    """

    omega: float
    value: float
    lower: float
    iterations: int

    @property
    def at_infinity(self) -> bool:
        return math.isinf(self.omega)


def _seed_frequencies(A: Array, lo: float, hi: float) -> Array:
    """A few starting frequencies: the band ends, pole magnitudes and resonances inside it."""
    seeds = [lo, hi]
    if A.shape[0]:
        poles = np.linalg.eigvals(A)
        seeds += list(np.abs(poles)) + list(np.abs(poles.imag))
    finite_hi = hi if math.isfinite(hi) else max([1.0, *[s for s in seeds if math.isfinite(s)]])
    seeds += list(np.geomspace(max(lo, 1e-3), max(finite_hi, 1e-3) * 10, 12))
    return np.array([s for s in seeds if lo <= s <= hi])


def _midpoints(points: Array, hi: float) -> Array:
    """One interior frequency of each interval between consecutive points (and beyond)."""
    mids = list((points[:-1] + points[1:]) / 2)
    if math.isinf(hi) and points.size:
        mids.append(2.0 * points[-1] + 1.0)
    return np.array(mids)


def nu_minimum(A: Array, B: Array, C: Array, D: Array,
               band: tuple[float, float] | None = None) -> NuMinimum:
    """Locate min nu(w) over w in ``band`` (closed; default [0, inf] including infinity)."""
    lo, hi = (0.0, math.inf) if band is None else (float(band[0]), float(band[1]))
    if A.shape[0] == 0:  # static gain: nu is constant
        v = float(nu_values(A, B, C, D, np.array([math.inf]))[0])
        return NuMinimum(math.inf if band is None else lo, v, v, 0)
    seeds = _seed_frequencies(A, lo, hi)
    with np.errstate(all="ignore"):
        values = nu_values(A, B, C, D, seeds)
    if math.isinf(hi):  # the limit w -> infinity is part of the full axis
        seeds = np.append(seeds, math.inf)
        values = np.append(values, nu_values(A, B, C, D, np.array([math.inf])))
    finite = np.isfinite(values)
    k = int(np.argmin(np.where(finite, values, np.inf)))
    best_w, best = float(seeds[k]), float(values[k])
    lower = -math.inf
    iterations = 0
    while iterations < MAX_ITERATIONS:
        iterations += 1
        gamma = best - LEVEL_GAP * max(1.0, abs(best))
        crossings = level_crossings(A, B, C, D, gamma)
        if crossings is None:
            gamma = best - 1e3 * LEVEL_GAP * max(1.0, abs(best))
            crossings = level_crossings(A, B, C, D, gamma)
            if crossings is None:
                break
        inside = crossings[(crossings >= lo) & (crossings <= hi)]
        if inside.size == 0:
            lower = gamma
            break
        ends = [lo] + ([] if math.isinf(hi) else [hi])
        points = np.unique(np.concatenate([inside, ends]))
        trial = _midpoints(points, hi)
        trial = trial[(trial >= lo) & (trial <= hi)]
        with np.errstate(all="ignore"):
            tv = nu_values(A, B, C, D, trial)
        tv = np.where(np.isfinite(tv), tv, np.inf)
        j = int(np.argmin(tv)) if tv.size else -1
        if j < 0 or tv[j] >= gamma:  # no interval below gamma: only spurious crossings
            lower = gamma
            break
        best_w, best = float(trial[j]), float(tv[j])
    best_w, best = _polish(A, B, C, D, best_w, best, lo, hi)
    return NuMinimum(best_w, best, min(lower, best), iterations)


def _polish(A: Array, B: Array, C: Array, D: Array, w0: float, v0: float, lo: float,
            hi: float) -> tuple[float, float]:
    """Local refinement of a finite minimiser inside the band (keeps the better point)."""
    if math.isinf(w0):
        return w0, v0
    left = max(lo, w0 * (1 - 1e-3) if w0 > 0 else 0.0)
    right = min(hi, w0 * (1 + 1e-3) if w0 > 0 else 1e-6)
    if right <= left:
        return w0, v0
    from scipy.optimize import minimize_scalar  # imported on use (start-up time)

    res = minimize_scalar(lambda x: nu_values(A, B, C, D, np.array([x]))[0],
                          bounds=(left, right), method="bounded", options={"xatol": 1e-14})
    if np.isfinite(res.fun) and res.fun < v0:
        return float(res.x), float(res.fun)
    return w0, v0




def nu_rounding_bound(A, B, C, D, omega: float) -> float:
    """A first-order bound on the rounding error of ν(ω) evaluated in floating point:
    n u cond(jωI - A) |C| |(jωI - A)^-1| |B| + u |D| (2-norms, u the unit roundoff), the
    usual forward-error size of a linear solve. Infinite when jωI - A is singular."""
    n = A.shape[0]
    u = np.finfo(float).eps / 2
    with np.errstate(all="ignore"):
        try:
            s = np.linalg.svd(1j * omega * np.eye(n) - A, compute_uv=False)
        except np.linalg.LinAlgError:
            return math.inf
        if n and (s[-1] == 0 or not np.all(np.isfinite(s))):
            return math.inf
        inverse = 1 / s[-1] if n else 0.0
        cond = s[0] / s[-1] if n else 1.0
        bound = n * u * cond * np.linalg.norm(C, 2) * inverse * np.linalg.norm(B, 2) \
            + u * np.linalg.norm(D, 2)
    return float(bound) if math.isfinite(bound) else math.inf


__all__ = ["NuMinimum", "hamiltonian", "level_crossings", "nu_minimum", "nu_rounding_bound",
           "nu_values"]
