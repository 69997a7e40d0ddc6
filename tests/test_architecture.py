"""The layering and size rules of docs/architecture.md, checked on the source tree.

- The core (``app/kinematics``, ``dh2urdf``) imports nothing from ``app`` outside
  ``app.kinematics``; ``dh2urdf`` imports nothing from ``app`` at all.
- A module longer than :data:`MAX_LINES` says why in its docstring, in a paragraph starting
  ``Why one module:``.
- No test module imports another test module (shared helpers live in helper modules).
- The core's import graph has no cycle (imports that run: module- and function-level).
- A route module (``app/api/routes/<area>.py``) holds routes only: it imports no other
  route module (what routes share lives in plumbing modules beside them, ``app/api/*.py``)
  and defines no pydantic model (wire models live in ``app/api/schemas/<area>.py``).

Imports are read from the syntax tree, so imports inside functions and ``TYPE_CHECKING``
blocks count too, and a name in a docstring or a comment does not.
"""

from __future__ import annotations

import ast
import importlib
import inspect
from pathlib import Path
from types import ModuleType

import pytest
from pydantic import BaseModel

ROOT = Path(__file__).resolve().parents[1]
MAX_LINES = 500
REASON = "Why one module:"


def _modules(*folders: str) -> list[Path]:
    return sorted(p for folder in folders for p in (ROOT / folder).rglob("*.py"))


def _package(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _nodes(tree: ast.AST, runtime: bool) -> list[ast.AST]:
    """Every node of ``tree``; with ``runtime``, none inside an ``if TYPE_CHECKING:`` body
    (never executed: annotations only)."""
    if not runtime:
        return list(ast.walk(tree))
    out: list[ast.AST] = []
    todo = [tree]
    while todo:
        node = todo.pop()
        out.append(node)
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            todo.extend(node.orelse)
            continue
        todo.extend(ast.iter_child_nodes(node))
    return out


def imported(path: Path, package: str | None = None, *, runtime: bool = False) -> set[str]:
    """Every module ``path`` imports (absolute names; relative imports resolved against
    ``package``, by default the package ``path`` is in). With ``runtime``, the imports
    Python executes only: module-level and function-level ones, not ``TYPE_CHECKING``."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    if package is None:
        here = _package(path).split(".")
        if path.name != "__init__.py":
            here = here[:-1]
    else:
        here = package.split(".")
    out: set[str] = set()
    for node in _nodes(tree, runtime):
        if isinstance(node, ast.Import):
            out.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = here[: len(here) - node.level + 1]
                name = ".".join([*base, node.module] if node.module else base)
            else:
                name = node.module or ""
            out.add(name)
            out.update(f"{name}.{alias.name}" for alias in node.names)
    return out


def _rel(path: Path) -> str:
    return str(path.relative_to(ROOT))


@pytest.mark.parametrize("path", _modules("app/kinematics"), ids=_rel)
def test_core_imports_nothing_from_the_app_outside_the_core(path: Path) -> None:
    bad = sorted(
        m
        for m in imported(path)
        if (m == "app" or m.startswith("app."))
        and not (m == "app.kinematics" or m.startswith("app.kinematics."))
    )
    assert not bad, f"{_rel(path)} imports {bad}"


#: Modules that start processes: the core leaves them to app.workers (and app.robots.documents'
#: bounded child).
PROCESS_MODULES = {"multiprocessing", "concurrent.futures.process", "subprocess"}


@pytest.mark.parametrize("path", _modules("app/kinematics"), ids=_rel)
def test_the_core_starts_no_process(path: Path) -> None:
    bad = sorted(
        m
        for m in imported(path)
        if any(m == p or m.startswith(p + ".") for p in PROCESS_MODULES)
        or m in {"concurrent.futures.ProcessPoolExecutor", "os.fork"}
    )
    assert not bad, f"{_rel(path)} imports {bad}: process pools belong in app/workers"


@pytest.mark.parametrize("path", _modules("dh2urdf"), ids=_rel)
def test_dh2urdf_imports_nothing_from_the_app(path: Path) -> None:
    bad = sorted(m for m in imported(path) if m == "app" or m.startswith("app."))
    assert not bad, f"{_rel(path)} imports {bad}"


def import_graph(*folders: str) -> dict[str, set[str]]:
    """Module → the modules of ``folders`` it imports when it runs (:func:`imported` with
    ``runtime``), including the packages Python runs first when it imports a submodule
    (``from a.b.c import x`` runs ``a.b``'s ``__init__``), except the importer's own."""
    modules = {_package(p): p for p in _modules(*folders)}
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        parts = name.split(".")
        own = {".".join(parts[:i]) for i in range(1, len(parts) + 1)}
        edges: set[str] = set()
        for m in imported(path, runtime=True):
            bits = m.split(".")
            for i in range(1, len(bits) + 1):
                target = ".".join(bits[:i])
                if target in modules and target not in own:
                    edges.add(target)
        graph[name] = edges
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The import cycles of ``graph``: its strongly connected components of more than one
    module (Tarjan), each sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
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
            visit(v)
    return found


def test_the_core_import_graph_has_no_cycle() -> None:
    """No import cycle in ``app/kinematics`` (module-level and function-level imports; a
    ``TYPE_CHECKING`` import never runs). Elsewhere two remain, left to their own
    restructuring: ``app/api`` (routes ↔ ik_request ↔ schemas) and ``dh2urdf`` (table ↔
    parse, function-level)."""
    assert cycles(import_graph("app/kinematics")) == []


def test_the_cycle_finder_sees_cycles_through_packages_and_function_imports(
    tmp_path: Path,
) -> None:
    """The check above would pass on a reader that sees nothing: a package whose
    ``__init__`` imports a module that imports a submodule of the package back (from inside
    a function) is a cycle; a ``TYPE_CHECKING`` import is not."""
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    path = tmp_path / "sample.py"
    path.write_text(
        "from typing import TYPE_CHECKING\n"
        "if TYPE_CHECKING:\n"
        "    from app.robots.registry import Registry\n"
        "else:\n"
        "    import app.storage.jobs\n"
        "def f():\n"
        "    from app.kinematics.ik.kernel import attempt\n"
    )
    found = imported(path, package="app.kinematics", runtime=True)
    assert "app.kinematics.ik.kernel" in found and "app.storage.jobs" in found
    assert "app.robots.registry" not in found


ROUTES = "app.api.routes"


def _route_modules() -> list[Path]:
    return [p for p in _modules("app/api/routes") if p.name != "__init__.py"]


@pytest.mark.parametrize("path", _route_modules(), ids=_rel)
def test_no_route_module_imports_another_route_module(path: Path) -> None:
    bad = sorted(m for m in imported(path) if m == ROUTES or m.startswith(ROUTES + "."))
    assert not bad, f"{_rel(path)} imports {bad}: share it from a module beside the routes"


def wire_models(module: ModuleType) -> list[str]:
    """The pydantic models ``module`` defines (not those it imports)."""
    return sorted(
        name
        for name, obj in vars(module).items()
        if inspect.isclass(obj) and issubclass(obj, BaseModel) and obj.__module__ == module.__name__
    )


@pytest.mark.parametrize("path", _route_modules(), ids=_rel)
def test_no_route_module_defines_a_wire_model(path: Path) -> None:
    found = wire_models(importlib.import_module(_package(path)))
    assert not found, f"{_rel(path)} defines {found}: wire models go in app/api/schemas/"


def test_the_model_reader_sees_models_defined_and_not_imported() -> None:
    fk = importlib.import_module("app.api.schemas.fk")
    assert {"FKRequest", "FKResponse", "FKBatchRequest"} <= set(wire_models(fk))
    assert "ConfigurationIn" not in wire_models(fk)  # imported from schemas.common


@pytest.mark.parametrize("path", _modules("app", "dh2urdf", "robots"), ids=_rel)
def test_a_long_module_says_why_it_is_one_module(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    lines = text.count("\n")
    if lines <= MAX_LINES:
        return
    doc = ast.get_docstring(ast.parse(text)) or ""
    assert REASON in doc, (
        f"{_rel(path)} has {lines} lines (> {MAX_LINES}): split it by concept, or state "
        f"in its docstring, in a paragraph starting {REASON!r}, why it is one"
    )


@pytest.mark.parametrize("path", sorted((ROOT / "tests").rglob("test_*.py")), ids=_rel)
def test_no_test_module_imports_another_test_module(path: Path) -> None:
    bad = sorted(m for m in imported(path) if m.rsplit(".", 1)[-1].startswith("test_"))
    assert not bad, f"{_rel(path)} imports test modules {bad}: move shared code to a helper"


def test_the_import_reader_sees_what_these_rules_look_for(tmp_path: Path) -> None:
    """The checks above would pass on an empty set: show the reader finds each kind."""
    path = tmp_path / "sample.py"
    path.write_text(
        "from typing import TYPE_CHECKING\n"
        "import app.storage.store\n"
        "from app.kinematics import models\n"
        "from ..settings import Settings\n"
        "if TYPE_CHECKING:\n"
        "    from app.robots.registry import Registry\n"
        "def f():\n"
        "    from tests.api.test_fk import helper\n"
    )
    found = imported(path, package="app.kinematics")
    assert {
        "app.storage.store",
        "app.kinematics.models",
        "app.settings",
        "app.robots.registry",
    } <= found
    assert "tests.api.test_fk" in found


#: Value sets only the wire has (discriminators of the request shapes, answer kinds).
WIRE_ONLY_LITERALS = {
    ("paths.py", '"line"'),
    ("paths.py", '"arc"'),
}


@pytest.mark.parametrize("path", _modules("app/api/schemas"), ids=_rel)
def test_wire_value_sets_come_from_their_definitions(path: Path) -> None:
    """A value set the core (or the storage) defines is imported, not spelled again in a
    ``Literal[...]`` of string constants."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    spelled = []
    for node in ast.walk(tree):
        if (
            isinstance(node, ast.Subscript)
            and isinstance(node.value, ast.Name)
            and node.value.id == "Literal"
        ):
            values = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
            if values and all(isinstance(v, ast.Constant) for v in values):
                text = ", ".join(ast.unparse(v) for v in values).replace("'", '"')
                if (path.name, text) not in WIRE_ONLY_LITERALS:
                    spelled.append(text)
    assert not spelled, f"{_rel(path)} spells value sets {spelled}: import them"
