"""Find a KYP certificate numerically, then make it exact (untrusted search, trusted check).

1. Balance the state coordinates with a diagonal similarity of powers of two (exact, so
   the certificate maps back without rounding): badly scaled models (poles near 1e12
   and 1e-4 together) become tractable.
2. Fast path (:mod:`verify.passivity.search.reduce`, :mod:`verify.passivity.search.riccati`): solve
   the equality constraints P B N = C^T N (N spans ker(D + D^T)) exactly once, as
   P = P0 + V Y V^T, and find Y with a margin from a Riccati equation of the
   remaining regular problem (one ordered Schur form of its Hamiltonian). The float P
   is rounded to a short dyadic matrix and corrected exactly on k pivot rows so that
   the equality holds (:class:`_ShortRounding`); the exact P0 + V Y V^T is the
   fallback. No SDP is solved; this is O(n^3): about 0.2 s at n = 100 and 1 s at 200.
3. Fallback, for models on the boundary (lossless parts, singular auxiliary problems):
   the Riccati midpoint of the KYP equation and the max-margin SDP (cvxpy + Clarabel),
   rounded and then projected exactly onto the equality constraints by a symmetric
   rank-2k correction (Peyrl-Parrilo style). Input directions u in ker(D + D^T) with
   B u = 0 are dropped first (:func:`verify.passivity.search.reduce.equality_directions`). The
   fallback is skipped when nu(w) is clearly negative in floating point (no certificate
   can exist; the caller seeks a witness), and the SDP above :data:`SDP_STATE_LIMIT`
   states (642 MB and 14 s at 60 states on an idle machine, over 3.6 GB at 100; the
   exact frequency-domain route decides those sizes instead).
4. Lossless models (D + Dᵀ = 0) that the fast path leaves open: the storage with
   M(P) = 0 is solved from the Krylov equations P K = L modulo primes and lifted
   (:mod:`verify.passivity.search.lossless`); no SDP, any size.
5. Every candidate is checked exactly (:func:`verify.passivity.check.certificate.check_kyp`):
   P > 0 and M(P) <= 0. The solvers' status never decides anything.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
from gmpy2 import mpq

from verify.inputs.numbers import fraction
from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import (
    ExactModel,
    check_kyp,
    kyp_matrix,
    verified_kyp,
    verified_kyp_split,
)
from verify.passivity.check.kyp_int import SplitP, int_matrix, int_matrix_from_ints
from verify.passivity.search.lossless import lossless_certificate
from verify.passivity.search.reduce import (
    NoCertificate,
    NotReducible,
    equality_directions,
    null_basis_of_transpose,
    reduce_kyp,
    v_matrix,
)
from verify.passivity.search.riccati import lmi_margin, margin_candidates


@dataclass
class KypSearch:
    P: ex.RationalMatrix | None
    margin: float | None
    status: str
    reason: str


def _balance(A: np.ndarray) -> np.ndarray:
    """Diagonal scaling T (powers of 2) so that T^-1 A T is balanced."""
    if A.shape[0] == 0:
        return np.ones(0)
    _, (scaling, _) = sla.matrix_balance(A, permute=False, separate=True)
    return np.asarray(scaling, dtype=float)


def solve_numeric(A, B, C, D, N: np.ndarray, *, kernel: np.ndarray | None = None
                  ) -> tuple[np.ndarray | None, float | None, str]:
    """Max-margin KYP solution in the given coordinates (cvxpy + Clarabel).

    N: the directions of the equality P B N = C^T N; ``kernel`` (default N): a basis of
    ker(D + D^T), where no margin is asked.
    """
    import cvxpy as cp  # the SDP fallback only: imported on use (start-up time)

    kernel = N if kernel is None else kernel
    n, m = A.shape[0], D.shape[0]
    S = D + D.T
    P = cp.Variable((n, n), symmetric=True)
    t = cp.Variable()
    M = cp.bmat([[A.T @ P + P @ A, P @ B - C.T], [B.T @ P - C, -S]])
    # margin on the state block and on the range of S (not on ker S)
    if kernel.shape[1]:
        Q, _ = np.linalg.qr(kernel)
        range_proj = np.eye(m) - Q @ Q.T
        range_proj[np.abs(range_proj) < 1e-12] = 0.0  # no margin asked where S vanishes
    else:
        range_proj = np.eye(m)
    E = sla.block_diag(np.eye(n), range_proj)
    cons = [P >> t * np.eye(n), -M >> t * E, t <= 1.0]  # (a trace bound upsets Clarabel)
    if N.shape[1]:
        cons.append((P @ B - C.T) @ N == 0)
    prob = cp.Problem(cp.Maximize(t), cons)
    try:
        with warnings.catch_warnings():  # an inaccurate solution is caught by the exact check
            warnings.simplefilter("ignore")
            prob.solve(solver=cp.CLARABEL)
    except (cp.error.SolverError, ValueError) as exc:
        return None, None, f"solver error: {exc}"
    if P.value is None:
        return None, None, f"solver status {prob.status}"
    return np.asarray(P.value), float(t.value), str(prob.status)


def riccati_candidate(A, B, C, D) -> np.ndarray | None:
    """An interior KYP candidate from two Riccati solutions, O(n^3) (no SDP).

    With S = D + D^T > 0 (regularised to S + 2 eps I when singular), the KYP LMI's
    boundary is the Riccati equation A^T P + P A + (P B - C^T) S^-1 (B^T P - C) = 0. Its
    stabilising and anti-stabilising solutions bound the feasible P (available storage
    and required supply); their midpoint is an interior point when the two differ. The
    candidate is only a proposal: it is rounded, projected and checked exactly.
    """
    n, m = A.shape[0], D.shape[0]
    S = D + D.T
    w = np.linalg.eigvalsh(S)
    scale = max(1.0, float(np.abs(C @ B).max()) if n else 1.0)
    if w[0] <= 1e-9 * max(1.0, abs(w[-1])):
        S = S + 2e-7 * scale * np.eye(m)
    try:
        with np.errstate(all="ignore"):
            # scipy solves A'X + XA - (XB + s) R^-1 (B'X + s') + Q = 0; with X = -P this is
            # the KYP Riccati equation. Stabilising solution: X1. Anti-stabilising: -Y with
            # Y the stabilising solution for (-A, B, s = -C^T).
            X1 = sla.solve_continuous_are(A, B, np.zeros((n, n)), S, s=C.T)
            Y = sla.solve_continuous_are(-A, B, np.zeros((n, n)), S, s=-C.T)
    except (np.linalg.LinAlgError, ValueError):
        return None
    P = (-X1 + Y) / 2  # midpoint of the two extreme solutions P1 = -X1 and P2 = Y
    if not np.all(np.isfinite(P)):
        return None
    return (P + P.T) / 2


def _project_equalities(P: ex.RationalMatrix, G: ex.RationalMatrix, target: ex.RationalMatrix):
    """Symmetric exact correction so that P G = target (G full column rank, G^T target sym)."""
    R = ex.add(target, ex.matmul(P, G), -1)
    Hq = ex.inverse(ex.matmul(ex.transpose(G), G))
    RH = ex.matmul(R, Hq)
    GH = ex.matmul(G, Hq)
    GtR = ex.matmul(ex.transpose(G), R)
    term1 = ex.matmul(RH, ex.transpose(G))
    term2 = ex.matmul(GH, ex.transpose(R))
    term3 = ex.matmul(ex.matmul(GH, GtR), ex.matmul(Hq, ex.transpose(G)))
    delta = ex.add(ex.add(term1, term2), term3, -1)
    return ex.add(P, delta)


def _roundings(P_float: np.ndarray):
    """Rational candidates near P: dyadic at several precisions, then short fractions.

    Short continued-fraction rationals recover exact solutions on the boundary of the LMI
    (e.g. a lossless direction that pins an entry of P to 2), which no dyadic rounding of
    a floating-point P meets exactly.
    """
    scale = max(1.0, float(np.max(np.abs(P_float))))
    for bits in (24, 36, 48, 60):
        step_bits = max(bits - int(np.ceil(np.log2(scale))), 8)
        yield f"{bits}-bit", ex.rationalize(P_float, step_bits)
    for limit in (16, 1000, 10**6):
        yield f"continued-fraction (denominators <= {limit})", [
            [mpq(fraction(float(x)).limit_denominator(limit)) for x in row] for row in P_float
        ]


def _balanced(model: ExactModel, scaling: np.ndarray) -> ExactModel:
    """The exact model in coordinates x = T x_b, T = diag(scaling) (powers of two)."""
    t = [mpq(float(x)) for x in scaling]
    n, m = model.n, model.m
    A = [[model.A[i][j] * t[j] / t[i] for j in range(n)] for i in range(n)]
    B = [[model.B[i][j] / t[i] for j in range(m)] for i in range(n)]
    C = [[model.C[i][j] * t[j] for j in range(n)] for i in range(m)]
    return ExactModel(A, B, C, model.D)


def _unbalance(P_b: ex.RationalMatrix, scaling: np.ndarray) -> ex.RationalMatrix:
    """P = T^-1 P_b T^-1: the same storage function x_b^T P_b x_b in the model's states."""
    t = [mpq(float(x)) for x in scaling]
    return [[x / (t[i] * t[j]) for j, x in enumerate(row)] for i, row in enumerate(P_b)]


def _symmetric_rounding(Y: np.ndarray, bits: int) -> ex.RationalMatrix:
    """Dyadic rounding of the upper triangle, mirrored: exactly symmetric."""
    r = Y.shape[0]
    if r == 0:
        return []
    scale = max(1.0, float(np.max(np.abs(Y))))
    Yr = ex.rationalize(Y, max(bits - int(np.ceil(np.log2(scale))), 8))
    return [[Yr[min(i, j)][max(i, j)] for j in range(r)] for i in range(r)]


#: Above this many states the SDP fallback is not tried: Clarabel's memory and time grow
#: like n^4 and n^6 (a 60-state tangent model: minutes and 700 MB on a loaded machine),
#: while the exact frequency-domain route (verify.passivity.fd_decision) decides such
#: models completely up to 120 states, in seconds, with less memory.
SDP_STATE_LIMIT = 20
#: nu(w) below -this x (1 + |H(jw)|) in floating point: no KYP certificate can exist
NEGATIVE_NU = 1e-6


def _clearly_not_passive(A, B, C, D) -> str:
    """Why no KYP certificate can exist, from floating point ("" when none is seen).

    When nu(w) is clearly negative somewhere the model is not passive, and the slow
    fallback searches (the Riccati midpoint, then an SDP) are skipped: the caller seeks an
    exact witness instead. Skipping a search only ever loses a certificate, so a wrong
    float answer costs completeness, never soundness.
    """
    from verify.passivity.search.hamiltonian import nu_minimum, nu_rounding_bound, nu_values

    try:
        with np.errstate(all="ignore"):
            found = nu_minimum(A, B, C, D)
            ends = np.abs(nu_values(A, B, C, D, np.array([0.0, np.inf])))
            noise = nu_rounding_bound(A, B, C, D, found.omega) \
                if np.isfinite(found.omega) else np.inf
    except (np.linalg.LinAlgError, ValueError, OverflowError):
        return ""
    scale = float(np.max(ends[np.isfinite(ends)], initial=0.0))
    # a value inside the rounding error of its own evaluation is noise, not a sign
    if np.isfinite(found.value) and found.value < -NEGATIVE_NU * (1.0 + scale) \
            and -found.value > noise:
        return f"ν ≈ {found.value:.3g} < 0 at ω ≈ {found.omega:.4g} in floating point"
    return ""


FAST_CANDIDATES = 3  # Riccati margins tried before the fallback


def _worth_checking(model: ExactModel, P: ex.RationalMatrix, frugal: bool) -> bool:
    """Whether to run the exact check on P. Always, unless ``frugal``: then not when P has
    a non-positive or M(P) a positive eigenvalue beyond rounding (1e-12 of its largest
    entry) in floating point. Such a candidate (on a lossless or tangent model) fails the
    exact check after a costly exact LDL^T (about 12 s each at 60 states); skipping it
    loses nothing when the complete frequency-domain route decides the model next."""
    if not frugal:
        return True
    try:
        with np.errstate(all="ignore"):
            Pf = np.array([[float(x) for x in row] for row in P])
            M = np.array([[float(x) for x in row] for row in kyp_matrix(model, P)])
            if not (np.all(np.isfinite(Pf)) and np.all(np.isfinite(M))):
                return True
            p_low = np.linalg.eigvalsh((Pf + Pf.T) / 2)[0]
            m_high = np.linalg.eigvalsh((M + M.T) / 2)[-1]
    except (np.linalg.LinAlgError, ValueError, OverflowError):
        return True
    scale = max(float(np.max(np.abs(M), initial=0.0)), 1e-300)
    return bool(p_low > 0 and m_high <= 1e-12 * scale)


#: significant bits of the short rounding of a candidate P (:class:`_ShortRounding`)
SHORT_BITS = 52


class _ShortRounding:
    """A candidate P with short entries: the float P0 + V Y Vᵀ (model coordinates) rounded
    to a symmetric dyadic matrix, then corrected exactly on k pivot rows and columns so
    that P B N' = Cᵀ N' holds (N' from
    :func:`verify.passivity.search.reduce.equality_directions`).

    The correction Δ is supported on the pivot rows/columns p of a nonsingular k x k block
    B1 = (B N')[p]: with R = Cᵀ N' − P̃ B N', Δ[f, p] = R[f] B1⁻¹ on the other rows f and
    Δ[p, p] = (R[p] − Δ[f, p]ᵀ (B N')[f]) B1⁻¹, symmetric because N'ᵀ C B N' is. Only the
    2k rows and columns carry long denominators, which
    :mod:`verify.passivity.check.kyp_int` exploits; the exact P0 + V Y Vᵀ has them
    everywhere.
    """

    def __init__(self, model: ExactModel, red, scaling: np.ndarray) -> None:
        self.model, self.red, self.scaling = model, red, scaling
        n = model.n
        self.P0 = red.P0_float
        self.V = v_matrix(n, red.pivots, red.free, red.X)
        self.setup: tuple | bool | None = False  # computed on first use

    def _equality(self):
        model = self.model
        N = equality_directions(model)
        if isinstance(N, NoCertificate):
            return None
        k = len(N[0]) if model.m and N[0] else 0
        if k == 0:
            return ()
        Bp = ex.matmul(model.B, N)
        CtN = ex.matmul(ex.transpose(model.C), N)
        basis = null_basis_of_transpose(Bp, model.n, k)
        if basis is None:
            return None
        pivots, free, _ = basis
        B1inv = ex.inverse([Bp[i] for i in pivots])
        return Bp, CtN, pivots, free, B1inv

    def certificate(self, Y: np.ndarray) -> SplitP | None:
        """P = P̃ + Δ as a :class:`SplitP` (P̃ short dyadic, Δ on the pivot rows and
        columns), or None when the correction does not apply."""
        if self.setup is False:
            self.setup = self._equality()
        if self.setup is None:
            return None
        n = self.model.n
        with np.errstate(all="ignore"):
            Pb = self.P0 + self.V @ Y @ self.V.T
            t = 1.0 / self.scaling
            Pf = t[:, None] * Pb * t[None, :]  # exact: powers of two
            Pf = (Pf + Pf.T) / 2
            top = float(np.max(np.abs(Pf))) if n else 0.0
        if not (np.all(np.isfinite(Pf)) and 0.0 < top < 2.0 ** 900):
            return None
        e = SHORT_BITS - int(np.ceil(np.log2(top)))
        Z = np.rint(np.ldexp(Pf, e))
        Z = np.triu(Z) + np.triu(Z, 1).T  # exactly symmetric
        light = int_matrix_from_ints(Z.astype(np.int64).tolist(), 2 ** e if e >= 0 else 1,
                                     1 if e >= 0 else 2 ** -e)
        if not self.setup:
            return SplitP(light, [], int_matrix_from_ints([], 1, 1, cols=n),
                          int_matrix_from_ints([[] for _ in range(n)], 1, 1))
        Bp, CtN, pivots, free, B1inv = self.setup
        k = len(pivots)
        # R = Cᵀ N' - P̃ B N', exactly: P̃ B N' over the integers
        Bi = int_matrix(Bp, n, k)
        PB = light.Z * Bi.Z  # / (dL dB)
        den = light.d * Bi.d
        R = [[CtN[i][a] - mpq(int(PB[i, a]), den) for a in range(k)] for i in range(n)]
        R1 = [R[i] for i in pivots]
        if free:
            D21 = ex.matmul([R[i] for i in free], B1inv)  # Δ[f, p]
            R1 = ex.add(R1, ex.matmul(ex.transpose(D21), [Bp[i] for i in free]), -1)
        else:
            D21 = []
        D11 = ex.matmul(R1, B1inv)
        if not ex.is_symmetric(D11):
            return None
        heavy_rows = [[mpq(0)] * n for _ in range(k)]
        for a in range(k):
            for b, j in enumerate(free):
                heavy_rows[a][j] = D21[b][a]
            for b, j in enumerate(pivots):
                heavy_rows[a][j] = D11[a][b]
        return SplitP(light, list(pivots), int_matrix(heavy_rows, k, n),
                      int_matrix(D21, n - k, k))


def rational_p(sp: SplitP) -> ex.RationalMatrix:
    """The exact P = L + H of a split certificate, as rationals."""
    L, dL = sp.light.rows, sp.light.d
    P = [[mpq(z, dL) for z in row] for row in L]
    for a, i in enumerate(sp.heavy):
        for j, h in enumerate(sp.rows.rows[a]):
            P[i][j] += mpq(h, sp.rows.d)
    for b, i in enumerate(sp.others):
        for a, j in enumerate(sp.heavy):
            P[i][j] += mpq(sp.cols.rows[b][a], sp.cols.d)
    return P


def reduced_search(model: ExactModel, scaling: np.ndarray, frugal: bool = False
                   ) -> KypSearch | NotReducible:
    """The fast path: a KypSearch when it decides (certificate, or none can exist), else
    the reason it does not apply."""
    try:
        red = reduce_kyp(_balanced(model, scaling))
    except OverflowError:
        return NotReducible("the reduced problem does not fit the floating-point range")
    if isinstance(red, NoCertificate):
        return KypSearch(None, None, "structure", red.reason)
    if isinstance(red, NotReducible):
        return red
    last = "no Riccati solution with a margin"
    short = _ShortRounding(model, red, scaling)
    for tried, (Y, w) in enumerate(margin_candidates(red.Aa, red.Ba, red.Ca, red.Sa)):
        if tried == FAST_CANDIDATES:
            break
        split = short.certificate(Y)  # short entries: a cheap exact check
        result = verified_kyp_split(model, split) if split is not None else None
        if result is not None:
            P = rational_p(split)
            margin = lmi_margin(red.Aa, red.Ba, red.Ca, red.Sa, Y)
            return KypSearch(P, margin, "reduced riccati",
                             f"{result.reason} (reduced Riccati candidate with margin "
                             f"w = {w:.3g}, rounded to {SHORT_BITS} bits and corrected "
                             "exactly on the equality's pivot rows)")
        for bits in (52, 40):
            P = _unbalance(red.assemble(_symmetric_rounding(Y, bits)), scaling)
            result = verified_kyp(model, P)
            if result is None:
                if not _worth_checking(model, P, frugal):
                    last = "candidate skipped: no clear margin in floating point"
                    continue
                result = check_kyp(model, P)
            if result.ok:
                margin = lmi_margin(red.Aa, red.Ba, red.Ca, red.Sa, Y)
                return KypSearch(P, margin, "reduced riccati",
                                 f"{result.reason} (reduced Riccati candidate with margin "
                                 f"w = {w:.3g}, {bits}-bit rounding of Y)")
            last = result.reason
    return NotReducible(last)


def find_certificate(model: ExactModel, A, B, C, D, *, frugal: bool = False) -> KypSearch:
    """Search, round, project and check; returns an exactly checked P or the reason.

    ``frugal``: a complete exact route follows, so candidates without a clear margin in
    floating point are not checked exactly (:func:`_worth_checking`)."""
    n, m = model.n, model.m
    if n == 0:
        ok = check_kyp(model, [])
        return KypSearch([] if ok.ok else None, None, "static", ok.reason)
    scaling = _balance(A)
    fast = reduced_search(model, scaling, frugal)
    if isinstance(fast, KypSearch):
        return fast
    lossless = lossless_certificate(model)  # D + Dᵀ = 0: M(P) = 0 solved exactly
    if lossless.P is not None:
        return KypSearch(lossless.P, 0.0, "lossless", lossless.reason)
    fast = NotReducible(f"{fast.reason}; lossless route: {lossless.reason}")
    negative = _clearly_not_passive(A, B, C, D)
    if negative:  # the fallback cannot succeed; the caller looks for a witness
        return KypSearch(None, None, "float analysis",
                         f"reduced Riccati search: {fast.reason}; fallback not tried: {negative}")
    T, Ti = np.diag(scaling), np.diag(1.0 / scaling)
    Ab, Bb, Cb = Ti @ A @ T, Ti @ B, C @ T
    S = ex.add(model.D, ex.transpose(model.D))
    kernel = ex.kernel_basis(S)
    kernel_f = (np.array([[float(x) for x in row] for row in kernel])
                if m and kernel[0] else np.zeros((m, 0)))
    N_exact = equality_directions(model)  # B N' of full column rank
    if isinstance(N_exact, NoCertificate):
        return KypSearch(None, None, "structure", N_exact.reason)
    k = len(N_exact[0]) if m and N_exact[0] else 0
    N = np.array([[float(x) for x in row] for row in N_exact]) if k else np.zeros((m, 0))
    if k:
        G = ex.matmul(model.B, N_exact)
        target = ex.matmul(ex.transpose(model.C), N_exact)
        GtT = ex.matmul(ex.transpose(G), target)
        if not ex.is_symmetric(GtT):
            return KypSearch(None, None, "structure",
                             "N^T C B N is not symmetric, so P B N = C^T N has no symmetric P")
    last, margin, status = "not tried", None, "riccati"
    skip_sdp = f"more than {SDP_STATE_LIMIT} states" if n > SDP_STATE_LIMIT else ""
    for method in ("riccati", "sdp"):
        if method == "sdp" and skip_sdp:
            last = f"{last}; SDP not tried: {skip_sdp}"
            break
        if method == "riccati":
            Pb = riccati_candidate(Ab, Bb, Cb, D)
        else:
            Pb, margin, status = solve_numeric(Ab, Bb, Cb, D, N, kernel=kernel_f)
        if Pb is None:
            last = f"no {method} candidate ({status})"
            continue
        P_float = Ti.T @ Pb @ Ti  # back to the model's coordinates
        P_float = (P_float + P_float.T) / 2
        if not np.all(np.isfinite(P_float)):
            last = f"{method}: the candidate is not finite"
            continue
        for label, P in _roundings(P_float):
            P = [[(P[i][j] + P[j][i]) / 2 for j in range(n)] for i in range(n)]
            if k:
                P = _project_equalities(P, G, target)
            result = verified_kyp(model, P)
            if result is None:
                if not _worth_checking(model, P, frugal):
                    last = f"{method}: candidate skipped, no clear margin in floating point"
                    continue
                result = check_kyp(model, P)
            if result.ok:
                return KypSearch(P, margin, status,
                                 f"{result.reason} ({method} candidate, {label} rounding)")
            last = f"{method}: {result.reason}"
    return KypSearch(None, margin, status,
                     f"the rounded numerical solutions fail the exact check: {last}; "
                     f"reduced Riccati search: {fast.reason}")
