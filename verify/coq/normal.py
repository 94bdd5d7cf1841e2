"""The matrix-level normal form of an expression, as the prelude's ``so3_norm`` leaves it.

An identity between expressions in rotations (Section 3's R, R_l, R̄, ...) often holds
only because some rotation meets its transpose: eq. (13) and Theorem 1's S_r, S_rl and
V derivatives rewrite R̄_rᵀR_rl as R̄ᵀR_l, that is R_r R_rᵀ = I inside a product. In
quaternion coordinates Coq's ``field`` must expand rational functions of high degree to
see it. The prelude's tactic ``so3_norm`` (``SO3.v``) instead rewrites the goal at matrix
level with lemmas proved once: ``sk``, ``sym``, ``msub``, ``mneg`` unfolded, transposes
pushed down to the leaves, products distributed over sums, scalars pulled out, products
associated to the right, ``hat`` split over sums, ``hat(vee(M)) = sk(M)``,
``vee(M)·w = -tr(M hat(w))/2``, and in each product every adjacent ``Rᵀ R`` or ``R Rᵀ``
of a rotation cancelled; ``so3_norm_hat`` also takes rotations out of ``hat``
(``hat(R u) = R hat(u) Rᵀ``). What is left often holds with each rotation replaced by a
free matrix, where ``field`` works on small polynomials.

:func:`normal_form` computes the same normal form on the checker's expression trees,
so the exporter can tell, before writing the proof, whether the identity holds for
free matrices after ``so3_norm`` (or ``so3_norm_hat``). Nothing here is trusted: Coq
re-does the rewriting with its own lemmas, and ``field`` decides what is left.
"""

from __future__ import annotations

from fractions import Fraction

from verify.coq.terms import CoqExportError
from verify.proof.expr import MATRIX, SCALAR, VECTOR, Expr

_MINUS_ONE = Expr("const", (), SCALAR, Fraction(-1))
_HALF = Expr("const", (), SCALAR, Fraction(1, 2))


def normal_form(e: Expr, *, hat: bool = False) -> Expr:
    """``e`` rewritten as ``so3_norm`` (with ``hat``: ``so3_norm_hat``) rewrites its Coq
    text; the value is the same."""
    n = _Normaliser(hat)
    if e.shape == MATRIX:
        return _matrix_expr(n.mat(e))
    if e.shape == VECTOR:
        return _vector_expr(n.vec(e))
    if e.shape == SCALAR:
        return n.sca(e)
    raise CoqExportError("only scalars, vectors and matrices are normalised")


class _Normaliser:
    """A matrix in normal form is a list of terms (scalar coefficients, word of matrix
    atoms); a vector, a list of terms (coefficients, word, vector leaf)."""

    def __init__(self, hat: bool) -> None:
        self.hat_out = hat

    # scalars: rebuilt with their matrix and vector parts normalised
    def sca(self, e: Expr) -> Expr:
        op = e.op
        if op in ("var", "const", "lambda_min", "cos", "sin"):
            return e  # a lambda_min is an atom in Coq (a section variable)
        if op == "trace":
            return Expr("trace", (_matrix_expr(self.mat(e.args[0])),), SCALAR)
        if op == "dot":
            u, v = (self.vec(a) for a in e.args)
            for vee_side, other in ((u, v), (v, u)):  # vee(A) . w = -tr(A hat(w))/2
                if len(vee_side) == 1 and vee_side[0][:2] == ((), ()) and \
                        vee_side[0][2].op == "vee":
                    a = vee_side[0][2].args[0]
                    h = Expr("hat", (_vector_expr(other),), MATRIX)
                    t = Expr("trace", (Expr("matmul", (a, h), MATRIX),), SCALAR)
                    c = Expr("const", (), SCALAR, Fraction(-1, 2))
                    return self.sca(Expr("scale", (c, t), SCALAR))
            return Expr("dot", (_vector_expr(u), _vector_expr(v)), SCALAR)
        if op in ("add", "neg", "scale"):
            return Expr(op, tuple(self.sca(a) for a in e.args), SCALAR)
        raise CoqExportError(f"no normal form for the scalar operation {op!r}")

    def mat(self, e: Expr) -> list[tuple[tuple, tuple]]:
        op, a = e.op, e.args
        if op == "identity":
            return [((), ())]
        if op in ("var", "zero"):
            return [((), (e,))]
        if op == "add":
            return self.mat(a[0]) + self.mat(a[1])
        if op == "neg":
            return [((_MINUS_ONE, *c), w) for c, w in self.mat(a[0])]
        if op == "scale":
            s = self.sca(a[0])
            return [((s, *c), w) for c, w in self.mat(a[1])]
        if op == "matmul":
            left, right = self.mat(a[0]), self.mat(a[1])
            return [(c1 + c2, _reduce(w1 + w2)) for c1, w1 in left for c2, w2 in right]
        if op == "transpose":
            return [_transpose_term(c, w) for c, w in self.mat(a[0])]
        if op in ("sk", "sym"):
            m, sign = a[0], ((_MINUS_ONE,) if op == "sk" else ())
            return [((_HALF, *c), w) for c, w in self.mat(m)] + [
                ((_HALF, *sign, *c), w) for c, w in self.mat(Expr("transpose", (m,), MATRIX))]
        if op == "hat":
            return [t for c, w, x in self.vec(a[0]) for t in self.hat_term(c, w, x)]
        if op == "outer":
            vs = tuple(_vector_expr(self.vec(x)) for x in a)
            return [((), (Expr("outer", vs, MATRIX),))]
        raise CoqExportError(f"no normal form for the matrix operation {op!r}")

    def hat_term(self, coefs: tuple, word: tuple, leaf: Expr) -> list[tuple[tuple, tuple]]:
        """hat(c W x) as matrix terms; with ``hat_out`` the rotations leading W come out
        of the hat (hat(R u) = R hat(u) Rᵀ)."""
        k = 0
        while self.hat_out and k < len(word) and _rotation(word[k]):
            k += 1
        outer = word[:k]
        _, back = _transpose_term((), outer)
        if k == len(word) and leaf.op == "vee":  # hat(vee(M)) = sk(M)
            middle = self.mat(Expr("sk", leaf.args, MATRIX))
        else:
            middle = [((), (Expr("hat", (_vector_expr([((), word[k:], leaf)]),), MATRIX),))]
        return [(coefs + c, _reduce((*outer, *w, *back))) for c, w in middle]

    def vec(self, e: Expr) -> list[tuple[tuple, tuple, Expr]]:
        op, a = e.op, e.args
        if op in ("var", "zero"):
            return [((), (), e)]
        if op == "add":
            return self.vec(a[0]) + self.vec(a[1])
        if op == "neg":
            return [((_MINUS_ONE, *c), w, x) for c, w, x in self.vec(a[0])]
        if op == "scale":
            s = self.sca(a[0])
            return [((s, *c), w, x) for c, w, x in self.vec(a[1])]
        if op == "matmul":
            return [(c1 + c2, _reduce(w1 + w2), x)
                    for c1, w1 in self.mat(a[0]) for c2, w2, x in self.vec(a[1])]
        if op == "vee":
            return [((), (), Expr("vee", (_matrix_expr(self.mat(a[0])),), VECTOR))]
        raise CoqExportError(f"no normal form for the vector operation {op!r}")


def _transpose_term(coefs: tuple, word: tuple) -> tuple[tuple, tuple]:
    out, sign = [], ()
    for atom in reversed(word):
        if atom.op == "hat":  # hat(v)ᵀ = -hat(v)
            out.append(atom)
            sign += (_MINUS_ONE,)
        elif atom.op == "transpose":
            out.append(atom.args[0])
        else:
            out.append(Expr("transpose", (atom,), MATRIX))
    return coefs + sign, tuple(out)


def _rotation(atom: Expr) -> tuple[int, bool] | None:
    """(uid, transposed) of a rotation atom R or Rᵀ."""
    t = atom.op == "transpose"
    base = atom.args[0] if t else atom
    if base.op == "var" and base.data.kind == "rotation":
        return base.data.uid, t
    return None


def _reduce(word: tuple) -> tuple:
    """The word with every adjacent R Rᵀ or Rᵀ R of a rotation cancelled."""
    word = list(word)
    i = 0
    while i < len(word) - 1:
        x, y = _rotation(word[i]), _rotation(word[i + 1])
        if x and y and x[0] == y[0] and x[1] != y[1]:
            del word[i:i + 2]
            i = max(i - 1, 0)
        else:
            i += 1
    return tuple(word)


def _product_expr(coefs: tuple, core: Expr) -> Expr:
    for c in reversed(coefs):
        core = Expr("scale", (c, core), core.shape)
    return core


def _matrix_expr(terms: list) -> Expr:
    if not terms:
        return Expr("zero", (), MATRIX)
    out = None
    for coefs, word in terms:
        core = word[-1] if word else Expr("identity", (), MATRIX)
        for atom in reversed(word[:-1]):
            core = Expr("matmul", (atom, core), MATRIX)
        t = _product_expr(coefs, core)
        out = t if out is None else Expr("add", (out, t), MATRIX)
    return out


def _vector_expr(terms: list) -> Expr:
    if not terms:
        return Expr("zero", (), VECTOR)
    out = None
    for coefs, word, leaf in terms:
        core = leaf
        for atom in reversed(word):
            core = Expr("matmul", (atom, core), VECTOR)
        t = _product_expr(coefs, core)
        out = t if out is None else Expr("add", (out, t), VECTOR)
    return out
