"""The checker's folder shows its parts (issue 42 part 5): sub-packages by what they do, each saying what it owns,
and no import circle between its modules.

The circle check reads every `import` and `from … import` in checker/ with ast, the ones inside functions too (a
lazy import is still an arrow), and follows `from package import name` to the sub-module when `name` is one.
Imports by a string (importlib.import_module) are not arrows here: the zygote's warm list and the labs' registry
load modules that way on purpose, below everything that names them.
"""
import ast
import os

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHECKER = os.path.join(ROOT, "checker")


def modules():
    """{dotted name: path} of every Python module of the checker (templates are scripts, not modules)."""
    found = {}
    for folder, dirs, files in os.walk(CHECKER):
        dirs[:] = [d for d in dirs if d not in ("__pycache__", "templates")]
        for name in files:
            if name.endswith(".py"):
                parts = os.path.relpath(os.path.join(folder, name), ROOT)[:-3].split(os.sep)
                found[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = os.path.join(folder, name)
    return found


def arrows(known):
    """{module: set of checker modules it imports}."""
    graph = {}
    for name, path in known.items():
        package = name if path.endswith("__init__.py") else name.rsplit(".", 1)[0]
        targets = set()
        with open(path, encoding="utf-8") as handle:
            tree = ast.parse(handle.read(), path)
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                targets.update(alias.name for alias in node.names)
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.split(".")
                    base = base[:len(base) - (node.level - 1)]
                    source = ".".join(base + ([node.module] if node.module else []))
                else:
                    source = node.module or ""
                for alias in node.names:
                    sub = f"{source}.{alias.name}"
                    targets.add(sub if sub in known else source)
        graph[name] = {t for t in targets if t in known and t != name}
    return graph


def circles(graph):
    """The strongly connected components of more than one module (Tarjan's algorithm)."""
    index, low, stack, on, found, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_the_circle_finder_finds_a_circle():
    """The control: a made-up graph with one circle of three and a tail."""
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a", "d"}, "d": set()}
    assert circles(graph) == [["a", "b", "c"]]
    assert circles({"a": {"b"}, "b": set()}) == []


def test_no_import_circle_in_the_checker():
    graph = arrows(modules())
    assert len(graph) > 30 and graph["checker.cli"], "the reader found no arrows: it is broken, not the checker"
    assert circles(graph) == []


ROOMS = sorted(d for d in os.listdir(CHECKER)
               if os.path.isfile(os.path.join(CHECKER, d, "__init__.py")) and d != "labs")


@pytest.mark.parametrize("room", ROOMS)
def test_each_room_says_what_it_owns_in_two_lines(room):
    with open(os.path.join(CHECKER, room, "__init__.py"), encoding="utf-8") as handle:
        text = handle.read()
    doc = ast.get_docstring(ast.parse(text))
    assert doc and 1 <= len(doc.splitlines()) <= 2, f"checker/{room}/__init__.py: say what the room owns in two lines"


def test_the_checker_folder_holds_only_the_orchestration_beside_its_rooms():
    """Beside the rooms, the top of checker/ keeps the command line and the grading of one file and a batch."""
    loose = sorted(f for f in os.listdir(CHECKER) if f.endswith(".py"))
    assert loose == ["__init__.py", "__main__.py", "cli.py", "entries.py", "grade.py", "project.py"]
    assert len(ROOMS) >= 6
