"""The import contract: imports point down the architecture's layers, and nothing imports in a cycle.

A small AST check over every module of ``workbench/`` (nothing is imported):

* an import (at module level or inside a function) from a package to a package of a
  higher layer fails;
* a cycle between top-level packages (``workbench.<package>``) fails, counting every
  import;
* a cycle between modules through module-level imports fails, counting the
  ``__init__`` of each package an import runs (imports inside functions run later,
  when every module is complete, so they cannot leave one half-initialised).

Imports under ``if TYPE_CHECKING:`` are exempt from all three: they never run.
The checker is exercised on a tiny synthetic tree first, so a bug that made it
blind would fail here rather than pass silently.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

WORKBENCH = Path(__file__).resolve().parent.parent / "workbench"

LAYERS: dict[str, int] = {
    # bottom utilities: one exception hierarchy, optional-dependency names, data paths,
    # the shared pose/shape vocabulary
    "workbench": 0,
    "errors": 0,
    "limits": 0,
    "optional": 0,
    "paths": 0,
    "output_files": 0,
    "entry_points": 0,
    "ros_packages": 0,
    "spatial": 0,
    # ROS 1 message types
    "msgs": 1,
    # the bus and bag files (same layer)
    "bus": 2,
    "bag": 2,
    # frames over time (numpy/scipy only)
    "tf": 3,
    # robot descriptions loaded into Drake
    "model": 4,
    # the Meshcat viewer
    "viz": 5,
    # capabilities (same layer; may use each other without cycles)
    "planning": 6,
    "mapping": 6,
    "navigation": 6,
    "actionlib": 6,
    "serial": 6,
    "sim": 6,
    "rviz": 6,
    "turtlesim": 6,
    "teleop": 6,
    "robot_state": 6,
    "introspect": 6,
    # rospy/tf shims and lab demos for the manual's scripts
    "compat": 7,
    "labs": 7,
    # the command line
    "cli": 8,
    "__main__": 8,
}
"""Each top-level module or package of ``workbench`` -> its layer, bottom (0) to top.

The layers of ARCHITECTURE.md: a package may import its own layer (without cycles)
and every layer below, never one above. ``workbench`` is the package root (its
``__init__`` re-exports only bottom utilities); ``__main__`` is the command line.
A new package must be given a layer here (``test_every_package_has_a_layer``).
"""


@dataclass(frozen=True)
class Import:
    """One import statement: who imports what, where."""

    source: str  # dotted module name of the importing module
    target: str  # dotted module name imported (a module or a package)
    line: int
    module_level: bool


def module_name(root: Path, path: Path) -> str:
    """``workbench.tf.buffer`` for ``<root>/tf/buffer.py`` (``__init__`` names the package)."""
    parts = [root.name, *path.relative_to(root).with_suffix("").parts]
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _walk(node: ast.AST, module_level: bool) -> Iterator[tuple[ast.AST, bool]]:
    """Every import node under ``node``, skipping ``if TYPE_CHECKING:`` bodies."""
    for child in ast.iter_child_nodes(node):
        if isinstance(child, ast.Import | ast.ImportFrom):
            yield child, module_level
        elif isinstance(child, ast.If) and _is_type_checking(child.test):
            for other in child.orelse:
                yield from _walk(ast.Module(body=[other], type_ignores=[]), module_level)
        elif isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda):
            yield from _walk(child, False)
        else:
            yield from _walk(child, module_level)


def imports_of(root: Path, path: Path, modules: set[str]) -> list[Import]:
    """The imports of ``path`` that point into the tree at ``root``."""
    source = module_name(root, path)
    package = source if path.name == "__init__.py" else source.rpartition(".")[0]
    tree = ast.parse(path.read_text(), filename=str(path))
    found: list[Import] = []
    for node, module_level in _walk(tree, True):
        targets: list[str] = []
        if isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        else:
            base = node.module or ""
            if node.level:
                anchor = package.split(".")
                anchor = anchor[: len(anchor) - (node.level - 1)]
                base = ".".join([*anchor, base] if base else anchor)
            for alias in node.names:
                submodule = f"{base}.{alias.name}"
                targets.append(submodule if submodule in modules else base)
        for target in targets:
            if target == root.name or target.startswith(root.name + "."):
                found.append(Import(source, target, node.lineno, module_level))
    return found


def scan(root: Path) -> list[Import]:
    """Every import inside the package tree at ``root``."""
    paths = sorted(root.rglob("*.py"))
    modules = {module_name(root, path) for path in paths}
    return [item for path in paths for item in imports_of(root, path, modules)]


def top_package(module: str) -> str:
    """``tf`` for ``workbench.tf.buffer``; ``workbench`` for the root package itself."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else parts[0]


def upward_imports(imports: list[Import], layers: dict[str, int]) -> list[str]:
    """One line per import from a lower layer to a higher one (or from/to an unmapped package)."""
    problems = []
    for item in imports:
        source, target = top_package(item.source), top_package(item.target)
        if source == target:
            continue
        missing = [name for name in (source, target) if name not in layers]
        if missing:
            problems.append(
                f"{item.source}:{item.line} imports {item.target}: "
                f"put {', '.join(missing)} in a layer of LAYERS"
            )
        elif layers[target] > layers[source]:
            problems.append(
                f"{item.source}:{item.line} imports {item.target} "
                f"(layer {layers[target]} above {source}'s layer {layers[source]})"
            )
    return problems


def cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one member (Tarjan), sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for other in sorted(edges.get(node, ())):
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in on_stack:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for node in sorted(edges):
        if node not in index:
            visit(node)
    return sorted(found)


def package_cycles(imports: list[Import]) -> list[list[str]]:
    """Cycles between top-level packages, through any import."""
    edges: dict[str, set[str]] = {}
    for item in imports:
        source, target = top_package(item.source), top_package(item.target)
        if source != target:
            edges.setdefault(source, set()).add(target)
    return cycles(edges)


def _executed_by(source: str, target: str) -> list[str]:
    """The modules importing ``target`` runs: it and its packages' ``__init__`` files.

    A package the importing module lives in is left out: Python has begun running it
    before the importing module, so importing it again does not run anything.
    """
    parts = target.split(".")
    chain = [".".join(parts[:n]) for n in range(1, len(parts) + 1)]
    return [name for name in chain if name != source and not source.startswith(name + ".")]


def module_cycles(imports: list[Import]) -> list[list[str]]:
    """Cycles between modules through module-level imports (packages' ``__init__`` included)."""
    edges: dict[str, set[str]] = {}
    for item in imports:
        if item.module_level:
            edges.setdefault(item.source, set()).update(_executed_by(item.source, item.target))
    return cycles(edges)


def _explain(edges_of: list[Import], component: list[str], package_level: bool) -> str:
    members = set(component)
    key = top_package if package_level else (lambda name: name)
    lines = [
        f"    {item.source}:{item.line} -> {item.target}"
        for item in edges_of
        if key(item.source) in members
        and key(item.target) in members
        and key(item.source) != key(item.target)
        and (package_level or item.module_level)
    ]
    return " <-> ".join(component) + "\n" + "\n".join(sorted(set(lines)))


# --- the checker on a synthetic tree -------------------------------------------------------


def _write(root: Path, files: dict[str, str]) -> None:
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


@pytest.fixture
def synthetic(tmp_path: Path) -> Path:
    """``pkg``: ``low`` imports ``high`` in a function, ``high`` <-> ``mid`` at module level."""
    root = tmp_path / "pkg"
    _write(
        root,
        {
            "__init__.py": "",
            "low/__init__.py": "from pkg.low.core import f\n",
            "low/core.py": "def f():\n    from pkg.high import thing\n    return thing\n",
            "low/typed.py": (
                "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from pkg.high import x\n"
            ),
            "mid/__init__.py": "from .a import g\n",
            "mid/a.py": "from pkg.high.b import h\ndef g():\n    return h\n",
            "high/__init__.py": "thing = 1\n",
            "high/b.py": "from pkg.mid import a\nh = 2\n",
            "high/c.py": "def later():\n    from pkg.mid import a\n",
        },
    )
    return root


def test_checker_finds_an_upward_import_inside_a_function(synthetic: Path) -> None:
    problems = upward_imports(scan(synthetic), {"pkg": 0, "low": 0, "mid": 1, "high": 2})
    assert problems == [
        "pkg.low.core:2 imports pkg.high (layer 2 above low's layer 0)",
        "pkg.mid.a:1 imports pkg.high.b (layer 2 above mid's layer 1)",
    ]


def test_checker_skips_type_checking_imports(synthetic: Path) -> None:
    assert not [item for item in scan(synthetic) if item.source == "pkg.low.typed"]


def test_checker_names_unmapped_packages(synthetic: Path) -> None:
    problems = upward_imports(scan(synthetic), {"pkg": 0, "low": 0, "high": 2})
    assert any("put mid in a layer of LAYERS" in line for line in problems)


def test_checker_finds_package_and_module_cycles(synthetic: Path) -> None:
    imports = scan(synthetic)
    assert package_cycles(imports) == [["high", "mid"]]
    # pkg.mid.a -> pkg.high.b -> pkg.mid (its __init__) -> pkg.mid.a at module level;
    # high.c's import is inside a function and adds nothing.
    assert module_cycles(imports) == [["pkg.high.b", "pkg.mid", "pkg.mid.a"]]


def test_checker_resolves_relative_imports(synthetic: Path) -> None:
    targets = {item.target for item in scan(synthetic) if item.source == "pkg.mid"}
    assert targets == {"pkg.mid.a"}


# --- the contract on workbench/ ------------------------------------------------------------


@pytest.fixture(scope="module")
def workbench_imports() -> list[Import]:
    return scan(WORKBENCH)


def test_every_package_has_a_layer() -> None:
    packages = {path.name for path in WORKBENCH.iterdir() if (path / "__init__.py").is_file()}
    packages |= {path.stem for path in WORKBENCH.glob("*.py") if path.stem != "__init__"}
    unmapped = sorted(packages - set(LAYERS))
    assert not unmapped, f"give these packages a layer in LAYERS: {unmapped}"


def test_imports_point_down_the_layers(workbench_imports: list[Import]) -> None:
    problems = upward_imports(workbench_imports, LAYERS)
    assert not problems, "imports pointing up the layers:\n" + "\n".join(problems)


def test_no_cycle_between_packages(workbench_imports: list[Import]) -> None:
    found = package_cycles(workbench_imports)
    text = "\n".join(_explain(workbench_imports, c, package_level=True) for c in found)
    assert not found, f"import cycles between packages:\n{text}"


def test_no_cycle_between_modules(workbench_imports: list[Import]) -> None:
    found = module_cycles(workbench_imports)
    text = "\n".join(_explain(workbench_imports, c, package_level=False) for c in found)
    assert not found, f"import cycles between modules (module-level imports):\n{text}"
