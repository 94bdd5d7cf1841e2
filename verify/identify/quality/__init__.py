"""Stage 3 of identification: how well the estimate describes the operator.

What flows in: an :class:`verify.identify.estimate.result.Estimate` and the prepared
identification and validation trials. What flows out: Section 4's fit ratios of the model
simulated on the logged input and the residual tests
(:class:`verify.identify.quality.fits.Quality`), and the identifiability gate's answer
(:class:`verify.identify.quality.identifiability.Identifiability`): whether the data
determine the operator at all, with the reasons when they do not, before any verdict is
drawn; and whether the data reject the fitted class against one pole and one zero more
(:class:`verify.identify.quality.model_class.ClassTest`).
:mod:`verify.identify.quality.coverage` checks the estimator itself on simulated
experiments with a known operator (how often its intervals hold the truth).
"""
