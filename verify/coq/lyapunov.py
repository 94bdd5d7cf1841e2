"""The pole conditions of a positive-real certificate as Coq lines: every eigenvalue of A
in the open left half-plane, from a Lyapunov witness (prelude ``PoleCert.v``).

A positive-real H(s) = C (sI - A)^-1 B + D has no pole in Re s > 0 and only simple
imaginary-axis poles with PSD residues (the paper's Section 4). When A is Hurwitz there
is no pole with Re s >= 0 at all and the residue conditions hold vacuously; ``PoleCert.v``
proves ``hurwitz n A`` from a rational symmetric P with P > 0 and A^T P + P A < 0.

P is proposed here (untrusted): the floating-point solution of A^T P + P A = -I, rounded
to short rationals and symmetrised; its two definiteness witnesses come from
:func:`verify.coq.witness.psd_witness`, and Coq re-checks everything. None is returned
when A is not Hurwitz (an imaginary-axis pole: the residue conditions then stay with the
Python exact checker) or no witness is found.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
from gmpy2 import mpq

from verify.coq.kyp import matrix_literal, q_literal, terms_literal
from verify.coq.witness import Witness, psd_witness
from verify.passivity.check import exact as ex

THEOREM = "stable"


def lyap_matrix(A: ex.RationalMatrix, P: ex.RationalMatrix) -> ex.RationalMatrix:
    """A^T P + P A, exactly (``lyap`` in PoleCert.v)."""
    n = len(A)
    return [[sum((A[k][i] * P[k][j] + P[i][k] * A[k][j] for k in range(n)), mpq(0))
             for j in range(n)] for i in range(n)]


def lyapunov_witness(A: ex.RationalMatrix
                     ) -> tuple[ex.RationalMatrix, Witness, Witness] | None:
    """(P, witness of P > 0, witness of -(A^T P + P A) > 0), or None."""
    from scipy.linalg import solve_continuous_lyapunov

    n = len(A)
    if n == 0:
        return None
    F = np.array([[float(x) for x in row] for row in A])
    if not np.all(np.isfinite(F)) or np.max(np.real(np.linalg.eigvals(F))) >= 0:
        return None
    try:
        Pf = solve_continuous_lyapunov(F.T, -np.eye(n))
    except (np.linalg.LinAlgError, ValueError):
        return None
    scale = float(np.max(np.abs(Pf)))
    if not np.isfinite(scale) or scale == 0:
        return None
    for bits in (12, 24, 40):
        step = Fraction(2) ** (bits - int(np.ceil(np.log2(scale))))
        P = [[mpq(Fraction(round((Pf[i, j] + Pf[j, i]) / 2 * step)) / step)
              for j in range(n)] for i in range(n)]
        wP = psd_witness(P, strict=True)
        if wP is None:
            continue
        wL = psd_witness(ex.scale(-1, lyap_matrix(A, P)), strict=True)
        if wL is not None:
            return P, wP, wL
    return None


def lyapunov_lines(A: ex.RationalMatrix, n: int) -> list[str] | None:
    """The unit's lines proving ``hurwitz n A`` (A defined before them), or None."""
    found = lyapunov_witness(A)
    if found is None:
        return None
    P, wP, wL = found
    return [
        "",
        "(** The pole conditions: every eigenvalue of A has Re < 0 ([hurwitz] in PoleCert.v),",
        "    from a Lyapunov witness LP = LP^T > 0 with A^T LP + LP A < 0 (definiteness "
        f"witnesses: {wP.method}; {wL.method}). *)",
        f"Definition LP : matQ :=\n  {matrix_literal(P)}.",
        f"Definition eLP : Q := {q_literal(wP.eps)}.",
        f"Definition wLP : list term :=\n  {terms_literal(wP)}.",
        f"Definition eLL : Q := {q_literal(wL.eps)}.",
        f"Definition wLL : list term :=\n  {terms_literal(wL)}.",
        "",
        f"Theorem {THEOREM} : hurwitz {n} A.",
        "Proof.",
        f"  apply (lyapunov_sound {n} A LP eLP wLP eLL wLL).",
        "  vm_cast_no_check (eq_refl true).  (* the kernel evaluates the check once, at Qed *)",
        "Qed.",
    ]
