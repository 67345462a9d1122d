"""The package's shape: no import cycle, small modules, models that never import each other."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from conftest import ROOT

import vbi_lib as vbi

PACKAGE = ROOT / "vbi_lib"
#: No module of the library is longer than this many lines.
MAX_LINES = 600


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def imports(path: Path) -> set[str]:
    """The vbi_lib modules a file imports, anywhere in it (functions included)."""
    name = module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found |= {a.name for a in node.names if a.name.startswith("vbi_lib")}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if not target.startswith("vbi_lib"):
                continue
            for alias in node.names:
                candidate = f"{target}.{alias.name}"
                # `from pkg import submodule` depends on the submodule, not on pkg's __init__
                if (PACKAGE.parent / (candidate.replace(".", "/") + ".py")).is_file() or (
                    PACKAGE.parent / candidate.replace(".", "/") / "__init__.py"
                ).is_file():
                    found.add(candidate)
                else:
                    found.add(target)
    found.discard(name)
    return found


MODULES = {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}
GRAPH = {name: imports(path) & set(MODULES) for name, path in MODULES.items()}


def test_no_import_cycle() -> None:
    state: dict[str, int] = {}

    def visit(node: str, trail: list[str]) -> None:
        state[node] = 1
        for child in sorted(GRAPH[node]):
            if state.get(child) == 1:
                cycle = trail[trail.index(child) :] + [child] if child in trail else [node, child]
                pytest.fail("import cycle: " + " -> ".join(cycle))
            if child not in state:
                visit(child, trail + [child])
        state[node] = 2

    for name in sorted(GRAPH):
        if name not in state:
            visit(name, [name])


@pytest.mark.parametrize("name", sorted(MODULES))
def test_module_is_small(name: str) -> None:
    lines = MODULES[name].read_text().count("\n")
    assert lines <= MAX_LINES, f"{name} has {lines} lines; split it by job"


def test_models_never_import_each_other() -> None:
    models = {f"vbi_lib.models.{cls.__module__.rpartition('.')[2]}" for cls in vbi.MODELS.values()}
    assert len(models) == len(vbi.MODELS)
    for name in models:
        assert not (GRAPH[name] & (models - {name})), f"{name} imports another model"


def test_public_functions_and_classes_have_docstrings() -> None:
    """The API page documents them (an undocumented public name would be a dead link)."""
    missing = []
    for name, path in MODULES.items():
        for node in ast.parse(path.read_text()).body:
            if isinstance(node, ast.FunctionDef | ast.ClassDef) and not node.name.startswith("_"):
                if ast.get_docstring(node) is None:
                    missing.append(f"{name}.{node.name}")
    assert not missing, f"public names without a docstring: {missing}"
