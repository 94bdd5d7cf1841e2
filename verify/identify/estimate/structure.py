"""Model structures of the identified human H(s) and their parameter vectors.

The paper's structure (Section 4, "Human Modeling") is a 2 x 2 transfer matrix whose
diagonal elements are (b1 s + b0) / (s^2 + a1 s + a0) and whose off-diagonal elements
are constants c12, c21. :meth:`Structure.poles_zeros` generalises the diagonal elements
to ``zeros`` zeros over ``poles`` poles (monic denominator), keeping constant
off-diagonals; :meth:`Structure.order` is a 2 x 2 state-space model of a given order.

Parameter vectors are ordered as :meth:`Structure.names` says: for each diagonal element
i = 1, 2 the numerator coefficients b{z}_i ... b0_i then the denominator coefficients
a{p-1}_i ... a0_i (descending powers of s), then c12 and c21.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from verify.errors import VerifyInputError


@dataclass(frozen=True)
class Structure:
    """What is estimated: ``kind`` is "paper", "poles_zeros" or "order"."""

    kind: str
    poles: int = 2
    zeros: int = 1
    states: int = 0

    @classmethod
    def paper(cls) -> Structure:
        """Diagonal (b1 s + b0)/(s^2 + a1 s + a0), constant off-diagonals (Section 4)."""
        return cls("paper", 2, 1)

    @classmethod
    def poles_zeros(cls, poles: int, zeros: int) -> Structure:
        """Diagonal elements with ``zeros`` zeros and ``poles`` poles, constant off-diagonals."""
        if not (isinstance(poles, int) and isinstance(zeros, int) and 0 <= zeros <= poles
                and poles >= 1):
            raise VerifyInputError(
                f"structure poles:zeros needs integers with 0 <= zeros <= poles and poles >= 1, "
                f"got poles={poles!r}, zeros={zeros!r}; e.g. --structure 2:1")
        return cls("poles_zeros", poles, zeros)

    @classmethod
    def order(cls, states: int) -> Structure:
        """A 2 x 2 state-space model with ``states`` states."""
        if not (isinstance(states, int) and states >= 1):
            raise VerifyInputError(
                f"structure order:N needs an integer N >= 1, got {states!r}; "
                f"e.g. --structure order:4")
        return cls("order", states=states)

    @property
    def diagonal_with_constant_coupling(self) -> bool:
        """True for the structures whose off-diagonal elements are constants."""
        return self.kind in ("paper", "poles_zeros")

    def names(self) -> tuple[str, ...]:
        """Parameter names in the order of the parameter vector (module docstring)."""
        if not self.diagonal_with_constant_coupling:
            raise NotImplementedError("the order:N structure names its own parameters")
        out: list[str] = []
        for i in (1, 2):
            out += [f"b{k}_{i}" for k in range(self.zeros, -1, -1)]
            out += [f"a{k}_{i}" for k in range(self.poles - 1, -1, -1)]
        return (*out, "c12", "c21")

    def transfer_matrix(self, theta: Sequence[Any]) -> tuple[list, list]:
        """(num, den) of the 2 x 2 transfer matrix, as :func:`from_transfer_function` takes.

        The entries of ``theta`` are passed through unchanged (floats stay floats,
        rationals stay rationals), so an exact parameter vector gives an exact model.
        """
        names = self.names()
        if len(theta) != len(names):
            raise VerifyInputError(f"expected {len(names)} parameters {names}, got {len(theta)}")
        per = self.zeros + 1 + self.poles
        elements = []
        for i in range(2):
            block = list(theta[i * per:(i + 1) * per])
            elements.append((block[: self.zeros + 1], [1, *block[self.zeros + 1:]]))
        c12, c21 = theta[-2], theta[-1]
        num = [[elements[0][0], [c12]], [[c21], elements[1][0]]]
        den = [[elements[0][1], [1]], [[1], elements[1][1]]]
        return num, den
