"""What an SOS certificate asserts: p = sum over blocks of <Q_k, H_k(x) (z_k z_k^T)>.

A *block* pairs a multiplier with a monomial basis z = (z_1, ..., z_m) and a Gram
matrix Q. The multiplier is a k x k symmetric matrix H of polynomials known to be
positive semidefinite for every real x (k = 1: a scalar g >= 0, e.g. 1, a gain k > 0,
an assumption; k = 3: e.g. sym(A) - lambda_min(A) I). Index the Gram matrix by pairs
(a, i), a a basis monomial and i a row of H (row r = a k + i); the block contributes

    sum_{r, s} Q_rs H_{i(r) i(s)} z_{a(r)} z_{a(s)},

which is >= 0 when Q is PSD (write Q = sum_l v_l v_l^T; each v_l gives u_l^T H u_l with
u_l = sum_a z_a v_l[(a, .)], a polynomial vector, and H is PSD). So p = sum of blocks
with every Q PSD proves p >= 0 (Putinar/Schmuedgen-style multipliers, matrix
S-procedure; Parrilo 2003, Scherer & Hol 2006).
"""

from __future__ import annotations

from dataclasses import dataclass

from verify.sos import poly as pl


@dataclass(frozen=True)
class Multiplier:
    """A k x k matrix of polynomials, PSD on all real x for the reason ``grounds``."""

    grounds: str
    matrix: tuple[tuple[pl.Poly, ...], ...]

    @property
    def size(self) -> int:
        return len(self.matrix)

    def degree(self) -> int:
        return max(pl.degree(e) for row in self.matrix for e in row)

    def exponents(self) -> list[pl.Monomial]:
        return [m for row in self.matrix for e in row for m in e]

    def same_as(self, other: Multiplier) -> bool:
        return self.grounds == other.grounds and self.matrix == other.matrix


def scalar_multiplier(grounds: str, g: pl.Poly) -> Multiplier:
    return Multiplier(grounds, ((g,),))


@dataclass(frozen=True)
class Block:
    multiplier: Multiplier
    basis: tuple[pl.Monomial, ...]

    @property
    def gram_size(self) -> int:
        return self.multiplier.size * len(self.basis)

    def index(self, r: int) -> tuple[int, int]:
        """(basis position a, multiplier row i) of Gram row r."""
        k = self.multiplier.size
        return r // k, r % k

    def entry_polynomial(self, r: int, s: int) -> pl.Poly:
        """Coefficient polynomial of Q_rs (one ordered pair) in the block's sum."""
        a, i = self.index(r)
        b, j = self.index(s)
        h = self.multiplier.matrix[i][j]
        m = pl.mono_mul(self.basis[a], self.basis[b])
        return {pl.mono_mul(e, m): c for e, c in h.items()}


def expand(block: Block, gram) -> pl.Poly:
    """sum_{r,s} Q_rs * entry_polynomial(r, s), exactly (``gram`` of mpq, symmetric)."""
    out: pl.Poly = {}
    n = block.gram_size
    for r in range(n):
        for s in range(r, n):
            q = gram[r][s]
            if not q:
                continue
            w = q if r == s else 2 * q
            for m, c in block.entry_polynomial(r, s).items():
                v = out.get(m, 0) + w * c
                if v:
                    out[m] = v
                else:
                    out.pop(m, None)
    return out


@dataclass(frozen=True)
class SosProgram:
    """Prove ``target`` >= 0 over R^n with the given multipliers (bases chosen by search)."""

    variables: tuple[str, ...]
    target: pl.Poly
    multipliers: tuple[Multiplier, ...]


@dataclass
class StepProgram:
    """The SOS program of one claim ``slack >= 0``, and what binds a certificate to it.

    ``numerator`` is the slack's numerator, ``factors`` the known non-negative factors
    divided out of it (numerator = prod f^k * ``program.target``), ``groups`` the
    parameters of each variable (for the search's bases). :mod:`verify.proof.sos_step`
    derives it from a proof step; :mod:`verify.sos.certificate` checks a certificate
    against it.

    ``statement`` is the inequality as a certificate of this program writes it and must
    carry: printed from the step's tree with every label ignored (a label is only the
    author's word), or, for a step of the paper's proofs, with the package's own labels.
    ``declarations`` and ``assumptions`` are the premises it rests on, printed from
    their trees (``R ∈ SO(3)``, ``k > 0``; ``c >= 0``), and :attr:`claim` the sentence
    a checked certificate is reported as.
    """

    program: SosProgram
    groups: list[list[int]]
    numerator: pl.Poly
    factors: list[tuple[pl.Poly, int]]
    statement: str
    #: the statement with the author's labels ("" if not known)
    labelled: str = ""
    declarations: tuple[str, ...] = ()
    assumptions: tuple[str, ...] = ()
    #: ``label = tree`` for each label of the step that reads otherwise than its tree
    definitions: tuple[str, ...] = ()

    @property
    def claim(self) -> str:
        """``statement for all declarations with assumptions``: what is proved; a
        statement written with labels (the paper's) also says what each label stands
        for (``writing label = tree; ...``)."""
        text = self.statement
        if self.declarations:
            text += " for all " + ", ".join(self.declarations)
        if self.assumptions:
            text += " with " + " and ".join(self.assumptions)
        if self.definitions and self.statement == self.labelled:
            text += ", writing " + "; ".join(self.definitions)
        return text
