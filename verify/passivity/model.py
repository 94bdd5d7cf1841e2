"""Human models H(s) as validated continuous-time LTI systems (issue 4, item 1).

Section 4 of the paper closes the loop through an identified human model H(s), a square
m x m transfer matrix (m inputs, m outputs). The passivity gate works on a state-space
realisation H(s) = C (sI - A)^-1 B + D, held here as an :class:`LTIModel`. Models come
from

* :func:`from_state_space`: (A, B, C, D) as given, after validation (n = 0 is allowed);
* :func:`from_transfer_function`: an m x m grid of numerator/denominator coefficient
  lists (descending powers of s), realised and reduced to a *minimal* realisation, whose
  frequency response is then checked against the polynomials themselves;
* :func:`from_python`: python-control ``StateSpace`` / ``TransferFunction`` and
  scipy.signal ``lti`` objects (continuous time only).

Every problem with the input is a :class:`~verify.errors.VerifyInputError` whose message
is one line naming the problem.

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

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import scipy.linalg as sla
from numpy.typing import ArrayLike, NDArray

from verify.errors import VerifyInputError

Array = NDArray[np.float64]

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


# --------------------------------------------------------------------------- validation


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _scalar(value: Any, where: str) -> float:
    """A real, finite number as float; bool, text, None and complex values are refused."""
    if isinstance(value, complex | np.complexfloating) and value.imag == 0:
        value = value.real
    if isinstance(value, bool | np.bool_) or not isinstance(
        value, int | float | np.integer | np.floating
    ):
        raise VerifyInputError(
            f"{where}: expected a real number, got {type(value).__name__} {_short(value)}"
        )
    try:
        x = float(value)
    except OverflowError:
        raise VerifyInputError(f"{where}: number too large for a float") from None
    if not math.isfinite(x):
        raise VerifyInputError(f"{where}: NaN or Inf is not allowed")
    return x


def _finite(value: NDArray, where: str) -> Array:
    """A float64 copy of an integer or float array, refusing NaN and Inf (by index)."""
    arr = np.array(value, dtype=float)
    bad = np.argwhere(~np.isfinite(arr))
    if bad.size:
        index = "".join(f"[{k}]" for k in bad[0])
        raise VerifyInputError(f"{where}{index}: NaN or Inf is not allowed")
    return arr


def _nested(value: Any, where: str) -> Any:
    """Nested lists / tuples / arrays of real numbers as nested lists of float."""
    if isinstance(value, np.ndarray):
        if value.dtype.kind in "iuf":
            return _finite(value, where).tolist()
        value = value.tolist()  # bool, complex, object, text: checked entry by entry
    if isinstance(value, list | tuple):
        return [_nested(v, f"{where}[{i}]") for i, v in enumerate(value)]
    return _scalar(value, where)


def _matrix(value: Any, where: str) -> Array:
    """A real finite array of any rank from nested sequences (ragged nesting refused)."""
    if isinstance(value, np.ndarray) and value.dtype.kind in "iuf":
        return _finite(value, where)
    nested = _nested(value, where)
    try:
        return np.array(nested, dtype=float)
    except ValueError:
        raise VerifyInputError(f"{where}: ragged nesting (rows of different lengths)") from None


def _check_state_space(
    A: ArrayLike, B: ArrayLike, C: ArrayLike, D: ArrayLike, ctx: str
) -> tuple[Array, Array, Array, Array]:
    """Validated float64 copies of (A, B, C, D) with consistent shapes and H square."""
    Am, Bm, Cm, Dm = (_matrix(x, f"{ctx}: {k}") for k, x in zip("ABCD", (A, B, C, D), strict=True))
    if Dm.ndim != 2 or Dm.size == 0:
        raise VerifyInputError(
            f"{ctx}: D: expected an m x m matrix with m >= 1, got shape {Dm.shape}"
        )
    p, q = Dm.shape
    if p != q:
        raise VerifyInputError(
            f"{ctx}: H must be square (m inputs = m outputs), but D is {p} x {q}"
        )
    m = p
    if Am.ndim == 1 and Am.size == 0:
        Am = Am.reshape(0, 0)
    if Am.ndim != 2 or Am.shape[0] != Am.shape[1]:
        raise VerifyInputError(f"{ctx}: A: expected a square n x n matrix, got shape {Am.shape}")
    n = Am.shape[0]
    if n == 0 and Bm.ndim == 1 and Bm.size == 0:
        Bm = Bm.reshape(0, m)
    if n == 0 and Cm.ndim == 1 and Cm.size == 0:
        Cm = Cm.reshape(m, 0)
    if Bm.ndim == 2 and Cm.ndim == 2 and Bm.shape[0] == Cm.shape[1] == n:
        if Bm.shape[1] != Cm.shape[0]:
            raise VerifyInputError(
                f"{ctx}: H must be square (m inputs = m outputs), but B has {Bm.shape[1]} "
                f"column(s) and C has {Cm.shape[0]} row(s)"
            )
    if Bm.shape != (n, m):
        raise VerifyInputError(
            f"{ctx}: B: expected shape ({n}, {m}) for {n} state(s) and {m} input(s), got {Bm.shape}"
        )
    if Cm.shape != (m, n):
        raise VerifyInputError(
            f"{ctx}: C: expected shape ({m}, {n}) for {m} output(s) and {n} state(s), "
            f"got {Cm.shape}"
        )
    return Am, Bm, Cm, Dm


def _frozen(x: Array) -> Array:
    y = np.array(x, dtype=np.float64, copy=True)
    y.setflags(write=False)
    return y


# --------------------------------------------------------------------------- the model


@dataclass(frozen=True, eq=False)
class LTIModel:
    """A validated continuous-time square LTI model H(s) = C (sI - A)^-1 B + D.

    The matrices are read-only float64 copies. ``source`` is the file the model came from,
    or ``"python"``; ``meta`` holds the optional descriptive fields of a model file
    (``k_s``, ``units``, ``description``, ``reconstructed``). ``realization_error`` is set
    for models realised from a transfer function (see the module docstring), else None.
    Equality is identity (the fields hold arrays).
    """

    name: str
    A: Array
    B: Array
    C: Array
    D: Array
    source: str = "python"
    meta: dict = field(default_factory=dict)
    realization_error: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):
            raise VerifyInputError(f"model name must be a string, got {type(self.name).__name__}")
        if not isinstance(self.source, str):
            raise VerifyInputError(f"model {self.name!r}: source must be a string")
        if not isinstance(self.meta, dict):
            raise VerifyInputError(f"model {self.name!r}: meta must be a dict")
        A, B, C, D = _check_state_space(self.A, self.B, self.C, self.D, f"model {self.name!r}")
        for key, value in zip("ABCD", (A, B, C, D), strict=True):
            object.__setattr__(self, key, _frozen(value))
        object.__setattr__(self, "meta", dict(self.meta))
        if self.realization_error is not None:
            err = _scalar(self.realization_error, f"model {self.name!r}: realization_error")
            object.__setattr__(self, "realization_error", err)

    @property
    def n(self) -> int:
        """Number of states (0 for a static gain)."""
        return int(self.A.shape[0])

    @property
    def m(self) -> int:
        """Number of inputs, equal to the number of outputs."""
        return int(self.D.shape[0])

    def frequency_response(self, omega: ArrayLike) -> NDArray[np.complex128]:
        """H(j w) = C (j w I - A)^-1 B + D at each real w, shape (len(omega), m, m).

        A frequency where j w is an eigenvalue of A (a pole on the imaginary axis) has no
        value and raises :class:`VerifyInputError`.
        """
        w = _matrix(omega, f"model {self.name!r}: omega")
        if w.ndim == 0:
            w = w.reshape(1)
        if w.ndim != 1:
            raise VerifyInputError(
                f"model {self.name!r}: omega must be a 1-D array, got shape {w.shape}"
            )
        n, m = self.n, self.m
        H = np.empty((w.size, m, m), dtype=complex)
        H[:] = self.D
        if n == 0 or w.size == 0:
            return H
        eye = np.eye(n)
        chunk = max(1, (1 << 22) // (n * n))  # at most ~64 MB of complex matrices at once
        for start in range(0, w.size, chunk):
            ws = w[start : start + chunk]
            M = 1j * ws[:, None, None] * eye - self.A
            rhs = np.broadcast_to(self.B.astype(complex), (ws.size, n, m))
            try:
                X = np.linalg.solve(M, rhs)
            except np.linalg.LinAlgError:
                singular = (x for x, Mk in zip(ws, M, strict=True) if np.linalg.matrix_rank(Mk) < n)
                wk = next(singular, ws[0])
                raise VerifyInputError(
                    f"model {self.name!r}: omega = {wk:g} is a pole (j omega is an "
                    "eigenvalue of A), H(j omega) is undefined there"
                ) from None
            H[start : start + ws.size] += self.C @ X
        return H


def from_state_space(
    A: ArrayLike,
    B: ArrayLike,
    C: ArrayLike,
    D: ArrayLike,
    *,
    name: str = "model",
    source: str = "python",
    meta: dict | None = None,
) -> LTIModel:
    """A model from its state-space matrices, validated and kept as given (not reduced).

    A may be empty (n = 0): A = [] with B of shape (0, m) and C of shape (m, 0) (or both
    given as []); D (m x m, m >= 1) fixes m.
    """
    ctx = f"model {name!r}" if source == "python" else source
    return _state_space_model(A, B, C, D, ctx, name=name, source=source, meta=meta)


def _state_space_model(
    A: Any, B: Any, C: Any, D: Any, ctx: str, *, name: str, source: str, meta: dict | None
) -> LTIModel:
    A, B, C, D = _check_state_space(A, B, C, D, ctx)
    return LTIModel(name, A, B, C, D, source=source, meta=dict(meta or {}))


# --------------------------------------------------------------------------- transfer functions


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


def from_transfer_function(
    num: Any,
    den: Any,
    *,
    name: str = "model",
    source: str = "python",
    meta: dict | None = None,
) -> LTIModel:
    """A minimal realisation of the m x m transfer matrix num[i][j] / den[i][j].

    ``num[i][j]`` and ``den[i][j]`` are coefficient lists of element (i, j) in descending
    powers of s (leading zeros are ignored). Each element must be proper and have a
    non-zero denominator. A constant transfer matrix gives n = 0. The realisation error
    (module docstring) is stored in ``realization_error``; above 1e-8 the input is refused.
    """
    ctx = f"model {name!r}" if source == "python" else source
    return _transfer_function_model(num, den, ctx, name=name, source=source, meta=meta)


def _transfer_function_model(
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


# --------------------------------------------------------------------------- python objects


def _continuous(dt: Any, what: str) -> None:
    if dt is None or (not isinstance(dt, bool) and dt == 0):
        return
    raise VerifyInputError(
        f"{what} is discrete-time (dt = {dt!r}); the passivity gate needs a continuous-time model"
    )


def from_python(obj: Any, *, name: str | None = None) -> LTIModel:
    """Convert a python-control or scipy.signal LTI object (continuous time only).

    Accepted: python-control ``StateSpace`` and ``TransferFunction`` (dt = 0, or None,
    which python-control calls an unspecified timebase), scipy.signal ``lti`` objects
    (``StateSpace``, ``TransferFunction``, ``ZerosPolesGain``), and an :class:`LTIModel`
    (returned as is, or renamed). Transfer functions go through
    :func:`from_transfer_function` (minimal realisation); state-space data are kept as
    given. Discrete-time objects and anything else raise :class:`VerifyInputError`.
    """
    if isinstance(obj, LTIModel):
        return obj if name is None else dataclasses.replace(obj, name=name)
    module = type(obj).__module__ or ""
    what = type(obj).__name__
    if module.split(".")[0] == "control":
        import control

        label = name if name is not None else str(getattr(obj, "name", None) or "model")
        if isinstance(obj, control.StateSpace):
            _continuous(obj.dt, f"python-control {what} {label!r}")
            return from_state_space(obj.A, obj.B, obj.C, obj.D, name=label)
        if isinstance(obj, control.TransferFunction):
            _continuous(obj.dt, f"python-control {what} {label!r}")
            num = getattr(obj, "num_list", None) or obj.num
            den = getattr(obj, "den_list", None) or obj.den
            return from_transfer_function(num, den, name=label)
    elif module.split(".")[0] == "scipy":
        from scipy import signal

        label = name if name is not None else "model"
        if isinstance(obj, signal.dlti):
            _continuous(getattr(obj, "dt", True), f"scipy.signal {what} {label!r}")
        if isinstance(obj, signal.lti):
            if isinstance(obj, signal.StateSpace):
                return from_state_space(obj.A, obj.B, obj.C, obj.D, name=label)
            tf = obj.to_tf() if isinstance(obj, signal.ZerosPolesGain) else obj
            num = np.atleast_2d(np.asarray(tf.num))
            if num.shape[0] != 1:
                raise VerifyInputError(
                    f"scipy.signal {what} {label!r}: H must be square, but it has "
                    f"{num.shape[0]} outputs and 1 input"
                )
            return from_transfer_function([[num[0]]], [[np.asarray(tf.den)]], name=label)
    raise VerifyInputError(
        f"cannot convert {module}.{what}: expected a python-control StateSpace or "
        "TransferFunction, a scipy.signal lti object, or an LTIModel"
    )


__all__ = [
    "CHECK_FREQUENCIES",
    "MINIMALITY_TOLERANCES",
    "REALIZATION_ERROR_LIMIT",
    "LTIModel",
    "from_python",
    "from_state_space",
    "from_transfer_function",
]
