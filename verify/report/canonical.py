"""Floats of the claims' evidence as reports write them: machine-independent.

Evidence data hold floating-point measurements (worst errors over a bound, fit ratios,
gaps between step sizes, test statistics). Their last digits depend on the BLAS build and
its summation order, so the report would differ from machine to machine. Written, each
float keeps ``DIGITS`` significant digits, and a magnitude below ``ROUNDOFF`` (the level
of floating-point round-off, where even the leading digit is noise) is written as the
power of ten just above it, with its sign: an upper bound on the measured size, which is
what such a figure is read for. A round-off error measured against its allowed bound (a
key ending in ``_over_bound``) is noise in every digit, so it too is written as the decade
above it (0.042 and 0.054 both as 0.1: "at most a tenth of the bound"). Exact values
(strings, integers, fractions) are untouched.
"""

from __future__ import annotations

import math
from typing import Any

#: Significant digits of a written float.
DIGITS = 4
#: Below this magnitude a float is round-off: written as the decade above it.
ROUNDOFF = 1e-12


def canonical_float(x: float, *, roundoff: bool = False) -> float:
    """``x`` as a report writes it (module docstring); ``roundoff``: x measures round-off,
    written as the decade above it."""
    if not math.isfinite(x) or x == 0:
        return x + 0.0  # no negative zero
    if roundoff or abs(x) < ROUNDOFF:
        return math.copysign(10.0 ** math.ceil(math.log10(abs(x))), x)
    return float(f"{x:.{DIGITS}g}")


def canonical_data(value: Any) -> Any:
    """Every float inside dicts, lists and tuples made canonical; bools and ints kept."""
    if isinstance(value, float):
        return canonical_float(value)
    if isinstance(value, dict):
        return {k: canonical_float(v, roundoff=True)
                if isinstance(v, float) and str(k).endswith("_over_bound")
                else canonical_data(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [canonical_data(v) for v in value]
    return value


__all__ = ["DIGITS", "ROUNDOFF", "canonical_data", "canonical_float"]
