"""Trusted: the exact checks a passive (or not passive) verdict rests on.

Everything in this package is exact rational arithmetic (gmpy2 ``mpq``, integer matrices
over a common denominator, FLINT polynomials) with no solver and no floating point in
any decision: the matrix helpers and the LDL^T / diagonal-dominance tests of positive
semidefiniteness (:mod:`.exact`, :mod:`.intmat`, :mod:`.psd`); the KYP (positive-real)
and generalized KYP certificate checks (:mod:`.certificate`, :mod:`.gkyp`); the complete
frequency-domain decision of positive realness and the re-check of its certificate,
with the polynomial facts and sums of squares it derives (:mod:`.frequency_domain`,
:mod:`.fd_certificate`, :mod:`.qpoly`, :mod:`.univariate_sos`); the exact confirmation
of non-passivity witnesses (:mod:`.witness`, :mod:`.fd_witness`, :mod:`.witness_bound`);
and the exact minimal realisation every verdict is stated for (:mod:`.realization`).
A bug here can make a verdict wrong; a bug anywhere else can only make it inconclusive.
Floating-point values may enter only as proposals (a rounded direction, a root
enclosure) that these checks then confirm or reject exactly.
"""
