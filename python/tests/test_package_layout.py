"""The package's module graph (issue 25: no import circle; modules by feature), read from the
source files' own import statements with ast, not from the running package."""
import ast
import os
import pathlib

import cpkit

PKG = pathlib.Path(os.environ.get("CPKIT_SOURCE_DIR", pathlib.Path(__file__).parents[2])) / "python" / "cpkit"


def imports_of(path):
    """Sibling modules imported by `path` (relative imports, at any depth of the file)."""
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.level == 1:
            if node.module:
                out.add(node.module.split(".")[0])
            else:
                out.update(a.name for a in node.names)
    return out - {"_cpkit"}


def test_no_import_circle():
    graph = {p.stem: imports_of(p) for p in PKG.glob("*.py") if p.stem != "__init__"}
    assert set().union(*graph.values()) <= set(graph), "import of a module that does not exist"
    state = {}  # depth-first search: 1 on the stack, 2 done

    def visit(m, path):
        state[m] = 1
        for n in sorted(graph[m]):
            assert state.get(n) != 1, "import circle: " + " -> ".join(path + [m, n])
            if n not in state:
                visit(n, path + [m])
        state[m] = 2

    for m in sorted(graph):
        if m not in state:
            visit(m, [])


def test_feature_modules_and_public_names():
    names = {p.stem for p in PKG.glob("*.py")}
    for feature in ("model", "system", "rate", "step", "maps", "simulation", "lcp", "friction"):
        assert feature in names
    assert not {"contact", "three_d", "three_d_more"} & names  # the old add-on modules are gone
    for p in PKG.glob("*.py"):
        for node in ast.parse(p.read_text()).body:
            if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "__all__":
                for name in ast.literal_eval(node.value):
                    assert hasattr(cpkit, name), f"{p.name}: {name} is not importable from cpkit"
