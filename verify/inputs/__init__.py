"""The input layer: everything a user hands to ``verify`` is validated here.

What flows in: TOML files (network files, model files), command-line numbers
(``--margin``, ``--band``, ``--tolerance``, ``simulate`` options) and Python objects
given to the public API (model matrices). What flows out: exact rationals for the
exact machinery (:func:`rational`, :func:`exact_array`: integers as they are, binary
floats as the dyadic rationals they store, decimals of a file or a flag as the decimal
they spell) or finite floats for simulation and numerical proposals (:func:`real`,
:func:`real_array`). Bad input is a one-line :class:`~verify.errors.VerifyInputError`
naming the argument, the value and the fix; nothing is ever evaluated.

Modules: :mod:`verify.inputs.numbers` (numbers and numeric arrays, both flavours,
command-line numbers and the strict certificate number), :mod:`verify.inputs.files`
(opening only regular files, of bounded size), :mod:`verify.inputs.toml` (reading a TOML
file), :mod:`verify.inputs.time_grid` (the steps of a run of given length and step),
:mod:`verify.inputs.experiment_log` (operator experiment logs, CSV and NPZ, with
:mod:`~verify.inputs.log_checks` and :mod:`~verify.inputs.log_npz`) and
:mod:`verify.inputs.campaign_spec` (campaign specs for ``verify campaign``, imported on
use). New input kinds belong in this package and use these validators rather than
their own.
"""

from verify.inputs.numbers import (
    MAX_DECIMAL_EXPONENT,
    Rational,
    decimal_literal,
    exact_array,
    float_view,
    parse_number,
    positive_real,
    rational,
    real,
    real_array,
    to_float,
)
from verify.inputs.toml import read_toml

__all__ = ["MAX_DECIMAL_EXPONENT", "Rational", "decimal_literal", "exact_array", "float_view",
           "parse_number", "positive_real", "rational", "read_toml", "real", "real_array",
           "to_float"]
