"""The rational type of model data and its conversions, re-exported from the input layer.

The conversion lives in :mod:`verify.inputs.numbers`, where every input kind uses it;
the passivity code imports it from here under its historical name.
"""

from verify.inputs.numbers import (
    MAX_DECIMAL_EXPONENT,
    Rational,
    decimal_literal,
    float_view,
    rational,
    to_float,
)

__all__ = ["MAX_DECIMAL_EXPONENT", "Rational", "decimal_literal", "float_view", "rational",
           "to_float"]
