"""Stage 2 of identification: prepared trials -> estimated H(s) with its covariance.

What flows in: prepared :class:`verify.inputs.experiment.Trial` records (stage 1) and a
:class:`verify.identify.estimate.structure.Structure` (the paper's Section 4 class, P:Z,
or a state-space order). What flows out: an :class:`verify.identify.estimate.result.Estimate`
(parameters in the structure's order, covariance, noise model), or
:class:`verify.identify.estimate.result.CannotIdentifyError` when the data determine no
model. :func:`verify.identify.estimate.estimation.estimate_model` runs it output by
output on the per-output view of the trials (:mod:`verify.identify.estimate.trial_data`):
SRIVC starting denominators (:mod:`~verify.identify.estimate.riv`, on the continuous-time
filters of :mod:`~verify.identify.estimate.ct_filters`), then the output-error refinement
(:mod:`~verify.identify.estimate.pem`) of the simulated output
(:mod:`~verify.identify.estimate.prediction`); the bootstrap over trials
(:mod:`~verify.identify.estimate.bootstrap`) and the ARX baseline of the benchmark
(:mod:`~verify.identify.estimate.baseline`) are the alternatives, and the residual tests
(:mod:`~verify.identify.estimate.residual_tests`) choose a noise model.
"""
