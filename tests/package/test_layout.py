"""The package's layout: ``import glshade`` leaves the lab unimported and `gs.report` loads it on
first use; no import cycle among glshade's modules; no module imports another's private names.

The import graph is read from the source with `ast`, not from a running interpreter, so that a
deferred import (one inside a function, run only on some calls) counts as much as one at the top
of a module. Its rule:

- Every ``import`` and ``from ... import`` statement of a module of glshade is an edge, wherever
  it stands: at module level, inside a function or class, under ``if TYPE_CHECKING:``, in a
  ``try``. Imports of other packages are not edges.
- A package is its ``__init__``. ``import glshade as gs`` and ``from glshade import X`` are edges
  to ``glshade``; ``from . import x`` and ``from glshade import x`` where ``x`` is a submodule are
  edges to that submodule, not to the package; ``from .mod import name`` is an edge to ``mod``;
  ``import glshade.dask`` is an edge to ``glshade.dask``. Relative imports are resolved from the
  importing module's package. The parent packages that Python runs before a submodule are not
  edges (every module of a subpackage would otherwise close a cycle with its parent).
- One edge is allowed to close a cycle, and only where it stands now: ``glshade`` (the package)
  to ``glshade.lab.report``, from its module ``__getattr__`` (the lazy import behind `gs.report`
  and `gs.Report`) and under ``if TYPE_CHECKING:`` (the names' types). The lab is a client of the
  package (``import glshade as gs``), which names two of the lab's objects without importing the
  lab at import time; `test_import_glshade_leaves_the_lab_unimported` holds it to that.
"""

from __future__ import annotations

import ast
import functools
import itertools
import json
import subprocess
import sys
from collections import deque
from dataclasses import dataclass
from pathlib import Path

import pytest

import glshade

PACKAGE = Path(glshade.__file__).parent

# The one edge that may close a cycle, and where it may stand (see the module's docstring).
LAZY_EDGE = ("glshade", "glshade.lab.report")
LAZY_PLACES = frozenset({"__getattr__", "TYPE_CHECKING"})


@dataclass(frozen=True)
class Edge:
    """One import statement's dependency of `source` on `target`, both modules of glshade."""

    source: str
    target: str
    names: tuple[str, ...]  # what a ``from target import ...`` takes that is not a submodule
    place: str  # "module", "TYPE_CHECKING", or the innermost enclosing function or class
    line: int

    def __str__(self) -> str:
        return f"{self.source} -> {self.target} ({_path(self.source)}:{self.line}, {self.place})"


@functools.cache
def _modules() -> dict[str, Path]:
    """Every module of glshade by dotted name (a package by its own: its ``__init__.py``), with
    the native module by its stub."""
    found: dict[str, Path] = {}
    for path in sorted([*PACKAGE.rglob("*.py"), *PACKAGE.rglob("*.pyi")]):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        if parts[-1] == "__init__":
            parts = parts[:-1]
        found.setdefault(".".join(parts), path)
    return found


def _path(module: str) -> str:
    return str(_modules()[module].relative_to(PACKAGE.parent.parent))


def _is_package(module: str) -> bool:
    return _modules()[module].name == "__init__.py"


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


class _Imports(ast.NodeVisitor):
    """The edges of one module, each with the place of its statement."""

    def __init__(self, module: str) -> None:
        self.module = module
        self.places = ["module"]
        self.edges: list[Edge] = []

    def _scope(self, node: ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef) -> None:
        self.places.append(node.name)
        self.generic_visit(node)
        self.places.pop()

    visit_FunctionDef = visit_AsyncFunctionDef = visit_ClassDef = _scope

    def visit_If(self, node: ast.If) -> None:
        if not _is_type_checking(node.test):
            self.generic_visit(node)
            return
        self.places.append("TYPE_CHECKING")
        for statement in node.body:
            self.visit(statement)
        self.places.pop()
        for statement in node.orelse:
            self.visit(statement)

    def _edge(self, target: str, names: tuple[str, ...], node: ast.stmt) -> None:
        if target == "glshade" or target.startswith("glshade."):
            assert target in _modules(), f"{_path(self.module)}:{node.lineno} imports {target}"
            self.edges.append(Edge(self.module, target, names, self.places[-1], node.lineno))

    def visit_Import(self, node: ast.Import) -> None:
        for alias in node.names:
            self._edge(alias.name, (), node)

    def visit_ImportFrom(self, node: ast.ImportFrom) -> None:
        if node.level:
            package = self.module if _is_package(self.module) else self.module.rpartition(".")[0]
            for _ in range(node.level - 1):
                package = package.rpartition(".")[0]
            base = f"{package}.{node.module}" if node.module else package
        else:
            base = node.module or ""
        names = []
        for alias in node.names:
            if f"{base}.{alias.name}" in _modules():
                self._edge(f"{base}.{alias.name}", (), node)
            else:
                names.append(alias.name)
        if names:
            self._edge(base, tuple(names), node)


@functools.cache
def _edges() -> tuple[Edge, ...]:
    edges: list[Edge] = []
    for module, path in _modules().items():
        if path.suffix == ".py":
            visitor = _Imports(module)
            visitor.visit(ast.parse(path.read_text(encoding="utf-8"), str(path)))
            edges += visitor.edges
    return tuple(edges)


def _components(graph: dict[str, set[str]]) -> list[list[str]]:
    """Tarjan's strongly connected components of `graph`."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for other in sorted(graph[node]):
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in on_stack:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            component = []
            while True:
                other = stack.pop()
                on_stack.discard(other)
                component.append(other)
                if other == node:
                    break
            found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def _shortest_cycle(graph: dict[str, set[str]], start: str) -> list[str]:
    """The shortest path from `start` back to itself (breadth first), as its nodes."""
    before: dict[str, str] = {}
    queue = deque([start])
    while queue:
        node = queue.popleft()
        for other in sorted(graph[node]):
            if other == start:
                path = [node]
                while path[-1] != start:
                    path.append(before[path[-1]])
                return [*reversed(path), start]
            if other not in before:
                before[other] = node
                queue.append(other)
    raise AssertionError(f"{start} is on no cycle")


def _run(code: str) -> str:
    """What a fresh interpreter prints running `code`; fails the test with its stderr."""
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=False
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


@pytest.mark.subprocess
def test_import_glshade_leaves_the_lab_unimported() -> None:
    code = (
        "import json, sys, glshade\n"
        "names = dir(glshade)\n"  # completion lists the lazy names without loading the lab
        "assert 'report' in names and 'Report' in names, names\n"
        "print(json.dumps(sorted(m for m in sys.modules if m.startswith('glshade.'))))\n"
    )
    loaded = json.loads(_run(code))
    assert "glshade._glshade" in loaded  # the list is what it claims to be
    assert [m for m in loaded if m.split(".")[1] == "lab"] == []


@pytest.mark.subprocess
@pytest.mark.lab
def test_report_and_Report_load_the_lab_on_first_use() -> None:
    code = """
import sys
import glshade as gs

assert "glshade.lab.report" not in sys.modules
Report, report = gs.Report, gs.report
from glshade.lab import report as lab
assert Report is lab.Report and report is lab.report, (Report, report)
r = gs.report(
    vertices=10, rounds=1, isas=["baseline"], scenes=["1 directional"], studies=False,
    progress=False,
)
assert type(r) is Report, type(r)
print(len(r.rows))
"""
    assert _run(code).split() == ["4"]  # 2 dtypes x 2 accuracy modes


def test_the_imports_of_glshade_make_no_cycle() -> None:
    lazy = [e for e in _edges() if (e.source, e.target) == LAZY_EDGE]
    assert lazy, "the lazy edge behind gs.report is gone: drop it from this test"
    misplaced = [str(e) for e in lazy if e.place not in LAZY_PLACES]
    assert misplaced == [], "glshade may import glshade.lab.report only lazily"
    graph: dict[str, set[str]] = {module: set() for module in _modules()}
    for e in _edges():
        if (e.source, e.target) != LAZY_EDGE:
            graph[e.source].add(e.target)
    cycles = []
    for component in _components(graph):
        if len(component) > 1 or component[0] in graph[component[0]]:
            cycle = _shortest_cycle(graph, component[0])
            statements = [
                str(e)
                for a, b in itertools.pairwise(cycle)
                for e in _edges()
                if (e.source, e.target) == (a, b)
            ]
            cycles.append(" -> ".join(cycle) + "\n    " + "\n    ".join(statements))
    assert cycles == [], "import cycles:\n" + "\n".join(cycles)


def test_no_module_imports_another_s_private_names() -> None:
    private = [
        f"{e}: {name}"
        for e in _edges()
        for name in e.names
        if name.startswith("_") and not (name.startswith("__") and name.endswith("__"))
    ]
    assert private == []
