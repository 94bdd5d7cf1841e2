"""Continuous-time filters evaluated on uniformly sampled signals (first-order hold).

The estimators of :mod:`verify.identify.estimate.estimation` need, for a monic denominator
A(s) = s^n + a_{n-1} s^{n-1} + ... + a_0 and a sampled signal x, the signals
s^k / A(s) x for k = 0..n (the "state-variable filter" outputs of continuous-time
identification, Garnier, Mensler & Richard, Int. J. Control 76(13), 2003) and the free
responses of A (the transients a trial starts with).

Intersample behaviour: x is taken piecewise linear between samples (first-order hold),
which is exact for piecewise-linear signals and accurate to O(h^2) for smooth ones. The
filter's continuous state at the first sample is zero unless given (a trial that starts
where the previous one left off, :meth:`Filter.filtered` and :meth:`Filter.coast`).
Discretisation is ``scipy.signal.cont2discrete(..., method="foh")``; the recursion runs in
``scipy.signal.lfilter``.
"""

from __future__ import annotations

import numpy as np
from scipy import linalg, signal

__all__ = ["Filter", "companion", "filtered", "free_responses"]


def companion(a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(Ac, Bc) of 1/A(s) in controllable canonical form, state z = (w, w', ..., w^(n-1)).

    ``a`` holds a_{n-1}, ..., a_0 (descending powers, the leading 1 left out); w = x / A(s)
    is the filter's output when x drives it.
    """
    n = len(a)
    Ac = np.zeros((n, n))
    Ac[:-1, 1:] = np.eye(n - 1)
    Ac[-1, :] = -np.asarray(a, float)[::-1]
    Bc = np.zeros((n, 1))
    Bc[-1, 0] = 1.0
    return Ac, Bc


class Filter:
    """1/A(s) discretised once for a step h (FOH), applied to any number of signals.

    ``a`` holds a_{n-1}, ..., a_0 (the leading 1 of the monic A left out).
    """

    def __init__(self, a: np.ndarray, h: float) -> None:
        self.a = np.asarray(a, float)
        self.h = float(h)
        n = self.n = len(self.a)
        Ac, Bc = companion(self.a)
        Ad, Bd, _, Dd, _ = signal.cont2discrete((Ac, Bc, np.eye(n), np.zeros((n, 1))), h,
                                                method="foh")
        # with C = I and D = 0, scipy's FOH feedthrough is the offset M in z_k = xi_k + M x_k,
        # where xi_{k+1} = Ad xi_k + Bd x_k is the recursion scipy's discrete model runs
        self.Ad, self.M = Ad, Dd[:, 0]
        # an overflowing discretisation (a wildly unstable candidate) gives NaN outputs
        self.den = (np.real(np.poly(Ad)) if np.all(np.isfinite(Ad))
                    else np.full(n + 1, np.nan))
        # first n + 1 powers of Ad; every later one follows from Cayley-Hamilton
        first = [np.eye(n)]
        for _ in range(n):
            first.append(Ad @ first[-1])
        self._first = np.array(first)
        # numerators of xi_j = N_j(z)/den(z) x: the impulse response 0, Bd, Ad Bd, ...
        # convolved with den and truncated (den(z) times the response is a polynomial)
        impulse = np.concatenate([np.zeros((1, n)), (self._first[:n] @ Bd)[:, :, 0]])
        self.num = np.array([np.convolve(self.den, impulse[:, j])[: n + 1] for j in range(n)])
        self._free = np.zeros((0, n, n))

    def _powers(self, count: int) -> np.ndarray:
        """Ad^k for k = 0..count-1, shape (count, n, n) (cached, grown on demand).

        Each entry of Ad^k obeys the recursion of the characteristic polynomial den, so
        all entries are one all-pole impulse response g combined with the first n powers.
        """
        if self._free.shape[0] < count:
            n = self.n
            impulse = np.zeros(count)
            impulse[0] = 1.0
            g = signal.lfilter([1.0], self.den, impulse)
            # entry sequences s_k = sum_m c_m g_{k-m}, with c = (den * s)[:n]
            coeff = np.array([sum(self.den[j] * self._first[m - j] for j in range(m + 1))
                              for m in range(n)])  # (n, n, n)
            shifted = np.zeros((count, n))
            for m in range(n):
                shifted[m:, m] = g[: count - m]
            self._free = (shifted @ coeff.reshape(n, n * n)).reshape(count, n, n)
        return self._free[:count]

    def filtered(self, x: np.ndarray, z0: np.ndarray | None = None) -> np.ndarray:
        """s^k / A(s) x at the samples, for k = 0..n, shape (N, n + 1).

        Continuous state z = (w, ..., w^(n-1)) equal to ``z0`` at the first sample (zero
        when None), x piecewise linear (module docstring). Columns 0..n-1 are that state
        at every sample; column n is s^n / A(s) x = x - sum_k a_k s^k / A(s) x.
        """
        x = np.asarray(x, float)
        n = self.n
        out = np.empty((x.shape[0], n + 1))
        for j in range(n):
            out[:, j] = signal.lfilter(self.num[j], self.den, x)
        # lfilter starts from xi_0 = 0; a continuous state z0 needs xi_0 = z0 - M x_0
        start = -self.M * x[0] if z0 is None else np.asarray(z0, float) - self.M * x[0]
        out[:, :n] += self._powers(x.shape[0]) @ start
        out[:, :n] += np.outer(x, self.M)
        out[:, n] = x - out[:, :n] @ self.a[::-1]
        return out

    def coast(self, z: np.ndarray, seconds: float) -> np.ndarray:
        """The state ``seconds`` after ``z`` with zero input: exp(Ac seconds) z."""
        Ac, _ = companion(self.a)
        return linalg.expm(Ac * float(seconds)) @ np.asarray(z, float)

    def held(self, z: np.ndarray, x: float, seconds: float, slope: float = 0.0
             ) -> np.ndarray:
        """The state ``seconds`` after ``z`` with the input x + slope tau (tau from 0):
        the exponential of the system augmented by the input and its slope."""
        Ac, Bc = companion(self.a)
        n = self.n
        big = np.zeros((n + 2, n + 2))
        big[:n, :n], big[:n, n], big[n, n + 1] = Ac, Bc[:, 0], 1.0
        start = np.concatenate([np.asarray(z, float), [float(x), float(slope)]])
        return (linalg.expm(big * float(seconds)) @ start)[:n]

    def free(self, count: int) -> np.ndarray:
        """The n free responses of A(s) at t = k h, k = 0..count-1, shape (count, n).

        Column j is the solution w of A(d/dt) w = 0 with w^(i)(0) = 1 if i = j else 0;
        they span every transient of an element with denominator A, whatever its
        numerator.
        """
        return self._powers(count)[:, 0, :]


def filtered(a: np.ndarray, x: np.ndarray, h: float) -> np.ndarray:
    """s^k / A(s) x for k = 0..n (see :meth:`Filter.filtered`)."""
    return Filter(a, h).filtered(x)


def free_responses(a: np.ndarray, h: float, count: int) -> np.ndarray:
    """The n free responses of A(s) (see :meth:`Filter.free`)."""
    return Filter(a, h).free(count)
