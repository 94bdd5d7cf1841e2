"""Model files realised as LTI models (the format: :mod:`verify.inputs.model_file`).

A model file's validated :class:`~verify.inputs.model_file.ModelDocument` flows in (read by
the input layer: keys, tables, descriptive fields); an :class:`LTIModel` flows out, its
state space checked and kept exact, or its transfer function realised exactly over Q and
minimally (:mod:`verify.passivity.check.realization`). Every problem is a one-line
:class:`~verify.errors.VerifyInputError` starting with the file path.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from verify.inputs.model_file import (
    ModelDocument,
    load_model_document,
    model_document_from_bytes,
    read_model_document,
)
from verify.passivity.model import LTIModel, state_space_model, transfer_function_model


def model_of(doc: ModelDocument) -> LTIModel:
    """The LTI model a validated model document describes."""
    table, ctx = doc.table, doc.context
    if doc.kind == "state_space":
        return state_space_model(
            table["A"], table["B"], table["C"], table["D"], ctx,
            name=doc.name, source=doc.source, meta=doc.meta,
        )  # fmt: skip
    return transfer_function_model(
        table["num"], table["den"], ctx, name=doc.name, source=doc.source, meta=doc.meta
    )


def parse_model(data: dict[str, Any], source: str) -> LTIModel:
    """Validate a parsed TOML document and return the model (``source`` names the file)."""
    return model_of(read_model_document(data, source))


def model_from_bytes(raw: bytes, source: str) -> LTIModel:
    """A model file's bytes as a model, read as :func:`load_model` reads a file."""
    return model_of(model_document_from_bytes(raw, source))


def load_model(path: str | Path) -> LTIModel:
    """Read and validate a model file; every problem is a one-line VerifyInputError.

    Parameters
    ----------
    path : str or Path
        A TOML model file (state space, transfer function or the paper's human model);
        every number is read as the exact rational it denotes.

    Returns
    -------
    LTIModel
        The model, with its exact data in ``exact`` and floating-point views.

    Raises
    ------
    VerifyInputError
        On an unreadable file, bad TOML, or a missing, unknown or non-finite entry.
    """
    return model_of(load_model_document(path))


__all__ = ["load_model", "model_from_bytes", "model_of", "parse_model"]
