"""The application modules import one another without a circle, imports inside functions included.

An import circle is dodged by moving an import into a function, which hides the dependency; the
graph here counts those too. Layers (docs: ARCHITECTURE): the drivers sit below the problems,
which sit below the trim, the warm start and the studies above it.
"""

import ast
from pathlib import Path

import lpc_mdo

PACKAGE = Path(lpc_mdo.__file__).parent
#: Subpackages that are not the application layer (foundation, vehicle data; components and
#: groups install from their own folders).
BELOW = ("core", "vehicle")


def _modules():
    found = {}
    for path in PACKAGE.rglob("*.py"):
        parts = path.relative_to(PACKAGE).with_suffix("").parts
        if parts[0] in BELOW or parts[0] == "data":
            continue
        parts = parts[:-1] if parts[-1] == "__init__" else parts
        found[".".join(("lpc_mdo", *parts))] = path
    return found


def _import_graph():
    modules = _modules()
    edges = {name: set() for name in modules}
    for name, path in modules.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                    base = ".".join([*anchor, *([node.module] if node.module else [])])
                # A name is a submodule when there is one of that name, else a name of ``base``.
                targets = [
                    f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base
                    for a in node.names
                ]
            elif isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            else:
                continue
            for target in targets:
                while target and target not in modules:
                    target = target.rpartition(".")[0]
                if target not in ("", "lpc_mdo", name):  # the root package imports nothing
                    edges[name].add(target)
    return edges


def _reaches(edges, start):
    seen, todo = set(), [start]
    while todo:
        for nxt in edges[todo.pop()]:
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen


def test_no_import_circle_in_the_application_layer():
    edges = _import_graph()
    circles = sorted(name for name in edges if name in _reaches(edges, name))
    assert not circles, f"modules on an import circle: {circles}"


def test_drivers_import_nothing_above_them():
    edges = _import_graph()
    above = {"lpc_mdo.problems", "lpc_mdo.progress", "lpc_mdo.trim", "lpc_mdo.warm_start"}
    for name in edges:
        if name.startswith("lpc_mdo.drivers"):
            assert not _reaches(edges, name) & above, name
