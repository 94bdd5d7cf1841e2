"""Stage 1 of identification: the trials, prepared by the protocol of Section 4.

What flows in: an :class:`verify.inputs.experiment.ExperimentLog` (read from files by
:mod:`verify.inputs.experiment_log`, or simulated here in the paper's protocol with a known
operator, :mod:`verify.identify.data.simulated_experiment`, which the shipped example
logs come from, :mod:`verify.identify.data.example_logs`). What flows out:
:class:`verify.identify.data.protocol.Prepared`, the trials with the dead time after each
reference change removed, decimated, and split into identification and validation trials
(:func:`verify.identify.data.protocol.prepare`), with notes on what was removed.
"""
