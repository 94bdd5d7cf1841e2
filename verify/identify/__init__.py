"""Identification of the human operator from experiment logs (Section 4, "Human Modeling").

What flows in: experiment logs (CSV or NPZ, read by :mod:`verify.inputs.experiment_log`
into :class:`verify.inputs.experiment.ExperimentLog`), one or more trials of the
operator's input e (first two components of sk(R_l^T R_r)^vee) and output u_h (first two
components of omega_h^b), sampled uniformly. What flows out: a continuous-time
:class:`verify.passivity.model.LTIModel` of H(s) in the chosen structure (the paper's
2-pole-1-zero diagonal with constant off-diagonals, given numbers of poles and zeros, or a
state-space order) with its parameter covariance and quality figures (fit ratios of
Section 4, residual tests), written as a ``verify gate`` model file, and a verdict on
passivity that holds for every model in the parameter confidence region, decided by the
exact machinery of :mod:`verify.passivity`.

The stages, in the order the data pass through them (each imports only the ones above it):

1. :mod:`verify.identify.data`: logs -> trials prepared by the Section 4 protocol (dead
   time, decimation, split), and simulated experiments with a known operator;
2. :mod:`verify.identify.estimate`: prepared trials -> an :class:`Estimate` of H(s)'s
   parameters with their covariance (SRIVC, output-error refinement, bootstrap);
3. :mod:`verify.identify.quality`: estimate and trials -> fit ratios, residual tests and the
   identifiability gate that refuses data which do not determine the operator;
4. :mod:`verify.identify.model`: estimate -> the exact model (a ``verify gate`` file whose
   decimals are the model, read back) and its confidence region as exact rationals;
5. :mod:`verify.identify.robust`: region -> the robust verdict for every model of it
   (proof or region-wide refutation, each with a certificate and its exact checker), and
   the likelihood-ratio test whether the data reject passivity;
6. :mod:`verify.identify.figures` and :mod:`verify.identify.command`: pictures of the fit
   and the verdicts, and ``verify identify``, which runs the stages in order and writes
   every file.
"""
