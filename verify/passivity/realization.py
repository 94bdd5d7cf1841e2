"""Minimal realisation of a transfer matrix H(s) given as num/den grids (issue 4, item 1).

Realisation of a transfer matrix
--------------------------------
Each non-constant element (i, j) gets its controllable canonical (companion) realisation,
driven by input j and read by output i; the blocks are stacked block-diagonally. The
stack is minimal only when no pole is shared within a column or a row and no element has
a pole-zero cancellation, so it is then reduced. Scaling first: a diagonal power-of-two
balancing of A (exact), unit-norm columns of B, and row i of C divided by
max(|C_i|, |A| |D_i|), so that the dynamics of an output are weighed against its
feedthrough. Then an orthogonal staircase (Kalman) decomposition keeps the controllable
part, and the same on the dual system keeps the observable part. Rank decisions use
singular values: one counts when it exceeds tol times the 2-norm of [A B] (resp.
[A^T C^T]), with tol = 1e-10 (``MINIMALITY_TOLERANCES[0]``).

The realisation is then checked: its frequency response is compared with direct
evaluation of num/den at 0 and 50 log-spaced frequencies from a decade below the smallest
to a decade above the largest pole magnitude (frequencies within a relative 1e-6 of a
pole are skipped). The largest relative error is stored in ``realization_error``. Should
it exceed ``REALIZATION_ERROR_LIMIT`` (1e-8) because the reduction discarded a mode that
matters, the reduction is repeated with tol = 1e-13; if that fails too, the input is
refused. A minimal realisation is thus minimal up to a relative 1e-10 (or 1e-13), never
at the price of an error above 1e-8.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.linalg as sla
from numpy.typing import NDArray

from verify.errors import VerifyInputError
from verify.passivity.model import Array, LTIModel, _nested, _short

#: Relative thresholds for a singular value to count in the staircase rank decisions: the
#: first is used unless the reduced model fails the frequency check, then the next.
MINIMALITY_TOLERANCES = (1e-10, 1e-13)
#: Largest accepted relative frequency-response error of a transfer-function realisation.
REALIZATION_ERROR_LIMIT = 1e-8
#: Number of log-spaced frequencies (besides 0) in the realisation check.
CHECK_FREQUENCIES = 50
#: Gains below this fraction of the peak gain are not used as the scale of a relative error.
_GAIN_FLOOR = 1e-6
#: A check frequency closer than this (relative) to a pole is skipped.
_POLE_GAP = 1e-6


def _grid(value: Any, label: str, ctx: str) -> list[list[Array]]:
    """An m_out x m_in grid of non-empty 1-D coefficient lists, as float arrays."""
    nested = _nested(value, f"{ctx}: {label}")
    shape_hint = f"expected {label}[i][j] = coefficients of element (i, j)"
    if not isinstance(nested, list) or not nested:
        raise VerifyInputError(f"{ctx}: {label}: {shape_hint}, got {_short(nested)}")
    grid: list[list[Array]] = []
    for i, row in enumerate(nested):
        if not isinstance(row, list) or not row:
            raise VerifyInputError(
                f"{ctx}: {label}[{i}]: {shape_hint}, a non-empty list per output row"
            )
        cells = []
        for j, coeffs in enumerate(row):
            where = f"{ctx}: {label}[{i}][{j}]"
            if not isinstance(coeffs, list):
                raise VerifyInputError(
                    f"{where}: expected a list of coefficients (descending powers of s), "
                    "got a number (nesting too shallow)"
                )
            if not coeffs:
                raise VerifyInputError(f"{where}: empty coefficient list")
            for k, c in enumerate(coeffs):
                if isinstance(c, list):
                    raise VerifyInputError(
                        f"{where}[{k}]: expected a number, got a list (nesting too deep)"
                    )
            cells.append(np.array(coeffs, dtype=float))
        if len(cells) != len(grid[0] if grid else cells):
            raise VerifyInputError(
                f"{ctx}: {label}: rows of different lengths ({label}[0] has {len(grid[0])} "
                f"entries, {label}[{i}] has {len(cells)})"
            )
        grid.append(cells)
    return grid


def _strip(c: Array) -> Array:
    """Coefficients without leading (exact) zeros; [] for the zero polynomial."""
    nz = np.flatnonzero(c)
    return c[nz[0] :] if nz.size else c[:0]


@dataclass(frozen=True)
class _Element:
    num: Array  # stripped, possibly empty (zero element)
    den: Array  # stripped, non-empty


def _elements(num: Any, den: Any, ctx: str) -> list[list[_Element]]:
    N, Dg = _grid(num, "num", ctx), _grid(den, "den", ctx)
    shape_n, shape_d = (len(N), len(N[0])), (len(Dg), len(Dg[0]))
    if shape_n != shape_d:
        raise VerifyInputError(
            f"{ctx}: num is {shape_n[0]} x {shape_n[1]} but den is {shape_d[0]} x {shape_d[1]}; "
            "they need the same m x m nesting"
        )
    if shape_n[0] != shape_n[1]:
        raise VerifyInputError(
            f"{ctx}: H must be square (m inputs = m outputs), but num/den are "
            f"{shape_n[0]} x {shape_n[1]}"
        )
    out = []
    for i, (nrow, drow) in enumerate(zip(N, Dg, strict=True)):
        row = []
        for j, (nc, dc) in enumerate(zip(nrow, drow, strict=True)):
            nu, de = _strip(nc), _strip(dc)
            if de.size == 0:
                raise VerifyInputError(f"{ctx}: den[{i}][{j}]: zero denominator")
            if nu.size > de.size:
                raise VerifyInputError(
                    f"{ctx}: element ({i}, {j}) is improper: numerator degree {nu.size - 1} "
                    f"> denominator degree {de.size - 1} (H must be proper)"
                )
            row.append(_Element(nu, de))
        out.append(row)
    return out


def _stacked_realization(
    elements: list[list[_Element]], ctx: str
) -> tuple[Array, Array, Array, Array]:
    """Block-diagonal companion realisations of the elements (not minimal in general)."""
    m = len(elements)
    D = np.zeros((m, m))
    blocks = []
    for i, row in enumerate(elements):
        for j, el in enumerate(row):
            if el.num.size == 0:
                continue
            with np.errstate(all="ignore"):
                a = el.den / el.den[0]
                b = np.concatenate([np.zeros(el.den.size - el.num.size), el.num]) / el.den[0]
            if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
                raise VerifyInputError(
                    f"{ctx}: element ({i}, {j}): coefficients overflow when the denominator "
                    "is made monic"
                )
            D[i, j] = b[0]
            r = b[1:] - b[0] * a[1:]  # strictly proper remainder, s^(k-1) ... s^0
            if a.size == 1 or not r.any():
                continue
            k = a.size - 1
            Ab = np.zeros((k, k))
            Ab[0, :] = -a[1:]
            Ab[1:, :-1] = np.eye(k - 1)
            blocks.append((i, j, Ab, r))
    n = sum(Ab.shape[0] for _, _, Ab, _ in blocks)
    A, B, C = np.zeros((n, n)), np.zeros((n, m)), np.zeros((m, n))
    at = 0
    for i, j, Ab, r in blocks:
        k = Ab.shape[0]
        A[at : at + k, at : at + k] = Ab
        B[at, j] = 1.0
        C[i, at : at + k] = r
        at += k
    return A, B, C, D


def _controllable_part(A: Array, B: Array, C: Array, tol_rel: float) -> tuple[Array, Array, Array]:
    """Orthogonal staircase: the controllable part of (A, B, C), SVD rank decisions.

    A singular value counts when it exceeds ``tol_rel`` times the 2-norm of [A B].
    """
    n = A.shape[0]
    scale = np.linalg.norm(np.hstack([A, B]), 2) if n else 0.0
    if n == 0 or scale == 0.0:
        return A[:0, :0], B[:0], C[:, :0]
    tol = tol_rel * scale
    A, B, C = A.copy(), B.copy(), C.copy()
    k = 0
    block = B
    while k < n:
        U, s, _ = np.linalg.svd(block, full_matrices=True)
        r = int(np.sum(s > tol))
        if r == 0:
            break
        A[k:, :] = U.T @ A[k:, :]
        A[:, k:] = A[:, k:] @ U
        B[k:, :] = U.T @ B[k:, :]
        C[:, k:] = C[:, k:] @ U
        block = A[k + r :, k : k + r]
        k += r
    return A[:k, :k], B[:k], C[:, :k]


def _minimal_realization(
    A: Array, B: Array, C: Array, D: Array, tol_rel: float
) -> tuple[Array, Array, Array]:
    """A minimal (controllable and observable) part of (A, B, C); D is unaffected.

    Scaling first: A is balanced by a diagonal similarity (powers of two, exact), the
    columns of B get unit norm, and row i of C is divided by max(|C_i|, |A| |D_i|): the
    dynamic part of output i is measured against its feedthrough, so that rounding noise
    in a numerator that is (nearly) a multiple of its denominator is not mistaken for
    dynamics, while a model whose gain is small throughout keeps its states.
    """
    if A.shape[0] == 0:
        return A, B, C
    _, (t, _) = sla.matrix_balance(A, permute=False, separate=True)
    A, B, C = A * (1.0 / t)[:, None] * t[None, :], B / t[:, None], C * t[None, :]
    bs = np.linalg.norm(B, axis=0)
    bs[bs == 0] = 1.0
    cs = np.maximum(np.linalg.norm(C, axis=1), np.linalg.norm(A, 2) * np.linalg.norm(D, axis=1))
    cs[cs == 0] = 1.0
    A, B, C = _controllable_part(A, B / bs, C / cs[:, None], tol_rel)
    At, Ct, Bt = _controllable_part(A.T, C.T, B.T, tol_rel)  # observable part, by duality
    return At.T, Bt.T * bs, Ct.T * cs[:, None]


def _check_frequencies(elements: list[list[_Element]]) -> Array:
    poles = [np.roots(el.den) for row in elements for el in row if el.den.size > 1]
    p = np.concatenate(poles) if poles else np.zeros(0)
    mags = np.abs(p)
    mags = mags[mags > 0]
    lo, hi = (mags.min(), mags.max()) if mags.size else (1.0, 1.0)
    w = np.concatenate([[0.0], np.logspace(np.log10(lo) - 1, np.log10(hi) + 1, CHECK_FREQUENCIES)])
    if p.size:
        gap = np.abs(1j * w[:, None] - p[None, :]) / np.maximum(1.0, np.abs(p))[None, :]
        w = w[gap.min(axis=1) > _POLE_GAP]
    return w


def _direct_response(elements: list[list[_Element]], omega: Array) -> NDArray[np.complex128]:
    s = 1j * omega
    m = len(elements)
    H = np.zeros((omega.size, m, m), dtype=complex)
    for i, row in enumerate(elements):
        for j, el in enumerate(row):
            if el.num.size:
                H[:, i, j] = np.polyval(el.num, s) / np.polyval(el.den, s)
    return H


def _realization_error(model: LTIModel, elements: list[list[_Element]]) -> float:
    """Largest relative error ||H_ss - H_tf||_F / ||H_tf||_F over the check frequencies.

    The scale of the relative error is never taken below ``1e-6`` times the peak gain on
    the grid, so that a transmission zero on the grid (s/(s+1) at w = 0) does not turn
    rounding into a false alarm. An identically zero H gives the absolute error.
    """
    w = _check_frequencies(elements)
    direct = _direct_response(elements, w)
    realised = model.frequency_response(w)
    gain = np.linalg.norm(direct, axis=(1, 2))
    diff = np.linalg.norm(realised - direct, axis=(1, 2))
    peak = float(gain.max()) if gain.size else 0.0
    if peak == 0.0:
        return float(diff.max()) if diff.size else 0.0
    return float(np.max(diff / np.maximum(gain, _GAIN_FLOOR * peak)))


def transfer_function_model(
    num: Any, den: Any, ctx: str, *, name: str, source: str, meta: dict | None
) -> LTIModel:
    elements = _elements(num, den, ctx)
    A0, B0, C0, D = _stacked_realization(elements, ctx)
    err = math.nan
    for tol in MINIMALITY_TOLERANCES:
        A, B, C = _minimal_realization(A0, B0, C0, D, tol)
        model = LTIModel(name, A, B, C, D, source=source, meta=dict(meta or {}))
        with np.errstate(all="ignore"):
            err = _realization_error(model, elements)
        if err <= REALIZATION_ERROR_LIMIT:  # False for NaN
            return LTIModel(
                name, A, B, C, D, source=source, meta=dict(meta or {}), realization_error=err
            )
    raise VerifyInputError(
        f"{ctx}: realisation error {err:.3g} of the transfer function exceeds "
        f"{REALIZATION_ERROR_LIMIT:g} (badly scaled or nearly cancelling coefficients?)"
    )
