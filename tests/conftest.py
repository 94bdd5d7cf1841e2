"""Hypothesis profiles: 'ci' (bounded, the default), 'dev', and 'deep'.

Select with VERIFY_HYPOTHESIS_PROFILE=deep (or dev). Slow tests run with VERIFY_SLOW=1.

BLAS runs one thread per test process unless the environment says otherwise: `pytest -n 2`
on 2 cores with OpenBLAS's default threads per worker oversubscribed the machine (the
suite took 15 min against 4.5 min pinned). Set here, before anything imports numpy.
"""

import os

for _variable in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")

import pytest  # noqa: E402
from hypothesis import HealthCheck, settings  # noqa: E402

settings.register_profile(
    "ci",
    max_examples=40,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
settings.register_profile("dev", max_examples=150, deadline=None)
settings.register_profile(
    "deep",
    max_examples=2000,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
settings.load_profile(os.environ.get("VERIFY_HYPOTHESIS_PROFILE", "ci"))


def pytest_configure(config):
    """One folder for the session's compiled Coq prelude (``coq_tools.SHARED_ENV``), made
    by the first process, before ``pytest -n`` starts its workers (they inherit it)."""
    from coq_tools import SHARED_ENV

    if os.environ.get(SHARED_ENV):
        return
    import tempfile

    os.environ[SHARED_ENV] = tempfile.mkdtemp(prefix="verify-coq-prelude-")
    config._verify_coq_prelude = os.environ[SHARED_ENV]


def pytest_unconfigure(config):
    made = getattr(config, "_verify_coq_prelude", None)
    if made:
        import shutil

        shutil.rmtree(made, ignore_errors=True)


def pytest_collection_modifyitems(config, items):
    if os.environ.get("VERIFY_SLOW") == "1":
        return
    skip = pytest.mark.skip(reason="slow deep check; set VERIFY_SLOW=1")
    for item in items:
        if "slow" in item.keywords:
            item.add_marker(skip)


@pytest.fixture(autouse=True)
def _front_end_without_namespaces(request, monkeypatch):
    """Where this machine cannot make namespaces (some CI containers), ``verify check
    FILE.py`` refuses unless ``--unsandboxed``; the tests of the checker itself then run
    the front end in its plain child process (the sandbox's own tests skip with the
    reason). Where namespaces exist, nothing changes."""
    from verify.proof import sandbox

    if not sandbox.unavailable() or request.node.get_closest_marker("sandbox_required"):
        return
    import verify.proof.isolate as isolate

    plain = isolate.load_isolated

    def unsandboxed(path, **options):
        options["sandboxed"] = False
        return plain(path, **options)

    monkeypatch.setattr(isolate, "load_isolated", unsandboxed)


@pytest.fixture(scope="session")
def prelude_dir(tmp_path_factory):
    """A folder with the Coq prelude, compiled on demand once per session (skips where
    coqc is missing)."""
    from coq_tools import compile_prelude

    from verify.coq.development import coqc_available

    if not coqc_available():
        pytest.skip("coqc not installed")
    return compile_prelude(tmp_path_factory.mktemp("coq-prelude"))
