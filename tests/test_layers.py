"""The package's structure: no import cycles, and layers that import only downward.

The layers, lowest first, as ARCHITECTURE.md draws them. A module may import modules of
its own layer or of a layer below; any import up is a dependency of a library on one of
its users. Within a layer, the import graph must still be acyclic.
"""

from __future__ import annotations

import pytest
from import_graph import cycles, import_graph

#: (layer, the module prefixes it holds), lowest first.
LAYERS: list[tuple[str, tuple[str, ...]]] = [
    ("utilities", ("verify", "verify.errors", "verify.validation", "verify.artefacts")),
    ("inputs", ("verify.inputs", "verify.data")),
    ("exact objects", ("verify.so3", "verify.system", "verify.symbolic",
                       "verify.random_networks", "verify.network_file")),
    ("checks and searches", ("verify.sos", "verify.proof", "verify.passivity")),
    ("simulation, identification, campaigns", ("verify.sim", "verify.identify",
                                               "verify.campaign", "verify.strategies")),
    ("claims", ("verify.paper_proofs", "verify.certificates", "verify.claims", "verify.coq")),
    ("reports", ("verify.report",)),
    ("command line", ("verify.cli",)),
]

GRAPH = import_graph()


def layer_of(module: str) -> int:
    """The index of the layer whose longest prefix names the module."""
    best, best_len = None, -1
    for i, (_name, prefixes) in enumerate(LAYERS):
        for p in prefixes:
            if (module == p or module.startswith(p + ".")) and len(p) > best_len:
                best, best_len = i, len(p)
    if best is None:
        raise AssertionError(f"{module} is in no layer; add it to LAYERS")
    return best


def test_every_module_has_a_layer():
    for module in GRAPH:
        layer_of(module)


def test_no_import_cycles():
    found = cycles(GRAPH)
    assert found == [], "import cycles: " + "; ".join(" <-> ".join(c) for c in found)


def test_layers_import_only_downward():
    upward = sorted(
        f"{a} ({LAYERS[layer_of(a)][0]}) imports {b} ({LAYERS[layer_of(b)][0]})"
        for a, targets in GRAPH.items() for b in targets if layer_of(b) > layer_of(a))
    assert upward == [], "imports up a layer:\n" + "\n".join(upward)


@pytest.mark.parametrize("library", ["verify.sos", "verify.proof", "verify.passivity",
                                     "verify.sim", "verify.identify"])
def test_library_layers_know_nothing_of_the_paper(library):
    """The paper's proofs and claims are used by the libraries' callers, never by them."""
    paper = ("verify.paper_proofs", "verify.claims")
    bad = sorted(f"{a} -> {b}" for a, targets in GRAPH.items()
                 if a == library or a.startswith(library + ".")
                 for b in targets if b.startswith(paper))
    assert bad == []


def test_the_graph_sees_lazy_imports_and_skips_type_checking_ones(tmp_path):
    """The reader itself: a function-level import is an edge, a TYPE_CHECKING one is not."""
    from import_graph import _imports

    src = tmp_path / "m.py"
    src.write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n"
                   "    import verify.report\n"
                   "def f():\n    from verify.so3 import hat\n    return hat\n")
    assert _imports("verify.m", src, {"verify.so3", "verify.report"}) == {"verify.so3"}


def test_the_graph_sees_imports_by_name(tmp_path):
    """A lazy public face's table of homes and import_module calls are edges; a string
    that only happens to spell a module (a label written into a file) is not."""
    from import_graph import _imports

    src = tmp_path / "m.py"
    src.write_text('import importlib\n_HOME = {"hat": "verify.so3", "x": "verify.system"}\n'
                   'LABEL = "verify.claims"\n'
                   'def f():\n    return importlib.import_module("verify.report")\n')
    known = {"verify.so3", "verify.system", "verify.claims", "verify.report"}
    assert _imports("verify.m", src, known) == {"verify.so3", "verify.system", "verify.report"}


#: The stages of identification (Section 4), in the order data flows through them.
IDENTIFY_STAGES = ["data", "estimate", "quality", "model", "robust", "figures", "command"]


def test_identification_stages_import_only_earlier_stages():
    """A newcomer reads ``verify/identify/`` top to bottom: no stage needs a later one."""
    def stage(module: str) -> int:
        return IDENTIFY_STAGES.index(module.split(".")[2])

    modules = [m for m in GRAPH if m.startswith("verify.identify.")]
    assert {m.split(".")[2] for m in modules} == set(IDENTIFY_STAGES)
    later = sorted(f"{a} -> {b}" for a in modules for b in GRAPH[a]
                   if b.startswith("verify.identify.") and stage(b) > stage(a))
    assert later == []
