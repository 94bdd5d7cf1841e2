"""Export of exact proofs and certificates to Coq, checked by ``coqc``.

What flows in: exact objects the Python side has already decided (derivation steps
with their expression trees, SOS certificates, KYP and band certificates as rational
matrices). What flows out: a Coq development (a folder of ``.v`` files, a
``_CoqProject`` and a top file ``All.v`` that ``Require``s every unit) whose statements
are written from the readable definitions of the prelude (``prelude/*.v``) and whose
proofs Coq's kernel checks without trusting this package: only data (numbers,
polynomials, matrices) crosses over, and Coq re-checks it. :mod:`~verify.coq.unit`
holds the unit of export, :mod:`~verify.coq.development` writes and compiles a
development; :mod:`~verify.coq.kyp` and :mod:`~verify.coq.band` export KYP and band
(generalized KYP) certificates of the paper's Section 4 from witnesses proposed by
:mod:`~verify.coq.witness`; :mod:`~verify.coq.band_fd` exports exact-band certificates
(H(jw) + H(jw)^H >= 0 on a band, from polynomial witnesses proposed by
:mod:`~verify.coq.interval_witness`) and :mod:`~verify.coq.positive_real` the frequency
inequality of positive-real ones; :mod:`~verify.coq.export` decides what is exported and lists
the rest with the reason; :mod:`~verify.coq.audit` checks sources and ``Print
Assumptions``; :mod:`~verify.coq.command` is the ``verify coq`` command.
"""
