"""The package's layers import only downward, and no module imports itself through others.

Layers, bottom to top (CONTRIBUTING.md, 'Layers'): the foundation ``lpc_mdo.core``
(with the root package ``lpc_mdo``), the components ``lpc_mdo.components``, the vehicle data
``lpc_mdo.vehicle`` (schema, parts, condition-kind declarations), the groups ``lpc_mdo.groups``
and the application (every other module of ``lpc_mdo``). Imports inside functions count: an
import deferred into a function is still a dependency, and hiding a circle that way is what
this check is for.
"""

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: Installed package -> its folder in the repository (pyproject.toml's package-dir).
PACKAGE_DIRS = {
    "lpc_mdo": "lpc_mdo",
    "lpc_mdo.components": "components",
    "lpc_mdo.groups": "groups",
}
#: Layers, bottom to top: (name, module prefixes). A module is in the first layer that matches.
LAYERS = (
    ("foundation", ("lpc_mdo.core",)),
    ("components", ("lpc_mdo.components",)),
    ("vehicle", ("lpc_mdo.vehicle",)),
    ("groups", ("lpc_mdo.groups",)),
    ("application", ("lpc_mdo",)),
)


def _modules():
    """Return installed module name -> source path, for every module of the package."""
    modules = {}
    for package, folder in PACKAGE_DIRS.items():
        for path in sorted((ROOT / folder).rglob("*.py")):
            parts = list(path.relative_to(ROOT / folder).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts.pop()
            modules[".".join([package, *parts])] = path
    return modules


MODULES = _modules()


def _owner(name):
    """Return the package module that an imported name belongs to (None: not the package's)."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


def _imports(module, path):
    """Return the package modules that ``module`` imports anywhere in its source."""
    is_package = path.name == "__init__.py"
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = module.split(".")[: len(module.split(".")) - node.level + is_package]
                base = ".".join(parts + ([base] if base else []))
            # ``from package import module`` depends on that module; ``from module import name``
            # on the module.
            names = [
                f"{base}.{alias.name}" if f"{base}.{alias.name}" in MODULES else base
                for alias in node.names
            ]
        else:
            continue
        for name in names:
            owner = _owner(name)
            if owner is not None and owner != module:
                found.add(owner)
    return found


GRAPH = {module: _imports(module, path) for module, path in MODULES.items()}


def _layer(module):
    if module == "lpc_mdo":
        return 0  # the root package: everything imports it on the way in
    for index, (_, prefixes) in enumerate(LAYERS):
        if any(module == p or module.startswith(p + ".") for p in prefixes):
            return index
    raise AssertionError(module)


def _cycles(graph):
    """Return the strongly connected components of more than one module (Tarjan, iterative)."""
    index, low, on_stack, stack, result = {}, {}, set(), [], []
    counter = 0
    for start in graph:
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
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
                if len(component) > 1:
                    result.append(sorted(component))
    return result


def test_the_package_is_found():
    # The check is only as good as its module list: every layer has modules in it.
    assert {_layer(m) for m in MODULES} == set(range(len(LAYERS)))
    assert "lpc_mdo.groups.lpc" in MODULES and "lpc_mdo.components.aero.vlm_aic" in MODULES


def test_no_import_circle():
    assert _cycles(GRAPH) == []


def test_cycle_finder_finds_a_circle_through_a_function_level_import(tmp_path):
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert _cycles(graph) == [["a", "b", "c"]]
    path = tmp_path / "probe.py"
    path.write_text("def f():\n    from lpc_mdo.groups.lpc import LPCGroup\n", encoding="utf-8")
    assert _imports("lpc_mdo.core.probe", path) == {"lpc_mdo.groups.lpc"}
    path.write_text("from .checks import check_range\n", encoding="utf-8")
    assert _imports("lpc_mdo.core.probe", path) == {"lpc_mdo.core.checks"}


@pytest.mark.parametrize("module", sorted(MODULES))
def test_imports_only_downward(module):
    layer = _layer(module)
    upward = sorted(m for m in GRAPH[module] if _layer(m) > layer)
    assert not upward, (
        f"{module} ({LAYERS[layer][0]}) imports {upward}, which sit higher "
        f"({', '.join(LAYERS[_layer(m)][0] for m in upward)})"
    )
