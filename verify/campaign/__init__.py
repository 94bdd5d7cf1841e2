"""Campaigns: sweeps of closed-loop runs with the paper's property checks, on Dask.

In: a campaign spec (:func:`verify.campaign.models.load_spec`: swept k_s,
n, seeds, autonomous inputs, reference schedules, run lengths and steps, human models as
files or seeded families, and the properties of Lemma 1 and Theorem 1 to check). It is
expanded into runs keyed by a hash of their parameters (:mod:`.runs`); each run is one
task that simulates the closed loop and checks the properties with the simulator's
step-doubling tolerances (:mod:`.execute`), on a Dask LocalCluster or an existing
scheduler (:mod:`.engine`). Out: a Parquet store with one row per run key, appended as
rows finish so that an interrupted campaign resumes without repeating runs
(:mod:`.store`), and a Markdown/HTML report that maps the properties over the swept
parameters beside each human's passivity verdict and gives the ``verify simulate``
command that reproduces any run (:mod:`.report`); ``verify campaign`` ties these
together (:mod:`.command`).
"""
