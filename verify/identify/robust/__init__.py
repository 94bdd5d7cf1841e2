"""Stage 5 of identification: passivity of every model of the confidence region.

What flows in: the exact model and its confidence region (stage 4) and a band. What flows
out: the robust verdict (:func:`verify.identify.robust.verdict.robust_verdict`: passive,
not passive, or inconclusive, for every model of the region) and the largest band proved
(:func:`verify.identify.robust.verdict.largest_band`), each proof or region-wide
refutation with a certificate file. The searches run in floating point and only propose
(:mod:`~verify.identify.robust.proof_search`, :mod:`~verify.identify.robust.refutation_search`);
the certificate formats (:mod:`~verify.identify.robust.band_certificate`,
:mod:`~verify.identify.robust.refutation_certificate`) are decided by their exact checkers
(:mod:`~verify.identify.robust.band_check`, :mod:`~verify.identify.robust.refutation_check`,
which ``verify certificates check`` also runs). Beside it, the statistical answer: the best
passive model of the paper's class and the likelihood-ratio test whether the data reject
passivity (:mod:`~verify.identify.robust.passive_fit`). When the data reject the fitted
class, :mod:`~verify.identify.robust.model_class_check` withdraws the answers the larger
model's region does not support.
"""
