"""The add-on's modules import each other without a cycle (issue 27).

operators.py, preferences.py and ui.py once imported each other in a circle
(partly inside functions, which hid it until a function ran). This test reads
every module of addon/stick_morph with ast, without importing it (no bpy
here), collects its relative imports at any depth, top level and inside
functions alike, and asserts that the graph they make is acyclic.
"""

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[2] / "addon" / "stick_morph"


def module_imports(path):
    """The add-on modules `path` imports relatively ("from . import a, b",
    "from .a import x", "from .a.b import y"), at any depth."""
    names = set()
    modules = {p.stem for p in PACKAGE.glob("*.py")}
    for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
        if not isinstance(node, ast.ImportFrom) or node.level == 0:
            continue
        assert node.level == 1, f"{path.name}: import from outside the package ({ast.dump(node)})"
        if node.module:
            names.add(node.module.split(".")[0])
        else:
            names.update(alias.name for alias in node.names if alias.name in modules)
    return names - {"__init__"}


def import_graph():
    return {path.stem: module_imports(path) for path in sorted(PACKAGE.glob("*.py")) if path.stem != "__init__"}


def find_cycle(graph):
    """A cycle of graph as a list of modules (first == last), or None."""
    state = {}  # module -> "open" while on the path, "done" after

    def visit(node, path):
        state[node] = "open"
        for child in sorted(graph.get(node, ())):
            if state.get(child) == "open":
                return path[path.index(child):] + [child] if child in path else [node, child]
            if child not in state:
                found = visit(child, path + [child])
                if found:
                    return found
        state[node] = "done"
        return None

    for start in sorted(graph):
        if start not in state:
            found = visit(start, [start])
            if found:
                return found
    return None


def test_the_graph_is_read():
    graph = import_graph()
    # A few known edges, so that a parser that sees nothing cannot pass.
    assert "common" in graph["core"]
    assert "ui" in graph["operators"]  # inside a function (the redo panel)
    assert "properties" in graph["ui"]


def test_find_cycle_finds_one():
    assert find_cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert find_cycle({"a": {"b"}, "b": set()}) is None


def test_addon_imports_have_no_cycle():
    graph = import_graph()
    cycle = find_cycle(graph)
    assert cycle is None, "the add-on's modules import each other in a circle: " + " -> ".join(cycle)


def test_every_addon_file_is_under_700_lines():
    long = {p.name: n for p in PACKAGE.glob("*.py") if (n := len(p.read_text().splitlines())) >= 700}
    assert not long, f"add-on files of 700 lines or more: {long}"
