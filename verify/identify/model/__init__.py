"""Stage 4 of identification: the estimate as an exact model and an exact region.

What flows in: an :class:`verify.identify.estimate.result.Estimate` with the quality
figures of stage 3. What flows out: the ``verify gate`` model file whose short decimal
coefficients *are* the model, with an ``[identification]`` table, and the same file read
back exactly (:mod:`verify.identify.model.model_writer`); and the parameter confidence
region centred on the written values, as exact rationals
(:class:`verify.identify.model.region.Region`), which the robust verdict of stage 5
decides on and its certificates are bound to.
"""
