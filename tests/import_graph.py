"""The package's import graph read from its source (no import is executed).

Every ``import`` of a ``verify`` module counts, at module level or inside a function (a
lazy import is still a dependency); imports under ``if TYPE_CHECKING:`` do not, since
they never run. ``from P import name`` is an edge to the module ``P.name`` when that is
a module, else to ``P``. Importing by name is importing too: a module named by a string
passed to ``import_module`` or ``__import__``, or by the values of a table of module
names (the lazy public faces' ``{"decide": "verify.passivity.decision"}``), is an edge.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "verify"


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def modules() -> dict[str, Path]:
    return {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def _type_checking_only(node: ast.If) -> bool:
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _modules_named_in_code(node: ast.AST, known: set[str]) -> set[str]:
    """Modules named by strings that are imported by name (module docstring)."""
    named: set[str] = set()
    if isinstance(node, ast.Call):
        func = node.func
        called = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
        if called in ("import_module", "__import__"):
            named.update(a.value for a in node.args
                         if isinstance(a, ast.Constant) and isinstance(a.value, str))
    if isinstance(node, ast.Dict) and node.values and all(
            isinstance(v, ast.Constant) and v.value in known for v in node.values):
        named.update(v.value for v in node.values)  # type: ignore[union-attr]
    return named


def _imports(name: str, path: Path, known: set[str]) -> set[str]:
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found: set[str] = set()

    def visit(nodes: list[ast.stmt]) -> None:
        for node in nodes:
            if isinstance(node, ast.If) and _type_checking_only(node):
                visit(node.orelse)
                continue
            if isinstance(node, ast.Import):
                found.update(a.name for a in node.names)
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    parts = package.split(".")
                    parts = parts[: len(parts) - (node.level - 1)]
                    base = ".".join(parts + ([base] if base else []))
                for alias in node.names:
                    sub = f"{base}.{alias.name}"
                    found.add(sub if sub in known else base)
            for sub in ast.walk(node) if not isinstance(node, (ast.FunctionDef,
                                                                  ast.AsyncFunctionDef,
                                                                  ast.ClassDef, ast.If,
                                                                  ast.With, ast.Try,
                                                                  ast.For, ast.While)) else ():
                found.update(_modules_named_in_code(sub, known))
            for child in ast.iter_child_nodes(node):
                if isinstance(child, ast.stmt):
                    visit([child])
                elif isinstance(child, ast.excepthandler):
                    visit(child.body)

    visit(ast.parse(path.read_text(encoding="utf-8")).body)
    return {m for m in found if m in known and m != name}


def import_graph() -> dict[str, set[str]]:
    """Module -> the ``verify`` modules it imports."""
    mods = modules()
    known = set(mods)
    return {name: _imports(name, path, known) for name, path in mods.items()}


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def connect(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                connect(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            connect(v)
    return found
