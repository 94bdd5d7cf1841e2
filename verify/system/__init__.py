"""The paper's system: stealthy control (Section 2) and the control laws (Section 3)."""

from verify.system.laws import (
    human_body_velocities,
    interface_velocity,
    leader_velocity,
    quasi_average_initial,
    quasi_average_rate,
)
from verify.system.stealthy import (
    apply_projector,
    dbar,
    dbar_jacobian,
    direction_sum,
    directions,
    projector_dense,
    s_matrix,
    stealthy_input,
    w_matrix,
)

__all__ = [
    "apply_projector",
    "dbar",
    "dbar_jacobian",
    "direction_sum",
    "directions",
    "human_body_velocities",
    "interface_velocity",
    "leader_velocity",
    "projector_dense",
    "quasi_average_initial",
    "quasi_average_rate",
    "s_matrix",
    "stealthy_input",
    "w_matrix",
]
