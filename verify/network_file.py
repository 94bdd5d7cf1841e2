"""Network files: the attitudes of n bodies, numbers only (TOML).

```toml
name = "optional label"
# exactly one of the two keys:
quaternions = [[1.0, 0.0, 0.0, 0.0], [0.9, 0.1, 0.0, 0.4]]   # (w, x, y, z), normalised
rotations = [[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]]  # 3x3, row by row
```

Values are read with ``tomllib`` and checked to be numbers (never evaluated). Rotation
matrices must lie in SO(3) within a tolerance, or be projected onto it on request.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from verify import so3
from verify.errors import VerifyInputError
from verify.inputs.numbers import real, real_array
from verify.inputs.toml import read_toml
from verify.so3 import Array
from verify.system.stealthy import as_network, dbar

ALLOWED_KEYS = {"name", "description", "quaternions", "rotations"}


@dataclass(frozen=True)
class Network:
    """A loaded, validated network of body attitudes (shape (n, 3, 3))."""

    name: str
    attitudes: Array
    projected_by: float = 0.0  # largest change made by projection onto SO(3)


def _array(value: Any, where: str, tail: tuple[int, ...]) -> Array:
    if isinstance(value, list) and not value:
        raise VerifyInputError(f"{where}: a network needs at least one body; give one entry "
                               "per body")
    return real_array(value, where, (None, *tail))


def parse_network(
    data: dict[str, Any],
    source: str,
    *,
    project: bool = False,
    tolerance: float = so3.ROTATION_TOLERANCE,
) -> Network:
    """Validate a parsed TOML document and return the network."""
    where = "the SO(3) tolerance (--tolerance)"
    if real(tolerance, where) < 0:
        raise VerifyInputError(f"{where} must be >= 0, got {tolerance}; e.g. --tolerance 1e-9")
    unknown = sorted(set(data) - ALLOWED_KEYS)
    if unknown:
        raise VerifyInputError(
            f"{source}: unknown key(s) {', '.join(unknown)}; "
            f"allowed: {', '.join(sorted(ALLOWED_KEYS))}"
        )
    has_q, has_r = "quaternions" in data, "rotations" in data
    if has_q == has_r:
        raise VerifyInputError(f"{source}: give exactly one of 'quaternions' or 'rotations'")
    name = data.get("name", Path(source).stem)
    if not isinstance(name, str):
        raise VerifyInputError(f"{source}: 'name' must be a string")
    moved = 0.0
    if has_q:
        q = _array(data["quaternions"], f"{source}: quaternions", (4,))
        zero = np.flatnonzero(np.linalg.norm(q, axis=1) == 0)
        if zero.size:
            raise VerifyInputError(f"{source}: quaternion {zero[0]} is zero, not a rotation")
        R = so3.quaternion_to_matrix(q)
    else:
        R = _array(data["rotations"], f"{source}: rotations", (3, 3))
        if project:
            P = so3.project(R)
            moved = float(np.abs(P - R).max())
            R = P
        so3.check_rotations(R, name=f"{source}: rotation", tolerance=tolerance)
    R = as_network(R, check=False)
    dbar(R)  # raises DbarUndefinedError with a clear message
    return Network(name=name, attitudes=R, projected_by=moved)


def load_network(
    path: str | Path, *, project: bool = False, tolerance: float = so3.ROTATION_TOLERANCE
) -> Network:
    """Read and validate a network file; every problem is a one-line VerifyInputError."""
    path = Path(path)
    return parse_network(read_toml(path), str(path), project=project, tolerance=tolerance)
