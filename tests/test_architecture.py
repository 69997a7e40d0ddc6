"""The layering and size rules of docs/architecture.md, checked on the source tree.

- The core (``app/kinematics``, ``dh2urdf``) imports nothing from ``app`` outside
  ``app.kinematics``; ``dh2urdf`` imports nothing from ``app`` at all.
- A module longer than :data:`MAX_LINES` says why in its docstring, in a paragraph starting
  ``Why one module:``.
- No test module imports another test module (shared helpers live in helper modules).
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


def imported(path: Path, package: str | None = None) -> set[str]:
    """Every module ``path`` imports (absolute names; relative imports resolved against
    ``package``, by default the package ``path`` is in)."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    if package is None:
        here = _package(path).split(".")
        if path.name != "__init__.py":
            here = here[:-1]
    else:
        here = package.split(".")
    out: set[str] = set()
    for node in ast.walk(tree):
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


@pytest.mark.parametrize("path", _modules("dh2urdf"), ids=_rel)
def test_dh2urdf_imports_nothing_from_the_app(path: Path) -> None:
    bad = sorted(m for m in imported(path) if m == "app" or m.startswith("app."))
    assert not bad, f"{_rel(path)} imports {bad}"


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
