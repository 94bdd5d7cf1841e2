"""The compiled prelude is cached per Coq version and prelude text, in XDG_CACHE_HOME.

A stand-in compiler (writes ``X.vo`` for ``X.v`` and counts calls) makes these fast; the
real ``coqc`` path is exercised by the Coq tests and ``verify gate --coq``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from verify.coq import prelude_cache as pc
from verify.coq.development import compile_development, write_development

SOURCES = {"SO3": "(* a *)", "QCert": "(* b *)"}


class FakeCoqc:
    def __init__(self, fail: str | None = None) -> None:
        self.calls: list[str] = []
        self.fail = fail

    def __call__(self, folder: Path, rel: str, coqc: str, timeout: float):
        self.calls.append(rel)
        if rel == self.fail:
            return False, "Error", 0.0
        (Path(folder) / (rel[:-2] + ".vo")).write_bytes(b"vo of " + rel.encode())
        return True, "", 0.01


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    monkeypatch.setattr(pc, "coq_version", lambda coqc: "8.16.1 4.13.1")
    return tmp_path / "xdg" / "verify" / "coq-prelude"


def test_cache_root_follows_xdg(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert pc.cache_root() == tmp_path / "verify" / "coq-prelude"
    monkeypatch.setenv("XDG_CACHE_HOME", "relative/path")  # not absolute: ignored (XDG)
    assert pc.cache_root() == Path.home() / ".cache" / "verify" / "coq-prelude"


def test_the_key_depends_on_version_root_and_every_source() -> None:
    key = pc.prelude_key("8.16.1", "VerifyCoq", SOURCES)
    assert key != pc.prelude_key("8.17.0", "VerifyCoq", SOURCES)
    assert key != pc.prelude_key("8.16.1", "Other", SOURCES)
    assert key != pc.prelude_key("8.16.1", "VerifyCoq", {**SOURCES, "QCert": "(* c *)"})
    assert key == pc.prelude_key("8.16.1", "VerifyCoq", dict(SOURCES))


def test_compiled_once_then_reused_and_a_damaged_entry_rebuilt(cache) -> None:
    fake = FakeCoqc()
    first = pc.compiled_prelude(SOURCES, "VerifyCoq", compile_one=fake)
    assert first is not None and [f for f, _ in first.compiled] == ["SO3.v", "QCert.v"]
    assert first.folder.parent == cache and "compiled once" in first.summary()
    second = pc.compiled_prelude(SOURCES, "VerifyCoq", compile_one=fake)
    assert second is not None and second.compiled == () and fake.calls == ["SO3.v",
                                                                           "QCert.v"]
    assert "reused" in second.summary()
    (second.folder / "QCert.vo").write_bytes(b"damaged")  # the manifest no longer matches
    third = pc.compiled_prelude(SOURCES, "VerifyCoq", compile_one=fake)
    assert third is not None and third.compiled and len(fake.calls) == 4
    assert (third.folder / "QCert.vo").read_bytes() == b"vo of QCert.v"
    assert not [p for p in cache.iterdir() if p.name.startswith("building-")]


def test_a_refused_prelude_is_not_cached(cache) -> None:
    assert pc.compiled_prelude(SOURCES, "VerifyCoq", compile_one=FakeCoqc("QCert.v")) is None
    assert not cache.exists() or not any(cache.iterdir())


def test_a_development_without_units_compiles_nothing(tmp_path, cache, monkeypatch) -> None:
    write_development(tmp_path / "dev", [])
    calls = []
    monkeypatch.setattr("verify.coq.development._compile_one",
                        lambda *a: calls.append(a) or (True, "", 0.0))
    result = compile_development(tmp_path / "dev")
    assert result.ok and result.timings == () and not calls
    assert "nothing compiled" in result.prelude
