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

The realisation of a transfer matrix and its check are in
:mod:`verify.passivity.realization`.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from verify.errors import VerifyInputError

Array = NDArray[np.float64]


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
    from verify.passivity.realization import transfer_function_model

    return transfer_function_model(num, den, ctx, name=name, source=source, meta=meta)



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
    "LTIModel",
    "from_python",
    "from_state_space",
    "from_transfer_function",
]
