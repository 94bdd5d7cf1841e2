"""Machine checks of the paper "Passivity-based semi-autonomous rotational motion
navigation for rigid-body networks" (``../shared/paper/paper.tex``).

Subpackages, data flowing one way:

* :mod:`verify.so3` -- the SO(3) kernel (hat, vee, exp, log, sampling, projection);
* :mod:`verify.system` -- the paper's system of Sections 2-3 (S(d), dbar, W, A(d), laws);
* :mod:`verify.symbolic` -- exact algebra over SO(3) (rational quaternions);
* :mod:`verify.claims` -- the claim registry and the checks of the paper's statements;
* :mod:`verify.report` -- Markdown / HTML / JSON reports rendered from the registry;
* :mod:`verify.cli` -- the ``verify`` command.
"""

__version__ = "0.1.0"
