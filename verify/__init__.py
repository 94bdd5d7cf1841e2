"""Machine checks of the paper "Passivity-based semi-autonomous rotational motion
navigation for rigid-body networks" (``../shared/paper/paper.tex``).

Layers, lowest first; a module imports only from its own layer or those below
(``ARCHITECTURE.md``; kept by ``tests/test_layers.py``):

0. utilities: :mod:`verify.errors`, :mod:`verify.validation`, :mod:`verify.artefacts`;
1. inputs: :mod:`verify.inputs` (numbers, model files, logs, campaign specs), package data;
2. exact objects: :mod:`verify.so3`, :mod:`verify.system` (S(d), dbar, W, A(d), the laws),
   :mod:`verify.symbolic`, network files and random networks;
3. checks and searches: :mod:`verify.passivity`, :mod:`verify.sos`, :mod:`verify.proof`;
4. simulation, identification, campaigns: :mod:`verify.sim`, :mod:`verify.identify`,
   :mod:`verify.campaign`, :mod:`verify.strategies`;
5. claims: :mod:`verify.paper_proofs`, :mod:`verify.certificates`, :mod:`verify.claims`;
6. reports: :mod:`verify.report`;
7. the ``verify`` command: :mod:`verify.cli`.
"""

__version__ = "0.1.0"
