"""Human models H(s) as validated continuous-time LTI systems.

Section 4 of the paper closes the loop through an identified human model H(s), a square
m x m transfer matrix (m inputs, m outputs). The passivity gate works on a state-space
realisation H(s) = C (sI - A)^-1 B + D, held here as an :class:`LTIModel`. Models come
from

* :func:`from_state_space`: (A, B, C, D) as given, after validation (n = 0 is allowed);
* :func:`from_transfer_function`: an m x m grid of numerator/denominator coefficient
  lists (descending powers of s), realised exactly over Q as a *minimal* realisation
  whose transfer matrix is checked to equal the given one exactly;
* :func:`from_python`: python-control ``StateSpace`` / ``TransferFunction`` and
  scipy.signal ``lti`` objects (continuous time only).

Every number denotes an exact rational (:mod:`verify.inputs.numbers`: integers
exactly, binary floats as the dyadic rationals they store, decimals of a model file as the
decimal they spell); the model keeps it in ``LTIModel.exact`` and derives float views.

Every problem with the input is a :class:`~verify.errors.VerifyInputError` whose message
is one line naming the problem.

The realisation of a transfer matrix and its check are in
:mod:`verify.passivity.check.realization`.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from verify.errors import VerifyInputError
from verify.inputs.numbers import exact_array, float_view, real_array
from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel
from verify.passivity.check.realization import transfer_function_realization

Array = NDArray[np.float64]


# --------------------------------------------------------------------------- validation


def _rows(nested: Any, shape: tuple[int, ...]) -> ex.RationalMatrix:
    """A 2-D rational matrix (list of rows) of the given 2-D shape."""
    if shape[0] == 0:
        return []
    if shape[1] == 0:
        return [[] for _ in range(shape[0])]
    return [list(row) for row in nested]


def _check_state_space(A: Any, B: Any, C: Any, D: Any, ctx: str) -> ExactModel:
    """Validated exact (A, B, C, D) with consistent shapes and H square."""
    (A, sa), (B, sb), (C, sc), (D, sd) = (
        exact_array(x, f"{ctx}: {k}") for k, x in zip("ABCD", (A, B, C, D), strict=True)
    )
    if len(sd) != 2 or 0 in sd:
        raise VerifyInputError(f"{ctx}: D: expected an m x m matrix with m >= 1, got shape {sd}")
    p, q = sd
    if p != q:
        raise VerifyInputError(
            f"{ctx}: H must be square (m inputs = m outputs), but D is {p} x {q}"
        )
    m = p
    if sa == (0,):
        sa = (0, 0)
    if len(sa) != 2 or sa[0] != sa[1]:
        raise VerifyInputError(f"{ctx}: A: expected a square n x n matrix, got shape {sa}")
    n = sa[0]
    if n == 0 and sb == (0,):
        sb = (0, m)
    if n == 0 and sc == (0,):
        sc = (m, 0)
    if len(sb) == 2 and len(sc) == 2 and sb[0] == sc[1] == n and sb[1] != sc[0]:
        raise VerifyInputError(
            f"{ctx}: H must be square (m inputs = m outputs), but B has {sb[1]} "
            f"column(s) and C has {sc[0]} row(s)"
        )
    if sb != (n, m):
        raise VerifyInputError(
            f"{ctx}: B: expected shape ({n}, {m}) for {n} state(s) and {m} input(s), got {sb}"
        )
    if sc != (m, n):
        raise VerifyInputError(
            f"{ctx}: C: expected shape ({m}, {n}) for {m} output(s) and {n} state(s), got {sc}"
        )
    return ExactModel(_rows(A, sa), _rows(B, sb), _rows(C, sc), _rows(D, sd))


def _frozen(x: Array) -> Array:
    x.setflags(write=False)
    return x


# --------------------------------------------------------------------------- the model


@dataclass(frozen=True, eq=False)
class LTIModel:
    """A validated continuous-time square LTI model H(s) = C (sI - A)^-1 B + D.

    ``exact`` holds the model's exact rational (A, B, C, D): the source of truth, and the
    only data the exact decision reads. ``A``, ``B``, ``C``, ``D`` are read-only float64
    *views* of it (rounded to nearest; +-inf where an entry is beyond the float range),
    used only to propose (certificate candidates, witness frequencies) and to simulate.
    Given without ``exact``, the matrices are converted exactly
    (:mod:`verify.inputs.numbers`); given with it, they are ignored and re-derived.

    ``source`` is the file the model came from, or ``"python"``; ``meta`` holds the
    optional descriptive fields of a model file (``k_s``, ``units``, ``description``,
    ``reconstructed``); ``realization`` says how the state-space data were obtained.
    Equality is identity (the fields hold arrays).
    """

    name: str
    A: Any = None
    B: Any = None
    C: Any = None
    D: Any = None
    source: str = "python"
    meta: dict = field(default_factory=dict)
    exact: ExactModel | None = None
    realization: str = "state space as given"

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):
            raise VerifyInputError(f"model name must be a string, got {type(self.name).__name__}")
        if not isinstance(self.source, str):
            raise VerifyInputError(f"model {self.name!r}: source must be a string")
        if not isinstance(self.meta, dict):
            raise VerifyInputError(f"model {self.name!r}: meta must be a dict")
        em = self.exact
        if em is None:
            em = _check_state_space(self.A, self.B, self.C, self.D, f"model {self.name!r}")
        elif not isinstance(em, ExactModel):
            raise VerifyInputError(f"model {self.name!r}: exact must be an ExactModel")
        else:  # re-validate the exact data's shapes (no trust in a hand-built ExactModel)
            em = _check_state_space(em.A, em.B, em.C, em.D, f"model {self.name!r}")
        n, m = em.n, em.m
        object.__setattr__(self, "exact", em)
        for key, X, r, c in (("A", em.A, n, n), ("B", em.B, n, m), ("C", em.C, m, n),
                             ("D", em.D, m, m)):
            object.__setattr__(self, key, _frozen(float_view(X, r, c)))
        object.__setattr__(self, "meta", dict(self.meta))

    @property
    def n(self) -> int:
        """Number of states (0 for a static gain)."""
        return self.exact.n

    @property
    def m(self) -> int:
        """Number of inputs, equal to the number of outputs."""
        return self.exact.m

    @property
    def float_view_finite(self) -> bool:
        """Whether every entry of the float view is finite (the float route can run)."""
        return all(bool(np.all(np.isfinite(X))) for X in (self.A, self.B, self.C, self.D))

    def frequency_response(self, omega: ArrayLike) -> NDArray[np.complex128]:
        """H(j w) = C (j w I - A)^-1 B + D at each real w, shape (len(omega), m, m).

        Floating point, from the float view. A frequency where j w is an eigenvalue of A
        (a pole on the imaginary axis) has no value and raises :class:`VerifyInputError`.
        """
        w = real_array(omega, f"model {self.name!r}: omega")
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
    return state_space_model(A, B, C, D, ctx, name=name, source=source, meta=meta)


def state_space_model(
    A: Any, B: Any, C: Any, D: Any, ctx: str, *, name: str, source: str, meta: dict | None
) -> LTIModel:
    """:func:`from_state_space` with the error context ``ctx`` given (a model file's table)."""
    em = _check_state_space(A, B, C, D, ctx)
    return LTIModel(name, source=source, meta=dict(meta or {}), exact=em)


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
    non-zero denominator. A constant transfer matrix gives n = 0. The realisation is exact
    (:mod:`verify.passivity.check.realization`): no floating point between the numbers given
    and the rational (A, B, C, D).
    """
    ctx = f"model {name!r}" if source == "python" else source
    return transfer_function_model(num, den, ctx, name=name, source=source, meta=meta)


def transfer_function_model(num: Any, den: Any, ctx: str, *, name: str, source: str,
                            meta: dict | None) -> LTIModel:
    """The exact minimal realisation of num/den as an LTIModel
    (:func:`verify.passivity.check.realization.transfer_function_realization`)."""
    exact, realization = transfer_function_realization(num, den, ctx)
    return LTIModel(name, source=source, meta=dict(meta or {}), exact=exact,
                    realization=realization)



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
    :func:`from_transfer_function` (exact minimal realisation); state-space data are kept
    as given. Every float denotes its exact binary value (0.1 is 3602879701896397/2^55).
    Discrete-time objects and anything else raise :class:`VerifyInputError`.
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
