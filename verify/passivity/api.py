"""The public face of the passivity gate: any model in, a decision or a curve out (Section 4).

Section 4 of the paper asks whether the identified human model H(s) is passive, through
nu(w) = lambda_min(H(jw) + H(jw)^H)/2 frequency by frequency. The functions here take
a model in whatever form a control engineer holds it and answer with the exact decisions
and the curves of the package:

* :func:`as_model`: an :class:`~verify.passivity.model.LTIModel` from a python-control
  ``StateSpace``/``TransferFunction``, a scipy.signal ``lti`` object, a tuple of arrays
  ``(A, B, C, D)`` or ``(num, den)``, a static gain (a number or an m x m array), a
  model file's path, or an ``LTIModel`` (returned as is);
* :func:`decide` (whole frequency axis, optional margin) and :func:`decide_band` (a
  band [w1, w2]): verdicts with an exact certificate or witness;
* :func:`nu` and :func:`relative_index`: the curves nu(w) and R(w) in floating point
  (R(w) is the largest singular value of (I - H)(I + H)^-1, the relative passivity
  index that MATLAB's ``passiveplot`` draws; R(w) <= 1 exactly where nu(w) >= 0);
* :func:`passivity_indices`, :func:`ifp_index`, :func:`ofp_index`: nu_IFP and rho_OFP
  with a numerical estimate and exact bounds (Khalil, Nonlinear Systems, Def. 6.3).

Every bad argument, whatever its kind, is one :class:`~verify.errors.VerifyInputError`
with a one-line message naming the argument, its value and the fix. Numbers keep their
exact value: an int is that integer, a binary float the dyadic rational it stores, a
``Fraction`` itself, and a string such as ``"0.1"`` or ``"1/10"`` the decimal or
fraction it spells (for margins and bands).

>>> from verify.passivity import decide_band, nu
>>> H = ([0.5, 1], [1, 1, 2])                   # (0.5 s + 1) / (s^2 + s + 2)
>>> print(decide_band(H, (0, 1.5)).verdict)
passive
>>> round(float(nu(H, [0.0])[0]), 3)            # H(0) = 1/2
0.5
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from verify.errors import VerifyInputError
from verify.inputs.numbers import fraction, parse_number, rational, real_array
from verify.validation import message, shown

if TYPE_CHECKING:
    from verify.passivity.band import BandDecision
    from verify.passivity.decision import Decision
    from verify.passivity.indices import IndexBounds
    from verify.passivity.model import LTIModel

#: What :func:`as_model` accepts, for its error message.
MODEL_KINDS = ("a python-control StateSpace or TransferFunction, a scipy.signal lti object, "
               "(A, B, C, D), (num, den), a static gain (number or m x m array), a model "
               "file's path, or an LTIModel")


# --------------------------------------------------------------------------- models


def _is_number(x: Any) -> bool:
    return isinstance(x, int | float | Fraction | np.integer | np.floating) and not isinstance(
        x, bool | np.bool_)


def _transfer_function(num: Any, den: Any, name: str) -> LTIModel:
    """(num, den) of one SISO element (coefficient lists) or an m x m grid of them."""
    from verify.passivity.model import from_transfer_function

    def depth(x: Any) -> int:
        d = 0
        while isinstance(x, list | tuple | np.ndarray) and len(x) > 0:
            x, d = x[0], d + 1
        return d

    dn, dd = depth(num), depth(den)
    if dn != dd or dn not in (1, 3):
        raise VerifyInputError(message(
            "(num, den) as two coefficient lists (descending powers of s) or two m x m grids "
            "of them", "model", (num, den), "e.g. ([1, 2], [1, 3, 2]) for (s + 2)/(s^2 + 3s + 2)"))
    if dn == 1:
        num, den = [[list(num)]], [[list(den)]]
    return from_transfer_function(num, den, name=name)


def as_model(model: Any, *, name: str | None = None) -> LTIModel:
    """An exact :class:`~verify.passivity.model.LTIModel` from any supported form.

    Parameters
    ----------
    model
        A python-control ``StateSpace``/``TransferFunction`` or scipy.signal ``lti``
        object (continuous time), a tuple ``(A, B, C, D)`` of arrays, a tuple
        ``(num, den)`` (coefficient lists in descending powers of s, or m x m grids of
        them), a static gain (a number or an m x m array), the path of a TOML model file
        (``str`` or ``os.PathLike``), or an ``LTIModel``.
    name : str, optional
        The model's name in verdicts and certificates (default ``"model"``, or the
        object's own name).

    Returns
    -------
    LTIModel
        Every number kept as the exact rational it denotes; transfer functions realised
        exactly (minimal realisation over Q).

    Raises
    ------
    VerifyInputError
        For anything else, or inconsistent shapes, NaN, Inf, a discrete-time object.

    Examples
    --------
    >>> as_model(([1, 2], [1, 3, 2])).n            # (s + 2)/((s + 1)(s + 2)): one state
    1
    >>> as_model(np.eye(2)).m                      # a static gain
    2
    """
    from verify.passivity.model import LTIModel, from_python, from_state_space

    if name is not None and not isinstance(name, str):
        raise VerifyInputError(message("a string", "name", name))
    label = "model" if name is None else name
    try:
        if isinstance(model, LTIModel):
            return from_python(model, name=name)
        module = (type(model).__module__ or "").split(".")[0]
        if module in ("control", "scipy"):
            return from_python(model, name=name)
        if isinstance(model, str | os.PathLike):
            from pathlib import Path

            from verify.passivity.io.model_file import load_model

            return load_model(Path(model))
        if _is_number(model) or (isinstance(model, np.ndarray) and model.ndim in (0, 2)):
            D = np.asarray(model) if isinstance(model, np.ndarray) else [[model]]
            D = [[D.item()]] if isinstance(D, np.ndarray) and D.ndim == 0 else D
            return from_state_space([], [], [], D, name=label)
        if isinstance(model, tuple | list) and len(model) == 4:
            return from_state_space(*model, name=label)
        if isinstance(model, tuple | list) and len(model) == 2:
            return _transfer_function(model[0], model[1], label)
    except VerifyInputError:
        raise
    except (TypeError, ValueError, AttributeError, IndexError, ZeroDivisionError,
            OverflowError) as exc:  # a malformed object of a supported kind
        raise VerifyInputError(message(MODEL_KINDS, "model", model,
                                       detail=f"{type(exc).__name__}: {exc}")) from None
    raise VerifyInputError(message(MODEL_KINDS, "model", model,
                                   detail=f"of type {type(model).__name__}"))


# --------------------------------------------------------------------------- numbers


def exact_number(value: Any, name: str, example: str) -> Fraction:
    """``value`` as the exact rational it denotes; a string is read like a model file's
    decimal (``"0.1"`` is 1/10) or a fraction (``"1/10"``)."""
    if isinstance(value, str):
        return parse_number(value, name, example)
    return fraction(rational(value, name))


def as_band(band: Any, *, name: str = "band") -> tuple[Fraction, Fraction]:
    """``(w1, w2)`` with 0 <= w1 < w2 rad/s, exactly, from a pair of numbers or ``"W1:W2"``."""
    from verify.passivity.band import check_band, parse_band

    if isinstance(band, str):
        return parse_band(band)
    if not isinstance(band, Sequence | np.ndarray) or len(band) != 2:
        raise VerifyInputError(message("a pair (w1, w2) of frequencies in rad/s", name, band,
                                       "e.g. (0, 1.5) or '0:1.5'"))
    w1, w2 = (exact_number(w, f"{name}[{i}]", "(0, 1.5)") for i, w in enumerate(band))
    return check_band(w1, w2, f"{name}={shown(band)}")


def _frequencies(omega: ArrayLike, name: str = "omega") -> NDArray[np.float64]:
    w = real_array(omega, name)
    if w.ndim > 1:
        raise VerifyInputError(message("a number or a 1-D array of frequencies", name, omega,
                                       f"got shape {w.shape}"))
    return w.reshape(-1)


# --------------------------------------------------------------------------- decisions


def decide(model: Any, margin: Any = 0, *, name: str | None = None) -> Decision:
    """Is H passive (nu(w) >= margin for every w, with H stable up to simple lossless poles)?

    Parameters
    ----------
    model
        Any form :func:`as_model` accepts.
    margin : number or str, default 0
        nu0 in nu(w) >= nu0, decided exactly as passivity of H - nu0 I.
    name : str, optional
        The model's name in the verdict and its certificate.

    Returns
    -------
    Decision
        ``verdict`` (:data:`~verify.passivity.verdicts.PASSIVE`, ``NOT_PASSIVE`` or
        ``INCONCLUSIVE``) with its ``reason``; a passive verdict carries an exactly
        checked ``certificate``, a not-passive one an exactly checked ``witness``.

    Examples
    --------
    >>> d = decide(([1, -1], [1, 1]))              # (s - 1)/(s + 1): not positive real
    >>> print(d.verdict)
    not passive
    """
    from verify.passivity.decision import decide as decide_model

    m = as_model(model, name=name)
    return decide_model(m, exact_number(margin, "margin", "0.01"))


def decide_band(model: Any, band: Any, margin: Any = 0, *, name: str | None = None,
                exact_first: bool = True) -> BandDecision:
    """Is nu(w) >= margin for every w in the band [w1, w2] (rad/s) where H(jw) is defined?

    Parameters
    ----------
    model
        Any form :func:`as_model` accepts.
    band : pair of numbers, or str
        ``(w1, w2)`` with 0 <= w1 < w2, or ``"W1:W2"``; numbers are exact (0.1 as a
        float is its binary value, ``"0.1"`` or ``Fraction(1, 10)`` one tenth).
    margin : number or str, default 0
        nu0 in nu(w) >= nu0 on the band.
    name : str, optional
        The model's name in the verdict and its certificate.
    exact_first : bool, default True
        The exact root-counting route before the generalized KYP SDP.

    Returns
    -------
    BandDecision
        Verdict and reason, with a certificate or a witness inside the band.

    Examples
    --------
    >>> print(decide_band(([1, 2], [1, 3, 2]), "0:10").verdict)
    passive
    """
    from verify.passivity.band import decide_band as decide_on_band

    if not isinstance(exact_first, bool):
        raise VerifyInputError(message("True or False", "exact_first", exact_first))
    m = as_model(model, name=name)
    return decide_on_band(m, as_band(band), exact_number(margin, "margin", "0.01"),
                          exact_first=exact_first)


# --------------------------------------------------------------------------- curves


def nu(model: Any, omega: ArrayLike) -> NDArray[np.float64]:
    """nu(w) = lambda_min(H(jw) + H(jw)^H) / 2 at each frequency (paper, Section 4).

    Floating point, from the model's float view: a curve to look at, never a verdict
    (:func:`decide` decides). A frequency at a pole of H on the imaginary axis raises
    :class:`VerifyInputError`.

    Examples
    --------
    >>> nu(([1], [1, 1]), [0, 1]).round(3)          # 1/(s + 1): nu(w) = 1/(1 + w^2)
    array([1. , 0.5])
    """
    m = as_model(model)
    H = m.frequency_response(_frequencies(omega))
    return np.linalg.eigvalsh((H + np.conj(np.swapaxes(H, 1, 2))) / 2)[:, 0]


def relative_index(model: Any, omega: ArrayLike) -> NDArray[np.float64]:
    """R(w) = sigma_max((I - H(jw)) (I + H(jw))^-1), the relative passivity index per w.

    ``R(w) <= 1`` exactly where H(jw) + H(jw)^H >= 0, i.e. where nu(w) >= 0 (the index
    MATLAB's ``passiveplot`` and ``getPassiveIndex(G)`` report; it presumes I + H
    minimum phase). Where I + H(jw) is singular R is ``inf``. Floating point.

    Examples
    --------
    >>> relative_index(([1], [1, 1]), [0]).round(3)  # H(0) = 1: (1 - 1)/(1 + 1)
    array([0.])
    """
    m = as_model(model)
    return _relative(m.frequency_response(_frequencies(omega)))


def _relative(H: NDArray[np.complex128]) -> NDArray[np.float64]:
    eye = np.eye(H.shape[1])
    out = np.full(H.shape[0], np.inf)
    for k, Hk in enumerate(H):
        try:
            T = np.linalg.solve((eye + Hk).T, (eye - Hk).T).T  # (I - H)(I + H)^-1
        except np.linalg.LinAlgError:
            continue
        if np.all(np.isfinite(T)):
            out[k] = np.linalg.norm(T, 2)
    return out


# --------------------------------------------------------------------------- indices


def ifp_index(model: Any) -> IndexBounds:
    """nu_IFP, the largest nu with H - nu I passive: estimate and exact bounds.

    Examples
    --------
    >>> print(ifp_index(([1], [1, 1])).summary())   # 1/(s + 1): nu(w) -> 0 as w -> inf
    ν_IFP = 0 exactly (KYP certificate for 0; exact witness: ω → ∞)
    """
    from verify.passivity.indices import ifp_index as ifp

    return ifp(as_model(model))


def ofp_index(model: Any) -> IndexBounds:
    """rho_OFP, the largest rho with u^T y >= rho |y|^2 + dV/dt: estimate and exact bounds.

    Examples
    --------
    >>> rho = ofp_index(([1], [1, 1]))               # 1/(s + 1): Re 1/H(jw) = 1
    >>> rho.exact, rho.lower
    (True, Fraction(1, 1))
    """
    from verify.passivity.indices import ofp_index as ofp

    return ofp(as_model(model))


def passivity_indices(model: Any) -> tuple[IndexBounds, IndexBounds]:
    """(nu_IFP, rho_OFP) of a model (:func:`ifp_index`, :func:`ofp_index`)."""
    m = as_model(model)
    return ifp_index(m), ofp_index(m)


__all__ = ["as_band", "as_model", "decide", "decide_band", "exact_number", "ifp_index", "nu",
           "ofp_index", "passivity_indices", "relative_index"]
