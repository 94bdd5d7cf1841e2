"""The campaign spec's model files realised as LTI models and checked for simulation.

In: a :class:`~verify.inputs.campaign_spec.CampaignSpec` whose ``model`` humans carry
their files' bytes (read, bounded and validated as model documents by the input layer).
Out: :func:`load_spec`, the spec with every model checked as the
closed loop of Sections 2-3 needs it: 2 or 3 ports (inputs = outputs, the operator's
command e to omega_h) and entries within the float range the simulator integrates in.
Every problem is one line led by the spec's path and ``humans[i].model``.
"""

from __future__ import annotations

from pathlib import Path

from verify.errors import VerifyInputError
from verify.inputs.campaign_spec import (
    CampaignSpec,
    HumanEntry,
    load_campaign_spec,
    prefixed,
)
from verify.passivity.io.model_file import model_from_bytes
from verify.passivity.model import LTIModel


def check_human_model(human: HumanEntry, where: str) -> LTIModel:
    """The model of ``human``, refused unless the simulator can run it."""
    path = human.path
    try:
        model = model_from_bytes(human.text or b"", str(path))
    except VerifyInputError as exc:
        raise VerifyInputError(prefixed(str(exc), where)) from None
    if model.m not in (2, 3):
        raise VerifyInputError(f"{where}: {path}: the human model needs 2 or 3 ports "
                               f"(inputs = outputs), got {model.m}")
    if not model.float_view_finite:
        raise VerifyInputError(f"{where}: {path}: an entry is beyond the float range; the "
                               "simulator integrates the model in floating point")
    return model


def load_spec(path: str | Path) -> CampaignSpec:
    """A campaign spec read by the input layer, with every model file's LTI model built
    and checked (:func:`check_human_model`)."""
    spec = load_campaign_spec(path)
    for i, human in enumerate(spec.humans):
        if human.kind == "model":
            check_human_model(human, f"{spec.path}: humans[{i}].model")
    return spec


__all__ = ["check_human_model", "load_spec"]
