"""The KYP matrix M(P) as one integer matrix over a common denominator (FLINT, exact).

M(P) = [[Aᵀ P + P A, P B − Cᵀ], [Bᵀ P − C, −(D + Dᵀ)]] (the KYP lemma, the paper's
Section 4) is formed from the integer numerators of A, B, C, D and P (each over its
own least common denominator) with FLINT ``fmpz_mat`` products: no rational arithmetic
per entry, and no gcd until the end. The result is exact; it feeds the verified
floating-point Cholesky test (:mod:`verify.passivity.check.float_cholesky`) without a
round trip through ``mpq``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import reduce

import flint
from gmpy2 import lcm, mpz

from verify.passivity.check import exact as ex


@dataclass(frozen=True)
class IntMatrix:
    """The exact matrix Z / d: Z a FLINT integer matrix, d a positive integer."""

    Z: flint.fmpz_mat
    d: int


def int_matrix(m: ex.RationalMatrix, rows: int, cols: int) -> IntMatrix:
    """``m`` over the least common denominator of its entries (exact)."""
    d = reduce(lcm, {x.denominator for row in m for x in row}, mpz(1))
    entries = [int(x.numerator * (d // x.denominator)) for row in m for x in row]
    return IntMatrix(flint.fmpz_mat(rows, cols, entries), int(d))


def _lcm(*values: int) -> int:
    return int(reduce(lcm, (mpz(v) for v in values), mpz(1)))


def negated_kyp_matrix(A: IntMatrix, B: IntMatrix, C: IntMatrix, D: IntMatrix,
                       P: IntMatrix) -> tuple[list[list[int]], int]:
    """−M(P) as integer rows over one denominator: (rows, d) with −M(P) = rows / d."""
    n, m = A.Z.nrows(), D.Z.nrows()
    AtP = A.Z.transpose() * P.Z  # / (dA dP)
    PB = P.Z * B.Z  # / (dP dB)
    d = _lcm(A.d * P.d, P.d * B.d, C.d, D.d)
    top = (AtP + AtP.transpose()) * flint.fmpz(d // (A.d * P.d))
    off = PB * flint.fmpz(d // (P.d * B.d)) - C.Z.transpose() * flint.fmpz(d // C.d)
    S = (D.Z + D.Z.transpose()) * flint.fmpz(d // D.d)
    top_rows = [[-int(z) for z in row] for row in top.tolist()]
    off_rows = [[-int(z) for z in row] for row in off.tolist()] if m else [[] for _ in
                                                                         range(n)]
    S_rows = [[int(z) for z in row] for row in S.tolist()]
    rows = [top_rows[i] + off_rows[i] for i in range(n)]
    rows += [[off_rows[i][j] for i in range(n)] + S_rows[j] for j in range(m)]
    return rows, d


__all__ = ["IntMatrix", "int_matrix", "negated_kyp_matrix"]
