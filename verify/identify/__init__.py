"""Identification of the human operator from experiment logs (Section 4, "Human Modeling").

What flows in: experiment logs (CSV or NPZ, read by :mod:`verify.inputs.experiment_log`
into :class:`verify.identify.experiment.ExperimentLog`), one or more trials of the
operator's input e (first two components of sk(R_l^T R_r)^vee) and output u_h (first two
components of omega_h^b), sampled uniformly. What flows out: a continuous-time
:class:`verify.passivity.model.LTIModel` of H(s) in the chosen structure (the paper's
2-pole-1-zero diagonal with constant off-diagonals, given numbers of poles and zeros, or a
state-space order) with its parameter covariance and quality figures (fit ratios of
Section 4, residual tests), written as a ``verify gate`` model file, and a verdict on
passivity that holds for every model in the parameter confidence region, decided by the
exact machinery of :mod:`verify.passivity`.
"""
