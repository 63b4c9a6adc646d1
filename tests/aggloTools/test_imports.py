"""The Python side's structure: one installed package, no search-path edits,
no import cycle among the package, the tutorials' scripts, the benchmarks
and the tests, and benchmarks that do not depend on pytest."""

import ast
import importlib
import re

import pytest

from aggloTools.runner import project_dir

ROOT = project_dir()
PACKAGE = ROOT / "tools" / "aggloTools" / "src" / "aggloTools"


def python_files():
    """Every Python file of the project (not run output or the venv)."""
    out = []
    for top in ("tools", "tutorials", "bench", "tests"):
        for f in (ROOT / top).rglob("*.py"):
            rel = f.relative_to(ROOT).parts
            if "runs" in rel or "__pycache__" in rel:
                continue
            out.append(f)
    return sorted(out)


def module_name(f):
    """aggloTools.<module> for the package; a tutorial package's module by
    its dotted name from the package's top folder (channel.post.report,
    channel for its __init__); the file's stem otherwise (tutorial scripts
    import each other by that name)."""
    if PACKAGE in f.parents:
        stem = f.stem
        return "aggloTools" if stem == "__init__" else f"aggloTools.{stem}"
    parts = [] if f.stem == "__init__" else [f.stem]
    folder = f.parent
    while (folder / "__init__.py").is_file() and "tutorials" in \
            folder.relative_to(ROOT).parts[:1]:
        parts.insert(0, folder.name)
        folder = folder.parent
    return ".".join(parts)


def imports(f):
    """The modules f imports (absolute names; relative package imports
    resolved; scripts loaded with runner.tutorial_module or
    runner.bench_module count as imports of the script)."""
    tree = ast.parse(f.read_text())
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            if node.level:              # from .x import y, from . import x
                base = "aggloTools" + (f".{node.module}" if node.module
                                       else "")
            else:
                base = node.module
            out.add(base)
            out |= {f"{base}.{a.name}" for a in node.names}
        elif isinstance(node, ast.Call) and getattr(
                node.func, "id", getattr(node.func, "attr", "")) in \
                ("tutorial_module", "bench_module") and node.args and \
                isinstance(node.args[-1], ast.Constant):
            out.add(node.args[-1].value)
    return out


def graph():
    files = python_files()
    names = {module_name(f) for f in files}
    g = {}
    for f in files:
        g.setdefault(module_name(f), set()).update(
            m for m in imports(f) if m in names and m != module_name(f))
    return g


def cycles(g):
    """Every cycle of the directed graph g (node -> set of nodes) that is
    found by a depth-first search, as lists of nodes."""
    found, state, stack = [], {}, []

    def visit(n):
        state[n] = 1
        stack.append(n)
        for m in sorted(g.get(n, ())):
            if state.get(m) == 1:
                found.append(stack[stack.index(m):] + [m])
            elif m not in state:
                visit(m)
        stack.pop()
        state[n] = 2

    for n in sorted(g):
        if n not in state:
            visit(n)
    return found


def test_cycle_search_finds_a_cycle():
    """The search below can fail: it finds the cycle channel <->
    channelPost that existed before the package, and a longer one."""
    assert cycles({"channel": {"channelPost"}, "channelPost": {"channel"}})
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}})
    assert not cycles({"a": {"b"}, "b": {"c"}, "d": {"a", "c"}})


def test_no_import_cycle():
    g = graph()
    # the graph is the real one: the tutorials use the package
    assert "aggloTools.placement" in g["channel.case.particles"]
    assert "channel.case.settings" in g["channel.post.postprocess"]
    assert "channelCosts" in g["channelSolverSettings"]
    assert cycles(g) == []


def test_benchmarks_do_not_need_pytest():
    """Everything a benchmark imports, directly or through the package and
    the tutorials, is free of pytest and the tests' conftest."""
    g = graph()
    files = python_files()
    raw = {module_name(f): imports(f) for f in files}
    for bench in (f for f in files if f.parent == ROOT / "bench"):
        seen, todo = set(), [module_name(bench)]
        while todo:
            n = todo.pop()
            if n in seen:
                continue
            seen.add(n)
            todo += g.get(n, ())
        used = set().union(*(raw[n] for n in seen))
        assert not {m.split(".")[0] for m in used} & {"pytest", "conftest"}, \
            bench.name


def test_no_search_path_edits():
    """No script edits the module search path (they import the installed
    package)."""
    hits = []
    for top in ("tools", "tutorials", "bench", "tests"):
        for f in (ROOT / top).rglob("*"):
            rel = f.relative_to(ROOT).parts
            if not f.is_file() or "runs" in rel or "__pycache__" in rel \
                    or f.suffix in (".pyc", ".png", ".json") \
                    or f == __import__("pathlib").Path(__file__):
                continue
            text = f.read_text(errors="replace")
            if re.search(r"sys\.path\.(insert|append)|PYTHONPATH=", text):
                hits.append(str(f.relative_to(ROOT)))
    assert hits == []


@pytest.mark.parametrize("name", sorted(
    p.stem for p in PACKAGE.glob("*.py") if p.stem != "__init__"))
def test_package_module_imports_alone(name):
    """Each module of the installed package imports on its own, from the
    installed location (not a copy on a search path)."""
    m = importlib.import_module(f"aggloTools.{name}")
    assert PACKAGE in __import__("pathlib").Path(m.__file__).parents
