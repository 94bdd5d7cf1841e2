"""Sum-of-squares certificates: untrusted search, exact rounding, trusted check.

In: a polynomial p with rational coefficients (the numerator of a step's slack, see
:mod:`verify.proof.sos_step`) and multipliers H_k, matrices of polynomials that are PSD
for a reason the caller re-derives (1, a positive gain, an assumption, the spectral
fact sym(A) - lambda_min(A) I >= 0).

Out: rational Gram matrices Q_k with p = sum_k <Q_k, H_k (x) z_k z_k^T> exactly and
every Q_k PSD exactly, stored as JSON (``verify-sos-certificate/1``).

Modules, in the order data flows: :mod:`~verify.sos.poly` (exact polynomials),
:mod:`~verify.sos.program` (what a certificate asserts), :mod:`~verify.sos.basis`
(monomial bases), :mod:`~verify.sos.search` (the SDP, cvxpy + Clarabel; untrusted),
:mod:`~verify.sos.rounding` (Peyrl-Parrilo rounding and exact correction),
:mod:`~verify.sos.check` (the trusted exact check), :mod:`~verify.sos.certificate`
(JSON, and the checks of a certificate against the program of its claim),
:mod:`~verify.sos.prove` (search, round, check). The library knows nothing of proofs:
callers derive the program (:mod:`verify.proof.sos_step`) and decide which claim a
stored certificate is bound to (:mod:`verify.certificates.sos_kind`).
"""

from verify.sos.certificate import SCHEMA, check_against_program, check_bound, check_form
from verify.sos.check import SosCheck, check_identity_and_psd
from verify.sos.program import Block, Multiplier, SosProgram, StepProgram
from verify.sos.prove import find_certificate

__all__ = ["SCHEMA", "Block", "Multiplier", "SosCheck", "SosProgram", "StepProgram",
           "check_against_program", "check_bound", "check_form", "check_identity_and_psd",
           "find_certificate"]
