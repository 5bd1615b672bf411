"""The project's import graph: no circles between modules, the experiments core never leans
on the command line, and the bridge to rcssserver stands beside the simulator (it imports
soccer_sim, never agents or experiments; soccer_sim never imports it).

Every module of the project's packages is parsed (not imported) with :mod:`ast`, and every
``import`` statement it can execute is collected, at module level and inside functions and
classes alike; imports under ``if TYPE_CHECKING:`` never run and are left out. An import
resolves to the module it names: ``import a.b`` and ``from a import b`` (``b`` a submodule)
to ``a.b`` (``a/b/__init__.py`` when ``a.b`` is a package), ``from a.b import name`` (``name``
not a submodule) to ``a.b``; relative imports are resolved against the importing module's
package. Parent packages that Python initialises on the way are not counted as imported (a
package's ``__init__`` re-exporting its submodules would otherwise close a circle with each
of them). Imports of names computed at run time (``importlib.import_module(variable)``) are
invisible to this check.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("soccer_sim", "agents", "formations", "experiments", "kernel_cache", "rcss_bridge")


@dataclass(frozen=True)
class Edge:
    """One import: ``source`` imports ``target`` at ``line`` (inside a function if ``deferred``)."""

    source: str
    target: str
    line: int
    deferred: bool


# ----------------------------------------------------------------------------- the graph
def project_modules(root: Path, packages: Iterable[str]) -> dict[str, Path]:
    """Dotted module name -> file, for every ``.py`` file under the given package directories."""
    modules: dict[str, Path] = {}
    for package in packages:
        for path in sorted((root / package).rglob("*.py")):
            parts = list(path.relative_to(root).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts.pop()
            modules[".".join(parts)] = path
    return modules


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _imports(tree: ast.AST) -> Iterator[tuple[ast.Import | ast.ImportFrom, bool]]:
    """Every import statement that can run, with whether it sits inside a function."""

    def walk(node: ast.AST, in_function: bool) -> Iterator[tuple[ast.Import | ast.ImportFrom, bool]]:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.Import, ast.ImportFrom)):
                yield child, in_function
            elif isinstance(child, ast.If) and _is_type_checking(child.test):
                for other in child.orelse:  # the body never runs
                    yield from walk(ast.Module(body=[other], type_ignores=[]), in_function)
            else:
                nested = in_function or isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
                yield from walk(child, nested)

    yield from walk(tree, False)


def _nearest_module(name: str, modules: dict[str, Path]) -> str | None:
    """``name`` or its longest prefix that is a project module (None: not the project's)."""
    parts = name.split(".")
    while parts:
        candidate = ".".join(parts)
        if candidate in modules:
            return candidate
        parts.pop()
    return None


def import_edges(modules: dict[str, Path]) -> list[Edge]:
    """Every import between two project modules (self-imports left out)."""
    edges: list[Edge] = []
    for module, path in modules.items():
        package = module if path.name == "__init__.py" else module.rpartition(".")[0]
        for node, deferred in _imports(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            targets: list[str | None] = []
            if isinstance(node, ast.Import):
                targets = [_nearest_module(alias.name, modules) for alias in node.names]
            else:
                if node.level:
                    base_parts = package.split(".")
                    if node.level > 1:
                        base_parts = base_parts[: len(base_parts) - (node.level - 1)]
                    base = ".".join(base_parts + ([node.module] if node.module else []))
                else:
                    base = node.module or ""
                for alias in node.names:
                    sub = f"{base}.{alias.name}"
                    targets.append(sub if alias.name != "*" and sub in modules else _nearest_module(base, modules))
            for target in targets:
                if target is not None and target != module:
                    edges.append(Edge(module, target, node.lineno, deferred))
    return edges


def strongly_connected(nodes: Iterable[str], edges: Iterable[Edge]) -> list[list[str]]:
    """The graph's strongly connected components (Tarjan's algorithm, iterative), each sorted."""
    succ: dict[str, list[str]] = {n: [] for n in nodes}
    for e in edges:
        succ[e.source].append(e.target)
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    components: list[list[str]] = []
    for start in sorted(succ):
        if start in index:
            continue
        work = [(start, iter(succ[start]))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            for child in children:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(succ[child])))
                    break
                if child in on_stack:
                    low[node] = min(low[node], index[child])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    components.append(sorted(component))
    return components


def shortest_path(edges: Iterable[Edge], start: str, goals: set[str], within: set[str] | None = None) -> list[Edge]:
    """The fewest imports leading from ``start`` to a module of ``goals`` (staying inside
    ``within`` if given), or [] when none does."""
    by_source: dict[str, list[Edge]] = {}
    for e in edges:
        if within is None or (e.source in within and e.target in within):
            by_source.setdefault(e.source, []).append(e)
    came: dict[str, Edge] = {}
    frontier = [start]
    seen = {start}
    while frontier:
        following = []
        for node in frontier:
            for e in by_source.get(node, ()):
                if e.target in goals:
                    path = [e]
                    while path[0].source != start:
                        path.insert(0, came[path[0].source])
                    return path
                if e.target not in seen:
                    seen.add(e.target)
                    came[e.target] = e
                    following.append(e.target)
        frontier = following
    return []


def describe(path: list[Edge]) -> str:
    """``a -> b (line 3) -> c (line 9, in a function)``."""
    steps = [path[0].source] if path else []
    for e in path:
        steps.append(f"{e.target} (line {e.line}{', in a function' if e.deferred else ''})")
    return " -> ".join(steps)


def cycles(modules: dict[str, Path], edges: list[Edge]) -> list[str]:
    """One description per import circle: a closed path through each component of more than
    one module (preceded by the component's members when the path does not visit them all)."""
    found = []
    for component in strongly_connected(modules, edges):
        if len(component) > 1:
            members = set(component)
            path = describe(shortest_path(edges, component[0], {component[0]}, members))
            found.append(f"{', '.join(component)}: {path}" if len(component) > 2 else path)
    return found


# ----------------------------------------------------------------------------- the project
@pytest.fixture(scope="module")
def project() -> tuple[dict[str, Path], list[Edge]]:
    modules = project_modules(ROOT, PACKAGES)
    return modules, import_edges(modules)


def test_the_project_has_no_import_circles(project):
    modules, edges = project
    found = cycles(modules, edges)
    assert not found, "import circles (each a closed path of imports):\n" + "\n".join(found)


def test_the_experiments_core_does_not_import_the_command_line(project):
    modules, edges = project
    commands = {m for m in modules if m == "experiments.commands" or m.startswith("experiments.commands.")}
    core = [m for m in modules if m.split(".")[:2] in (["experiments", "runner"], ["experiments", "results"])]
    assert commands and core, "the experiments core or its command line is not where this test looks"
    leaks = [describe(path) for m in sorted(core) if (path := shortest_path(edges, m, commands))]
    assert not leaks, "the experiments core reaches experiments.commands:\n" + "\n".join(leaks)


def test_the_bridge_imports_the_simulator_only(project):
    """rcss_bridge may import soccer_sim (configuration, views, self-localisation), never the
    teams (agents) or the runner (experiments); soccer_sim and agents never import the bridge."""
    modules, edges = project
    bridge = {m for m in modules if m.split(".")[0] == "rcss_bridge"}
    assert bridge, "rcss_bridge is not where this test looks"
    for sources, forbidden, rule in (
            (bridge, ("agents", "experiments"), "rcss_bridge reaches agents or experiments"),
            ({m for m in modules if m.split(".")[0] in ("soccer_sim", "agents")}, ("rcss_bridge",),
             "soccer_sim or agents reaches rcss_bridge")):
        goals = {m for m in modules if m.split(".")[0] in forbidden}
        leaks = [describe(path) for m in sorted(sources) if (path := shortest_path(edges, m, goals))]
        assert not leaks, rule + ":\n" + "\n".join(leaks)


def test_the_graph_sees_every_package(project):
    modules, edges = project
    for package in PACKAGES:
        assert package in modules
    # A known import, to show the walk reaches real code: the formations package re-exports Formation.
    assert ("formations", "formations.formation") in {(e.source, e.target) for e in edges}


# ----------------------------------------------------------------------------- the walker itself
def _write(root: Path, files: dict[str, str]) -> dict[str, Path]:
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return project_modules(root, ("pkg",))


def test_a_circle_through_a_function_level_import_is_found(tmp_path):
    modules = _write(tmp_path, {
        "pkg/__init__.py": "",
        "pkg/a.py": "from pkg.b import thing\n",
        "pkg/b.py": "def thing():\n    from pkg import a\n    return a\n",
        "pkg/c.py": "import pkg.a\n",
    })
    found = cycles(modules, import_edges(modules))
    assert found == ["pkg.a -> pkg.b (line 1) -> pkg.a (line 2, in a function)"]


def test_relative_imports_and_submodules_resolve(tmp_path):
    modules = _write(tmp_path, {
        "pkg/__init__.py": "from .sub import leaf\n",
        "pkg/sub/__init__.py": "from ..top import X\nfrom . import leaf\n",
        "pkg/sub/leaf.py": "from .. import top\nfrom pkg.sub import something_else\n",
        "pkg/top.py": "X = 1\n",
    })
    edges = {(e.source, e.target) for e in import_edges(modules)}
    assert edges == {
        ("pkg", "pkg.sub.leaf"), ("pkg.sub", "pkg.top"), ("pkg.sub", "pkg.sub.leaf"),
        ("pkg.sub.leaf", "pkg.top"), ("pkg.sub.leaf", "pkg.sub"),
    }
    # pkg.sub <-> pkg.sub.leaf: leaf takes a name (not a submodule) from its package's __init__.
    assert cycles(modules, import_edges(modules)) == ["pkg.sub -> pkg.sub.leaf (line 2) -> pkg.sub (line 2)"]


def test_type_checking_imports_are_left_out(tmp_path):
    modules = _write(tmp_path, {
        "pkg/__init__.py": "",
        "pkg/a.py": "import typing\nfrom pkg.b import f\nif typing.TYPE_CHECKING:\n    import pkg.c\n",
        "pkg/b.py": "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from pkg.a import A\nelse:\n"
                    "    import pkg.c\ndef f():\n    pass\n",
        "pkg/c.py": "import numpy\n",
    })
    assert {(e.source, e.target) for e in import_edges(modules)} == {("pkg.a", "pkg.b"), ("pkg.b", "pkg.c")}
    assert cycles(modules, import_edges(modules)) == []


def bare_helper_imports(tests_root: Path) -> list[str]:
    """Imports of a test helper module (a non-test module under ``tests/``) by its bare name,
    which works only through pytest's own path handling; each as ``file:line: module``."""
    helpers = {path.stem for path in tests_root.rglob("*.py")
               if not path.name.startswith("test_") and path.name != "conftest.py"}
    found = []
    for path in sorted(tests_root.rglob("*.py")):
        for node, _ in _imports(ast.parse(path.read_text(), str(path))):
            names = [alias.name for alias in node.names] if isinstance(node, ast.Import) else (
                [node.module] if node.module and not node.level else [])
            found += [f"{path.relative_to(tests_root.parent)}:{node.lineno}: {name}"
                      for name in names if name.split(".")[0] in helpers]
    return found


def test_tests_import_their_helpers_one_way():
    """Helpers are imported by their full name (``tests.soccer_sim.core_helpers``), never bare."""
    assert bare_helper_imports(ROOT / "tests") == []


def test_a_bare_helper_import_is_found(tmp_path):
    (tmp_path / "tests" / "pkg").mkdir(parents=True)
    (tmp_path / "tests" / "pkg" / "shared.py").write_text("X = 1\n")
    (tmp_path / "tests" / "pkg" / "test_a.py").write_text(
        "from tests.pkg.shared import X\n\ndef f():\n    from shared import X\n")
    assert bare_helper_imports(tmp_path / "tests") == ["tests/pkg/test_a.py:4: shared"]
